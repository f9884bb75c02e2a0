//! The scans shared by the two structures without adjacency: the vertex list (corners hold vertex
//! indices) and explicit storage (corners hold coordinates). Both store only the faces' corners, so
//! every relation is found by scanning them, as the lecture on polygon-mesh data structures
//! describes; the only difference is how a corner names its vertex (the key `K`) and how keys map
//! to the lab's ids.
//!
//! Edge ids: edge `{a, b}` is the first corner (lowest index in `keys`) whose outgoing side
//! is `{a, b}`. Because faces are contiguous and a face uses a vertex once, that is the corner
//! in the first face (in face order) that contains the edge.

use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::reads::{read, traced, Traced};
use crate::core::topology::{BoundaryCurves, Cost, Operator};

/// The cost table of the scans: both structures of this family (vertex list, explicit
/// storage) answer every operator by the scans below, so they declare the same costs.
pub(crate) fn scan_cost(op: Operator) -> Cost {
    match op {
        Operator::R00 | Operator::R01 | Operator::R02 => Cost::Linear,
        Operator::R10 => Cost::Log,
        Operator::R11 | Operator::R21 | Operator::R22 => Cost::LocalTimesLinear,
        Operator::R12 | Operator::BoundaryEdge | Operator::BoundaryVertex => Cost::Linear,
        Operator::EdgeSuccessor | Operator::EdgePredecessor => Cost::Linear,
        Operator::R20 => Cost::Local,
        Operator::BoundaryCurves => Cost::Quadratic,
    }
}

/// How corner keys relate to the lab's vertex ids.
pub(crate) trait Naming<K> {
    /// The key that stands for vertex `v`.
    fn key(&self, v: VertexId) -> K;
    /// The vertex a key stands for.
    fn vertex(&self, k: K) -> VertexId;
}

/// Faces as runs of corner keys.
#[derive(Clone, Debug)]
pub(crate) struct Corners<K> {
    /// Per corner, its vertex's key; face j is `keys[offsets[j]..offsets[j+1]]`.
    pub keys: Vec<K>,
    /// Face offsets into `keys`, `faces + 1` entries.
    pub offsets: Vec<u32>,
}

/// Inline memory of already reported neighbours, so a vertex scan reports each edge once
/// without allocating; beyond its capacity the scan looks back over the faces it has passed.
struct Seen<K> {
    keys: [Option<K>; 48],
    len: usize,
}

impl<K: Copy + PartialEq + Traced> Corners<K> {
    pub fn num_faces(&self) -> usize {
        self.offsets.len() - 1
    }

    #[inline]
    pub fn face(&self, f: usize) -> &[K] {
        &self.keys[read!("offsets", self.offsets, f) as usize
            ..read!("offsets", self.offsets, f + 1) as usize]
    }

    /// The face of corner `c`: binary search of the offsets, O(log n2).
    #[inline]
    pub fn face_of(&self, c: usize) -> usize {
        self.offsets.partition_point(|o: &u32| {
            traced!(
                "offsets",
                (o as *const u32 as usize - self.offsets.as_ptr() as usize) / 4,
                *o
            );
            *o as usize <= c
        }) - 1
    }

    #[inline]
    fn next_in(&self, c: usize, f: usize) -> usize {
        if c + 1 == read!("offsets", self.offsets, f + 1) as usize {
            read!("offsets", self.offsets, f) as usize
        } else {
            c + 1
        }
    }

    #[inline]
    fn prev_in(&self, c: usize, f: usize) -> usize {
        if c == read!("offsets", self.offsets, f) as usize {
            read!("offsets", self.offsets, f + 1) as usize - 1
        } else {
            c - 1
        }
    }

    /// End keys of the edge leaving corner `c`.
    #[inline]
    pub fn ends(&self, c: usize) -> (K, K) {
        let f = self.face_of(c);
        (
            read!("corners", self.keys, c),
            read!("corners", self.keys, self.next_in(c, f)),
        )
    }

    /// Does face `f` contain edge `{a, b}`? Returns the corner of `f` whose outgoing side it is.
    fn find_in_face(&self, f: usize, a: K, b: K) -> Option<usize> {
        let (s, e) = (
            read!("offsets", self.offsets, f) as usize,
            read!("offsets", self.offsets, f + 1) as usize,
        );
        (s..e).find(|&c| {
            let n = read!("corners", self.keys, self.next_in(c, f));
            let k = read!("corners", self.keys, c);
            (k == a && n == b) || (k == b && n == a)
        })
    }

