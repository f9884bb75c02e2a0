//! The access models of the two half-edge storages ([`MeshTopology::access`]): what the shared
//! operators of [`HalfEdge`](super::HalfEdge) read, primitive by primitive, from the index
//! arrays or the pointer records.
//!
//! Per primitive: the index storage reads one `u32` per `next`, `prev`, `vertex`, `face`,
//! `outgoing` and `face_half_edge` and none for `twin` (`h ^ 1`); the pointer storage reads one
//! pointer per link (`twin` is `pair`), plus the target record's `id` to answer in the lab's
//! ids, and one id-table entry to enter the records from an id. A step of the vertex loop,
//! `next(twin(h))`, is one dependent load on indices (`next[h ^ 1]`) and two on pointers
//! (`h->pair->next`).
//!
//! [`MeshTopology::access`]: crate::MeshTopology::access

use crate::core::access::{Access, Container, Read, Step, Unit};
use crate::core::topology::Operator;

/// Both storages' boundary curves also look each boundary half-edge up by binary search among
/// those found (log ∂n1 loads per answer), which the model leaves out.
const BINARY_SEARCH: &str =
    "each boundary half-edge is also looked up by binary search among those found (log ∂n1 dependent loads per answer)";

/// The index storage's arrays ([`IndexHalfEdge`](crate::IndexHalfEdge)).
mod index {
    use super::*;
    pub const VH: Container = Container::new("vertex_half_edge", Unit::Vertex, 4.0);
    pub const FH: Container = Container::new("face_half_edge", Unit::Face, 4.0);
    pub const VERTEX: Container = Container::new("vertex", Unit::HalfEdge, 4.0);
    pub const NEXT: Container = Container::new("next", Unit::HalfEdge, 4.0);
    pub const PREV: Container = Container::new("prev", Unit::HalfEdge, 4.0);
    pub const FACE: Container = Container::new("face", Unit::HalfEdge, 4.0);
}

/// What each operator of [`IndexHalfEdge`](crate::IndexHalfEdge) reads.
pub(crate) fn index(op: Operator) -> Option<Access> {
    use index::*;
    Some(match op {
        // vertex_half_edge[v], then per step vertex[h ^ 1] and h = next[h ^ 1].
        Operator::R00 => Access::new(
            const {
                &[
                    Read::new(VH, 4.0, 0.0),
                    Read::new(NEXT, 0.0, 4.0),
                    Read::new(VERTEX, 0.0, 4.0),
                ]
            },
            0.0,
            1.0,
        )
        .stepping(Step::Twin),
        Operator::R01 => Access::new(
            const { &[Read::new(VH, 4.0, 0.0), Read::new(NEXT, 0.0, 4.0)] },
            0.0,
            1.0,
        )
        .stepping(Step::Twin),
        Operator::R02 => Access::new(
            const {
                &[
                    Read::new(VH, 4.0, 0.0),
                    Read::new(NEXT, 0.0, 4.0),
                    Read::new(FACE, 0.0, 4.0),
                ]
            },
            0.0,
            1.0,
        )
        .stepping(Step::Twin),
        // vertex[2e], vertex[2e + 1]: independent.
        Operator::R10 => Access::new(const { &[Read::new(VERTEX, 8.0, 0.0)] }, 0.0, 0.0),
        // Per side with a face: next(side), then the face's three half-edges by `next`.
        Operator::R11 => Access::new(
            const { &[Read::new(FACE, 8.0, 0.0), Read::new(NEXT, 32.0, 0.0)] },
            3.0,
            0.0,
        ),
        Operator::R12 => Access::new(const { &[Read::new(FACE, 8.0, 0.0)] }, 0.0, 0.0),
        Operator::R20 => Access::new(
            const {
                &[
                    Read::new(FH, 4.0, 0.0),
                    Read::new(NEXT, 0.0, 4.0),
                    Read::new(VERTEX, 0.0, 4.0),
                ]
            },
            0.0,
            1.0,
        ),
        Operator::R21 => Access::new(
            const { &[Read::new(FH, 4.0, 0.0), Read::new(NEXT, 0.0, 4.0)] },
            0.0,
            1.0,
        ),
        Operator::R22 => Access::new(
            const {
                &[
                    Read::new(FH, 4.0, 0.0),
                    Read::new(NEXT, 0.0, 4.0),
                    Read::new(FACE, 0.0, 4.0),
                ]
            },
            0.0,
            1.0,
        ),
        // face[vertex_half_edge[v]].
        Operator::BoundaryVertex => Access::new(
            const { &[Read::new(VH, 4.0, 0.0), Read::new(FACE, 4.0, 0.0)] },
            1.0,
            0.0,
        ),
        Operator::BoundaryEdge => Access::new(const { &[Read::new(FACE, 8.0, 0.0)] }, 0.0, 0.0),
        // A scan of face[] for the boundary half-edges, then each loop by `next`.
        Operator::BoundaryCurves => Access::new(
            const { &[Read::scan(FACE, 1.0), Read::new(NEXT, 0.0, 4.0)] },
            0.0,
            1.0,
        )
        .noting(BINARY_SEARCH),
        // face[2e] (and face[2e + 1] half the time), then next (or prev) of the one in `face`.
        Operator::EdgeSuccessor => Access::new(
            const { &[Read::new(FACE, 6.0, 0.0), Read::new(NEXT, 4.0, 0.0)] },
            1.0,
            0.0,
        ),
        Operator::EdgePredecessor => Access::new(
            const { &[Read::new(FACE, 6.0, 0.0), Read::new(PREV, 4.0, 0.0)] },
            1.0,
            0.0,
        ),
    })
}

