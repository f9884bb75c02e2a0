//! One random edit ([`Edit`]) and how the suite draws them: mostly of elements that exist,
//! sometimes of ones that do not, and faces on the boundary drawn on purpose.

use super::model::Model;
use crate::algorithms::select::Aabb;
use crate::core::edit::{EditOp, MeshEdit};
use crate::core::ids::{EdgeId, FaceId, VertexId};
use glam::DVec3;
use rand::Rng;
use rand_chacha::ChaCha8Rng;

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

pub(super) fn edge_between<M: MeshEdit>(m: &M, a: u32, b: u32) -> Option<EdgeId> {
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
pub(super) fn face_left<M: MeshEdit>(m: &M, a: u32, b: u32) -> Option<FaceId> {
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
pub(super) fn draw(rng: &mut ChaCha8Rng, model: &Model, triangles_only: bool) -> Edit {
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

/// The edits beside a drawn one, now and then: a vertex moved (a live one, or one past the
/// last: a deleted vertex's position is no part of the contract), a face that does not exist
/// split, or a face added on the boundary ([`boundary_face`]).
pub(super) fn besides_edits(
    rng: &mut ChaCha8Rng,
    model: &Model,
    triangles_only: bool,
) -> Vec<Edit> {
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
pub(super) fn boundary_face(
    rng: &mut ChaCha8Rng,
    model: &Model,
    triangles_only: bool,
) -> Vec<Edit> {
    boundary_face_of(rng, model, triangles_only).unwrap_or_default()
}

pub(super) fn boundary_face_of(
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
