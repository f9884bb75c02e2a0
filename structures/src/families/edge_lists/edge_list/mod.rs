//! # Edge list
//!
//! The *Kantenliste* of the lecture on polygon-mesh data structures: vertices in a point list,
//! edges in a list of their own, each edge `E = (start, end, left polygon, right polygon)`, and
//! every polygon as the list of its edges' indices. The left polygon is the one that traverses the
//! edge from start to end (counter-clockwise seen from outside, its interior on the left, as the
//! lecture orients polygons); the right polygon traverses it from end to start and is `N` (none) on
//! the boundary. "Finding shared edges is now easier (check the second polygon index); finding the
//! shared vertices of polygons is still hard": nothing points from a vertex to its edges.
//!
//! | stores | bytes |
//! |---|---|
//! | `positions[v]`: x, y, z | 24 per vertex |
//! | `edge_start[e]`, `edge_end[e]`: start and end vertex | 8 per edge |
//! | `edge_left[e]`, `edge_right[e]`: left and right polygon (`N` = none) | 8 per edge |
//! | `face_edges[c]`: the edges of each polygon, in order | 4 per corner (12 per triangle) |
//! | `face_offsets[f]`: first entry of each polygon in `face_edges` | 4 per face |
//!
//! About 52 bytes per triangle of a closed triangle mesh (n1 = 1.5 n2, n0 = n2 / 2).
//! Structure-of-arrays: the vertex queries scan all edges but read only their end vertices,
//! so they stream 8 bytes per edge instead of a 16-byte record.
//!
//! `EdgeId`: index into the edge arrays, numbered by first appearance (edge 0 leaves the first
//! corner of face 0), as [`crate::core::soup::Connectivity`] numbers them; an edge's start and end
//! are the order in which its first face traverses it, so that face is its left polygon.
//!
//! Costs, as the lecture's table *Operationen in der Kantenliste* states them (n = number of
//! edges, k = valence of the vertex or corners of the k-gon):
//!
//! | given | wanted | operator | how | cost |
//! |---|---|---|---|---|
//! | vertex | outgoing edges | R01 | scan all n edges for the vertex | O(n) |
//! | vertex | neighbour vertices | R00 | the other ends of those edges | O(n) |
//! | vertex | adjacent faces | R02 | the polygon of each edge in which it leaves the vertex | O(n) |
//! | vertex | on the boundary? | boundary vertex | one of its edges has no right polygon | O(n) |
//! | edge | end points | R10 | start and end vertex in the edge | O(1) |
//! | edge | successor, predecessor | edge successor / predecessor | walk the polygon (k-gon) | O(k) |
//! | edge | adjacent faces | R12 | left and right polygon in the edge | O(1) |
//! | edge | on the boundary? | boundary edge | right polygon is `N` | O(1) |
//! | edge | edges of its faces | R11 | the edge lists of its two polygons | O(k) |
//! | face (k-gon) | vertices | R20 | in each edge, the vertex where the polygon enters it | O(k) |
//! | face (k-gon) | edges | R21 | the edge list of the polygon | O(k) |
//! | face (k-gon) | neighbour faces | R22 | the other polygon of each edge | O(k) |
//! | mesh | boundary curves | boundary curves | scan for right = `N`, then rotate around vertices | O(n) |
//!
//! Editing ([`MeshEdit`](crate::MeshEdit)): every operation, each at the cost of the scans it
//! needs (the table in `edit.rs`).
//!
//! Non-manifold vertices (several fans) are stored and answered correctly: the vertex queries
//! scan the edges and never assume one fan, and the boundary walk stays within a fan.
//! Non-manifold edges and inconsistent orientation are refused (an edge has room for two
//! polygons, one on each side).

mod edit;

use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::reads::{self, read, traced};
use crate::core::soup::PolygonSoup;
use crate::core::topology::{BoundaryCurves, Capabilities, Cost, MeshTopology, Operator};
use crate::families::edge_lists::boundary_walk;
use glam::DVec3;
use std::fmt::Write;