/// The pointer storage's records and id tables ([`PointerHalfEdge`](crate::PointerHalfEdge)):
/// each record is its own glibc block, 8 bytes of header and rounded up to 16, so a 40-byte
/// record takes 48 bytes of memory and a 16-byte one 32. A fan walk reads a field or two of
/// each record it visits (a step: `pair` of `h`, `vert` and `next` of the pair, two records),
/// and the cache brings the whole record, so the vertex loops say the records their reads land
/// in ([`Read::in_records`](crate::core::access::Read::in_records)); the other operators count
/// the bytes read only.
mod pointer {
    use super::*;
    pub const VERTS: Container = Container::new("verts", Unit::Vertex, 8.0);
    pub const FACES: Container = Container::new("faces", Unit::Face, 8.0);
    pub const EDGES: Container = Container::new("edges", Unit::HalfEdge, 8.0);
    pub const HE_VERT: Container = Container::new("HE_vert", Unit::Vertex, 48.0);
    pub const HE_FACE: Container = Container::new("HE_face", Unit::Face, 32.0);
    pub const HE_EDGE: Container = Container::new("HE_edge", Unit::HalfEdge, 48.0);
}

/// What the pointer storage's loops leave out of the model.
const SCATTERED: &str = "each step's loads land in other 48-byte heap records, allocated in edge order rather than in the walk's: they miss L1 more often than the arrays' neighbouring entries, and the model counts them at L1 latency";