    /// The edge id of the edge leaving corner `c`: a scan of the faces before `c`'s, O(n).
    pub fn canonical(&self, c: usize) -> usize {
        let (a, b) = self.ends(c);
        let f = self.face_of(c);
        (0..f).find_map(|g| self.find_in_face(g, a, b)).unwrap_or(c)
    }

    /// The corner of the other face on corner `c`'s edge, if any: a scan, O(n).
    pub fn twin(&self, c: usize) -> Option<usize> {
        let (a, b) = self.ends(c);
        let f = self.face_of(c);
        (0..self.num_faces())
            .filter(|&g| g != f)
            .find_map(|g| self.find_in_face(g, a, b))
    }

    /// Every distinct edge around key `k`, once, as (edge id, other end key): one scan.
    pub fn vertex_edges(&self, k: K, mut f: impl FnMut(usize, K)) {
        let mut seen = Seen {
            keys: [None; 48],
            len: 0,
        };
        for face in 0..self.num_faces() {
            let (s, e) = (
                read!("offsets", self.offsets, face) as usize,
                read!("offsets", self.offsets, face + 1) as usize,
            );
            let Some(c) = (s..e).find(|&c| read!("corners", self.keys, c) == k) else {
                continue;
            };
            let (n, p) = (self.next_in(c, face), self.prev_in(c, face));
            // The outgoing edge lives at corner c, the incoming one at corner p.
            for (corner, other) in [
                (c, read!("corners", self.keys, n)),
                (p, read!("corners", self.keys, p)),
            ] {
                if !self.seen_before(&mut seen, face, k, other) {
                    f(corner, other);
                }
            }
        }
    }

    /// Has edge `{k, other}` been reported? Remembers it if not.
    fn seen_before(&self, seen: &mut Seen<K>, face: usize, k: K, other: K) -> bool {
        if seen.keys[..seen.len.min(48)].contains(&Some(other)) {
            return true;
        }
        if seen.len >= 48 && (0..face).any(|g| self.find_in_face(g, k, other).is_some()) {
            return true;
        }
        if seen.len < 48 {
            seen.keys[seen.len] = Some(other);
        }
        seen.len += 1;
        false
    }

    /// Faces containing key `k`.
    pub fn vertex_faces(&self, k: K, mut f: impl FnMut(FaceId)) {
        for face in 0..self.num_faces() {
            let corners = self.face(face);
            #[cfg(feature = "count-reads")]
            for (i, x) in corners.iter().enumerate() {
                let first = self.offsets[face] as usize;
                traced!("corners", first + i, *x);
                if *x == k {
                    break;
                }
            }
            if corners.contains(&k) {
                f(FaceId::new(face));
            }
        }
    }

    /// A vertex is on the boundary iff it has more distinct edges than faces (each fan of
    /// faces around it has as many edges as faces when closed, one more when open).
    pub fn is_boundary_vertex(&self, k: K) -> bool {
        let (mut edges, mut faces) = (0usize, 0usize);
        self.vertex_edges(k, |_, _| edges += 1);
        self.vertex_faces(k, |_| faces += 1);
        edges > faces
    }

    /// Edges of the faces of edge `e` other than `e`, as edge ids.
    pub fn edge_edges(&self, e: usize, mut f: impl FnMut(EdgeId)) {
        for c in std::iter::once(e).chain(self.twin(e)) {
            let face = self.face_of(c);
            let (s, end) = (
                read!("offsets", self.offsets, face) as usize,
                read!("offsets", self.offsets, face + 1) as usize,
            );
            for x in (s..end).filter(|&x| x != c) {
                f(EdgeId::new(self.canonical(x)));
            }
        }
    }

    /// Faces of edge `e`.
    pub fn edge_faces(&self, e: usize, mut f: impl FnMut(FaceId)) {
        f(FaceId::new(self.face_of(e)));
        if let Some(t) = self.twin(e) {
            f(FaceId::new(self.face_of(t)));
        }
    }

    /// Edges of face `face` in order.
    pub fn face_edges(&self, face: usize, mut f: impl FnMut(EdgeId)) {
        let (s, end) = (
            read!("offsets", self.offsets, face) as usize,
            read!("offsets", self.offsets, face + 1) as usize,
        );
        for c in s..end {
            f(EdgeId::new(self.canonical(c)));
        }
    }

    /// Faces across the edges of `face`.
    pub fn face_faces(&self, face: usize, mut f: impl FnMut(FaceId)) {
        let (s, end) = (
            read!("offsets", self.offsets, face) as usize,
            read!("offsets", self.offsets, face + 1) as usize,
        );
        for c in s..end {
            if let Some(t) = self.twin(c) {
                f(FaceId::new(self.face_of(t)));
            }
        }
    }

