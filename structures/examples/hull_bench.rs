//! Times seed 004's three hull algorithms against n, next to Qhull in the same run, and
//! counts the faces each creates against the seed's bound 6n − 20.
//!
//! `cargo run --release -p topolab-structures --example hull_bench -- [SHAPE ...] [--max N]`
//!
//! SHAPE: cube, ball, sphere (default ball and sphere). n runs 1k, 10k, 100k, 1M up to
//! `--max` (default 1M). Gift wrapping (O(n·h)) and the plain incremental algorithm (O(n²))
//! stop growing n once one size took more than 1 s; the randomized one always goes on. Each
//! time is the best of 3 runs (1 run from 100k on) of [`benchmark_row`], Qhull's the best of
//! as many `ConvexHull` calls; Qhull is skipped without the workspace's `.venv` with SciPy.

use std::path::Path;
use topolab_structures::hull::{benchmark_row, qhull, random_points, Algorithm, Shape};

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
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
    let python = qhull::python(root);
    if python.is_none() {
        println!(
            "Qhull SKIPPED: no {}/.venv/bin/python with scipy",
            root.display()
        );
    }
    println!(
        "{:<7} {:>8} {:<11} {:>10} {:>10} {:>9} {:>11} {:>9} {:>9}",
        "shape",
        "n",
        "algorithm",
        "seconds",
        "created",
        "per point",
        "/(6n-20)",
        "hull v",
        "/ Qhull"
    );
    for shape_name in &shapes {
        let shape = Shape::from_name(shape_name).unwrap();
        let mut too_slow = [false; 3];
        let sizes = [1_000usize, 10_000, 100_000, 1_000_000];
        for &n in sizes.iter().filter(|&&n| n <= max) {
            let points = random_points(shape, n, 42);
            let repeat = if n >= 100_000 { 1 } else { 3 };
            let reference = python
                .as_ref()
                .map(|py| qhull::run(py, root, &points, repeat).expect("qhull"));
            if let Some(q) = &reference {
                println!(
                    "{:<7} {:>8} {:<11} {:>10.4} {:>10} {:>9} {:>11} {:>9} {:>9}",
                    shape_name,
                    n,
                    "qhull",
                    q.seconds,
                    "-",
                    "-",
                    "-",
                    q.vertices.len(),
                    "1.00"
                );
            }
            for (a, algorithm) in Algorithm::all(7).into_iter().enumerate() {
                if too_slow[a] {
                    continue;
                }
                let mut best = f64::INFINITY;
                let mut row = (0.0, 0, 0);
                for _ in 0..repeat {
                    row = benchmark_row(&points, algorithm).expect("hull");
                    best = best.min(row.0);
                }
                let (_, created, hull_vertices) = row;
                // The next n is 10 times larger: up to 100 times the time for O(n²). The
                // randomized algorithm (expected O(n log n)) always goes on to the largest n.
                let quadratic = !matches!(algorithm, Algorithm::Randomized { .. });
                too_slow[a] = quadratic && best > 1.0;
                let ratio = reference
                    .as_ref()
                    .map_or("-".to_string(), |q| format!("{:.2}", best / q.seconds));
                println!(
                    "{:<7} {:>8} {:<11} {:>10.4} {:>10} {:>9.3} {:>11.3} {:>9} {:>9}",
                    shape_name,
                    n,
                    algorithm.name(),
                    best,
                    created,
                    created as f64 / n as f64,
                    created as f64 / (6.0 * n as f64 - 20.0),
                    hull_vertices,
                    ratio
                );
            }
        }
    }
}
