//! The hull benchmark shared by the report and `examples/hull_bench.rs`: each algorithm on
//! random points of one shape at growing n, with the quantities of the cost analysis in the
//! lecture on 3D convex hulls: the faces each algorithm creates against the expected bound
//! 6n − 20, its `Volume6` tests against its bound (n·h, n², n lg n), the conflict-list work
//! Σ|P(e)| against n lg n, and the fitted exponents of time and work against n ([`fits`]).
//! Hulls from outside the lab (Qhull and CGAL, through the FFI of the `topolab` crate) are added
//! to the rows afterwards, on the same points ([`point_sets`], [`insert_outside_row`]), timed
//! the same way ([`warm_median`]).

use crate::measuring::checksum::mix;
use crate::measuring::fit::fit_exponent;
use crate::measuring::timing::median;
use crate::measuring::timing::meter::MemoryMeter;
pub use crate::studies::hull::rows::{HullFit, HullRow};
use glam::DVec3;
use std::time::Instant;
use topolab_structures::hull::{convex_hull, random_points, Algorithm, Shape, Work};
use topolab_structures::Result;

/// The points of the hull's target (`targets::plan::Cell::Hull`): 1M in a ball.
pub const HULL_POINTS: usize = 1_000_000;

/// The seed of the benchmark's random points: `random_points(shape, n, POINTS_SEED)`, for the
/// lab's algorithms and for the outside hulls added afterwards alike.
pub const POINTS_SEED: u64 = 42;

/// The seed of the randomized algorithm's insertion order in the benchmark (and in the hull's
/// target, which times the same hulls).
pub const RANDOMIZED_SEED: u64 = 7;

/// The hull table's row of `algorithm` on the hull target's [`HULL_POINTS`] points in a ball.
pub fn hull_target_row<'a>(rows: &'a [HullRow], algorithm: &str) -> Option<&'a HullRow> {
    rows.iter()
        .find(|r| r.shape == "ball" && r.n == HULL_POINTS && r.algorithm == algorithm)
}

/// The checksum of a hull's vertex set: Σ mix(v, 1) over its input indices v (wrapping; the
/// terms of [`crate::measuring::checksum`]), the same in any order, so two hulls with the same vertices
/// agree and a missing, extra or other vertex changes it.
pub fn vertex_checksum(vertices: impl IntoIterator<Item = u32>) -> u64 {
    vertices
        .into_iter()
        .fold(0u64, |sum, v| sum.wrapping_add(mix(v as u64, 1)))
}

/// How many timed runs a hull of `n` points gets after its warm-up run took
/// `warm_up_seconds`: 3 below 100k points, 1 from 100k on or when the warm-up took over a
/// second (the run's work then dominates its noise).
pub fn timed_runs(n: usize, warm_up_seconds: f64) -> usize {
    if n >= 100_000 || warm_up_seconds > 1.0 {
        1
    } else {
        3
    }
}

/// A hull timed as the benchmark times every hull, the lab's and the outside ones.
#[derive(Clone, Debug)]
pub struct Warm<T> {
    /// The median of the timed runs, seconds.
    pub seconds: f64,
    /// How many timed runs ([`timed_runs`]).
    pub timed_runs: usize,
    /// What the warm-up run returned.
    pub warm_up: T,
    /// What the last timed run returned.
    pub last: T,
}

/// Times a hull of `n` points warm: `run(true)` once as the warm-up (its time decides
/// [`timed_runs`] and is otherwise not used), then `run(false)` that many times; the time is
/// their median. `run` returns the seconds it measured around the hull alone and what it
/// built (keep it small: the hull itself is best dropped inside `run`, after its clock).
pub fn warm_median<T, E>(
    n: usize,
    mut run: impl FnMut(bool) -> std::result::Result<(f64, T), E>,
) -> std::result::Result<Warm<T>, E> {
    let (warm_up_seconds, warm_up) = run(true)?;
    let runs = timed_runs(n, warm_up_seconds);
    let mut times = Vec::with_capacity(runs);
    let mut last = None;
    for _ in 0..runs {
        let (seconds, out) = run(false)?;
        times.push(seconds);
        last = Some(out);
    }
    times.sort_by(f64::total_cmp);
    Ok(Warm {
        seconds: median(&times),
        timed_runs: runs,
        warm_up,
        last: last.expect("timed_runs is at least 1"),
    })
}

