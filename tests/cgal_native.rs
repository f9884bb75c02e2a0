//! CGAL's native C++ sweeps and workloads give the lab's checksums for both structures, their
//! construction reports problems the way the lab's structures do, and `convex_hull_3` builds
//! the hull the lab's algorithms build. Their sampled kernels, and that the harness times every
//! cell of them natively, are checked with every baseline's in `tests/native_baselines.rs`.

#[cfg(not(has_cgal))]
#[test]
fn skipped_cgal_not_compiled_in() {
    common::report_skip("cgal native sweeps", topolab::CGAL_MISSING);
    for name in [
        topolab::registry::CGAL_SURFACE_MESH,
        topolab::registry::CGAL_POLYHEDRON,
    ] {
        assert!(!topolab::registry::NAMES.contains(&name), "{name}");
    }
}

mod common;

#[cfg(has_cgal)]
mod native {
    use super::common::{
        baseline_meshes, broken_soups, check_native_workloads, checksum, close, closed_fan_soups,
        construction_cell,
    };
    use glam::DVec3;
    use topolab::cgal::hull::convex_hull_3;
    use topolab::cgal::{self, Cgal, CgalStructure, Polyhedron, SurfaceMesh};
    use topolab_structures::hull::{convex_hull, random_points, Algorithm, Shape};
    use topolab_structures::meshes;
    use topolab_structures::{MeshTopology, Operator, VertexId, VertexList};

    /// A native answer with CGAL's own failures turned into a test failure.
    fn ok<T>(answer: topolab_structures::Result<T>) -> T {
        answer.expect("CGAL failed inside the shim")
    }

    fn native_sweeps_equal_the_checksums_of_the_lab<S: CgalStructure>() {
        for (name, soup) in baseline_meshes() {
            let mesh = Cgal::<S>::from_soup(&soup).unwrap();
            let reference = VertexList::from_soup(&soup).unwrap();
            for op in Operator::ALL {
                let expected = checksum(&reference, op);
                assert_eq!(
                    ok(mesh.native_sweep(op)),
                    expected,
                    "{} {} on {name}",
                    S::NAME,
                    op.name()
                );
                // The per-query FFI path agrees too.
                assert_eq!(
                    checksum(&mesh, op),
                    expected,
                    "{} {} per query on {name}",
                    S::NAME,
                    op.name()
                );
            }
        }
    }

    #[test]
    fn surface_mesh_sweeps_equal_the_checksums_of_the_lab() {
        native_sweeps_equal_the_checksums_of_the_lab::<cgal::SurfaceMeshClass>();
    }

    #[test]
    fn polyhedron_sweeps_equal_the_checksums_of_the_lab() {
        native_sweeps_equal_the_checksums_of_the_lab::<cgal::PolyhedronClass>();
    }

    #[test]
    fn checksums_see_the_boundary() {
        let grid = meshes::grid(6, 4, true);
        let (sm, ph) = (
            SurfaceMesh::from_soup(&grid).unwrap(),
            Polyhedron::from_soup(&grid).unwrap(),
        );
        for op in [
            Operator::BoundaryVertex,
            Operator::BoundaryEdge,
            Operator::BoundaryCurves,
        ] {
            assert_ne!(ok(sm.native_sweep(op)), 0, "{op:?} on a grid");
            assert_ne!(ok(ph.native_sweep(op)), 0, "{op:?} on a grid");
        }
    }

    fn workloads_compute_what_the_benchmark_says<S: CgalStructure>() {
        check_native_workloads(
            |soup| Cgal::<S>::from_soup(soup).unwrap(),
            |mesh, w| ok(mesh.prepare_workload(w)),
            |mesh, w| ok(mesh.native_workload(w)),
            |mesh, v| mesh.position(VertexId::new(v)),
        );
    }

