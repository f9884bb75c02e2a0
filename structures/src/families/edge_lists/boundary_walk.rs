//! Boundary curves for structures that store each edge's faces and answer the successor of an
//! edge in a face (the edge list, the winged-edge structure).
//!
//! One scan of the edges finds the boundary edges; each curve is then walked from boundary
//! edge to boundary edge by rotating around their shared vertex through the faces
//! ([`next_boundary_edge`]). Nothing is allocated beyond the caller's buffer: while the
//! curves are built, `out.edges` starts with the sorted boundary edges (to look up an edge's
//! rank by binary search) and `out.starts` starts with a bitmap of the ranks already walked;
//! both prefixes are removed at the end. Cost: O(n1) for the scan, O(∂n1 log ∂n1) for the
//! look-ups, plus the rotations (a few successor queries per boundary edge).

use crate::core::ids::{EdgeId, FaceId};
use crate::core::topology::{BoundaryCurves, MeshTopology};

/// The one face of boundary edge `e`.
fn only_face<M: MeshTopology>(m: &M, e: EdgeId) -> Option<FaceId> {
    let mut face = None;
    m.edge_faces(e, |f| face = Some(f));
    face
}

/// The boundary edge that follows boundary edge `e` along its curve, walking in the direction
/// in which `e`'s face traverses it: if `e` runs a → b, the boundary edge that leaves b.
///
/// From `e` the walk takes the successor in `e`'s face (it leaves b), and while that edge is
/// interior it crosses to the edge's other face (where the edge enters b) and takes the
/// successor there (which leaves b again). It stays in the fan of faces of `e`, so a vertex
/// with several fans (a bowtie) gives each fan's boundary its own, well-defined continuation.
/// `None` only on a broken structure.
fn next_boundary_edge<M: MeshTopology>(m: &M, e: EdgeId) -> Option<EdgeId> {
    let mut face = only_face(m, e)?;
    let mut leaving = m.edge_successor(e, face)?;
    while !m.is_boundary_edge(leaving) {
        let mut across = None;
        m.edge_faces(leaving, |f| {
            if f != face {
                across = Some(f);
            }
        });
        face = across?;
        leaving = m.edge_successor(leaving, face)?;
        if leaving == e {
            return None;
        }
    }
    Some(leaving)
}

/// Writes every boundary curve of `m` into `out` (see the module docs for how).
pub(crate) fn boundary_curves<M: MeshTopology>(m: &M, out: &mut BoundaryCurves) {
    out.clear();
    out.starts.clear();
    m.for_each_edge(|e| {
        if m.is_boundary_edge(e) {
            out.edges.push(e);
        }
    });
    let boundary = out.edges.len();
    out.edges.sort_unstable();
    // Scratch in `starts`: `words` words of "already walked" bits (by rank in the sorted
    // prefix of `edges`), then the end of each curve counted from the end of that prefix.
    let words = boundary.div_ceil(32);
    out.starts.resize(words, 0);
    for rank in 0..boundary {
        if out.starts[rank / 32] & (1 << (rank % 32)) != 0 {
            continue;
        }
        let mut e = out.edges[rank];
        // Each step marks one edge, so the walk ends when it comes back to its first edge
        // (already marked), or, on a broken structure, at a dead end.
        while let Ok(r) = out.edges[..boundary].binary_search(&e) {
            let (word, bit) = (r / 32, 1u32 << (r % 32));
            if out.starts[word] & bit != 0 {
                break;
            }
            out.starts[word] |= bit;
            out.edges.push(e);
            match next_boundary_edge(m, e) {
                Some(next) => e = next,
                None => break,
            }
        }
        out.starts.push((out.edges.len() - boundary) as u32);
    }
    out.edges.drain(..boundary);
    out.starts.drain(..words);
    out.starts.insert(0, 0);
}
