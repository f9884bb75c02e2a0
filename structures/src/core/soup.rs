//! [`PolygonSoup`]: the face list every structure is built from, and the shared analysis of
//! its edges ([`Connectivity`]) that constructions use to find twins and reject non-manifold input.

use crate::core::error::{Error, Numbering, Result};
use crate::core::ids::{FaceId, VertexId};
use glam::DVec3;

mod buckets;
mod fans;

/// Random soups of polygons over 8 vertices that pass [`PolygonSoup::check`], most of them
/// bad: non-manifold edges, faces running both ways along an edge, polygons of 3 to 6
/// corners, unused vertices. For the tests of the edge analysis and the fans.
#[cfg(test)]
fn random_soups() -> impl proptest::strategy::Strategy<Value = PolygonSoup> {
    use proptest::prelude::*;
    let face = prop::sample::subsequence((0u32..8).collect::<Vec<_>>(), 3..=6).prop_shuffle();
    prop::collection::vec(face, 0..14)
        .prop_map(|faces| PolygonSoup::from_polygons(vec![DVec3::ZERO; 8], &faces))
        .prop_filter("a checked soup", |s| s.check().is_ok())
}

pub(crate) use buckets::bucket_step_budget;
pub(crate) use fans::find_root;

/// Positions plus polygons of any size k >= 3, stored as one flat index buffer with offsets.
///
/// Face `j` is `indices[offsets[j]..offsets[j + 1]]`, its corners in order (counter-clockwise
/// seen from outside). A *corner* is a position in `indices`: corner `c` of face `j` is the
/// vertex `indices[c]`, and the edge leaving it goes to the next corner of the same face.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PolygonSoup {
    /// Vertex positions; vertex `i` is `VertexId(i)` in every structure.
    pub positions: Vec<DVec3>,
    indices: Vec<u32>,
    offsets: Vec<u32>,
}

impl PolygonSoup {
    /// An empty soup.
    pub fn new() -> Self {
        Self {
            positions: Vec::new(),
            indices: Vec::new(),
            offsets: vec![0],
        }
    }

    /// An empty soup with room for `vertices`, `faces` and `corners`.
    pub fn with_capacity(vertices: usize, faces: usize, corners: usize) -> Self {
        let mut offsets = Vec::with_capacity(faces + 1);
        offsets.push(0);
        Self {
            positions: Vec::with_capacity(vertices),
            indices: Vec::with_capacity(corners),
            offsets,
        }
    }

    /// A soup from positions and faces given as slices of vertex indices.
    pub fn from_polygons<F: AsRef<[u32]>>(positions: Vec<DVec3>, faces: &[F]) -> Self {
        let mut soup = Self::with_capacity(positions.len(), faces.len(), faces.len() * 3);
        soup.positions = positions;
        for f in faces {
            soup.push_face(f.as_ref());
        }
        soup
    }

    /// Adds a vertex and returns its id.
    pub fn push_vertex(&mut self, p: DVec3) -> VertexId {
        self.positions.push(p);
        VertexId::new(self.positions.len() - 1)
    }

    /// Adds a face (not checked here: see [`PolygonSoup::check`]) and returns its id.
    pub fn push_face(&mut self, corners: &[u32]) -> FaceId {
        self.indices.extend_from_slice(corners);
        self.offsets.push(self.indices.len() as u32);
        FaceId::new(self.offsets.len() - 2)
    }

    /// Number of vertices.
    #[inline]
    pub fn num_vertices(&self) -> usize {
        self.positions.len()
    }

    /// Number of faces.
    #[inline]
    pub fn num_faces(&self) -> usize {
        self.offsets.len() - 1
    }

    /// Number of corners (sum of the face sizes).
    #[inline]
    pub fn num_corners(&self) -> usize {
        self.indices.len()
    }

    /// The vertex indices of face `f`, in order.
    #[inline]
    pub fn face(&self, f: usize) -> &[u32] {
        &self.indices[self.offsets[f] as usize..self.offsets[f + 1] as usize]
    }

