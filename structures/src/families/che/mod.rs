//! # Compact Half-Edge (CHE), levels 0–3
//!
//! The CHE thesis chapter (chapter 4, "A Estrutura de Dados CHE"; see "The sources" in
//! `docs/structures.md`): a triangle mesh stored as integer arrays, in four levels that each add
//! containers and answer the relations with that level's algorithm, so the lab can measure the
//! chapter's Table 4.1 cell by cell.
//!
//! Vertices, half-edges and triangles are non-negative integers. Triangle `t` owns the
//! half-edges `3t, 3t+1, 3t+2`; half-edge `he` belongs to triangle `he / 3`, and
//! `next(he) = 3⌊he/3⌋ + (he+1) % 3`, `prev(he) = 3⌊he/3⌋ + (he+2) % 3` (§4.1, [`next`],
//! [`prev`], [`triangle`]). Half-edge `3t + i` leaves vertex `i` of input face `t`.
//!
//! | level | type | adds (§) | bytes |
//! |---|---|---|---|
//! | 0 "triangle soup" | [`CheL0`] | `G[v]` geometry, `V[he]` start vertex (§4.1) | 24 per vertex + 12 per triangle |
//! | 1 adjacency | [`CheL1`] | `O[he]` opposite half-edge, `-1` on the boundary (§4.2, Algorithm 1) | + 12 per triangle (topology: exactly 24 per triangle) |
//! | 2 cells | [`CheL2`] | `VH[v]` one half-edge per vertex (Algorithm 3), `EH` the edge map (Algorithm 2) (§4.3) | + 4 per vertex + 4 per edge |
//! | 3 boundary curves | [`CheL3`] | `CH[k-1]` one half-edge of boundary curve k, and `O[he] = -k` on curve k (§4.4, Algorithm 4) | + 4 per curve |
//!
//! Every container is a `u32` or `i32` array (the chapter's `-1` is kept as a signed value in
//! `O[]` and `VH[]`), so a mesh may have at most `i32::MAX` half-edges.
//!
//! ## Relations and their cost (Table 4.1 of §4.6, plus what the table does not list)
//!
//! | operator | L0 | L1 | L2 | L3 |
//! |---|---|---|---|---|
//! | R00, R01, R02 | O(n2) Algorithm 5 | O(n2) Algorithm 6 | O(deg v) Algorithm 7 | O(deg v) Algorithm 7 |
//! | R10 | O(1) | O(1) | O(1) | O(1) |
//! | R11, R12 | O(n2) Algorithm 8 | O(1) | O(1) | O(1) |
//! | R20, R21 | O(1) | O(1) | O(1) | O(1) |
//! | R22 | O(n2) Algorithm 9 | O(1) | O(1) | O(1) |
//! | boundary vertex | O(n2) (Algorithm 5's scan) | O(n2) (Algorithm 6) | O(1): `O[VH[v]] < 0` | O(1) |
//! | boundary edge | O(n2) (Algorithm 8's scan) | O(1): `O[he] < 0` | O(1) | O(1) |
//! | boundary curves | O(n2²): a scan per half-edge | O(n2) scan, §4.6 | O(n2) | O(∂n1) Algorithm 10 (each step turns around one vertex) |
//! | successor, predecessor | O(1) | O(1) | O(1) | O(1) |
//!
//! At level 0 the chapter gathers a star's simplices in a set, which a query may not
//! allocate: every edge and neighbour of a vertex is met as a half-edge leaving it except, at a
//! boundary vertex, the boundary edge entering it, whose far end is recovered from sums over
//! the same scan (the "missing number" of two lists) and its half-edge by a second scan.
//! A level-0 edge's boundary test is Algorithm 8's scan, O(n2), so the boundary curves (and
//! `num_boundary_edges`) of level 0 cost a scan per half-edge, O(n2²): keep level 0 to small
//! meshes or to the operators Table 4.1 lists. Enumerating the edges (`for_each_edge`,
//! `num_edges`) is no relation of the chapter and would cost the same O(n2²) by Algorithm 8;
//! level 0 instead sorts its half-edges by their vertex pair in a temporary buffer,
//! O(n2 log n2), the one place a CHE level allocates to answer (the exception the trait's
//! [`for_each_edge`](crate::MeshTopology::for_each_edge) documents).
//!
//! Successor and predecessor are O(1) at every level: the three half-edges of the face are
//! `3t..3t+3`, so the edge is found among them by its end vertices. The boundary curves of
//! levels 0–2 also check each boundary half-edge against the curves already written (a query
//! may not allocate a visited array), which adds O(∂n1²): on the lab's meshes ∂n1 ~ √n2.
//!
//! ## Edge ids
//!
//! An edge is represented by one of its half-edges, as the chapter does (`E_id e = he`):
//! `EdgeId(he)`. At level 0 there is no `O[]`, so *either* half-edge of an interior edge names it,
//! and the relations answer with the half-edge they read;
//! [`MeshTopology::for_each_edge`](crate::MeshTopology::for_each_edge) lists the smaller one. From
//! level 1 on, answers always give the smaller half-edge `min(he, O[he])` (the boundary half-edge
//! for a boundary edge): exactly the keys of level 2's `EH` (Algorithm 2).
//!
//! ## What is refused
//!
//! Triangles only ([`Error::NotTriangles`](crate::Error::NotTriangles)). Non-manifold edges
//! ([`Error::NonManifoldEdge`](crate::Error::NonManifoldEdge), naming the edge and its faces) and
//! inconsistent orientation are refused as everywhere in the lab. Non-manifold vertices are refused
//! ([`Error::NonManifoldVertex`](crate::Error::NonManifoldVertex)): `VH[v]` stores one half-edge
//! and the vertex star (Algorithms 6, 7) walks one fan, so a second fan would be silently missed.
//!
//! ## Construction
//!
//! [`opposites_algorithm_1`] is Algorithm 1 as written (a `HashMap` keyed by the sorted vertex
//! pair); [`opposites_by_buckets`] builds the identical `O[]` without hashing, in the same one
//! pass with a small bucket per smaller vertex in place of the map. `from_soup` uses the fast one and
//! `from_soup_chapter` the chapter's algorithms; a proptest checks they agree.
//!
//! Note on the pseudo-code: Algorithms 6 and 7 step `h ← next(O[h])`, which from the boundary
//! half-edge stored in `VH[v]` stops at once; the walk here ([`fan_walk_algorithm_7`]) turns the
//! other way, `h ← O[prev(h)]`, which from that half-edge reaches every triangle of the star.
//! Algorithm 10 steps `next(O[next(he)])` even when `next(he)` is on the boundary; the walk here
//! ([`next_boundary_half_edge`]) is Algorithm 4's inner loop, which stops there.
//!
//! ## Speed: the timed vertex relations of levels 2 and 3
//!
//! R00, R01 and R02 answer sets, so levels 2 and 3 answer them by the fastest walk of the same
//! star rather than in Algorithm 7's order; [`CheLevel::vertex_star`] (and with it
//! `topolab explain che --trace`) keeps Algorithm 7 as the chapter writes it. Five things
//! made the walk slow. They were found by counting instructions with callgrind on the
//! harness's R00 sweep of a torus (the `fan_sweep` example's docs give the command, which
//! counts the timed kernel only), and each change below lowered that count:
//!
//! - **`% 3` on the walk's chain.** The walk's dependency chain is `h → prev(h) → O[prev(h)]
//!   → h`. With `next` written `he % 3 == 2` and `prev` `he % 3 == 0` in one loop, the
//!   compiler computed one full remainder for both before every `O[]` load. [`next`] and
//!   [`prev`] now test divisibility (`(he + 1).is_multiple_of(3)`, the same definition),
//!   a multiply and a compare.
//! - **Calls.** The relations the `che_topology!` macro writes were not `#[inline]`: the
//!   harness called R00 out of line and the smoothing workload reached the boundary test
//!   through the GOT. They are `#[inline]` now, as the fairness rule of
//!   [`MeshTopology`](crate::MeshTopology) asks of every structure.
//! - **One chain.** The walk (`Fan::spokes`) covers an interior star from both ends at once,
//!   forward `h ← O[prev(h)]` and backward `g ← next(O[g])`, until the two meet: two
//!   independent chains, each half as long. Each neighbour is read as `V[e]` of the half-edge
//!   `e` that enters the vertex, at the index where the walk reads `O[e]`, instead of
//!   `V[next(h)]` after it. A boundary star is walked forward only: its `VH[v]` is one end,
//!   and the other is not stored.
//! - **Bounds checks.** Levels 2 and 3 never change `V[]`, `O[]` and `VH[]` after they are
//!   built, except that level 3 writes negative curve labels into `O[]`. So the walk reads
//!   `V[]` and `O[]` without bounds checks. This is safe because every id the arrays hold is
//!   checked to be in range once: when the mesh is built, after level 3's relabelling, and
//!   in `validate()`. The unchecked reads are in one small module (`fan.rs`), which says why
//!   each index is in range. The smoothing workload gained too, because the compiler now
//!   shares the boundary test's `VH[v]` and `O[VH[v]]` reads with the walk that follows it.
//!   Each end of the walk then tracked the next spoke it reports (a half-edge entering the
//!   vertex), which needs one state variable fewer and a few instructions fewer, but timed
//!   no faster.
//! - **`prev` as a choice of two candidates.** Written "`he + 2` if 3 divides `he`, else
//!   `he - 1`", [`prev`] compiled to `he + (test ? 2 : -1)`: after the multiply and the
//!   compare, an add-with-carry and an `or` made the `-1` or `2`, then an add, all before the
//!   forward walk's next `O[]` load: one cycle more on that chain than [`next`], which the
//!   compiler already wrote as a conditional move. Written as a choice between the
//!   candidates `he + 2` and `he - 1` (the same definition), both candidates are computed
//!   beside the multiply and a conditional move picks one: multiply, compare, move, load.
//!   Timed in thread CPU time by a copy of both walks outside the crate (the same arrays and
//!   checksum, the variants and the index half-edge taking turns on the 1M-triangle torus),
//!   the conditional move lowered R00's ratio to the index half-edge; the same move written
//!   in inline assembly was no faster than the Rust form. The report's Targets turns, run
//!   with the binaries before and after on a busy machine, could not tell the two apart: the
//!   rounds of one run spread wider than the change.
//!
//! What is left is the chain, and it is the CHE's design: each step computes `prev` or
//! `next` (a multiply, a compare and a conditional move) before its load, where the
//! half-edge's `twin` is `h ^ 1`, one instruction. Per spoke, the CHE's chains do several
//! dependent instructions of arithmetic before the load against one on the index
//! half-edge's, which the CHE's two chains (each half as long) only make up for in part.
//! These variants were measured on that same sweep (instructions counted, most of them timed
//! in turns too) and not kept:
//!
//! | variant | why it was not kept |
//! |---|---|
//! | one end only, with a boundary check first | fewer instructions, but slower: one chain, twice as long |
//! | one end only, two steps unrolled | fewer instructions, but no faster than one end |
//! | `prev` as arithmetic, `h - 1 + 3·[3 divides h]` | more instructions than the two-candidate `prev` |
//! | `prev` as a select the compiler cannot turn into a branch | as many instructions as the two-candidate `prev`, which is kept, and no faster |
//! | a software prefetch of `O[VH[v + 8]]`, offered to the index half-edge too (`next[VH[v + 8] ^ 1]`) | no faster for either, within the spread of the rounds: the sweep reads two forward streams, which the hardware prefetcher already follows |
//! | both candidate `O[]` entries of `prev` loaded, then one selected | more instructions, and slower in the copy outside the crate (both chains, candidates clamped to the array) |
//! | both ends, each tracking the half-edge that enters | about the same instructions, no faster |
//!
//! The two-ended walk and the unchecked reads were timed with the structures taking turns in
//! one process (`cargo run --release --example fan_sweep`, whose docs give its arguments):
//! the two-ended walk made R00 and smoothing faster against the index half-edge on the
//! 1M-triangle torus. The unchecked reads were timed on the 100k-triangle torus
//! (`fan_sweep 100000 torus 201`), because on a busy machine the 1M-triangle ratios swung
//! more within one binary than the change could move them; they made R00 and smoothing
//! faster against both the index half-edge and OpenMesh. The instruction counts show why the
//! CHE's walk cannot match the index half-edge's step for step: it takes more instructions per
//! vertex, and most of the difference is `prev` and `next` at each of a vertex's steps. The
//! developers' guide sets the goals (R00 at most 1.35× and smoothing at most 1.2× the index
//! half-edge's time); the report's Targets section measures both in turns and shows whether a
//! run meets them.