/// What one run of [`convex_hull`] built, for a benchmark row (the hull itself is dropped).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Built {
    /// [`topolab_structures::hull::Hull::faces_created`].
    pub faces_created: usize,
    /// Vertices of the hull.
    pub hull_vertices: usize,
    /// [`vertex_checksum`] of them.
    pub vertex_checksum: u64,
    /// [`topolab_structures::hull::Hull::work`].
    pub work: Work,
}

/// One benchmark measurement of [`convex_hull`] on `points` with `algorithm`, by
/// [`warm_median`]: the clock runs around the call alone (input checks and duplicate removal
/// are in it, as is building the winged-edge it returns; dropping it is not). With `meter`,
/// the warm-up run counts the peak heap the call needed, and no timed run counts: counting
/// costs a few thread-local operations per allocation, which stay out of the clock. Every run
/// must build the same hull (the algorithms are deterministic, the randomized one by its
/// seed), else an error.
pub fn benchmark_row(
    points: &[DVec3],
    algorithm: Algorithm,
    meter: Option<&dyn MemoryMeter>,
) -> std::result::Result<(Warm<Built>, Option<usize>), String> {
    let warm = warm_median(points.len(), |warm_up| {
        // The lab's allocator counts only while asked, on this thread.
        let counting = meter.filter(|_| warm_up);
        let before = counting.map(|m| {
            m.counting(true);
            m.reset_peak();
            m.current()
        });
        let start = Instant::now();
        let hull = convex_hull(points, algorithm);
        let seconds = start.elapsed().as_secs_f64();
        let peak = counting.zip(before).map(|(m, before)| {
            let peak = m.peak().saturating_sub(before);
            m.counting(false);
            peak
        });
        let hull = hull.map_err(|e| e.to_string())?;
        let vertices = hull.vertices();
        let built = Built {
            faces_created: hull.faces_created,
            hull_vertices: vertices.len(),
            vertex_checksum: vertex_checksum(vertices.iter().map(|v| v.0)),
            work: hull.work,
        };
        Ok::<_, String>((seconds, (built, peak)))
    })?;
    if warm.warm_up.0 != warm.last.0 {
        return Err(format!(
            "{} on {} points built two different hulls: {:?}, then {:?}",
            algorithm.name(),
            points.len(),
            warm.warm_up.0,
            warm.last.0
        ));
    }
    let peak = warm.warm_up.1;
    Ok((
        Warm {
            seconds: warm.seconds,
            timed_runs: warm.timed_runs,
            warm_up: warm.warm_up.0,
            last: warm.last.0,
        },
        peak,
    ))
}

/// A point set of the benchmark, as a hull added after the run ([`insert_outside_row`]) needs
/// it: which points, and the randomized algorithm's hull of them, to agree with.
#[derive(Clone, Debug, PartialEq)]
pub struct PointSet {
    /// `ball`, `sphere` or `cube`.
    pub shape: String,
    /// Number of points.
    pub n: usize,
    /// Vertices of the randomized algorithm's hull.
    pub hull_vertices: usize,
    /// Their [`vertex_checksum`], if the row has it.
    pub vertex_checksum: Option<u64>,
}

impl PointSet {
    /// The points: `random_points` of the shape with [`POINTS_SEED`], as the benchmark drew
    /// them.
    pub fn points(&self) -> Result<Vec<DVec3>> {
        Ok(random_points(
            Shape::from_name(&self.shape)?,
            self.n,
            POINTS_SEED,
        ))
    }

