//! The peers' `MeshEdit` against a naive model: seeded random sequences of every editing
//! operation, each also applied by hand to the face list of the lab's
//! [`Model`](topolab_structures::testing::editing::Model); after every edit `validate()`, the
//! live faces and positions compared with the model's, and, while nothing is deleted, every
//! relation compared with the oracle rebuilt from the structure's faces. An operation a peer
//! does not offer (`supports(op)` false) must be refused with `Refusal::NotImplemented`,
//! nothing changed; one it offers must be done exactly when the model allows it.
//!
//! The lab's own edit suite (`topolab_structures::edit_conformance!`) cannot enrol the peers:
//! it draws every operation and fails on a `NotImplemented` refusal of an edit the model
//! allows (except, with `not_implemented_on_polygons`, on a start mesh with polygons), and no
//! peer offers every operation. This file is the peers' suite until it can.

use glam::DVec3;
use topolab_peers::{BabySharkCornerTable, LoxDirectedEdge, LoxHalfEdge, TriMesh};
use topolab_structures::algorithms::changing::to_soup;
use topolab_structures::testing::conformance::compare;
use topolab_structures::testing::editing::{canonical_face, start_mesh, Model};
use topolab_structures::{EdgeId, EditOp, Error, FaceId, MeshEdit, PolygonSoup, Refusal, VertexId};

/// splitmix64: the test's own seeded draws.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
    fn chance(&mut self, percent: u64) -> bool {
        self.next() % 100 < percent
    }
    fn point(&mut self) -> DVec3 {
        let mut unit = || (self.next() >> 11) as f64 / (1u64 << 53) as f64;
        DVec3::new(unit(), unit(), unit())
    }
}

/// One drawn edit, in the lab's vertex ids.
#[derive(Clone, Debug)]
enum Edit {
    AddVertex(DVec3),
    SetPosition(u32, DVec3),
    AddFace(Vec<u32>),
    SplitFace(u32, u32, DVec3),
    SplitMissingFace(u32),
    Flip(u32, u32),
    SplitEdge(u32, u32, DVec3),
    Collapse(u32, u32),
    DeleteFace(u32, u32),
    DeleteVertex(u32),
    SplitVertex(u32, u32, u32, DVec3),
    Weld(u32, u32),
    Collect,
}

impl Edit {
    fn op(&self) -> EditOp {
        match self {
            // `set_position` is refused as `AddVertex` (the lab's structures name it so).
            Edit::AddVertex(_) | Edit::SetPosition(..) => EditOp::AddVertex,
            Edit::AddFace(_) => EditOp::AddFace,
            Edit::SplitFace(..) | Edit::SplitMissingFace(_) => EditOp::SplitFace,
            Edit::Flip(..) => EditOp::FlipEdge,
            Edit::SplitEdge(..) => EditOp::SplitEdge,
            Edit::Collapse(..) => EditOp::CollapseEdge,
            Edit::DeleteFace(..) => EditOp::DeleteFace,
            Edit::DeleteVertex(_) => EditOp::DeleteVertex,
            Edit::SplitVertex(..) => EditOp::SplitVertex,
            Edit::Weld(..) => EditOp::WeldVertices,
            Edit::Collect => EditOp::GarbageCollection,
        }
    }
}

fn live(model: &Model, v: u32) -> bool {
    model.positions.get(v as usize).is_some_and(Option::is_some)
}

/// The model's live face running a → b, with the corner of a.
fn face_with(model: &Model, a: u32, b: u32) -> Option<(usize, usize)> {
    model.faces.iter().enumerate().find_map(|(i, f)| {
        let f = f.as_ref()?;
        let k = f.len();
        (0..k)
            .find(|&c| f[c] == a && f[(c + 1) % k] == b)
            .map(|c| (i, c))
    })
}

fn triangle(model: &Model, f: usize) -> bool {
    model.faces[f].as_ref().is_some_and(|f| f.len() == 3)
}

fn third(model: &Model, f: usize, c: usize) -> u32 {
    model.faces[f].as_ref().expect("live")[(c + 2) % 3]
}

/// Is this soup an oriented manifold with one fan per vertex (the model's rule)?
fn manifold(soup: &PolygonSoup) -> bool {
    soup.connectivity()
        .and_then(|c| c.check_vertex_fans(soup))
        .is_ok()
}

