//! # Pointer half-edge
//!
//! The half-edge structure of the lecture on polygon-mesh data structures exactly as its slides
//! declare it, records linked by
//! real pointers, each record its own heap allocation:
//!
//! ```text
//! struct HE_edge { HE_vert* vert; HE_edge* pair; HE_face* face; HE_edge* next; };
//! struct HE_vert { float x, y, z; HE_edge* edge; };
//! struct HE_face { HE_edge* edge; };
//! ```
//!
//! Measuring what chasing those pointers costs against the same connectivity in index arrays
//! ([`crate::IndexHalfEdge`]) is the point of this structure: both answer every operator with the
//! same code ([`crate::families::half_edge::HalfEdge`]), monomorphised for pointers here and for
//! arrays there. All unsafe code of the crate is in the private `links` module: records are written
//! only while they are built or edited (through `&mut`: no reference to a record is alive then),
//! never move, and are freed in `Drop` (garbage collection after edits builds them anew).
//!
//! | record (one allocation each) | fields | bytes |
//! |---|---|---|
//! | `HE_edge` per half-edge | `vert`, `pair`, `face`, `next` (8 each), `id` (4) + padding | 40 |
//! | `HE_vert` per vertex | `x`, `y`, `z` (`f64`, the lab's precision), `edge` (8), `id` (4) + padding | 40 |
//! | `HE_face` per face | `edge` (8), `id` (4) + padding | 16 |
//! | id tables `verts`, `faces`, `edges` | one pointer per record: the way in from an id, and what `Drop` frees | 8 per record |
//!
//! The `id` fields answer queries in the lab's ids (vertex i of the input is `VertexId(i)`);
//! walking never uses them. A closed triangle mesh (3 half-edges and 1/2 vertex per face) takes
//! 3 · 48 + 24 + 48 / 2 = 192 bytes per face, plus the allocator's overhead per record
//! (not counted by `heap_bytes`), against 66 for the index half-edge.
//!
//! Boundary: as OpenMesh does, every boundary edge has an explicit boundary half-edge with
//! `face = null`, so `pair` is never null and the lecture's loops need no NULL checks; boundary
//! half-edges are linked by `next` around each hole, and a boundary vertex's `edge` is its
//! outgoing boundary half-edge (boundary test: `vert->edge->face == null`).
//!
//! `EdgeId` `e`: half-edges `2e` and `2e + 1`; edges numbered by first appearance in the soup.
//!
//! | operator | how (the lecture's loops) | cost |
//! |---|---|---|
//! | R00, R01, R02 | from `vert->edge`, `edge = edge->pair->next` | O(k) |
//! | R10, R12 | `edge->vert`, `edge->pair->vert`; `edge->face`, `edge->pair->face` | O(1) |
//! | R11, R20, R21, R22 | `edge = edge->next` around the face(s) | O(k) |
//! | successor | the half-edge in that face, `->next` | O(1) |
//! | predecessor | no `prev` pointer: walk `next` around the face | O(k) |
//! | boundary vertex, boundary edge | `face == null` | O(1) |
//! | boundary curves | scan the half-edges for boundary ones, walk each loop | O(n) |
//!
//! The lecture's summary table gives the successor O(k) too; it assumes a stored predecessor
//! instead of the record's `next` (see "Costs" in [`crate::families::half_edge`]).
//!
//! Construction: `soup.connectivity()` (one pass by buckets) and its fan walk, then
//! linear. Non-manifold vertices are refused ([`crate::Error::NonManifoldVertex`]).

#[allow(unsafe_code)]
mod links;

use crate::core::error::{Error, Result};
use crate::core::ids::{FaceId, VertexId};
use crate::core::reads::traced;
use crate::core::topology::Cost;
use crate::families::half_edge::edit::HalfEdgeLinksMut;
use crate::families::half_edge::{HalfEdge, HalfEdgeArrays, HalfEdgeLinks};
use glam::DVec3;
use links::{HeEdge, Records};
use std::fmt::Write;

/// The pointer half-edge structure; see the module docs.
pub type PointerHalfEdge = HalfEdge<PointerLinks>;

/// The heap records of [`PointerHalfEdge`].
pub struct PointerLinks {
    /// Every record, with the tables from ids to records.
    records: Records,
}

/// A half-edge while walking: a reference to its record, equal by address.
#[derive(Copy, Clone)]
pub struct EdgeRef<'a>(&'a HeEdge);

