//! CHE level 0, the "triangle soup" (§4.1): `G[]` and `V[]` only; every relation that needs a
//! neighbour scans `V[]` (Algorithms 5, 8, 9).

use super::build::{build_fast, build_fast_owned, Checked};
use super::{che_topology, half_edges_of, next, prev, printed, triangle};
use super::{vec_bytes, CheLevel, StarRead};
use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
use crate::core::reads::read;
use crate::core::soup::PolygonSoup;
use crate::core::topology::{Cost, MeshTopology, Operator};
use glam::DVec3;

/// CHE level 0: geometry and the start vertex of each half-edge; see the [module docs](super).
#[derive(Clone, Debug, PartialEq)]
pub struct CheL0 {
    /// `G[v]`: the coordinates of vertex v (the chapter's Geometry container).
    pub(super) g: Vec<DVec3>,
    /// `V[he]`: the start vertex of half-edge he; triangle t owns half-edges 3t, 3t+1, 3t+2.
    pub(super) v: Vec<u32>,
    /// Vertices deleted by an edit, kept as slots until garbage collection ([`super::edit`]);
    /// empty (no memory) until the first deletion.
    pub(super) deleted: Vec<bool>,
}

/// Table 4.1's level-0 column, and the cost of the operators the table does not list.
fn level0_cost(op: Operator) -> Cost {
    match op {
        Operator::R10 | Operator::R20 | Operator::R21 => Cost::Constant,
        Operator::EdgeSuccessor | Operator::EdgePredecessor => Cost::Constant,
        Operator::BoundaryCurves => Cost::Quadratic,
        _ => Cost::Linear,
    }
}

che_topology!(CheL0, "che-l0", level0_cost);

/// Finds the neighbour across the boundary edge entering a vertex from one scan, without
/// storage: around a manifold vertex every neighbour is the end of a half-edge leaving it,
/// except, at a boundary vertex, the start `u` of the boundary half-edge entering it. Each
/// interior neighbour is met once leaving and once entering, so the sums of entering minus
/// leaving neighbours are `u - w` and `u² - w²` (`w` the end of the boundary half-edge
/// leaving), which give `u` (the "missing number" of the two lists).
#[derive(Default)]
struct LoneNeighbour {
    /// Σ entering − Σ leaving.
    sum: i128,
    /// Σ entering² − Σ leaving².
    sum_of_squares: i128,
}

impl LoneNeighbour {
    #[inline(always)]
    fn add(&mut self, entering_from: u32, leaving_to: u32) {
        let (a, b) = (entering_from as i128, leaving_to as i128);
        self.sum += a - b;
        self.sum_of_squares += a * a - b * b;
    }

    /// `u`, or `None` for an interior vertex (`u ≠ w` always, so `u - w = 0` means interior).
    fn vertex(&self) -> Option<u32> {
        (self.sum != 0).then(|| ((self.sum + self.sum_of_squares / self.sum) / 2) as u32)
    }
}

impl CheL0 {
    /// Level 0 of the containers `G[]` and `V[]`.
    pub(crate) fn from_parts(g: Vec<DVec3>, v: Vec<u32>) -> Self {
        Self {
            g,
            v,
            deleted: Vec::new(),
        }
    }

    fn build(soup: &PolygonSoup) -> Result<Self> {
        build_fast(soup, <Self as MeshTopology>::NAME).map(Self::finish)
    }

    /// [`Self::build`] consuming the soup ([`build_fast_owned`]: no copy of its arrays).
    fn build_owned(soup: PolygonSoup) -> Result<Self> {
        build_fast_owned(soup, <Self as MeshTopology>::NAME).map(Self::finish)
    }

    /// The checks need O[] (non-manifold edges and vertices are refused at every level);
    /// level 0 keeps only G[] and V[].
    fn finish(c: Checked) -> Self {
        Self::from_parts(c.g, c.v)
    }

    /// `G[]`: the vertex positions.
    #[inline]
    pub fn geometry(&self) -> &[DVec3] {
        &self.g
    }

    /// Every half-edge, in index order.
    fn half_edges(&self) -> impl Iterator<Item = HalfEdgeId> {
        (0..self.v.len() as u32).map(HalfEdgeId)
    }

    /// `V[he]`.
    #[inline(always)]
    fn start(&self, he: HalfEdgeId) -> VertexId {
        VertexId(read!("V", self.v, he.index()))
    }

    /// The scan of Algorithm 8: the half-edge from `a` to `b`, each `V[]` read reported.
    fn find_half_edge(
        &self,
        a: VertexId,
        b: VertexId,
        mut trace: impl FnMut(StarRead),
    ) -> Option<HalfEdgeId> {
        self.half_edges().find(|&he| {
            let start = self.start(he);
            trace(StarRead::Vertex { he, vertex: start });
            start == a && {
                let end = self.start(next(he));
                trace(StarRead::Vertex {
                    he: next(he),
                    vertex: end,
                });
                end == b
            }
        })
    }

