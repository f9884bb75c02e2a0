//! The hull benchmark shared by the report and `examples/hull_bench.rs`: each algorithm (and
//! Qhull, when SciPy is there) on random points of one shape at growing n, with the faces
//! each algorithm creates against the expected bound 6n − 20 of the lecture on 3D convex
//! hulls.

use super::qhull;
use glam::DVec3;
use std::path::Path;
use std::time::Instant;
use topolab_structures::hull::{convex_hull, random_points, Algorithm, Shape};
use topolab_structures::Result;

/// One timed hull. (`Default`, so that a row of an outside hull, such as CGAL's, names only
/// what it has.)
#[derive(Clone, Debug, Default, serde::Serialize)]
pub struct HullRow {
    /// `cube`, `ball` or `sphere`.
    pub shape: String,
    /// Number of points.
    pub n: usize,
    /// `gift`, `incremental`, `randomized`, `qhull`, or an outside hull's name (CGAL's
    /// `cgal-convex-hull-3`).
    pub algorithm: String,
    /// Best time of the repetitions, seconds.
    pub seconds: f64,
    /// Faces created during the construction (`None` for Qhull).
    pub faces_created: Option<usize>,
    /// Vertices of the hull.
    pub hull_vertices: usize,
}

/// One benchmark measurement: builds the hull of `points` with `algorithm` and returns
/// `(seconds, faces_created, hull_vertices)`. The time covers the whole call of
/// [`convex_hull`] (input checks and duplicate removal included), measured once with
/// [`Instant`]; repeat and take the best or median in the caller.
pub fn benchmark_row(points: &[DVec3], algorithm: Algorithm) -> Result<(f64, usize, usize)> {
    let start = Instant::now();
    let hull = convex_hull(points, algorithm)?;
    let seconds = start.elapsed().as_secs_f64();
    Ok((seconds, hull.faces_created, hull.vertices().len()))
}

/// Runs the benchmark for `shape` over `sizes` (increasing). Gift wrapping (O(n·h)) and the
/// plain incremental algorithm (O(n²)) stop growing n once one size took more than
/// `max_seconds`; the randomized one always goes on. Each time is the best of 3 runs (1 from
/// 100k points on). `qhull` is `(python, workspace root)`. Every row goes to `progress` too.
pub fn run(
    shape: Shape,
    shape_name: &str,
    sizes: &[usize],
    qhull: Option<(&Path, &Path)>,
    max_seconds: f64,
    mut progress: impl FnMut(&HullRow),
) -> Result<Vec<HullRow>, String> {
    let mut rows = Vec::new();
    let mut too_slow = [false; 3];
    let mut push = |row: HullRow, rows: &mut Vec<HullRow>| {
        progress(&row);
        rows.push(row);
    };
    for &n in sizes {
        let points = random_points(shape, n, 42);
        let repeat = if n >= 100_000 { 1 } else { 3 };
        if let Some((python, root)) = qhull {
            let q = qhull::run(python, root, &points, repeat)?;
            let row = HullRow {
                shape: shape_name.into(),
                n,
                algorithm: "qhull".into(),
                seconds: q.seconds,
                faces_created: None,
                hull_vertices: q.vertices.len(),
            };
            push(row, &mut rows);
        }
        for (a, algorithm) in Algorithm::all(7).into_iter().enumerate() {
            if too_slow[a] {
                continue;
            }
            let mut best = f64::INFINITY;
            let mut last = (0.0, 0, 0);
            for _ in 0..repeat {
                last = benchmark_row(&points, algorithm).map_err(|e| e.to_string())?;
                best = best.min(last.0);
            }
            // The next n is 10 times larger: up to 100 times the time for O(n²).
            too_slow[a] = !matches!(algorithm, Algorithm::Randomized { .. }) && best > max_seconds;
            let row = HullRow {
                shape: shape_name.into(),
                n,
                algorithm: algorithm.name().into(),
                seconds: best,
                faces_created: Some(last.1),
                hull_vertices: last.2,
            };
            push(row, &mut rows);
        }
    }
    Ok(rows)
}