fn soup_of(model: &Model, extra: Option<&[u32]>) -> PolygonSoup {
    let positions = model
        .positions
        .iter()
        .map(|p| p.unwrap_or(DVec3::ZERO))
        .collect();
    let mut faces: Vec<Vec<u32>> = model.faces.iter().flatten().cloned().collect();
    faces.extend(extra.map(<[u32]>::to_vec));
    PolygonSoup::from_polygons(positions, &faces)
}

/// What the model says an edit of an offered operation must do: `Some(next)` when it must be
/// done, `None` when it must be refused. The rules are those of the lab's edit suite.
fn expect(model: &Model, edit: &Edit, triangles_only: bool) -> Option<Model> {
    let mut next = model.clone();
    let n = model.positions.len() as u32;
    match edit {
        Edit::AddVertex(p) => next.positions.push(Some(*p)),
        Edit::SetPosition(v, p) => {
            if !live(model, *v) {
                return None;
            }
            next.positions[*v as usize] = Some(*p);
        }
        Edit::AddFace(vs) => {
            let distinct = (1..vs.len()).all(|i| !vs[..i].contains(&vs[i]));
            if !distinct || vs.len() < 3 || !vs.iter().all(|&v| live(model, v)) {
                return None;
            }
            if (triangles_only && vs.len() != 3) || !manifold(&soup_of(model, Some(vs))) {
                return None;
            }
            next.faces.push(Some(vs.clone()));
        }
        Edit::SplitFace(a, b, p) => {
            let (f, _) = face_with(model, *a, *b)?;
            let face = model.faces[f].clone().expect("live");
            next.positions.push(Some(*p));
            let k = face.len();
            next.faces[f] = Some(vec![face[0], face[1], n]);
            for i in 1..k {
                next.faces.push(Some(vec![face[i], face[(i + 1) % k], n]));
            }
        }
        Edit::SplitMissingFace(_) => return None,
        Edit::Flip(a, b) => {
            let (a, b) = (*a, *b);
            let ((f1, c1), (f2, c2)) = (face_with(model, a, b)?, face_with(model, b, a)?);
            if !triangle(model, f1) || !triangle(model, f2) {
                return None;
            }
            let (x, y) = (third(model, f1, c1), third(model, f2, c2));
            if x == y || model.neighbours(x).contains(&y) {
                return None;
            }
            next.faces[f1] = Some(vec![a, y, x]);
            next.faces[f2] = Some(vec![b, x, y]);
        }
        Edit::SplitEdge(a, b, p) => {
            let (a, b) = (*a, *b);
            let sides = [face_with(model, a, b), face_with(model, b, a)];
            if sides.iter().all(Option::is_none)
                || sides.iter().flatten().any(|&(f, _)| !triangle(model, f))
            {
                return None;
            }
            if let [Some((f, c)), Some((g, d))] = sides {
                if third(model, f, c) == third(model, g, d) {
                    return None;
                }
            }
            next.positions.push(Some(*p));
            for (f, c) in sides.into_iter().flatten() {
                let face = model.faces[f].clone().expect("live");
                let (s, t, o) = (face[c], face[(c + 1) % 3], face[(c + 2) % 3]);
                next.faces[f] = Some(vec![s, n, o]);
                next.faces.push(Some(vec![n, t, o]));
            }
        }
        Edit::Collapse(a, b) => return model.collapse(*a, *b),
        // Offered by no peer yet: every call must be refused as not implemented.
        Edit::DeleteFace(..) | Edit::DeleteVertex(_) | Edit::SplitVertex(..) | Edit::Weld(..) => {
            return None
        }
        Edit::Collect => next.collect(),
    }
    Some(next)
}

/// The structure's edge between a and b, found through its own queries.
fn edge_between<M: MeshEdit>(m: &M, a: u32, b: u32) -> Option<EdgeId> {
    if a as usize >= m.num_vertices() || m.is_deleted_vertex(VertexId(a)) {
        return None;
    }
    let mut found = None;
    m.vertex_edges(VertexId(a), |e| {
        let [x, y] = m.edge_vertices(e);
        if (x.0, y.0) == (a, b) || (x.0, y.0) == (b, a) {
            found = Some(e);
        }
    });
    found
}

