//! An edit applied to the structure and to the model, and the two compared.

use super::edit::{besides_edits, draw, edge_between, face_left, Edit};
use super::expect::expect;
use super::model::{start_mesh, Model};
use crate::algorithms::changing::to_soup;
use crate::algorithms::select::{
    rotate_selection, scale_selection, select_faces_in, select_vertices_in, smooth_step,
};
use crate::core::edit::{EditOp, MeshEdit, Refusal};
use crate::core::error::Error;
use crate::core::ids::{FaceId, VertexId};
use crate::testing::conformance::compare;
use crate::testing::oracle::canonical_face;
use glam::{DQuat, DVec3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::collections::BTreeMap;

/// Applies `edit` to the structure; `None` when it cannot be asked (the structure has no edge
/// or face between the vertices named), which the model must then refuse.
pub(super) fn apply<M: MeshEdit>(m: &mut M, edit: &Edit) -> Option<Result<(), Error>> {
    Some(match edit {
        Edit::AddVertex(p) => m.add_vertex(*p).map(drop),
        Edit::SetPosition(v, p) => m.set_position(VertexId(*v), *p),
        Edit::AddFace(vs) => {
            let vs: Vec<VertexId> = vs.iter().map(|&v| VertexId(v)).collect();
            m.add_face(&vs).map(drop)
        }
        Edit::DeleteFace(a, b) => m.delete_face(face_left(m, *a, *b)?),
        Edit::DeleteMissingFace(f) => m.delete_face(FaceId(*f)),
        Edit::DeleteVertex(v) => m.delete_vertex(VertexId(*v)),
        Edit::Flip(a, b) => m.flip_edge(edge_between(m, *a, *b)?),
        Edit::SplitEdge(a, b, p) => m.split_edge(edge_between(m, *a, *b)?, *p).map(drop),
        Edit::SplitFace(a, b, p) => m.split_face(face_left(m, *a, *b)?, *p).map(drop),
        Edit::SplitMissingFace(k) => m
            .split_face(FaceId::new(m.num_faces() + *k as usize), DVec3::ONE)
            .map(drop),
        Edit::Collapse(a, b) => m.collapse_edge(VertexId(*a), VertexId(*b)),
        Edit::SplitVertex(v, l, r, p) => m
            .split_vertex(VertexId(*v), *p, VertexId(*l), VertexId(*r))
            .map(drop),
        Edit::Weld(a, b) => m.weld_vertices(VertexId(*a), VertexId(*b)),
        Edit::InsertEdge(a, b, c) => m
            .insert_edge(face_left(m, *a, *b)?, VertexId(*a), VertexId(*c))
            .map(drop),
        Edit::DeleteEdge(a, b) => m.delete_edge(edge_between(m, *a, *b)?),
        // Compared with the model's selection in `check_edit`.
        Edit::Select(_) => Ok(()),
        Edit::Rotate(b, centre, axis, angle) => {
            let s = select_vertices_in(m, b);
            rotate_selection(m, &s, *centre, DQuat::from_axis_angle(*axis, *angle))
        }
        Edit::Scale(b, centre, factors) => {
            let s = select_vertices_in(m, b);
            scale_selection(m, &s, *centre, *factors)
        }
        Edit::Smooth => smooth_step(m).map(drop),
        Edit::Collect => {
            m.garbage_collection();
            Ok(())
        }
    })
}

/// The structure's live faces, canonical and sorted.
pub(super) fn face_set<M: MeshEdit>(m: &M) -> Vec<Vec<u32>> {
    let mut out = Vec::new();
    for f in 0..m.num_faces() {
        let f = FaceId::new(f);
        if m.is_deleted_face(f) {
            continue;
        }
        let mut face = Vec::new();
        m.face_vertices(f, |v| face.push(v.0));
        out.push(canonical_face(&face));
    }
    out.sort();
    out
}

/// Checks the structure against the model after an edit.
pub(super) fn agree<M: MeshEdit>(m: &M, model: &Model) -> Result<(), String> {
    m.validate()
        .map_err(|e| format!("validate() failed: {e}"))?;
    if m.num_vertices() != model.positions.len() {
        return Err(format!(
            "{} vertex slots, the model has {}",
            m.num_vertices(),
            model.positions.len()
        ));
    }
    for (v, p) in model.positions.iter().enumerate() {
        let vid = VertexId::new(v);
        match p {
            None if !m.is_deleted_vertex(vid) => return Err(format!("v{v} should be deleted")),
            Some(_) if m.is_deleted_vertex(vid) => return Err(format!("v{v} is deleted")),
            Some(p) if m.position(vid) != *p => return Err(format!("v{v} moved")),
            _ => {}
        }
    }
    let (got, want) = (face_set(m), model.face_set());
    if got != want {
        return Err(format!("faces {got:?}, the model has {want:?}"));
    }
    let clean =
        model.positions.iter().all(Option::is_some) && model.faces.iter().all(Option::is_some);
    if clean {
        compare(m, &to_soup(m))?;
    }
    Ok(())
}

/// What a run did.
#[derive(Debug, Default)]
pub(super) struct Tally {
    /// Drawn edits done.
    pub(super) done: usize,
    /// Drawn edits refused (as the model does, or as not implemented).
    pub(super) refused: usize,
    pub(super) welds: usize,
    pub(super) welds_refused: usize,
    /// Per operation, edits done.
    pub(super) done_by: BTreeMap<EditOp, usize>,
    /// Per operation `M` implements, edits it refused (as the model does).
    pub(super) refused_by: BTreeMap<EditOp, usize>,
    /// Per operation `M` does not implement, edits it refused as not implemented.
    pub(super) not_implemented: BTreeMap<EditOp, usize>,
    /// Faces of more than three corners refused that only a structure of triangles only
    /// refuses (the model would allow a polygon structure to add them).
    pub(super) polygons_refused: usize,
    /// Vertices moved.
    pub(super) moved: usize,
}

impl Tally {
    pub(super) fn add(&mut self, other: Tally) {
        self.done += other.done;
        self.refused += other.refused;
        self.welds += other.welds;
        self.welds_refused += other.welds_refused;
        for (mine, theirs) in [
            (&mut self.done_by, other.done_by),
            (&mut self.refused_by, other.refused_by),
            (&mut self.not_implemented, other.not_implemented),
        ] {
            for (op, n) in theirs {
                *mine.entry(op).or_default() += n;
            }
        }
        self.polygons_refused += other.polygons_refused;
        self.moved += other.moved;
    }
}

pub(super) fn run_tally<M: MeshEdit>(
    seed: u64,
    steps: usize,
    not_implemented_on_polygons: bool,
) -> Result<Tally, String> {
    let mut tally = Tally::default();
    let soup = start_mesh(seed);
    let may_refuse = not_implemented_on_polygons && !soup.is_triangle_mesh();
    // The model's rules are those of an oriented manifold with one fan per vertex: a start
    // mesh with a non-manifold vertex (which OpenMesh builds, with open fans) is skipped, as
    // structures that cannot build it skip it below.
    if !Model::manifold(&soup) {
        return Ok(tally);
    }
    let Ok(mut m) = M::from_soup(&soup) else {
        return Ok(tally);
    };
    let triangles_only = M::capabilities().triangles_only;
    let mut model = Model::of(&soup);
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5eed);
    // The edits beside the drawn ones come from a stream of their own, which `draw` never
    // reads: moves change no topology and splits of missing faces nothing, so neither
    // changes what is drawn after them; faces added on the boundary change the mesh the
    // later edits are drawn on.
    let mut besides = ChaCha8Rng::seed_from_u64(seed ^ 0xe7_7a);
    for step in 0..steps {
        let edit = draw(&mut rng, &model, triangles_only);
        check_edit(&mut m, &mut model, &edit, true, may_refuse, &mut tally)
            .map_err(|msg| format!("step {step}: {edit:?}{msg}"))?;
        for edit in besides_edits(&mut besides, &model, triangles_only) {
            check_edit(&mut m, &mut model, &edit, false, may_refuse, &mut tally)
                .map_err(|msg| format!("step {step}, beside: {edit:?}{msg}"))?;
        }
    }
    m.garbage_collection();
    model.collect();
    agree(&m, &model).map_err(|msg| format!("after the final collection: {msg}"))?;
    Ok(tally)
}