/// What each operator of [`PointerHalfEdge`](crate::PointerHalfEdge) reads.
pub(crate) fn pointer(op: Operator) -> Option<Access> {
    use pointer::*;
    Some(match op {
        // verts[v]->edge, then per step h->pair, pair->vert->id and h = pair->next.
        Operator::R00 => Access::new(
            const {
                &[
                    Read::new(VERTS, 8.0, 0.0),
                    Read::new(HE_VERT, 8.0, 4.0).in_records(1.0, 1.0),
                    Read::new(HE_EDGE, 0.0, 24.0).in_records(0.0, 2.0),
                ]
            },
            1.0,
            2.0,
        )
        .noting(SCATTERED),
        Operator::R01 => Access::new(
            const {
                &[
                    Read::new(VERTS, 8.0, 0.0),
                    Read::new(HE_VERT, 8.0, 0.0).in_records(1.0, 0.0),
                    Read::new(HE_EDGE, 0.0, 20.0).in_records(0.0, 2.0),
                ]
            },
            1.0,
            2.0,
        )
        .noting(SCATTERED),
        Operator::R02 => Access::new(
            const {
                &[
                    Read::new(VERTS, 8.0, 0.0),
                    Read::new(HE_VERT, 8.0, 0.0).in_records(1.0, 0.0),
                    Read::new(HE_EDGE, 0.0, 24.0).in_records(0.0, 2.0),
                    Read::new(HE_FACE, 0.0, 4.0).in_records(0.0, 1.0),
                ]
            },
            1.0,
            2.0,
        )
        .noting(SCATTERED),
        // edges[2e]->vert->id and edges[2e]->pair->vert->id.
        Operator::R10 => Access::new(
            const {
                &[
                    Read::new(EDGES, 8.0, 0.0),
                    Read::new(HE_EDGE, 24.0, 0.0),
                    Read::new(HE_VERT, 8.0, 0.0),
                ]
            },
            3.0,
            0.0,
        ),
        // Per side: its face, next(side), the face's three half-edges by `next`, two ids.
        Operator::R11 => Access::new(
            const { &[Read::new(EDGES, 8.0, 0.0), Read::new(HE_EDGE, 104.0, 0.0)] },
            5.0,
            0.0,
        ),
        Operator::R12 => Access::new(
            const {
                &[
                    Read::new(EDGES, 8.0, 0.0),
                    Read::new(HE_EDGE, 24.0, 0.0),
                    Read::new(HE_FACE, 8.0, 0.0),
                ]
            },
            3.0,
            0.0,
        ),
        // faces[f]->edge, then per step h->vert->id and h = h->next.
        Operator::R20 => Access::new(
            const {
                &[
                    Read::new(FACES, 8.0, 0.0),
                    Read::new(HE_FACE, 8.0, 0.0),
                    Read::new(HE_EDGE, 0.0, 16.0),
                    Read::new(HE_VERT, 0.0, 4.0),
                ]
            },
            1.0,
            1.0,
        )
        .noting(SCATTERED),
        Operator::R21 => Access::new(
            const {
                &[
                    Read::new(FACES, 8.0, 0.0),
                    Read::new(HE_FACE, 8.0, 0.0),
                    Read::new(HE_EDGE, 0.0, 12.0),
                ]
            },
            1.0,
            1.0,
        )
        .noting(SCATTERED),
        Operator::R22 => Access::new(
            const {
                &[
                    Read::new(FACES, 8.0, 0.0),
                    Read::new(HE_FACE, 8.0, 4.0),
                    Read::new(HE_EDGE, 0.0, 24.0),
                ]
            },
            1.0,
            1.0,
        )
        .noting(SCATTERED),
        // verts[v]->edge->face.
        Operator::BoundaryVertex => Access::new(
            const {
                &[
                    Read::new(VERTS, 8.0, 0.0),
                    Read::new(HE_VERT, 8.0, 0.0),
                    Read::new(HE_EDGE, 8.0, 0.0),
                ]
            },
            2.0,
            0.0,
        ),
        // edges[2e]->face and edges[2e]->pair->face.
        Operator::BoundaryEdge => Access::new(
            const { &[Read::new(EDGES, 8.0, 0.0), Read::new(HE_EDGE, 24.0, 0.0)] },
            2.0,
            0.0,
        ),
        Operator::BoundaryCurves => Access::new(
            const {
                &[
                    Read::scan(EDGES, 1.0),
                    Read::scan(HE_EDGE, 1.0),
                    Read::new(HE_EDGE, 0.0, 12.0),
                ]
            },
            0.0,
            1.0,
        )
        .noting(BINARY_SEARCH),
        // edges[2e], its pair, face->id (and the pair's half the time), then next->id.
        Operator::EdgeSuccessor => Access::new(
            const {
                &[
                    Read::new(EDGES, 8.0, 0.0),
                    Read::new(HE_EDGE, 32.0, 0.0),
                    Read::new(HE_FACE, 6.0, 0.0),
                ]
            },
            4.0,
            0.0,
        ),
        // No `prev`: three `next` around the triangle instead of one.
        Operator::EdgePredecessor => Access::new(
            const {
                &[
                    Read::new(EDGES, 8.0, 0.0),
                    Read::new(HE_EDGE, 48.0, 0.0),
                    Read::new(HE_FACE, 6.0, 0.0),
                ]
            },
            6.0,
            0.0,
        ),
    })
}
