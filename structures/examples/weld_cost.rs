//! What one vertex weld costs on the half-edges, against the mesh size: a cylinder of `w`
//! columns and `h` rows of squares (two triangles each), capped at the bottom and cut open
//! along one column from the cap's rim up, is zipped shut by welding the seam's two copies of each vertex bottom
//! to top (`weld_vertices`), each weld merging one pair of boundary edges.
//! Prints nanoseconds per weld (the median of the rounds) per structure and size; the weld is
//! O(valence), so the time should not grow with h. The winged-edge (a face rewrite, also
//! O(k)) runs beside for comparison, and the four CHE levels, whose weld rebuilds every
//! container from `V[]` (O(n)), so their time should grow with h: they weld only the seam's
//! first [`CHE_WELDS`] rows (every weld rebuilds the whole mesh, so a full zip would be
//! quadratic), in microseconds.
//!
//! ```sh
//! cargo run --release -p topolab-structures --example weld_cost             # h = 100, 1000, 8000
//! cargo run --release -p topolab-structures --example weld_cost -- 100,10000 5
//! ```

use glam::DVec3;
use std::time::Instant;
use topolab_structures::{
    CheL0, CheL1, CheL2, CheL3, IndexHalfEdge, MeshEdit, PointerHalfEdge, PolygonSoup, VertexId,
    WingedEdge,
};

const W: u32 = 64;

/// The rows the CHE levels weld per round: each weld costs a rebuild of the whole mesh.
const CHE_WELDS: u32 = 16;

/// The slit cylinder: vertex (i, j) is `j * (W + 1) + i`; column W lies on column 0 and is
/// its copy (the seam), except that row 0 uses vertex (0, 0) on both sides; the cap's centre
/// is the last vertex.
fn slit_cylinder(h: u32) -> PolygonSoup {
    let id = |i: u32, j: u32| if i == W && j == 0 { 0 } else { j * (W + 1) + i };
    let mut positions = Vec::new();
    for j in 0..=h {
        for i in 0..=W {
            let t = (i % W) as f64 / W as f64 * std::f64::consts::TAU;
            positions.push(DVec3::new(t.cos(), t.sin(), j as f64 / W as f64));
        }
    }
    // A cap closes the bottom, so that the slit ends at a vertex inside the surface.
    let cap = positions.len() as u32;
    positions.push(DVec3::new(0.0, 0.0, -1.0));
    let mut faces: Vec<Vec<u32>> = (0..W).map(|i| vec![cap, id(i + 1, 0), id(i, 0)]).collect();
    for j in 0..h {
        for i in 0..W {
            faces.push(vec![id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            faces.push(vec![id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    PolygonSoup::from_polygons(positions, &faces)
}

/// Nanoseconds per weld of zipping the seam of `soup` (`h` rows) in `M` up to row `rows`
/// (the median of `rounds`).
fn zip<M: MeshEdit>(soup: &PolygonSoup, rows: u32, rounds: usize) -> f64 {
    let mut times = Vec::new();
    for _ in 0..rounds {
        let mut m = M::from_soup(soup).expect("a slit cylinder builds");
        let start = Instant::now();
        for j in 1..=rows {
            m.weld_vertices(VertexId(j * (W + 1)), VertexId(j * (W + 1) + W))
                .unwrap_or_else(|e| panic!("{}: weld of row {j}: {e}", M::NAME));
        }
        times.push(start.elapsed().as_nanos() as f64 / rows as f64);
        m.validate().expect("valid after the zip");
    }
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let heights: Vec<u32> = args
        .get(1)
        .map(|s| s.split(',').map(|x| x.parse().expect("a height")).collect())
        .unwrap_or_else(|| vec![100, 1000, 8000]);
    let rounds: usize = args.get(2).map_or(5, |s| s.parse().expect("a count"));
    println!(
        "{:>8} {:>10} {:>18} {:>18} {:>18} {:>12} {:>12} {:>12} {:>12}",
        "rows",
        "faces",
        "index-half-edge",
        "pointer-half-edge",
        "winged-edge",
        "che-l0",
        "che-l1",
        "che-l2",
        "che-l3"
    );
    for h in heights {
        let soup = slit_cylinder(h);
        let che = h.min(CHE_WELDS);
        println!(
            "{h:>8} {:>10} {:>15.0} ns {:>15.0} ns {:>15.0} ns {:>9.0} µs {:>9.0} µs {:>9.0} µs {:>9.0} µs",
            soup.num_faces(),
            zip::<IndexHalfEdge>(&soup, h, rounds),
            zip::<PointerHalfEdge>(&soup, h, rounds),
            zip::<WingedEdge>(&soup, h, rounds),
            zip::<CheL0>(&soup, che, rounds) / 1e3,
            zip::<CheL1>(&soup, che, rounds) / 1e3,
            zip::<CheL2>(&soup, che, rounds) / 1e3,
            zip::<CheL3>(&soup, che, rounds) / 1e3,
        );
    }
}
