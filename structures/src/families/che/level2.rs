//! CHE level 2, the cells (§4.3): adds `VH[]`, one half-edge leaving each vertex (the boundary
//! one for a boundary vertex, Algorithm 3), and the edge map `EH` (Algorithm 2). The vertex
//! star starts at `VH[v]` (Algorithm 7): O(deg v). The timed relations walk it from both ends
//! at once ([`Fan::spokes`]; see "Speed" in the [module docs](super)).

use super::build::{
    build_chapter, build_fast, build_fast_owned, edge_map_algorithm_2, edge_map_by_scan, Checked,
};
use super::fan::{ranges_hold, Fan};
use super::level1::check_opposites;
use super::triangle;
use super::{che_topology, fan_walk_algorithm_7, level1::level1_cost, printed, vec_bytes};
use super::{CheL1, CheLevel, StarRead};
use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
use crate::core::reads::read;
use crate::core::soup::PolygonSoup;
use crate::core::topology::{Cost, MeshTopology, Operator};
use glam::DVec3;

/// CHE level 2: level 1 plus a half-edge per vertex and the edge map; see the
/// [module docs](super).
#[derive(Clone, Debug, PartialEq)]
pub struct CheL2 {
    /// `G[]`, `V[]`, `O[]`.
    pub(super) l1: CheL1,
    /// `VH[v]`: a half-edge leaving v, the boundary one if v is on the boundary (so
    /// `O[VH[v]] < 0` tells boundary vertices); `-1` for a vertex no triangle uses.
    pub(super) vh: Vec<i32>,
    /// `EH`: the edge map's keys in increasing order, each edge's smaller half-edge
    /// `min(he, O[he])`; edge `EH[i]`'s properties would live at rank i.
    pub(super) eh: Vec<u32>,
}

/// Table 4.1's level-2 column (level 1 with the vertex star in O(deg v)), and the cost of the
/// operators the table does not list.
pub(crate) fn level2_cost(op: Operator) -> Cost {
    match op {
        Operator::R00 | Operator::R01 | Operator::R02 => Cost::Local,
        Operator::BoundaryVertex => Cost::Constant,
        _ => level1_cost(op),
    }
}

che_topology!(CheL2, "che-l2", level2_cost);

impl CheL2 {
    /// Level 2 of checked containers, with `EH` built by `edge_map`.
    ///
    /// Refuses containers whose ids are out of range ([`ranges_hold`]): the timed walk
    /// ([`Fan`]) reads `V[]` and `O[]` without bounds checks on the strength of this check.
    pub(crate) fn from_checked(
        c: Checked,
        edge_map: fn(&[i32]) -> Vec<u32>,
        structure: &'static str,
    ) -> Result<Self> {
        let (l1, vh) = CheL1::from_checked(c);
        let eh = edge_map(l1.opposite());
        let l2 = Self { l1, vh, eh };
        l2.check_ranges(structure)?;
        Ok(l2)
    }

    fn build(soup: &PolygonSoup) -> Result<Self> {
        let name = <Self as MeshTopology>::NAME;
        build_fast(soup, name).and_then(|c| Self::from_checked(c, edge_map_by_scan, name))
    }

    /// [`Self::build`] consuming the soup ([`build_fast_owned`]: no copy of its arrays).
    fn build_owned(soup: PolygonSoup) -> Result<Self> {
        let name = <Self as MeshTopology>::NAME;
        build_fast_owned(soup, name).and_then(|c| Self::from_checked(c, edge_map_by_scan, name))
    }

    /// Builds level 2 with the chapter's Algorithms 1, 2 and 3 (maps) instead of the fast
    /// construction of `from_soup`; the containers are identical.
    pub fn from_soup_chapter(soup: &PolygonSoup) -> Result<Self> {
        let name = <Self as MeshTopology>::NAME;
        build_chapter(soup, name).and_then(|c| Self::from_checked(c, edge_map_algorithm_2, name))
    }