/// The structure's face running a → b, found by its face list.
fn face_running<M: MeshEdit>(m: &M, a: u32, b: u32) -> Option<FaceId> {
    (0..m.num_faces()).map(FaceId::new).find(|&f| {
        if m.is_deleted_face(f) {
            return false;
        }
        let mut c = Vec::new();
        m.face_vertices(f, |v| c.push(v.0));
        let k = c.len();
        (0..k).any(|i| c[i] == a && c[(i + 1) % k] == b)
    })
}

/// `None` when the edit cannot even be asked (no such edge or face in the structure): then
/// the model must refuse it too.
fn apply<M: MeshEdit>(m: &mut M, edit: &Edit) -> Option<Result<(), Error>> {
    let v = VertexId;
    Some(match edit {
        Edit::AddVertex(p) => m.add_vertex(*p).map(drop),
        Edit::SetPosition(x, p) => m.set_position(v(*x), *p),
        Edit::AddFace(vs) => m
            .add_face(&vs.iter().map(|&x| v(x)).collect::<Vec<_>>())
            .map(drop),
        Edit::SplitFace(a, b, p) => m.split_face(face_running(m, *a, *b)?, *p).map(drop),
        Edit::SplitMissingFace(k) => m
            .split_face(FaceId::new(m.num_faces() + *k as usize), DVec3::ZERO)
            .map(drop),
        Edit::Flip(a, b) => m.flip_edge(edge_between(m, *a, *b)?),
        Edit::SplitEdge(a, b, p) => m.split_edge(edge_between(m, *a, *b)?, *p).map(drop),
        Edit::Collapse(a, b) => m.collapse_edge(v(*a), v(*b)),
        Edit::DeleteFace(a, b) => m.delete_face(face_running(m, *a, *b)?),
        Edit::DeleteVertex(x) => m.delete_vertex(v(*x)),
        Edit::SplitVertex(x, l, r, p) => m.split_vertex(v(*x), *p, v(*l), v(*r)).map(drop),
        Edit::Weld(a, b) => m.weld_vertices(v(*a), v(*b)),
        Edit::Collect => {
            m.garbage_collection();
            if M::supports(EditOp::GarbageCollection) {
                Ok(())
            } else {
                Err(Error::EditRefused {
                    structure: M::NAME,
                    op: EditOp::GarbageCollection,
                    reason: Refusal::NotImplemented,
                })
            }
        }
    })
}

fn draw(rng: &mut Rng, model: &Model) -> Edit {
    let live: Vec<u32> = (0..model.positions.len() as u32)
        .filter(|&v| self::live(model, v))
        .collect();
    let nv = model.positions.len() + 2;
    let mut vertex = |rng: &mut Rng| {
        if live.is_empty() || rng.chance(5) {
            rng.below(nv) as u32
        } else {
            live[rng.below(live.len())]
        }
    };
    let near = |rng: &mut Rng, v: u32, vertex: &mut dyn FnMut(&mut Rng) -> u32| {
        let ring = model.neighbours(v);
        if ring.is_empty() || rng.chance(10) {
            vertex(rng)
        } else {
            ring[rng.below(ring.len())]
        }
    };
    let p = rng.point();
    let a = vertex(rng);
    let b = near(rng, a, &mut vertex);
    match rng.below(100) {
        0..4 => Edit::AddVertex(p),
        4..8 => Edit::SetPosition(a, p),
        8..13 => {
            // A triangle on a boundary edge, its third corner an unused vertex or a boundary
            // neighbour: faces the model allows, drawn on purpose.
            let boundary: Vec<(u32, u32)> = model
                .faces
                .iter()
                .flatten()
                .flat_map(|f| (0..f.len()).map(move |i| (f[i], f[(i + 1) % f.len()])))
                .filter(|&(x, y)| face_with(model, y, x).is_none())
                .collect();
            let unused: Vec<u32> = live
                .iter()
                .copied()
                .filter(|&v| model.neighbours(v).is_empty())
                .collect();
            let Some(&(x, y)) = boundary.get(rng.below(boundary.len())) else {
                return Edit::AddVertex(p);
            };
            let c = if !unused.is_empty() && rng.chance(50) {
                unused[rng.below(unused.len())]
            } else {
                let ring: Vec<u32> = model
                    .neighbours(x)
                    .into_iter()
                    .chain(model.neighbours(y))
                    .filter(|&w| w != x && w != y)
                    .collect();
                match ring.len() {
                    0 => vertex(rng),
                    k => ring[rng.below(k)],
                }
            };
            Edit::AddFace(vec![y, x, c])
        }
        13..18 => {
            let c = if rng.chance(50) {
                near(rng, b, &mut vertex)
            } else {
                vertex(rng)
            };
            let mut face = if rng.chance(50) {
                vec![b, a, c]
            } else {
                vec![a, b, c]
            };
            if rng.chance(10) {
                face.push(vertex(rng));
            }
            Edit::AddFace(face)
        }
        18..30 => Edit::SplitFace(a, b, p),
        30..32 => Edit::SplitMissingFace(rng.below(3) as u32),
        32..50 => Edit::Flip(a, b),
        50..64 => Edit::SplitEdge(a, b, p),
        64..84 => Edit::Collapse(a, b),
        84..88 => Edit::DeleteFace(a, b),
        88..91 => Edit::DeleteVertex(a),
        91..95 => {
            let r = near(rng, a, &mut vertex);
            Edit::SplitVertex(a, b, r, p)
        }
        95..98 => Edit::Weld(a, b),
        _ => Edit::Collect,
    }
}

