//! CHE level 1, adjacency between triangles (§4.2): adds `O[]`, the opposite of each
//! half-edge (`-1` on the boundary). Edge and triangle relations become O(1); the vertex star
//! still scans `V[]` for its first half-edge (Algorithm 6).

use super::build::{build_chapter, build_fast, build_fast_owned, Checked};
use super::level0::check_start_vertices;
use super::{che_topology, fan_walk_algorithm_7, next, opposite_of, printed, vec_bytes};
use super::{CheL0, CheLevel, StarRead};
use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, HalfEdgeId, VertexId};
use crate::core::reads::traced;
use crate::core::soup::PolygonSoup;
use crate::core::topology::{Cost, MeshTopology, Operator};
use glam::DVec3;

/// CHE level 1: level 0 plus opposite half-edges; see the [module docs](super).
///
/// Its topology is exactly 24 bytes per triangle: `V[]` and `O[]`, 4 bytes per half-edge each.
#[derive(Clone, Debug, PartialEq)]
pub struct CheL1 {
    /// `G[]` and `V[]`.
    pub(super) l0: CheL0,
    /// `O[he]`: the opposite half-edge of he (same vertices, other direction), negative on the
    /// boundary (`-1` here; level 3 stores `-k` for boundary curve k).
    pub(super) o: Vec<i32>,
}

/// Table 4.1's level-1 column, and the cost of the operators the table does not list.
pub(crate) fn level1_cost(op: Operator) -> Cost {
    match op {
        Operator::R00 | Operator::R01 | Operator::R02 | Operator::BoundaryVertex => Cost::Linear,
        Operator::BoundaryCurves => Cost::Linear,
        _ => Cost::Constant,
    }
}

che_topology!(CheL1, "che-l1", level1_cost);

impl CheL1 {
    /// Level 1 of checked containers, and the `VH[]` the checks computed (level 2 keeps it).
    pub(crate) fn from_checked(c: Checked) -> (Self, Vec<i32>) {
        let Checked { g, v, o, vh } = c;
        let l0 = CheL0::from_parts(g, v);
        (Self { l0, o }, vh)
    }

    fn build(soup: &PolygonSoup) -> Result<Self> {
        build_fast(soup, <Self as MeshTopology>::NAME).map(|c| Self::from_checked(c).0)
    }

    /// [`Self::build`] consuming the soup ([`build_fast_owned`]: no copy of its arrays).
    fn build_owned(soup: PolygonSoup) -> Result<Self> {
        build_fast_owned(soup, <Self as MeshTopology>::NAME).map(|c| Self::from_checked(c).0)
    }

    /// Builds level 1 with the chapter's Algorithm 1 (a map keyed by vertex pairs) instead of
    /// the fast construction of `from_soup`; the containers are identical.
    pub fn from_soup_chapter(soup: &PolygonSoup) -> Result<Self> {
        build_chapter(soup, <Self as MeshTopology>::NAME).map(|c| Self::from_checked(c).0)
    }

    /// `G[]`: the vertex positions.
    #[inline]
    pub fn geometry(&self) -> &[DVec3] {
        self.l0.geometry()
    }

    /// `O[]`: the opposite of each half-edge, negative on the boundary.
    #[inline]
    pub fn opposite(&self) -> &[i32] {
        &self.o
    }

    /// Level 0 (`G[]`, `V[]`).
    #[inline]
    pub fn level0(&self) -> &CheL0 {
        &self.l0
    }

    /// `O[]` to relabel with boundary curve numbers (level 3, Algorithm 4).
    pub(crate) fn opposite_mut(&mut self) -> &mut [i32] {
        &mut self.o
    }

    fn check_containers(&self) -> Result<()> {
        self.check_opposites(<Self as MeshTopology>::NAME)
    }

    /// `V[]` is valid and `O[]` pairs half-edges with the same vertices in opposite directions
    /// ([`check_opposites`]).
    pub(crate) fn check_opposites(&self, structure: &'static str) -> Result<()> {
        check_opposites(
            self.geometry().len(),
            self.start_vertices(),
            &self.o,
            structure,
        )
    }

