//! The grids' own tests: the lecture's example, refusals, `validate` and `explain`.

use super::*;
use crate::core::ids::VertexId;
use crate::core::soup::PolygonSoup;
use crate::core::topology::MeshTopology;
use crate::meshes;
use crate::testing::conformance::compare;

/// The example of the lecture on polygon-mesh data structures: origin (-1, 1), cells
/// 0.2 x 0.2, 10 points in x and 20 in y (points, not cells: 9 x 19 cells).
fn lecture_grid() -> (PolygonSoup, [u32; 2]) {
    let points = [10u32, 20];
    let mut soup = meshes::grid(points[0] as usize - 1, points[1] as usize - 1, false);
    for p in &mut soup.positions {
        *p = DVec3::new(-1.0 + p.x * 0.2, 1.0 + p.y * 0.2, 0.0);
    }
    (soup, points)
}

#[test]
fn the_lecture_example_answers_its_top_right_corner() {
    // "Koordinaten des rechten oberen Punktes?": the last of 10 x 20 points.
    let (soup, [nx, ny]) = lecture_grid();
    let grid = RegularGrid::from_soup(&soup).expect("a regular grid");
    assert_eq!(grid.heap_bytes(), 0, "nothing stored per element");
    assert_eq!(grid.num_vertices(), (nx * ny) as usize);
    let top_right = grid.position(VertexId(nx * ny - 1));
    let expected = DVec3::new(
        -1.0 + (nx - 1) as f64 * 0.2,
        1.0 + (ny - 1) as f64 * 0.2,
        0.0,
    );
    assert!((top_right - expected).length() < 1e-12, "{top_right}");
    assert!((expected - DVec3::new(0.8, 4.8, 0.0)).length() < 1e-12);
    grid.validate().expect("valid");
}

#[test]
fn the_height_field_stores_any_positions_the_regular_grid_refuses_them() {
    let mut soup = meshes::grid(4, 3, true);
    for (v, p) in soup.positions.iter_mut().enumerate() {
        p.z = (v as f64 * 0.7).sin();
        p.x += 0.01 * v as f64;
    }
    let field = HeightField::from_soup(&soup).expect("a grid's topology");
    compare(&field, &soup).expect("every operator matches the oracle");
    assert_eq!(field.heap_bytes(), 20 * 24);
    let err = RegularGrid::from_soup(&soup).expect_err("positions off the formula");
    assert_eq!(err.kind(), "not-a-grid");
    assert!(err.to_string().contains("vertex 1 is at"), "{err}");
}

#[test]
fn refusals_name_the_reason() {
    let reason = |soup: &PolygonSoup| {
        RegularGrid::from_soup(soup)
            .expect_err("refused")
            .to_string()
    };
    assert!(reason(&PolygonSoup::new()).contains("no faces"));
    assert!(reason(&meshes::quad_cube()).contains("face 0 is [0, 2, 3, 1]"));
    assert!(reason(&meshes::mixed_polygons()).contains("face 0 is [0, 1, 2, 3]"));
    let swapped = meshes::grid(3, 2, true).reorder_faces(&[0, 1, 2, 3, 5, 4, 6, 7, 8, 9, 10, 11]);
    assert!(
        reason(&swapped).contains("face 4 is [2, 7, 6], but face 4 of the 3x2 grid is [2, 3, 7]"),
        "{}",
        reason(&swapped)
    );
    let mut missing = meshes::grid(2, 2, false);
    missing = missing.with_faces(|f| f != 3);
    assert!(reason(&missing).contains("3 faces, but a 2x2 quad grid has 4"));
}

#[test]
fn validate_catches_inconsistent_shapes_and_geometry() {
    let soup = meshes::grid(2, 2, false);
    let mut grid = RegularGrid::from_soup(&soup).expect("grid");
    grid.shape.nx = 0;
    assert_eq!(grid.validate().map_err(|e| e.kind()), Err("invariant"));
    let mut field = HeightField::from_soup(&soup).expect("grid");
    field.shape.ny = 3;
    let err = field.validate().expect_err("9 positions for 12 vertices");
    assert!(err.to_string().contains("9 positions"), "{err}");
}

#[test]
fn explain_shows_the_implicit_numbering_of_a_2x2_grid() {
    let grid = RegularGrid::from_soup(&meshes::grid(2, 2, true)).expect("grid");
    let mut out = String::new();
    grid.explain(&mut out).expect("string");
    assert!(out.contains("v6   v7   v8"), "{out}");
    assert_eq!(out.matches("\n  e").count(), 16, "{out}");
    assert_eq!(out.matches("\n  f").count(), 8, "{out}");
    assert!(out.contains("f1: cell (0, 0), vertices [0, 4, 3]"), "{out}");
}