mod access;
pub(crate) mod build;
mod edit;
mod fan;
pub mod file;
mod level0;
mod level1;
mod level2;
mod level3;
pub mod mapped;
mod topology;

pub use build::{
    boundary_curves_algorithm_4, edge_map_algorithm_2, edge_map_by_scan, every_vertex_one_fan,
    opposites_algorithm_1, opposites_and_vertex_half_edges, opposites_by_buckets,
    vertex_half_edges_algorithm_3,
};
pub use level0::CheL0;
pub use level1::CheL1;
pub use level2::CheL2;
pub use level3::CheL3;
pub use mapped::{CheFile, MappedChe, MappedCheL1, MappedCheL2, MappedCheL3};

pub use crate::core::corners::{next, prev, triangle};

use crate::core::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
use crate::core::reads::read;
use crate::core::topology::BoundaryCurves;
use topology::che_topology;

/// The half-edge that represents edge `e` (`E_id e = he`, §4.6).
#[inline(always)]
pub const fn half_edge(e: EdgeId) -> HalfEdgeId {
    HalfEdgeId(e.0)
}

/// `O[he]` as a half-edge, `None` on the boundary (any negative value: `-1`, or `-k` at level 3).
#[inline(always)]
pub fn opposite_of(o: &[i32], he: HalfEdgeId) -> Option<HalfEdgeId> {
    let x = read!("O", o, he.index());
    (x >= 0).then_some(HalfEdgeId(x as u32))
}