    fn check_containers(&self) -> Result<()> {
        self.check_start_vertices(<Self as MeshTopology>::NAME)
    }

    /// `V[]` holds whole triangles of existing vertices ([`check_start_vertices`]).
    pub(crate) fn check_start_vertices(&self, structure: &'static str) -> Result<()> {
        check_start_vertices(self.g.len(), &self.v, structure)
    }

    pub(crate) fn container_bytes(&self) -> usize {
        vec_bytes(&self.g) + vec_bytes(&self.v) + vec_bytes(&self.deleted)
    }

    pub(crate) fn print_containers(&self, w: &mut dyn std::fmt::Write) -> std::fmt::Result {
        printed::geometry(w, &self.g)?;
        printed::start_vertices(w, &self.v)
    }
}

/// `V[]` holds whole triangles of the `vertices` vertices: level 0's invariant, on slices so
/// that a mapped CHE checks its containers with the same code.
pub(crate) fn check_start_vertices(
    vertices: usize,
    v: &[u32],
    structure: &'static str,
) -> Result<()> {
    if !v.len().is_multiple_of(3) {
        return Err(Error::invariant(
            structure,
            "V[] does not hold whole triangles",
        ));
    }
    match v.iter().position(|&x| x as usize >= vertices) {
        Some(he) => Err(Error::invariant(
            structure,
            format!("V[{he}] = {} names a missing vertex", v[he]),
        )),
        None => Ok(()),
    }
}

impl CheLevel for CheL0 {
    const LEVEL: u8 = 0;
    const STAR_ALGORITHM: &'static str = "Algorithm 5 (§4.6): scan V[] for the vertex";

    /// Every edge once, as its smaller half-edge. An enumeration helper, not one of the
    /// chapter's queries: without `O[]`, asking Algorithm 8 for each half-edge's twin would cost
    /// O(n2²), so the half-edges are sorted by their end vertices instead (O(n2 log n2), with a
    /// temporary buffer) and the first of each pair is listed.
    fn each_edge(&self, mut f: impl FnMut(EdgeId)) {
        let mut keyed: Vec<(u64, u32)> = self
            .half_edges()
            .map(|he| {
                let (a, b) = (self.start(he).0, self.start(next(he)).0);
                let (lo, hi) = if a < b { (a, b) } else { (b, a) };
                (((lo as u64) << 32) | hi as u64, he.0)
            })
            .collect();
        keyed.sort_unstable();
        let mut firsts: Vec<u32> = keyed.chunk_by(|x, y| x.0 == y.0).map(|g| g[0].1).collect();
        firsts.sort_unstable();
        firsts.into_iter().for_each(|he| f(EdgeId(he)));
    }

    #[inline]
    fn start_vertices(&self) -> &[u32] {
        &self.v
    }

    /// Algorithm 5: every half-edge leaving `v` is found by scanning `V[]`; the chapter
    /// gathers the star's simplices in a set, which a query may not allocate, so the
    /// boundary half-edge entering `v` (the one simplex not met as a half-edge leaving `v`)
    /// comes from sums over the scan (see the module docs) and a second scan.
    fn vertex_star(
        &self,
        v: VertexId,
        mut trace: impl FnMut(StarRead),
        mut corner: impl FnMut(HalfEdgeId),
    ) -> Option<HalfEdgeId> {
        let mut lone = LoneNeighbour::default();
        for he in self.half_edges() {
            let start = self.start(he);
            trace(StarRead::Vertex { he, vertex: start });
            if start == v {
                trace(StarRead::Corner { he });
                corner(he);
                let entering_from = self.start(prev(he));
                trace(StarRead::Vertex {
                    he: prev(he),
                    vertex: entering_from,
                });
                let leaving_to = self.start(next(he));
                trace(StarRead::Vertex {
                    he: next(he),
                    vertex: leaving_to,
                });
                lone.add(entering_from.0, leaving_to.0);
            }
        }
        let closing = self.find_half_edge(VertexId(lone.vertex()?), v, &mut trace);
        if let Some(he) = closing {
            trace(StarRead::Closing { he });
        }
        closing
    }

    /// Algorithm 8's scan for the half-edge with the same vertices in the other direction.
    fn twin(&self, he: HalfEdgeId) -> Option<HalfEdgeId> {
        self.find_half_edge(self.start(next(he)), self.start(he), |_| {})
    }

    /// Algorithm 9: one scan of `V[]` for the half-edges opposite to any of `t`'s three.
    fn triangles_across(&self, t: FaceId, mut f: impl FnMut(FaceId)) {
        let mut own = half_edges_of(t).map(|he| (self.start(he), self.start(next(he))));
        let own = [(); 3].map(|()| own.next().expect("a triangle has three half-edges"));
        for he in self.half_edges() {
            let reversed = (self.start(next(he)), self.start(he));
            if triangle(he) != t && own.contains(&reversed) {
                f(triangle(he));
            }
        }
    }
}
