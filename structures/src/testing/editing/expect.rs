//! What the model says an edit must do: done (and how the model changes) or refused.

use super::edit::Edit;
use super::model::Model;
use crate::algorithms::select::{laplacian_mean, rotate_point, scale_point};
use glam::DQuat;

/// What the model says an edit of an operation the structure implements must do:
/// `Some(apply)` when it must succeed, `None` when it must be refused; `triangles_only` (the
/// structure's capability) refuses faces of more than three corners, `distinct_positions`
/// (explicit storage's) a move that leaves two live vertices at one position.
pub(super) fn expect(
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
pub(super) fn expect_faces(model: &Model, edit: &Edit, triangles_only: bool) -> Option<Model> {
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

// The model's collapse is the expectation of a drawn collapse: it lives beside it.
impl Model {
    /// The model after collapsing `v0` into `v1`, or `None` when the collapse must be refused
    /// (pmp-library's `is_collapse_ok` with the tetrahedron test of OpenMesh's Decimater,
    /// worked out on the face list).
    pub fn collapse(&self, v0: u32, v1: u32) -> Option<Model> {
        expect(self, &Edit::Collapse(v0, v1), false, false)
    }
}
