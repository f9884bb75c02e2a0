//! The outside libraries' hulls in the benchmark: each library this build of
//! `topolab-baselines` has ([`HullLibrary::compiled_in`]: Qhull in-process, CGAL's
//! `convex_hull_3`) gets a row for every point set of the lecture's randomized algorithm, right
//! after that point set's rows.

use super::bench::{self, HullRow};
use topolab_baselines::hulls::{HullLibrary, OutsideHull};

/// Adds the rows of every outside hull library compiled in to `rows` (see the module docs);
/// without them, nothing (the report's notes say why).
pub fn add_outside_hulls(rows: &mut Vec<HullRow>) -> Result<(), String> {
    for library in HullLibrary::ALL.into_iter().filter(|l| l.compiled_in()) {
        add_rows(library, rows)?;
    }
    Ok(())
}

/// Adds `library`'s row for every point set of the randomized algorithm in `rows`: the same
/// points ([`bench::PointSet::points`]), timed as the lab's hulls are ([`bench::warm_median`]:
/// a warm-up run, then the median of [`bench::timed_runs`] runs of one call each, the library's
/// own clock). Its hull must have the randomized hull's vertices (random points are in general
/// position, and both keep only corner points: the same count and, where both have it, the
/// same [`bench::vertex_checksum`]) and be a closed triangulated surface, in every run; else an
/// error naming the point set.
pub fn add_rows(library: HullLibrary, rows: &mut Vec<HullRow>) -> Result<(), String> {
    let name = library.name();
    for set in bench::point_sets(rows) {
        let points = set.points().map_err(|e| e.to_string())?;
        let what = format!("{name}'s hull of {} points {}", set.n, set.shape);
        let timed = bench::warm_median(set.n, |_warm_up| {
            let hull = library.hull(&points).map_err(|e| format!("{what}: {e}"))?;
            Ok::<_, String>((hull.seconds, hull))
        })?;
        for hull in [&timed.warm_up, &timed.last] {
            check(&what, &set, hull)?;
        }
        eprintln!(
            "topolab report: hull {} {} {name}: {:.3} s",
            set.shape, set.n, timed.seconds
        );
        let row = HullRow {
            hull_vertices: timed.last.vertices,
            vertex_checksum: checksum(&timed.last),
            ..set.outside_row(name, &timed)
        };
        bench::insert_outside_row(rows, row);
    }
    Ok(())
}

/// The [`bench::vertex_checksum`] of `hull`'s vertices, when the library returned their ids.
fn checksum(hull: &OutsideHull) -> Option<u64> {
    let ids = hull.vertex_ids.as_ref()?;
    Some(bench::vertex_checksum(ids.iter().copied()))
}

/// Does `hull` agree with the randomized algorithm's hull of `set`, and is it closed and
/// triangulated?
fn check(what: &str, set: &bench::PointSet, hull: &OutsideHull) -> Result<(), String> {
    let checksum = checksum(hull);
    let differs = match (checksum, set.vertex_checksum) {
        (Some(a), Some(b)) => a != b,
        _ => false,
    };
    if hull.vertices != set.hull_vertices || differs {
        return Err(format!(
            "{what}: {} vertices (checksum {checksum:x?}), the randomized algorithm's {} (checksum {:x?})",
            hull.vertices, set.hull_vertices, set.vertex_checksum
        ));
    }
    if !hull.closed_triangles {
        return Err(format!(
            "{what}: {} vertices, not a closed triangulated surface",
            hull.vertices
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::hull::{convex_hull, random_points, Algorithm, Shape};

    /// The row of `algorithm` on the benchmark's ball of `n` points, with the randomized
    /// algorithm's hull vertices and checksum.
    fn row(algorithm: &str, n: usize) -> HullRow {
        let points = random_points(Shape::Ball, n, bench::POINTS_SEED);
        let hull = convex_hull(&points, Algorithm::Randomized { seed: 7 }).unwrap();
        let vertices = hull.vertices();
        HullRow {
            shape: "ball".into(),
            n,
            algorithm: algorithm.into(),
            hull_vertices: vertices.len(),
            vertex_checksum: Some(bench::vertex_checksum(vertices.iter().map(|v| v.0))),
            ..HullRow::default()
        }
    }

    #[test]
    fn outside_rows_follow_their_point_sets_and_must_have_the_randomized_hulls_vertices() {
        for library in HullLibrary::ALL {
            if !library.compiled_in() {
                println!("SKIPPED {}: not compiled in", library.name());
                continue;
            }
            let mut rows = vec![
                row("gift", 500),
                row("randomized", 500),
                row("randomized", 900),
            ];
            add_rows(library, &mut rows).unwrap();
            let names: Vec<(&str, usize)> =
                rows.iter().map(|r| (r.algorithm.as_str(), r.n)).collect();
            let name = library.name();
            assert_eq!(
                names,
                [
                    ("gift", 500),
                    ("randomized", 500),
                    (name, 500),
                    ("randomized", 900),
                    (name, 900)
                ]
            );
            let q = &rows[2];
            assert_eq!((q.hull_vertices, q.timed_runs), (rows[1].hull_vertices, 3));
            if library == HullLibrary::Qhull {
                assert_eq!(q.vertex_checksum, rows[1].vertex_checksum);
            }
            assert!(q.seconds > 0.0 && q.faces_created.is_none() && q.peak_bytes.is_none());
            // A hull that disagrees stops the benchmark with an error naming the point set.
            let mut fewer = vec![row("randomized", 500)];
            fewer[0].hull_vertices -= 1;
            let e = add_rows(library, &mut fewer).unwrap_err();
            assert!(e.contains("500 points ball"), "{e}");
        }
    }

    #[test]
    fn qhull_must_have_the_randomized_hulls_vertex_set() {
        if !HullLibrary::Qhull.compiled_in() {
            println!("SKIPPED: Qhull not compiled in");
            return;
        }
        // Another vertex set of the same size stops the benchmark.
        let mut wrong = vec![row("randomized", 500)];
        wrong[0].vertex_checksum = wrong[0].vertex_checksum.map(|c| c ^ 1);
        let e = add_rows(HullLibrary::Qhull, &mut wrong).unwrap_err();
        assert!(e.contains("qhull's hull of 500 points ball"), "{e}");
    }
}
