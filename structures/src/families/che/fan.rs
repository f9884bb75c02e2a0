//! The timed vertex star of CHE levels 2 and 3. The crate's only unchecked array reads are
//! here, so this module is the one place to audit for them.
//!
//! A level-2 mesh's `V[]`, `O[]` and `VH[]` change only where they are rewritten whole:
//! level 3 writing negative curve labels into `O[]`, and the edits (`MeshEdit`, in the
//! module `edit`), which cost O(n) on these levels anyway. So whether every id these arrays
//! hold is in range is checked when the mesh is built ([`ranges_hold`]) and again by each of
//! those writers before it returns, instead of on every read. [`CheL2`](super::CheL2) also
//! checks it in `validate()`. It builds a [`Fan`] only over arrays that passed the check.
//!
//! Inside the walk, every index is one of these:
//! - `VH[v]`, read with a bounds check (`v` is the caller's);
//! - a non-negative `O[]` value;
//! - `next` or `prev` of one of the above.
//!
//! The first two are below the number of half-edges `n` by the checked ranges. The third is
//! below `n` too, because `n` is a multiple of 3 and `next`/`prev` stay inside their triangle.
//! So the reads of `O[]` and `V[]` need no bounds check. Reads of `G[]` (positions) stay
//! checked.
//!
//! Counted with callgrind on the harness's kernels over a torus, dropping the bounds checks
//! lowered the instructions per vertex of che-l2's R00 sweep and of the smoothing workload.
//! See "Speed" in the [module docs](super) for how the time this gained was measured and for
//! what the other structures were offered (the trait's fairness rule).

#![allow(unsafe_code)]

use super::{next, prev};
use crate::core::ids::{HalfEdgeId, VertexId};
use crate::core::reads::{read, traced};

/// Do `V[]`, `O[]` and `VH[]` hold only ids in range, which is what [`Fan`] needs?
///
/// - `V[]` and `O[]` both have `n` entries, one per half-edge, and `n` is a multiple of 3.
///   So `next` and `prev` of an id below `n` are also below `n`.
/// - `n` fits in `i32`.
/// - Every `O[he]` and every `VH[v]` is negative (boundary or unused) or below `n`.
///
/// One pass over `O[]` and `VH[]`.
pub(crate) fn ranges_hold(v: &[u32], o: &[i32], vh: &[i32]) -> bool {
    let n = o.len();
    let Ok(limit) = i32::try_from(n) else {
        return false;
    };
    // `fold` with `max` rather than `all`, so the compiler vectorises the pass.
    let below = |xs: &[i32]| xs.iter().fold(i32::MIN, |m, &x| m.max(x)) < limit;
    v.len() == n && n.is_multiple_of(3) && below(o) && below(vh)
}

/// `V[]`, `O[]` and `VH[]` of a CHE whose ranges hold ([`ranges_hold`]). Its walk reads
/// `V[]` and `O[]` without bounds checks.
#[derive(Copy, Clone)]
pub(crate) struct Fan<'a> {
    v: &'a [u32],
    o: &'a [i32],
    vh: &'a [i32],
}

impl<'a> Fan<'a> {
    /// The walk over these arrays.
    ///
    /// # Safety
    ///
    /// [`ranges_hold`]`(v, o, vh)` must be true. Checking it here would cost a pass over the
    /// arrays on every query; [`CheL2`](super::CheL2) checks it once when it is built.
    #[inline(always)]
    pub(crate) unsafe fn new_unchecked(v: &'a [u32], o: &'a [i32], vh: &'a [i32]) -> Self {
        // The length conditions are cheap enough to check in debug builds.
        debug_assert!(v.len() == o.len() && o.len().is_multiple_of(3));
        Self { v, o, vh }
    }

    /// `O[he]`, where `he` is below the number of half-edges (see the module docs for why
    /// every caller's `he` is).
    #[inline(always)]
    fn o(self, he: HalfEdgeId) -> i32 {
        debug_assert!(he.index() < self.o.len());
        // SAFETY: `he` is `VH[v] >= 0`, a non-negative `O[]` value, or `next`/`prev` of one,
        // all below `o.len()` because `ranges_hold` was true when this `Fan` was made.
        let x = unsafe { *self.o.get_unchecked(he.index()) };
        traced!("O", he.index(), x);
        x
    }

    /// `V[he]`, for an `he` as in [`Fan::o`]; `V[]` has the same length as `O[]`.
    #[inline(always)]
    fn v(self, he: HalfEdgeId) -> VertexId {
        debug_assert!(he.index() < self.v.len());
        // SAFETY: as in `o`, and `v.len() == o.len()` by `ranges_hold`.
        let x = unsafe { *self.v.get_unchecked(he.index()) };
        traced!("V", he.index(), x);
        VertexId(x)
    }

    /// `VH[v]`, bounds-checked because `v` is the caller's; `None` for an unused vertex.
    #[inline(always)]
    fn start(self, v: VertexId) -> Option<HalfEdgeId> {
        let he = read!("VH", self.vh, v.index());
        (he >= 0).then_some(HalfEdgeId(he as u32))
    }

    /// Is `v` on the boundary? `O[VH[v]] < 0` (§4.3).
    #[inline(always)]
    pub(crate) fn on_boundary(self, v: VertexId) -> bool {
        self.start(v).is_some_and(|he| self.o(he) < 0)
    }

    /// The far end `V[e]` of a spoke entering the vertex.
    #[inline(always)]
    pub(crate) fn far_end(self, e: HalfEdgeId) -> VertexId {
        self.v(e)
    }

    /// The far end of the lone spoke of a boundary vertex, the boundary half-edge `b` leaving
    /// it (what [`Fan::spokes`] returns): `V[next(b)]`.
    #[inline(always)]
    pub(crate) fn lone_far_end(self, b: HalfEdgeId) -> VertexId {
        self.v(next(b))
    }

