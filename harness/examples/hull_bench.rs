//! Times the three hull algorithms of the lecture on 3D convex hulls against n, next to Qhull
//! and CGAL's `convex_hull_3` (the report's outside hulls, when compiled in) on the same
//! points, with the quantities of the lecture's analysis: faces created against the expected
//! bound 6n − 20, `Volume6` tests against each algorithm's bound (gift wrapping
//! n·h, incremental n², randomized n lg n), the conflict-list work Σ|P(e)| against n lg n,
//! the share of tests the floating-point filter left to exact arithmetic, the peak heap per
//! point, and at the end the fitted exponents per algorithm and the cost of one visibility
//! test with the face's cached plane and with the adaptive `orient3d` alone.
//!
//! `cargo run --release -p topolab-harness --example hull_bench -- [SHAPE ...] [--max N]`
//!
//! SHAPE: cube, ball, sphere (default ball and sphere). n runs 1k, 10k, 100k, 1M up to
//! `--max` (default 1M). Gift wrapping (O(n·h)) and the plain incremental algorithm (O(n²))
//! run the next n while its predicted `Volume6` tests are at most [`bench::MAX_TESTS`]; the
//! randomized one always goes on. Each time is the median of [`bench::timed_runs`] runs after
//! a warm-up run ([`bench::benchmark_row`]; the peak heap is counted in the warm-up), Qhull's
//! and CGAL's the same way, in-process (`topolab_harness::studies::hull::outside::add_outside_hulls`; a build without
//! Qhull says so). Columns: `×Qhull` the time over Qhull's at the same n, `/bound` the
//! `Volume6` tests over the algorithm's bound, `ΣP/nlgn` Σ|P(e)| over n lg n, `exact` the tests
//! decided exactly, `B/pt` peak heap bytes per point.

use std::time::Instant;
use topolab_harness::studies::hull::bench;
use topolab_structures::hull::plane::{FacePlane, TestCount};
use topolab_structures::hull::predicates::volume6;
use topolab_structures::hull::{random_points, Shape};

/// The lab's counting allocator, C++'s heap included: the benchmark measures each run's peak
/// heap with it, as the report does.
#[global_allocator]
static ALLOCATOR: topolab_alloc::CountingAllocator =
    topolab_alloc::CountingAllocator::with_foreign(topolab_baselines::heap::CPP_HEAP);

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let max = args
        .iter()
        .position(|a| a == "--max")
        .and_then(|i| args.get(i + 1))
        .and_then(|m| m.parse().ok())
        .unwrap_or(1_000_000usize);
    let mut shapes: Vec<String> = args
        .iter()
        .filter(|a| ["cube", "ball", "sphere"].contains(&a.as_str()))
        .cloned()
        .collect();
    if shapes.is_empty() {
        shapes = vec!["ball".into(), "sphere".into()];
    }
    if !topolab_baselines::HAS_QHULL {
        println!("Qhull SKIPPED: {}", topolab_baselines::QHULL_MISSING);
    }
    let mut rows = Vec::new();
    for shape_name in &shapes {
        let shape = Shape::from_name(shape_name).unwrap();
        let sizes: Vec<usize> = [1_000usize, 10_000, 100_000, 1_000_000]
            .into_iter()
            .filter(|&n| n <= max)
            .collect();
        let run = bench::run(
            shape,
            shape_name,
            &sizes,
            bench::MAX_TESTS,
            Some(&ALLOCATOR),
            |row| {
                eprintln!(
                    "{} {} {}: {:.4} s",
                    row.shape, row.n, row.algorithm, row.seconds
                )
            },
        )
        .expect("hull benchmark");
        rows.extend(run);
    }
    topolab_harness::studies::hull::outside::add_outside_hulls(&mut rows).expect("outside hulls");
    println!(
        "{:<7} {:>8} {:<18} {:>9} {:>4} {:>7} {:>8} {:>8} {:>7} {:>11} {:>7} {:>8} {:>7} {:>5}",
        "shape",
        "n",
        "algorithm",
        "seconds",
        "runs",
        "×Qhull",
        "created",
        "/(6n-20)",
        "hull v",
        "Volume6",
        "/bound",
        "ΣP/nlgn",
        "exact",
        "B/pt"
    );
    for row in &rows {
        let qhull_seconds = rows
            .iter()
            .find(|q| q.shape == row.shape && q.n == row.n && q.algorithm == "qhull")
            .map_or(f64::NAN, |q| q.seconds);
        let n = row.n as f64;
        let opt = |x: Option<String>| x.unwrap_or_else(|| "-".into());
        let bound = bench::bound(&row.algorithm, row.n, row.hull_vertices);
        println!(
            "{:<7} {:>8} {:<18} {:>9.4} {:>4} {:>7.2} {:>8} {:>8} {:>7} {:>11} {:>7} {:>8} {:>7} {:>5}",
            row.shape,
            row.n,
            row.algorithm,
            row.seconds,
            row.timed_runs,
            row.seconds / qhull_seconds,
            opt(row.faces_created.map(|c| c.to_string())),
            opt(row
                .faces_created
                .map(|c| format!("{:.3}", c as f64 / (6.0 * n - 20.0)))),
            row.hull_vertices,
            opt(row.volume6_tests.map(|t| t.to_string())),
            opt(row
                .volume6_tests
                .zip(bound)
                .map(|(t, b)| format!("{:.3}", t as f64 / b.1))),
            opt(row
                .conflict_work
                .map(|w| format!("{:.3}", w as f64 / bench::n_lg_n(row.n)))),
            opt(row
                .exact_tests
                .zip(row.volume6_tests)
                .map(|(e, t)| format!("{:.1e}", e as f64 / t.max(1) as f64))),
            opt(row.peak_bytes.map(|b| format!("{:.0}", b as f64 / n))),
        );
    }
    println!("\nfitted exponents against n (t ∝ n^e); work = Σ|P(e)| for randomized, Volume6 tests otherwise");
    println!(
        "{:<7} {:<11} {:>5} {:>6} {:>6} {:>8} {:>6} {:>6}",
        "shape", "algorithm", "sizes", "time", "work", "bound", "of it", "within"
    );
    for f in bench::fits(&rows) {
        let e = |x: Option<f64>| x.map_or("-".into(), |x| format!("{x:.2}"));
        println!(
            "{:<7} {:<11} {:>5} {:>6.2} {:>6} {:>8} {:>6} {:>6}",
            f.shape,
            f.algorithm,
            f.sizes,
            f.time_exponent,
            e(f.conflict_exponent.or(f.tests_exponent)),
            f.bound.unwrap_or_else(|| "-".into()),
            e(f.bound_exponent),
            f.within_bound.map_or("-".into(), |w| w.to_string())
        );
    }
    filter_cost();
}

