//! The edge list and the winged-edge structure built from a million triangles (ignored by
//! default; run in release: `cargo test --release -p topolab-structures --test
//! edge_structures_at_scale -- --ignored`). Construction must stay O(n log n) and the result
//! must pass `validate()`; how long it takes is for benchmarks, not asserted here.

use topolab_structures::{meshes, MeshTopology};

fn build_and_validate<M: MeshTopology>() {
    let soup = meshes::torus_with_triangles(1_000_000);
    let m = M::from_soup(&soup).unwrap_or_else(|e| panic!("{}: {e}", M::NAME));
    m.validate().unwrap_or_else(|e| panic!("{}: {e}", M::NAME));
    assert_eq!(m.num_faces(), soup.num_faces());
    // A closed torus: Euler characteristic 0, no boundary.
    let euler = m.num_vertices() as i64 - m.num_edges() as i64 + m.num_faces() as i64;
    assert_eq!(euler, 0, "{}", M::NAME);
    assert_eq!(m.num_boundary_edges(), 0, "{}", M::NAME);
}

#[test]
#[ignore = "a million triangles: run in release with --ignored"]
fn edge_list_from_a_million_triangle_torus() {
    build_and_validate::<topolab_structures::EdgeList>();
}

#[test]
#[ignore = "a million triangles: run in release with --ignored"]
fn winged_edge_from_a_million_triangle_torus() {
    build_and_validate::<topolab_structures::WingedEdge>();
}
