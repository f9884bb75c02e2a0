//! CHE level 3, the boundary curves (§4.4): adds `CH[]`, one half-edge per boundary curve
//! (Algorithm 4), and stores in `O[he]` the number of the curve of each boundary half-edge as
//! a negative value (curve k → `-k`), so boundary tests stay `O[he] < 0`. The boundary curves
//! are walked from `CH[]` (Algorithm 10) in O(∂n1).

use super::build::{
    boundary_curves_algorithm_4, build_chapter, build_fast, build_fast_owned, edge_map_algorithm_2,
    edge_map_by_scan,
};
use super::{che_topology, level2::level2_cost, printed, vec_bytes, walk_boundary_curve};
use super::{next_boundary_half_edge, opposite_of, CheL2, CheLevel, StarRead};
use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
use crate::core::reads;
use crate::core::soup::PolygonSoup;
use crate::core::topology::{BoundaryCurves, Cost, MeshTopology, Operator};
use glam::DVec3;

/// CHE level 3: level 2 plus one half-edge per boundary curve; see the [module docs](super).
#[derive(Clone, Debug, PartialEq)]
pub struct CheL3 {
    /// `G[]`, `V[]`, `O[]` (boundary half-edges labelled `-k`), `VH[]`, `EH`.
    pub(super) l2: CheL2,
    /// `CH[k - 1]`: a half-edge of boundary curve k (curves numbered from 1).
    pub(super) ch: Vec<u32>,
}

/// Table 4.1's level-3 column (level 2), with boundary curves in O(∂n1).
pub(crate) fn level3_cost(op: Operator) -> Cost {
    match op {
        Operator::BoundaryCurves => Cost::Boundary,
        _ => level2_cost(op),
    }
}

che_topology!(CheL3, "che-l3", level3_cost);

impl CheL3 {
    pub(crate) fn from_level2(mut l2: CheL2) -> Result<Self> {
        let ch = l2.relabel_opposites(Self::NAME, boundary_curves_algorithm_4)?;
        Ok(Self { l2, ch })
    }

    fn build(soup: &PolygonSoup) -> Result<Self> {
        build_fast(soup, Self::NAME)
            .and_then(|c| CheL2::from_checked(c, edge_map_by_scan, Self::NAME))
            .and_then(Self::from_level2)
    }

    /// [`Self::build`] consuming the soup ([`build_fast_owned`]: no copy of its arrays).
    fn build_owned(soup: PolygonSoup) -> Result<Self> {
        build_fast_owned(soup, Self::NAME)
            .and_then(|c| CheL2::from_checked(c, edge_map_by_scan, Self::NAME))
            .and_then(Self::from_level2)
    }

    /// Builds level 3 with the chapter's Algorithms 1–4 (maps) instead of the fast
    /// construction of `from_soup`; the containers are identical.
    pub fn from_soup_chapter(soup: &PolygonSoup) -> Result<Self> {
        build_chapter(soup, Self::NAME)
            .and_then(|c| CheL2::from_checked(c, edge_map_algorithm_2, Self::NAME))
            .and_then(Self::from_level2)
    }

    /// `G[]`: the vertex positions.
    #[inline]
    pub fn geometry(&self) -> &[DVec3] {
        self.l2.geometry()
    }

    /// Level 2 (`G[]`, `V[]`, `O[]` with curve labels, `VH[]`, `EH`).
    #[inline]
    pub fn level2(&self) -> &CheL2 {
        &self.l2
    }

    /// `CH[]`: one half-edge of each boundary curve; `CH[k - 1]` is on curve k.
    pub fn curve_half_edge(&self) -> &[u32] {
        &self.ch
    }

    fn check_containers(&self) -> Result<()> {
        let structure = <Self as MeshTopology>::NAME;
        self.l2.check_cells(structure)?;
        check_curves(self.l2.level1().opposite(), &self.ch, structure)
    }

    fn container_bytes(&self) -> usize {
        self.l2.container_bytes() + vec_bytes(&self.ch)
    }

    fn print_containers(&self, w: &mut dyn std::fmt::Write) -> std::fmt::Result {
        self.l2.print_containers(w)?;
        printed::curves(w, &self.ch)
    }
}

/// Level 3's own invariant on slices (so that a mapped CHE checks its containers with the
/// same code), for an `O[]` that already passed level 2's checks: each curve of `CH[]` is
/// labelled `-k` in `O[]` all the way round, and every boundary half-edge is on one.
pub(crate) fn check_curves(o: &[i32], ch: &[u32], structure: &'static str) -> Result<()> {
    let mut walked = 0;
    for (k, &start) in ch.iter().enumerate() {
        let label = -(k as i32 + 1);
        let mut he = HalfEdgeId(start);
        loop {
            if o.get(he.index()) != Some(&label) {
                return Err(Error::invariant(
                    structure,
                    format!(
                        "half-edge {he} of boundary curve {} is not labelled {label}",
                        k + 1
                    ),
                ));
            }
            walked += 1;
            he = next_boundary_half_edge(he, |h| opposite_of(o, h));
            if he.0 == start {
                break;
            }
        }
    }
    if walked != o.iter().filter(|&&x| x < 0).count() {
        return Err(Error::invariant(
            structure,
            "a boundary half-edge is on no curve of CH[]",
        ));
    }
    Ok(())
}

impl CheLevel for CheL3 {
    const LEVEL: u8 = 3;
    const STAR_ALGORITHM: &'static str = CheL2::STAR_ALGORITHM;

    #[inline]
    fn start_vertices(&self) -> &[u32] {
        self.l2.start_vertices()
    }

    #[inline(always)]
    fn vertex_star(
        &self,
        v: VertexId,
        trace: impl FnMut(StarRead),
        corner: impl FnMut(HalfEdgeId),
    ) -> Option<HalfEdgeId> {
        self.l2.vertex_star(v, trace, corner)
    }

    #[inline(always)]
    fn twin(&self, he: HalfEdgeId) -> Option<HalfEdgeId> {
        self.l2.twin(he)
    }

    #[inline(always)]
    fn edge_of(&self, he: HalfEdgeId) -> EdgeId {
        self.l2.edge_of(he)
    }

    #[inline(always)]
    fn neighbours(&self, v: VertexId, f: impl FnMut(VertexId)) {
        self.l2.neighbours(v, f)
    }

    #[inline(always)]
    fn spoke_edges(&self, v: VertexId, f: impl FnMut(EdgeId)) {
        self.l2.spoke_edges(v, f)
    }

    #[inline(always)]
    fn star_triangles(&self, v: VertexId, f: impl FnMut(FaceId)) {
        self.l2.star_triangles(v, f)
    }

    #[inline(always)]
    fn vertex_on_boundary(&self, v: VertexId) -> bool {
        self.l2.vertex_on_boundary(v)
    }

    fn triangles_across(&self, t: FaceId, f: impl FnMut(FaceId)) {
        self.l2.triangles_across(t, f)
    }

    fn each_edge(&self, f: impl FnMut(EdgeId)) {
        self.l2.each_edge(f)
    }

    #[inline]
    fn edge_count(&self) -> usize {
        self.l2.edge_count()
    }

    /// Algorithm 10 (§4.6): each curve walked from its half-edge in `CH[]`, O(∂n1).
    fn walk_boundary_curves(&self, out: &mut BoundaryCurves) {
        out.clear();
        for he in reads::each("CH", &self.ch, 0) {
            walk_boundary_curve(HalfEdgeId(he), |h| self.twin(h), out);
        }
    }
}