    /// Successor (`forward`) or predecessor of edge `e` in `face`.
    pub fn neighbour_in_face(&self, e: usize, face: usize, forward: bool) -> Option<EdgeId> {
        let (a, b) = self.ends(e);
        let c = self.find_in_face(face, a, b)?;
        let x = if forward {
            self.next_in(c, face)
        } else {
            self.prev_in(c, face)
        };
        Some(EdgeId::new(self.canonical(x)))
    }

    /// Boundary curves by scans, per fan (the definition of [`crate::summary`]): each curve is
    /// walked from a boundary corner to the boundary edge that ends the same fan at the far
    /// vertex (`next_on_curve`), so a vertex with several fans continues each
    /// fan's boundary in that fan. Every step searches twins (O(n)), so O(n²) in all.
    pub fn boundary_curves(&self, out: &mut BoundaryCurves) {
        out.clear();
        for start in 0..self.keys.len() {
            if self.twin(start).is_some() || out.edges.contains(&EdgeId::new(self.canonical(start)))
            {
                continue;
            }
            let (mut cur, mut at) = (start, self.ends(start).1);
            loop {
                out.edges.push(EdgeId::new(self.canonical(cur)));
                // `None`, or an edge already on a curve, only where an edge has more than two
                // faces (the count is undefined there): the curve ends.
                let Some(next) = self.next_on_curve(cur, at) else {
                    break;
                };
                if out.edges.contains(&EdgeId::new(self.canonical(next))) {
                    break;
                }
                let (a, b) = self.ends(next);
                at = if a == at { b } else { a };
                cur = next;
            }
            out.end_curve();
        }
    }

    /// The boundary edge (as its corner) that follows boundary edge `c` at its end `at`: the
    /// walk turns around `at` through the faces, crossing edges at `at` that have a second
    /// face, until the edge it reaches has none. Orientation does not matter: in each face
    /// the walk takes the edge at `at` it did not come by.
    fn next_on_curve(&self, c: usize, at: K) -> Option<usize> {
        let mut edge = c;
        for _ in 0..self.keys.len() {
            let face = self.face_of(edge);
            // The corner of `at` in this face, and the face's other edge there.
            let other = if read!("corners", self.keys, edge) == at {
                self.prev_in(edge, face)
            } else {
                self.next_in(edge, face)
            };
            match self.twin(other) {
                None => return Some(other),
                Some(t) => edge = t,
            }
        }
        None
    }

    /// Every edge id once, in increasing order, with whether it is a boundary edge. An
    /// enumeration helper (not a timed operator): it sorts the corners by their end vertices,
    /// O(n log n), with a temporary buffer.
    pub fn enumerate_edges(&self, names: &impl Naming<K>, mut f: impl FnMut(usize, bool)) {
        let mut keyed: Vec<(u64, u32)> = (0..self.keys.len())
            .map(|c| {
                let (a, b) = self.ends(c);
                let (a, b) = (names.vertex(a).0, names.vertex(b).0);
                let (lo, hi) = if a < b { (a, b) } else { (b, a) };
                (((lo as u64) << 32) | hi as u64, c as u32)
            })
            .collect();
        keyed.sort_unstable();
        let mut firsts: Vec<(u32, bool)> = keyed
            .chunk_by(|x, y| x.0 == y.0)
            .map(|g| (g[0].1, g.len() == 1))
            .collect();
        firsts.sort_unstable();
        for (c, boundary) in firsts {
            f(c as usize, boundary);
        }
    }

    pub fn heap_bytes(&self) -> usize {
        self.keys.capacity() * std::mem::size_of::<K>() + self.offsets.capacity() * 4
    }

    /// Offsets start at 0, increase by at least 3, end at the corner count.
    pub fn validate(&self, structure: &'static str) -> crate::core::error::Result<()> {
        if self.offsets.first() != Some(&0)
            || *self.offsets.last().unwrap_or(&1) as usize != self.keys.len()
        {
            return Err(crate::core::error::Error::invariant(
                structure,
                "offsets must run from 0 to the corner count",
            ));
        }
        if let Some(w) = self.offsets.windows(2).position(|w| w[1] < w[0] + 3) {
            return Err(crate::core::error::Error::invariant(
                structure,
                format!("face {w} has fewer than 3 corners"),
            ));
        }
        Ok(())
    }
}