/// The half-edges of triangle `t`: `3t, 3t+1, 3t+2` (§4.1).
#[inline(always)]
pub fn half_edges_of(t: FaceId) -> impl Iterator<Item = HalfEdgeId> {
    (3 * t.0..3 * t.0 + 3).map(HalfEdgeId)
}

/// One read a vertex-star algorithm makes, reported to a trace (`topolab explain che --trace`).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum StarRead {
    /// `V[he]` was read (the scans of levels 0 and 1).
    Vertex {
        /// The half-edge.
        he: HalfEdgeId,
        /// Its start vertex.
        vertex: VertexId,
    },
    /// `O[he]` was read.
    Opposite {
        /// The half-edge.
        he: HalfEdgeId,
        /// Its opposite (negative on the boundary).
        opposite: i32,
    },
    /// `VH[v]` was read (levels 2 and 3).
    VertexHalfEdge {
        /// The vertex.
        vertex: VertexId,
        /// Its stored half-edge (`-1` for an unused vertex).
        he: i32,
    },
    /// A triangle of the star was reached through `he`, the half-edge leaving the vertex.
    Corner {
        /// The half-edge leaving the vertex.
        he: HalfEdgeId,
    },
    /// The star ends at this boundary half-edge entering the vertex (boundary vertices only).
    Closing {
        /// The half-edge entering the vertex.
        he: HalfEdgeId,
    },
}

