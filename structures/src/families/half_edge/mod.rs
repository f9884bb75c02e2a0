//! What the two half-edge structures share: how they are built ([`HalfEdgeArrays`]), the
//! few primitives each answers in its own way ([`HalfEdgeLinks`]: `next`, `twin`, the start
//! vertex, the face, one half-edge per vertex and per face), and every operator, `validate`
//! and `explain` written once on top of those primitives ([`HalfEdge`]).
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

mod build;
pub mod index;
pub mod pointer;

pub use build::HalfEdgeArrays;
pub(crate) use build::NONE;

use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::soup::PolygonSoup;
use crate::core::topology::{BoundaryCurves, Capabilities, Cost, MeshTopology, Operator};
use glam::DVec3;
use std::fmt::Write;

/// The primitives a half-edge storage answers; everything else is derived in [`HalfEdge`].
///
/// `H` is how the storage names a half-edge while walking: a `u32` index for arrays, a
/// reference to the record for pointers. Half-edge ids (`id`) follow [`HalfEdgeArrays`].
pub trait HalfEdgeLinks: Sized {
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
    /// Invariants of the storage itself that the id-level checks of [`HalfEdge::validate`]
    /// cannot see (for pointers: every link points to a record of this mesh).
    fn validate_storage(&self) -> Result<()>;
    /// For `explain`: what the storage is and how its fields are named.
    fn describe(w: &mut dyn Write) -> std::fmt::Result;
    /// For `explain`: the stored `prev` of `h`, if the storage keeps one.
    fn stored_prev(&self, h: Self::H<'_>) -> Option<u32>;
}

/// A half-edge structure over the storage `L`; see the module docs.
pub struct HalfEdge<L> {
    /// The storage that answers the primitives.
    pub(crate) links: L,
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

/// The cost table of both half-edge structures (the lecture's half-edge table; the
/// predecessor depends on whether `prev` is stored).
fn half_edge_cost(op: Operator, predecessor: Cost) -> Cost {
    match op {
        Operator::R00 | Operator::R01 | Operator::R02 => Cost::Local,
        Operator::R10 | Operator::R12 => Cost::Constant,
        Operator::R11 | Operator::R20 | Operator::R21 | Operator::R22 => Cost::Local,
        Operator::BoundaryVertex | Operator::BoundaryEdge => Cost::Constant,
        Operator::BoundaryCurves => Cost::Linear,
        Operator::EdgeSuccessor => Cost::Constant,
        Operator::EdgePredecessor => predecessor,
    }
}

impl<L: HalfEdgeLinks> MeshTopology for HalfEdge<L> {
    const NAME: &'static str = L::NAME;

    fn capabilities() -> Capabilities {
        Capabilities::POLYGONS
    }

    fn cost(op: Operator) -> Cost {
        half_edge_cost(op, L::PREDECESSOR)
    }

    fn from_soup(soup: &PolygonSoup) -> Result<Self> {
        let arrays = HalfEdgeArrays::from_soup(soup)?;
        Ok(Self {
            links: L::from_arrays(arrays, &soup.positions),
        })
    }

    fn num_vertices(&self) -> usize {
        self.links.num_vertices()
    }
    fn num_edges(&self) -> usize {
        self.links.num_half_edges() / 2
    }
    fn num_faces(&self) -> usize {
        self.links.num_faces()
    }
    fn for_each_edge(&self, mut f: impl FnMut(EdgeId)) {
        for e in 0..self.num_edges() {
            f(EdgeId::new(e));
        }
    }
    fn position(&self, v: VertexId) -> DVec3 {
        self.links.position(v)
    }