    pub(crate) fn container_bytes(&self) -> usize {
        self.l0.container_bytes() + vec_bytes(&self.o)
    }

    pub(crate) fn print_containers(&self, w: &mut dyn std::fmt::Write) -> std::fmt::Result {
        self.l0.print_containers(w)?;
        printed::opposites(w, &self.o)
    }
}

/// Level 1's invariant on slices (so that a mapped CHE checks its containers with the same
/// code): `V[]` holds whole triangles of the `vertices` vertices, and `O[]` pairs half-edges
/// with the same vertices in opposite directions.
pub(crate) fn check_opposites(
    vertices: usize,
    v: &[u32],
    o: &[i32],
    structure: &'static str,
) -> Result<()> {
    check_start_vertices(vertices, v, structure)?;
    if o.len() != v.len() {
        return Err(Error::invariant(structure, "O[] and V[] differ in length"));
    }
    for he in (0..v.len() as u32).map(HalfEdgeId) {
        let Some(twin) = opposite_of(o, he) else {
            continue;
        };
        let paired = twin.index() < v.len()
            && twin != he
            && o[twin.index()] == he.0 as i32
            && v[twin.index()] == v[next(he).index()]
            && v[next(twin).index()] == v[he.index()];
        if !paired {
            return Err(Error::invariant(
                structure,
                format!("O[{he}] = {twin} is not its opposite half-edge"),
            ));
        }
    }
    Ok(())
}

/// Algorithm 6 (§4.6) over `V[]` and `O[]`: the first half-edge leaving `vertex` is found by
/// scanning `V[]`. It may be an interior half-edge of a boundary vertex (the pseudo-code
/// assumes it is not), so the walk first turns back, `h ← next(O[h])`, to the boundary
/// half-edge leaving `vertex` (or all the way round), then walks the fan forward as
/// Algorithm 7 does. Level 1's vertex star, owned ([`CheL1`]) or mapped.
#[inline]
pub(crate) fn vertex_star_algorithm_6(
    v: &[u32],
    o: &[i32],
    vertex: VertexId,
    mut trace: impl FnMut(StarRead),
    corner: impl FnMut(HalfEdgeId),
) -> Option<HalfEdgeId> {
    let mut first = None;
    for (he, &start) in (0u32..).map(HalfEdgeId).zip(v) {
        traced!("V", he.0, start);
        let start = VertexId(start);
        trace(StarRead::Vertex { he, vertex: start });
        if start == vertex {
            first = Some(he);
            break;
        }
    }
    let he0 = first?;
    let mut h = he0;
    loop {
        trace(StarRead::Opposite {
            he: h,
            opposite: o[h.index()],
        });
        match opposite_of(o, h) {
            None => break,
            Some(twin) => h = next(twin),
        }
        if h == he0 {
            break;
        }
    }
    fan_walk_algorithm_7(o, h, trace, corner)
}

impl CheLevel for CheL1 {
    const LEVEL: u8 = 1;
    const STAR_ALGORITHM: &'static str =
        "Algorithm 6 (§4.6): scan V[] for a first half-edge, turn back to the boundary, walk the fan";

    #[inline]
    fn start_vertices(&self) -> &[u32] {
        self.l0.start_vertices()
    }

    /// Algorithm 6 (`vertex_star_algorithm_6`, shared with the mapped level 1).
    fn vertex_star(
        &self,
        v: VertexId,
        trace: impl FnMut(StarRead),
        corner: impl FnMut(HalfEdgeId),
    ) -> Option<HalfEdgeId> {
        vertex_star_algorithm_6(self.start_vertices(), &self.o, v, trace, corner)
    }

    #[inline(always)]
    fn twin(&self, he: HalfEdgeId) -> Option<HalfEdgeId> {
        opposite_of(&self.o, he)
    }

    /// The smaller half-edge of the edge, `min(he, O[he])` (the key of level 2's `EH`).
    #[inline(always)]
    fn edge_of(&self, he: HalfEdgeId) -> EdgeId {
        EdgeId(opposite_of(&self.o, he).map_or(he, |o| o.min(he)).0)
    }
}
