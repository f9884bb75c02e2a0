//! [`MeshEdit`](topolab_structures::MeshEdit) for the peers: each operation a crate offers is
//! done by the crate's own call, after the lab's own checks have said the edit is legal, so
//! that no crate sees an edit it would panic on or carry out wrongly; an operation a crate
//! does not offer is refused with [`Refusal::NotImplemented`] and nothing is emulated. Each
//! adapter's module docs give the table of its calls, costs and refusals.
//!
//! The checks are the lab's: ids in range ([`Refusal::NoSuchElement`]), a face of at least
//! three distinct corners ([`Refusal::BadFace`]), and for a new face the face-rewriting
//! structures' test that every vertex it touches keeps one fan with each directed edge once
//! ([`topolab_structures::core::rewrite::check_result`]).

pub mod baby_shark;
pub mod lox;
pub mod tri_mesh;

use topolab_structures::core::rewrite::check_result;
pub(crate) use topolab_structures::core::rewrite::{check_flip, check_split_edge};
use topolab_structures::{refuse, EditOp, MeshTopology, Refusal, Result, VertexId};

/// Is `v` a vertex of `m` (for an adapter that never deletes one)?
pub(crate) fn in_range<M: MeshTopology>(m: &M, v: VertexId) -> bool {
    v.index() < m.num_vertices()
}

/// The lab's checks of `add_face(vertices)`, in the order of the face-rewriting structures'
/// `add_face`: at least three distinct corners ([`Refusal::BadFace`]), then (for a crate of
/// triangles) three ([`Refusal::NotTriangles`]), every corner a vertex
/// ([`Refusal::NoSuchElement`]), and the result an oriented manifold with one fan per vertex
/// ([`check_result`]: [`Refusal::NonManifoldEdge`], [`Refusal::NonManifoldVertex`]).
pub(crate) fn check_add_face<M: MeshTopology>(
    m: &M,
    vertices: &[VertexId],
    triangles_only: bool,
) -> Result<()> {
    let op = EditOp::AddFace;
    let distinct = (1..vertices.len()).all(|i| !vertices[..i].contains(&vertices[i]));
    if vertices.len() < 3 || !distinct {
        return Err(refuse::<M>(op, Refusal::BadFace));
    }
    if triangles_only && vertices.len() != 3 {
        return Err(refuse::<M>(op, Refusal::NotTriangles));
    }
    if !vertices.iter().all(|&v| in_range(m, v)) {
        return Err(refuse::<M>(op, Refusal::NoSuchElement));
    }
    check_result(m, &[], &[vertices.to_vec()], vertices).map_err(|r| refuse::<M>(op, r))
}

/// How many sides of the face `vertices` have no edge yet (the edges `add_face` creates).
pub(crate) fn new_sides<M: MeshTopology>(m: &M, vertices: &[VertexId]) -> usize {
    let k = vertices.len();
    (0..k)
        .filter(|&i| {
            let (a, b) = (vertices[i], vertices[(i + 1) % k]);
            let mut found = false;
            m.vertex_vertices(a, |w| found |= w == b);
            !found
        })
        .count()
}
