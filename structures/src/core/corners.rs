//! The corner arithmetic of a triangle mesh stored face by face: triangle `t` owns the corners
//! (half-edges) `3t, 3t+1, 3t+2`, so the next and previous corner of a triangle and the
//! triangle of a corner are arithmetic, not loads (the CHE thesis chapter, §4.1). The CHE
//! answers with them ([`crate::che`] re-exports them under the chapter's names), and the access
//! model's corner step ([`crate::core::access::Step::Corner`]) is `prev` followed by a load:
//! they stand here, below both, so the step is the CHE's own arithmetic and not a copy of it.

use crate::core::ids::{FaceId, HalfEdgeId};

/// `next(he)`: the following half-edge of the same triangle (§4.1).
///
/// `(he + 1) % 3 == 0` is asked as divisibility (`is_multiple_of`), which compiles to a
/// multiply and a compare; written `he % 3 == 2` beside [`prev`]'s test in one loop, the
/// compiler computes one full remainder for both in front of every `O[]` load of a fan walk
/// (see "Speed" in the docs of [`crate::che`]).
#[inline(always)]
pub const fn next(he: HalfEdgeId) -> HalfEdgeId {
    HalfEdgeId(if (he.0 + 1).is_multiple_of(3) {
        he.0 - 2
    } else {
        he.0 + 1
    })
}

/// `prev(he)`: the preceding half-edge of the same triangle (§4.1); a divisibility test, as
/// in [`next`].
///
/// Written as a choice between `he + 2` and `he - 1`, the two candidates, so that the compiler
/// computes both beside the test and picks one with a conditional move: a multiply, a compare
/// and the move on the fan walk's chain. Written `he + 2` or `he - 1` by whether 3 divides
/// `he` (the same definition), it added `-1` or `2` to `he` after the test instead, two more
/// dependent instructions before every `O[]` load of the forward walk (see "Speed" in the docs of
/// [`crate::che`]).
#[inline(always)]
pub const fn prev(he: HalfEdgeId) -> HalfEdgeId {
    let later = he.0 + 2;
    HalfEdgeId(if later % 3 == 2 { later } else { later - 3 })
}

/// The triangle `⌊he/3⌋` that owns half-edge `he` (§4.1).
#[inline(always)]
pub const fn triangle(he: HalfEdgeId) -> FaceId {
    FaceId(he.0 / 3)
}
