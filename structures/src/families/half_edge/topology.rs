//! [`MeshTopology`] for both half-edge storages, written once over [`HalfEdgeLinks`]: the
//! lecture's loops (`edge->next` around a face, `edge->pair->next` around a vertex).

use super::validate::validate_links;
use super::{HalfEdge, HalfEdgeArrays, HalfEdgeLinks};
use crate::core::error::Result;
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::soup::PolygonSoup;
use crate::core::topology::{
    BoundaryCurves, Capabilities, Cost, InputChecks, MeshTopology, Operator,
};
use glam::DVec3;
use std::fmt::Write;

/// The cost table of both half-edge structures: the summary table of the lecture on
/// polygon-mesh data structures, except the successor (see "Costs" in the module docs); the
/// predecessor depends on whether `prev` is stored.
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
    const FAMILY: crate::core::family::Family = crate::core::family::Family::HalfEdge;

    fn capabilities() -> Capabilities {
        Capabilities::POLYGONS
    }

    fn cost(op: Operator) -> Cost {
        half_edge_cost(op, L::PREDECESSOR)
    }

    fn input_checks() -> Option<InputChecks> {
        Some(PolygonSoup::manifold_connectivity)
    }

    fn from_soup(soup: &PolygonSoup) -> Result<Self> {
        let arrays = HalfEdgeArrays::from_soup(soup)?;
        Ok(Self {
            links: L::from_arrays(arrays, &soup.positions),
            marks: Default::default(),
        })
    }

    /// The same arrays; the soup's faces dropped before the links are made, its positions
    /// taken rather than copied where the storage keeps them ([`HalfEdgeLinks::from_arrays_owned`]).
    fn from_soup_owned(soup: PolygonSoup) -> Result<Self> {
        let arrays = HalfEdgeArrays::from_soup(&soup)?;
        Ok(Self {
            links: L::from_arrays_owned(arrays, soup.into_positions()),
            marks: Default::default(),
        })
    }

    #[inline]
    fn num_vertices(&self) -> usize {
        self.links.num_vertices()
    }
    #[inline]
    fn num_edges(&self) -> usize {
        self.links.num_half_edges() / 2
    }
    #[inline]
    fn num_faces(&self) -> usize {
        self.links.num_faces()
    }
    fn for_each_edge(&self, mut f: impl FnMut(EdgeId)) {
        for e in 0..self.num_edges() {
            f(EdgeId::new(e));
        }
    }
    #[inline]
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
    #[inline]
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
    #[inline]
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
    #[inline]
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
    #[inline]
    fn edge_successor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        let h = self.half_edge_in(e, face)?;
        Some(self.edge_of(self.links.next(h)))
    }
    #[inline]
    fn edge_predecessor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        let h = self.half_edge_in(e, face)?;
        Some(self.edge_of(self.links.prev(h)))
    }

    fn validate(&self) -> Result<()> {
        self.links.validate_storage()?;
        validate_links(&self.links, &self.marks)
    }

    fn heap_bytes(&self) -> usize {
        self.links.heap_bytes() + self.marks.heap_bytes()
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

    fn access(op: Operator) -> Option<crate::core::access::Access> {
        L::access(op)
    }
}
