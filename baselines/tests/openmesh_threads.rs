//! OpenMesh from many threads at once, in a fresh process: this file is its own test binary
//! and its first test is the process's first use of OpenMesh, where the shim's one-time,
//! process-wide set-up happens (openmesh/shim.cpp, `setup_once`). Before that set-up was made
//! thread-safe, two threads building their first mesh together corrupted OpenMesh's error
//! stream (a SIGSEGV in 1 test run of 5). `.ci/run` runs this binary and the other OpenMesh
//! test binaries repeatedly, with parallel test threads, so a race shows up in CI.

#[cfg(not(has_openmesh))]
mod common;

#[cfg(not(has_openmesh))]
#[test]
fn skipped_openmesh_not_compiled_in() {
    common::report_skip("openmesh threads", topolab_baselines::OPENMESH_MISSING);
    assert!(!topolab_baselines::compiled::COMPILED.contains(&topolab_baselines::compiled::OPENMESH));
}

#[cfg(has_openmesh)]
mod threads {
    use std::sync::{Arc, Barrier};
    use topolab_baselines::openmesh::OpenMesh;
    use topolab_structures::meshes;
    use topolab_structures::{MeshTopology, Operator, PolygonSoup};

    const THREADS: usize = 8;
    const BUILDS_PER_THREAD: usize = 40;

    /// Three triangles on one edge: OpenMesh's `add_face` refuses the third and writes to its
    /// error stream (the process-wide state of the race).
    fn refused() -> PolygonSoup {
        let positions = (0..5)
            .map(|i| glam::DVec3::new(i as f64, (i * i) as f64, 0.0))
            .collect();
        PolygonSoup::from_polygons(positions, &[[0u32, 1, 2], [1, 0, 3], [0, 1, 4]])
    }

    /// Every thread waits at a barrier, then builds meshes (accepted and refused, triangle and
    /// polygon) and sweeps them natively; every answer must equal the one computed alone.
    #[test]
    fn builds_from_eight_threads_at_once_agree_with_one_thread() {
        let inputs = Arc::new([
            meshes::torus(9, 6),
            meshes::quad_cube(),
            meshes::grid(5, 4, true),
            refused(),
        ]);
        // What one thread computes, after the parallel part (so that the first use of OpenMesh
        // in this process is the parallel one).
        let start = Arc::new(Barrier::new(THREADS));
        let workers: Vec<_> = (0..THREADS)
            .map(|t| {
                let (inputs, start) = (Arc::clone(&inputs), Arc::clone(&start));
                std::thread::spawn(move || {
                    // The first build right after the barrier, with no Rust work before it
                    // (`build_native` only checks indices), so that threads enter OpenMesh
                    // for the first time together.
                    let first = &inputs[t % inputs.len()];
                    start.wait();
                    let first = OpenMesh::build_native(first, 64).map(|om| om.num_faces());
                    let mut answers = Vec::new();
                    for b in 0..BUILDS_PER_THREAD {
                        let soup = &inputs[(t + b) % inputs.len()];
                        answers.push(((t + b) % inputs.len(), outcome(soup)));
                    }
                    (first, answers)
                })
            })
            .collect();
        let answers: Vec<_> = workers
            .into_iter()
            .map(|w| w.join().expect("a building thread panicked"))
            .collect();
        let alone: Vec<String> = inputs.iter().map(outcome).collect();
        assert!(alone[3].starts_with("refused: "), "{}", alone[3]);
        for (t, (first, thread)) in answers.iter().enumerate() {
            let input = &inputs[t % inputs.len()];
            match first {
                Ok(faces) => assert_eq!(*faces, input.num_faces(), "thread {t}'s first build"),
                Err(e) => assert!(alone[t % inputs.len()].starts_with("refused: "), "{e}"),
            }
            assert_eq!(thread.len(), BUILDS_PER_THREAD);
            for (input, answer) in thread {
                assert_eq!(answer, &alone[*input], "thread {t}, input {input}");
            }
        }
    }

    /// A build's outcome as text: the counts and every native sweep's checksum, or the error.
    fn outcome(soup: &PolygonSoup) -> String {
        match OpenMesh::from_soup(soup) {
            Ok(om) => {
                let sums: Vec<String> = Operator::ALL
                    .iter()
                    .map(|&op| match om.native_sweep(op) {
                        Ok(sum) => sum.to_string(),
                        Err(e) => format!("failed: {e}"),
                    })
                    .collect();
                format!(
                    "{} {} {} {}",
                    om.num_vertices(),
                    om.num_edges(),
                    om.num_faces(),
                    sums.join(",")
                )
            }
            Err(e) => format!("refused: {e}"),
        }
    }

    /// A C++ exception inside OpenMesh (here `std::bad_alloc` from `reserve` of 2^32 edges,
    /// about 128 GB) comes back as a typed error, not an abort ("Rust cannot catch foreign
    /// exceptions"). Where the system grants the reservation anyway (memory overcommit set to
    /// "always"), the build must still succeed and be valid.
    #[test]
    fn an_exception_inside_openmesh_is_a_typed_error() {
        let soup = meshes::torus(4, 3);
        match OpenMesh::build_native(&soup, u32::MAX as usize) {
            Err(e) => {
                assert_eq!(e.kind(), "foreign", "{e}");
                assert!(
                    e.to_string()
                        .contains("OpenMesh failed in topolab_om_build"),
                    "{e}"
                );
            }
            Ok(om) => om.validate().expect("a valid mesh"),
        }
        // The shim is still usable afterwards.
        assert!(OpenMesh::from_soup(&soup).is_ok());
    }
}
