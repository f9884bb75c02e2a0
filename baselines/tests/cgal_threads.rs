//! CGAL from many threads at once, in a fresh process: this file is its own test binary and
//! its first test is the process's first use of CGAL, where the shim's one-time, process-wide
//! set-up happens (cgal/shim.cpp, `setup_once`: CGAL's failure behaviour). Eight threads
//! building and sweeping meshes of both structures together must each get the answers one
//! thread gets alone. `.ci/run` runs this binary and the other baseline test binaries
//! repeatedly (`.ci/repeat-baseline-tests`), with parallel test threads, so a race shows up in
//! CI.

mod common;

#[cfg(not(has_cgal))]
#[test]
fn skipped_cgal_not_compiled_in() {
    common::report_skip("cgal threads", topolab_baselines::CGAL_MISSING);
    assert!(!topolab_baselines::compiled::COMPILED
        .contains(&topolab_baselines::compiled::CGAL_SURFACE_MESH));
}

#[cfg(has_cgal)]
mod threads {
    use super::common::broken_soups;
    use std::sync::{Arc, Barrier};
    use topolab_baselines::cgal::{self, Cgal, CgalStructure, Polyhedron, SurfaceMesh};
    use topolab_structures::hull::{random_points, Shape};
    use topolab_structures::meshes;
    use topolab_structures::{MeshTopology, Operator, PolygonSoup};

    const THREADS: usize = 8;
    const BUILDS_PER_THREAD: usize = 30;

    /// Every thread waits at a barrier, then builds meshes of both structures (accepted and
    /// refused, triangle and polygon), sweeps them natively and builds a convex hull; every
    /// answer must equal the one computed alone.
    #[test]
    fn builds_from_eight_threads_at_once_agree_with_one_thread() {
        let inputs = Arc::new([
            meshes::torus(9, 6),
            meshes::quad_cube(),
            meshes::grid(5, 4, true),
            meshes::bowtie(),
            broken_soups().swap_remove(0),
        ]);
        let start = Arc::new(Barrier::new(THREADS));
        let workers: Vec<_> = (0..THREADS)
            .map(|t| {
                let (inputs, start) = (Arc::clone(&inputs), Arc::clone(&start));
                std::thread::spawn(move || {
                    // The first build right after the barrier, with no Rust work before it
                    // (`build_native` only checks indices), so that threads enter CGAL for
                    // the first time together.
                    let first = &inputs[t % inputs.len()];
                    start.wait();
                    let first = if t % 2 == 0 {
                        SurfaceMesh::build_native(first, 64).map(|m| m.num_faces())
                    } else {
                        Polyhedron::build_native(first, 64).map(|m| m.num_faces())
                    };
                    let mut answers = Vec::new();
                    for b in 0..BUILDS_PER_THREAD {
                        let input = (t + b) % inputs.len();
                        answers.push((input, outcomes(&inputs[input])));
                    }
                    (first, answers, hull())
                })
            })
            .collect();
        let answers: Vec<_> = workers
            .into_iter()
            .map(|w| w.join().expect("a building thread panicked"))
            .collect();
        let alone: Vec<String> = inputs.iter().map(outcomes).collect();
        assert!(alone[4].contains("refused: "), "{}", alone[4]);
        let hull_alone = hull();
        for (t, (first, thread, hull)) in answers.iter().enumerate() {
            let input = &inputs[t % inputs.len()];
            match first {
                Ok(faces) => assert_eq!(*faces, input.num_faces(), "thread {t}'s first build"),
                Err(e) => assert!(alone[t % inputs.len()].contains("refused: "), "{e}"),
            }
            assert_eq!(thread.len(), BUILDS_PER_THREAD);
            for (input, answer) in thread {
                assert_eq!(answer, &alone[*input], "thread {t}, input {input}");
            }
            assert_eq!(hull, &hull_alone, "thread {t}'s hull");
        }
    }

    /// Both structures' outcomes on `soup` as text.
    fn outcomes(soup: &PolygonSoup) -> String {
        format!(
            "{} | {}",
            outcome::<cgal::SurfaceMeshClass>(soup),
            outcome::<cgal::PolyhedronClass>(soup)
        )
    }

    /// A build's outcome as text: the counts and every native sweep's checksum, or the error.
    fn outcome<S: CgalStructure>(soup: &PolygonSoup) -> String {
        match Cgal::<S>::from_soup(soup) {
            Ok(mesh) => {
                let sums: Vec<String> = Operator::ALL
                    .iter()
                    .map(|&op| match mesh.native_sweep(op) {
                        Ok(sum) => sum.to_string(),
                        Err(e) => format!("failed: {e}"),
                    })
                    .collect();
                format!(
                    "{} {} {} {}",
                    mesh.num_vertices(),
                    mesh.num_edges(),
                    mesh.num_faces(),
                    sums.join(",")
                )
            }
            Err(e) => format!("refused: {e}"),
        }
    }

    /// The hull of 2000 points in a ball (exact predicates: each thread's own FPU rounding
    /// mode switches), as counts and volume.
    fn hull() -> String {
        let h = cgal::hull::convex_hull_3(&random_points(Shape::Ball, 2000, 5), 1).unwrap();
        format!(
            "{} {} {} {}",
            h.vertices, h.faces, h.closed_triangles, h.volume
        )
    }

    /// A C++ exception inside CGAL (here `std::bad_alloc` or `std::length_error` from
    /// Surface_mesh's `reserve` of 2^32 edges, about 128 GB) comes back as a typed error, not
    /// an abort ("Rust cannot catch foreign exceptions"). Where the system grants the
    /// reservation anyway (memory overcommit set to "always"), the build must still succeed
    /// and be valid.
    #[test]
    fn an_exception_inside_cgal_is_a_typed_error() {
        let soup = meshes::torus(4, 3);
        match SurfaceMesh::build_native(&soup, u32::MAX as usize) {
            Err(e) => {
                assert_eq!(e.kind(), "foreign", "{e}");
                assert!(
                    e.to_string().contains("CGAL failed in topolab_cgal_build"),
                    "{e}"
                );
            }
            Ok(mesh) => mesh.validate().expect("a valid mesh"),
        }
        // The shim is still usable afterwards.
        assert!(SurfaceMesh::from_soup(&soup).is_ok());
    }
}