    #[test]
    fn workloads_compute_what_the_benchmark_says_in_both() {
        workloads_compute_what_the_benchmark_says::<cgal::SurfaceMeshClass>();
        workloads_compute_what_the_benchmark_says::<cgal::PolyhedronClass>();
    }

    #[test]
    fn heap_bytes_are_what_the_records_take() {
        for soup in [
            meshes::torus_with_triangles(60_000),
            meshes::grid(90, 70, true),
        ] {
            // Surface_mesh: 28 B per vertex (point, halfedge), 16 per halfedge (face, vertex,
            // next, prev), 4 per face, and a removed-flag bit per vertex, edge and face.
            let sm = SurfaceMesh::from_soup(&soup).unwrap();
            let (v, e, f) = (sm.num_vertices(), sm.num_edges(), sm.num_faces());
            let bits = |n: usize| n.div_ceil(8);
            let records = 28 * v + 32 * e + 4 * f + bits(v) + bits(e) + bits(f);
            assert_eq!(sm.heap_bytes(), records, "Surface_mesh");
            // Polyhedron_3 with ids: list nodes of 56 B per vertex (links, point, halfedge,
            // id), 64 per halfedge (links, five handles, id), 32 per facet (links, halfedge,
            // id), and 8 B per entry of the tables by id, reserved exactly.
            let ph = Polyhedron::from_soup(&soup).unwrap();
            let records = 56 * v + 2 * 64 * e + 32 * f + 8 * (v + e + f);
            assert_eq!(ph.heap_bytes(), records, "Polyhedron_3");
        }
    }

    fn the_report_counts_cgals_own_build_by_its_blocks<S: CgalStructure>(most: f64) {
        for soup in [
            meshes::torus_with_triangles(60_000),
            meshes::grid(90, 70, true),
        ] {
            let cell = construction_cell::<Cgal<S>>(&soup);
            let held = cell.bytes.unwrap() as f64;
            let peak = cell.peak_bytes.unwrap() as f64;
            let declared = cell.declared_bytes.unwrap() as f64;
            eprintln!(
                "{}: {held} B held, {peak} B at the peak, {declared} B declared",
                S::NAME
            );
            // Counted by the lab's operator new: at least the records, and at most `most`
            // times them (each block rounded up by glibc).
            assert!(
                held >= declared && held <= most * declared,
                "{}: {held} B held, {declared} declared",
                S::NAME
            );
            // The peak is the library's construction, not the lab's checks before it (whose
            // edge analysis peaks at nearly the mesh's size): told the exact counts, neither
            // class grows an array, and the builder's own maps, freed at its end, are smaller
            // than the id tables made after it.
            assert!(
                peak >= held && peak < 1.01 * held,
                "{}: peak {peak}, held {held}",
                S::NAME
            );
        }
    }

    #[test]
    fn the_report_counts_cgals_own_build_by_its_blocks_in_both() {
        // Surface_mesh: a few property arrays, each rounded up by a few bytes.
        the_report_counts_cgals_own_build_by_its_blocks::<cgal::SurfaceMeshClass>(1.01);
        // Polyhedron_3: a block per node, its 56, 128 and 32 bytes handed out as 56, 136 and
        // 40 (glibc's 16-byte steps, less its 8-byte size field): 296 B per triangle of a
        // closed mesh for 276 declared.
        the_report_counts_cgals_own_build_by_its_blocks::<cgal::PolyhedronClass>(1.08);
    }

    fn refusals_name_elements_like_the_lab<S: CgalStructure>() {
        for soup in broken_soups() {
            let lab = VertexList::from_soup(&soup).unwrap_err().to_string();
            let checked = Cgal::<S>::from_soup(&soup).unwrap_err().to_string();
            // CGAL refuses the face too; the error still names it the lab's way.
            let native = Cgal::<S>::build_native(&soup, 8).unwrap_err().to_string();
            assert_eq!(checked, lab, "{}", S::NAME);
            assert_eq!(native, lab, "{}", S::NAME);
        }
    }

