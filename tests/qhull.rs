//! Qhull in-process (`topolab::qhull`, through `qhull/shim.c`) against SciPy's `ConvexHull`
//! (the correctness reference, `python/qhull_reference.py` in a subprocess: skipped with a
//! message without the workspace's `.venv`), against the lab's three hull algorithms, with its
//! errors typed, and from parallel threads. Seeded point sets: a ball, a sphere, and a cube
//! with coplanar points (a grid on its faces and inside, and random points on its faces).

#[cfg(not(has_qhull))]
#[test]
fn skipped_qhull_not_compiled_in() {
    eprintln!("SKIPPED qhull: {}", topolab::QHULL_MISSING);
    // The report then says how Qhull ran: not at all.
    assert_eq!(topolab::registry::qhull_description(), None);
}

#[cfg(has_qhull)]
mod in_process {
    use glam::DVec3;
    use std::path::Path;
    use topolab::qhull::{self, Failure, QhullError};
    use topolab_structures::hull::{convex_hull, random_points, Algorithm, Shape};

    /// The cube [−1, 1]³ with many coplanar points: a 5 × 5 × 5 grid (points inside, on
    /// faces and on edges) and random points on each face, in a seeded order.
    fn cube_with_coplanar_points() -> Vec<DVec3> {
        let mut points: Vec<DVec3> = (0..125)
            .map(|i| DVec3::new((i % 5) as f64, (i / 5 % 5) as f64, (i / 25) as f64) * 0.5 - 1.0)
            .collect();
        for (k, p) in random_points(Shape::Cube, 600, 11).into_iter().enumerate() {
            // Push each random point onto one of the six faces.
            let mut q = p.to_array();
            q[k % 3] = if k % 2 == 0 { 1.0 } else { -1.0 };
            points.push(DVec3::from_array(q));
        }
        points
    }

    fn point_sets() -> Vec<(&'static str, Vec<DVec3>)> {
        vec![
            ("ball", random_points(Shape::Ball, 3000, 2)),
            ("sphere", random_points(Shape::Sphere, 800, 3)),
            ("cube with coplanar points", cube_with_coplanar_points()),
        ]
    }