/// Applies one edit to the structure and, when the structure must do it, to the model, and
/// checks the two against each other; `drawn` edits count in `done` and `refused`. `Err`
/// continues a message that names the edit.
pub(super) fn check_edit<M: MeshEdit>(
    m: &mut M,
    model: &mut Model,
    edit: &Edit,
    drawn: bool,
    may_refuse: bool,
    tally: &mut Tally,
) -> Result<(), String> {
    let op = edit.op();
    let implemented = op.is_none_or(M::supports);
    let caps = M::capabilities();
    let triangles_only = caps.triangles_only;
    let expected = if implemented {
        expect(model, edit, triangles_only, caps.distinct_positions)
    } else {
        None
    };
    if let Edit::Select(b) = edit {
        let got = select_vertices_in(m, b);
        let got: Vec<u32> = got.vertices().iter().map(|v| v.0).collect();
        let want = model.vertices_in(b);
        if got != want {
            return Err(format!(": selected vertices {got:?}, the model's {want:?}"));
        }
        let mut got: Vec<Vec<u32>> = select_faces_in(m, b)
            .faces()
            .iter()
            .map(|&f| {
                let mut face = Vec::new();
                m.face_vertices(f, |v| face.push(v.0));
                canonical_face(&face)
            })
            .collect();
        got.sort();
        let want = model.faces_in(b);
        if got != want {
            return Err(format!(": selected faces {got:?}, the model's {want:?}"));
        }
    }
    // A collapse's test alone (what a decimater asks of its candidates) must answer as the
    // collapse itself then does.
    let checked = match edit {
        Edit::Collapse(a, b) => Some(
            m.check_collapse(VertexId(*a), VertexId(*b))
                .map_err(|e| e.to_string()),
        ),
        _ => None,
    };
    let got = apply(m, edit);
    if let (Some(checked), Some(got)) = (checked, &got) {
        let done = got.as_ref().map(drop).map_err(|e| e.to_string());
        if checked != done {
            return Err(format!(
                ": check_collapse says {checked:?}, the collapse {done:?}"
            ));
        }
    }
    let weld = matches!(edit, Edit::Weld(..));
    let op_name = op.map_or("", EditOp::name);
    let refused = |tally: &mut Tally| {
        tally.refused += drawn as usize;
        tally.welds_refused += weld as usize;
    };
    match (expected, got) {
        (_, Some(Ok(()))) if !implemented => {
            return Err(format!(
                " done; {} does not implement {op_name} (`supports` says so)",
                M::NAME
            ))
        }
        (
            _,
            Some(Err(Error::EditRefused {
                reason: Refusal::NotImplemented,
                ..
            })),
        ) if !implemented => {
            refused(tally);
            if let Some(op) = op {
                *tally.not_implemented.entry(op).or_default() += 1;
            }
        }
        (_, Some(Err(e))) if !implemented => {
            return Err(format!(
                " refused with {e}; {} does not implement {op_name}, which it must refuse \
                 as not implemented",
                M::NAME
            ))
        }
        (_, None) if !implemented => refused(tally),
        (Some(next), Some(Ok(()))) => {
            *model = next;
            tally.done += drawn as usize;
            tally.welds += weld as usize;
            tally.moved += matches!(edit, Edit::SetPosition(..)) as usize;
            if let Some(op) = op {
                *tally.done_by.entry(op).or_default() += 1;
            }
        }
        (None, None) => refused(tally),
        (None, Some(Err(e))) if e.kind() == "edit-refused" => {
            refused(tally);
            if let Some(op) = op {
                *tally.refused_by.entry(op).or_default() += 1;
            }
            if let Edit::AddFace(vs) = edit {
                if vs.len() > 3 && expect(model, edit, false, false).is_some() {
                    tally.polygons_refused += 1;
                }
            }
        }
        (
            Some(_),
            Some(Err(Error::EditRefused {
                reason: Refusal::NotImplemented,
                ..
            })),
        ) if may_refuse => refused(tally),
        (Some(_), None) => {
            return Err(format!(
                ": {} has no such edge or face; the model allows the edit",
                M::NAME
            ))
        }
        (Some(_), Some(Err(e))) => return Err(format!(" refused: {e}; the model allows it")),
        (None, Some(Err(e))) => return Err(format!(" failed with {e}")),
        (None, Some(Ok(()))) => return Err(" done; the model refuses it".to_string()),
    }
    agree(m, model).map_err(|msg| format!(", after it: {msg}"))
}