    /// All faces in input order.
    pub fn faces(&self) -> impl ExactSizeIterator<Item = &[u32]> + '_ {
        self.offsets
            .windows(2)
            .map(move |w| &self.indices[w[0] as usize..w[1] as usize])
    }

    /// A soup of triangles: `indices` holds three corners per triangle, in order (the
    /// inverse of [`PolygonSoup::into_triangles`]).
    ///
    /// # Panics
    /// If `indices.len()` is not a multiple of 3, or the corners are past `u32`.
    pub fn from_triangles(positions: Vec<DVec3>, indices: Vec<u32>) -> Self {
        assert!(
            indices.len().is_multiple_of(3),
            "three corners per triangle"
        );
        let corners = u32::try_from(indices.len()).expect("corners numbered by u32");
        Self {
            positions,
            offsets: (0..=corners).step_by(3).collect(),
            indices,
        }
    }

    /// The positions and the flat index buffer of a soup of triangles, taken without a copy
    /// (the face offsets, three apart, are dropped); the soup itself when it has a face of
    /// another size.
    pub fn into_triangles(self) -> std::result::Result<(Vec<DVec3>, Vec<u32>), Self> {
        if !self.is_triangle_mesh() {
            return Err(self);
        }
        Ok((self.positions, self.indices))
    }

    /// The positions, taken without a copy (the faces are dropped).
    pub fn into_positions(self) -> Vec<DVec3> {
        self.positions
    }

    /// The flat index buffer (all corners of all faces).
    #[inline]
    pub fn indices(&self) -> &[u32] {
        &self.indices
    }

    /// The face offsets: `num_faces() + 1` entries, starting with 0.
    #[inline]
    pub fn offsets(&self) -> &[u32] {
        &self.offsets
    }

    /// First corner of face `f`.
    #[inline]
    pub fn face_start(&self, f: usize) -> usize {
        self.offsets[f] as usize
    }

    /// The corner after `c` in its face `f` (wrapping around).
    #[inline]
    pub fn next_corner(&self, c: usize, f: usize) -> usize {
        if c + 1 == self.offsets[f + 1] as usize {
            self.offsets[f] as usize
        } else {
            c + 1
        }
    }

    /// The corner before `c` in its face `f` (wrapping around).
    #[inline]
    pub fn prev_corner(&self, c: usize, f: usize) -> usize {
        if c == self.offsets[f] as usize {
            self.offsets[f + 1] as usize - 1
        } else {
            c - 1
        }
    }

    /// `true` when every face is a triangle (and there is at least one face).
    pub fn is_triangle_mesh(&self) -> bool {
        self.num_faces() > 0 && self.indices.len() == 3 * self.num_faces()
    }

    /// The first face that is not a triangle, with its size, if any.
    pub fn first_non_triangle(&self) -> Option<(usize, usize)> {
        self.faces()
            .enumerate()
            .find(|(_, f)| f.len() != 3)
            .map(|(j, f)| (j, f.len()))
    }

    /// Rejects what no structure can store: indices out of range, faces with fewer than three
    /// corners or a repeated vertex, non-finite coordinates, counts beyond `u32` handles.
    pub fn check(&self) -> Result<()> {
        for (what, count) in [
            ("vertices", self.positions.len()),
            ("faces", self.num_faces()),
            ("corners", self.indices.len()),
        ] {
            if count >= u32::MAX as usize {
                return Err(Error::TooLarge {
                    what,
                    count: count as u64,
                });
            }
        }
        for (i, p) in self.positions.iter().enumerate() {
            for value in p.to_array() {
                if !value.is_finite() {
                    return Err(Error::NonFiniteCoordinate {
                        vertex: i,
                        value,
                        numbering: Numbering::FromZero,
                    });
                }
            }
        }
        let n = self.positions.len();
        for (j, face) in self.faces().enumerate() {
            if face.len() < 3 {
                return Err(Error::TooFewCorners {
                    face: j,
                    corners: face.len(),
                    numbering: Numbering::FromZero,
                });
            }
            for (k, &v) in face.iter().enumerate() {
                if v as usize >= n {
                    return Err(Error::IndexOutOfRange {
                        face: j,
                        index: v as i64,
                        vertices: n,
                        numbering: Numbering::FromZero,
                    });
                }
                if face[..k].contains(&v) {
                    return Err(Error::RepeatedVertex {
                        face: j,
                        vertex: v,
                        numbering: Numbering::FromZero,
                    });
                }
            }
        }
        Ok(())
    }

    /// [`PolygonSoup::check`], then the edge analysis that every structure with explicit
    /// adjacency needs: fails on an edge with more than two faces or two faces that traverse
    /// their shared edge in the same direction. Vertex fans are checked separately
    /// ([`Connectivity::check_vertex_fans`]) because some structures support non-manifold vertices.
    pub fn connectivity(&self) -> Result<Connectivity> {
        self.check()?;
        Connectivity::build(self)
    }

    /// [`PolygonSoup::connectivity`], then [`Connectivity::check_vertex_fans`]: the checks of
    /// the structures that store one fan per vertex and build from the shared edge analysis
    /// (the half-edges, the winged-edge), and what the Rust crates are admitted by.
    pub fn manifold_connectivity(&self) -> Result<Connectivity> {
        let connectivity = self.connectivity()?;
        connectivity.check_vertex_fans(self)?;
        Ok(connectivity)
    }

    /// The soup with its faces restricted to the given subset (vertex list unchanged).
    pub fn with_faces(&self, keep: impl Fn(usize) -> bool) -> Self {
        // Counted first, so that keeping few of many faces reserves room for few.
        let (faces, corners) = self
            .faces()
            .enumerate()
            .filter(|&(j, _)| keep(j))
            .fold((0, 0), |(n, c), (_, f)| (n + 1, c + f.len()));
        let mut out = Self::with_capacity(0, faces, corners);
        out.positions = self.positions.clone();
        for (j, f) in self.faces().enumerate() {
            if keep(j) {
                out.push_face(f);
            }
        }
        out
    }

    /// Keeps the faces `keep` says to keep, in their order, in place: the index buffer and
    /// the offsets are compacted, nothing is allocated (the vertex list is unchanged). `keep`
    /// is asked once a face, in order.
    pub fn retain_faces(&mut self, mut keep: impl FnMut(usize) -> bool) {
        let (mut faces, mut corners) = (0, 0);
        for j in 0..self.num_faces() {
            // Face j starts at or after where it is written (faces <= j). offsets[faces] is
            // written after offsets[j + 1] is read, and is offsets[j + 1] itself, unchanged,
            // until a face is dropped; then faces <= j, below any offset read later.
            let (start, end) = (self.offsets[j] as usize, self.offsets[j + 1] as usize);
            if keep(j) {
                self.indices.copy_within(start..end, corners);
                corners += end - start;
                faces += 1;
                self.offsets[faces] = corners as u32;
            }
        }
        self.indices.truncate(corners);
        self.offsets.truncate(faces + 1);
    }

    /// The corners of face `f`, to change in place (the repair's flips and splits).
    pub(crate) fn face_mut(&mut self, f: usize) -> &mut [u32] {
        &mut self.indices[self.offsets[f] as usize..self.offsets[f + 1] as usize]
    }

    /// The flat index buffer, to change in place (the repair renames vertices).
    pub(crate) fn indices_mut(&mut self) -> &mut [u32] {
        &mut self.indices
    }

    /// The same mesh with vertices renamed: old vertex `i` becomes `perm[i]`.
    pub fn relabel_vertices(&self, perm: &[u32]) -> Self {
        assert_eq!(perm.len(), self.num_vertices());
        let mut positions = vec![DVec3::ZERO; self.num_vertices()];
        for (i, &p) in perm.iter().enumerate() {
            positions[p as usize] = self.positions[i];
        }
        Self {
            positions,
            indices: self.indices.iter().map(|&v| perm[v as usize]).collect(),
            offsets: self.offsets.clone(),
        }
    }

    /// The same mesh with faces in another order: new face `k` is old face `order[k]`.
    pub fn reorder_faces(&self, order: &[u32]) -> Self {
        let mut out =
            Self::with_capacity(self.num_vertices(), self.num_faces(), self.num_corners());
        out.positions = self.positions.clone();
        for &j in order {
            out.push_face(self.face(j as usize));
        }
        out
    }

    /// Bytes of the soup's own arrays (positions, indices, offsets).
    pub fn heap_bytes(&self) -> usize {
        self.positions.capacity() * std::mem::size_of::<DVec3>()
            + self.indices.capacity() * 4
            + self.offsets.capacity() * 4
    }
}

