//! The checks of each face as a polygon: degenerate, simple, planar, convex.

use super::{FindingKind, Findings, Options};
use crate::core::attributes::NewellSum;
use crate::core::soup::PolygonSoup;
use glam::{DVec2, DVec3};

/// Degenerate, non-simple, non-planar and non-convex faces (triangles are planar, simple and
/// convex unless degenerate).
pub(super) fn polygon_checks(
    soup: &PolygonSoup,
    j: usize,
    options: &Options,
    found: &mut Findings,
) {
    let face = soup.face(j);
    let fid = found.numbering().id(j as u64);
    let points = || face.iter().map(|&v| soup.positions[v as usize]);
    let mut newell = NewellSum::default();
    let (mut lo, mut hi, mut sum) = (DVec3::INFINITY, DVec3::NEG_INFINITY, DVec3::ZERO);
    for p in points() {
        newell.add(p);
        lo = lo.min(p);
        hi = hi.max(p);
        sum += p;
    }
    let area_vector = newell.finish();
    let size = (hi - lo).length();
    let k = face.len();
    // Twice the area over the size: how far the face extends across its longest direction.
    if size == 0.0 || area_vector.length() / size <= options.tolerance {
        found.add(FindingKind::DegenerateFace, || {
            (
                face.to_vec(),
                vec![j as u32],
                format!("face {fid} has (nearly) zero area"),
            )
        });
        return;
    }
    if k == 3 {
        return;
    }
    let normal = area_vector.normalize();
    let centroid = sum / k as f64;
    let off_plane = points()
        .map(|p| normal.dot(p - centroid).abs())
        .fold(0.0, f64::max);
    if off_plane > options.planarity_tolerance * size {
        found.add(FindingKind::NonPlanarFace, || {
            (
                face.to_vec(),
                vec![j as u32],
                format!(
                    "face {fid}: a corner lies {off_plane:.3e} from its plane, more than {} of its size {size:.3e}",
                    options.planarity_tolerance
                ),
            )
        });
    }
    // Project onto the coordinate plane most nearly parallel to the face.
    let drop = normal.abs().max_position();
    let flat = |p: DVec3| {
        let a = p.to_array();
        DVec2::new(a[(drop + 1) % 3], a[(drop + 2) % 3])
    };
    let corner = |i: usize| flat(soup.positions[face[i % k] as usize]);
    let simplicity = (k <= MAX_SIMPLICITY_CORNERS)
        .then(|| self_intersection(k, &corner))
        .flatten();
    if let Some((a, b)) = simplicity {
        found.add(FindingKind::NonSimpleFace, || {
            (
                face.to_vec(),
                vec![j as u32],
                format!("face {fid}: its edges {a} and {b} intersect"),
            )
        });
        return;
    }
    // The lecture's test: the turn at every corner has the same sign (collinear corners,
    // turns within rounding of zero, do not count).
    let turn = |i: usize| (corner(i + 1) - corner(i)).perp_dot(corner(i + 2) - corner(i + 1));
    let flat_turn = 1e-12 * size * size;
    let (left, right) = (0..k).map(turn).fold((false, false), |(l, r), t| {
        (l || t > flat_turn, r || t < -flat_turn)
    });
    if left && right {
        found.add(FindingKind::NonConvexFace, || {
            (
                face.to_vec(),
                vec![j as u32],
                format!("face {fid} turns both left and right: not convex"),
            )
        });
    }
}

/// Faces with more corners are not tested for self-intersection: the pairwise test is
/// O(k²) (a 4096-gon takes about 8 million segment tests).
pub const MAX_SIMPLICITY_CORNERS: usize = 4096;

/// The first pair of edges (edge `i` from corner `i` to `i + 1`) of a closed polygon that meet
/// other than at a shared corner, or adjacent edges that fold back onto each other.
fn self_intersection(k: usize, corner: &impl Fn(usize) -> DVec2) -> Option<(usize, usize)> {
    let orient = |a: DVec2, b: DVec2, c: DVec2| (b - a).perp_dot(c - a);
    let on_segment = |a: DVec2, b: DVec2, p: DVec2| {
        orient(a, b, p) == 0.0 && p.cmpge(a.min(b)).all() && p.cmple(a.max(b)).all()
    };
    for a in 0..k {
        let (p, q) = (corner(a), corner(a + 1));
        // Adjacent edge folding back: the next corner lies on this edge.
        if on_segment(p, q, corner(a + 2)) {
            return Some((a, (a + 1) % k));
        }
        for b in a + 2..k {
            if (b + 1) % k == a {
                continue; // adjacent through the closing corner
            }
            let (r, s) = (corner(b), corner(b + 1));
            let (d1, d2) = (orient(p, q, r), orient(p, q, s));
            let (d3, d4) = (orient(r, s, p), orient(r, s, q));
            let crosses = d1 * d2 < 0.0 && d3 * d4 < 0.0;
            let touches = on_segment(p, q, r)
                || on_segment(p, q, s)
                || on_segment(r, s, p)
                || on_segment(r, s, q);
            if crosses || touches {
                return Some((a, b));
            }
        }
    }
    None
}
