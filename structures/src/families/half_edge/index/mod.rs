//! # Index half-edge
//!
//! The half-edge structure of the lecture on polygon-mesh data structures stored the way OpenMesh
//! and pmp-library store it: structure of arrays with `u32` handles instead of pointers. Edge `e`
//! owns half-edges `2e` and `2e + 1`, so the lecture's `pair` is not stored: `pair(h) = h ^ 1`.
//! Boundary edges get an explicit boundary half-edge with no face, linked by `next` around the
//! hole, and a boundary vertex's half-edge is its outgoing boundary half-edge (as in OpenMesh), so
//! the boundary test is one read. Every circulator is built from two primitives, `next` and `twin`;
//! the operators are the ones shared with the pointer half-edge
//! ([`crate::families::half_edge::HalfEdge`]), monomorphised for arrays.
//!
//! | stores | lecture field | bytes |
//! |---|---|---|
//! | `positions[v]`: x, y, z | `HE_vert::{x, y, z}` | 24 per vertex |
//! | `vertex_half_edge[v]`: an outgoing half-edge (boundary one first) | `HE_vert::edge` | 4 per vertex |
//! | `face_half_edge[f]`: the half-edge leaving the first corner | `HE_face::edge` | 4 per face |
//! | `vertex[h]`: start vertex | `HE_edge::vert` | 4 per half-edge |
//! | `next[h]`: next half-edge of the face or boundary loop | `HE_edge::next` | 4 per half-edge |
//! | `prev[h]`: previous half-edge (OpenMesh keeps it too) | — | 4 per half-edge |
//! | `face[h]`: face, `u32::MAX` on the boundary | `HE_edge::face` | 4 per half-edge |
//! | `pair(h) = h ^ 1` | `HE_edge::pair` | 0 |
//!
//! A closed triangle mesh has about 3 half-edges per face and 1/2 vertex per face:
//! 16 · 3 + 4 + 28 / 2 = 66 bytes per face, OpenMesh's measured 66 B/face.
//!
//! `EdgeId` `e`: half-edges `2e` and `2e + 1`; edges numbered by first appearance in the soup.
//!
//! | operator | how | cost |
//! |---|---|---|
//! | R00, R01, R02 | rotate `next(twin(h))` from the vertex's half-edge | O(k) |
//! | R10, R12 | the pair's two half-edges | O(1) |
//! | R11, R20, R21, R22 | walk `next` around the face(s) | O(k) |
//! | boundary vertex | `face[vertex_half_edge[v]]` is none | O(1) |
//! | boundary edge | either half-edge has no face | O(1) |
//! | boundary curves | scan the half-edges for boundary ones, walk each loop | O(n) |
//! | successor, predecessor | the half-edge in that face, then `next` / `prev` | O(1) |
//!
//! Construction: `soup.connectivity()` (one pass by buckets, see [`crate::Connectivity`])
//! and its fan walk, then linear; no hash maps. Non-manifold vertices are refused
//! ([`crate::Error::NonManifoldVertex`]).

use crate::core::error::Result;
use crate::core::ids::{FaceId, VertexId};
use crate::core::reads::read;
use crate::core::topology::Cost;
use crate::families::half_edge::edit::HalfEdgeLinksMut;
use crate::families::half_edge::{HalfEdge, HalfEdgeArrays, HalfEdgeLinks, NONE};
use glam::DVec3;
use std::fmt::Write;

/// The index half-edge structure; see the module docs.
pub type IndexHalfEdge = HalfEdge<IndexLinks>;

/// The arrays of [`IndexHalfEdge`].
#[derive(Clone, Debug)]
pub struct IndexLinks {
    /// `positions[v]`: the coordinates of vertex v.
    positions: Vec<DVec3>,
    /// `vertex`, `next`, `face` per half-edge and the per-vertex and per-face half-edges.
    arrays: HalfEdgeArrays,
    /// `prev[h]`: the half-edge whose `next` is `h`.
    prev: Vec<u32>,
}

impl HalfEdgeLinks for IndexLinks {
    type H<'a> = u32;

    const NAME: &'static str = "index-half-edge";
    const PREDECESSOR: Cost = Cost::Constant;

    fn from_arrays(arrays: HalfEdgeArrays, positions: &[DVec3]) -> Self {
        Self::from_arrays_owned(arrays, positions.to_vec())
    }

    fn from_arrays_owned(arrays: HalfEdgeArrays, positions: Vec<DVec3>) -> Self {
        let mut prev = vec![NONE; arrays.num_half_edges()];
        for (h, &n) in arrays.next.iter().enumerate() {
            prev[n as usize] = h as u32;
        }
        Self {
            positions,
            arrays,
            prev,
        }
    }

