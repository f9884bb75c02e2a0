//! The three convex hull algorithms of the lecture on 3D convex hulls: each result is a valid
//! winged-edge that matches the oracle of its own faces, is closed (Euler characteristic 2),
//! convex (every input point on the inner side of every face, exactly), has only extreme points
//! as vertices, and the three agree with each other; degenerate input gives typed errors, never
//! a panic.

use glam::DVec3;
use proptest::prelude::*;
use topolab_structures::hull::predicates::{collinear, volume6};
use topolab_structures::hull::{convex_hull, random_points, Algorithm, Hull, Shape};
use topolab_structures::testing::conformance::compare;
use topolab_structures::MeshTopology;

/// Every property of a correct hull of `points` that does not need another algorithm.
fn check_hull(points: &[DVec3], hull: &Hull, what: &str) {
    let soup = hull.to_soup();
    compare(&hull.mesh, &soup).unwrap_or_else(|e| panic!("{what}: {e}"));
    let m = &hull.mesh;
    let (v, e, f) = (hull.vertices().len(), m.num_edges(), m.num_faces());
    assert_eq!(v as i64 - e as i64 + f as i64, 2, "{what}: V − E + F");
    assert_eq!(m.num_boundary_edges(), 0, "{what}: closed");
    for face in soup.faces() {
        let [a, b, c] = [face[0], face[1], face[2]].map(|i| soup.positions[i as usize]);
        assert_eq!(face.len(), 3, "{what}: triangles");
        for (i, &p) in points.iter().enumerate() {
            assert!(
                volume6(a, b, c, p) <= 0.0,
                "{what}: point {i} sees face {face:?}"
            );
        }
    }
    // Only corners: a hull vertex inside a facet has all its neighbours in one plane with it,
    // and one inside an edge of the polytope lies between two neighbours on that edge's line.
    for vertex in hull.vertices() {
        let p = points[vertex.index()];
        assert!(
            points[..vertex.index()].iter().all(|&q| q != p),
            "{what}: vertex {vertex} repeats an earlier point"
        );
        let mut around = Vec::new();
        m.vertex_vertices(vertex, |w| around.push(points[w.index()]));
        let q0 = around[0];
        let flat = match around.iter().find(|&&w| !collinear(p, q0, w)) {
            Some(&w) => around.iter().all(|&q| volume6(p, q0, w, q) == 0.0),
            None => true,
        };
        let between = |q: DVec3, r: DVec3| {
            collinear(q, p, r)
                && (0..3).any(|k| (q[k] < p[k] && p[k] < r[k]) || (q[k] > p[k] && p[k] > r[k]))
        };
        let straight = around
            .iter()
            .any(|&q| around.iter().any(|&r| between(q, r)));
        assert!(
            !flat && !straight,
            "{what}: vertex {vertex} is not a corner"
        );
    }
}

/// Builds all three hulls, checks each, and checks that they agree.
fn check_all(points: &[DVec3], what: &str) -> Vec<Hull> {
    let hulls: Vec<Hull> = Algorithm::all(7)
        .into_iter()
        .map(|a| {
            let hull = convex_hull(points, a).unwrap_or_else(|e| panic!("{what} {a:?}: {e}"));
            check_hull(points, &hull, &format!("{what} {}", a.name()));
            hull
        })
        .collect();
    let volume = hulls[0].volume();
    for (a, hull) in Algorithm::all(7).iter().zip(&hulls) {
        assert_eq!(
            hull.vertices(),
            hulls[0].vertices(),
            "{what}: {} vertices",
            a.name()
        );
        assert!(
            (hull.volume() - volume).abs() <= 1e-9 * volume.abs().max(1e-300),
            "{what}: {} volume {} vs {volume}",
            a.name(),
            hull.volume()
        );
    }
    hulls
}

#[test]
fn random_points_in_a_cube_a_ball_and_on_a_sphere() {
    for (shape, n) in [(Shape::Cube, 300), (Shape::Ball, 300), (Shape::Sphere, 120)] {
        for seed in 0..3 {
            let points = random_points(shape, n, seed);
            let hulls = check_all(&points, &format!("{shape:?} n={n} seed={seed}"));
            if shape == Shape::Sphere {
                assert_eq!(hulls[0].vertices().len(), n, "on a sphere h = n");
            }
        }
    }
}