/// Edges with their end points and polygons, polygons as lists of edges; see the module docs.
#[derive(Clone, Debug)]
pub struct EdgeList {
    /// `positions[v]`: the coordinates of vertex v.
    positions: Vec<DVec3>,
    /// `edge_start[e]`: the vertex edge e starts at (as its left polygon traverses it).
    edge_start: Vec<VertexId>,
    /// `edge_end[e]`: the vertex edge e ends at.
    edge_end: Vec<VertexId>,
    /// `edge_left[e]`: the polygon that traverses e from start to end.
    edge_left: Vec<FaceId>,
    /// `edge_right[e]`: the polygon that traverses e from end to start; `INVALID` (the
    /// lecture's `N`) on the boundary.
    edge_right: Vec<FaceId>,
    /// The edges of every polygon in its order: polygon f is
    /// `face_edges[face_offsets[f]..face_offsets[f + 1]]`, edge i joining its corners i and i + 1.
    face_edges: Vec<EdgeId>,
    /// Start of each polygon in `face_edges`, plus one final entry.
    face_offsets: Vec<u32>,
    /// `deleted[v]`: vertex v was deleted by an edit ([`crate::MeshEdit`]) and keeps its slot
    /// until `garbage_collection`; empty until the first deletion.
    deleted: Vec<bool>,
}

impl EdgeList {
    /// The edges of face `f` in order.
    #[inline]
    fn edges_of(&self, f: FaceId) -> &[EdgeId] {
        &self.face_edges
            [self.face_offsets[f.index()] as usize..self.face_offsets[f.index() + 1] as usize]
    }

    /// The edges of face `f` in order, as the queries read them (see [`crate::core::reads`]).
    #[inline]
    fn listed(&self, f: FaceId) -> impl Iterator<Item = EdgeId> + '_ {
        let start = read!("face_offsets", self.face_offsets, f.index()) as usize;
        let end = read!("face_offsets", self.face_offsets, f.index() + 1) as usize;
        reads::each("face_edges", &self.face_edges[start..end], start)
    }

    /// Where face `f` enters and leaves edge `e`: e's start and end in f's traversal.
    #[inline]
    fn ends_in(&self, e: EdgeId, f: FaceId) -> [VertexId; 2] {
        let (start, end) = (
            read!("edge_start", self.edge_start, e.index()),
            read!("edge_end", self.edge_end, e.index()),
        );
        if read!("edge_left", self.edge_left, e.index()) == f {
            [start, end]
        } else {
            [end, start]
        }
    }

    /// Calls `f` with every edge that has `v` as an end, and whether `v` is its start: the
    /// lecture's "scan all n edges for the vertex".
    #[inline]
    fn scan_edges_of(&self, v: VertexId, mut f: impl FnMut(EdgeId, bool)) {
        for (e, (&start, &end)) in self.edge_start.iter().zip(&self.edge_end).enumerate() {
            traced!("edge_start", e, start);
            traced!("edge_end", e, end);
            if start == v || end == v {
                f(EdgeId::new(e), start == v);
            }
        }
    }

    /// The edge after (`forward`) or before `e` in the cycle of face `f`, `None` if f has no
    /// edge e: the lecture's "walk the polygon".
    fn neighbour_in_face(&self, e: EdgeId, f: FaceId, forward: bool) -> Option<EdgeId> {
        if f.index() >= self.num_faces() {
            return None;
        }
        let _start = read!("face_offsets", self.face_offsets, f.index());
        traced!(
            "face_offsets",
            f.index() + 1,
            self.face_offsets[f.index() + 1]
        );
        let edges = self.edges_of(f);
        let i = edges.iter().position(|&x| x == e);
        #[cfg(feature = "count-reads")]
        for (j, x) in edges
            .iter()
            .take(i.map_or(edges.len(), |i| i + 1))
            .enumerate()
        {
            traced!("face_edges", _start as usize + j, *x);
        }
        let i = i?;
        let step = if forward { 1 } else { edges.len() - 1 };
        let j = (i + step) % edges.len();
        traced!("face_edges", _start as usize + j, edges[j]);
        Some(edges[j])
    }
}

impl MeshTopology for EdgeList {
    const NAME: &'static str = "edge-list";
    const FAMILY: crate::core::family::Family = crate::core::family::Family::EdgeLists;

    fn capabilities() -> Capabilities {
        Capabilities {
            non_manifold_vertices: true,
            ..Capabilities::POLYGONS
        }
    }

    fn cost(op: Operator) -> Cost {
        match op {
            Operator::R00 | Operator::R01 | Operator::R02 | Operator::BoundaryVertex => {
                Cost::Linear
            }
            Operator::R10 | Operator::R12 | Operator::BoundaryEdge => Cost::Constant,
            Operator::EdgeSuccessor | Operator::EdgePredecessor => Cost::Local,
            Operator::R11 | Operator::R20 | Operator::R21 | Operator::R22 => Cost::Local,
            Operator::BoundaryCurves => Cost::Linear,
        }
    }