    #[inline]
    fn vertex_vertices(&self, v: VertexId, mut f: impl FnMut(VertexId)) {
        let l = &self.links;
        self.for_each_outgoing(v, |h| f(l.vertex(l.twin(h))));
    }
    #[inline]
    fn vertex_edges(&self, v: VertexId, mut f: impl FnMut(EdgeId)) {
        self.for_each_outgoing(v, |h| f(self.edge_of(h)));
    }
    #[inline]
    fn vertex_faces(&self, v: VertexId, mut f: impl FnMut(FaceId)) {
        self.for_each_outgoing(v, |h| {
            if let Some(face) = self.links.face(h) {
                f(face)
            }
        });
    }
    #[inline]
    fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2] {
        let h = self.links.half_edge(2 * e.0);
        [self.links.vertex(h), self.links.vertex(self.links.twin(h))]
    }
    fn edge_edges(&self, e: EdgeId, mut f: impl FnMut(EdgeId)) {
        let h = self.links.half_edge(2 * e.0);
        for side in [h, self.links.twin(h)] {
            if self.links.face(side).is_some() {
                self.for_each_in_loop(self.links.next(side), |x| {
                    if x != side {
                        f(self.edge_of(x))
                    }
                });
            }
        }
    }
    fn edge_faces(&self, e: EdgeId, mut f: impl FnMut(FaceId)) {
        let h = self.links.half_edge(2 * e.0);
        for side in [h, self.links.twin(h)] {
            if let Some(face) = self.links.face(side) {
                f(face);
            }
        }
    }
    #[inline]
    fn face_vertices(&self, face: FaceId, mut f: impl FnMut(VertexId)) {
        let start = self.links.face_half_edge(face);
        self.for_each_in_loop(start, |h| f(self.links.vertex(h)));
    }
    #[inline]
    fn face_edges(&self, face: FaceId, mut f: impl FnMut(EdgeId)) {
        let start = self.links.face_half_edge(face);
        self.for_each_in_loop(start, |h| f(self.edge_of(h)));
    }
    #[inline]
    fn face_faces(&self, face: FaceId, mut f: impl FnMut(FaceId)) {
        let l = &self.links;
        self.for_each_in_loop(l.face_half_edge(face), |h| {
            if let Some(g) = l.face(l.twin(h)) {
                f(g)
            }
        });
    }
    #[inline]
    fn is_boundary_vertex(&self, v: VertexId) -> bool {
        self.links
            .outgoing(v)
            .is_some_and(|h| self.links.face(h).is_none())
    }
    #[inline]
    fn is_boundary_edge(&self, e: EdgeId) -> bool {
        let h = self.links.half_edge(2 * e.0);
        self.links.face(h).is_none() || self.links.face(self.links.twin(h)).is_none()
    }
    /// One scan for the boundary half-edges (their ids land in `out.edges` as a sorted
    /// scratch list, so nothing is allocated beyond the caller's buffer), then each loop is
    /// walked with `next` once, finding "already walked" by binary search in the scratch list.
    fn boundary_curves(&self, out: &mut BoundaryCurves) {
        out.clear();
        let l = &self.links;
        // The top bit of a scratch entry marks a walked half-edge (the builder keeps
        // half-edge ids below 2^31).
        const WALKED: u32 = 1 << 31;
        for id in 0..l.num_half_edges() as u32 {
            if l.face(l.half_edge(id)).is_none() {
                out.edges.push(EdgeId(id));
            }
        }
        let scratch = out.edges.len();
        let mark = |edges: &mut Vec<EdgeId>, id: u32| {
            if let Ok(i) = edges[..scratch].binary_search_by_key(&id, |x| x.0 & !WALKED) {
                edges[i].0 |= WALKED;
            }
        };
        for i in 0..scratch {
            if out.edges[i].0 & WALKED != 0 {
                continue;
            }
            let start = l.half_edge(out.edges[i].0);
            self.for_each_in_loop(start, |h| {
                let id = l.id(h);
                mark(&mut out.edges, id);
                out.edges.push(EdgeId(id >> 1));
            });
            out.end_curve();
        }
        // Drop the scratch list; curve starts were recorded after it.
        out.edges.drain(..scratch);
        for s in &mut out.starts[1..] {
            *s -= scratch as u32;
        }
    }
    fn edge_successor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        let h = self.half_edge_in(e, face)?;
        Some(self.edge_of(self.links.next(h)))
    }
    fn edge_predecessor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        let h = self.half_edge_in(e, face)?;
        Some(self.edge_of(self.links.prev(h)))
    }

    fn validate(&self) -> Result<()> {
        self.links.validate_storage()?;
        validate_links(&self.links)
    }

    fn heap_bytes(&self) -> usize {
        self.links.heap_bytes()
    }

    fn explain(&self, w: &mut dyn Write) -> std::fmt::Result {
        let l = &self.links;
        L::describe(w)?;
        writeln!(w, "\nHE_vert (one record per vertex):")?;
        for v in 0..l.num_vertices() {
            let p = l.position(VertexId::new(v));
            let edge = l
                .outgoing(VertexId::new(v))
                .map_or("null".to_string(), |h| format!("h{}", l.id(h)));
            writeln!(
                w,
                "  v{v}: x = {:.3}, y = {:.3}, z = {:.3}, edge = {edge}",
                p.x, p.y, p.z
            )?;
        }
        writeln!(w, "\nHE_face (one record per face):")?;
        for f in 0..l.num_faces() {
            let h = l.face_half_edge(FaceId::new(f));
            writeln!(w, "  f{f}: edge = h{}", l.id(h))?;
        }
        writeln!(
            w,
            "\nHE_edge (two records per edge; h and h^1 are the pair of edge h/2):"
        )?;
        for id in 0..l.num_half_edges() as u32 {
            let h = l.half_edge(id);
            let face = l
                .face(h)
                .map_or("null".to_string(), |f| format!("f{}", f.0));
            write!(
                w,
                "  h{id}: vert = v{}, pair = h{}, face = {face}, next = h{}",
                l.vertex(h).0,
                l.id(l.twin(h)),
                l.id(l.next(h)),
            )?;
            if let Some(p) = l.stored_prev(h) {
                write!(w, ", prev = h{p}")?;
            }
            writeln!(w, "  (edge e{})", id >> 1)?;
        }
        writeln!(
            w,
            "\nface = null marks a boundary half-edge; boundary vertices keep their outgoing\n\
             boundary half-edge in `edge`, so `edge->face == null` tells the boundary in O(1)."
        )
    }
}