/// What every CHE level provides; the relations common to all levels are built on it once.
///
/// Public so that teaching code (`topolab explain che`) can trace each level's vertex star.
pub trait CheLevel {
    /// The level's number (0–3).
    const LEVEL: u8;
    /// The section of the chapter and the algorithm of its vertex star.
    const STAR_ALGORITHM: &'static str;

    /// `V[]`: the start vertex of each half-edge.
    fn start_vertices(&self) -> &[u32];

    /// The vertex star of `v` by this level's algorithm: calls `corner(he)` for the half-edge
    /// leaving `v` in each triangle of its star, reports every container read to `trace`, and
    /// returns the boundary half-edge entering `v` if `v` is on the boundary.
    fn vertex_star(
        &self,
        v: VertexId,
        trace: impl FnMut(StarRead),
        corner: impl FnMut(HalfEdgeId),
    ) -> Option<HalfEdgeId>;

    /// The opposite of `he` if its edge is interior (level 0: Algorithm 8's scan).
    fn twin(&self, he: HalfEdgeId) -> Option<HalfEdgeId>;

    /// The edge id this level answers for half-edge `he` (see the module docs).
    #[inline(always)]
    fn edge_of(&self, he: HalfEdgeId) -> EdgeId {
        EdgeId(he.0)
    }