    fn from_soup(soup: &PolygonSoup) -> Result<Self> {
        let conn = soup.connectivity()?;
        let corner = |c: u32| soup.indices()[c as usize];
        let next = |c: u32| soup.next_corner(c as usize, conn.corner_face[c as usize] as usize);
        let n1 = conn.num_edges();
        let (mut edge_start, mut edge_end) = (Vec::with_capacity(n1), Vec::with_capacity(n1));
        let (mut edge_left, mut edge_right) = (Vec::with_capacity(n1), Vec::with_capacity(n1));
        for &[first, other] in &conn.edge_corners {
            edge_start.push(VertexId(corner(first)));
            edge_end.push(VertexId(soup.indices()[next(first)]));
            edge_left.push(FaceId(conn.corner_face[first as usize]));
            edge_right.push(if other == u32::MAX {
                FaceId::INVALID
            } else {
                FaceId(conn.corner_face[other as usize])
            });
        }
        Ok(Self {
            positions: soup.positions.clone(),
            edge_start,
            edge_end,
            edge_left,
            edge_right,
            face_edges: conn.corner_edge.iter().map(|&e| EdgeId(e)).collect(),
            face_offsets: soup.offsets().to_vec(),
            deleted: Vec::new(),
        })
    }

    #[inline]
    fn num_vertices(&self) -> usize {
        self.positions.len()
    }
    #[inline]
    fn num_edges(&self) -> usize {
        self.edge_start.len()
    }
    #[inline]
    fn num_faces(&self) -> usize {
        self.face_offsets.len() - 1
    }
    fn for_each_edge(&self, mut f: impl FnMut(EdgeId)) {
        (0..self.num_edges()).for_each(|e| f(EdgeId::new(e)));
    }
    #[inline]
    fn position(&self, v: VertexId) -> DVec3 {
        self.positions[v.index()]
    }