    /// The row of outside hull `algorithm` on these points, timed by `timed`; the caller adds
    /// what its hull has (`hull_vertices`, ...).
    pub fn outside_row<T>(&self, algorithm: &str, timed: &Warm<T>) -> HullRow {
        HullRow {
            shape: self.shape.clone(),
            n: self.n,
            algorithm: algorithm.into(),
            seconds: timed.seconds,
            timed_runs: timed.timed_runs,
            ..HullRow::default()
        }
    }
}

/// The point sets of `rows` that the randomized algorithm ran on (every one: it runs every
/// size), in row order.
pub fn point_sets(rows: &[HullRow]) -> Vec<PointSet> {
    rows.iter()
        .filter(|r| r.algorithm == "randomized")
        .map(|r| PointSet {
            shape: r.shape.clone(),
            n: r.n,
            hull_vertices: r.hull_vertices,
            vertex_checksum: r.vertex_checksum,
        })
        .collect()
}

/// Inserts the row of an outside hull right after the rows of its point set (at the end if
/// there are none).
pub fn insert_outside_row(rows: &mut Vec<HullRow>, row: HullRow) {
    let after = rows
        .iter()
        .rposition(|r| r.shape == row.shape && r.n == row.n)
        .map_or(rows.len(), |i| i + 1);
    rows.insert(after, row);
}

/// Runs the benchmark for `shape` over `sizes` (increasing). Gift wrapping (O(n·h)) and the
/// plain incremental algorithm (O(n²)) run the next size only while its `Volume6` tests,
/// predicted by [`predicted_tests`], are at most `max_tests`; the randomized one always goes
/// on. A count, not a time, decides, so the sizes shown do not depend on the machine's load.
/// Each row is one [`benchmark_row`]: a warm-up run, which with `meter` measures the call's
/// peak heap, then the median of [`timed_runs`] runs. Every row goes to `progress` too.
pub fn run(
    shape: Shape,
    shape_name: &str,
    sizes: &[usize],
    max_tests: f64,
    meter: Option<&dyn MemoryMeter>,
    mut progress: impl FnMut(&HullRow),
) -> std::result::Result<Vec<HullRow>, String> {
    let mut rows = Vec::new();
    let mut too_slow = [false; 3];
    // Each slow algorithm's last (n, Volume6 tests): the growth of its work so far.
    let mut last_work: [Option<(usize, u64)>; 3] = [None; 3];
    for &n in sizes {
        let points = random_points(shape, n, POINTS_SEED);
        for (a, algorithm) in Algorithm::all(RANDOMIZED_SEED).into_iter().enumerate() {
            if too_slow[a] {
                continue;
            }
            let (timed, peak_bytes) = benchmark_row(&points, algorithm, meter)?;
            let built = timed.last;
            let randomized = matches!(algorithm, Algorithm::Randomized { .. });
            let work = (n, built.work.volume6_tests);
            if let (false, Some(&next)) = (randomized, sizes.iter().find(|&&m| m > n)) {
                too_slow[a] = predicted_tests(last_work[a], work, next) > max_tests;
            }
            last_work[a] = Some(work);
            let row = HullRow {
                shape: shape_name.into(),
                n,
                algorithm: algorithm.name().into(),
                seconds: timed.seconds,
                timed_runs: timed.timed_runs,
                faces_created: Some(built.faces_created),
                hull_vertices: built.hull_vertices,
                vertex_checksum: Some(built.vertex_checksum),
                volume6_tests: Some(built.work.volume6_tests),
                exact_tests: Some(built.work.exact_tests),
                conflict_work: randomized.then_some(built.work.conflict_work),
                peak_bytes,
            };
            progress(&row);
            rows.push(row);
        }
    }
    Ok(rows)
}

