//! The meshes' tests: the generators and the names the command line gives them make the
//! surfaces they name, checked with the oracle (from the testing room, above the meshes: so
//! these run as an integration test).

use topolab_structures::meshes::*;
use topolab_structures::testing::oracle::Oracle;
use topolab_structures::PolygonSoup;

/// V - E + F and the boundary curves, both from the edge analysis and from the oracle.
fn euler_and_curves(s: &PolygonSoup) -> (i64, usize) {
    let c = s.connectivity().unwrap();
    c.check_vertex_fans(s).unwrap();
    let euler = s.num_vertices() as i64 - c.num_edges() as i64 + s.num_faces() as i64;
    let oracle = Oracle::new(s);
    assert_eq!(oracle.edge_faces.len(), c.num_edges());
    assert!(
        oracle.vertex_faces.iter().all(|f| !f.is_empty()),
        "unused vertex"
    );
    (
        euler,
        oracle.boundary_curve_count().expect("simple boundary"),
    )
}

#[test]
fn generators_give_closed_surfaces_with_the_right_euler_characteristic() {
    for (s, chi) in [
        (torus(5, 4), 0),
        (sphere(4, 6), 2),
        (closed_tetrahedron(), 2),
    ] {
        let c = s.connectivity().unwrap();
        assert!(c.edge_corners.iter().all(|e| e[1] != u32::MAX));
        let euler = s.num_vertices() as i64 - c.num_edges() as i64 + s.num_faces() as i64;
        assert_eq!(euler, chi);
    }
    let t = torus_with_triangles(1000).num_faces();
    assert!((950..=1050).contains(&t), "{t} triangles");
}

#[test]
fn random_meshes_are_reproducible() {
    let p = RandomMeshParams::default();
    assert_eq!(random_mesh(7, p), random_mesh(7, p));
    assert_ne!(random_mesh(7, p), random_mesh(8, p));
}

#[test]
fn perforated_plates_have_the_requested_genus_and_boundary_curves() {
    for (genus, holes) in [
        (0, 0),
        (1, 0),
        (2, 0),
        (3, 0),
        (5, 0),
        (0, 1),
        (0, 3),
        (2, 2),
    ] {
        for triangles in [200, 3000] {
            let s = perforated_plate(genus, holes, triangles);
            let (euler, curves) = euler_and_curves(&s);
            assert_eq!(
                euler,
                2 - 2 * genus as i64 - holes as i64,
                "g{genus} k{holes}"
            );
            assert_eq!(curves, holes, "g{genus} k{holes}");
            assert_eq!(Oracle::new(&s).face_components(), 1);
            assert!(s.is_triangle_mesh());
        }
    }
    let s = perforated_plate(3, 0, 100_000).num_faces();
    assert!((90_000..=110_000).contains(&s), "{s} triangles");
}

#[test]
fn mixed_grid_has_every_face_size_from_three_to_six_and_one_boundary() {
    let s = mixed_grid(2000);
    let (euler, curves) = euler_and_curves(&s);
    assert_eq!((euler, curves), (1, 1));
    for k in 3..=6 {
        assert!(s.faces().any(|f| f.len() == k), "no {k}-gon");
    }
    assert!((1800..=2200).contains(&s.num_faces()), "{}", s.num_faces());
}

#[test]
fn perturbation_is_seeded_bounded_and_keeps_the_faces() {
    let s = torus(6, 4);
    let p = perturb(&s, 0.01, 3);
    assert_eq!(p, perturb(&s, 0.01, 3));
    assert_ne!(p, perturb(&s, 0.01, 4));
    assert!(p.faces().eq(s.faces()));
    for (a, b) in s.positions.iter().zip(&p.positions) {
        let d = (*a - *b).abs().max_element();
        assert!(d > 0.0 && d <= 0.01, "moved by {d}");
    }
}

#[test]
fn specs_name_the_generators() {
    let g = from_spec("genus:2:1_000").unwrap();
    assert_eq!(euler_and_curves(&g), (-2, 0));
    let h = from_spec("holes:4:1000").unwrap();
    assert_eq!(euler_and_curves(&h), (-2, 4));
    let m = from_spec("surface:1:2:1000").unwrap();
    assert_eq!(euler_and_curves(&m), (-2, 2));
    assert_eq!(from_spec("mixed:500").unwrap(), mixed_grid(500));
    for unknown in [
        "genus:2",
        "holes:x:10",
        "torus:100:3",
        "torus:-5",
        "torus:",
        "cube:10",
    ] {
        assert_eq!(
            from_spec(unknown).unwrap_err(),
            SpecError::Unknown,
            "{unknown}"
        );
    }
}
