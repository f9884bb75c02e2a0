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
use topolab_structures::{EdgeId, EditOp, Error, FaceId, MeshTopology, Refusal, Result, VertexId};

/// The lab's refusal of `op` by `M`.
pub(crate) fn refuse<M: MeshTopology>(op: EditOp, reason: Refusal) -> Error {
    Error::EditRefused {
        structure: M::NAME,
        op,
        reason,
    }
}

/// `op` refused as one the crate does not offer.
pub(crate) fn not_implemented<M: MeshTopology, T>(op: EditOp) -> Result<T> {
    Err(refuse::<M>(op, Refusal::NotImplemented))
}

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

/// One face of an edge: the face, its corners, and the corner where it leaves the end it
/// runs from.
pub(crate) type Side = (FaceId, Vec<VertexId>, usize);

/// The faces of edge `e` = {a, b} through the structure's own queries (R10, R12, R20):
/// `[the face running a → b, the one running b → a]`.
pub(crate) fn sides_of<M: MeshTopology>(m: &M, e: EdgeId) -> [Option<Side>; 2] {
    let [a, b] = m.edge_vertices(e);
    let mut out = [None, None];
    m.edge_faces(e, |f| {
        let mut c = Vec::with_capacity(3);
        m.face_vertices(f, |v| c.push(v));
        let k = c.len();
        for i in 0..k {
            if (c[i], c[(i + 1) % k]) == (a, b) {
                out[0] = Some((f, c.clone(), i));
            } else if (c[i], c[(i + 1) % k]) == (b, a) {
                out[1] = Some((f, c.clone(), i));
            }
        }
    });
    out
}

/// Do `a` and `b` share an edge? One turn around `a`.
pub(crate) fn adjacent<M: MeshTopology>(m: &M, a: VertexId, b: VertexId) -> bool {
    let mut found = false;
    m.vertex_vertices(a, |w| found |= w == b);
    found
}

/// The lab's checks of a flip of edge `e` (an edge of the mesh), as the face-rewriting
/// structures make them: two faces ([`Refusal::BoundaryEdge`]), both triangles
/// ([`Refusal::NotTriangles`]), and their third corners distinct and not yet joined
/// ([`Refusal::EdgeExists`]).
pub(crate) fn check_flip<M: MeshTopology>(m: &M, e: EdgeId) -> Result<()> {
    let op = EditOp::FlipEdge;
    let [Some((_, c1, i1)), Some((_, c2, i2))] = sides_of(m, e) else {
        return Err(refuse::<M>(op, Refusal::BoundaryEdge));
    };
    if c1.len() != 3 || c2.len() != 3 {
        return Err(refuse::<M>(op, Refusal::NotTriangles));
    }
    let (x, y) = (c1[(i1 + 2) % 3], c2[(i2 + 2) % 3]);
    if x == y || adjacent(m, x, y) {
        return Err(refuse::<M>(op, Refusal::EdgeExists));
    }
    Ok(())
}

/// The lab's checks of a split of edge `e` (an edge of the mesh): at least one face
/// ([`Refusal::NoSuchElement`]), triangles ([`Refusal::NotTriangles`]), and two faces that do
/// not share their third corner (the new edge to it would have four faces:
/// [`Refusal::EdgeExists`]).
pub(crate) fn check_split_edge<M: MeshTopology>(m: &M, e: EdgeId) -> Result<()> {
    let op = EditOp::SplitEdge;
    let sides: Vec<Side> = sides_of(m, e).into_iter().flatten().collect();
    if sides.is_empty() {
        return Err(refuse::<M>(op, Refusal::NoSuchElement));
    }
    if sides.iter().any(|(_, c, _)| c.len() != 3) {
        return Err(refuse::<M>(op, Refusal::NotTriangles));
    }
    if let [(_, c1, i1), (_, c2, i2)] = &sides[..] {
        if c1[(i1 + 2) % 3] == c2[(i2 + 2) % 3] {
            return Err(refuse::<M>(op, Refusal::EdgeExists));
        }
    }
    Ok(())
}
