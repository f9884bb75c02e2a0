//! The access models of the CGAL baselines ([`MeshTopology::access`]): what their own loops
//! (`cgal/kernels.h`, timed as [`MeshTopology::native`] kernels, one sweep over CGAL's element
//! ranges) read from each structure, from CGAL's documented layout and the record sizes of
//! CGAL 5.5 on x86-64 (`sizeof`, measured).
//!
//! - `Surface_mesh` keeps its connectivity in property arrays indexed by element:
//!   `v:connectivity` (one incoming halfedge per vertex, 4 bytes), `h:connectivity` (face,
//!   target vertex, next, prev of each halfedge, 16 bytes; halfedges `2e` and `2e + 1` side
//!   by side, the opposite of `h` is `h ^ 1`, read from nothing) and `f:connectivity` (one
//!   halfedge per face, 4 bytes); points and the removed flags are arrays of their own, which
//!   the relations do not read. A vertex circulator's step, `opposite(next(h))`, is one
//!   dependent load, as in the index half-edge and OpenMesh.
//! - `Polyhedron_3` (its default `HalfedgeDS_list`, with `Polyhedron_items_with_id_3`) keeps
//!   each vertex, facet and pair of opposite halfedges as a node of an `In_place_list`, its own
//!   heap block: a vertex is 56 bytes (list links, halfedge, point, id) in a 64-byte glibc
//!   block, a halfedge pair 128 bytes (per halfedge: list links, opposite, next, prev, vertex,
//!   facet, id) in a 144-byte block, 72 per halfedge, a facet 32 bytes (list links, halfedge,
//!   id) in a 48-byte block. Every link is a pointer read from a record; a step around a vertex,
//!   `h->next()->opposite()`, is two dependent loads; an answer's index is the `id` of its
//!   record. A sweep walks the lists: each element's address is read from the node before
//!   (the lab's pointer half-edge enters its records from an id table instead; neither load
//!   is on a query's chain, see [`topolab_structures::Access`]).
//!
//! Edge keys the harness's checksum mixes in are the harness's reads, not counted here. A
//! `Surface_mesh` loop reads a field or two of each 16-byte `h:connectivity` record it visits,
//! and the cache brings the whole record: each such read says the records it lands in
//! ([`Read::in_records`](topolab_structures::Read::in_records)). The `Polyhedron_3` models
//! count the bytes read only.
//!
//! [`MeshTopology::access`]: topolab_structures::MeshTopology::access
//! [`MeshTopology::native`]: topolab_structures::MeshTopology::native

use topolab_structures::{Access, Container, Operator, Read, Unit};

/// What CGAL's circulators do that the models leave out.
const CIRCULATOR: &str = "CGAL's circulator ranges also count windings to tell the first halfedge from the end (work the model leaves out)";

/// `Surface_mesh`'s property arrays.
mod sm {
    use super::*;
    pub const VCONN: Container = Container::new("v:connectivity", Unit::Vertex, 4.0);
    pub const HCONN: Container = Container::new("h:connectivity", Unit::HalfEdge, 16.0);
    pub const FCONN: Container = Container::new("f:connectivity", Unit::Face, 4.0);
}