/// No corner: the missing second corner of a boundary edge, or a corner the analysis did not
/// reach.
const NO_CORNER: u32 = u32::MAX;

/// The undirected edges of a checked soup with each edge's one or two corners: found in one
/// pass by buckets when every edge has at most two corners running opposite ways, by sorting
/// the corners by vertex pair (O(c log c) for c corners) when some edge has not.
///
/// Edges are numbered in order of first appearance: edge 0 is the edge leaving corner 0, and
/// so on, so every structure that numbers its edges from this table agrees with the others.
#[derive(Clone, Debug)]
pub struct Connectivity {
    /// Per edge: the corner whose outgoing side is the edge (its smallest such corner), and the
    /// corner of the face on the other side (`u32::MAX` on the boundary).
    pub edge_corners: Vec<[u32; 2]>,
    /// Per corner: the edge leaving it.
    pub corner_edge: Vec<u32>,
    /// Per corner: its face.
    pub corner_face: Vec<u32>,
}

impl Connectivity {
    fn build(soup: &PolygonSoup) -> Result<Self> {
        let (connectivity, mut problems) = Self::analyse(soup, true);
        match problems.pop() {
            Some(first) => Err(first),
            None => Ok(connectivity),
        }
    }

    /// The edge analysis of a checked soup that goes on past problems: every edge with more
    /// than two faces ([`Error::NonManifoldEdge`]) and every pair of faces traversing their
    /// shared edge in the same direction ([`Error::InconsistentOrientation`]) is reported, in
    /// order of its end vertices. An inconsistent pair is still stored as twins; a
    /// non-manifold edge is stored with no twin (all its corners map to it, `edge_corners`
    /// holds its first corner only), so that [`Connectivity::vertex_fans`] still works.
    /// `stop_at_first` ends the analysis at the first problem (what constructions want); the
    /// connectivity it then returns is partial (corners past the problem have no edge) and is
    /// only for reporting.
    ///
    /// A soup whose edges all have one corner, or two running opposite ways, is analysed by
    /// buckets in one pass without sorting (the module `buckets`), unless a vertex of very
    /// high valence makes the buckets too long; any other falls back to sorting the corners by
    /// vertex pair, which finds and orders the problems.
    pub fn analyse(soup: &PolygonSoup, stop_at_first: bool) -> (Self, Vec<Error>) {
        Self::analyse_of(soup, soup.num_vertices(), stop_at_first)
    }