/// The `Volume6` tests a slow algorithm's next size may be predicted to take ([`run`]): 2·10⁹,
/// some 6 to 30 s on the 2-core reference machine (gift wrapping about 15 ns a test,
/// incremental 3). As counted, it keeps gift wrapping's 100k ball (551 million
/// tests) and leaves out the incremental algorithm's 1M ball (6 billion, 17 s) and 100k sphere
/// (10 billion, 36 s): their O(n²) shows on the sizes before (the ball to 100k, the sphere to
/// 10k).
pub const MAX_TESTS: f64 = 2e9;

/// The predicted `Volume6` tests of a slow hull algorithm (gift wrapping, incremental) at
/// `next` points, from its runs at `now` and `before` (the size before, same algorithm), each
/// (n, tests): the tests grow from `now` to `next` at the exponent they grew from `before` to
/// `now`. With no size before, they are taken to grow like n², the bound of both (n·h with
/// h up to n for gift wrapping).
pub fn predicted_tests(before: Option<(usize, u64)>, now: (usize, u64), next: usize) -> f64 {
    let exponent = match before {
        Some((n0, w0)) if n0 < now.0 && w0 > 0 && now.1 > 0 => {
            (now.1 as f64 / w0 as f64).ln() / (now.0 as f64 / n0 as f64).ln()
        }
        _ => 2.0,
    };
    now.1 as f64 * (next as f64 / now.0.max(1) as f64).powf(exponent)
}

/// n lg n, the lecture's expected bound of the randomized algorithm.
pub fn n_lg_n(n: usize) -> f64 {
    let n = n as f64;
    n * n.log2()
}

/// The lecture's cost bound of `algorithm` for n points with h hull vertices, by name and
/// value: gift wrapping O(n·h), incremental O(n²), randomized incremental expected
/// O(n lg n); `None` for another algorithm (an outside hull). The lecture's h for gift wrapping counts
/// the hull's edges, which is proportional to its vertices (3h − 6 for a triangulated hull).
pub fn bound(algorithm: &str, n: usize, h: usize) -> Option<(&'static str, f64)> {
    let n_f = n as f64;
    match algorithm {
        "gift" => Some(("n·h", n_f * h as f64)),
        "incremental" => Some(("n²", n_f * n_f)),
        "randomized" => Some(("n lg n", n_lg_n(n))),
        _ => None,
    }
}

