//! Exact geometric predicates shared by the three hull algorithms, and the input checks.
//!
//! Every orientation test goes through Shewchuk's adaptive exact `orient3d` / `orient2d`
//! (the `robust` crate): the *sign* is exact for any finite doubles, so no input (grids,
//! coplanar or collinear points) can make two tests contradict each other. The value itself
//! is an approximation and is only ever used for its sign.
//!
//! "Any finite doubles" holds only while no operation inside the predicates overflows or
//! underflows (Shewchuk's exactness proof assumes neither). `orient3d` multiplies three
//! coordinate differences: with coordinates near 1e300 the products overflow and the signs
//! come out wrong (the algorithms then broke their own invariants), and with coordinates
//! near 1e-120 they underflow to 0 (four corners of a tetrahedron came out coplanar).
//! [`prepare`] therefore refuses, with [`Error::CoordinateOutOfRange`], a coordinate that is
//! not 0 and not of a magnitude within [`MIN_COORDINATE`, `MAX_COORDINATE`] = [2^-250, 2^250]:
//! - overflow: with |x| ≤ 2^250, a difference is ≤ 2^251, a product of three ≤ 2^753, and the
//!   sums and error bounds of `orient3d` stay far below 2^1023;
//! - underflow: every coordinate of magnitude ≥ 2^-250 is a multiple of 2^-302 (its unit in
//!   the last place), so every difference is too, every product of three is a multiple of
//!   2^-906, and so is every sum and rounded result: a non-zero value stays ≥ 2^-906, and even
//!   its error bound (about 2^-50 times it) stays a normal double (≥ 2^-1022).

use crate::core::error::{Error, Numbering, Result};
use glam::DVec3;
use robust::{Coord, Coord3D};

#[inline]
fn c3(p: DVec3) -> Coord3D<f64> {
    Coord3D {
        x: p.x,
        y: p.y,
        z: p.z,
    }
}

/// The seed's `Volume6(f, p)`: six times the signed volume of the tetrahedron (a, b, c, p).
/// Positive when `p` is on the side from which a, b, c appear counter-clockwise (outside a
/// face a b c oriented outwards: `p` sees the face), zero when the four are coplanar.
/// The sign is exact.
#[inline]
pub fn volume6(a: DVec3, b: DVec3, c: DVec3, p: DVec3) -> f64 {
    // orient3d is positive when p is *below* (a, b, c); the seed's Volume6 is its negation.
    -robust::orient3d(c3(a), c3(b), c3(c), c3(p))
}

/// Are a, b, c on one line? Exact: all three axis projections are collinear.
#[inline]
pub fn collinear(a: DVec3, b: DVec3, c: DVec3) -> bool {
    let projections: [fn(DVec3) -> Coord<f64>; 3] = [
        |p| Coord { x: p.x, y: p.y },
        |p| Coord { x: p.y, y: p.z },
        |p| Coord { x: p.z, y: p.x },
    ];
    projections
        .iter()
        .all(|proj| robust::orient2d(proj(a), proj(b), proj(c)) == 0.0)
}

/// For `w` and `s` on one ray from `a` (checked by the caller), is `s` farther from `a`?
/// Exact: along a line every coordinate is monotone, and comparing floats is exact.
#[inline]
pub fn farther_on_ray(a: DVec3, w: DVec3, s: DVec3) -> bool {
    (0..3).any(|k| (w[k] > a[k] && s[k] > w[k]) || (w[k] < a[k] && s[k] < w[k]))
}

/// The largest coordinate magnitude the predicates take (2^250; see the module docs).
pub const MAX_COORDINATE: f64 = 1.8092513943330656e75;

/// The smallest non-zero coordinate magnitude the predicates take (2^-250).
pub const MIN_COORDINATE: f64 = 5.527147875260445e-76;

/// The checked input of every hull algorithm.
pub struct Prepared {
    /// Input indices of the distinct points: the first occurrence of each position.
    pub distinct: Vec<u32>,
    /// Four distinct points not in one plane, found in the order of `distinct`.
    pub simplex: [u32; 4],
}

/// Checks `points` and removes duplicates: NaN or infinite coordinates give
/// [`Error::NonFiniteCoordinate`], coordinates the exact predicates cannot take (module docs)
/// [`Error::CoordinateOutOfRange`], more than `u32` points [`Error::TooLarge`], and fewer than
/// four distinct points or points all on one plane [`Error::DegeneratePoints`]. Duplicates are
/// allowed: only the first occurrence (smallest index) of a position can be a hull vertex.
pub fn prepare(points: &[DVec3]) -> Result<Prepared> {
    if u32::try_from(points.len()).is_err() {
        return Err(Error::TooLarge {
            what: "points",
            count: points.len() as u64,
        });
    }
    for (vertex, p) in points.iter().enumerate() {
        if let Some(&value) = p.to_array().iter().find(|c| !c.is_finite()) {
            return Err(Error::NonFiniteCoordinate {
                vertex,
                value,
                numbering: Numbering::FromZero,
            });
        }
        if let Some(&value) = p
            .to_array()
            .iter()
            .find(|c| **c != 0.0 && !(MIN_COORDINATE..=MAX_COORDINATE).contains(&c.abs()))
        {
            return Err(Error::CoordinateOutOfRange {
                vertex,
                value,
                min: MIN_COORDINATE,
                max: MAX_COORDINATE,
            });
        }
    }
    let distinct = first_occurrences(points);
    let simplex = find_simplex(points, &distinct)?;
    Ok(Prepared { distinct, simplex })
}