    /// The spokes of `v`'s star, the edges from `v` to its neighbours. Calls `spoke(e, O[e])`
    /// once for each spoke that has a half-edge `e` entering `v`. If `v` is on the boundary,
    /// returns the boundary half-edge leaving `v` (`VH[v]`): that spoke has no entering
    /// half-edge. An unused vertex has no spokes.
    ///
    /// Each spoke is reported by the half-edge `e` that enters `v`. Its far end is `V[e]`
    /// and its edge is `min(e, O[e])`, both read at the index where the walk reads `O[e]`.
    /// Each triangle of the star is the triangle of exactly one reported `e`.
    ///
    /// An interior star is walked from both ends at once until the two ends meet: forward
    /// `h ← O[prev(h)]` (Algorithm 7's step) and backward `g ← next(O[g])`. That is two
    /// independent chains of dependent loads instead of one. A boundary star is walked
    /// forward only, as Algorithm 7 walks it ([`fan_walk_algorithm_7`](super::fan_walk_algorithm_7)
    /// keeps that order for teaching); its `VH[v]` is one end, and the other end is not
    /// stored. The spokes come in neither walk's cyclic order.
    #[inline(always)]
    pub(crate) fn spokes(
        self,
        v: VertexId,
        mut spoke: impl FnMut(HalfEdgeId, i32),
    ) -> Option<HalfEdgeId> {
        let start = self.start(v)?;
        let mut back = self.o(start);
        let mut h = start;
        if back < 0 {
            loop {
                let e = prev(h);
                let x = self.o(e);
                spoke(e, x);
                if x < 0 {
                    return Some(start);
                }
                h = HalfEdgeId(x as u32);
            }
        }
        // `f` is the next spoke to report forward (entering the vertex, `prev` of a
        // half-edge leaving it), `b` the next to report backward (`O[g]` of the half-edge
        // `g` leaving the vertex); the spokes from `f` round to `b` are not reported yet.
        let mut f = prev(start);
        let mut b = HalfEdgeId(back as u32);
        let mut g = start;
        loop {
            let x = self.o(f);
            spoke(f, x);
            if f == b {
                return None;
            }
            spoke(b, g.0 as i32);
            g = next(b);
            f = prev(HalfEdgeId(x as u32));
            if f == b {
                return None;
            }
            back = self.o(g);
            b = HalfEdgeId(back as u32);
        }
    }
}

/// R00, R01 and R02 over [`Fan::spokes`], for the mapped CHE once its file is verified
/// ([`MappedChe`](super::MappedChe)). [`CheL2`](super::CheL2)'s relations compose the walk in
/// the same way in their own bodies, left as they were timed.
impl Fan<'_> {
    /// R00: each spoke's far end, and the lone spoke's at a boundary vertex.
    #[inline(always)]
    pub(crate) fn neighbours(self, v: VertexId, mut f: impl FnMut(VertexId)) {
        if let Some(b) = self.spokes(v, |e, _| f(self.far_end(e))) {
            f(self.lone_far_end(b));
        }
    }

    /// R01: each spoke's edge `min(e, O[e])`, and the lone spoke's.
    #[inline(always)]
    pub(crate) fn spoke_edges(self, v: VertexId, mut f: impl FnMut(crate::core::ids::EdgeId)) {
        let lone = self.spokes(v, |e, o| {
            f(crate::core::ids::EdgeId(if o < 0 {
                e.0
            } else {
                e.0.min(o as u32)
            }))
        });
        if let Some(b) = lone {
            f(crate::core::ids::EdgeId(b.0));
        }
    }

    /// R02: the triangle of each entering half-edge.
    #[inline(always)]
    pub(crate) fn star_triangles(self, v: VertexId, mut f: impl FnMut(crate::core::ids::FaceId)) {
        self.spokes(v, |e, _| f(super::triangle(e)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn next_and_prev_stay_in_the_triangle_as_its_remainders_say() {
        // §4.1 by remainder, against the divisibility and two-candidate forms the walk runs,
        // near 0 and near the largest half-edge id `ranges_hold` lets through (below i32::MAX).
        let top = i32::MAX as u32 - 1;
        for h in (0..300).chain(top - 300..=top) {
            let base = h - h % 3;
            let (n, p) = (next(HalfEdgeId(h)).0, prev(HalfEdgeId(h)).0);
            assert_eq!(n, base + (h % 3 + 1) % 3, "next({h})");
            assert_eq!(p, base + (h % 3 + 2) % 3, "prev({h})");
        }
    }

    #[test]
    fn ranges_hold_only_for_ids_below_the_half_edge_count() {
        // One triangle: half-edges 0, 1, 2 over vertices 0, 1, 2, all on the boundary.
        let v = [0, 1, 2];
        assert!(ranges_hold(&v, &[-1, -1, -1], &[0, 1, 2]));
        assert!(
            ranges_hold(&v, &[-1, -3, -2], &[0, -1, 2]),
            "labels and unused"
        );
        assert!(
            !ranges_hold(&v, &[3, -1, -1], &[0, 1, 2]),
            "O[] past the end"
        );
        assert!(
            !ranges_hold(&v, &[-1, -1, -1], &[0, 1, 3]),
            "VH[] past the end"
        );
        assert!(
            !ranges_hold(&v[..2], &[-1, -1], &[0, 1]),
            "not whole triangles"
        );
        assert!(
            !ranges_hold(&v[..2], &[-1, -1, -1], &[0, 1]),
            "V[] shorter than O[]"
        );
        assert!(
            ranges_hold(&[], &[], &[-1]),
            "an empty mesh with an unused vertex"
        );
    }
}