    /// Is every id of `V[]`, `O[]` and `VH[]` in range ([`ranges_hold`])? The timed walk
    /// ([`Fan`]) relies on this.
    fn check_ranges(&self, structure: &'static str) -> Result<()> {
        if ranges_hold(self.start_vertices(), self.l1.opposite(), &self.vh) {
            Ok(())
        } else {
            Err(Error::invariant(
                structure,
                "V[], O[] and VH[] are not one entry per half-edge with every id in range",
            ))
        }
    }

    /// `G[]`: the vertex positions.
    #[inline]
    pub fn geometry(&self) -> &[DVec3] {
        self.l1.geometry()
    }

    /// Level 1 (`G[]`, `V[]`, `O[]`).
    #[inline]
    pub fn level1(&self) -> &CheL1 {
        &self.l1
    }

    /// `VH[]`: a half-edge leaving each vertex, `-1` for an unused vertex.
    pub fn vertex_half_edge(&self) -> &[i32] {
        &self.vh
    }

    /// `EH`: the edge map's keys (each edge's smaller half-edge), in increasing order.
    pub fn edge_map(&self) -> &[u32] {
        &self.eh
    }

    /// Lets `relabel` rewrite `O[]` (level 3 labels the boundary curves, Algorithm 4), then
    /// checks the ranges again, so that no write can leave an id the timed walk ([`Fan`])
    /// would read out of bounds.
    pub(crate) fn relabel_opposites<R>(
        &mut self,
        structure: &'static str,
        relabel: impl FnOnce(&mut [i32]) -> R,
    ) -> Result<R> {
        let r = relabel(self.l1.opposite_mut());
        self.check_ranges(structure)?;
        Ok(r)
    }

    /// The timed vertex star over `V[]`, `O[]` and `VH[]` ([`Fan`]). Besides the module
    /// `fan`, the crate's only unsafe code for the CHE: the promise that the ranges hold.
    #[inline(always)]
    #[allow(unsafe_code)]
    pub(crate) fn fan(&self) -> Fan<'_> {
        // SAFETY: `ranges_hold` was true when `self` was built (`from_checked`); the only
        // writers afterwards, `relabel_opposites` and the edits (`edit::Parts`), check the
        // ranges again before they return.
        unsafe { Fan::new_unchecked(self.start_vertices(), self.l1.opposite(), &self.vh) }
    }

    fn check_containers(&self) -> Result<()> {
        self.check_cells(<Self as MeshTopology>::NAME)
    }

    /// Levels 0–1 are valid, `VH[]` follows Algorithm 3's rule and `EH` holds every edge once
    /// ([`check_cells`]).
    pub(crate) fn check_cells(&self, structure: &'static str) -> Result<()> {
        let (v, o) = (self.start_vertices(), self.l1.opposite());
        check_cells(self.geometry().len(), v, o, &self.vh, &self.eh, structure)
    }

    pub(crate) fn container_bytes(&self) -> usize {
        self.l1.container_bytes() + vec_bytes(&self.vh) + vec_bytes(&self.eh)
    }

    pub(crate) fn print_containers(&self, w: &mut dyn std::fmt::Write) -> std::fmt::Result {
        self.l1.print_containers(w)?;
        printed::vertex_half_edges_and_edge_map(w, &self.vh, &self.eh)
    }
}

