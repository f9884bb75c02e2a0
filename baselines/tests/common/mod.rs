//! Helpers of the baselines' tests, shared with the `topolab` crate's tests (its
//! `tests/common` includes this file).
#![allow(dead_code)]

use glam::DVec3;
use topolab_structures::{meshes, PolygonSoup};

/// Tells the person running the tests that `what` did not run and why. Written to stderr
/// directly: libtest captures `eprintln!` of a passing test, and a skip must be seen.
pub fn report_skip(what: &str, why: &str) {
    use std::io::Write;
    let _ = writeln!(std::io::stderr(), "SKIPPED {what}: {why}");
}

/// Three triangles on one edge, then two triangles traversing their shared edge the same way:
/// the halfedge libraries (OpenMesh, CGAL) refuse the last face of each.
pub fn broken_soups() -> Vec<PolygonSoup> {
    let positions = (0..5)
        .map(|i| DVec3::new(i as f64, (i * i) as f64, 0.0))
        .collect();
    vec![
        PolygonSoup::from_polygons(positions, &[[0u32, 1, 2], [1, 0, 3], [0, 1, 4]]),
        PolygonSoup::from_polygons(
            (0..4).map(|i| DVec3::new(i as f64, 0.0, 1.0)).collect(),
            &[[0u32, 1, 2], [0, 1, 3]],
        ),
    ]
}

/// A closed tetrahedron plus a triangle at its vertex 0, the triangle first or last.
pub fn closed_fan_soups() -> Vec<PolygonSoup> {
    let tetrahedron = meshes::closed_tetrahedron();
    let mut positions = tetrahedron.positions.clone();
    positions.extend([DVec3::new(5.0, 5.0, 5.0), DVec3::new(6.0, 5.0, 5.0)]);
    let faces: Vec<Vec<u32>> = tetrahedron.faces().map(|f| f.to_vec()).collect();
    let triangle = vec![0u32, 4, 5];
    let last: Vec<Vec<u32>> = faces.iter().cloned().chain([triangle.clone()]).collect();
    let first: Vec<Vec<u32>> = [triangle].into_iter().chain(faces).collect();
    vec![
        PolygonSoup::from_polygons(positions.clone(), &last),
        PolygonSoup::from_polygons(positions, &first),
    ]
}
