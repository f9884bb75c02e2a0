//! Times the three hull algorithms of the lecture on 3D convex hulls against n, next to Qhull
//! in the same run, and counts the faces each creates against the lecture's bound 6n − 20.
//!
//! `cargo run --release -p topolab-harness --example hull_bench -- [SHAPE ...] [--max N]`
//!
//! SHAPE: cube, ball, sphere (default ball and sphere). n runs 1k, 10k, 100k, 1M up to
//! `--max` (default 1M). Gift wrapping (O(n·h)) and the plain incremental algorithm (O(n²))
//! stop growing n once one size took more than 1 s; the randomized one always goes on. Each
//! time is the best of 3 runs (1 run from 100k on) of [`bench::benchmark_row`], Qhull's the best of
//! as many `ConvexHull` calls; Qhull is skipped without the workspace's `.venv` with SciPy.

use std::path::Path;
use topolab_harness::hull::{bench, qhull};
use topolab_structures::hull::Shape;

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
        let sizes: Vec<usize> = [1_000usize, 10_000, 100_000, 1_000_000]
            .into_iter()
            .filter(|&n| n <= max)
            .collect();
        let mut qhull_seconds = f64::NAN;
        bench::run(
            shape,
            shape_name,
            &sizes,
            python.as_deref().map(|p| (p, root)),
            1.0,
            |row| {
                if row.algorithm == "qhull" {
                    qhull_seconds = row.seconds;
                }
                let created = row.faces_created.map_or("-".into(), |c| c.to_string());
                let per = |c: usize, d: f64| format!("{:.3}", c as f64 / d);
                println!(
                    "{:<7} {:>8} {:<11} {:>10.4} {:>10} {:>9} {:>11} {:>9} {:>9.2}",
                    row.shape,
                    row.n,
                    row.algorithm,
                    row.seconds,
                    created,
                    row.faces_created
                        .map_or("-".into(), |c| per(c, row.n as f64)),
                    row.faces_created
                        .map_or("-".into(), |c| per(c, 6.0 * row.n as f64 - 20.0)),
                    row.hull_vertices,
                    row.seconds / qhull_seconds
                );
            },
        )
        .expect("hull benchmark");
    }
}
