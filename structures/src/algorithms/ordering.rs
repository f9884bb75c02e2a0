//! Vertex and face orderings: the same mesh with its elements numbered differently.
//!
//! Element order changes traversal cost many times over: a vertex-vertex sweep reads the
//! neighbours of each vertex in turn, and when neighbours have nearby numbers their data
//! shares cache lines. A Loop-subdivided mesh whose new vertices were appended (see `refine`)
//! scatters them, and OpenMesh's sweep of it is far slower per vertex than its sweep of an
//! ordered torus (the report's "Real meshes at scale" section sets the two side by side). The
//! report's "Element order" section runs the 1-ring sweep under each ordering to show it.
//!
//! | ordering | vertex order |
//! |---|---|
//! | `input` | as given (the soup unchanged, faces too) |
//! | `random` | a seeded random permutation: the worst case for caches |
//! | `morton` | along the Z-order curve of the positions (21 bits per axis in the bounding box) |
//! | `hilbert` | along the 3D Hilbert curve (21 bits per axis): no jumps between octants |
//! | `bfs` | breadth first over vertex-vertex adjacency, from vertex 0, then the next unvisited vertex |
//!
//! Faces follow the vertices, one rule for every ordering but `input`: sorted by their smallest
//! new vertex, ties kept in input order. So faces around a vertex are near each other when the
//! vertex's neighbours are. Corners keep their order within each face (orientation and the
//! starting corner are unchanged).

use crate::core::soup::PolygonSoup;
use glam::DVec3;
use rand::seq::SliceRandom;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// How to number the vertices (faces follow: see the module documentation).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Ordering {
    /// The input order.
    Input,
    /// A random permutation from a seed.
    Random(u64),
    /// Morton (Z-order) curve of the positions.
    Morton,
    /// Hilbert curve of the positions.
    Hilbert,
    /// Breadth-first over the vertex-vertex adjacency.
    BreadthFirst,
}

impl Ordering {
    /// The orderings the benchmarks compare (random with seed 1).
    pub const ALL: [Ordering; 5] = [
        Ordering::Input,
        Ordering::Random(1),
        Ordering::Morton,
        Ordering::Hilbert,
        Ordering::BreadthFirst,
    ];

    /// The name used in reports and on the command line (`random` takes seed 1; `random:S`
    /// another seed).
    pub fn name(self) -> String {
        match self {
            Ordering::Input => "input".into(),
            Ordering::Random(1) => "random".into(),
            Ordering::Random(seed) => format!("random:{seed}"),
            Ordering::Morton => "morton".into(),
            Ordering::Hilbert => "hilbert".into(),
            Ordering::BreadthFirst => "bfs".into(),
        }
    }

    /// The ordering of a name given by [`Ordering::name`].
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "input" => Some(Ordering::Input),
            "random" => Some(Ordering::Random(1)),
            "morton" => Some(Ordering::Morton),
            "hilbert" => Some(Ordering::Hilbert),
            "bfs" => Some(Ordering::BreadthFirst),
            _ => name
                .strip_prefix("random:")
                .and_then(|s| s.parse().ok())
                .map(Ordering::Random),
        }
    }
}

/// A reordered mesh with the maps back to its input.
#[derive(Clone, Debug)]
pub struct Reordered {
    /// The mesh in its new order.
    pub soup: PolygonSoup,
    /// Per input vertex, its new number.
    pub new_vertex: Vec<u32>,
    /// Per new face, its input number.
    pub old_face: Vec<u32>,
}

/// `soup` in the order `ordering` gives. O(V log V + F log F) (O(V + C) for `bfs`, plus the
/// face sort), linear memory.
pub fn reorder(soup: &PolygonSoup, ordering: Ordering) -> Reordered {
    let nv = soup.num_vertices();
    // Vertices listed in their new order: visit[k] is the input vertex that becomes k.
    let visit: Vec<u32> = match ordering {
        Ordering::Input => {
            return Reordered {
                soup: soup.clone(),
                new_vertex: (0..nv as u32).collect(),
                old_face: (0..soup.num_faces() as u32).collect(),
            }
        }
        Ordering::Random(seed) => {
            let mut v: Vec<u32> = (0..nv as u32).collect();
            v.shuffle(&mut ChaCha8Rng::seed_from_u64(seed));
            v
        }
        Ordering::Morton => by_curve(&soup.positions, morton),
        Ordering::Hilbert => by_curve(&soup.positions, hilbert),
        Ordering::BreadthFirst => breadth_first(soup),
    };
    let mut new_vertex = vec![0u32; nv];
    for (k, &v) in visit.iter().enumerate() {
        new_vertex[v as usize] = k as u32;
    }
    let relabelled = soup.relabel_vertices(&new_vertex);
    // Faces by smallest new vertex, ties in input order: one sort of (key, face) pairs.
    let mut keys: Vec<u64> = relabelled
        .faces()
        .enumerate()
        .map(|(j, f)| ((*f.iter().min().unwrap_or(&0) as u64) << 32) | j as u64)
        .collect();
    keys.sort_unstable();
    let old_face: Vec<u32> = keys.iter().map(|&k| k as u32).collect();
    Reordered {
        soup: relabelled.reorder_faces(&old_face),
        new_vertex,
        old_face,
    }
}

