//! The changing workloads (√3 subdivision and the collapse test) on the CHE levels give the
//! index half-edge's meshes: the CHE renumbers faces and edges as it edits (see its editing
//! module), so the meshes are compared as sets of faces.

use topolab_structures::algorithms::changing::{collapse_test, sqrt3_step, to_soup};
use topolab_structures::meshes;
use topolab_structures::testing::editing::canonical_face;
use topolab_structures::{CheL0, CheL1, CheL2, CheL3, IndexHalfEdge, MeshEdit, PolygonSoup};

fn faces(m: &impl MeshEdit) -> Vec<Vec<u32>> {
    let soup = to_soup(m);
    let mut out: Vec<Vec<u32>> = soup.faces().map(canonical_face).collect();
    out.sort();
    out
}

fn after<M: MeshEdit>(
    soup: &PolygonSoup,
    work: fn(&mut M) -> topolab_structures::Result<()>,
) -> (Vec<Vec<u32>>, usize) {
    let mut m = M::from_soup(soup).expect("a manifold triangle mesh");
    work(&mut m).unwrap_or_else(|e| panic!("{}: {e}", M::NAME));
    m.validate().unwrap_or_else(|e| panic!("{}: {e}", M::NAME));
    (faces(&m), m.num_vertices())
}

fn same_as_half_edge<M: MeshEdit>() {
    for soup in [meshes::torus(6, 5), meshes::grid(4, 3, true)] {
        let before = faces(&M::from_soup(&soup).expect("manifold"));
        let (restored, nv) = after::<M>(&soup, collapse_test);
        assert_eq!(
            restored,
            before,
            "{}: the collapse test gives the mesh back",
            M::NAME
        );
        assert_eq!(
            nv,
            soup.num_vertices(),
            "{}: the new vertices are collected",
            M::NAME
        );
        let want = after::<IndexHalfEdge>(&soup, sqrt3_step);
        let got = after::<M>(&soup, sqrt3_step);
        assert_ne!(got.0, before, "√3 changes the mesh");
        assert_eq!(
            got,
            want,
            "{}: √3 gives the index half-edge's mesh",
            M::NAME
        );
    }
}

#[test]
fn the_che_levels_run_the_changing_workloads_like_the_half_edge() {
    same_as_half_edge::<CheL0>();
    same_as_half_edge::<CheL1>();
    same_as_half_edge::<CheL2>();
    same_as_half_edge::<CheL3>();
}