/// Every invariant of half-edge connectivity, checked through the primitives by ids.
fn validate_links<L: HalfEdgeLinks>(l: &L) -> Result<()> {
    let fail = |message: String| Err(Error::invariant(L::NAME, message));
    let (nh, nv, nf) = (l.num_half_edges(), l.num_vertices(), l.num_faces());
    if nh % 2 != 0 {
        return fail(format!("{nh} half-edges: half-edges come in pairs"));
    }
    let mut leaving = vec![0u32; nv];
    let mut directed = Vec::with_capacity(nh);
    let mut with_face = 0usize;
    // `next` must be a permutation, so every face and boundary loop closes.
    let mut has_prev = vec![false; nh];
    for id in 0..nh as u32 {
        let h = l.half_edge(id);
        if l.id(h) != id {
            return fail(format!("half-edge {id} reports id {}", l.id(h)));
        }
        let t = l.twin(h);
        if l.id(t) != id ^ 1 || l.twin(t) != h {
            return fail(format!(
                "pair of h{id} is h{}, expected h{}",
                l.id(t),
                id ^ 1
            ));
        }
        let (a, b) = (l.vertex(h), l.vertex(t));
        if a.index() >= nv || b.index() >= nv || a == b {
            return fail(format!("h{id} runs v{} -> v{}", a.0, b.0));
        }
        let n = l.next(h);
        if l.vertex(n) != b {
            return fail(format!(
                "h{id} ends at v{}, but its next h{} starts at v{}",
                b.0,
                l.id(n),
                l.vertex(n).0
            ));
        }
        if l.face(n) != l.face(h) {
            return fail(format!(
                "h{id} and its next h{} border different faces",
                l.id(n)
            ));
        }
        if has_prev[l.id(n) as usize] {
            return fail(format!("h{} is the next of two half-edges", l.id(n)));
        }
        has_prev[l.id(n) as usize] = true;
        if l.stored_prev(n).is_some_and(|p| p != id) {
            return fail(format!("prev of h{} is not h{id}", l.id(n)));
        }
        match l.face(h) {
            Some(f) if f.index() >= nf => return fail(format!("h{id} names missing face {f}")),
            Some(_) => with_face += 1,
            None if l.face(t).is_none() => {
                return fail(format!("edge e{} has no face on either side", id >> 1))
            }
            None => {}
        }
        leaving[a.index()] += 1;
        directed.push((a.0, b.0));
    }
    directed.sort_unstable();
    if let Some(w) = directed.windows(2).find(|w| w[0] == w[1]) {
        return fail(format!("two half-edges run v{} -> v{}", w[0].0, w[0].1));
    }
    let mut in_face_loops = 0usize;
    for f in 0..nf {
        let fid = FaceId::new(f);
        let start = l.face_half_edge(fid);
        let mut h = start;
        let mut len = 0usize;
        loop {
            if l.face(h) != Some(fid) {
                return fail(format!("the loop of f{f} reaches h{}", l.id(h)));
            }
            len += 1;
            h = l.next(h);
            if h == start {
                break;
            }
            if len > nh {
                return fail(format!("the loop of f{f} does not close"));
            }
        }
        if len < 3 {
            return fail(format!("f{f} has {len} half-edges"));
        }
        in_face_loops += len;
    }
    if in_face_loops != with_face {
        return fail(format!(
            "{with_face} half-edges border faces but the face loops hold {in_face_loops}"
        ));
    }
    for (v, &count) in leaving.iter().enumerate() {
        let vid = VertexId::new(v);
        let Some(start) = l.outgoing(vid) else {
            if count != 0 {
                return fail(format!("v{v} has no half-edge but {count} leave it"));
            }
            continue;
        };
        let (mut h, mut steps, mut boundary) = (start, 0u32, false);
        loop {
            if l.vertex(h) != vid {
                return fail(format!("the rotation of v{v} reaches h{}", l.id(h)));
            }
            boundary |= l.face(h).is_none();
            steps += 1;
            h = l.next(l.twin(h));
            if h == start || steps > count {
                break;
            }
        }
        if steps != count || h != start {
            return fail(format!(
                "the rotation of v{v} reaches {steps} of its {count} outgoing half-edges"
            ));
        }
        if boundary && l.face(start).is_some() {
            return fail(format!(
                "v{v} is on the boundary but its half-edge h{} is not a boundary half-edge",
                l.id(start)
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use crate::core::soup::PolygonSoup;
    use crate::core::topology::{BoundaryCurves, MeshTopology};
    use crate::testing::meshes;
    use crate::{IndexHalfEdge, PointerHalfEdge};
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
        assert!(!m.is_boundary_vertex(crate::VertexId(1)));

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
