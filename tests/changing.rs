//! The changing workloads (√3 subdivision, the collapse test) give the same meshes on
//! OpenMesh, run natively by the protocol's C++ loop, as on the lab's editable structures.

#![cfg(has_openmesh)]

use topolab::openmesh::OpenMesh;
use topolab_harness::studies::changing::mesh_checksum;
use topolab_structures::algorithms::changing::Changing;
use topolab_structures::{meshes, IndexHalfEdge, MeshTopology, PointerHalfEdge};

#[test]
fn openmesh_and_the_half_edges_change_meshes_alike() {
    for soup in [meshes::torus(12, 9), meshes::grid(7, 5, true)] {
        for w in Changing::ALL {
            let mut om = OpenMesh::from_soup(&soup).expect("manifold");
            om.native_changing(w).expect("OpenMesh runs it");
            om.validate().expect("OpenMesh's result is valid");
            let mut index = IndexHalfEdge::from_soup(&soup).expect("manifold");
            w.run(&mut index).expect("runs");
            let mut pointer = PointerHalfEdge::from_soup(&soup).expect("manifold");
            w.run(&mut pointer).expect("runs");
            let expected = mesh_checksum(&om);
            assert_eq!(mesh_checksum(&index), expected, "{}", w.name());
            assert_eq!(mesh_checksum(&pointer), expected, "{}", w.name());
            if w == Changing::Collapse {
                let input = IndexHalfEdge::from_soup(&soup).expect("manifold");
                assert_eq!(
                    expected,
                    mesh_checksum(&input),
                    "the collapse test restores the mesh"
                );
            } else {
                assert_eq!(expected.faces, 3 * soup.num_faces());
            }
        }
    }
}

#[test]
fn openmesh_refuses_the_changing_workloads_on_polygon_meshes() {
    let mut om = OpenMesh::from_soup(&meshes::grid(3, 3, false)).expect("quads");
    let err = om.native_changing(Changing::Sqrt3).expect_err("a PolyMesh");
    assert_eq!(err.kind(), "unsupported");
}
