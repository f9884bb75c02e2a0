//! A face's plane prepared once for many visibility tests: the lecture's `Volume6(f, p)`
//! with the face fixed, in floating point first and exactly only when that is uncertain.
//!
//! `Volume6(a, b, c, p)` is the negated `orient3d(a, b, c, p)`, the determinant of the rows
//! a − p, b − p, c − p, which equals the determinant of the rows a − p, b − a, c − a.
//! Expanded along its first row it is (a − p) · n with n = (b − a) × (c − a): the face's
//! part, n and the magnitudes of its products, is computed once per face, and each point
//! costs one difference, two dot products and a comparison.
//!
//! The comparison is the first stage of Shewchuk's adaptive `orient3d` ("Adaptive Precision
//! Floating-Point Arithmetic and Fast Robust Geometric Predicates"): the determinant is
//! computed in floating point from the rounded differences, and its sign is certain when
//! its magnitude exceeds (7 + 56ε)ε times the permanent (the same expression with every
//! product and difference replaced by its absolute value). The bound holds for any 3 × 3
//! determinant of rounded coordinate differences evaluated as a sum of three terms, each a
//! difference times a difference of two products; this expansion is the transpose of the
//! one Shewchuk bounds, with the same rounding steps. When the bound does not settle the
//! sign, the exact predicate decides ([`super::predicates::volume6`]). Overflowing inputs
//! make the bound infinite or NaN and also fall through to it.
//!
//! [`RoundedPlane`] goes one step further for the conflict lists, where one face is tested
//! against many points: one bound per face for every point within a given reach of the
//! origin (the permanent is monotone in the point's differences), widened by the rounding of
//! the points to `f32`, so a test costs one difference, one dot product and one comparison,
//! and a list entry is 16 bytes. Monotone: the bound of a point is at most the face's.

use super::predicates::volume6;
use glam::DVec3;

/// Half an ulp of 1.0 (Shewchuk's ε, the unit roundoff of round-to-nearest doubles).
const EPSILON: f64 = f64::EPSILON * 0.5;
/// Shewchuk's first-stage error bound factor for `orient3d`.
const ERROR_BOUND: f64 = (7.0 + 56.0 * EPSILON) * EPSILON;
/// The unit roundoff of `f32` (2⁻²⁴), with room for the rounding of the bound itself.
const F32_BOUND: f64 = (1.0 + 1.0 / (1u64 << 20) as f64) / (1u64 << 24) as f64;
/// Coordinates whose magnitude is 0 or in [2⁻¹⁰⁰, 2¹⁰⁰] round to a normal `f32` within
/// 2⁻²⁴ relative; [`round_to_f32`] marks the others.
const F32_SAFE: std::ops::RangeInclusive<f64> = 1.0 / (1u128 << 100) as f64..=(1u128 << 100) as f64;

/// The face (a, b, c), counter-clockwise seen from outside, ready for [`FacePlane::volume6`].
#[derive(Copy, Clone, Debug)]
pub struct FacePlane {
    a: DVec3,
    b: DVec3,
    c: DVec3,
    /// (b − a) × (c − a), in floating point from the rounded differences.
    normal: DVec3,
    /// Per component, the sum of the magnitudes of the two products behind `normal`.
    magnitude: DVec3,
}

/// How many visibility tests ran and how many the filter left to exact arithmetic.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct TestCount {
    /// Tests.
    pub tests: u64,
    /// Tests decided by the exact predicate.
    pub exact: u64,
}

impl FacePlane {
    /// The plane of the face (a, b, c).
    #[inline]
    pub fn new(a: DVec3, b: DVec3, c: DVec3) -> Self {
        let (u, v) = (b - a, c - a);
        let products = |i: usize, j: usize| (u[i] * v[j], u[j] * v[i]);
        let (x, y, z) = (products(1, 2), products(2, 0), products(0, 1));
        FacePlane {
            a,
            b,
            c,
            normal: DVec3::new(x.0 - x.1, y.0 - y.1, z.0 - z.1),
            magnitude: DVec3::new(
                x.0.abs() + x.1.abs(),
                y.0.abs() + y.1.abs(),
                z.0.abs() + z.1.abs(),
            ),
        }
    }

    /// `Volume6(a, b, c, p)`: positive when p sees the face, zero when p is in its plane,
    /// negative below. The sign is exact (see the module docs); `count` records the test.
    #[inline]
    pub fn volume6(&self, p: DVec3, count: &mut TestCount) -> f64 {
        count.tests += 1;
        let d = self.a - p;
        // orient3d's determinant, the negated Volume6.
        let det = d.x * self.normal.x + d.y * self.normal.y + d.z * self.normal.z;
        let permanent = d.x.abs() * self.magnitude.x
            + d.y.abs() * self.magnitude.y
            + d.z.abs() * self.magnitude.z;
        let bound = ERROR_BOUND * permanent;
        if det > bound || -det > bound {
            return -det;
        }
        count.exact += 1;
        volume6(self.a, self.b, self.c, p)
    }