    #[inline]
    fn vertex_vertices(&self, v: VertexId, mut f: impl FnMut(VertexId)) {
        self.scan_edges_of(v, |e, starts| {
            f(if starts {
                read!("edge_end", self.edge_end, e.index())
            } else {
                read!("edge_start", self.edge_start, e.index())
            })
        });
    }
    #[inline]
    fn vertex_edges(&self, v: VertexId, mut f: impl FnMut(EdgeId)) {
        self.scan_edges_of(v, |e, _| f(e));
    }
    #[inline]
    fn vertex_faces(&self, v: VertexId, mut f: impl FnMut(FaceId)) {
        // A polygon through v leaves v along exactly one of its edges: the left polygon of an
        // edge starting at v, or the right polygon of an edge ending at v.
        self.scan_edges_of(v, |e, starts| {
            let leaving = if starts {
                read!("edge_left", self.edge_left, e.index())
            } else {
                read!("edge_right", self.edge_right, e.index())
            };
            if let Some(face) = leaving.valid() {
                f(face);
            }
        });
    }
    #[inline]
    fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2] {
        [
            read!("edge_start", self.edge_start, e.index()),
            read!("edge_end", self.edge_end, e.index()),
        ]
    }
    #[inline]
    fn edge_edges(&self, e: EdgeId, mut f: impl FnMut(EdgeId)) {
        self.edge_faces(e, |face| {
            for x in self.listed(face) {
                if x != e {
                    f(x);
                }
            }
        });
    }
    #[inline]
    fn edge_faces(&self, e: EdgeId, mut f: impl FnMut(FaceId)) {
        f(read!("edge_left", self.edge_left, e.index()));
        if let Some(right) = read!("edge_right", self.edge_right, e.index()).valid() {
            f(right);
        }
    }
    #[inline]
    fn face_vertices(&self, face: FaceId, mut f: impl FnMut(VertexId)) {
        for e in self.listed(face) {
            f(self.ends_in(e, face)[0]);
        }
    }
    #[inline]
    fn face_edges(&self, face: FaceId, f: impl FnMut(EdgeId)) {
        self.listed(face).for_each(f);
    }
    #[inline]
    fn face_faces(&self, face: FaceId, mut f: impl FnMut(FaceId)) {
        for e in self.listed(face) {
            let (left, right) = (
                read!("edge_left", self.edge_left, e.index()),
                read!("edge_right", self.edge_right, e.index()),
            );
            if let Some(other) = (if left == face { right } else { left }).valid() {
                f(other);
            }
        }
    }
    #[inline]
    fn is_boundary_vertex(&self, v: VertexId) -> bool {
        let mut boundary = false;
        self.scan_edges_of(v, |e, _| {
            boundary |= !read!("edge_right", self.edge_right, e.index()).is_valid()
        });
        boundary
    }
    #[inline]
    fn is_boundary_edge(&self, e: EdgeId) -> bool {
        !read!("edge_right", self.edge_right, e.index()).is_valid()
    }
    #[inline]
    fn boundary_curves(&self, out: &mut BoundaryCurves) {
        boundary_walk::boundary_curves(self, out);
    }
    #[inline]
    fn edge_successor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        self.neighbour_in_face(e, face, true)
    }
    #[inline]
    fn edge_predecessor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        self.neighbour_in_face(e, face, false)
    }

    fn validate(&self) -> Result<()> {
        let fail = |message: String| Err(Error::invariant(Self::NAME, message));
        let (n0, n1, n2) = (self.num_vertices(), self.num_edges(), self.num_faces());
        if [&self.edge_end, &self.edge_start]
            .iter()
            .any(|a| a.len() != n1)
            || [&self.edge_left, &self.edge_right]
                .iter()
                .any(|a| a.len() != n1)
        {
            return fail("the four edge arrays differ in length".into());
        }
        if self.face_offsets.first() != Some(&0)
            || self.face_offsets.last().map(|&o| o as usize) != Some(self.face_edges.len())
            || self.face_offsets.windows(2).any(|w| w[1] < w[0] + 3)
        {
            return fail(
                "face offsets must start at 0, grow by at least 3 and end at the edge-list length"
                    .into(),
            );
        }
        // Each edge: ends exist and differ, its left polygon exists, the right one is N or another polygon.
        for e in 0..n1 {
            let (a, b) = (self.edge_start[e], self.edge_end[e]);
            let (left, right) = (self.edge_left[e], self.edge_right[e]);
            if a.index() >= n0 || b.index() >= n0 || a == b {
                return fail(format!("edge e{e} has ends {a:?}, {b:?}"));
            }
            if left.index() >= n2 || right == left || (right.is_valid() && right.index() >= n2) {
                return fail(format!("edge e{e} has polygons {left:?}, {right:?}"));
            }
        }
        // Each polygon: its edges exist, name it as left or right, and chain head to tail.
        // Counting the mentions per side checks that the left polygon lists the edge once, and
        // the right one once if there is one.
        let mut mentions = vec![[0u32; 2]; n1];
        for f in 0..n2 {
            let face = FaceId::new(f);
            let edges = self.edges_of(face);
            for (i, &e) in edges.iter().enumerate() {
                if e.index() >= n1 {
                    return fail(format!("polygon f{f} lists a missing edge {e:?}"));
                }
                if self.edge_left[e.index()] != face && self.edge_right[e.index()] != face {
                    return fail(format!(
                        "polygon f{f} lists e{} but is not one of its polygons",
                        e.0
                    ));
                }
                let next = edges[(i + 1) % edges.len()];
                if next.index() >= n1 || self.ends_in(next, face)[0] != self.ends_in(e, face)[1] {
                    return fail(format!(
                        "in polygon f{f}, e{} does not continue with e{}",
                        e.0, next.0
                    ));
                }
                mentions[e.index()][(self.edge_left[e.index()] != face) as usize] += 1;
            }
        }
        for (e, (&[left, right], face)) in mentions.iter().zip(&self.edge_right).enumerate() {
            if left != 1 || right != face.is_valid() as u32 {
                return fail(format!(
                    "edge e{e} is listed {left} times by its left and {right} times by its right polygon"
                ));
            }
        }
        Ok(())
    }

    fn heap_bytes(&self) -> usize {
        self.positions.capacity() * std::mem::size_of::<DVec3>()
            + (self.edge_start.capacity() + self.edge_end.capacity()) * 4
            + (self.edge_left.capacity() + self.edge_right.capacity()) * 4
            + self.face_edges.capacity() * 4
            + self.face_offsets.capacity() * 4
            + self.deleted.capacity()
    }

    fn explain(&self, w: &mut dyn Write) -> std::fmt::Result {
        writeln!(w, "edge list (Kantenliste): a point list, an edge list E = (start, end, left polygon, right polygon), polygons as lists of edge indices")?;
        writeln!(w, "indices start at 0; N = no polygon (boundary); the left polygon traverses the edge from start to end")?;
        writeln!(w, "V = ({} vertices)", self.num_vertices())?;
        for (v, p) in self.positions.iter().enumerate() {
            writeln!(w, "  V{v} = ({:.3}, {:.3}, {:.3})", p.x, p.y, p.z)?;
        }
        writeln!(w, "E = ({} edges)", self.num_edges())?;
        for e in 0..self.num_edges() {
            let right = match self.edge_right[e].valid() {
                Some(f) => format!("P{}", f.0),
                None => "N".to_string(),
            };
            writeln!(
                w,
                "  E{e} = ({}, {}, P{}, {right})",
                self.edge_start[e].0, self.edge_end[e].0, self.edge_left[e].0
            )?;
        }
        writeln!(w, "polygons ({}):", self.num_faces())?;
        for f in 0..self.num_faces() {
            let edges: Vec<String> = self
                .edges_of(FaceId::new(f))
                .iter()
                .map(|e| e.0.to_string())
                .collect();
            writeln!(w, "  P{f} = ({})", edges.join(", "))?;
        }
        writeln!(
            w,
            "all edges of a vertex: scan all {} edges for it",
            self.num_edges()
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::meshes;

    /// The lecture's example (two triangles P1 = (E5, E4, E1), P2 = (E2, E4, E3) over V1..V4),
    /// 0-based: P1 runs V1 → V4 → V2, P2 runs V3 → V2 → V4.
    fn lecture_example() -> EdgeList {
        let soup = PolygonSoup::from_polygons(
            vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y],
            &[[0u32, 3, 1], [2, 1, 3]],
        );
        EdgeList::from_soup(&soup).unwrap()
    }

    #[test]
    fn the_shared_edge_has_the_lectures_start_end_left_and_right() {
        let m = lecture_example();
        // The lecture's E4 = (4, 2, P1, P2): from V4 to V2, P1 on the left, P2 on the right.
        let shared = (0..m.num_edges())
            .find(|&e| !m.is_boundary_edge(EdgeId::new(e)))
            .unwrap();
        assert_eq!(
            m.edge_vertices(EdgeId::new(shared)),
            [VertexId(3), VertexId(1)]
        );
        assert_eq!(
            (m.edge_left[shared], m.edge_right[shared]),
            (FaceId(0), FaceId(1))
        );
        // Every boundary edge has its polygon on the left and N on the right, like E1, E2, E3, E5.
        assert_eq!(m.num_boundary_edges(), 4);
        m.validate().unwrap();
    }

    #[test]
    fn validate_reports_a_polygon_listed_on_the_wrong_side() {
        let mut m = lecture_example();
        m.edge_right.swap(0, 1);
        let err = m.validate().unwrap_err();
        assert_eq!(err.kind(), "invariant", "{err}");
        let mut m = lecture_example();
        m.face_edges.swap(0, 1);
        assert!(m.validate().is_err(), "a polygon whose edges do not chain");
    }

    #[test]
    fn heap_bytes_are_the_documented_bytes_per_element() {
        let soup = meshes::torus(6, 5);
        let m = EdgeList::from_soup(&soup).unwrap();
        let (n0, n1, n2) = (m.num_vertices(), m.num_edges(), m.num_faces());
        let corners = soup.num_corners();
        assert_eq!(
            m.heap_bytes(),
            24 * n0 + 16 * n1 + 4 * corners + 4 * (n2 + 1)
        );
        // 52 bytes per triangle (plus the final offset) on a closed triangle mesh.
        assert_eq!(m.heap_bytes(), 52 * n2 + 4);
    }

    #[test]
    fn explain_prints_the_lectures_records_for_the_open_tetrahedron() {
        let m = EdgeList::from_soup(&meshes::open_tetrahedron()).unwrap();
        let mut text = String::new();
        m.explain(&mut text).unwrap();
        // Face 0 = (0, 1, 3): its first edge runs 0 -> 1 with face 0 on the left and no face on the right.
        assert!(text.contains("E0 = (0, 1, P0, N)"), "{text}");
        assert!(text.contains("P0 = (0, 1, 2)"), "{text}");
        assert_eq!(text.matches("  E").count(), 6, "{text}");
    }
}