/// Vertices sorted by the curve index `key` gives their quantised positions (ties by number).
fn by_curve(positions: &[DVec3], key: fn([u32; 3]) -> u64) -> Vec<u32> {
    const BITS: u32 = 21;
    let (lo, hi) = positions.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), &p| (lo.min(p), hi.max(p)),
    );
    let max = ((1u32 << BITS) - 1) as f64;
    // The same scale on every axis, so the curve's cells are cubes.
    let extent = (hi - lo).max_element();
    let scale = if extent > 0.0 { max / extent } else { 0.0 };
    let mut keyed: Vec<(u64, u32)> = positions
        .iter()
        .enumerate()
        .map(|(i, &p)| {
            let q = ((p - lo) * scale).clamp(DVec3::ZERO, DVec3::splat(max));
            (key([q.x as u32, q.y as u32, q.z as u32]), i as u32)
        })
        .collect();
    keyed.sort_unstable();
    keyed.into_iter().map(|(_, i)| i).collect()
}

/// Spreads the low 21 bits of `x` to every third bit.
fn spread(x: u32) -> u64 {
    let mut x = x as u64 & 0x1f_ffff;
    x = (x | (x << 32)) & 0x1f_0000_0000_ffff;
    x = (x | (x << 16)) & 0x1f_0000_ff00_00ff;
    x = (x | (x << 8)) & 0x100f_00f0_0f00_f00f;
    x = (x | (x << 4)) & 0x10c3_0c30_c30c_30c3;
    x = (x | (x << 2)) & 0x1249_2492_4924_9249;
    x
}

/// The Morton code: the bits of x, y, z interleaved (z highest).
fn morton([x, y, z]: [u32; 3]) -> u64 {
    spread(x) | (spread(y) << 1) | (spread(z) << 2)
}

/// The Hilbert index of a point with 21-bit coordinates (Skilling's transposition, "Programming
/// the Hilbert curve", 2004): coordinates to the transposed index, then interleaved.
fn hilbert(mut x: [u32; 3]) -> u64 {
    const BITS: u32 = 21;
    // Inverse undo of excess work.
    let mut q = 1u32 << (BITS - 1);
    while q > 1 {
        let p = q - 1;
        for i in 0..3 {
            if x[i] & q != 0 {
                x[0] ^= p;
            } else {
                let t = (x[0] ^ x[i]) & p;
                x[0] ^= t;
                x[i] ^= t;
            }
        }
        q >>= 1;
    }
    // Gray encode.
    x[1] ^= x[0];
    x[2] ^= x[1];
    let mut t = 0;
    let mut q = 1u32 << (BITS - 1);
    while q > 1 {
        if x[2] & q != 0 {
            t ^= q - 1;
        }
        q >>= 1;
    }
    for v in &mut x {
        *v ^= t;
    }
    // x[0] holds the most significant bit of each triple.
    morton([x[2], x[1], x[0]])
}