impl PartialEq for EdgeRef<'_> {
    #[inline(always)]
    fn eq(&self, other: &Self) -> bool {
        std::ptr::eq(self.0, other.0)
    }
}
impl Eq for EdgeRef<'_> {}

impl HalfEdgeLinks for PointerLinks {
    type H<'a> = EdgeRef<'a>;

    const NAME: &'static str = "pointer-half-edge";
    const PREDECESSOR: Cost = Cost::Local;

    fn from_arrays(arrays: HalfEdgeArrays, positions: &[DVec3]) -> Self {
        Self {
            records: Records::new(&arrays, positions),
        }
    }

    fn num_half_edges(&self) -> usize {
        self.records.counts().2
    }
    fn num_vertices(&self) -> usize {
        self.records.counts().0
    }
    fn num_faces(&self) -> usize {
        self.records.counts().1
    }
    #[inline(always)]
    fn half_edge(&self, id: u32) -> EdgeRef<'_> {
        EdgeRef(self.records.edge(id))
    }
    #[inline(always)]
    fn id(&self, h: EdgeRef<'_>) -> u32 {
        h.0.id()
    }
    #[inline(always)]
    fn twin<'a>(&'a self, h: EdgeRef<'a>) -> EdgeRef<'a> {
        let pair = h.0.pair();
        traced!("pair", h.0.id(), pair.id());
        EdgeRef(pair)
    }
    #[inline(always)]
    fn next<'a>(&'a self, h: EdgeRef<'a>) -> EdgeRef<'a> {
        let next = h.0.next();
        traced!("next", h.0.id(), next.id());
        EdgeRef(next)
    }
    #[inline(always)]
    fn vertex(&self, h: EdgeRef<'_>) -> VertexId {
        let vert = h.0.vert().id();
        traced!("vert", h.0.id(), vert);
        VertexId(vert)
    }
    #[inline(always)]
    fn face(&self, h: EdgeRef<'_>) -> Option<FaceId> {
        let face = h.0.face().map(|f| FaceId(f.id()));
        traced!("face", h.0.id(), face.unwrap_or(FaceId::INVALID));
        face
    }
    #[inline(always)]
    fn outgoing(&self, v: VertexId) -> Option<EdgeRef<'_>> {
        let edge = self.records.vert(v.0).edge();
        traced!("HE_vert.edge", v.0, edge.map_or(u32::MAX, |e| e.id()));
        edge.map(EdgeRef)
    }
    #[inline(always)]
    fn face_half_edge(&self, f: FaceId) -> EdgeRef<'_> {
        let edge = self.records.face(f.0).edge();
        traced!("HE_face.edge", f.0, edge.id());
        EdgeRef(edge)
    }
    #[inline(always)]
    fn position(&self, v: VertexId) -> DVec3 {
        self.records.vert(v.0).position()
    }

    fn heap_bytes(&self) -> usize {
        self.records.heap_bytes()
    }

    fn validate_storage(&self) -> Result<()> {
        self.records
            .validate()
            .map_err(|message| Error::invariant(Self::NAME, message))
    }

    fn describe(w: &mut dyn Write) -> std::fmt::Result {
        writeln!(
            w,
            "pointer half-edge: the HE_vert, HE_face and HE_edge records of the lecture on\n\
             polygon-mesh data structures, each its own heap allocation, linked by pointers\n\
             (printed as the id of the record pointed to)"
        )
    }

    fn stored_prev(&self, _h: EdgeRef<'_>) -> Option<u32> {
        None
    }
    fn access(op: crate::core::topology::Operator) -> Option<crate::core::access::Access> {
        super::access::pointer(op)
    }
}

impl HalfEdgeLinksMut for PointerLinks {
    fn set_next(&mut self, h: u32, n: u32) {
        self.records.set_next(h, n);
    }
    fn set_vertex(&mut self, h: u32, v: u32) {
        self.records.set_vert(h, v);
    }
    fn set_face(&mut self, h: u32, f: u32) {
        self.records.set_face(h, f);
    }
    fn set_outgoing(&mut self, v: u32, h: u32) {
        self.records.set_vert_edge(v, h);
    }
    fn set_face_half_edge(&mut self, f: u32, h: u32) {
        self.records.set_face_edge(f, h);
    }
    fn set_position(&mut self, v: u32, p: DVec3) {
        self.records.set_position(v, p);
    }
    fn push_vertex(&mut self, p: DVec3) -> u32 {
        self.records.push_vert(p)
    }
    fn push_edge(&mut self, a: u32, b: u32) -> u32 {
        self.records.push_edge_pair(a, b)
    }
    fn push_face(&mut self, h: u32) -> u32 {
        self.records.push_face(h)
    }
    fn reserve(&mut self, vertices: usize, edges: usize, faces: usize) {
        self.records.reserve(vertices, edges, faces);
    }
}