    #[test]
    fn refusals_name_elements_like_the_lab_in_both() {
        refusals_name_elements_like_the_lab::<cgal::SurfaceMeshClass>();
        refusals_name_elements_like_the_lab::<cgal::PolyhedronClass>();
    }

    fn a_closed_fan_is_refused_in_any_order<S: CgalStructure>() {
        for soup in closed_fan_soups() {
            let checked = Cgal::<S>::from_soup(&soup).unwrap_err();
            assert_eq!(
                checked.kind(),
                "non-manifold-vertex",
                "{}: {checked}",
                S::NAME
            );
            // CGAL refuses it as well, named the same way.
            let native = Cgal::<S>::build_native(&soup, 16).unwrap_err();
            assert_eq!(native.to_string(), checked.to_string(), "{}", S::NAME);
        }
        // Open fans (the bowtie) are stored; the conformance suite checks the answers.
        assert!(Cgal::<S>::from_soup(&meshes::bowtie()).is_ok());
    }

    #[test]
    fn a_closed_fan_at_a_non_manifold_vertex_is_refused_in_any_order() {
        a_closed_fan_is_refused_in_any_order::<cgal::SurfaceMeshClass>();
        a_closed_fan_is_refused_in_any_order::<cgal::PolyhedronClass>();
    }

    #[test]
    fn explain_shows_every_record() {
        let soup = meshes::open_tetrahedron();
        for (text, name) in [
            (
                explain(&SurfaceMesh::from_soup(&soup).unwrap()),
                "Surface_mesh",
            ),
            (
                explain(&Polyhedron::from_soup(&soup).unwrap()),
                "Polyhedron_3",
            ),
        ] {
            assert!(text.contains(name), "{text}");
            // 4 vertices, 12 halfedges (3 of them border ones), 3 faces.
            assert_eq!(text.matches("\n  v").count(), 4, "{text}");
            assert_eq!(text.matches("\n  h").count(), 12, "{text}");
            assert_eq!(text.matches("face -").count(), 3, "{text}");
            assert_eq!(text.matches("\n  f").count(), 3, "{text}");
        }
    }

    fn explain(m: &impl MeshTopology) -> String {
        let mut text = String::new();
        m.explain(&mut text).unwrap();
        text
    }

    #[test]
    fn convex_hull_3_builds_the_hull_the_lab_builds() {
        for (shape, n) in [
            (Shape::Ball, 3000),
            (Shape::Sphere, 500),
            (Shape::Cube, 2000),
        ] {
            let points = random_points(shape, n, 11);
            let lab = convex_hull(&points, Algorithm::Randomized { seed: 3 }).unwrap();
            let cgal = convex_hull_3(&points, 2).unwrap();
            // Random points are in general position: the hull's triangulation is unique.
            assert_eq!(cgal.vertices, lab.vertices().len(), "{shape:?}");
            assert_eq!(cgal.faces, lab.mesh.num_faces(), "{shape:?}");
            assert!(cgal.closed_triangles, "{shape:?}");
            assert!(close(cgal.volume, lab.volume()), "{shape:?}");
            assert!(cgal.seconds > 0.0 && cgal.seconds.is_finite());
        }
    }

    #[test]
    fn convex_hull_3_refuses_what_the_lab_refuses() {
        let plane: Vec<DVec3> = (0..20)
            .map(|i| DVec3::new(i as f64, (i * i % 7) as f64, 0.0))
            .collect();
        let mut nan = random_points(Shape::Ball, 10, 1);
        nan[4].y = f64::NAN;
        for points in [plane, nan, vec![DVec3::ONE; 3]] {
            let lab = convex_hull(&points, Algorithm::Gift).unwrap_err();
            let cgal = convex_hull_3(&points, 1).unwrap_err();
            assert_eq!(cgal.to_string(), lab.to_string());
        }
    }
}
