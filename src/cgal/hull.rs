//! `CGAL::convex_hull_3` (CGAL's quickhull, with the `Exact_predicates_inexact_constructions_kernel`:
//! exact orientation tests on the input doubles, as the lab's hulls use Shewchuk's `orient3d`)
//! into a `Surface_mesh`, through `cgal/hull.cpp`: [`convex_hull_3`] for one point set, and
//! [`add_to_benchmark`] for the report's hull section, beside the lecture's three algorithms
//! and Qhull (`crate::qhull`).

use super::{ffi, status};
use glam::DVec3;
use topolab_harness::hull::bench::{self, HullRow};
use topolab_structures::Result;

/// The name of CGAL's rows in the hull benchmark ([`HullRow::algorithm`]).
pub const ALGORITHM: &str = "cgal-convex-hull-3";

/// What `CGAL::convex_hull_3` built.
#[derive(Clone, Debug, PartialEq)]
pub struct CgalHull {
    /// Best time of the `convex_hull_3` call alone, seconds (input checks, copies and the
    /// volume not included; the clock is read inside the shim).
    pub seconds: f64,
    /// Vertices of the hull.
    pub vertices: usize,
    /// Faces of the hull (triangles).
    pub faces: usize,
    /// Every face a triangle and no border: a closed triangulated surface.
    pub closed_triangles: bool,
    /// The enclosed volume (signed tetrahedra from the origin, as the lab's hulls sum it).
    pub volume: f64,
}

/// The convex hull of `points` by `CGAL::convex_hull_3`, timed over `repeat` runs (at least
/// one). The input is checked first the way the lab's hull algorithms check it
/// ([`topolab_structures::hull::predicates::prepare`]): NaN or infinite coordinates, more
/// points than `u32` counts, and points whose hull is not a solid are the same typed errors.
pub fn convex_hull_3(points: &[DVec3], repeat: u32) -> Result<CgalHull> {
    topolab_structures::hull::predicates::prepare(points)?;
    let (mut seconds, mut counts, mut volume) = (0.0, [0u32; 3], 0.0);
    // SAFETY: `points` are 3 contiguous f64 each (DVec3 is repr(C), size asserted in
    // `foreign`), their count fits u32 (`prepare` checked it); the out-pointers are valid and
    // `counts` has the 3 slots the shim fills.
    let code = unsafe {
        ffi::topolab_cgal_convex_hull(
            points.as_ptr().cast::<f64>(),
            points.len() as u32,
            repeat,
            &mut seconds,
            counts.as_mut_ptr(),
            &mut volume,
        )
    };
    status("topolab_cgal_convex_hull", code)?;
    Ok(CgalHull {
        seconds,
        vertices: counts[0] as usize,
        faces: counts[1] as usize,
        closed_triangles: counts[2] != 0,
        volume,
    })
}

/// Adds a row of `CGAL::convex_hull_3` to the hull benchmark `rows` for every point set of
/// the lecture's randomized algorithm in them, right after that point set's rows: the same
/// points ([`bench::PointSet::points`]), timed the same way ([`bench::warm_median`]: a warm-up
/// run, then the median of [`bench::timed_runs`] runs of one [`convex_hull_3`] call each, the
/// call alone). CGAL's hull must have the randomized hull's vertex count (random points are in
/// general position, and both hulls keep only corner points), else an error naming the point
/// set; so must it be closed and triangulated.
pub fn add_to_benchmark(rows: &mut Vec<HullRow>) -> std::result::Result<(), String> {
    for set in bench::point_sets(rows) {
        let points = set.points().map_err(|e| e.to_string())?;
        let timed = bench::warm_median(set.n, |_warm_up| {
            let hull = convex_hull_3(&points, 1).map_err(|e| e.to_string())?;
            Ok::<_, String>((hull.seconds, hull))
        })?;
        let hull = &timed.last;
        if hull.vertices != set.hull_vertices || !hull.closed_triangles {
            return Err(format!(
                "CGAL's convex_hull_3 of {} points {}: {} hull vertices{}, the randomized algorithm {}",
                set.n,
                set.shape,
                hull.vertices,
                if hull.closed_triangles { "" } else { " (not a closed triangulated surface)" },
                set.hull_vertices
            ));
        }
        eprintln!(
            "topolab report: hull {} {} {ALGORITHM}: {:.3} s",
            set.shape, set.n, timed.seconds
        );
        let row = HullRow {
            hull_vertices: hull.vertices,
            ..set.outside_row(ALGORITHM, &timed)
        };
        bench::insert_outside_row(rows, row);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::hull::{convex_hull, random_points, Algorithm, Shape};

    fn row(algorithm: &str, n: usize, hull_vertices: usize) -> HullRow {
        HullRow {
            shape: "ball".into(),
            n,
            algorithm: algorithm.into(),
            hull_vertices,
            ..HullRow::default()
        }
    }

    #[test]
    fn cgal_rows_follow_their_point_sets_and_must_agree_with_the_randomized_hull() {
        let h = |n| {
            let points = random_points(Shape::Ball, n, bench::POINTS_SEED);
            convex_hull(&points, Algorithm::Randomized { seed: 7 })
                .unwrap()
                .vertices()
                .len()
        };
        let (h1, h2) = (h(500), h(900));
        let mut rows = vec![
            row("gift", 500, h1),
            row("randomized", 500, h1),
            row("randomized", 900, h2),
        ];
        add_to_benchmark(&mut rows).unwrap();
        let names: Vec<(&str, usize)> = rows.iter().map(|r| (r.algorithm.as_str(), r.n)).collect();
        assert_eq!(
            names,
            [
                ("gift", 500),
                ("randomized", 500),
                (ALGORITHM, 500),
                ("randomized", 900),
                (ALGORITHM, 900)
            ]
        );
        assert_eq!(rows[2].hull_vertices, h1);
        assert!(rows[2].seconds > 0.0 && rows[2].faces_created.is_none());
        assert_eq!(rows[2].timed_runs, 3);
        // A hull that disagrees stops the benchmark with an error naming the point set.
        let mut wrong = vec![row("randomized", 500, h1 + 1)];
        let e = add_to_benchmark(&mut wrong).unwrap_err();
        assert!(e.contains("500 points ball"), "{e}");
    }
}