#[test]
fn the_tetrahedron_is_its_own_hull() {
    let points = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
    for hull in check_all(&points, "tetrahedron") {
        assert_eq!((hull.mesh.num_faces(), hull.faces_created), (4, 4));
        assert!((hull.volume() - 1.0 / 6.0).abs() < 1e-15);
    }
}

/// Points of the grid {0..k}³: a cube with 8 corners; every face, edge and interior point is
/// not a vertex; each square facet is two triangles.
#[test]
fn an_integer_grid_gives_the_cubes_eight_corners_and_twelve_triangles() {
    for k in [1, 2, 4] {
        let mut points = Vec::new();
        for x in 0..=k {
            for y in 0..=k {
                for z in 0..=k {
                    points.push(DVec3::new(x as f64, y as f64, z as f64));
                }
            }
        }
        for hull in check_all(&points, &format!("grid {k}")) {
            assert_eq!(hull.vertices().len(), 8);
            assert_eq!(hull.mesh.num_faces(), 12);
            assert_eq!(hull.volume(), (k * k * k) as f64);
        }
    }
}

#[test]
fn duplicates_become_vertices_through_their_first_occurrence() {
    let mut points = random_points(Shape::Sphere, 40, 3);
    let copies: Vec<DVec3> = points.iter().step_by(3).copied().collect();
    points.extend(copies);
    points.insert(0, points[10]);
    let hulls = check_all(&points, "duplicates");
    assert_eq!(hulls[0].vertices().len(), 40);
    assert!(hulls[0].vertices().iter().all(|v| v.index() <= 40));
}

#[test]
fn degenerate_inputs_give_typed_errors() {
    let line: Vec<DVec3> = (0..5).map(|i| DVec3::splat(i as f64)).collect();
    let plane: Vec<DVec3> = (0..9)
        .map(|i| DVec3::new((i % 3) as f64, (i / 3) as f64, 0.0))
        .collect();
    let cases: [(&str, Vec<DVec3>, &str); 6] = [
        ("nothing", vec![], "degenerate-points"),
        (
            "three points",
            vec![DVec3::ZERO, DVec3::X, DVec3::Y],
            "degenerate-points",
        ),
        (
            "one point five times",
            vec![DVec3::ONE; 5],
            "degenerate-points",
        ),
        ("a line", line, "degenerate-points"),
        ("a plane", plane, "degenerate-points"),
        (
            "NaN",
            vec![
                DVec3::ZERO,
                DVec3::X,
                DVec3::Y,
                DVec3::new(0.0, f64::NAN, 1.0),
            ],
            "non-finite-coordinate",
        ),
    ];
    for (what, points, kind) in cases {
        for a in Algorithm::all(1) {
            let err = convex_hull(&points, a).unwrap_err();
            assert_eq!(err.kind(), kind, "{what} {a:?}: {err}");
        }
    }
    let inf = [
        DVec3::ZERO,
        DVec3::X,
        DVec3::Y,
        DVec3::new(f64::INFINITY, 0.0, 1.0),
    ];
    assert_eq!(
        convex_hull(&inf, Algorithm::Gift).unwrap_err().kind(),
        "non-finite-coordinate"
    );
}

/// Corners and inner points of the cube [0, 4]³ scaled by `scale`.
fn scaled_cube(scale: f64) -> Vec<DVec3> {
    let mut points = Vec::new();
    for i in 0..27 {
        let [x, y, z] = [i % 3, (i / 3) % 3, i / 9].map(|c| (2 * c) as f64);
        points.push(DVec3::new(x, y, z) * scale);
    }
    points
}

#[test]
fn coordinates_whose_products_overflow_or_underflow_are_refused_by_name() {
    // Near 1e300 the products of orient3d overflow: the algorithms broke their own invariants
    // ("face 1 uses vertex 3 more than once"); near 1e-120 they underflow to 0 and the cube
    // came out flat ("degenerate-points").
    for (what, points) in [
        ("1e300", scaled_cube(1e300)),
        ("-1e300", scaled_cube(-1e300)),
        ("1e-120", scaled_cube(1e-120)),
        (
            "one far point",
            [scaled_cube(1.0), vec![DVec3::new(0.5, 1e100, 0.5)]].concat(),
        ),
        (
            "one tiny coordinate",
            [scaled_cube(1.0), vec![DVec3::new(1.0, 1e-80, 1.0)]].concat(),
        ),
    ] {
        for a in Algorithm::all(1) {
            let err = convex_hull(&points, a).unwrap_err();
            assert_eq!(err.kind(), "coordinate-out-of-range", "{what} {a:?}: {err}");
            assert!(
                err.to_string()
                    .contains("outside the range the hull's exact predicates handle"),
                "{what}: {err}"
            );
        }
    }
}