/// Breadth-first order over vertex-vertex adjacency (each face's consecutive corners), from
/// vertex 0 and then from the smallest unvisited vertex; unused vertices come in input order.
fn breadth_first(soup: &PolygonSoup) -> Vec<u32> {
    let nv = soup.num_vertices();
    // Adjacency in compressed rows: both directions of every face side (interior edges twice).
    let mut start = vec![0u32; nv + 1];
    for f in soup.faces() {
        for &v in f {
            start[v as usize + 1] += 2;
        }
    }
    for v in 0..nv {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut neighbours = vec![0u32; soup.num_corners() * 2];
    for f in soup.faces() {
        for (i, &a) in f.iter().enumerate() {
            let b = f[(i + 1) % f.len()];
            for (x, y) in [(a, b), (b, a)] {
                neighbours[fill[x as usize] as usize] = y;
                fill[x as usize] += 1;
            }
        }
    }
    let mut visited = vec![false; nv];
    let mut order = Vec::with_capacity(nv);
    for root in 0..nv {
        if visited[root] {
            continue;
        }
        visited[root] = true;
        let mut head = order.len();
        order.push(root as u32);
        while head < order.len() {
            let v = order[head] as usize;
            head += 1;
            for &w in &neighbours[start[v] as usize..start[v + 1] as usize] {
                if !visited[w as usize] {
                    visited[w as usize] = true;
                    order.push(w);
                }
            }
        }
    }
    order
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::meshes;
    use crate::testing::oracle::{pair, Oracle};

    fn is_permutation(p: &[u32]) -> bool {
        let mut seen = vec![false; p.len()];
        p.iter()
            .all(|&i| (i as usize) < p.len() && !std::mem::replace(&mut seen[i as usize], true))
    }

    fn test_meshes() -> Vec<PolygonSoup> {
        let mut v: Vec<PolygonSoup> = meshes::canonical().into_iter().map(|m| m.soup).collect();
        v.push(meshes::perforated_plate(2, 1, 400));
        v.push(meshes::mixed_grid(100));
        v.push(meshes::random_mesh(5, meshes::RandomMeshParams::default()));
        v
    }

    #[test]
    fn every_ordering_is_a_permutation_and_keeps_the_mesh() {
        for s in test_meshes() {
            let before = Oracle::new(&s);
            for ordering in Ordering::ALL.into_iter().chain([Ordering::Random(9)]) {
                let r = reorder(&s, ordering);
                let name = ordering.name();
                assert!(is_permutation(&r.new_vertex), "{name}");
                assert!(is_permutation(&r.old_face), "{name}");
                let map = |v: u32| r.new_vertex[v as usize];
                for (k, &j) in r.old_face.iter().enumerate() {
                    let mapped: Vec<u32> = s.face(j as usize).iter().map(|&v| map(v)).collect();
                    assert_eq!(r.soup.face(k), &mapped[..], "{name}");
                }
                for (v, p) in s.positions.iter().enumerate() {
                    assert_eq!(r.soup.positions[map(v as u32) as usize], *p, "{name}");
                }
                // The oracle's answers agree once names are mapped.
                let after = Oracle::new(&r.soup);
                let new_face = |j: u32| r.old_face.iter().position(|&f| f == j).unwrap() as u32;
                for (&(a, b), faces) in &before.edge_faces {
                    let mut expected: Vec<u32> = faces.iter().map(|&f| new_face(f)).collect();
                    expected.sort_unstable();
                    assert_eq!(after.edge_faces[&pair(map(a), map(b))], expected, "{name}");
                }
                assert_eq!(after.edge_faces.len(), before.edge_faces.len());
                for (v, vv) in before.vertex_vertices.iter().enumerate() {
                    let mut expected: Vec<u32> = vv.iter().map(|&w| map(w)).collect();
                    expected.sort_unstable();
                    assert_eq!(after.vertex_vertices[map(v as u32) as usize], expected);
                }
                assert_eq!(after.boundary_curve_count(), before.boundary_curve_count());
            }
        }
    }

    #[test]
    fn faces_follow_their_smallest_vertex_and_input_is_unchanged() {
        let s = meshes::torus(8, 5);
        assert_eq!(reorder(&s, Ordering::Input).soup, s);
        for ordering in [
            Ordering::Random(3),
            Ordering::Morton,
            Ordering::BreadthFirst,
        ] {
            let r = reorder(&s, ordering);
            let mins: Vec<u32> = r.soup.faces().map(|f| *f.iter().min().unwrap()).collect();
            assert!(mins.windows(2).all(|w| w[0] <= w[1]), "{}", ordering.name());
        }
        assert_ne!(
            reorder(&s, Ordering::Random(3)).new_vertex,
            reorder(&s, Ordering::Random(4)).new_vertex
        );
    }

    #[test]
    fn curves_and_bfs_visit_neighbours_close_together() {
        // A 4 x 4 x 4 lattice along each curve: Hilbert steps one cell at a time, Morton
        // jumps, and both start at the origin.
        let lattice: Vec<DVec3> = (0..64)
            .map(|i| DVec3::new((i % 4) as f64, ((i / 4) % 4) as f64, (i / 16) as f64))
            .collect();
        let hilbert_path = by_curve(&lattice, hilbert);
        for w in hilbert_path.windows(2) {
            let d = lattice[w[0] as usize] - lattice[w[1] as usize];
            assert_eq!(d.abs().element_sum(), 1.0, "Hilbert jumps at {w:?}");
        }
        assert_eq!(by_curve(&lattice, morton)[..4], [0, 1, 4, 5]);
        assert_eq!(hilbert_path[0], 0);
        // Breadth first on a grid: vertex 0, then its neighbours.
        let g = meshes::grid(3, 3, true);
        let r = reorder(&g, Ordering::BreadthFirst);
        assert_eq!(r.new_vertex[0], 0);
        let first_ring: Vec<u32> = [1, 4, 5].iter().map(|&v| r.new_vertex[v]).collect();
        assert!(
            first_ring.iter().all(|&k| (1..=3).contains(&k)),
            "{first_ring:?}"
        );
        for name in ["input", "random", "random:7", "morton", "hilbert", "bfs"] {
            assert_eq!(Ordering::from_name(name).unwrap().name(), name);
        }
        assert_eq!(Ordering::from_name("spiral"), None);
    }
}