    #[test]
    fn qhull_in_process_builds_scipys_hull() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let Some(python) = topolab_harness::studies::hull::qhull::python(root) else {
            eprintln!(
                "SKIPPED qhull_in_process_builds_scipys_hull: no {}/.venv/bin/python with scipy (bash .ci/install-deps)",
                root.display()
            );
            return;
        };
        for (what, points) in point_sets() {
            let scipy =
                topolab_harness::studies::hull::qhull::run(&python, root, &points, 1).unwrap();
            let ours = qhull::convex_hull(&points).unwrap();
            assert_eq!(ours.vertices, scipy.vertices, "{what}: vertices");
            assert_eq!(ours.facets, scipy.simplices, "{what}: triangles");
            assert!(
                (ours.volume - scipy.volume).abs() <= 1e-12 * scipy.volume,
                "{what}: volume {} vs SciPy's {}",
                ours.volume,
                scipy.volume
            );
            assert!(ours.seconds > 0.0, "{what}: the shim's clock");
        }
    }

    #[test]
    fn the_lab_algorithms_build_qhulls_hull() {
        for (what, points) in point_sets() {
            let q = qhull::convex_hull(&points).unwrap();
            // A closed triangulated surface over the vertices.
            assert_eq!(q.facets, 2 * q.vertices.len() - 4, "{what}");
            for algorithm in Algorithm::all(5) {
                let hull = convex_hull(&points, algorithm).unwrap();
                let lab: Vec<u32> = hull.vertices().iter().map(|v| v.0).collect();
                assert_eq!(lab, q.vertices, "{what} {}: vertices", algorithm.name());
                let volume = hull.volume();
                assert!(
                    (volume - q.volume).abs() <= 1e-9 * q.volume,
                    "{what} {}: volume {volume} vs Qhull's {}",
                    algorithm.name(),
                    q.volume
                );
            }
        }
        // The cube's hull is its 8 corners: the coplanar points are no vertices.
        let cube = qhull::convex_hull(&cube_with_coplanar_points()).unwrap();
        assert_eq!(cube.vertices, [0, 4, 20, 24, 100, 104, 120, 124]);
        assert!((cube.volume - 8.0).abs() < 1e-12);
    }

    #[test]
    fn what_qhull_refuses_is_a_typed_error_with_its_message() {
        let refused = |points: &[DVec3]| match qhull::convex_hull(points) {
            Err(QhullError::Refused { failure, message }) => (failure, message),
            other => panic!("expected Qhull's refusal, got {other:?}"),
        };
        // Fewer than 4 points: Qhull's input error, through qh_new_qhull's setjmp.
        let (failure, message) = refused(&random_points(Shape::Ball, 3, 1));
        assert_eq!(failure, Failure::Input, "{message}");
        assert!(message.contains("QH6214"), "{message}");
        // All points on a plane: singular input.
        let flat: Vec<DVec3> = random_points(Shape::Cube, 100, 1)
            .into_iter()
            .map(|p| DVec3::new(p.x, p.y, 0.5))
            .collect();
        let (failure, message) = refused(&flat);
        assert_eq!(failure, Failure::Singular, "{message}");
        assert!(message.contains("QH6154"), "{message}");
        // No points at all.
        assert_eq!(refused(&[]).0, Failure::Input);
        // A NaN never reaches Qhull.
        let mut nan = random_points(Shape::Ball, 10, 1);
        nan[7].y = f64::NAN;
        let e = qhull::convex_hull(&nan).unwrap_err();
        assert!(
            matches!(
                e,
                QhullError::Points(topolab_structures::Error::NonFiniteCoordinate {
                    vertex: 7,
                    ..
                })
            ),
            "{e:?}"
        );
        // After the refusals, Qhull still builds hulls.
        assert_eq!(
            qhull::convex_hull(&cube_with_coplanar_points())
                .unwrap()
                .vertices
                .len(),
            8
        );
    }

    #[test]
    fn threads_build_hulls_in_parallel() {
        const THREADS: usize = 8;
        let sets: Vec<Vec<DVec3>> = (0..THREADS as u64)
            .map(|seed| random_points(Shape::Sphere, 2_000, seed))
            .collect();
        let alone: Vec<_> = sets
            .iter()
            .map(|p| qhull::convex_hull(p).unwrap())
            .collect();
        let barrier = std::sync::Barrier::new(THREADS);
        std::thread::scope(|scope| {
            for (points, expected) in sets.iter().zip(&alone) {
                let barrier = &barrier;
                scope.spawn(move || {
                    barrier.wait();
                    for _ in 0..10 {
                        let hull = qhull::convex_hull(points).unwrap();
                        assert_eq!(hull.vertices, expected.vertices);
                        assert_eq!(
                            (hull.facets, hull.volume),
                            (expected.facets, expected.volume)
                        );
                    }
                });
            }
        });
    }

    #[test]
    fn the_command_is_the_shims_and_the_version_the_libraries() {
        let header = std::fs::read_to_string(
            Path::new(env!("CARGO_MANIFEST_DIR")).join("baselines/c/qhull/shim.h"),
        )
        .unwrap();
        let define = header
            .lines()
            .find_map(|l| l.strip_prefix("#define TOPOLAB_QHULL_COMMAND "))
            .expect("TOPOLAB_QHULL_COMMAND in qhull/shim.h");
        assert_eq!(define.trim(), format!("\"{}\"", qhull::COMMAND));
        // Debian's libqhull-dev: Qhull 2020.2.
        let version = qhull::version();
        assert!(version.starts_with("2020.2"), "{version}");
    }
}
