//! # Sorted edge table
//!
//! A structure that lives outside the lab and is benchmarked by it: the worked example of the
//! lab's guide "Benchmark your own structure" (`docs/extend.md`). It implements
//! [`MeshTopology`] and nothing else of the lab; its tests run the lab's conformance suite
//! (`tests/conformance.rs`), its binary the lab's report with it added (`src/bin/report.rs`),
//! its bench the lab's criterion groups (`benches/operators.rs`).
//!
//! The structure: every edge of the mesh stored twice, once per direction, as a table of
//! directed edges `(a, b)` sorted by `a`, then `b`, and beside each the face that traverses it
//! from `a` to `b` (none on the outer side of a boundary edge). Nothing is stored per vertex:
//! a vertex's edges are the rows `(v, ·)`, found by binary search; an edge's other direction
//! is the row `(b, a)`, found the same way. It is the layout of a sparse adjacency matrix in
//! coordinate form, sorted by row; the faces are kept as lists of vertex indices (as in the
//! vertex list) for R20 and the faces' cyclic order.
//!
//! | stores | bytes |
//! |---|---|
//! | `positions[v]`: x, y, z | 24 per vertex |
//! | `ends[h]`: the directed edge `(a, b)`, sorted | 8 per directed edge (16 per edge) |
//! | `left[h]`: the face that traverses `h` from `a` to `b`, or [`NO_FACE`] | 4 per directed edge (8 per edge) |
//! | `corners[c]`, `offsets[f]`: each face's vertices in order | 4 per corner, 4 per face |
//!
//! `EdgeId`: the row of the edge's direction from the smaller vertex to the larger.
//!
//! | operator | how | cost |
//! |---|---|---|
//! | R00, R02, boundary vertex | binary search for the rows `(v, ·)`, then read them | O(log n + k) |
//! | R01 | the rows `(v, ·)`, and a binary search per row going down (to its edge's row) | O(k log n) |
//! | R10 | read the row | O(1) |
//! | R12, boundary edge | the row and its other direction (a binary search) | O(log n) |
//! | R20 | read the face's corners | O(k) |
//! | R21, R22, R11 | a binary search per side of the face(s) | O(k log n) |
//! | successor, predecessor | find the edge in the face's corners, one binary search | O(k + log n) |
//! | boundary curves | one scan of the rows, then a walk from outer row to outer row, turning around each end within its fan | O(n + ∂n k log n) |
//!
//! Non-manifold vertices (several fans) are stored and answered correctly: a vertex's rows are
//! its edges whatever its fans; an open fan has exactly one outer row leaving the vertex, and
//! the boundary curves continue each fan's boundary within the fan, as the lab defines them. Like
//! every structure of the lab it refuses non-manifold edges and inconsistent orientation (the
//! edge's two directions would not each have one face) with the soup's typed errors.
//!
//! Queries never allocate, and each is `#[inline]` so that the lab's kernels, generic over
//! the structure, compile it into their loops as they do the lab's own structures.
#![deny(missing_docs)]
#![forbid(unsafe_code)]

use std::fmt::Write;
use topolab_structures::glam::DVec3;
use topolab_structures::{
    BoundaryCurves, Capabilities, Cost, EdgeId, Error, FaceId, MeshTopology, Operator, PolygonSoup,
    Result, VertexId,
};

/// `left[h]` of a directed edge that no face traverses (the outer side of a boundary edge).
pub const NO_FACE: u32 = u32::MAX;

/// Every edge in both directions, sorted; see the crate docs.
#[derive(Clone, Debug, PartialEq)]
pub struct SortedEdgeTable {
    /// `positions[v]`: the coordinates of vertex v.
    positions: Vec<DVec3>,
    /// `ends[h] = [a, b]`: the directed edges, sorted, each edge in both directions.
    ends: Vec<[u32; 2]>,
    /// `left[h]`: the face that traverses `ends[h]` from `a` to `b`, or [`NO_FACE`].
    left: Vec<u32>,
    /// The faces' vertices, face after face.
    corners: Vec<u32>,
    /// Face f is `corners[offsets[f]..offsets[f + 1]]`.
    offsets: Vec<u32>,
}