    /// Does p see the face (`Volume6 > 0`)? Exact.
    #[inline]
    pub fn is_seen_from(&self, p: DVec3, count: &mut TestCount) -> bool {
        self.volume6(p, count) > 0.0
    }

    /// The face ready for points rounded to `f32` ([`round_to_f32`]) whose coordinates
    /// are all at most `reach` in magnitude: see [`RoundedPlane`].
    pub fn for_rounded_points(self, reach: f64) -> RoundedPlane {
        // |a_k − q_k| computed is at most |a_k| + reach computed (rounding is monotone), so
        // these bound the permanent of every such point, and reach · magnitude the move.
        let (a, m) = (self.a.abs(), self.magnitude);
        let permanent = (a.x + reach) * m.x + (a.y + reach) * m.y + (a.z + reach) * m.z;
        let moved = reach * m.x + reach * m.y + reach * m.z;
        RoundedPlane {
            plane: self,
            bound: ERROR_BOUND * permanent + F32_BOUND * moved,
        }
    }
}

/// A face's plane with one error bound for every point of a set, given rounded to `f32`:
/// the conflict lists' test, where a point costs one difference, one dot product and one
/// comparison. The bound adds two things to Shewchuk's first stage: the permanent of any
/// point within `reach` of the origin per coordinate, and the rounding of the point to
/// `f32` (the determinant is linear in the point with gradient −n, so moving it by at most
/// 2⁻²⁴|q_k| per coordinate moves it by at most 2⁻²⁴ Σ|q_k| |n_k|, with |q_k| ≤ `reach`
/// and |n_k| ≤ `magnitude[k]` (1 + 5ε)). Points the bound cannot settle, and marked points
/// (NaN), go to the exact predicate with their true coordinates.
#[derive(Copy, Clone, Debug)]
pub struct RoundedPlane {
    plane: FacePlane,
    bound: f64,
}

impl RoundedPlane {
    /// Does the point `rounded` ([`round_to_f32`] of a point given by `exact`, with
    /// coordinates within the `reach` of [`FacePlane::for_rounded_points`]) see the face?
    /// Exact.
    #[inline]
    pub fn is_seen_from(
        &self,
        rounded: [f32; 3],
        exact: impl FnOnce() -> DVec3,
        count: &mut TestCount,
    ) -> bool {
        count.tests += 1;
        let p = &self.plane;
        let q = DVec3::new(rounded[0].into(), rounded[1].into(), rounded[2].into());
        let d = p.a - q;
        let det = d.x * p.normal.x + d.y * p.normal.y + d.z * p.normal.z;
        if det > self.bound || -det > self.bound {
            return det < 0.0;
        }
        count.exact += 1;
        volume6(p.a, p.b, p.c, exact()) > 0.0
    }
}

impl RoundedPlane {
    /// Does the point p (not rounded), with coordinates within `reach`, see the face?
    /// Exact: the bound holds a fortiori for a point that was not rounded.
    #[inline]
    pub fn is_seen_from_point(&self, p: DVec3, count: &mut TestCount) -> bool {
        count.tests += 1;
        let f = &self.plane;
        let d = f.a - p;
        let det = d.x * f.normal.x + d.y * f.normal.y + d.z * f.normal.z;
        if det > self.bound || -det > self.bound {
            return det < 0.0;
        }
        count.exact += 1;
        volume6(f.a, f.b, f.c, p) > 0.0
    }
}

/// The largest magnitude of the coordinates of `rounded` (from [`round_to_f32`]; marked
/// points are skipped, they are always tested exactly): the `reach` of
/// [`FacePlane::for_rounded_points`].
pub fn reach(rounded: &[[f32; 3]]) -> f64 {
    rounded
        .iter()
        .flatten()
        .map(|x| f64::from(x.abs()))
        .filter(|x| !x.is_nan())
        .fold(0.0, f64::max)
}