    #[inline(always)]
    fn num_half_edges(&self) -> usize {
        self.arrays.num_half_edges()
    }
    #[inline(always)]
    fn num_vertices(&self) -> usize {
        self.positions.len()
    }
    #[inline(always)]
    fn num_faces(&self) -> usize {
        self.arrays.face_half_edge.len()
    }
    #[inline(always)]
    fn half_edge(&self, id: u32) -> u32 {
        id
    }
    #[inline(always)]
    fn id(&self, h: u32) -> u32 {
        h
    }
    #[inline(always)]
    fn twin(&self, h: u32) -> u32 {
        h ^ 1
    }
    #[inline(always)]
    fn next(&self, h: u32) -> u32 {
        read!("next", self.arrays.next, h as usize)
    }
    #[inline(always)]
    fn prev(&self, h: u32) -> u32 {
        read!("prev", self.prev, h as usize)
    }
    #[inline(always)]
    fn vertex(&self, h: u32) -> VertexId {
        VertexId(read!("vert", self.arrays.vertex, h as usize))
    }
    #[inline(always)]
    fn face(&self, h: u32) -> Option<FaceId> {
        FaceId(read!("face", self.arrays.face, h as usize)).valid()
    }
    /// Also asserts that the per-half-edge arrays have one length (it is called once per
    /// rotation), so a rotation's reads of `next[x]`, `vertex[x]` and `prev[x]` at one index
    /// `x` share one bounds check.
    #[inline(always)]
    fn outgoing(&self, v: VertexId) -> Option<u32> {
        let a = &self.arrays;
        let n = a.vertex.len();
        assert!(
            a.next.len() == n && a.face.len() == n && self.prev.len() == n,
            "one entry per half-edge in every per-half-edge array"
        );
        let h = read!("HE_vert.edge", self.arrays.vertex_half_edge, v.index());
        (h != NONE).then_some(h)
    }
    #[inline(always)]
    fn face_half_edge(&self, f: FaceId) -> u32 {
        read!("HE_face.edge", self.arrays.face_half_edge, f.index())
    }
    #[inline(always)]
    fn position(&self, v: VertexId) -> DVec3 {
        self.positions[v.index()]
    }

    fn heap_bytes(&self) -> usize {
        self.positions.capacity() * std::mem::size_of::<DVec3>()
            + self.arrays.heap_bytes()
            + self.prev.capacity() * 4
    }

    /// Array lengths agree and every stored index is in range (the links themselves are
    /// checked by the shared validation).
    fn validate_storage(&self) -> Result<()> {
        let a = &self.arrays;
        let (nh, nv, nf) = (
            a.num_half_edges(),
            self.positions.len(),
            a.face_half_edge.len(),
        );
        let fail = |what: String| Err(crate::core::error::Error::invariant(Self::NAME, what));
        if a.next.len() != nh || a.face.len() != nh || self.prev.len() != nh {
            return fail("per-half-edge arrays differ in length".into());
        }
        if a.vertex_half_edge.len() != nv {
            return fail("vertex_half_edge and positions differ in length".into());
        }
        let in_range = |x: u32, n: usize| (x as usize) < n;
        for h in 0..nh {
            if !in_range(a.vertex[h], nv)
                || !in_range(a.next[h], nh)
                || !in_range(self.prev[h], nh)
                || !(a.face[h] == NONE || in_range(a.face[h], nf))
            {
                return fail(format!("h{h} holds an index out of range"));
            }
        }
        if let Some(v) = (0..nv).find(|&v| {
            let h = a.vertex_half_edge[v];
            h != NONE && !in_range(h, nh)
        }) {
            return fail(format!("v{v}'s half-edge is out of range"));
        }
        if let Some(f) = (0..nf).find(|&f| !in_range(a.face_half_edge[f], nh)) {
            return fail(format!("f{f}'s half-edge is out of range"));
        }
        Ok(())
    }

    fn describe(w: &mut dyn Write) -> std::fmt::Result {
        writeln!(
            w,
            "index half-edge (OpenMesh style): the records of the lecture on polygon-mesh data\n\
             structures as arrays of u32 handles\n\
             HE_vert v: positions[v] (x, y, z), vertex_half_edge[v] (edge)\n\
             HE_face f: face_half_edge[f] (edge)\n\
             HE_edge h: vertex[h] (vert), next[h], prev[h], face[h]; pair = h ^ 1 is not stored"
        )
    }