impl SortedEdgeTable {
    /// The directed edges and their faces, as stored.
    pub fn rows(&self) -> (&[[u32; 2]], &[u32]) {
        (&self.ends, &self.left)
    }

    /// The row of the directed edge `a → b`, if the mesh has that edge.
    #[inline]
    fn row(&self, a: u32, b: u32) -> Option<usize> {
        self.ends.binary_search(&[a, b]).ok()
    }

    /// The edge between `a` and `b` (its row from the smaller end).
    #[inline]
    fn edge(&self, a: u32, b: u32) -> Option<EdgeId> {
        self.row(a.min(b), a.max(b)).map(EdgeId::new)
    }

    /// The rows `(v, ·)`: the directed edges leaving `v`.
    #[inline]
    fn leaving(&self, v: u32) -> std::ops::Range<usize> {
        let first = self.ends.partition_point(|e| e[0] < v);
        let count = self.ends[first..].iter().take_while(|e| e[0] == v).count();
        first..first + count
    }

    /// The row of `h`'s other direction.
    #[inline]
    fn reverse(&self, h: usize) -> Option<usize> {
        let [a, b] = self.ends[h];
        self.row(b, a)
    }

    /// The vertices of face `f`, in order.
    #[inline]
    fn face(&self, f: usize) -> &[u32] {
        &self.corners[self.offsets[f] as usize..self.offsets[f + 1] as usize]
    }

    /// The outer row that follows outer row `h` on its boundary curve, as the lab defines the
    /// curves (per fan): from `h`'s other direction, turn around `h`'s end `b` through the
    /// faces of that fan (each face's edge into `b`, then its other direction) until the row
    /// leaving `b` is an outer one. At a vertex of several fans this stays in `h`'s fan.
    #[inline]
    fn next_outer(&self, h: usize) -> Option<usize> {
        let b = self.ends[h][1];
        let mut inner = self.reverse(h)?;
        for _ in 0..self.ends.len() {
            let face = self.face(self.left[inner] as usize);
            let i = face.iter().position(|&v| v == b)?;
            let before = face[(i + face.len() - 1) % face.len()];
            let leaving = self.row(b, before)?;
            if self.left[leaving] == NO_FACE {
                return Some(leaving);
            }
            inner = leaving;
        }
        None
    }

    /// The faces on the two sides of edge `e` (`NO_FACE` on the outer side of a boundary).
    #[inline]
    fn sides(&self, e: EdgeId) -> [u32; 2] {
        let h = e.index();
        [
            self.left[h],
            self.reverse(h).map_or(NO_FACE, |r| self.left[r]),
        ]
    }

    /// The edge `step` sides after `e` in face `f`'s cycle (`step` = 1: the successor,
    /// `k - 1`: the predecessor); `None` if `e` is not a side of `f`.
    #[inline]
    fn neighbour_in_face(&self, e: EdgeId, f: FaceId, forward: bool) -> Option<EdgeId> {
        let [a, b] = self.ends[e.index()];
        let vs = self.face(f.index());
        let k = vs.len();
        let i = (0..k).find(|&i| {
            let (x, y) = (vs[i], vs[(i + 1) % k]);
            (x, y) == (a, b) || (x, y) == (b, a)
        })?;
        let j = if forward {
            (i + 1) % k
        } else {
            (i + k - 1) % k
        };
        self.edge(vs[j], vs[(j + 1) % k])
    }
}

impl MeshTopology for SortedEdgeTable {
    const NAME: &'static str = "sorted-edge-table";

    fn capabilities() -> Capabilities {
        Capabilities {
            non_manifold_vertices: true,
            ..Capabilities::POLYGONS
        }
    }

    fn cost(op: Operator) -> Cost {
        match op {
            Operator::R10 => Cost::Constant,
            Operator::R20 => Cost::Local,
            Operator::BoundaryCurves => Cost::Linear,
            // A binary search (times the k sides or neighbours, bounded on these meshes).
            _ => Cost::Log,
        }
    }