    /// R00 as the lab's query answers it (the order is free). Defaults to the star of
    /// [`CheLevel::vertex_star`]: the far end `V[next(he)]` of each corner's half-edge, and the
    /// start of the closing boundary half-edge.
    #[inline(always)]
    fn neighbours(&self, v: VertexId, f: impl FnMut(VertexId)) {
        by_star::neighbours(self, v, f)
    }

    /// R01 as the lab's query answers it. Defaults to the edge of each corner's half-edge
    /// along [`CheLevel::vertex_star`], and the closing one's.
    #[inline(always)]
    fn spoke_edges(&self, v: VertexId, f: impl FnMut(EdgeId)) {
        by_star::spoke_edges(self, v, f)
    }

    /// R02 as the lab's query answers it. Defaults to the triangle of each corner along
    /// [`CheLevel::vertex_star`].
    #[inline(always)]
    fn star_triangles(&self, v: VertexId, f: impl FnMut(FaceId)) {
        by_star::star_triangles(self, v, f)
    }

    /// Is `v` on the boundary? Defaults to walking the star (levels 0 and 1).
    fn vertex_on_boundary(&self, v: VertexId) -> bool {
        by_star::vertex_on_boundary(self, v)
    }

    /// R22 of triangle `t`. Defaults to the triangles across its three half-edges.
    fn triangles_across(&self, t: FaceId, mut f: impl FnMut(FaceId)) {
        for he in half_edges_of(t) {
            if let Some(o) = self.twin(he) {
                f(triangle(o));
            }
        }
    }

    /// Every edge once. Defaults to the half-edges that are the smaller of their pair.
    fn each_edge(&self, f: impl FnMut(EdgeId)) {
        by_star::each_edge(self, f)
    }

    /// Number of edges. Defaults to counting [`CheLevel::each_edge`].
    fn edge_count(&self) -> usize {
        let mut n = 0;
        self.each_edge(|_| n += 1);
        n
    }

    /// The boundary curves. Defaults to the scan of levels 0–2 (§4.6): every boundary
    /// half-edge not yet on a written curve starts a new curve.
    fn walk_boundary_curves(&self, out: &mut BoundaryCurves) {
        by_star::boundary_curves(self, out)
    }
}

/// The default bodies of [`CheLevel`]'s relations, as functions, so that a level whose
/// algorithm depends on a run-time condition (the mapped CHE, [`mapped`], walks its stars by
/// [`CheLevel::vertex_star`] until its file is verified) can still call them.
pub(crate) mod by_star {
    use super::{next, triangle, walk_boundary_curve, CheLevel};
    use crate::core::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
    use crate::core::reads::read;
    use crate::core::topology::BoundaryCurves;

    /// R00 by [`CheLevel::vertex_star`]: the far end `V[next(he)]` of each corner's
    /// half-edge, and the start of the closing boundary half-edge.
    #[inline(always)]
    pub(crate) fn neighbours<L: CheLevel + ?Sized>(
        level: &L,
        v: VertexId,
        mut f: impl FnMut(VertexId),
    ) {
        let vs = level.start_vertices();
        let neighbour = |h: HalfEdgeId| VertexId(read!("V", vs, h.index()));
        if let Some(p) = level.vertex_star(v, |_| {}, |h| f(neighbour(next(h)))) {
            f(neighbour(p));
        }
    }

