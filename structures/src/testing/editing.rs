//! The editing suite: random sequences of [`MeshEdit`] operations on a structure, each
//! applied as well to a naive [`Model`] (a face list edited by hand), with every refusal
//! checked against the model (which says whether an edit must be refused, not for which
//! [`Refusal`]) and, after every edit, `validate()`, the live faces
//! compared with the model's, and, when nothing is marked deleted, every relation compared
//! with the [`Oracle`](crate::testing::oracle::Oracle) rebuilt from the structure's face list
//! ([`compare`]). An operation the structure does not implement ([`MeshEdit::supports`])
//! must be refused with [`Refusal::NotImplemented`], nothing
//! changed. The [`edit_conformance!`](macro@crate::edit_conformance) macro enrols a
//! structure in one line, one that implements a subset of the operations too.
//!
//! The operations on positions ([`crate::algorithms::select`]) are drawn too: a box
//! selection (compared with the model's vertices and faces in the box), its rotation or
//! scaling, and a smoothing step, each applied to the model's positions by hand. The point
//! transforms themselves ([`rotate_point`], [`scale_point`], [`laplacian_mean`]) are shared
//! with the model so that positions compare bit for bit, and tested on their own in that
//! module. A structure that tells vertices apart by their coordinates
//! (`capabilities().distinct_positions`, explicit storage) must refuse a move that would put
//! two vertices at one position, which the model then refuses too.