    fn from_soup(soup: &PolygonSoup) -> Result<Self> {
        // The soup's own analysis refuses what no structure of the lab stores (bad indices,
        // repeated vertices, non-manifold edges, inconsistent orientation) with typed errors.
        soup.connectivity()?;
        // Each edge appears at most twice among the corners' sides, and the table holds two
        // rows per edge: rows are u32 ids.
        if 2 * soup.num_corners() >= NO_FACE as usize {
            return Err(Error::TooLarge {
                what: "directed edges",
                count: 2 * soup.num_corners() as u64,
            });
        }
        let mut rows: Vec<([u32; 2], u32)> = Vec::with_capacity(2 * soup.num_corners());
        for (f, face) in soup.faces().enumerate() {
            for (i, &a) in face.iter().enumerate() {
                rows.push(([a, face[(i + 1) % face.len()]], f as u32));
            }
        }
        rows.sort_unstable();
        // The outer side of each boundary edge: the direction no face traverses.
        let inner = rows.len();
        for i in 0..inner {
            let [a, b] = rows[i].0;
            if rows[..inner]
                .binary_search_by(|r| r.0.cmp(&[b, a]))
                .is_err()
            {
                rows.push(([b, a], NO_FACE));
            }
        }
        rows.sort_unstable();
        Ok(Self {
            positions: soup.positions.clone(),
            ends: rows.iter().map(|r| r.0).collect(),
            left: rows.iter().map(|r| r.1).collect(),
            corners: soup.indices().to_vec(),
            offsets: soup.offsets().to_vec(),
        })
    }

    #[inline]
    fn num_vertices(&self) -> usize {
        self.positions.len()
    }
    #[inline]
    fn num_edges(&self) -> usize {
        self.ends.len() / 2
    }
    #[inline]
    fn num_faces(&self) -> usize {
        self.offsets.len() - 1
    }
    fn num_boundary_edges(&self) -> usize {
        // Each boundary edge has exactly one outer row.
        self.left.iter().filter(|&&f| f == NO_FACE).count()
    }
    fn for_each_edge(&self, mut f: impl FnMut(EdgeId)) {
        for (h, &[a, b]) in self.ends.iter().enumerate() {
            if a < b {
                f(EdgeId::new(h));
            }
        }
    }