    /// R01 by [`CheLevel::vertex_star`]: the edge of each corner's half-edge, and the closing
    /// one's.
    #[inline(always)]
    pub(crate) fn spoke_edges<L: CheLevel + ?Sized>(
        level: &L,
        v: VertexId,
        mut f: impl FnMut(EdgeId),
    ) {
        if let Some(p) = level.vertex_star(v, |_| {}, |h| f(level.edge_of(h))) {
            f(level.edge_of(p));
        }
    }

    /// R02 by [`CheLevel::vertex_star`]: the triangle of each corner.
    #[inline(always)]
    pub(crate) fn star_triangles<L: CheLevel + ?Sized>(
        level: &L,
        v: VertexId,
        mut f: impl FnMut(FaceId),
    ) {
        level.vertex_star(v, |_| {}, |h| f(triangle(h)));
    }

    /// Is `v` on the boundary? The star walked to its end.
    pub(crate) fn vertex_on_boundary<L: CheLevel + ?Sized>(level: &L, v: VertexId) -> bool {
        level.vertex_star(v, |_| {}, |_| {}).is_some()
    }

    /// Every edge once: the half-edges that are the smaller of their pair.
    pub(crate) fn each_edge<L: CheLevel + ?Sized>(level: &L, mut f: impl FnMut(EdgeId)) {
        for he in (0..level.start_vertices().len() as u32).map(HalfEdgeId) {
            if level.twin(he).is_none_or(|o| he < o) {
                f(EdgeId(he.0));
            }
        }
    }

    /// The scan of levels 0–2 (§4.6): every boundary half-edge not yet on a written curve
    /// starts a new curve. Which are written is kept as one bit per half-edge, so the scan is
    /// linear (looking each one up in the curves written so far made it quadratic in the
    /// boundary edges: seconds on 40,000 separate triangles).
    pub(crate) fn boundary_curves<L: CheLevel + ?Sized>(level: &L, out: &mut BoundaryCurves) {
        out.clear();
        let half_edges = level.start_vertices().len();
        let mut written = vec![0u64; half_edges.div_ceil(64)];
        for he in (0..half_edges as u32).map(HalfEdgeId) {
            let (word, bit) = (he.index() / 64, 1u64 << (he.index() % 64));
            if level.twin(he).is_none() && written[word] & bit == 0 {
                let from = out.edges.len();
                walk_boundary_curve(he, |h| level.twin(h), out);
                for e in &out.edges[from..] {
                    written[e.index() / 64] |= 1u64 << (e.index() % 64);
                }
            }
        }
    }
}

/// Writes the boundary curve through boundary half-edge `start` into `out` as one curve.
pub(crate) fn walk_boundary_curve(
    start: HalfEdgeId,
    twin: impl Fn(HalfEdgeId) -> Option<HalfEdgeId>,
    out: &mut BoundaryCurves,
) {
    let mut he = start;
    loop {
        out.edges.push(EdgeId(he.0));
        he = next_boundary_half_edge(he, &twin);
        if he == start {
            break;
        }
    }
    out.end_curve();
}

/// The boundary half-edge that follows boundary half-edge `he` on its curve: it leaves the
/// vertex `he` enters, found by turning around that vertex (Algorithm 4's inner loop).
#[inline]
pub fn next_boundary_half_edge(
    he: HalfEdgeId,
    twin: impl Fn(HalfEdgeId) -> Option<HalfEdgeId>,
) -> HalfEdgeId {
    let mut g = next(he);
    while let Some(o) = twin(g) {
        g = next(o);
    }
    g
}