/// What each loop of `Surface_mesh` reads.
pub(super) fn surface_mesh(op: Operator) -> Option<Access> {
    use sm::*;
    Some(match op {
        // halfedge(v), then per step next(h) and the opposite's target (the neighbour).
        Operator::R00 => Access::new(
            const {
                &[
                    Read::new(VCONN, 4.0, 0.0),
                    Read::new(HCONN, 0.0, 8.0).in_records(0.0, 1.0),
                ]
            },
            0.0,
            1.0,
        )
        .noting(CIRCULATOR),
        Operator::R01 => Access::new(
            const {
                &[
                    Read::new(VCONN, 4.0, 0.0),
                    Read::new(HCONN, 0.0, 4.0).in_records(0.0, 1.0),
                ]
            },
            0.0,
            1.0,
        )
        .noting(CIRCULATOR),
        // Per step next(h) and face(h).
        Operator::R02 => Access::new(
            const {
                &[
                    Read::new(VCONN, 4.0, 0.0),
                    Read::new(HCONN, 0.0, 8.0).in_records(0.0, 1.0),
                ]
            },
            0.0,
            1.0,
        )
        .noting(CIRCULATOR),
        // The targets of halfedges 2e and 2e + 1.
        Operator::R10 => Access::new(
            const { &[Read::new(HCONN, 8.0, 0.0).in_records(2.0, 0.0)] },
            0.0,
            0.0,
        ),
        // Per side: its face (is it the border?), then next three times around the triangle.
        Operator::R11 => Access::new(const { &[Read::new(HCONN, 32.0, 0.0)] }, 3.0, 0.0),
        Operator::R12 | Operator::BoundaryEdge => Access::new(
            const { &[Read::new(HCONN, 8.0, 0.0).in_records(2.0, 0.0)] },
            0.0,
            0.0,
        ),
        // halfedge(f), then per step the target (or the opposite's face) and next.
        Operator::R20 | Operator::R22 => Access::new(
            const {
                &[
                    Read::new(FCONN, 4.0, 0.0),
                    Read::new(HCONN, 0.0, 8.0).in_records(0.0, 1.0),
                ]
            },
            0.0,
            1.0,
        )
        .noting(CIRCULATOR),
        Operator::R21 => Access::new(
            const {
                &[
                    Read::new(FCONN, 4.0, 0.0),
                    Read::new(HCONN, 0.0, 4.0).in_records(0.0, 1.0),
                ]
            },
            0.0,
            1.0,
        )
        .noting(CIRCULATOR),
        // is_border(v, false): the face of halfedge(v).
        Operator::BoundaryVertex => Access::new(
            const {
                &[
                    Read::new(VCONN, 4.0, 0.0),
                    Read::new(HCONN, 4.0, 0.0).in_records(1.0, 0.0),
                ]
            },
            1.0,
            0.0,
        ),
        // A scan of every halfedge's face, then each loop walked twice by next (once to mark
        // it and count its length, once for the checksum).
        Operator::BoundaryCurves => Access::new(
            const {
                &[
                    Read::scan(HCONN, 1.0),
                    Read::new(HCONN, 0.0, 8.0).in_records(0.0, 1.0),
                ]
            },
            0.0,
            2.0,
        ),
        // Per face (a third of a query each): halfedge(f), then per halfedge next to step and
        // to answer (prev too for the predecessor).
        Operator::EdgeSuccessor => Access::new(
            const {
                &[
                    Read::new(FCONN, 4.0 / 3.0, 0.0),
                    Read::new(HCONN, 4.0, 0.0).in_records(1.0, 0.0),
                ]
            },
            1.0,
            0.0,
        ),
        Operator::EdgePredecessor => Access::new(
            const {
                &[
                    Read::new(FCONN, 4.0 / 3.0, 0.0),
                    Read::new(HCONN, 8.0, 0.0).in_records(1.0, 0.0),
                ]
            },
            1.0,
            0.0,
        ),
    })
}

/// `Polyhedron_3`'s records, each counted as the glibc block it takes.
mod ph {
    use super::*;
    pub const VERTEX: Container = Container::new("Vertex", Unit::Vertex, 64.0);
    pub const HALFEDGE: Container = Container::new("Halfedge", Unit::HalfEdge, 72.0);
    pub const FACET: Container = Container::new("Facet", Unit::Face, 48.0);
}

/// What the Polyhedron's loops leave out of the model.
const LISTS: &str = "the sweep walks In_place_lists, each node's address read from the node before, and each step's loads land in other heap blocks: they miss L1 more often than neighbouring array entries, and the model counts them at L1 latency";

/// An interior vertex's whole fan is walked by the boundary test.
const FAN: &str = "CGAL::is_border(v) walks the fan until a border halfedge (an interior vertex's whole fan: valence 6 on the report's meshes, counted here)";