/// One visibility test against a face, three ways, on random faces of the unit sphere and
/// the points of a ball, best of 5: with the adaptive `orient3d` alone ([`volume6`], its own
/// filter, recomputing the face's part each time), with the face's plane prepared once
/// ([`FacePlane::volume6`], the filter's bound per point), and with one bound per face for
/// all points ([`RoundedPlane`](topolab_structures::hull::plane::RoundedPlane), the conflict
/// lists' test). All three are exact; the last
/// two go to exact arithmetic only where their filter is unsure.
fn filter_cost() {
    let faces = random_points(Shape::Sphere, 3 * 64, 5);
    let points = random_points(Shape::Ball, 200_000, 6);
    let mut best = [f64::INFINITY; 3];
    let mut seen = [0usize; 3];
    let mut count = [TestCount::default(); 3];
    for _ in 0..5 {
        for (k, best) in best.iter_mut().enumerate() {
            let start = Instant::now();
            let mut positive = 0;
            for f in faces.chunks_exact(3) {
                let plane = FacePlane::new(f[0], f[1], f[2]);
                let bounded = plane.for_rounded_points(1.0);
                for &p in &points {
                    positive += usize::from(match k {
                        0 => volume6(f[0], f[1], f[2], p) > 0.0,
                        1 => plane.volume6(p, &mut count[k]) > 0.0,
                        _ => bounded.is_seen_from_point(p, &mut count[k]),
                    });
                }
            }
            *best = best.min(start.elapsed().as_secs_f64());
            seen[k] = positive;
        }
    }
    assert!(seen.iter().all(|&s| s == seen[0]), "the tests disagree");
    let tests = (faces.len() / 3 * points.len()) as f64;
    let ns = |k: usize| best[k] * 1e9 / tests;
    println!(
        "\none Volume6 test: {:.2} ns with the adaptive orient3d alone, {:.2} ns with the face's cached plane ({} exact of {}), {:.2} ns with one bound per face ({} exact of {})",
        ns(0),
        ns(1),
        count[1].exact,
        count[1].tests,
        ns(2),
        count[2].exact,
        count[2].tests
    );
}