#[cfg(test)]
mod tests {
    use super::links::LIVE_RECORDS;
    use super::*;
    use crate::core::topology::MeshTopology;
    use crate::families::half_edge::index::IndexHalfEdge;
    use crate::meshes::{self, RandomMeshParams};

    fn live() -> isize {
        LIVE_RECORDS.with(|n| n.get())
    }

    #[test]
    fn building_and_dropping_many_meshes_frees_every_record() {
        let before = live();
        let mut built = 0;
        let soups = meshes::canonical()
            .into_iter()
            .map(|m| m.soup)
            .chain((0..300).map(|seed| meshes::random_mesh(seed, RandomMeshParams::default())));
        for soup in soups {
            let Ok(m) = PointerHalfEdge::from_soup(&soup) else {
                continue;
            };
            m.validate().expect("a fresh build is valid");
            let records = m.num_vertices() + m.num_faces() + 2 * m.num_edges();
            assert_eq!(
                live() - before,
                records as isize,
                "one allocation per record"
            );
            drop(m);
            assert_eq!(live(), before, "Drop frees every record");
            built += 1;
        }
        assert!(built > 100, "only {built} meshes were manifold");
    }

    #[test]
    fn records_take_the_bytes_the_module_docs_state() {
        use std::mem::size_of;
        assert_eq!(size_of::<super::links::HeEdge>(), 40);
        assert_eq!(size_of::<super::links::HeVert>(), 40);
        assert_eq!(size_of::<super::links::HeFace>(), 16);
        let m = PointerHalfEdge::from_soup(&meshes::closed_tetrahedron()).expect("manifold");
        let (records, tables) = (4 * 40 + 4 * 16 + 12 * 40, (4 + 4 + 12) * 8);
        assert_eq!(m.heap_bytes(), records + tables);
    }

    #[test]
    fn meshes_can_be_shared_across_threads_like_the_index_structure() {
        fn send_and_sync<T: Send + Sync>() {}
        send_and_sync::<PointerHalfEdge>();
        let m = PointerHalfEdge::from_soup(&meshes::closed_tetrahedron()).expect("manifold");
        let valences: Vec<usize> = std::thread::scope(|s| {
            let handles: Vec<_> = (0..4)
                .map(|v| {
                    let m = &m;
                    s.spawn(move || {
                        let mut n = 0;
                        m.vertex_vertices(VertexId(v), |_| n += 1);
                        n
                    })
                })
                .collect();
            handles
                .into_iter()
                .map(|h| h.join().expect("no panic"))
                .collect()
        });
        assert_eq!(valences, [3, 3, 3, 3]);
    }

    #[test]
    fn validate_catches_a_misdirected_pointer() {
        let soup = meshes::open_tetrahedron();
        let mut m = PointerHalfEdge::from_soup(&soup).expect("manifold");
        m.validate().expect("a fresh build is valid");
        m.links.records.relink_next(0, 5);
        let err = m.validate().expect_err("h0.next no longer continues h0");
        assert_eq!(err.kind(), "invariant");
        assert!(err.to_string().contains("h0"), "{err}");
    }

    #[test]
    fn explain_shows_the_same_records_as_the_index_half_edge_without_prev() {
        let soup = meshes::open_tetrahedron();
        let (mut pointers, mut indices) = (String::new(), String::new());
        let p = PointerHalfEdge::from_soup(&soup).expect("manifold");
        p.explain(&mut pointers).expect("string");
        let i = IndexHalfEdge::from_soup(&soup).expect("manifold");
        i.explain(&mut indices).expect("string");
        let records = |text: &str| -> Vec<String> {
            text.lines()
                .filter(|l| l.starts_with("  "))
                .map(|l| match (l.find(", prev"), l.find("  (edge")) {
                    (Some(a), Some(b)) => format!("{}{}", &l[..a], &l[b..]),
                    _ => l.to_string(),
                })
                .collect()
        };
        assert_eq!(records(&pointers), records(&indices));
        assert_eq!(records(&pointers).len(), 4 + 3 + 12);
        assert!(!pointers.contains("prev"), "{pointers}");
    }
}