/// What each loop of `Polyhedron_3` reads.
pub(super) fn polyhedron(op: Operator) -> Option<Access> {
    use ph::*;
    Some(match op {
        // The vertex's list link, halfedge and id; per step h->next, next->opposite, and for
        // the neighbour h->opposite->vertex->id.
        Operator::R00 => Access::new(
            const { &[Read::new(VERTEX, 24.0, 8.0), Read::new(HALFEDGE, 0.0, 32.0)] },
            1.0,
            2.0,
        )
        .noting(LISTS),
        Operator::R01 => Access::new(
            const { &[Read::new(VERTEX, 24.0, 0.0), Read::new(HALFEDGE, 0.0, 16.0)] },
            1.0,
            2.0,
        )
        .noting(LISTS),
        // Per step also h->facet->id.
        Operator::R02 => Access::new(
            const {
                &[
                    Read::new(VERTEX, 24.0, 0.0),
                    Read::new(HALFEDGE, 0.0, 24.0),
                    Read::new(FACET, 0.0, 8.0),
                ]
            },
            1.0,
            2.0,
        )
        .noting(LISTS),
        // Two list links per edge (a pair is two nodes), h->vertex->id and
        // h->opposite->vertex->id.
        Operator::R10 => Access::new(
            const { &[Read::new(HALFEDGE, 40.0, 0.0), Read::new(VERTEX, 16.0, 0.0)] },
            3.0,
            0.0,
        )
        .noting(LISTS),
        // Per side (h, then h->opposite): its facet, then next three times around the triangle.
        Operator::R11 => {
            Access::new(const { &[Read::new(HALFEDGE, 88.0, 0.0)] }, 4.0, 0.0).noting(LISTS)
        }
        // The facets of h and h->opposite, and their ids.
        Operator::R12 => Access::new(
            const { &[Read::new(HALFEDGE, 40.0, 0.0), Read::new(FACET, 16.0, 0.0)] },
            3.0,
            0.0,
        )
        .noting(LISTS),
        // The facet's list link, halfedge and id; per step h->vertex->id and h->next.
        Operator::R20 => Access::new(
            const {
                &[
                    Read::new(FACET, 24.0, 0.0),
                    Read::new(HALFEDGE, 0.0, 16.0),
                    Read::new(VERTEX, 0.0, 8.0),
                ]
            },
            1.0,
            1.0,
        )
        .noting(LISTS),
        Operator::R21 => Access::new(
            const { &[Read::new(FACET, 24.0, 0.0), Read::new(HALFEDGE, 0.0, 8.0)] },
            1.0,
            1.0,
        )
        .noting(LISTS),
        // Per step h->next and h->opposite->facet->id.
        Operator::R22 => Access::new(
            const { &[Read::new(FACET, 24.0, 8.0), Read::new(HALFEDGE, 0.0, 24.0)] },
            1.0,
            1.0,
        )
        .noting(LISTS),
        // v->halfedge, then up to a whole fan of steps (next, opposite, facet each).
        Operator::BoundaryVertex => Access::new(
            const {
                &[
                    Read::new(VERTEX, 24.0, 0.0),
                    Read::new(HALFEDGE, 144.0, 0.0),
                ]
            },
            13.0,
            0.0,
        )
        .noting(FAN),
        // Two list links, h->facet, h->opposite->facet.
        Operator::BoundaryEdge => {
            Access::new(const { &[Read::new(HALFEDGE, 40.0, 0.0)] }, 2.0, 0.0).noting(LISTS)
        }
        // A walk of the halfedge list reading each border test, then each loop walked twice
        // by next (marking each halfedge by its id the first time).
        Operator::BoundaryCurves => Access::new(
            const { &[Read::scan(HALFEDGE, 1.0), Read::new(HALFEDGE, 0.0, 24.0)] },
            0.0,
            2.0,
        )
        .noting(LISTS),
        // Per facet (a third of a query each): its list link and halfedge, then per halfedge
        // next to step and to answer (prev too for the predecessor).
        Operator::EdgeSuccessor => Access::new(
            const {
                &[
                    Read::new(FACET, 16.0 / 3.0, 0.0),
                    Read::new(HALFEDGE, 8.0, 0.0),
                ]
            },
            1.0,
            0.0,
        )
        .noting(LISTS),
        Operator::EdgePredecessor => Access::new(
            const {
                &[
                    Read::new(FACET, 16.0 / 3.0, 0.0),
                    Read::new(HALFEDGE, 16.0, 0.0),
                ]
            },
            1.0,
            0.0,
        )
        .noting(LISTS),
    })
}