    /// [`Connectivity::analyse`] of a soup of `num_vertices` vertices whose positions may have
    /// been dropped (the analysis reads no position): the checks' edge analysis, which holds
    /// the faces alone.
    pub(crate) fn analyse_of(
        soup: &PolygonSoup,
        num_vertices: usize,
        stop_at_first: bool,
    ) -> (Self, Vec<Error>) {
        match buckets::connectivity_by_buckets(soup, num_vertices) {
            Some(connectivity) => (connectivity, Vec::new()),
            None => Self::analyse_by_sorting(soup, stop_at_first),
        }
    }

    /// [`Connectivity::analyse`] by sorting the corners by vertex pair, O(c log c): the
    /// analysis that reports problems, and the oracle the buckets are tested against. The
    /// corners' ids are sorted (4 bytes a corner), each one's edge read from the soup when
    /// compared, and the edges are numbered in a pass over the corners in order (each edge by
    /// its smallest corner, which the sort puts first): at its peak 12 bytes a corner, the
    /// corners' faces and edges included.
    fn analyse_by_sorting(soup: &PolygonSoup, stop_at_first: bool) -> (Self, Vec<Error>) {
        let nc = soup.num_corners();
        let mut corner_face = Vec::with_capacity(nc);
        for (j, f) in soup.faces().enumerate() {
            corner_face.extend(std::iter::repeat_n(j as u32, f.len()));
        }
        let next = |c: usize| soup.next_corner(c, corner_face[c] as usize);
        // Sort key: (min vertex, max vertex) in the high bits, then the corner.
        let edge = |c: usize| {
            let (a, b) = (soup.indices[c], soup.indices[next(c)]);
            let (lo, hi) = if a < b { (a, b) } else { (b, a) };
            ((lo as u64) << 32) | hi as u64
        };
        let mut sorted: Vec<u32> = (0..nc as u32).collect();
        sorted.sort_unstable_by_key(|&c| (edge(c as usize), c));
        // Per corner, first the smallest corner of its edge, then (below) the edge's number.
        let mut corner_edge = vec![NO_CORNER; nc];
        let mut problems = Vec::new();
        let mut edges = 0;
        let mut i = 0;
        while i < nc && (problems.is_empty() || !stop_at_first) {
            let key = edge(sorted[i] as usize);
            let mut j = i + 1;
            while j < nc && edge(sorted[j] as usize) == key {
                j += 1;
            }
            let (a, b) = ((key >> 32) as u32, key as u32);
            let group = &sorted[i..j];
            let problem = match group.len() {
                1 => None,
                2 => {
                    let (c0, c1) = (group[0] as usize, group[1] as usize);
                    (soup.indices[c0] == soup.indices[c1]).then(|| Error::InconsistentOrientation {
                        a: soup.indices[c0],
                        b: soup.indices[next(c0)],
                        f: corner_face[c0],
                        g: corner_face[c1],
                    })
                }
                _ => {
                    let mut faces: Vec<u32> =
                        group.iter().map(|&c| corner_face[c as usize]).collect();
                    faces.sort_unstable();
                    Some(Error::NonManifoldEdge { a, b, faces })
                }
            };
            for &c in group {
                corner_edge[c as usize] = group[0];
            }
            edges += 1;
            problems.extend(problem);
            i = j;
        }
        drop(sorted);
        // Number edges by first appearance (smallest corner): a corner that is its edge's
        // smallest opens the edge, a later one is its other side; a third marks it
        // non-manifold (no twin: all its corners map to it, `edge_corners` holds the first).
        const THIRD: u32 = NO_CORNER - 1;
        let mut edge_corners: Vec<[u32; 2]> = Vec::with_capacity(edges);
        for c in 0..nc {
            let first = corner_edge[c];
            if first == NO_CORNER {
                // Past the first problem, when the analysis stopped there.
                continue;
            }
            if first as usize == c {
                corner_edge[c] = edge_corners.len() as u32;
                edge_corners.push([c as u32, NO_CORNER]);
            } else {
                let e = corner_edge[first as usize];
                corner_edge[c] = e;
                let other = &mut edge_corners[e as usize][1];
                *other = if *other == NO_CORNER { c as u32 } else { THIRD };
            }
        }
        for pair in &mut edge_corners {
            if pair[1] == THIRD {
                pair[1] = NO_CORNER;
            }
        }
        let connectivity = Self {
            edge_corners,
            corner_edge,
            corner_face,
        };
        (connectivity, problems)
    }

    /// Number of undirected edges.
    pub fn num_edges(&self) -> usize {
        self.edge_corners.len()
    }

    /// The corner on the other side of corner `c`'s outgoing edge, if the edge is interior.
    #[inline]
    pub fn twin_corner(&self, c: usize) -> Option<usize> {
        let [c0, c1] = self.edge_corners[self.corner_edge[c] as usize];
        // A corner that is neither (on an edge the lenient analysis left unpaired) has no twin.
        let other = match c as u32 {
            c if c == c0 => c1,
            c if c == c1 => c0,
            _ => u32::MAX,
        };
        (other != u32::MAX).then_some(other as usize)
    }
}
