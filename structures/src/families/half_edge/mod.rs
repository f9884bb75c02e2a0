//! What the two half-edge structures share: how they are built ([`HalfEdgeArrays`]), the
//! few primitives each answers in its own way ([`HalfEdgeLinks`]: `next`, `twin`, the start
//! vertex, the face, one half-edge per vertex and per face), and every operator, `validate`
//! and `explain` written once on top of those primitives ([`HalfEdge`]), and the editing
//! operations ([`crate::MeshEdit`]) written once over the writes of [`edit::HalfEdgeLinksMut`].
//!
//! The operators are generic and monomorphised, so the pointer structure really chases
//! pointers and the index structure really reads arrays: the comparison of the two measures
//! the storage, not two different algorithms.
//!
//! Conventions of both structures (OpenMesh's):
//! - edge `e` owns half-edges `2e` and `2e + 1` (twins); edges are numbered as
//!   [`crate::Connectivity`] numbers them (first appearance in the soup);
//! - boundary edges have an explicit boundary half-edge with no face, linked by `next` into
//!   boundary loops, so the lecture's vertex loop `edge = edge->pair->next` works on the
//!   boundary too;
//! - a boundary vertex's half-edge is its outgoing boundary half-edge, so "is `v` on the
//!   boundary?" is one test, and its rotation starts at the boundary;
//! - non-manifold vertices (the `bowtie`) are refused with [`crate::Error::NonManifoldVertex`]:
//!   one half-edge per vertex reaches only one fan by rotation.
//!
//! ## Costs
//!
//! As the summary table of the lecture on polygon-mesh data structures (*half-edge Struktur –
//! Zusammenfassung*), except one row. The table gives an edge's successor and predecessor
//! together as O(k): "Vorgänger in Kante und Vorgänger in k-gon entlang hangeln für
//! Nachfolger", a predecessor stored in the half-edge and a walk around the k-gon for the
//! successor. The lecture's own record declares the other link, `HE_edge::next`, and walks the
//! face with `edge = edge->next`; the lab stores `next` as the record does, so the successor
//! is one read, O(1), and it is the predecessor that needs the walk, O(k)
//! ([`PointerHalfEdge`](crate::PointerHalfEdge)), unless `prev` is stored as well, O(1)
//! ([`IndexHalfEdge`](crate::IndexHalfEdge), as OpenMesh does).
//!
//! ## Rotating one way
//!
//! The lab's fairness rule (the docs of [`MeshTopology`](crate::MeshTopology)) offers every
//! structure that walks fans the walk from both ends at once, which made the CHE and the
//! winged-edge faster. Here the backward rotation `twin(prev(g))` was measured beside the
//! forward one and did not pay, so both storages rotate one way, the lecture's loop. It was
//! measured by instruction counts (callgrind on the harness's R00 sweep, the command in the
//! `fan_sweep` example's docs) and by R00 timed in turns with OpenMesh in one process
//! (`cargo run --release --example fan_sweep`):
//!
//! - index: the second end added instructions and time. A step is one load and an `xor`, so
//!   the rotation is bound by its instructions more than by its chain, and the second chain
//!   only adds instructions.
//! - pointer: the second end added instructions and saved no time, in R00, R01 or smoothing.
//!   Without a stored `prev`, each backward step walks the face (`next` twice) before its
//!   `pair`, and the time goes to cache misses on records spread over the heap rather than to
//!   one chain's latency.
//!
//! The CHE's vertex star reads its arrays without bounds checks, because its ranges are
//! checked once when it is built (the fairness rule's "Bounds checks"). The same was offered
//! to the index half-edge. A copy of its rotation over its `vertex`, `next` and `face` arrays,
//! with unchecked reads, was timed against the same copy with checked reads, on the harness's
//! R00 sweep and smoothing workload of a 100k-triangle torus, in one process taking turns:
//!
//! - R00: fewer instructions per vertex, but the same time. The walk is one chain of `next`
//!   loads, not bound by its instructions.
//! - Smoothing: fewer instructions per vertex, and only slightly faster.
//!
//! It is not kept. Both storages are edited in place (`MeshEdit`), so a range checked when
//! the mesh is built would not stay true. Keeping it true would mean checking every link
//! that an edit writes.
//!
//! ## Memory order
//!
//! Edges keep the soup's first-appearance order ([`crate::Connectivity`]); the build does not
//! renumber them around vertices. A vertex's fan then lies in two runs of edges, those its
//! faces' row created and those the row before created, and a sweep over the vertices in
//! order reads both runs as streams. R00 over every vertex reads 52 bytes per vertex in the
//! index storage (`vertex_half_edge`, then `vertex` and `next` of six half-edges). Callgrind's
//! cache simulation (64-byte lines) on a 100k-triangle torus counts about one L1 miss per 64
//! of those bytes: every line is fetched once. On the 1M-triangle torus it counts more L1
//! misses, as the two runs lie a row of edges apart, more than L1 holds, but (with a 32 MB
//! last level simulated) still about one last-level miss per line: every line comes from
//! memory once. The report's "Sweeps against their limit" section sets the sweep beside what
//! the machine's bandwidth allows for those bytes. A numbering that put each fan in fewer
//! lines could not fetch fewer lines from memory; it would cost construction time. OpenMesh's
//! sweep reads its 16-byte halfedge records whole for the 8 bytes it needs of each, so on a
//! mesh larger than the caches the two stream 52 against about 100 bytes per vertex.

