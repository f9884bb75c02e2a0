//! The changing workloads (√3 subdivision, the collapse test) give the same meshes on CGAL's
//! Surface_mesh and Polyhedron_3, run natively through CGAL's Euler operations, as on the
//! lab's index half-edge.

#[cfg(not(has_cgal))]
mod common;

#[cfg(not(has_cgal))]
#[test]
fn skipped_cgal_not_compiled_in() {
    common::report_skip("cgal changing workloads", topolab::CGAL_MISSING);
    assert!(!topolab::registry::NAMES.contains(&topolab::registry::CGAL_SURFACE_MESH));
}

#[cfg(has_cgal)]
mod cgal {
    use topolab::cgal::{Polyhedron, SurfaceMesh};
    use topolab_harness::studies::changing::mesh_checksum;
    use topolab_structures::algorithms::changing::Changing;
    use topolab_structures::{meshes, IndexHalfEdge, MeshTopology};

    #[test]
    fn cgal_and_the_index_half_edge_change_meshes_alike() {
        for soup in [meshes::torus(12, 9), meshes::grid(7, 5, true)] {
            let input = mesh_checksum(&IndexHalfEdge::from_soup(&soup).expect("manifold"));
            for w in Changing::ALL {
                let mut index = IndexHalfEdge::from_soup(&soup).expect("manifold");
                w.run(&mut index).expect("runs");
                let expected = mesh_checksum(&index);
                let mut sm = SurfaceMesh::from_soup(&soup).expect("manifold");
                sm.native_changing(w).expect("Surface_mesh runs it");
                sm.validate().expect("Surface_mesh's result is valid");
                assert_eq!(mesh_checksum(&sm), expected, "Surface_mesh, {}", w.name());
                let mut poly = Polyhedron::from_soup(&soup).expect("manifold");
                poly.native_changing(w).expect("Polyhedron_3 runs it");
                poly.validate().expect("Polyhedron_3's result is valid");
                assert_eq!(mesh_checksum(&poly), expected, "Polyhedron_3, {}", w.name());
                // The workloads are not the identity, except the collapse test, which is.
                assert_eq!(w == Changing::Collapse, expected == input, "{}", w.name());
            }
        }
    }
}
