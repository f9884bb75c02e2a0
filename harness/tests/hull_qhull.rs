//! The three hull algorithms against Qhull (SciPy's `ConvexHull`, run by
//! `python/qhull_reference.py`): same hull vertex positions, same volume. Prints a SKIPPED
//! line when the workspace has no `.venv` with SciPy.

use glam::DVec3;
use std::path::Path;
use topolab_harness::studies::hull::qhull;
use topolab_structures::hull::{convex_hull, random_points, Algorithm, Shape};

fn sorted_positions(points: &[DVec3], indices: impl Iterator<Item = usize>) -> Vec<[f64; 3]> {
    let mut v: Vec<[f64; 3]> = indices.map(|i| points[i].to_array()).collect();
    v.sort_by(|a, b| a.partial_cmp(b).unwrap());
    v
}

#[test]
fn the_three_algorithms_match_qhull() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
    let Some(python) = qhull::python(root) else {
        println!(
            "SKIPPED the_three_algorithms_match_qhull: no {}/.venv/bin/python with scipy",
            root.display()
        );
        return;
    };
    let grid: Vec<DVec3> = (0..125)
        .map(|i| DVec3::new((i % 5) as f64, (i / 5 % 5) as f64, (i / 25) as f64) * 0.5)
        .collect();
    let cases = [
        ("cube", random_points(Shape::Cube, 2000, 1)),
        ("ball", random_points(Shape::Ball, 2000, 2)),
        ("sphere", random_points(Shape::Sphere, 500, 3)),
        ("grid 5x5x5", grid),
    ];
    for (what, points) in &cases {
        let reference = qhull::run(&python, root, points, 1).unwrap();
        let expected = sorted_positions(points, reference.vertices.iter().map(|&v| v as usize));
        for algorithm in Algorithm::all(9) {
            let hull = convex_hull(points, algorithm).unwrap();
            let got = sorted_positions(points, hull.vertices().iter().map(|v| v.index()));
            assert_eq!(got, expected, "{what} {}: hull vertices", algorithm.name());
            let volume = hull.volume();
            assert!(
                (volume - reference.volume).abs() <= 1e-9 * reference.volume,
                "{what} {}: volume {volume} vs Qhull {}",
                algorithm.name(),
                reference.volume
            );
        }
        println!(
            "{what}: {} hull vertices, agreeing with Qhull",
            expected.len()
        );
    }
}