mod access;
mod build;
pub mod edit;
pub mod index;
pub mod pointer;
mod topology;
mod validate;

pub use build::HalfEdgeArrays;
pub(crate) use build::NONE;

use crate::core::error::Result;
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::topology::Cost;
use glam::DVec3;
use std::fmt::Write;

/// The primitives a half-edge storage answers; everything else is derived in [`HalfEdge`].
///
/// `H` is how the storage names a half-edge while walking: a `u32` index for arrays, a
/// reference to the record for pointers. Half-edge ids (`id`) follow [`HalfEdgeArrays`].
pub trait HalfEdgeLinks: Sized + 'static {
    /// A half-edge while walking.
    type H<'a>: Copy + Eq
    where
        Self: 'a;

    /// The structure's name.
    const NAME: &'static str;

    /// The cost of the edge predecessor: O(1) with a stored `prev`, O(k) walking the face.
    const PREDECESSOR: Cost;

    /// Builds the storage from the arrays and the soup's positions.
    fn from_arrays(arrays: HalfEdgeArrays, positions: &[DVec3]) -> Self;

    /// [`HalfEdgeLinks::from_arrays`] taking the positions: a storage that keeps them as they
    /// are takes them without a copy (`from_soup_owned`).
    fn from_arrays_owned(arrays: HalfEdgeArrays, positions: Vec<DVec3>) -> Self {
        Self::from_arrays(arrays, &positions)
    }

    /// Number of half-edges.
    fn num_half_edges(&self) -> usize;
    /// Number of vertices.
    fn num_vertices(&self) -> usize;
    /// Number of faces.
    fn num_faces(&self) -> usize;

    /// The half-edge of id `id`.
    fn half_edge(&self, id: u32) -> Self::H<'_>;
    /// The id of `h`.
    fn id(&self, h: Self::H<'_>) -> u32;
    /// The oppositely oriented half-edge of the same edge (`pair`).
    fn twin<'a>(&'a self, h: Self::H<'a>) -> Self::H<'a>;
    /// The next half-edge around the face or boundary loop.
    fn next<'a>(&'a self, h: Self::H<'a>) -> Self::H<'a>;
    /// The previous half-edge; without a stored link, a walk around the loop.
    #[inline]
    fn prev<'a>(&'a self, h: Self::H<'a>) -> Self::H<'a> {
        let mut x = h;
        loop {
            let n = self.next(x);
            if n == h {
                return x;
            }
            x = n;
        }
    }
    /// The vertex `h` starts at.
    fn vertex(&self, h: Self::H<'_>) -> VertexId;
    /// The face `h` borders, `None` for a boundary half-edge.
    fn face(&self, h: Self::H<'_>) -> Option<FaceId>;
    /// The half-edge of vertex `v` (leaving it; the boundary one on the boundary), `None`
    /// for an unused vertex.
    fn outgoing(&self, v: VertexId) -> Option<Self::H<'_>>;
    /// The half-edge of face `f`.
    fn face_half_edge(&self, f: FaceId) -> Self::H<'_>;
    /// The position of `v`.
    fn position(&self, v: VertexId) -> DVec3;

    /// Bytes of every record and array.
    fn heap_bytes(&self) -> usize;
    /// Invariants of the storage itself that the id-level checks of [`HalfEdge::validate`](crate::MeshTopology::validate)
    /// cannot see (for pointers: every link points to a record of this mesh).
    fn validate_storage(&self) -> Result<()>;
    /// For `explain`: what the storage is and how its fields are named.
    fn describe(w: &mut dyn Write) -> std::fmt::Result;
    /// For `explain`: the stored `prev` of `h`, if the storage keeps one.
    fn stored_prev(&self, h: Self::H<'_>) -> Option<u32>;

    /// What `op` reads from this storage ([`MeshTopology::access`](crate::MeshTopology::access));
    /// `None` (the default): no model.
    fn access(op: crate::core::topology::Operator) -> Option<crate::core::access::Access> {
        let _ = op;
        None
    }
}

/// A half-edge structure over the storage `L`; see the module docs.
pub struct HalfEdge<L> {
    /// The storage that answers the primitives.
    pub(crate) links: L,
    /// What edits deleted and `garbage_collection` has not yet removed.
    pub(crate) marks: edit::Marks,
}

impl<L: HalfEdgeLinks> HalfEdge<L> {
    /// Calls `f` with every half-edge leaving `v`, rotating with `next(twin(h))` (the
    /// lecture's `edge->pair->next`), starting at `v`'s half-edge.
    #[inline(always)]
    fn for_each_outgoing<'a>(&'a self, v: VertexId, mut f: impl FnMut(L::H<'a>)) {
        let l = &self.links;
        let Some(start) = l.outgoing(v) else {
            return;
        };
        let mut h = start;
        loop {
            f(h);
            h = l.next(l.twin(h));
            if h == start {
                break;
            }
        }
    }

    /// Calls `f` with every half-edge of the loop of `start` (a face or boundary loop).
    #[inline(always)]
    fn for_each_in_loop<'a>(&'a self, start: L::H<'a>, mut f: impl FnMut(L::H<'a>)) {
        let mut h = start;
        loop {
            f(h);
            h = self.links.next(h);
            if h == start {
                break;
            }
        }
    }

    #[inline(always)]
    fn edge_of(&self, h: L::H<'_>) -> EdgeId {
        EdgeId(self.links.id(h) >> 1)
    }

    /// The half-edge of `e` that borders `face`, if any.
    #[inline]
    fn half_edge_in(&self, e: EdgeId, face: FaceId) -> Option<L::H<'_>> {
        let h = self.links.half_edge(2 * e.0);
        let t = self.links.twin(h);
        [h, t]
            .into_iter()
            .find(|&x| self.links.face(x) == Some(face))
    }

    /// The storage, for tests and measurements.
    pub fn links(&self) -> &L {
        &self.links
    }
}