/// Level 2's invariant on slices (so that a mapped CHE checks its containers with the same
/// code): levels 0–1 are valid ([`check_opposites`]), every id is in range ([`ranges_hold`]),
/// `VH[]` follows Algorithm 3's rule and `EH` holds every edge once.
pub(crate) fn check_cells(
    vertices: usize,
    v: &[u32],
    o: &[i32],
    vh: &[i32],
    eh: &[u32],
    structure: &'static str,
) -> Result<()> {
    check_opposites(vertices, v, o, structure)?;
    if !ranges_hold(v, o, vh) {
        return Err(Error::invariant(
            structure,
            "V[], O[] and VH[] are not one entry per half-edge with every id in range",
        ));
    }
    if vh.len() != vertices {
        return Err(Error::invariant(structure, "VH[] and G[] differ in length"));
    }
    for (he, (&start, &opposite)) in v.iter().zip(o).enumerate() {
        let stored = vh[start as usize];
        let fits = stored >= 0
            && v.get(stored as usize) == Some(&start)
            && (opposite >= 0 || o[stored as usize] < 0);
        if !fits {
            return Err(Error::invariant(
                structure,
                format!("VH[{start}] = {stored} breaks Algorithm 3's rule for half-edge {he}"),
            ));
        }
    }
    if eh != edge_map_by_scan(o) {
        return Err(Error::invariant(
            structure,
            "EH does not hold each edge's smaller half-edge",
        ));
    }
    Ok(())
}

impl CheLevel for CheL2 {
    const LEVEL: u8 = 2;
    const STAR_ALGORITHM: &'static str = "Algorithm 7 (§4.6): start at VH[v], walk the fan";

    #[inline]
    fn start_vertices(&self) -> &[u32] {
        self.l1.start_vertices()
    }

    /// Algorithm 7: the walk starts at `VH[v]`, the boundary half-edge of a boundary vertex,
    /// so one pass in one direction reaches the whole star.
    #[inline(always)]
    fn vertex_star(
        &self,
        v: VertexId,
        mut trace: impl FnMut(StarRead),
        corner: impl FnMut(HalfEdgeId),
    ) -> Option<HalfEdgeId> {
        let he = read!("VH", self.vh, v.index());
        trace(StarRead::VertexHalfEdge { vertex: v, he });
        if he < 0 {
            return None;
        }
        fan_walk_algorithm_7(self.l1.opposite(), HalfEdgeId(he as u32), trace, corner)
    }

    #[inline(always)]
    fn twin(&self, he: HalfEdgeId) -> Option<HalfEdgeId> {
        self.l1.twin(he)
    }

    #[inline(always)]
    fn edge_of(&self, he: HalfEdgeId) -> EdgeId {
        self.l1.edge_of(he)
    }

    /// The star walked from both ends (`Fan::spokes`); each neighbour is `V[e]` of the
    /// half-edge entering `v`.
    #[inline(always)]
    fn neighbours(&self, v: VertexId, mut f: impl FnMut(VertexId)) {
        let fan = self.fan();
        if let Some(b) = fan.spokes(v, |e, _| f(fan.far_end(e))) {
            f(fan.lone_far_end(b));
        }
    }

    /// The star walked from both ends (`Fan::spokes`); each edge is `min(e, O[e])`.
    #[inline(always)]
    fn spoke_edges(&self, v: VertexId, mut f: impl FnMut(EdgeId)) {
        let lone = self.fan().spokes(v, |e, o| {
            f(EdgeId(if o < 0 { e.0 } else { e.0.min(o as u32) }))
        });
        if let Some(b) = lone {
            f(EdgeId(b.0));
        }
    }

    /// The star walked from both ends (`Fan::spokes`); each entering half-edge's triangle.
    #[inline(always)]
    fn star_triangles(&self, v: VertexId, mut f: impl FnMut(FaceId)) {
        self.fan().spokes(v, |e, _| f(triangle(e)));
    }

    /// `O[VH[v]] < 0` (§4.3).
    #[inline(always)]
    fn vertex_on_boundary(&self, v: VertexId) -> bool {
        self.fan().on_boundary(v)
    }

    fn each_edge(&self, mut f: impl FnMut(EdgeId)) {
        for &he in &self.eh {
            f(EdgeId(he));
        }
    }

    #[inline]
    fn edge_count(&self) -> usize {
        self.eh.len()
    }
}
