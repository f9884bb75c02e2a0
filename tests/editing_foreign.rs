//! The editing suite ([`topolab_structures::testing::editing`]) on the C++ baselines that edit
//! through their own Euler operations: one line each. Each structure's tests run in parallel
//! threads on independent meshes, as the conformance tests do (the shims' one process-wide
//! set-up is thread-safe: `baselines/tests/openmesh_threads.rs`, `baselines/tests/cgal_threads.rs`).

#[cfg(has_openmesh)]
topolab_structures::edit_conformance!(
    openmesh,
    topolab::openmesh::OpenMesh,
    not_implemented_on_polygons
);

#[cfg(has_cgal)]
topolab_structures::edit_conformance!(cgal_surface_mesh, topolab::cgal::SurfaceMesh);

#[cfg(has_cgal)]
topolab_structures::edit_conformance!(cgal_polyhedron, topolab::cgal::Polyhedron);

/// `Polyhedron_3` beyond the suite: its ids are tables kept beside CGAL's lists (see
/// `topolab::cgal`'s edit module), so these check what those tables must keep.
#[cfg(has_cgal)]
mod polyhedron {
    use topolab::cgal::Polyhedron;
    use topolab_harness::studies::changing::mesh_checksum;
    use topolab_structures::algorithms::changing::Changing;
    use topolab_structures::testing::editing;
    use topolab_structures::{
        meshes, EdgeId, Error, FaceId, MeshEdit, MeshTopology, PolygonSoup, Refusal, VertexId,
    };

    fn reason<T: std::fmt::Debug>(got: Result<T, Error>) -> Refusal {
        match got {
            Err(Error::EditRefused { reason, .. }) => reason,
            other => panic!("not refused: {other:?}"),
        }
    }

    #[test]
    fn changing_workloads_through_mesh_edit_agree_with_the_native_run() {
        for soup in [meshes::torus(12, 9), meshes::grid(7, 5, true)] {
            for w in Changing::ALL {
                let mut native = Polyhedron::from_soup(&soup).expect("manifold");
                native.native_changing(w).expect("runs natively");
                let mut edited = Polyhedron::from_soup(&soup).expect("manifold");
                w.run(&mut edited).expect("runs through MeshEdit");
                edited.validate().expect("valid after the workload");
                assert_eq!(
                    mesh_checksum(&edited),
                    mesh_checksum(&native),
                    "{}",
                    w.name()
                );
            }
        }
    }

    #[test]
    fn refused_edits_change_nothing_and_deleted_ids_stay_until_collected() {
        let soup = meshes::grid(4, 3, true);
        let mut m = Polyhedron::from_soup(&soup).expect("manifold");
        let before = mesh_checksum(&m);
        let [v, e, f] = [m.num_vertices(), m.num_edges(), m.num_faces()];
        let first: Vec<VertexId> = {
            let mut corners = Vec::new();
            m.face_vertices(FaceId(0), |v| corners.push(v));
            corners
        };
        let far = VertexId(v as u32 - 1);
        let boundary = (0..e as u32)
            .map(EdgeId)
            .find(|&e| m.is_boundary_edge(e))
            .expect("a grid has a boundary");
        assert_eq!(reason(m.add_face(&first)), Refusal::NonManifoldEdge);
        assert_eq!(
            reason(m.collapse_edge(VertexId(0), far)),
            Refusal::NotNeighbours
        );
        assert_eq!(reason(m.flip_edge(boundary)), Refusal::BoundaryEdge);
        assert_eq!(
            reason(m.delete_face(FaceId(f as u32))),
            Refusal::NoSuchElement
        );
        assert_eq!(mesh_checksum(&m), before);
        assert_eq!([m.num_vertices(), m.num_edges(), m.num_faces()], [v, e, f]);

        // A deleted face keeps its id, refused as missing, and reading it is harmless.
        let gone = (0..f as u32)
            .map(FaceId)
            .find(|&g| m.delete_face(g).is_ok())
            .expect("some face can go");
        assert!(m.is_deleted_face(gone));
        assert_eq!(m.num_faces(), f);
        assert_eq!(reason(m.delete_face(gone)), Refusal::NoSuchElement);
        m.face_vertices(gone, |_| {});
        m.face_faces(gone, |_| {});
        m.validate().expect("valid with a deleted face");

        // Collected: the survivors keep their order, as a build without that face numbers them.
        m.garbage_collection();
        assert_eq!(m.num_faces(), f - 1);
        let faces: Vec<Vec<u32>> = soup
            .faces()
            .enumerate()
            .filter(|&(g, _)| g != gone.0 as usize)
            .map(|(_, c)| c.to_vec())
            .collect();
        let rest = PolygonSoup::from_polygons(soup.positions.clone(), &faces);
        let rebuilt = Polyhedron::from_soup(&rest).expect("manifold");
        assert_eq!(mesh_checksum(&m), mesh_checksum(&rebuilt));
    }

    #[test]
    fn polyhedra_edit_in_parallel_threads() {
        let threads: Vec<_> = (0..4u64)
            .map(|t| {
                std::thread::spawn(move || {
                    (t * 25..t * 25 + 25)
                        .map(|seed| editing::run::<Polyhedron>(seed, 40))
                        .collect::<Result<Vec<_>, String>>()
                })
            })
            .collect();
        for t in threads {
            let runs = t.join().expect("no panic").expect("agrees with the model");
            assert!(runs.iter().map(|(done, _)| done).sum::<usize>() > 200);
        }
    }
}

#[cfg(not(any(has_openmesh, has_cgal)))]
mod common;

#[cfg(not(any(has_openmesh, has_cgal)))]
#[test]
fn skipped_no_baseline_compiled_in() {
    common::report_skip("foreign editing", topolab::OPENMESH_MISSING);
    assert!(!topolab::registry::NAMES.contains(&topolab::registry::OPENMESH));
}
