//! A vertex's neighbourhood over the queries of [`MeshTopology`] alone (its faces, their
//! corners, its neighbours, which of its sides are boundary): what the face-rewriting
//! structures ([`crate::core::rewrite`]) and the collapse test
//! ([`check_collapse`](crate::core::link::check_collapse)) are built on.
//! Each helper allocates a small vector: they serve the editing operations, never a timed query.

use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::topology::MeshTopology;

pub(crate) use crate::core::offers::refuse;

pub(crate) fn corners<M: MeshTopology>(m: &M, f: FaceId) -> Vec<VertexId> {
    let mut out = Vec::with_capacity(4);
    m.face_vertices(f, |v| out.push(v));
    out
}

pub(crate) fn faces_at<M: MeshTopology>(m: &M, v: VertexId) -> Vec<FaceId> {
    let mut out = Vec::with_capacity(8);
    m.vertex_faces(v, |f| out.push(f));
    out.sort_unstable();
    out.dedup();
    out
}

/// The face that runs a → b, with its corners and the corner of a.
pub(crate) fn face_with<M: MeshTopology>(
    m: &M,
    a: VertexId,
    b: VertexId,
) -> Option<(FaceId, Vec<VertexId>, usize)> {
    faces_at(m, a).into_iter().find_map(|f| {
        let c = corners(m, f);
        let k = c.len();
        (0..k)
            .find(|&i| c[i] == a && c[(i + 1) % k] == b)
            .map(|i| (f, c, i))
    })
}

/// The vertices that share a face side with v, sorted.
pub(crate) fn neighbours<M: MeshTopology>(m: &M, v: VertexId) -> Vec<VertexId> {
    let mut out = Vec::new();
    for f in faces_at(m, v) {
        let c = corners(m, f);
        let k = c.len();
        for i in 0..k {
            if c[i] == v {
                out.push(c[(i + 1) % k]);
                out.push(c[(i + k - 1) % k]);
            }
        }
    }
    out.sort_unstable();
    out.dedup();
    out
}

/// The faces of edge `e` = {a, b}, each with its corners and the corner where it leaves the
/// end it runs from: `[the face running a → b, the one running b → a]`. The structure's own
/// edge → faces query (O(1) in the edge lists), not a search around a vertex.
#[allow(clippy::type_complexity)]
pub(crate) fn sides_of<M: MeshTopology>(
    m: &M,
    e: EdgeId,
    a: VertexId,
    b: VertexId,
) -> [Option<(FaceId, Vec<VertexId>, usize)>; 2] {
    let mut out = [None, None];
    m.edge_faces(e, |f| {
        let c = corners(m, f);
        let k = c.len();
        for i in 0..k {
            let (x, y) = (c[i], c[(i + 1) % k]);
            if (x, y) == (a, b) {
                out[0] = Some((f, c.clone(), i));
            } else if (x, y) == (b, a) {
                out[1] = Some((f, c.clone(), i));
            }
        }
    });
    out
}

/// Do `a` and `b` share a face side? One rotation around `a`, no allocation.
pub(crate) fn adjacent<M: MeshTopology>(m: &M, a: VertexId, b: VertexId) -> bool {
    let mut found = false;
    m.vertex_vertices(a, |w| found |= w == b);
    found
}

pub(crate) fn is_boundary_edge<M: MeshTopology>(m: &M, a: VertexId, b: VertexId) -> bool {
    face_with(m, a, b).is_none() || face_with(m, b, a).is_none()
}

pub(crate) fn is_boundary_vertex<M: MeshTopology>(m: &M, v: VertexId) -> bool {
    neighbours(m, v)
        .into_iter()
        .any(|w| is_boundary_edge(m, v, w))
}