/// The input indices of the first occurrence of each position in `points` (finite), in
/// input order, so every algorithm sees the same sequence. One pass with a hash table of
/// indices (open addressing, at most half full): O(n) expected, reading the points in order;
/// sorting by position instead took n log n comparisons, each reading two points at random
/// (a large share of a randomized hull's time on 1M points). Equal positions are equal as
/// numbers, so −0.0 and 0.0 are one position and hash alike.
fn first_occurrences(points: &[DVec3]) -> Vec<u32> {
    let slots = (2 * points.len()).next_power_of_two().max(16);
    let mask = slots - 1;
    let hash = |p: DVec3| {
        // +0.0 turns −0.0 into 0.0; then a multiply-xorshift mix of the three bit patterns.
        let mut h = 0u64;
        for c in (p + DVec3::ZERO).to_array() {
            h = (h ^ c.to_bits()).wrapping_mul(0x9e37_79b9_7f4a_7c15);
            h ^= h >> 29;
        }
        (h ^ (h >> 32)) as usize & mask
    };
    let mut table = vec![u32::MAX; slots];
    let mut distinct = Vec::with_capacity(points.len());
    for (i, &p) in points.iter().enumerate() {
        let mut slot = hash(p);
        loop {
            match table[slot] {
                u32::MAX => {
                    table[slot] = i as u32;
                    distinct.push(i as u32);
                    break;
                }
                j if points[j as usize] == p => break,
                _ => slot = (slot + 1) & mask,
            }
        }
    }
    distinct
}

/// The first four points of `order` (distinct positions) that span space: the first point,
/// the next one, the first not on their line, the first not on their plane.
pub fn find_simplex(points: &[DVec3], order: &[u32]) -> Result<[u32; 4]> {
    let p = |i: u32| points[i as usize];
    let degenerate = |dimension| Error::DegeneratePoints {
        distinct: order.len(),
        dimension,
    };
    let (&a, &b) = match order {
        [] => return Err(degenerate(0)),
        [_] => return Err(degenerate(0)),
        [a, b, ..] => (a, b),
    };
    let c = *order
        .iter()
        .find(|&&c| !collinear(p(a), p(b), p(c)))
        .ok_or_else(|| degenerate(1))?;
    let d = *order
        .iter()
        .find(|&&d| volume6(p(a), p(b), p(c), p(d)) != 0.0)
        .ok_or_else(|| degenerate(2))?;
    Ok([a, b, c, d])
}

/// The four outward faces (counter-clockwise seen from outside) of the tetrahedron `simplex`.
pub fn tetrahedron_faces(points: &[DVec3], simplex: [u32; 4]) -> [[u32; 3]; 4] {
    let [a, mut b, mut c, d] = simplex;
    let p = |i: u32| points[i as usize];
    if volume6(p(a), p(b), p(c), p(d)) > 0.0 {
        // d sees a b c: turn the base around so d is below it.
        std::mem::swap(&mut b, &mut c);
    }
    [[a, b, c], [a, d, b], [b, d, c], [a, c, d]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn volume6_is_positive_for_a_point_that_sees_the_face() {
        let (a, b, c) = (DVec3::ZERO, DVec3::X, DVec3::Y);
        assert!(volume6(a, b, c, DVec3::Z) > 0.0);
        assert!(volume6(a, b, c, -DVec3::Z) < 0.0);
        assert_eq!(volume6(a, b, c, DVec3::new(5.0, 7.0, 0.0)), 0.0);
    }

    #[test]
    fn collinearity_and_ray_order_are_exact() {
        let a = DVec3::new(0.125, 0.25, 0.375);
        let w = a * 3.0;
        assert!(collinear(DVec3::ZERO, a, w));
        assert!(!collinear(
            DVec3::ZERO,
            a,
            w + DVec3::new(0.0, 2f64.powi(-40), 0.0)
        ));
        assert!(farther_on_ray(DVec3::ZERO, a, w));
        assert!(!farther_on_ray(DVec3::ZERO, w, a));
    }

    #[test]
    fn tetrahedron_faces_see_the_fourth_corner_from_inside() {
        let points = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
        for simplex in [[0, 1, 2, 3], [0, 2, 1, 3]] {
            for f in tetrahedron_faces(&points, simplex) {
                let other = (0..4).find(|i| !f.contains(i)).unwrap();
                let p = |i: u32| points[i as usize];
                assert!(volume6(p(f[0]), p(f[1]), p(f[2]), p(other)) < 0.0, "{f:?}");
            }
        }
    }

    #[test]
    fn first_occurrences_match_a_search_for_an_earlier_equal_point() {
        // Few distinct values, signed zeros among them: many duplicates and collisions.
        let values = [-1.0, -0.0, 0.0, 0.5, 1.0];
        let points: Vec<DVec3> = (0..2000u32)
            .map(|i| {
                let v = |k: u32| values[((i * 7 + k * 13) ^ (i >> 3)) as usize % values.len()];
                DVec3::new(v(0), v(1), v(2))
            })
            .collect();
        let expected: Vec<u32> = (0..points.len())
            .filter(|&i| points[..i].iter().all(|&q| q != points[i]))
            .map(|i| i as u32)
            .collect();
        assert!(expected.len() < points.len() / 10);
        assert_eq!(first_occurrences(&points), expected);
    }

    #[test]
    fn duplicates_keep_their_first_occurrence() {
        let mut points = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
        points.insert(0, DVec3::X);
        let prepared = prepare(&points).unwrap();
        assert_eq!(prepared.distinct, [0, 1, 3, 4]);
    }
}