    fn stored_prev(&self, h: u32) -> Option<u32> {
        Some(self.prev[h as usize])
    }
    fn access(op: crate::core::topology::Operator) -> Option<crate::core::access::Access> {
        super::access::index(op)
    }
}

impl HalfEdgeLinksMut for IndexLinks {
    #[inline(always)]
    fn set_next(&mut self, h: u32, n: u32) {
        self.arrays.next[h as usize] = n;
        self.prev[n as usize] = h;
    }
    #[inline(always)]
    fn set_vertex(&mut self, h: u32, v: u32) {
        self.arrays.vertex[h as usize] = v;
    }
    #[inline(always)]
    fn set_face(&mut self, h: u32, f: u32) {
        self.arrays.face[h as usize] = f;
    }
    #[inline(always)]
    fn set_outgoing(&mut self, v: u32, h: u32) {
        self.arrays.vertex_half_edge[v as usize] = h;
    }
    #[inline(always)]
    fn set_face_half_edge(&mut self, f: u32, h: u32) {
        self.arrays.face_half_edge[f as usize] = h;
    }
    #[inline(always)]
    fn set_position(&mut self, v: u32, p: DVec3) {
        self.positions[v as usize] = p;
    }
    #[inline(always)]
    fn push_vertex(&mut self, p: DVec3) -> u32 {
        self.positions.push(p);
        self.arrays.vertex_half_edge.push(NONE);
        self.positions.len() as u32 - 1
    }
    #[inline(always)]
    fn push_edge(&mut self, a: u32, b: u32) -> u32 {
        let h = self.arrays.vertex.len() as u32;
        let a_ = &mut self.arrays;
        a_.vertex.extend([a, b]);
        // Linked by the caller before the operation returns.
        a_.next.extend([h, h + 1]);
        a_.face.extend([NONE, NONE]);
        self.prev.extend([h, h + 1]);
        h
    }
    #[inline(always)]
    fn push_face(&mut self, h: u32) -> u32 {
        self.arrays.face_half_edge.push(h);
        self.arrays.face_half_edge.len() as u32 - 1
    }
    fn reserve(&mut self, vertices: usize, edges: usize, faces: usize) {
        self.positions.reserve(vertices);
        self.arrays.vertex_half_edge.reserve(vertices);
        for a in [
            &mut self.arrays.vertex,
            &mut self.arrays.next,
            &mut self.arrays.face,
            &mut self.prev,
        ] {
            a.reserve(2 * edges);
        }
        self.arrays.face_half_edge.reserve(faces);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::topology::MeshTopology;
    use crate::meshes;

    fn tetrahedron() -> IndexHalfEdge {
        IndexHalfEdge::from_soup(&meshes::open_tetrahedron()).expect("manifold")
    }

    #[test]
    fn boundary_vertices_keep_their_boundary_half_edge() {
        let m = tetrahedron();
        for v in 0..3 {
            let h = m.links().outgoing(VertexId(v)).expect("used vertex");
            assert_eq!(m.links().face(h), None, "v{v} should start at the boundary");
        }
        let apex = m.links().outgoing(VertexId(3)).expect("used vertex");
        assert!(m.links().face(apex).is_some());
    }

    #[test]
    fn validate_catches_broken_links() {
        let mut m = tetrahedron();
        m.validate().expect("a fresh build is valid");
        let (a, b) = (m.links.arrays.next[0], m.links.arrays.next[2]);
        m.links.arrays.next.swap(0, 2);
        assert_ne!(a, b);
        assert_eq!(m.validate().map_err(|e| e.kind()), Err("invariant"));

        let mut m = tetrahedron();
        // v0's half-edge moved from its boundary half-edge to an interior one.
        let interior = (0..m.links.num_half_edges() as u32)
            .find(|&h| m.links.vertex(h) == VertexId(0) && m.links.face(h).is_some())
            .expect("v0 has faces");
        m.links.arrays.vertex_half_edge[0] = interior;
        let err = m.validate().expect_err("boundary half-edge invariant");
        assert!(err.to_string().contains("v0 is on the boundary"), "{err}");

        let mut m = tetrahedron();
        m.links.arrays.face[0] = 99;
        assert!(m.validate().is_err());
    }

    #[test]
    fn explain_prints_every_record_with_the_lecture_names() {
        let mut out = String::new();
        tetrahedron().explain(&mut out).expect("string");
        assert_eq!(out.matches("\n  h").count(), 12, "{out}");
        assert_eq!(out.matches("face = null").count(), 3 + 1, "{out}");
        assert!(
            out.contains("h0: vert = v0, pair = h1, face = f0, next = h2"),
            "{out}"
        );
    }
}