    #[inline]
    fn position(&self, v: VertexId) -> DVec3 {
        self.positions[v.index()]
    }
    #[inline]
    fn vertex_vertices(&self, v: VertexId, mut f: impl FnMut(VertexId)) {
        for h in self.leaving(v.0) {
            f(VertexId(self.ends[h][1]));
        }
    }
    #[inline]
    fn vertex_edges(&self, v: VertexId, mut f: impl FnMut(EdgeId)) {
        for h in self.leaving(v.0) {
            let [a, b] = self.ends[h];
            if a < b {
                f(EdgeId::new(h));
            } else if let Some(r) = self.row(b, a) {
                f(EdgeId::new(r));
            }
        }
    }
    #[inline]
    fn vertex_faces(&self, v: VertexId, mut f: impl FnMut(FaceId)) {
        // A face around v traverses exactly one edge leaving v: the side after v's corner.
        for h in self.leaving(v.0) {
            if self.left[h] != NO_FACE {
                f(FaceId(self.left[h]));
            }
        }
    }
    #[inline]
    fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2] {
        self.ends[e.index()].map(VertexId)
    }
    #[inline]
    fn edge_edges(&self, e: EdgeId, mut f: impl FnMut(EdgeId)) {
        for face in self.sides(e) {
            if face != NO_FACE {
                self.face_edges(FaceId(face), |x| {
                    if x != e {
                        f(x)
                    }
                });
            }
        }
    }
    #[inline]
    fn edge_faces(&self, e: EdgeId, mut f: impl FnMut(FaceId)) {
        for face in self.sides(e) {
            if face != NO_FACE {
                f(FaceId(face));
            }
        }
    }
    #[inline]
    fn face_vertices(&self, face: FaceId, mut f: impl FnMut(VertexId)) {
        for &v in self.face(face.index()) {
            f(VertexId(v));
        }
    }
    #[inline]
    fn face_edges(&self, face: FaceId, mut f: impl FnMut(EdgeId)) {
        let vs = self.face(face.index());
        for (i, &a) in vs.iter().enumerate() {
            if let Some(e) = self.edge(a, vs[(i + 1) % vs.len()]) {
                f(e);
            }
        }
    }
    #[inline]
    fn face_faces(&self, face: FaceId, mut f: impl FnMut(FaceId)) {
        let vs = self.face(face.index());
        for (i, &a) in vs.iter().enumerate() {
            // The face across side a → b traverses it from b to a.
            if let Some(r) = self.row(vs[(i + 1) % vs.len()], a) {
                if self.left[r] != NO_FACE {
                    f(FaceId(self.left[r]));
                }
            }
        }
    }
    #[inline]
    fn is_boundary_vertex(&self, v: VertexId) -> bool {
        // Every open fan around v ends on an outer row leaving v (the fan's other end is an
        // outer row arriving at v), so looking at the rows leaving v is enough.
        self.leaving(v.0).any(|h| self.left[h] == NO_FACE)
    }
    #[inline]
    fn is_boundary_edge(&self, e: EdgeId) -> bool {
        self.sides(e).contains(&NO_FACE)
    }

    fn boundary_curves(&self, out: &mut BoundaryCurves) {
        // Scratch without allocating: the front of `out.starts` holds one "walked" bit per
        // row while the curves are built, and is removed at the end.
        let words = self.ends.len().div_ceil(32);
        out.edges.clear();
        out.starts.clear();
        out.starts.resize(words, 0);
        out.starts.push(0);
        let walked = |starts: &[u32], h: usize| starts[h / 32] & (1 << (h % 32)) != 0;
        for first in 0..self.ends.len() {
            if self.left[first] != NO_FACE || walked(&out.starts, first) {
                continue;
            }
            // Outer rows run around the hole: from the end of one, the next leaves it in the
            // same fan ([`SortedEdgeTable::next_outer`]). The curve closes when it comes back
            // to its first row.
            let mut h = first;
            loop {
                out.starts[h / 32] |= 1 << (h % 32);
                let [a, b] = self.ends[h];
                out.edges.extend(self.edge(a, b));
                match self.next_outer(h) {
                    Some(g) if !walked(&out.starts, g) => h = g,
                    // Back at the first row (or, on a broken table, a dead end: `validate`
                    // says why).
                    _ => break,
                }
            }
            out.starts.push(out.edges.len() as u32);
        }
        out.starts.drain(..words);
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
        let (n0, n2) = (self.positions.len() as u32, self.num_faces() as u32);
        if self.ends.len() != self.left.len() {
            return fail("ends and left differ in length".into());
        }
        if let Some(w) = self.ends.windows(2).find(|w| w[0] >= w[1]) {
            return fail(format!("rows {:?} and {:?} are not sorted", w[0], w[1]));
        }
        for (h, &[a, b]) in self.ends.iter().enumerate() {
            if a == b || a >= n0 || b >= n0 {
                return fail(format!(
                    "row {h} = ({a}, {b}) is not an edge of two vertices"
                ));
            }
            if self.left[h] != NO_FACE && self.left[h] >= n2 {
                return fail(format!(
                    "row {h} names face {}, which does not exist",
                    self.left[h]
                ));
            }
            match self.reverse(h) {
                None => return fail(format!("row {h} = ({a}, {b}) has no row ({b}, {a})")),
                Some(r) if self.left[h] == NO_FACE && self.left[r] == NO_FACE => {
                    return fail(format!("edge ({a}, {b}) has no face on either side"))
                }
                Some(_) => {}
            }
        }
        if self.offsets.first() != Some(&0)
            || self.offsets.last().map(|&o| o as usize) != Some(self.corners.len())
            || self.offsets.windows(2).any(|w| w[1] < w[0] + 3)
        {
            return fail(
                "face offsets must start at 0, grow by at least 3 and end at the corner count"
                    .into(),
            );
        }
        // Each side of each face is the row that names the face, and no other row does.
        let mut named = 0;
        for f in 0..self.num_faces() {
            let vs = self.face(f);
            for (i, &a) in vs.iter().enumerate() {
                let b = vs[(i + 1) % vs.len()];
                if self.row(a, b).map(|h| self.left[h]) != Some(f as u32) {
                    return fail(format!(
                        "side ({a}, {b}) of face {f} is not a row naming it"
                    ));
                }
                named += 1;
            }
        }
        if self.left.iter().filter(|&&f| f != NO_FACE).count() != named {
            return fail("a row names a face that does not traverse it".into());
        }
        Ok(())
    }

    fn heap_bytes(&self) -> usize {
        self.positions.capacity() * std::mem::size_of::<DVec3>()
            + self.ends.capacity() * std::mem::size_of::<[u32; 2]>()
            + (self.left.capacity() + self.corners.capacity() + self.offsets.capacity())
                * std::mem::size_of::<u32>()
    }

    fn explain(&self, w: &mut dyn Write) -> std::fmt::Result {
        writeln!(
            w,
            "sorted edge table: every edge in both directions, sorted, with the face that traverses each direction"
        )?;
        writeln!(w, "vertices: {}", self.positions.len())?;
        for (v, p) in self.positions.iter().enumerate() {
            writeln!(w, "  v{v}: ({:.3}, {:.3}, {:.3})", p.x, p.y, p.z)?;
        }
        writeln!(w, "rows: {} (row: a -> b, face; - = none)", self.ends.len())?;
        for (h, &[a, b]) in self.ends.iter().enumerate() {
            let face = match self.left[h] {
                NO_FACE => "-".to_string(),
                f => format!("f{f}"),
            };
            writeln!(w, "  {h}: {a} -> {b}, {face}")?;
        }
        writeln!(w, "faces: {}", self.num_faces())?;
        for f in 0..self.num_faces() {
            let vs: Vec<String> = self.face(f).iter().map(|v| format!("v{v}")).collect();
            writeln!(w, "  f{f}: ({})", vs.join(", "))?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::meshes;

    #[test]
    fn the_open_tetrahedron_has_twelve_rows_and_three_outer_ones() {
        // Figure 4.10 of the CHE thesis chapter: 6 edges, 3 of them on the boundary.
        let m = SortedEdgeTable::from_soup(&meshes::open_tetrahedron()).unwrap();
        let (ends, left) = m.rows();
        assert_eq!(ends.len(), 12);
        assert!(ends.windows(2).all(|w| w[0] < w[1]));
        assert_eq!(left.iter().filter(|&&f| f == NO_FACE).count(), 3);
        let mut text = String::new();
        m.explain(&mut text).unwrap();
        let rows = text
            .lines()
            .filter(|l| l.starts_with("  ") && l.contains(" -> "));
        assert_eq!(rows.count(), 12, "{text}");
    }

    #[test]
    fn validate_finds_a_row_out_of_order() {
        let mut m = SortedEdgeTable::from_soup(&meshes::closed_tetrahedron()).unwrap();
        assert!(m.validate().is_ok());
        m.ends.swap(0, 1);
        let e = m.validate().unwrap_err();
        assert!(e.to_string().contains("not sorted"), "{e}");
    }

    #[test]
    fn a_non_manifold_edge_is_refused_with_the_soups_typed_error() {
        // Three triangles on the edge (0, 1).
        let soup = PolygonSoup::from_polygons(
            vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z, DVec3::ONE],
            &[[0, 1, 2], [1, 0, 3], [0, 1, 4]],
        );
        let e = SortedEdgeTable::from_soup(&soup).unwrap_err();
        assert!(e.is_non_manifold(), "{e}");
    }
}