/// p's coordinates rounded to `f32`, for [`RoundedPlane`]; NaN (so that
/// every test of p is exact) if a coordinate is outside the range where the rounding error
/// is at most 2⁻²⁴ of its magnitude (nonzero below 2⁻¹⁰⁰ or above 2¹⁰⁰).
pub fn round_to_f32(p: DVec3) -> [f32; 3] {
    let safe = p
        .to_array()
        .iter()
        .all(|&x| x == 0.0 || F32_SAFE.contains(&x.abs()));
    if safe {
        [p.x as f32, p.y as f32, p.z as f32]
    } else {
        [f32::NAN; 3]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    /// The filtered sign always equals the exact one, on random points, on points exactly
    /// in the plane (grids) and on points a few ulps off it, where the filter must give up.
    #[test]
    fn the_filtered_sign_is_the_exact_sign() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(4);
        let random = |rng: &mut rand_chacha::ChaCha8Rng| {
            DVec3::new(rng.random(), rng.random(), rng.random())
        };
        let mut count = TestCount::default();
        let (a, b, c) = (random(&mut rng), random(&mut rng), random(&mut rng));
        let plane = FacePlane::new(a, b, c);
        let mut near = 0;
        for i in 0..20_000 {
            let p = match i % 4 {
                0 => random(&mut rng),
                // On the plane up to rounding: a + s (b − a) + t (c − a), nudged by ulps.
                _ => {
                    let (s, t): (f64, f64) = (rng.random(), rng.random());
                    let q = a + s * (b - a) + t * (c - a);
                    let ulps = (i % 7) as f64 - 3.0;
                    near += 1;
                    q + DVec3::splat(ulps * f64::EPSILON * q.abs().max_element())
                }
            };
            let filtered = plane.volume6(p, &mut count);
            let exact = volume6(a, b, c, p);
            assert_eq!(filtered.signum(), exact.signum(), "{p:?}");
            assert_eq!(filtered == 0.0, exact == 0.0, "{p:?}");
        }
        assert_eq!(count.tests, 20_000);
        // The filter settles the random points and hands points near the plane over.
        assert!(count.exact > 0 && count.exact <= near, "{count:?}");
        let mut grid = TestCount::default();
        let flat = FacePlane::new(DVec3::ZERO, DVec3::X, DVec3::Y);
        for x in -2..=2 {
            for y in -2..=2 {
                let p = DVec3::new(x as f64, y as f64, 0.0);
                assert_eq!(flat.volume6(p, &mut grid), 0.0);
            }
        }
        assert!(flat.is_seen_from(DVec3::Z, &mut grid));
        assert!(!flat.is_seen_from(-DVec3::Z, &mut grid));
    }

    /// From coordinates rounded to `f32`, the answer is still the exact one for the true
    /// point: near the plane (where the rounding moves points across it) the filter gives up.
    #[test]
    fn the_rounded_test_answers_for_the_true_point() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(9);
        let random = |rng: &mut rand_chacha::ChaCha8Rng| {
            DVec3::new(rng.random(), rng.random(), rng.random())
        };
        let (a, b, c) = (random(&mut rng), random(&mut rng), random(&mut rng));
        let mut count = TestCount::default();
        let mut crossed = 0;
        let mut close = 0;
        let mut points = Vec::new();
        for i in 0..30_000 {
            let p = if i % 3 == 0 {
                random(&mut rng)
            } else {
                // Off the plane by 1e-9 (within f32 rounding: the rounded point may sit on
                // the other side) or by 1e-4 (clear of it, for the filter to decide).
                let (s, t): (f64, f64) = (rng.random(), rng.random());
                let q = a + s * (b - a) + t * (c - a);
                let off = if i % 3 == 1 { 1e-9 } else { 1e-4 };
                close += usize::from(i % 3 == 1);
                let sign = if rng.random::<bool>() { 1.0 } else { -1.0 };
                q + (b - a).cross(c - a).normalize() * sign * (1.0 + rng.random::<f64>()) * off
            };
            points.push(p);
        }
        let rounded: Vec<[f32; 3]> = points.iter().map(|&p| round_to_f32(p)).collect();
        let plane = FacePlane::new(a, b, c).for_rounded_points(reach(&rounded));
        for (&p, &r) in points.iter().zip(&rounded) {
            let exact = volume6(a, b, c, p) > 0.0;
            let moved = DVec3::new(r[0].into(), r[1].into(), r[2].into());
            crossed += usize::from((volume6(a, b, c, moved) > 0.0) != exact);
            assert_eq!(plane.is_seen_from(r, || p, &mut count), exact, "{p:?}");
        }
        assert!(
            crossed > 0,
            "the test must include points the rounding moves across"
        );
        assert!(
            count.exact >= crossed as u64 && count.exact <= close as u64,
            "{count:?}, {crossed} crossed, {close} close"
        );
        // Coordinates f32 cannot hold closely enough are always tested exactly.
        for p in [DVec3::new(1e-200, 0.5, 0.5), DVec3::new(0.5, 1e200, 0.5)] {
            assert!(round_to_f32(p)[0].is_nan());
            let before = count.exact;
            let exact = volume6(a, b, c, p) > 0.0;
            assert_eq!(plane.is_seen_from(round_to_f32(p), || p, &mut count), exact);
            assert_eq!(count.exact, before + 1);
        }
        assert_eq!(round_to_f32(DVec3::new(0.0, -0.25, 3.0)), [0.0, -0.25, 3.0]);
    }
}