fn face_set<M: MeshEdit>(m: &M) -> Vec<Vec<u32>> {
    let mut out: Vec<Vec<u32>> = (0..m.num_faces())
        .map(FaceId::new)
        .filter(|&f| !m.is_deleted_face(f))
        .map(|f| {
            let mut c = Vec::new();
            m.face_vertices(f, |v| c.push(v.0));
            canonical_face(&c)
        })
        .collect();
    out.sort();
    out
}

fn agree<M: MeshEdit>(m: &M, model: &Model) -> Result<(), String> {
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
        let id = VertexId::new(v);
        match p {
            None if !m.is_deleted_vertex(id) => return Err(format!("v{v} should be deleted")),
            Some(_) if m.is_deleted_vertex(id) => return Err(format!("v{v} is deleted")),
            Some(p) if m.position(id) != *p => {
                return Err(format!("v{v} is not where it should be"))
            }
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

/// Per operation: how many were done and how many refused (beside `NotImplemented`).
#[derive(Default, Debug)]
struct Tally {
    done: std::collections::BTreeMap<&'static str, usize>,
    refused: std::collections::BTreeMap<&'static str, usize>,
}

fn run<M: MeshEdit>(seed: u64, steps: usize, tally: &mut Tally) -> Result<(), String> {
    let soup = start_mesh(seed);
    if !manifold(&soup) {
        return Ok(());
    }
    let Ok(mut m) = M::from_soup(&soup) else {
        return Ok(());
    };
    let triangles_only = M::capabilities().triangles_only;
    let mut model = Model::of(&soup);
    let mut rng = Rng(seed ^ 0x005e_ed0f_9ee2);
    for step in 0..steps {
        let edit = draw(&mut rng, &model);
        let op = edit.op();
        // Every structure moves its vertices: `set_position` is no operation of `EditOp`.
        let offered = matches!(edit, Edit::SetPosition(..)) || M::supports(op);
        let expected = if offered {
            expect(&model, &edit, triangles_only)
        } else {
            None
        };
        if let Edit::Collapse(a, b) = edit {
            // The collapse's test alone answers as the collapse then does.
            let checked = m
                .check_collapse(VertexId(a), VertexId(b))
                .map_err(|e| e.to_string());
            let want = if !offered {
                Err(())
            } else {
                expected.as_ref().map(drop).ok_or(())
            };
            if checked.is_ok() != want.is_ok() {
                return Err(format!(
                    "step {step}: {edit:?}: check_collapse says {checked:?}, the model {want:?}"
                ));
            }
        }
        let got = apply(&mut m, &edit);
        match (expected, got) {
            (Some(next), Some(Ok(()))) => {
                model = next;
                *tally.done.entry(op.name()).or_default() += 1;
            }
            (None, None) => {}
            (None, Some(Err(Error::EditRefused { reason, .. }))) => {
                if !offered && reason != Refusal::NotImplemented {
                    return Err(format!(
                        "step {step}: {edit:?} refused with {reason:?}; {op} is not offered"
                    ));
                }
                if offered && reason == Refusal::NotImplemented {
                    return Err(format!(
                        "step {step}: {edit:?} refused as not implemented; {op} is offered"
                    ));
                }
                if offered {
                    *tally.refused.entry(op.name()).or_default() += 1;
                }
            }
            (Some(_), None) => {
                return Err(format!(
                    "step {step}: {edit:?}: the structure has no such element"
                ))
            }
            (Some(_), Some(Err(e))) => {
                return Err(format!(
                    "step {step}: {edit:?} refused: {e}; the model allows it"
                ))
            }
            (None, Some(Err(e))) => return Err(format!("step {step}: {edit:?} failed with {e}")),
            (None, Some(Ok(()))) => {
                return Err(format!("step {step}: {edit:?} done; the model refuses it"))
            }
        }
        agree(&m, &model).map_err(|msg| format!("after step {step} ({edit:?}): {msg}"))?;
    }
    // Every relation against the oracle once more, nothing deleted.
    m.garbage_collection();
    model.collect();
    agree(&m, &model).map_err(|msg| format!("after the final collection: {msg}"))
}

/// Runs 60 seeds of 40 edits on `M`; panics on the first disagreement, and unless every
/// operation `M` offers was done at least `min_done` times and refused at least once where the
/// model has refusals for it.
fn check<M: MeshEdit>(min_done: usize) {
    let mut tally = Tally::default();
    for seed in 0..60 {
        if let Err(msg) = run::<M>(seed, 40, &mut tally) {
            panic!("{} on edit seed {seed}: {msg}", M::NAME);
        }
    }
    for op in [
        EditOp::AddVertex,
        EditOp::AddFace,
        EditOp::SplitFace,
        EditOp::FlipEdge,
        EditOp::SplitEdge,
        EditOp::CollapseEdge,
    ] {
        if !M::supports(op) {
            continue;
        }
        let done = tally.done.get(op.name()).copied().unwrap_or(0);
        assert!(
            done >= min_done,
            "{}: {op} done {done} times: {tally:?}",
            M::NAME
        );
        // Refusals the random draws make often (a split edge is refused only where two
        // triangles share their third corner: `a_pillow_s_edges_are_neither_split_nor_flipped`).
        if op != EditOp::AddVertex && op != EditOp::SplitEdge {
            let refused = tally.refused.get(op.name()).copied().unwrap_or(0);
            assert!(refused > 0, "{}: {op} never refused: {tally:?}", M::NAME);
        }
    }
}

#[test]
fn lox_half_edge_edits_agree_with_the_model() {
    check::<LoxHalfEdge>(10);
}

#[test]
fn lox_directed_edge_edits_agree_with_the_model() {
    check::<LoxDirectedEdge>(10);
}

#[test]
fn baby_shark_corner_table_edits_agree_with_the_model() {
    check::<BabySharkCornerTable>(10);
}

#[test]
fn tri_mesh_edits_agree_with_the_model() {
    check::<TriMesh>(10);
}

/// Two triangles on the same three vertices, back to back: every edge's two triangles share
/// their third corner, so a split would give the new edge four triangles and a flip would
/// join a vertex to itself. Each peer that offers the operation refuses it, nothing changed.
fn pillow_refuses<M: MeshEdit>() {
    let soup = PolygonSoup::from_polygons(
        vec![DVec3::ZERO, DVec3::X, DVec3::Y],
        &[vec![0, 1, 2], vec![1, 0, 2]],
    );
    let mut m = M::from_soup(&soup).unwrap();
    let before = face_set(&m);
    let mut edges = Vec::new();
    m.for_each_edge(|e| edges.push(e));
    assert_eq!(edges.len(), 3);
    for e in edges {
        for (op, got) in [
            (EditOp::SplitEdge, m.split_edge(e, DVec3::ONE).map(drop)),
            (EditOp::FlipEdge, m.flip_edge(e)),
        ] {
            let want = if M::supports(op) {
                Refusal::EdgeExists
            } else {
                Refusal::NotImplemented
            };
            match got {
                Err(Error::EditRefused { reason, .. }) => assert_eq!(reason, want, "{op}"),
                other => panic!("{}: {op} of {e:?}: {other:?}", M::NAME),
            }
        }
        assert_eq!(face_set(&m), before);
        m.validate().unwrap();
    }
}

#[test]
fn a_pillow_s_edges_are_neither_split_nor_flipped() {
    pillow_refuses::<LoxHalfEdge>();
    pillow_refuses::<LoxDirectedEdge>();
    pillow_refuses::<TriMesh>();
    pillow_refuses::<BabySharkCornerTable>();
}