#[cfg(test)]
mod tests {
    use crate::core::soup::PolygonSoup;
    use crate::core::topology::{BoundaryCurves, MeshTopology};
    use crate::families::half_edge::index::IndexHalfEdge;
    use crate::families::half_edge::pointer::PointerHalfEdge;
    use crate::meshes;
    use glam::DVec3;

    /// Empty input, unused vertices and several boundary loops, for both storages.
    fn edge_cases<M: MeshTopology>() {
        let empty = M::from_soup(&PolygonSoup::new()).expect("an empty mesh is a mesh");
        empty.validate().expect("valid");
        assert_eq!((empty.num_vertices(), empty.num_edges()), (0, 0));
        let mut curves = BoundaryCurves::default();
        empty.boundary_curves(&mut curves);
        assert!(curves.is_empty());

        let lonely = PolygonSoup::from_polygons(vec![DVec3::ZERO; 2], &[] as &[[u32; 3]]);
        let m = M::from_soup(&lonely).expect("unused vertices are allowed");
        m.validate().expect("valid");
        assert!(!m.is_boundary_vertex(crate::core::ids::VertexId(1)));

        let annulus = M::from_soup(&meshes::annulus(5)).expect("manifold");
        annulus.boundary_curves(&mut curves);
        assert_eq!(curves.len(), 2, "inner and outer boundary");
        assert_eq!(curves.edges.len(), 10);
        assert_eq!(curves.starts, [0, 5, 10]);
    }

    #[test]
    fn edge_cases_of_both_storages() {
        edge_cases::<IndexHalfEdge>();
        edge_cases::<PointerHalfEdge>();
    }
}
