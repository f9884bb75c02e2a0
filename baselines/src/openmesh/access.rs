//! The access model of the OpenMesh baseline ([`MeshTopology::access`]): what its own loops
//! (`openmesh/shim.cpp`, timed as [`MeshTopology::native`] kernels) read from
//! `TriMesh_ArrayKernelT`'s arrays. The kernel stores per vertex its outgoing halfedge, per face
//! one halfedge, and per halfedge (two per edge, side by side) its face, to-vertex, next and
//! prev handles, 16 bytes; the opposite of halfedge `h` is `h ^ 1`, read from nothing. A step of
//! a vertex circulator is one dependent load (`next` of the opposite), as in the index
//! half-edge; positions (24 bytes per vertex) are not read by the relations. A loop reads a
//! field or two of each halfedge it visits, and the cache brings the whole 16-byte record:
//! each read says the records it lands in ([`Read::in_records`]), so the bandwidth bound of a
//! sweep counts the records' bytes (the R00 sweep: 16, not 8, per answer).
//!
//! [`Read::in_records`]: topolab_structures::Read::in_records
//!
//! [`MeshTopology::access`]: topolab_structures::MeshTopology::access
//! [`MeshTopology::native`]: topolab_structures::MeshTopology::native

use topolab_structures::{Access, Container, Operator, Read, Step, Unit};

const VERTICES: Container = Container::new("vertices", Unit::Vertex, 4.0);
const FACES: Container = Container::new("faces", Unit::Face, 4.0);
const HALFEDGES: Container = Container::new("halfedges", Unit::HalfEdge, 16.0);

/// What OpenMesh's circulators do that the model leaves out.
const CIRCULATOR: &str = "OpenMesh's circulators also count laps and check the handle's validity at each step (work the model leaves out)";

/// What OpenMesh's loop of `op` reads.
pub(super) fn model(op: Operator) -> Option<Access> {
    Some(match op {
        // halfedge_handle(v), then per step the to-vertex and `next` of the opposite.
        Operator::R00 | Operator::R02 => Access::new(
            const {
                &[
                    Read::new(VERTICES, 4.0, 0.0),
                    Read::new(HALFEDGES, 0.0, 8.0).in_records(0.0, 1.0),
                ]
            },
            0.0,
            1.0,
        )
        .stepping(Step::Twin)
        .noting(CIRCULATOR),
        Operator::R01 => Access::new(
            const {
                &[
                    Read::new(VERTICES, 4.0, 0.0),
                    Read::new(HALFEDGES, 0.0, 4.0).in_records(0.0, 1.0),
                ]
            },
            0.0,
            1.0,
        )
        .stepping(Step::Twin)
        .noting(CIRCULATOR),
        // The to-vertices of both halfedges.
        Operator::R10 => Access::new(
            const { &[Read::new(HALFEDGES, 8.0, 0.0).in_records(2.0, 0.0)] },
            0.0,
            0.0,
        ),
        // Per side: its face (is it the boundary?), then `next` around the triangle.
        Operator::R11 => Access::new(const { &[Read::new(HALFEDGES, 32.0, 0.0)] }, 2.0, 0.0),
        Operator::R12 | Operator::BoundaryEdge => Access::new(
            const { &[Read::new(HALFEDGES, 8.0, 0.0).in_records(2.0, 0.0)] },
            0.0,
            0.0,
        ),
        // halfedge_handle(f), then per step the to-vertex (or the opposite's face) and `next`.
        Operator::R20 | Operator::R22 => Access::new(
            const {
                &[
                    Read::new(FACES, 4.0, 0.0),
                    Read::new(HALFEDGES, 0.0, 8.0).in_records(0.0, 1.0),
                ]
            },
            0.0,
            1.0,
        )
        .noting(CIRCULATOR),
        Operator::R21 => Access::new(
            const {
                &[
                    Read::new(FACES, 4.0, 0.0),
                    Read::new(HALFEDGES, 0.0, 4.0).in_records(0.0, 1.0),
                ]
            },
            0.0,
            1.0,
        )
        .noting(CIRCULATOR),
        // The face of halfedge_handle(v).
        Operator::BoundaryVertex => Access::new(
            const {
                &[
                    Read::new(VERTICES, 4.0, 0.0),
                    Read::new(HALFEDGES, 4.0, 0.0).in_records(1.0, 0.0),
                ]
            },
            1.0,
            0.0,
        ),
        // A scan of every halfedge's face, then each loop walked twice by `next` (once for
        // its length, which the checksum mixes in, once for its edges).
        Operator::BoundaryCurves => Access::new(
            const {
                &[
                    Read::scan(HALFEDGES, 1.0),
                    Read::new(HALFEDGES, 0.0, 8.0).in_records(0.0, 1.0),
                ]
            },
            0.0,
            2.0,
        ),
        // The loop runs per face (a third of a query each): halfedge_handle(f), then per
        // halfedge `next` to step and `next` or `prev` to answer.
        Operator::EdgeSuccessor | Operator::EdgePredecessor => Access::new(
            const {
                &[
                    Read::new(FACES, 4.0 / 3.0, 0.0),
                    Read::new(HALFEDGES, 8.0, 0.0).in_records(1.0, 0.0),
                ]
            },
            1.0,
            0.0,
        ),
    })
}