#[test]
fn coordinates_at_the_limits_of_the_range_give_the_exact_hull() {
    use topolab_structures::hull::predicates::{MAX_COORDINATE, MIN_COORDINATE};
    assert_eq!(MAX_COORDINATE, 2f64.powi(250));
    assert_eq!(MIN_COORDINATE, 2f64.powi(-250));
    // The cube's corners reach MAX_COORDINATE (4 · 2^248); its smallest non-zero coordinate is
    // MIN_COORDINATE (2 · 2^-251); and both at once, a tiny point inside a huge cube.
    let huge = scaled_cube(MAX_COORDINATE / 4.0);
    let tiny = scaled_cube(MIN_COORDINATE / 2.0);
    let mixed = [huge.clone(), vec![DVec3::splat(MIN_COORDINATE)]].concat();
    for (what, points) in [("huge", huge), ("tiny", tiny), ("mixed", mixed)] {
        for hull in check_all(&points, what) {
            assert_eq!(hull.vertices().len(), 8, "{what}");
            assert_eq!(hull.mesh.num_faces(), 12, "{what}");
        }
    }
}

#[test]
fn the_randomized_algorithm_creates_about_the_expected_number_of_faces() {
    // On a sphere every point is inserted; the lecture's lemma: E[created] ≤ 6n − 20. One run
    // is a sample, so allow a margin; the count itself must at least cover the final hull.
    let n = 2000;
    let points = random_points(Shape::Sphere, n, 11);
    let hull = convex_hull(&points, Algorithm::Randomized { seed: 5 }).unwrap();
    assert!(hull.faces_created >= hull.mesh.num_faces());
    assert!(
        (hull.faces_created as f64) < 1.1 * (6 * n - 20) as f64,
        "{} faces created for n = {n}",
        hull.faces_created
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Points on a small integer grid, with many duplicates and coplanar sets: every
    /// algorithm either refuses with a typed error (all in a plane) or returns a correct hull,
    /// and all three agree.
    #[test]
    fn small_grid_points_never_break_the_algorithms(
        coords in prop::collection::vec((0i32..4, 0i32..4, 0i32..4), 0..40)
    ) {
        let points: Vec<DVec3> = coords
            .iter()
            .map(|&(x, y, z)| DVec3::new(x as f64, y as f64, z as f64))
            .collect();
        match convex_hull(&points, Algorithm::Gift) {
            Err(e) => {
                prop_assert_eq!(e.kind(), "degenerate-points");
                for a in Algorithm::all(3) {
                    prop_assert_eq!(convex_hull(&points, a).unwrap_err().kind(), "degenerate-points");
                }
            }
            Ok(_) => {
                check_all(&points, "grid points");
            }
        }
    }
}

/// Larger point sets, many insertion orders: the randomized algorithm (one face per point
/// and the merges of the conflict lists keeping it right) finds the same vertices and volume
/// as the incremental one, which tests every face for every point.
#[test]
fn the_randomized_conflict_graph_misses_no_point_on_larger_sets() {
    for (shape, n) in [
        (Shape::Sphere, 3000),
        (Shape::Ball, 6000),
        (Shape::Cube, 6000),
    ] {
        let points = random_points(shape, n, 21);
        let reference = convex_hull(&points, Algorithm::Incremental).unwrap();
        for seed in 0..6 {
            let hull = convex_hull(&points, Algorithm::Randomized { seed }).unwrap();
            let what = format!("{shape:?} n={n} seed={seed}");
            assert_eq!(hull.vertices(), reference.vertices(), "{what}");
            let (v, r) = (hull.volume(), reference.volume());
            assert!((v - r).abs() <= 1e-9 * r, "{what}: volume {v} vs {r}");
            hull.mesh.validate().unwrap();
        }
    }
}
