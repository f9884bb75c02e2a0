//! The general structures built from a million-triangle torus, checked with `validate()`.
//! Slow in debug builds, so ignored by default:
//! `cargo test --release -p topolab-structures --test large_meshes -- --ignored --nocapture`.

use std::time::Instant;
use topolab_structures::{meshes, IndexHalfEdge, MeshTopology, PointerHalfEdge, PolygonSoup};

/// Builds `M`, validates it, checks the torus's counts (closed, Euler characteristic 0), and
/// prints how long building and validating took (information only, nothing is timed here).
fn build_and_validate<M: MeshTopology>(soup: &PolygonSoup) {
    let start = Instant::now();
    let mesh = M::from_soup(soup).unwrap_or_else(|e| panic!("{}: {e}", M::NAME));
    let built = start.elapsed();
    mesh.validate()
        .unwrap_or_else(|e| panic!("{}: {e}", M::NAME));
    let validated = start.elapsed() - built;
    assert_eq!(mesh.num_faces(), soup.num_faces());
    assert_eq!(mesh.num_edges(), 3 * soup.num_faces() / 2, "{}", M::NAME);
    assert_eq!(mesh.num_boundary_edges(), 0, "{}", M::NAME);
    let euler = mesh.num_vertices() as i64 - mesh.num_edges() as i64 + mesh.num_faces() as i64;
    assert_eq!(euler, 0, "{}: a torus has Euler characteristic 0", M::NAME);
    println!(
        "{:<18} {} faces: build {:>7.1} ms, validate {:>7.1} ms, heap_bytes {:.1} B/face",
        M::NAME,
        soup.num_faces(),
        built.as_secs_f64() * 1e3,
        validated.as_secs_f64() * 1e3,
        mesh.heap_bytes() as f64 / soup.num_faces() as f64
    );
}

#[test]
#[ignore = "a million triangles: run in release with --ignored"]
fn general_structures_validate_on_a_million_triangle_torus() {
    let soup = meshes::torus_with_triangles(1_000_000);
    build_and_validate::<PointerHalfEdge>(&soup);
    build_and_validate::<IndexHalfEdge>(&soup);
}