/// [`HullFit`] of every (shape, algorithm) with at least two sizes in `rows`, in the order
/// they first appear.
pub fn fits(rows: &[HullRow]) -> Vec<HullFit> {
    let mut keys: Vec<(&str, &str)> = Vec::new();
    for r in rows {
        if !keys.contains(&(&r.shape, &r.algorithm)) {
            keys.push((&r.shape, &r.algorithm));
        }
    }
    let mut out = Vec::new();
    for (shape, algorithm) in keys {
        let series: Vec<&HullRow> = rows
            .iter()
            .filter(|r| r.shape == shape && r.algorithm == algorithm)
            .collect();
        let exponent = |y: &dyn Fn(&HullRow) -> Option<f64>| {
            let points: Option<Vec<(f64, f64)>> = series
                .iter()
                .map(|r| y(r).map(|y| (r.n as f64, y)))
                .collect();
            points
                .and_then(|p| fit_exponent(&p))
                .map(|fit| fit.exponent)
        };
        let Some(time_exponent) = exponent(&|r| Some(r.seconds)) else {
            continue;
        };
        let tests_exponent = exponent(&|r| r.volume6_tests.map(|t| t as f64));
        let conflict_exponent = exponent(&|r| r.conflict_work.map(|w| w as f64));
        let bound_name = bound(algorithm, 2, 1).map(|(name, _)| name.to_string());
        let bound_exponent = exponent(&|r| bound(algorithm, r.n, r.hull_vertices).map(|b| b.1));
        let work = conflict_exponent.or(tests_exponent);
        let within_bound = work.zip(bound_exponent).map(|(w, b)| w <= b + 0.1);
        out.push(HullFit {
            shape: shape.into(),
            algorithm: algorithm.into(),
            sizes: series.len(),
            time_exponent,
            tests_exponent,
            conflict_exponent,
            bound: bound_name,
            bound_exponent,
            within_bound,
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(algorithm: &str, n: usize, h: usize, seconds: f64, tests: u64) -> HullRow {
        HullRow {
            shape: "sphere".into(),
            n,
            algorithm: algorithm.into(),
            seconds,
            faces_created: Some(0),
            hull_vertices: h,
            volume6_tests: Some(tests),
            exact_tests: Some(0),
            conflict_work: (algorithm == "randomized").then_some(tests),
            ..HullRow::default()
        }
    }

    #[test]
    fn a_hull_is_timed_by_the_median_of_its_runs_after_one_warm_up() {
        // The warm-up (10 s, flagged) is not in the median; 3 runs below 100k points.
        let times = [10.0, 0.3, 0.1, 0.2];
        let mut calls = Vec::new();
        let warm: Warm<usize> = warm_median(1_000, |warm_up| {
            calls.push(warm_up);
            Ok::<_, ()>((times[calls.len() - 1], calls.len()))
        })
        .unwrap();
        assert_eq!(calls, [true, false]);
        assert_eq!((warm.timed_runs, warm.warm_up, warm.last), (1, 1, 2));
        assert_eq!(
            warm.seconds, 0.3,
            "a warm-up over a second leaves one timed run"
        );
        let mut calls = 0;
        let warm = warm_median(1_000, |warm_up| {
            calls += 1;
            assert_eq!(warm_up, calls == 1);
            Ok::<_, ()>(([0.5, 0.3, 0.1, 0.2][calls - 1], ()))
        })
        .unwrap();
        assert_eq!((warm.seconds, warm.timed_runs, calls), (0.2, 3, 4));
        assert_eq!(timed_runs(99_999, 0.5), 3);
        assert_eq!(timed_runs(100_000, 0.01), 1);
        // An error of any run is the result.
        let failed = warm_median(
            10,
            |warm_up| if warm_up { Ok((0.1, ())) } else { Err("no") },
        );
        assert_eq!(failed.unwrap_err(), "no");
    }

    /// A meter that records when it was asked to count, and counts 1 byte per call to
    /// `current` while counting.
    #[derive(Default)]
    struct Recorder {
        switches: std::cell::RefCell<Vec<bool>>,
    }

    impl MemoryMeter for Recorder {
        fn current(&self) -> usize {
            0
        }
        fn peak(&self) -> usize {
            1234
        }
        fn reset_peak(&self) {}
        fn counting(&self, on: bool) {
            self.switches.borrow_mut().push(on);
        }
    }

    #[test]
    fn the_lab_hull_counts_its_memory_in_the_warm_up_only() {
        let points = random_points(Shape::Ball, 2_000, POINTS_SEED);
        let meter = Recorder::default();
        let (timed, peak) =
            benchmark_row(&points, Algorithm::Randomized { seed: 7 }, Some(&meter)).unwrap();
        // Counting on and off once, around the warm-up; the three timed runs never count.
        assert_eq!(*meter.switches.borrow(), [true, false]);
        assert_eq!((peak, timed.timed_runs), (Some(1234), 3));
        let hull = convex_hull(&points, Algorithm::Randomized { seed: 7 }).unwrap();
        let vertices = hull.vertices();
        assert_eq!(timed.last.hull_vertices, vertices.len());
        assert_eq!(
            timed.last.vertex_checksum,
            vertex_checksum(vertices.iter().map(|v| v.0))
        );
        assert_eq!(timed.warm_up, timed.last);
        let (_, no_meter) = benchmark_row(&points, Algorithm::Gift, None).unwrap();
        assert_eq!(no_meter, None);
    }

    #[test]
    fn the_vertex_checksum_is_of_the_set() {
        let a = vertex_checksum([3, 1, 2]);
        assert_eq!(a, vertex_checksum([1, 2, 3]));
        assert_ne!(a, vertex_checksum([1, 2]));
        assert_ne!(a, vertex_checksum([1, 2, 4]));
        assert_eq!(vertex_checksum([]), 0);
    }

    #[test]
    fn outside_rows_follow_their_point_sets() {
        let mut rows = vec![
            row("gift", 1_000, 10, 1.0, 1),
            row("randomized", 1_000, 10, 1.0, 1),
            row("randomized", 2_000, 12, 1.0, 1),
        ];
        rows[1].vertex_checksum = Some(77);
        let sets = point_sets(&rows);
        assert_eq!(sets.len(), 2);
        assert_eq!(
            sets[0],
            PointSet {
                shape: "sphere".into(),
                n: 1_000,
                hull_vertices: 10,
                vertex_checksum: Some(77)
            }
        );
        assert_eq!(
            sets[1].points().unwrap(),
            random_points(Shape::Sphere, 2_000, POINTS_SEED)
        );
        for n in [1_000, 2_000, 3_000] {
            insert_outside_row(&mut rows, row("qhull", n, 10, 1.0, 0));
        }
        let order: Vec<(&str, usize)> = rows.iter().map(|r| (r.algorithm.as_str(), r.n)).collect();
        assert_eq!(
            order,
            [
                ("gift", 1_000),
                ("randomized", 1_000),
                ("qhull", 1_000),
                ("randomized", 2_000),
                ("qhull", 2_000),
                ("qhull", 3_000)
            ]
        );
    }

    #[test]
    fn the_next_size_is_predicted_from_the_growth_of_the_work() {
        // No size before: n² growth, 100 times the tests at 10 times the points.
        assert!((predicted_tests(None, (1_000, 5), 10_000) - 500.0).abs() < 1e-9);
        // Work that grew 32-fold from 1k to 10k points grows 32-fold again to 100k.
        let p = predicted_tests(Some((1_000, 1_000)), (10_000, 32_000), 100_000);
        assert!((p - 1_024_000.0).abs() < 1e-6, "{p}");
        // The incremental algorithm on a sphere, as counted: 995,004 tests at
        // 1k, 99,950,004 at 10k, 9,999,500,004 at 100k.
        let p = predicted_tests(Some((1_000, 995_004)), (10_000, 99_950_004), 100_000);
        assert!((p / 9_999_500_004.0 - 1.0).abs() < 0.01, "{p}");
    }

    #[test]
    fn fits_compare_the_work_with_the_lectures_bounds() {
        let mut rows = Vec::new();
        for n in [1_000usize, 10_000, 100_000] {
            // Gift wrapping on a sphere (h = n): work n², within n·h.
            rows.push(row("gift", n, n, 1e-9 * (n * n) as f64, (n * n) as u64));
            // A randomized run whose work grows like n²: beyond n lg n.
            rows.push(row("randomized", n, n, 1e-9 * n as f64, (n * n) as u64));
        }
        rows.push(row("qhull", 1_000, 1_000, 1e-3, 0));
        let fits = fits(&rows);
        assert_eq!(fits.len(), 2, "Qhull has one size only: no fit");
        let gift = &fits[0];
        assert_eq!(gift.bound.as_deref(), Some("n·h"));
        assert!((gift.time_exponent - 2.0).abs() < 1e-9);
        assert!((gift.bound_exponent.unwrap() - 2.0).abs() < 1e-9);
        assert_eq!(gift.within_bound, Some(true));
        let randomized = &fits[1];
        assert!((randomized.time_exponent - 1.0).abs() < 1e-9);
        assert!((randomized.conflict_exponent.unwrap() - 2.0).abs() < 1e-9);
        assert!(randomized.bound_exponent.unwrap() < 1.2);
        assert_eq!(randomized.within_bound, Some(false));
    }
}
