//! What one edit costs in isolation: flips, edge splits and collapses of random edges of a
//! torus, one after another on one mesh, each timed alone, on the index half-edge and the
//! CHE levels 1–3 (level 0 finds every opposite by a scan: it is left to the smallest size).
//! Prints the median time per operation and its ratio to the index half-edge's, per size:
//! the CHE's edits grow with the mesh where the half-edge's do not (see the CHE's editing
//! module for why).
//!
//! ```sh
//! cargo run --release --example che_edit_cost                  # 4k, 16k, 64k triangles
//! cargo run --release --example che_edit_cost -- 1000,100000 400
//! ```

use std::time::Instant;
use topolab_harness::measuring::timing::median;
use topolab_harness::teaching::edits::edge_between;
use topolab_structures::{
    meshes, CheL0, CheL1, CheL2, CheL3, IndexHalfEdge, MeshEdit, PolygonSoup, VertexId,
};

/// The operations timed.
#[derive(Copy, Clone, Debug)]
enum Op {
    Flip,
    Split,
    Collapse,
}

/// A tiny deterministic generator (xorshift), so every structure gets the same edges.
struct Rng(u64);
impl Rng {
    fn below(&mut self, n: usize) -> usize {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 % n as u64) as usize
    }
}

/// Median nanoseconds of `count` operations `op` on random edges of `soup` in `M`, and how
/// many were refused.
fn cost<M: MeshEdit>(soup: &PolygonSoup, op: Op, count: usize) -> (f64, usize) {
    let mut m = M::from_soup(soup).expect("a manifold torus");
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let (mut times, mut refused) = (Vec::with_capacity(count), 0);
    while times.len() + refused < count {
        // A random corner of a random live face, and the next one: an edge.
        let f = rng.below(m.num_faces());
        if m.is_deleted_face(topolab_structures::FaceId::new(f)) {
            continue; // the half-edge marks deleted faces; their links are no cycle any more
        }
        let mut corners = Vec::with_capacity(3);
        m.face_vertices(topolab_structures::FaceId::new(f), |v| corners.push(v.0));
        let c = rng.below(corners.len());
        let (a, b) = (corners[c], corners[(c + 1) % corners.len()]);
        let Some(e) = edge_between(&m, a, b) else {
            continue;
        };
        let mid = (m.position(VertexId(a)) + m.position(VertexId(b))) / 2.0;
        let t = Instant::now();
        let done = match op {
            Op::Flip => m.flip_edge(e),
            Op::Split => m.split_edge(e, mid).map(drop),
            Op::Collapse => m.collapse_edge(VertexId(a), VertexId(b)),
        };
        let ns = t.elapsed().as_nanos() as f64;
        match done {
            Ok(()) => times.push(ns),
            Err(_) => refused += 1,
        }
    }
    m.validate().expect("valid after the edits");
    times.sort_by(f64::total_cmp);
    (median(&times), refused)
}

fn main() {
    let mut args = std::env::args().skip(1);
    let sizes: Vec<usize> = args
        .next()
        .map(|a| a.split(',').filter_map(|s| s.parse().ok()).collect())
        .unwrap_or_else(|| vec![4_000, 16_000, 64_000]);
    let count: usize = args.next().and_then(|a| a.parse().ok()).unwrap_or(300);
    println!("median ns per operation ({count} random edges each, one after another); ratio to index-half-edge");
    for &n in &sizes {
        let soup = meshes::torus_with_triangles(n);
        println!("\ntorus of {} triangles", soup.num_faces());
        for op in [Op::Flip, Op::Split, Op::Collapse] {
            let (base, _) = cost::<IndexHalfEdge>(&soup, op, count);
            let mut row = format!("  {:<9} index-half-edge {:>9.0}", format!("{op:?}"), base);
            let mut add = |name: &str, (ns, refused): (f64, usize)| {
                row += &format!(
                    " | {name} {ns:>10.0} ({:>6.1}x, {refused} refused)",
                    ns / base
                );
            };
            if soup.num_faces() <= 4_096 {
                add("che-l0", cost::<CheL0>(&soup, op, count));
            }
            add("che-l1", cost::<CheL1>(&soup, op, count));
            add("che-l2", cost::<CheL2>(&soup, op, count));
            add("che-l3", cost::<CheL3>(&soup, op, count));
            println!("{row}");
        }
    }
}
