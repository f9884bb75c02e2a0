//! The geometric attributes computed through the trait (`core::attributes`), on meshes whose
//! answers are known: the unit cube, a closed tetrahedron (Gauss-Bonnet), a flat grid.

use glam::DVec3;
use std::f64::consts::{PI, TAU};
use topolab_structures::{meshes, FaceId, MeshAttributes, MeshTopology, VertexId, VertexList};

#[test]
fn attributes_of_the_unit_cube_and_tetrahedron() {
    let cube = VertexList::from_soup(&meshes::quad_cube()).unwrap();
    for f in 0..6 {
        assert!((cube.face_area(FaceId(f)) - 1.0).abs() < 1e-12);
        let p = cube.face_plane(FaceId(f));
        assert!((p.normal.length() - 1.0).abs() < 1e-12);
    }
    // Outward normals: the z = 0 face points down.
    assert!((cube.face_normal(FaceId(0)) - DVec3::NEG_Z).length() < 1e-12);
    // Every cube corner has three right angles: defect π/2; every edge is a right angle.
    for v in 0..8 {
        assert!((cube.angle_defect(VertexId(v)) - PI / 2.0).abs() < 1e-12);
    }
    cube.for_each_edge(|e| {
        assert!((cube.dihedral_angle(e).unwrap() - PI / 2.0).abs() < 1e-12);
        assert!(cube.is_sharp_edge(e, 0.5));
        assert!((cube.edge_length(e) - 1.0).abs() < 1e-12);
    });
    // A closed tetrahedron: total angle defect 4π (Gauss-Bonnet).
    let tet = VertexList::from_soup(&meshes::closed_tetrahedron()).unwrap();
    let total: f64 = (0..4).map(|v| tet.angle_defect(VertexId(v))).sum();
    assert!((total - 2.0 * TAU).abs() < 1e-9);
    let n = tet.vertex_normal(VertexId(3));
    assert!(n.z > 0.99);
}

#[test]
fn a_flat_grid_has_no_curvature_inside() {
    let g = VertexList::from_soup(&meshes::grid(3, 3, true)).unwrap();
    let inner = VertexId(5);
    assert!(!g.is_boundary_vertex(inner));
    assert!(g.angle_defect(inner).abs() < 1e-12);
    // Boundary corner of the grid: a right angle, defect π/2 against π.
    assert!((g.angle_defect(VertexId(0)) - PI / 2.0).abs() < 1e-12);
}