/// The loop of Algorithm 7 (§4.6): from `start`, a half-edge leaving a vertex, visits the
/// half-edge leaving it in each triangle of its fan, stepping `h ← O[prev(h)]` (across the
/// edge entering the vertex). Returns the boundary half-edge entering the vertex where the
/// walk stops, or `None` when it came back to `start` (an interior vertex).
///
/// From a boundary half-edge (what `VH[v]` stores for a boundary vertex) it reaches the whole
/// fan; see the module docs for why it does not step `next(O[h])` as the pseudo-code writes.
#[inline(always)]
pub fn fan_walk_algorithm_7(
    o: &[i32],
    start: HalfEdgeId,
    mut trace: impl FnMut(StarRead),
    mut corner: impl FnMut(HalfEdgeId),
) -> Option<HalfEdgeId> {
    let mut h = start;
    loop {
        trace(StarRead::Corner { he: h });
        corner(h);
        let entering = prev(h);
        let opposite = read!("O", o, entering.index());
        trace(StarRead::Opposite {
            he: entering,
            opposite,
        });
        if opposite < 0 {
            trace(StarRead::Closing { he: entering });
            return Some(entering);
        }
        h = HalfEdgeId(opposite as u32);
        if h == start {
            return None;
        }
    }
}

/// Prints a container as two rows: its indices and its values.
pub(crate) fn print_container<T: std::fmt::Display>(
    w: &mut dyn std::fmt::Write,
    name: &str,
    index: &str,
    values: &[T],
) -> std::fmt::Result {
    write!(w, "  {index:<5}")?;
    for i in 0..values.len() {
        write!(w, "{i:>4}")?;
    }
    writeln!(w)?;
    write!(w, "  {name:<5}")?;
    for x in values {
        write!(w, "{x:>4}")?;
    }
    writeln!(w)
}

/// How each of the CHE's containers is printed, with the heading that says what it holds: the
/// owned levels and the memory-mapped ones print their containers alike.
pub(crate) mod printed {
    use super::print_container;
    use glam::DVec3;
    use std::fmt::{Result, Write};

    /// `G[]`, a position per line.
    pub(crate) fn geometry(w: &mut dyn Write, g: &[DVec3]) -> Result {
        writeln!(w, "G[] geometry, one entry per vertex (n0 = {}):", g.len())?;
        for (i, p) in g.iter().enumerate() {
            writeln!(w, "  G[{i}] = ({:.3}, {:.3}, {:.3})", p.x, p.y, p.z)?;
        }
        Ok(())
    }

    /// `V[]`.
    pub(crate) fn start_vertices(w: &mut dyn Write, v: &[u32]) -> Result {
        writeln!(
            w,
            "V[] start vertex of each half-edge (3·n2 = {}; triangle t owns 3t, 3t+1, 3t+2):",
            v.len()
        )?;
        print_container(w, "V[]", "he", v)
    }

    /// `O[]`.
    pub(crate) fn opposites(w: &mut dyn Write, o: &[i32]) -> Result {
        writeln!(w, "O[] opposite half-edge (negative on the boundary):")?;
        print_container(w, "O[]", "he", o)
    }

    /// `VH[]` and `EH`.
    pub(crate) fn vertex_half_edges_and_edge_map(
        w: &mut dyn Write,
        vh: &[i32],
        eh: &[u32],
    ) -> Result {
        writeln!(
            w,
            "VH[] a half-edge leaving each vertex (the boundary one on the boundary):"
        )?;
        print_container(w, "VH[]", "v", vh)?;
        writeln!(
            w,
            "EH edge map: edge i is the half-edge EH[i] = min(he, O[he]):"
        )?;
        print_container(w, "EH[]", "i", eh)
    }

    /// `CH[]`.
    pub(crate) fn curves(w: &mut dyn Write, ch: &[u32]) -> Result {
        writeln!(
            w,
            "CH[] a half-edge of each boundary curve (O[he] = -k on curve k = index + 1):"
        )?;
        print_container(w, "CH[]", "k-1", ch)
    }
}

/// `Vec` bytes as allocated (capacity).
pub(crate) fn vec_bytes<T>(v: &Vec<T>) -> usize {
    v.capacity() * std::mem::size_of::<T>()
}