use crate::algorithms::changing::to_soup;
use crate::algorithms::select::{
    laplacian_mean, rotate_point, rotate_selection, scale_point, scale_selection, select_faces_in,
    select_vertices_in, smooth_step, Aabb,
};
use crate::core::edit::{EditOp, MeshEdit, Refusal};
use crate::core::error::Error;
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::soup::PolygonSoup;
use crate::testing::conformance::compare;
use crate::testing::meshes::{self, RandomMeshParams};
pub use crate::testing::oracle::canonical_face;
use glam::{DQuat, DVec3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::BTreeMap;

/// The naive model: positions and faces, `None` where deleted.
#[derive(Clone, Debug, Default)]
pub struct Model {
    /// Per vertex, its position, `None` once deleted.
    pub positions: Vec<Option<DVec3>>,
    /// Per face, its corners, `None` once deleted.
    pub faces: Vec<Option<Vec<u32>>>,
}

impl Model {
    /// The model of a soup.
    pub fn of(soup: &PolygonSoup) -> Self {
        Self {
            positions: soup.positions.iter().map(|&p| Some(p)).collect(),
            faces: soup.faces().map(|f| Some(f.to_vec())).collect(),
        }
    }

    fn live_faces(&self) -> impl Iterator<Item = (usize, &Vec<u32>)> {
        self.faces
            .iter()
            .enumerate()
            .filter_map(|(i, f)| f.as_ref().map(|f| (i, f)))
    }

    /// The live faces, canonical and sorted.
    pub fn face_set(&self) -> Vec<Vec<u32>> {
        let mut out: Vec<Vec<u32>> = self.live_faces().map(|(_, f)| canonical_face(f)).collect();
        out.sort();
        out
    }

    /// The soup of the live faces, all vertex slots kept (a deleted vertex at the origin).
    fn soup(&self, replace: Option<(usize, Option<Vec<u32>>)>, extra: &[Vec<u32>]) -> PolygonSoup {
        let positions = self
            .positions
            .iter()
            .map(|p| p.unwrap_or(DVec3::ZERO))
            .collect();
        let mut faces: Vec<Vec<u32>> = Vec::new();
        for (i, f) in self.faces.iter().enumerate() {
            let f = match &replace {
                Some((j, g)) if *j == i => g.clone(),
                _ => f.clone(),
            };
            faces.extend(f);
        }
        faces.extend(extra.iter().cloned());
        PolygonSoup::from_polygons(positions, &faces)
    }

    /// Would this face list be an oriented manifold with one fan per vertex?
    fn manifold(soup: &PolygonSoup) -> bool {
        soup.connectivity()
            .and_then(|c| c.check_vertex_fans(soup))
            .is_ok()
    }

    fn live_vertex(&self, v: u32) -> bool {
        self.positions.get(v as usize).is_some_and(|p| p.is_some())
    }

    /// The face holding the directed edge a → b, with the corner of a.
    fn face_with(&self, a: u32, b: u32) -> Option<(usize, usize)> {
        self.live_faces().find_map(|(i, f)| {
            let k = f.len();
            (0..k)
                .find(|&c| f[c] == a && f[(c + 1) % k] == b)
                .map(|c| (i, c))
        })
    }

    /// The vertices that share a face side with `v`, sorted.
    pub fn neighbours(&self, v: u32) -> Vec<u32> {
        let mut out = Vec::new();
        for (_, f) in self.live_faces() {
            let k = f.len();
            for c in 0..k {
                if f[c] == v {
                    out.push(f[(c + 1) % k]);
                    out.push(f[(c + k - 1) % k]);
                }
            }
        }
        out.sort_unstable();
        out.dedup();
        out
    }

    fn is_boundary_edge(&self, a: u32, b: u32) -> bool {
        self.face_with(a, b).is_none() || self.face_with(b, a).is_none()
    }

    /// Does `v` have an edge with a face on one side only?
    pub fn is_boundary_vertex(&self, v: u32) -> bool {
        self.neighbours(v)
            .into_iter()
            .any(|w| self.is_boundary_edge(v, w))
    }

    fn triangle(&self, f: usize) -> bool {
        self.faces[f].as_ref().is_some_and(|f| f.len() == 3)
    }

    fn third(&self, f: usize, c: usize) -> u32 {
        let face = self.faces[f].as_ref().expect("live");
        face[(c + 2) % 3]
    }

    /// The model after collapsing `v0` into `v1`, or `None` when the collapse must be refused
    /// (pmp-library's `is_collapse_ok` with the tetrahedron test of OpenMesh's Decimater,
    /// worked out on the face list).
    pub fn collapse(&self, v0: u32, v1: u32) -> Option<Model> {
        expect(self, &Edit::Collapse(v0, v1), false, false)
    }

    /// Are the live vertices' positions distinct (as explicit storage needs)?
    fn positions_distinct(&self) -> bool {
        let mut keys: Vec<[u64; 3]> = self
            .positions
            .iter()
            .flatten()
            .map(|p| p.to_array().map(|x| (x + 0.0).to_bits()))
            .collect();
        let n = keys.len();
        keys.sort_unstable();
        keys.dedup();
        keys.len() == n
    }

    /// The live vertices inside `b`.
    fn vertices_in(&self, b: &Aabb) -> Vec<u32> {
        (0..self.positions.len() as u32)
            .filter(|&v| self.positions[v as usize].is_some_and(|p| b.contains(p)))
            .collect()
    }

    /// The live faces whose corners are all inside `b`, canonical and sorted.
    fn faces_in(&self, b: &Aabb) -> Vec<Vec<u32>> {
        let mut out: Vec<Vec<u32>> = self
            .live_faces()
            .filter(|(_, f)| {
                f.iter()
                    .all(|&v| self.positions[v as usize].is_some_and(|p| b.contains(p)))
            })
            .map(|(_, f)| canonical_face(f))
            .collect();
        out.sort();
        out
    }

    /// The number of live faces.
    pub fn num_live_faces(&self) -> usize {
        self.live_faces().count()
    }

    /// Removes deleted slots, keeping the order of the others.
    pub fn collect(&mut self) {
        let mut map = vec![u32::MAX; self.positions.len()];
        let mut next = 0;
        for (v, p) in self.positions.iter().enumerate() {
            if p.is_some() {
                map[v] = next;
                next += 1;
            }
        }
        self.positions.retain(|p| p.is_some());
        self.faces.retain(|f| f.is_some());
        for f in self.faces.iter_mut().flatten() {
            for v in f.iter_mut() {
                *v = map[*v as usize];
            }
        }
    }
}

/// One random edit: what was asked, in the lab's ids.
#[derive(Clone, Debug)]
pub enum Edit {
    /// Add a vertex.
    AddVertex(DVec3),
    /// Move a vertex (refused where there is no such vertex).
    SetPosition(u32, DVec3),
    /// Add a face on these vertices.
    AddFace(Vec<u32>),
    /// Delete the face left of the directed edge a → b.
    DeleteFace(u32, u32),
    /// Delete a face by an id out of range (must be refused).
    DeleteMissingFace(u32),
    /// Delete a vertex.
    DeleteVertex(u32),
    /// Flip the edge between two vertices.
    Flip(u32, u32),
    /// Split the edge between two vertices.
    SplitEdge(u32, u32, DVec3),
    /// Split the face left of the directed edge a → b.
    SplitFace(u32, u32, DVec3),
    /// Split a face by an id this many past the structure's last (must be refused).
    SplitMissingFace(u32),
    /// Collapse the first vertex into the second.
    Collapse(u32, u32),
    /// Split a vertex (vertex, left, right).
    SplitVertex(u32, u32, u32, DVec3),
    /// Weld the second vertex into the first.
    Weld(u32, u32),
    /// Garbage collection.
    Collect,
    /// Insert an edge in the face left of the directed edge a → b, from a to the third vertex.
    InsertEdge(u32, u32, u32),
    /// Delete the edge between two vertices.
    DeleteEdge(u32, u32),
    /// Select the vertices and faces in a box (nothing changes).
    Select(Aabb),
    /// Rotate the vertices in a box about a centre, by an angle about an axis.
    Rotate(Aabb, DVec3, DVec3, f64),
    /// Scale the vertices in a box about a centre, by factors per axis.
    Scale(Aabb, DVec3, DVec3),
    /// One smoothing step.
    Smooth,
}

impl Edit {
    /// The operation the edit exercises, whose [`MeshEdit::supports`] says whether the
    /// structure must do it or refuse it as not implemented; `None` for what every structure
    /// does: garbage collection (a structure that deletes nothing has nothing to collect).
    pub fn op(&self) -> Option<EditOp> {
        Some(match self {
            Edit::Collect => return None,
            Edit::SetPosition(..) => EditOp::SetPosition,
            Edit::InsertEdge(..) => EditOp::InsertEdge,
            Edit::DeleteEdge(..) => EditOp::DeleteEdge,
            Edit::Select(_) => EditOp::Select,
            Edit::Rotate(..) => EditOp::RotateSelection,
            Edit::Scale(..) => EditOp::ScaleSelection,
            Edit::Smooth => EditOp::Smooth,
            Edit::AddVertex(_) => EditOp::AddVertex,
            Edit::AddFace(_) => EditOp::AddFace,
            Edit::DeleteFace(..) | Edit::DeleteMissingFace(_) => EditOp::DeleteFace,
            Edit::DeleteVertex(_) => EditOp::DeleteVertex,
            Edit::Flip(..) => EditOp::FlipEdge,
            Edit::SplitEdge(..) => EditOp::SplitEdge,
            Edit::SplitFace(..) | Edit::SplitMissingFace(_) => EditOp::SplitFace,
            Edit::Collapse(..) => EditOp::CollapseEdge,
            Edit::SplitVertex(..) => EditOp::SplitVertex,
            Edit::Weld(..) => EditOp::WeldVertices,
        })
    }
}

/// The operations the random sequences draw ([`Edit::op`]): every operation but garbage
/// collection (done by every structure, drawn as [`Edit::Collect`]) and the welds of edges,
/// faces and whole meshes (rebuilds, tested by the weld tests).
pub fn drawn() -> impl Iterator<Item = EditOp> {
    EditOp::ALL.into_iter().filter(|op| {
        !matches!(
            op,
            EditOp::GarbageCollection | EditOp::WeldEdges | EditOp::WeldFaces | EditOp::WeldMeshes
        )
    })
}

fn edge_between<M: MeshEdit>(m: &M, a: u32, b: u32) -> Option<EdgeId> {
    let mut found = None;
    if (a as usize) < m.num_vertices() && !m.is_deleted_vertex(VertexId(a)) {
        m.vertex_edges(VertexId(a), |e| {
            let [x, y] = m.edge_vertices(e);
            if (x.0, y.0) == (a, b) || (x.0, y.0) == (b, a) {
                found = Some(e);
            }
        });
    }
    found
}

/// The face left of the directed edge a → b.
fn face_left<M: MeshEdit>(m: &M, a: u32, b: u32) -> Option<FaceId> {
    let e = edge_between(m, a, b)?;
    let mut found = None;
    m.edge_faces(e, |f| {
        let mut face = Vec::new();
        m.face_vertices(f, |v| face.push(v.0));
        let k = face.len();
        if (0..k).any(|c| face[c] == a && face[(c + 1) % k] == b) {
            found = Some(f);
        }
    });
    found
}

/// Draws an edit, mostly of elements that exist, sometimes of ones that do not. For a
/// structure of triangles only, a quarter of the faces to add get a fourth corner (which it
/// must refuse), chosen by the point the face branch does not use (no number more is drawn
/// for it).
fn draw(rng: &mut ChaCha8Rng, model: &Model, triangles_only: bool) -> Edit {
    let nv = model.positions.len().max(1) as u32;
    let nf = model.faces.len().max(1) as u32;
    let live: Vec<u32> = (0..model.positions.len() as u32)
        .filter(|&v| model.live_vertex(v))
        .collect();
    let pick_vertex = |rng: &mut ChaCha8Rng| {
        if live.is_empty() || rng.random_bool(0.05) {
            rng.random_range(0..nv + 2)
        } else {
            live[rng.random_range(0..live.len())]
        }
    };
    // A neighbour of v, mostly.
    let near = |rng: &mut ChaCha8Rng, v: u32| {
        let n = model.neighbours(v);
        if n.is_empty() || rng.random_bool(0.1) {
            pick_vertex(rng)
        } else {
            n[rng.random_range(0..n.len())]
        }
    };
    let p = DVec3::new(rng.random(), rng.random(), rng.random());
    // A box about a third of the unit cube wide, around p (the meshes' positions are mostly
    // in the unit cube).
    let around = |p: DVec3| Aabb {
        min: p - DVec3::splat(0.2),
        max: p + DVec3::splat(0.2),
    };
    match rng.random_range(0..120) {
        0..4 => Edit::AddVertex(p),
        4..12 => {
            // A triangle on a boundary edge and a third vertex, or anything.
            let a = pick_vertex(rng);
            let b = near(rng, a);
            let c = if rng.random_bool(0.5) {
                near(rng, b)
            } else {
                pick_vertex(rng)
            };
            let mut face = if rng.random_bool(0.5) {
                vec![b, a, c]
            } else {
                vec![a, b, c]
            };
            if triangles_only && p.x < 0.25 {
                let d = live.get((p.y * live.len() as f64) as usize);
                face.push(d.copied().unwrap_or(nv));
            }
            Edit::AddFace(face)
        }
        12..17 => {
            let a = pick_vertex(rng);
            Edit::DeleteFace(a, near(rng, a))
        }
        17..18 => Edit::DeleteMissingFace(nf + rng.random_range(0..3)),
        18..22 => Edit::DeleteVertex(pick_vertex(rng)),
        22..42 => {
            let a = pick_vertex(rng);
            Edit::Flip(a, near(rng, a))
        }
        42..54 => {
            let a = pick_vertex(rng);
            Edit::SplitEdge(a, near(rng, a), p)
        }
        54..64 => {
            let a = pick_vertex(rng);
            Edit::SplitFace(a, near(rng, a), p)
        }
        64..84 => {
            let a = pick_vertex(rng);
            Edit::Collapse(a, near(rng, a))
        }
        84..94 => {
            let v = pick_vertex(rng);
            let (l, r) = (near(rng, v), near(rng, v));
            Edit::SplitVertex(v, l, r, p)
        }
        94..98 => {
            // Two neighbours of one vertex: on a boundary, welding them zips it by an edge.
            // Half the time the two boundary neighbours of a boundary vertex, so that welds
            // the model allows are drawn on every open mesh, not only by chance.
            let x = pick_vertex(rng);
            let along: Vec<u32> = model
                .neighbours(x)
                .into_iter()
                .filter(|&w| model.is_boundary_edge(x, w))
                .collect();
            if along.len() == 2 && rng.random_bool(0.5) {
                Edit::Weld(along[0], along[1])
            } else {
                Edit::Weld(near(rng, x), near(rng, x))
            }
        }
        98..100 => Edit::Collect,
        100..106 => {
            // From a to another corner of the face left of a → b, mostly one that is not a
            // neighbour of a in it.
            let a = pick_vertex(rng);
            let b = near(rng, a);
            let c = match model.face_with(a, b) {
                Some((f, i)) => {
                    let face = model.faces[f].as_ref().expect("live");
                    let k = face.len();
                    if k > 3 && rng.random_bool(0.9) {
                        face[(i + 2 + rng.random_range(0..k - 3)) % k]
                    } else {
                        face[rng.random_range(0..k)]
                    }
                }
                None => pick_vertex(rng),
            };
            Edit::InsertEdge(a, b, c)
        }
        106..112 => {
            let a = pick_vertex(rng);
            Edit::DeleteEdge(a, near(rng, a))
        }
        112..114 => Edit::Select(around(p)),
        114..116 => {
            let axis = DVec3::new(rng.random(), rng.random(), rng.random()) + DVec3::X;
            Edit::Rotate(around(p), p, axis.normalize(), rng.random_range(-3.0..3.0))
        }
        116..118 => {
            let factors = DVec3::new(
                rng.random_range(0.5..2.0),
                rng.random_range(0.5..2.0),
                rng.random_range(0.5..2.0),
            );
            Edit::Scale(around(p), p, factors)
        }
        _ => Edit::Smooth,
    }
}

/// What the model says an edit of an operation the structure implements must do:
/// `Some(apply)` when it must succeed, `None` when it must be refused; `triangles_only` (the
/// structure's capability) refuses faces of more than three corners, `distinct_positions`
/// (explicit storage's) a move that leaves two live vertices at one position.
fn expect(
    model: &Model,
    edit: &Edit,
    triangles_only: bool,
    distinct_positions: bool,
) -> Option<Model> {
    let next = expect_faces(model, edit, triangles_only)?;
    if distinct_positions && !next.positions_distinct() {
        return None;
    }
    Some(next)
}

/// [`expect`] but for the rule of distinct positions.
fn expect_faces(model: &Model, edit: &Edit, triangles_only: bool) -> Option<Model> {
    let mut next = model.clone();
    let n = model.positions.len() as u32;
    match edit {
        Edit::AddVertex(p) => next.positions.push(Some(*p)),
        Edit::SetPosition(v, p) => {
            if !model.live_vertex(*v) {
                return None;
            }
            next.positions[*v as usize] = Some(*p);
        }
        Edit::AddFace(vs) => {
            let distinct = (1..vs.len()).all(|i| !vs[..i].contains(&vs[i]));
            if !distinct || vs.len() < 3 || !vs.iter().all(|&v| model.live_vertex(v)) {
                return None;
            }
            if triangles_only && vs.len() != 3 {
                return None;
            }
            if !Model::manifold(&model.soup(None, std::slice::from_ref(vs))) {
                return None;
            }
            next.faces.push(Some(vs.clone()));
        }
        Edit::DeleteMissingFace(_) | Edit::SplitMissingFace(_) => return None,
        Edit::DeleteFace(a, b) => {
            let (f, _) = model.face_with(*a, *b)?;
            if !Model::manifold(&model.soup(Some((f, None)), &[])) {
                return None;
            }
            next.faces[f] = None;
        }
        Edit::DeleteVertex(v) => {
            if !model.live_vertex(*v) {
                return None;
            }
            for f in next.faces.iter_mut() {
                if f.as_ref().is_some_and(|f| f.contains(v)) {
                    *f = None;
                }
            }
            if !Model::manifold(&next.soup(None, &[])) {
                return None;
            }
            next.positions[*v as usize] = None;
        }
        Edit::Flip(a, b) => {
            let (a, b) = (*a, *b);
            if !model.live_vertex(a) || !model.live_vertex(b) {
                return None;
            }
            let ((f1, c1), (f2, c2)) = (model.face_with(a, b)?, model.face_with(b, a)?);
            if !model.triangle(f1) || !model.triangle(f2) {
                return None;
            }
            let (x, y) = (model.third(f1, c1), model.third(f2, c2));
            if x == y || model.neighbours(x).contains(&y) {
                return None;
            }
            next.faces[f1] = Some(vec![a, y, x]);
            next.faces[f2] = Some(vec![b, x, y]);
        }
        Edit::SplitEdge(a, b, p) => {
            let (a, b) = (*a, *b);
            if !model.live_vertex(a) || !model.live_vertex(b) {
                return None;
            }
            let sides = [model.face_with(a, b), model.face_with(b, a)];
            if sides.iter().all(Option::is_none) {
                return None;
            }
            if sides.iter().flatten().any(|&(f, _)| !model.triangle(f)) {
                return None;
            }
            if let [Some((f, c)), Some((g, d))] = sides {
                if model.third(f, c) == model.third(g, d) {
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
        Edit::SplitFace(a, b, p) => {
            let (f, _) = model.face_with(*a, *b)?;
            let face = model.faces[f].clone().expect("live");
            next.positions.push(Some(*p));
            let k = face.len();
            next.faces[f] = Some(vec![face[0], face[1], n]);
            for i in 1..k {
                next.faces.push(Some(vec![face[i], face[(i + 1) % k], n]));
            }
        }
        Edit::Collapse(v0, v1) => {
            let (v0, v1) = (*v0, *v1);
            if !model.live_vertex(v0) || !model.live_vertex(v1) {
                return None;
            }
            if !model.neighbours(v0).contains(&v1) {
                return None;
            }
            let around: Vec<usize> = model
                .live_faces()
                .filter(|(_, f)| f.contains(&v0))
                .map(|(i, _)| i)
                .collect();
            if around.iter().any(|&f| !model.triangle(f)) {
                return None;
            }
            // pmp's is_collapse_ok, naively, with OpenMesh's tetrahedron test after its
            // `left == right` rule (the model tells no refusal's reason).
            let left = model.face_with(v0, v1).map(|(f, c)| model.third(f, c));
            let right = model.face_with(v1, v0).map(|(f, c)| model.third(f, c));
            for (side, a, b) in [(left, v1, v0), (right, v0, v1)] {
                if let Some(x) = side {
                    if model.is_boundary_edge(a, x) && model.is_boundary_edge(x, b) {
                        return None;
                    }
                }
            }
            if left == right {
                return None;
            }
            if let (Some(l), Some(r)) = (left, right) {
                let valence = |v: u32| model.neighbours(v).len();
                if model.neighbours(l).contains(&r) && valence(l) == 3 && valence(r) == 3 {
                    return None;
                }
            }
            if model.is_boundary_vertex(v0)
                && model.is_boundary_vertex(v1)
                && !model.is_boundary_edge(v0, v1)
            {
                return None;
            }
            let ring1 = model.neighbours(v1);
            if model
                .neighbours(v0)
                .into_iter()
                .any(|w| w != v1 && Some(w) != left && Some(w) != right && ring1.contains(&w))
            {
                return None;
            }
            for f in around {
                let face = next.faces[f].as_mut().expect("live");
                if face.contains(&v1) {
                    next.faces[f] = None;
                } else {
                    for v in face.iter_mut().filter(|v| **v == v0) {
                        *v = v1;
                    }
                }
            }
            next.positions[v0 as usize] = None;
        }
        Edit::SplitVertex(v1, vl, vr, p) => {
            let (v1, vl, vr) = (*v1, *vl, *vr);
            if [v1, vl, vr].iter().any(|&v| !model.live_vertex(v)) || vl == vr {
                return None;
            }
            let ring = model.neighbours(v1);
            if !ring.contains(&vl) || !ring.contains(&vr) || vl == v1 || vr == v1 {
                return None;
            }
            // Walk from the face with v1 → vl to the one with vr → v1 (the fan that moves).
            let (mut f, _) = model.face_with(v1, vl)?;
            let mut moved = Vec::new();
            loop {
                if moved.contains(&f) {
                    return None;
                }
                moved.push(f);
                let face = model.faces[f].as_ref().expect("live");
                let k = face.len();
                let c = face.iter().position(|&v| v == v1).expect("around v1");
                let before = face[(c + k - 1) % k];
                if before == vr {
                    break;
                }
                f = model.face_with(v1, before)?.0;
            }
            next.positions.push(Some(*p));
            for f in moved {
                for v in next.faces[f].as_mut().expect("live").iter_mut() {
                    if *v == v1 {
                        *v = n;
                    }
                }
            }
            next.faces.push(Some(vec![n, v1, vl]));
            next.faces.push(Some(vec![v1, n, vr]));
        }
        Edit::Weld(a, b) => {
            let (a, b) = (*a, *b);
            if a == b || !model.live_vertex(a) || !model.live_vertex(b) {
                return None;
            }
            for f in next.faces.iter_mut().flatten() {
                if f.contains(&a) && f.contains(&b) {
                    return None;
                }
                for v in f.iter_mut().filter(|v| **v == b) {
                    *v = a;
                }
            }
            if !Model::manifold(&next.soup(None, &[])) {
                return None;
            }
            next.positions[b as usize] = None;
        }
        Edit::Collect => next.collect(),
        Edit::InsertEdge(a, b, c) => {
            let (a, c) = (*a, *c);
            let (f, i) = model.face_with(a, *b)?;
            if !model.live_vertex(c) || triangles_only {
                return None;
            }
            let face = model.faces[f].clone().expect("live");
            let k = face.len();
            let j = face.iter().position(|&v| v == c)?;
            // Not a, nor a neighbour of a in the face.
            if j == i || j == (i + 1) % k || (j + 1) % k == i {
                return None;
            }
            let one: Vec<u32> = (0..=(j + k - i) % k).map(|t| face[(i + t) % k]).collect();
            let two: Vec<u32> = (0..=(i + k - j) % k).map(|t| face[(j + t) % k]).collect();
            next.faces[f] = Some(one);
            next.faces.push(Some(two));
            if !Model::manifold(&next.soup(None, &[])) {
                return None;
            }
        }
        Edit::DeleteEdge(a, b) => {
            let (a, b) = (*a, *b);
            if !model.live_vertex(a) || !model.live_vertex(b) || triangles_only {
                return None;
            }
            let ((f1, i1), (f2, i2)) = (model.face_with(a, b)?, model.face_with(b, a)?);
            if f1 == f2 {
                return None;
            }
            let (one, two) = (
                model.faces[f1].clone().expect("live"),
                model.faces[f2].clone().expect("live"),
            );
            // one runs a → b at i1, two runs b → a at i2: one from b round to a, then two
            // after a up to before b.
            let mut merged: Vec<u32> = (1..=one.len()).map(|t| one[(i1 + t) % one.len()]).collect();
            merged.extend((2..two.len()).map(|t| two[(i2 + t) % two.len()]));
            if (1..merged.len()).any(|t| merged[..t].contains(&merged[t])) {
                return None;
            }
            next.faces[f1] = Some(merged);
            next.faces[f2] = None;
            if !Model::manifold(&next.soup(None, &[])) {
                return None;
            }
        }
        Edit::Select(_) => {}
        Edit::Rotate(b, centre, axis, angle) => {
            let rotation = DQuat::from_axis_angle(*axis, *angle);
            for v in model.vertices_in(b) {
                let p = next.positions[v as usize].as_mut().expect("live");
                *p = rotate_point(*p, *centre, rotation);
            }
        }
        Edit::Scale(b, centre, factors) => {
            for v in model.vertices_in(b) {
                let p = next.positions[v as usize].as_mut().expect("live");
                *p = scale_point(*p, *centre, *factors);
            }
        }
        Edit::Smooth => {
            for v in 0..model.positions.len() as u32 {
                if !model.live_vertex(v) || model.is_boundary_vertex(v) {
                    continue;
                }
                let ring = model.neighbours(v);
                let mean = laplacian_mean(
                    ring.iter()
                        .map(|&w| model.positions[w as usize].expect("live")),
                );
                if let Some(p) = mean {
                    next.positions[v as usize] = Some(p);
                }
            }
        }
    }
    Some(next)
}

/// Applies `edit` to the structure; `None` when it cannot be asked (the structure has no edge
/// or face between the vertices named), which the model must then refuse.
fn apply<M: MeshEdit>(m: &mut M, edit: &Edit) -> Option<Result<(), Error>> {
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
fn face_set<M: MeshEdit>(m: &M) -> Vec<Vec<u32>> {
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

/// The starting mesh of a seed: a canonical mesh or a random one, whichever `M` builds.
pub fn start_mesh(seed: u64) -> PolygonSoup {
    let canonical = meshes::canonical();
    let pick = (seed % (canonical.len() as u64 + 4)) as usize;
    if pick < canonical.len() {
        canonical[pick].soup.clone()
    } else {
        meshes::random_mesh(
            seed,
            RandomMeshParams {
                triangles_only: !seed.is_multiple_of(3),
                max_side: 5,
                keep: 0.9,
            },
        )
    }
}

/// Runs `steps` random edits of `seed` on `M`; `Err` describes the first disagreement.
/// Returns how many of the drawn edits succeeded and how many were refused (an operation `M`
/// does not implement, refused as [`Refusal::NotImplemented`], among them).
///
/// An edit of an operation `M` implements ([`MeshEdit::supports`], see [`Edit::op`]) must be
/// done exactly when the model allows it; one of an operation it does not implement must be
/// refused with [`Refusal::NotImplemented`] whatever the model says, and change nothing. A
/// structure of triangles only (`M::capabilities().triangles_only`) is also asked to add
/// faces of four corners, which it must refuse. Beside the drawn edits, from a stream of
/// their own, vertices are moved (`set_position`, refused where there is no such vertex)
/// and faces that do not exist split (refused).
pub fn run<M: MeshEdit>(seed: u64, steps: usize) -> Result<(usize, usize), String> {
    run_with::<M>(seed, steps, false)
}

/// [`run`], except that on a start mesh with polygons an edit the model allows may be refused
/// with [`Refusal::NotImplemented`] (and must then change nothing): for a library whose
/// polygon kernel lacks the triangle operations (OpenMesh's PolyMesh has no flip, 2-to-4
/// split or vertex split).
pub fn run_with<M: MeshEdit>(
    seed: u64,
    steps: usize,
    not_implemented_on_polygons: bool,
) -> Result<(usize, usize), String> {
    run_tally::<M>(seed, steps, not_implemented_on_polygons).map(|t| (t.done, t.refused))
}

/// How many vertex welds the random sequences of `seeds` did and how many they had refused
/// (each checked as in [`run_with`], with its `not_implemented_on_polygons`): the suite's
/// evidence that welds the model allows are drawn and done, and welds it forbids drawn and
/// refused, not only one of the two.
pub fn weld_counts<M: MeshEdit>(
    seeds: std::ops::Range<u64>,
    steps: usize,
    not_implemented_on_polygons: bool,
) -> Result<(usize, usize), String> {
    let (mut done, mut refused) = (0, 0);
    for seed in seeds {
        let tally = run_tally::<M>(seed, steps, not_implemented_on_polygons)
            .map_err(|msg| format!("seed {seed}: {msg}"))?;
        done += tally.welds;
        refused += tally.welds_refused;
    }
    Ok((done, refused))
}

/// The suite's vertex-weld test, nothing where `M` does not weld: the chosen cases
/// ([`weld_vertex_cases`](crate::testing::weld::weld_vertex_cases)) and the welds done in 200
/// random sequences ([`weld_counts`], with `not_implemented_on_polygons` as in
/// [`run_with`]), enough of each to show that welds are both done and refused. Panics on a
/// disagreement.
pub fn vertex_welds<M: MeshEdit>(not_implemented_on_polygons: bool) {
    if !M::supports(EditOp::WeldVertices) {
        return;
    }
    let cases = crate::testing::weld::weld_vertex_cases::<M>()
        .unwrap_or_else(|msg| panic!("{}: {msg}", M::NAME));
    assert!(cases >= 8, "only {cases} weld cases ran");
    let (done, refused) = weld_counts::<M>(0..200, 40, not_implemented_on_polygons)
        .unwrap_or_else(|msg| panic!("{msg}"));
    assert!(done >= 20, "only {done} random welds done");
    assert!(refused >= 20, "only {refused} random welds refused");
}

/// The count test of a structure that implements a subset of the operations (the
/// `offered_operations` arm of [`edit_conformance!`](macro@crate::edit_conformance)): over
/// the random sequences of 60 seeds, each checked as in [`run`], every operation the
/// sequences draw ([`drawn`]) that `M` implements was done at least 10 times and, but for
/// adding a vertex (which the model never refuses), an edge split (refused only where its two
/// triangles share their third corner), the weld ([`vertex_welds`]) and the operations on
/// positions but the move of one vertex (refused only for a vertex that does not exist, which
/// a box selection never names), refused at least once; every one it does not implement was drawn and refused as not implemented at least
/// 10 times; vertices were moved; and a structure of triangles only that adds faces refused
/// at least 10 faces of four corners the model allows a polygon structure. Panics otherwise.
pub fn offered_operations<M: MeshEdit>() {
    let mut tally = Tally::default();
    for seed in 0..60 {
        let t = run_tally::<M>(seed, 40, false)
            .unwrap_or_else(|msg| panic!("{} on edit seed {seed}: {msg}", M::NAME));
        tally.add(t);
    }
    let count = |by: &BTreeMap<EditOp, usize>, op| by.get(&op).copied().unwrap_or(0);
    for op in drawn() {
        if M::supports(op) {
            let done = count(&tally.done_by, op);
            assert!(done >= 10, "{}: {op} done {done} times: {tally:?}", M::NAME);
            // The operations on positions are refused only for a vertex that does not
            // exist, which the box selections never name.
            let never_refused = [
                EditOp::AddVertex,
                EditOp::SplitEdge,
                EditOp::WeldVertices,
                EditOp::Select,
                EditOp::RotateSelection,
                EditOp::ScaleSelection,
                EditOp::Smooth,
            ];
            if !never_refused.contains(&op) {
                let refused = count(&tally.refused_by, op);
                assert!(refused >= 1, "{}: {op} never refused: {tally:?}", M::NAME);
            }
        } else {
            let refused = count(&tally.not_implemented, op);
            assert!(
                refused >= 10,
                "{}: {op}, not implemented, refused as such {refused} times: {tally:?}",
                M::NAME
            );
        }
    }
    assert!(tally.moved >= 20, "{}: {tally:?}", M::NAME);
    if M::capabilities().triangles_only && M::supports(EditOp::AddFace) {
        assert!(tally.polygons_refused >= 10, "{}: {tally:?}", M::NAME);
    }
}

/// What a run did.
#[derive(Debug, Default)]
struct Tally {
    /// Drawn edits done.
    done: usize,
    /// Drawn edits refused (as the model does, or as not implemented).
    refused: usize,
    welds: usize,
    welds_refused: usize,
    /// Per operation, edits done.
    done_by: BTreeMap<EditOp, usize>,
    /// Per operation `M` implements, edits it refused (as the model does).
    refused_by: BTreeMap<EditOp, usize>,
    /// Per operation `M` does not implement, edits it refused as not implemented.
    not_implemented: BTreeMap<EditOp, usize>,
    /// Faces of more than three corners refused that only a structure of triangles only
    /// refuses (the model would allow a polygon structure to add them).
    polygons_refused: usize,
    /// Vertices moved.
    moved: usize,
}

impl Tally {
    fn add(&mut self, other: Tally) {
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

fn run_tally<M: MeshEdit>(
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

/// The edits beside a drawn one, now and then: a vertex moved (a live one, or one past the
/// last: a deleted vertex's position is no part of the contract), a face that does not exist
/// split, or a face added on the boundary ([`boundary_face`]).
fn besides_edits(rng: &mut ChaCha8Rng, model: &Model, triangles_only: bool) -> Vec<Edit> {
    match rng.random_range(0..16) {
        0..2 => {
            let n = model.positions.len() as u32;
            let live: Vec<u32> = (0..n).filter(|&v| model.live_vertex(v)).collect();
            let v = match live.len() {
                0 => n,
                k if rng.random_bool(0.9) => live[rng.random_range(0..k)],
                _ => n + rng.random_range(0..2),
            };
            let p = DVec3::new(rng.random(), rng.random(), rng.random());
            vec![Edit::SetPosition(v, p)]
        }
        2 => vec![Edit::SplitMissingFace(rng.random_range(0..3))],
        3..5 => boundary_face(rng, model, triangles_only),
        _ => Vec::new(),
    }
}

/// A face on a boundary edge, its third corner an unused vertex or a neighbour of the edge's
/// ends: faces the model allows, drawn on purpose (the random faces of [`draw`] seldom are).
/// For a structure of triangles only, half of them get a fourth corner, a vertex added just
/// before (the face is then one a polygon structure adds), which it must refuse. Nothing on a
/// mesh without boundary.
fn boundary_face(rng: &mut ChaCha8Rng, model: &Model, triangles_only: bool) -> Vec<Edit> {
    boundary_face_of(rng, model, triangles_only).unwrap_or_default()
}

fn boundary_face_of(
    rng: &mut ChaCha8Rng,
    model: &Model,
    triangles_only: bool,
) -> Option<Vec<Edit>> {
    let boundary: Vec<(u32, u32)> = model
        .live_faces()
        .flat_map(|(_, f)| (0..f.len()).map(move |i| (f[i], f[(i + 1) % f.len()])))
        .filter(|&(x, y)| model.face_with(y, x).is_none())
        .collect();
    let &(x, y) = boundary.get(rng.random_range(0..boundary.len().max(1)))?;
    let mut unused: Vec<u32> = (0..model.positions.len() as u32)
        .filter(|&v| model.live_vertex(v) && model.neighbours(v).is_empty())
        .collect();
    let mut ring: Vec<u32> = model.neighbours(x);
    ring.extend(model.neighbours(y));
    ring.retain(|&w| w != x && w != y);
    let mut corner = |rng: &mut ChaCha8Rng| {
        if !unused.is_empty() && (ring.is_empty() || rng.random_bool(0.5)) {
            Some(unused.swap_remove(rng.random_range(0..unused.len())))
        } else if !ring.is_empty() {
            Some(ring[rng.random_range(0..ring.len())])
        } else {
            None
        }
    };
    let mut face = vec![y, x, corner(rng)?];
    let mut edits = Vec::new();
    if triangles_only && rng.random_bool(0.5) {
        let p = DVec3::new(rng.random(), rng.random(), rng.random());
        edits.push(Edit::AddVertex(p));
        face.push(model.positions.len() as u32);
    }
    edits.push(Edit::AddFace(face));
    Some(edits)
}

/// Applies one edit to the structure and, when the structure must do it, to the model, and
/// checks the two against each other; `drawn` edits count in `done` and `refused`. `Err`
/// continues a message that names the edit.
fn check_edit<M: MeshEdit>(
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

/// Generates the editing tests of every structure the registry marks `[editable]`: the
/// callback of [`for_each_structure!`](crate::for_each_structure), so that the capability
/// in the registry is the enrolment.
///
/// ```ignore
/// topolab_structures::for_each_structure!(topolab_structures::editing_suite);
/// ```
#[macro_export]
macro_rules! editing_suite {
    (@one $module:ident, $ty:ty $(,)?) => {};
    (@one $module:ident, $ty:ty, editable) => {
        $crate::edit_conformance!($module, $ty);
    };
    ($($module:ident => $ty:ty $([$($capability:ident),*])?),* $(,)?) => {
        $( $crate::editing_suite!(@one $module, $ty, $($($capability),*)?); )*

        #[test]
        fn the_registry_says_which_structures_are_editable() {
            let tested: Vec<&str> = [$($crate::editing_suite!(@name $ty, $($($capability),*)?)),*]
                .into_iter()
                .flatten()
                .collect();
            assert_eq!(tested, $crate::registry::editable_names());
            // And run-time choice by name reaches exactly those, each as itself.
            struct Name;
            impl $crate::registry::EditVisitor for Name {
                type Output = &'static str;
                fn visit<M: $crate::MeshEdit>(self) -> &'static str {
                    M::NAME
                }
            }
            for name in $crate::registry::NAMES {
                let got = $crate::registry::visit_editable(name, Name);
                assert_eq!(got, tested.contains(name).then_some(*name), "{name}");
            }
            assert!(tested.len() >= 5, "{tested:?}");
        }
    };
    (@name $ty:ty $(,)?) => {
        None
    };
    (@name $ty:ty, editable) => {
        Some(<$ty as $crate::MeshTopology>::NAME)
    };
}

/// Generates the editing tests of one structure: seeded random sequences of edits
/// ([`run`]), each checked against the model and the oracle, as a proptest, and counts over
/// fixed seeds. An operation the structure does not implement ([`MeshEdit::supports`]) must
/// be refused as not implemented, nothing changed.
///
/// With two arguments, a structure that implements every operation but perhaps the vertex
/// weld and the insertion and deletion of an edge (which structures of triangles only do not
/// offer): its counts ask for more than 400 edits done and 100 refused over 40 seeds and,
/// per operation, those of [`offered_operations`](crate::testing::editing::offered_operations),
/// and the weld tests run (the weld of vertices only where it implements it). A third argument:
/// - `not_implemented_on_polygons` runs [`run_with`] instead (a library's polygon kernel that
///   refuses the triangle operations);
/// - `offered_operations` enrols a structure that implements a subset of the operations (the
///   Rust crates of `topolab-peers`): the same random sequences, and the counts of
///   [`offered_operations`](crate::testing::editing::offered_operations) (every operation it
///   implements done, every other refused as not implemented); the weld tests only for the
///   welds it implements ([`EditOp::WeldMeshes`], [`EditOp::WeldVertices`]).
///
/// ```ignore
/// topolab_structures::edit_conformance!(index_half_edge, topolab_structures::IndexHalfEdge);
/// topolab_structures::edit_conformance!(openmesh, topolab::openmesh::OpenMesh, not_implemented_on_polygons);
/// topolab_structures::edit_conformance!(lox_half_edge, topolab_peers::LoxHalfEdge, offered_operations);
/// ```
#[macro_export]
macro_rules! edit_conformance {
    ($module:ident, $ty:ty) => {
        mod $module {
            #[allow(unused_imports)]
            use super::*;

            $crate::testing::proptest::proptest! {
                #![proptest_config($crate::testing::proptest::prelude::ProptestConfig::with_cases(64))]
                #[test]
                fn random_edit_sequences(seed in $crate::testing::proptest::prelude::any::<u64>()) {
                    if let Err(msg) = $crate::testing::editing::run::<$ty>(seed, 40) {
                        panic!("{} on edit seed {seed}: {msg}", <$ty as $crate::MeshTopology>::NAME);
                    }
                }
            }

            #[test]
            fn halves_weld_back_into_the_original_and_bad_welds_are_refused() {
                let cut = $crate::testing::weld::weld_halves::<$ty>()
                    .unwrap_or_else(|msg| panic!("{}: {msg}", <$ty as $crate::MeshTopology>::NAME));
                assert!(cut >= 3, "only {cut} meshes cut and welded");
            }

            #[test]
            fn most_edits_succeed_and_some_are_refused() {
                let (mut done, mut refused) = (0, 0);
                for seed in 0..40 {
                    let (d, r) = $crate::testing::editing::run::<$ty>(seed, 40)
                        .unwrap_or_else(|msg| panic!("seed {seed}: {msg}"));
                    done += d;
                    refused += r;
                }
                assert!(done > 400 && refused > 100, "{done} edits done, {refused} refused");
            }

            #[test]
            fn edge_and_face_welds_give_the_meshes_built_directly_or_are_refused() {
                if !<$ty as $crate::MeshEdit>::supports($crate::EditOp::WeldEdges) {
                    return;
                }
                let checked = $crate::testing::weld::weld_edge_and_face_cases::<$ty>()
                    .unwrap_or_else(|msg| panic!("{}: {msg}", <$ty as $crate::MeshTopology>::NAME));
                assert_eq!(checked, 8);
            }

            #[test]
            fn vertex_welds_zip_and_close_boundaries_or_are_refused() {
                $crate::testing::editing::vertex_welds::<$ty>(false);
            }

            #[test]
            fn every_operation_is_done_and_refused_or_refused_as_not_implemented() {
                $crate::testing::editing::offered_operations::<$ty>();
            }
        }
    };
    // A library whose polygon kernel lacks the triangle operations ([`run_with`]).
    ($module:ident, $ty:ty, not_implemented_on_polygons) => {
        mod $module {
            #[allow(unused_imports)]
            use super::*;

            $crate::testing::proptest::proptest! {
                #![proptest_config($crate::testing::proptest::prelude::ProptestConfig::with_cases(64))]
                #[test]
                fn random_edit_sequences(seed in $crate::testing::proptest::prelude::any::<u64>()) {
                    if let Err(msg) = $crate::testing::editing::run_with::<$ty>(seed, 40, true) {
                        panic!("{} on edit seed {seed}: {msg}", <$ty as $crate::MeshTopology>::NAME);
                    }
                }
            }

            #[test]
            fn most_edits_succeed_and_some_are_refused() {
                let (mut done, mut refused) = (0, 0);
                for seed in 0..40 {
                    let (d, r) = $crate::testing::editing::run_with::<$ty>(seed, 40, true)
                        .unwrap_or_else(|msg| panic!("seed {seed}: {msg}"));
                    done += d;
                    refused += r;
                }
                assert!(done > 400 && refused > 100, "{done} edits done, {refused} refused");
            }

            #[test]
            fn edge_and_face_welds_give_the_meshes_built_directly_or_are_refused() {
                if !<$ty as $crate::MeshEdit>::supports($crate::EditOp::WeldEdges) {
                    return;
                }
                let checked = $crate::testing::weld::weld_edge_and_face_cases::<$ty>()
                    .unwrap_or_else(|msg| panic!("{}: {msg}", <$ty as $crate::MeshTopology>::NAME));
                assert_eq!(checked, 8);
            }

            #[test]
            fn vertex_welds_zip_and_close_boundaries_or_are_refused() {
                $crate::testing::editing::vertex_welds::<$ty>(true);
            }
        }
    };
    // A structure that implements a subset of the operations ([`offered_operations`]).
    ($module:ident, $ty:ty, offered_operations) => {
        mod $module {
            #[allow(unused_imports)]
            use super::*;

            $crate::testing::proptest::proptest! {
                #![proptest_config($crate::testing::proptest::prelude::ProptestConfig::with_cases(64))]
                #[test]
                fn random_edit_sequences(seed in $crate::testing::proptest::prelude::any::<u64>()) {
                    if let Err(msg) = $crate::testing::editing::run::<$ty>(seed, 40) {
                        panic!("{} on edit seed {seed}: {msg}", <$ty as $crate::MeshTopology>::NAME);
                    }
                }
            }

            #[test]
            fn offered_operations_are_done_and_the_others_refused_as_not_implemented() {
                $crate::testing::editing::offered_operations::<$ty>();
            }

            #[test]
            fn halves_weld_back_into_the_original_and_bad_welds_are_refused() {
                if !<$ty as $crate::MeshEdit>::supports($crate::EditOp::WeldMeshes) {
                    return;
                }
                let cut = $crate::testing::weld::weld_halves::<$ty>()
                    .unwrap_or_else(|msg| panic!("{}: {msg}", <$ty as $crate::MeshTopology>::NAME));
                assert!(cut >= 3, "only {cut} meshes cut and welded");
            }

            #[test]
            fn edge_and_face_welds_give_the_meshes_built_directly_or_are_refused() {
                if !<$ty as $crate::MeshEdit>::supports($crate::EditOp::WeldEdges) {
                    return;
                }
                let checked = $crate::testing::weld::weld_edge_and_face_cases::<$ty>()
                    .unwrap_or_else(|msg| panic!("{}: {msg}", <$ty as $crate::MeshTopology>::NAME));
                assert_eq!(checked, 8);
            }

            #[test]
            fn vertex_welds_zip_and_close_boundaries_or_are_refused() {
                $crate::testing::editing::vertex_welds::<$ty>(false);
            }
        }
    };
}
