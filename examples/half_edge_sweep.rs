//! What pointer chasing costs: the 1-ring (R00), vertex-face (R02) and face-face (R22) sweeps
//! of the pointer half-edge against the index half-edge on a 1M-triangle torus, median of 7,
//! with the harness checksums (the same numbers OpenMesh's sweeps must produce).
//!
//! `cargo run --release --example half_edge_sweep`

use std::hint::black_box;
use std::time::Instant;
use topolab_harness::checksum::mix;
use topolab_structures::{
    meshes, FaceId, IndexHalfEdge, MeshTopology, PointerHalfEdge, PolygonSoup, VertexId,
};

/// The median of 7 runs of `sweep`, in seconds, and its checksum.
fn median_of_7(mut sweep: impl FnMut() -> u64) -> (f64, u64) {
    let mut times = Vec::with_capacity(7);
    let mut checksum = 0;
    for _ in 0..7 {
        let start = Instant::now();
        checksum = black_box(sweep());
        times.push(start.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (times[3], checksum)
}

/// Runs `each` for elements `0..count`, which folds its answers into the returned checksum.
#[inline(always)]
fn sweep(count: usize, mut each: impl FnMut(u32, &mut u64)) -> u64 {
    let mut sum = 0u64;
    for x in 0..count as u32 {
        each(x, &mut sum);
    }
    sum
}

/// Adds one answer `b` of element `a` to the checksum (the harness's per-operator term).
#[inline(always)]
fn add(sum: &mut u64, a: u32, b: u32) {
    *sum = sum.wrapping_add(mix(a as u64, b as u64));
}

fn measure<M: MeshTopology>(soup: &PolygonSoup) {
    let start = Instant::now();
    let m = M::from_soup(soup).expect("a torus is manifold");
    let build = start.elapsed().as_secs_f64();
    let (nv, nf) = (m.num_vertices(), m.num_faces());
    let (r00, c00) = median_of_7(|| {
        sweep(nv, |v, sum| {
            m.vertex_vertices(VertexId(v), |w| add(sum, v, w.0))
        })
    });
    let (r02, c02) = median_of_7(|| {
        sweep(nv, |v, sum| {
            m.vertex_faces(VertexId(v), |f| add(sum, v, f.0))
        })
    });
    let (r22, c22) =
        median_of_7(|| sweep(nf, |f, sum| m.face_faces(FaceId(f), |g| add(sum, f, g.0))));
    println!(
        "{:<18} build {:>6.1} ns/face | r00 {:>5.1} ns/vertex ({c00:016x}) | r02 {:>5.1} ns/vertex ({c02:016x}) | r22 {:>5.1} ns/face ({c22:016x}) | {:.1} B/face",
        M::NAME,
        build * 1e9 / nf as f64,
        r00 * 1e9 / nv as f64,
        r02 * 1e9 / nv as f64,
        r22 * 1e9 / nf as f64,
        m.heap_bytes() as f64 / nf as f64,
    );
}

fn main() {
    let soup = meshes::torus_with_triangles(1_000_000);
    println!(
        "torus: {} vertices, {} triangles (ordered ring by ring)",
        soup.num_vertices(),
        soup.num_faces()
    );
    measure::<IndexHalfEdge>(&soup);
    measure::<PointerHalfEdge>(&soup);
}
