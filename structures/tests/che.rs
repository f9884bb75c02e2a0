//! The Compact Half-Edge beyond the conformance suite: the containers of the chapter's
//! example, the two constructions agreeing, the memory accounting, refusals, and (ignored,
//! run with `--release -- --ignored --nocapture`) the construction and R00 timings.

use topolab_structures::che::{
    self, edge_map_algorithm_2, edge_map_by_scan, opposites_algorithm_1, opposites_by_buckets,
    CheLevel,
};
use topolab_structures::meshes::{self, RandomMeshParams};
use topolab_structures::{CheL0, CheL1, CheL2, CheL3, Error, MeshTopology, PolygonSoup, VertexId};

/// Figure 4.10's open tetrahedron in our numbering: triangles (0,1,3), (1,2,3), (2,0,3).
#[test]
fn open_tetrahedron_containers_at_every_level() {
    let soup = meshes::open_tetrahedron();
    let l3 = CheL3::from_soup(&soup).unwrap();
    let l2 = l3.level2();
    let l1 = l2.level1();
    assert_eq!(l1.level0().start_vertices(), &[0, 1, 3, 1, 2, 3, 2, 0, 3]);
    // Half-edge 1 (1→3) and 5 (3→1) are opposite; 0 (0→1), 3 (1→2), 6 (2→0) are the boundary.
    assert_eq!(l1.opposite(), &[-1, 5, 7, -1, 8, 1, -1, 2, 4]);
    // Algorithm 3: a boundary vertex keeps its (last) boundary half-edge; the apex its first.
    assert_eq!(l2.vertex_half_edge(), &[0, 3, 6, 2]);
    assert_eq!(l2.edge_map(), &[0, 1, 2, 3, 4, 6]);
    // One boundary curve, numbered 1: its half-edges keep O = -1.
    assert_eq!(l3.curve_half_edge(), &[0]);
    let l1_fast = CheL1::from_soup(&soup).unwrap();
    assert_eq!(l1_fast.opposite(), l1.opposite());
}

#[test]
fn annulus_curves_are_numbered_in_opposite() {
    let l3 = CheL3::from_soup(&meshes::annulus(6)).unwrap();
    assert_eq!(l3.curve_half_edge().len(), 2);
    let o = l3.level2().level1().opposite();
    for (k, &start) in l3.curve_half_edge().iter().enumerate() {
        assert_eq!(o[start as usize], -(k as i32 + 1));
    }
    let labelled = |label| o.iter().filter(|&&x| x == label).count();
    assert_eq!((labelled(-1), labelled(-2)), (6, 6));
    // Level 2 keeps -1 on both curves.
    let l2 = CheL2::from_soup(&meshes::annulus(6)).unwrap();
    assert_eq!(
        l2.level1().opposite().iter().filter(|&&x| x == -1).count(),
        12
    );
}

fn random_triangles(seed: u64) -> PolygonSoup {
    meshes::random_mesh(
        seed,
        RandomMeshParams {
            triangles_only: true,
            ..RandomMeshParams::default()
        },
    )
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
    /// The fast construction and the chapter's (Algorithms 1–4 with maps) give identical
    /// containers, or refuse with the same error kind.
    #[test]
    fn fast_and_chapter_constructions_agree(seed in proptest::prelude::any::<u64>()) {
        let soup = random_triangles(seed);
        match (CheL3::from_soup(&soup), CheL3::from_soup_chapter(&soup)) {
            (Ok(fast), Ok(chapter)) => {
                proptest::prop_assert_eq!(&fast, &chapter);
                let o = chapter.level2().level1().opposite();
                let v = chapter.start_vertices();
                let level1 = CheL1::from_soup(&soup).unwrap();
                proptest::prop_assert_eq!(
                    opposites_by_buckets(v, soup.num_vertices()).unwrap(),
                    opposites_algorithm_1(v)
                );
                proptest::prop_assert_eq!(level1.opposite(), &opposites_algorithm_1(v)[..]);
                let (o_fast, vh_fast) =
                    che::opposites_and_vertex_half_edges(v, soup.num_vertices()).unwrap();
                proptest::prop_assert_eq!(
                    vh_fast,
                    che::vertex_half_edges_algorithm_3(v, &o_fast, soup.num_vertices())
                );
                proptest::prop_assert_eq!(edge_map_by_scan(o), edge_map_algorithm_2(o));
                proptest::prop_assert_eq!(
                    CheL2::from_soup(&soup).unwrap(),
                    CheL2::from_soup_chapter(&soup).unwrap()
                );
            }
            (Err(a), Err(b)) => proptest::prop_assert_eq!(a.kind(), b.kind()),
            (a, b) => proptest::prop_assert!(false, "fast {:?}, chapter {:?}", a.err(), b.err()),
        }
    }
}

/// Heap bytes are the container lengths times their element sizes; level 1's topology
/// (`V[]`, `O[]`) is exactly 24 bytes per triangle.
#[test]
fn heap_bytes_match_the_containers() {
    for soup in [
        meshes::torus(8, 6),
        meshes::annulus(7),
        meshes::grid(4, 3, true),
    ] {
        let (n0, n2) = (soup.num_vertices(), soup.num_faces());
        let geometry = 24 * n0;
        let l0 = CheL0::from_soup(&soup).unwrap();
        assert_eq!(l0.heap_bytes(), geometry + 12 * n2);
        let l1 = CheL1::from_soup(&soup).unwrap();
        assert_eq!(l1.heap_bytes() - geometry, 24 * n2, "level 1 topology");
        let l2 = CheL2::from_soup(&soup).unwrap();
        assert_eq!(l2.vertex_half_edge().len(), n0);
        assert_eq!(l2.edge_map().len(), MeshTopology::num_edges(&l2));
        assert_eq!(
            l2.heap_bytes(),
            l1.heap_bytes() + 4 * n0 + 4 * MeshTopology::num_edges(&l2)
        );
        let l3 = CheL3::from_soup(&soup).unwrap();
        assert_eq!(
            l3.heap_bytes(),
            l2.heap_bytes() + 4 * l3.curve_half_edge().len()
        );
    }
}

#[test]
fn refusals_name_the_problem() {
    let quads = meshes::quad_cube();
    for (e, name) in [
        (CheL0::from_soup(&quads).unwrap_err(), "che-l0"),
        (CheL2::from_soup(&quads).unwrap_err(), "che-l2"),
        (CheL3::from_soup(&quads).unwrap_err(), "che-l3"),
        (CheL3::from_soup_chapter(&quads).unwrap_err(), "che-l3"),
    ] {
        assert!(
            matches!(e, Error::NotTriangles { structure, .. } if structure == name),
            "{e}"
        );
    }
    let e = CheL1::from_soup(&quads).unwrap_err();
    assert!(
        matches!(
            e,
            Error::NotTriangles {
                structure: "che-l1",
                face: 0,
                corners: 4
            }
        ),
        "{e}"
    );
    let e = CheL2::from_soup(&meshes::bowtie()).unwrap_err();
    assert!(
        matches!(e, Error::NonManifoldVertex { vertex: 0, fans: 2 }),
        "{e}"
    );
    // Three triangles on edge (0, 1).
    let fin = PolygonSoup::from_polygons(
        vec![glam::DVec3::ZERO; 5],
        &[[0u32, 1, 2], [1, 0, 3], [0, 1, 4]],
    );
    for e in [
        CheL3::from_soup(&fin).unwrap_err(),
        CheL3::from_soup_chapter(&fin).unwrap_err(),
    ] {
        match e {
            Error::NonManifoldEdge { a: 0, b: 1, faces } => assert_eq!(faces, vec![0, 1, 2]),
            other => panic!("expected a non-manifold edge, got {other}"),
        }
    }
    let flipped =
        PolygonSoup::from_polygons(vec![glam::DVec3::ZERO; 4], &[[0u32, 1, 2], [0, 1, 3]]);
    assert_eq!(
        CheL0::from_soup(&flipped).unwrap_err().kind(),
        "inconsistent-orientation"
    );
    let out_of_range = PolygonSoup::from_polygons(vec![glam::DVec3::ZERO; 3], &[[0u32, 1, 7]]);
    assert_eq!(
        CheL1::from_soup(&out_of_range).unwrap_err().kind(),
        "index-out-of-range"
    );
}

/// Two closed fans meeting at one vertex (two tetrahedra sharing a tip) have no boundary at
/// all; the fan walk still finds the second fan.
#[test]
fn closed_fans_touching_at_a_vertex_are_refused() {
    let mut soup = meshes::closed_tetrahedron();
    for _ in 0..3 {
        soup.push_vertex(glam::DVec3::ONE);
    }
    // A second tetrahedron on vertices 3 (shared tip), 4, 5, 6.
    for f in [[4u32, 5, 3], [5, 6, 3], [6, 4, 3], [4, 6, 5]] {
        soup.push_face(&f);
    }
    let e = CheL1::from_soup(&soup).unwrap_err();
    assert!(
        matches!(e, Error::NonManifoldVertex { vertex: 3, fans: 2 }),
        "{e}"
    );
}

/// Algorithm 6 at a boundary vertex whose first half-edge in `V[]` is interior: the strip's
/// vertex 1 is first met leaving through an interior edge, and the star must still be whole.
#[test]
fn level1_star_from_an_interior_first_half_edge() {
    let soup = meshes::triangle_strip(3);
    let l1 = CheL1::from_soup(&soup).unwrap();
    let o = l1.opposite();
    let v = l1.start_vertices();
    let (mut found_case, mut checked) = (false, 0);
    for vertex in 0..soup.num_vertices() as u32 {
        let first = v.iter().position(|&x| x == vertex).unwrap();
        let mut l1_star = Vec::new();
        let closing = l1.vertex_star(VertexId(vertex), |_| {}, |h| l1_star.push(h));
        let l2 = CheL2::from_soup(&soup).unwrap();
        let mut l2_star = Vec::new();
        let l2_closing = l2.vertex_star(VertexId(vertex), |_| {}, |h| l2_star.push(h));
        l1_star.sort_unstable();
        l2_star.sort_unstable();
        assert_eq!(l1_star, l2_star, "star of v{vertex}");
        assert_eq!(closing, l2_closing);
        found_case |= o[first] >= 0 && closing.is_some();
        checked += 1;
    }
    assert!(
        found_case,
        "the strip has no boundary vertex found first by an interior half-edge"
    );
    assert_eq!(checked, soup.num_vertices());
}

/// R00 at level 2 through the trace: VH read first, then one O read per triangle.
#[test]
fn level2_star_reads_vh_then_opposites() {
    let l2 = CheL2::from_soup(&meshes::open_tetrahedron()).unwrap();
    let mut reads = Vec::new();
    l2.vertex_star(VertexId(3), |r| reads.push(r), |_| {});
    assert_eq!(
        reads[0],
        che::StarRead::VertexHalfEdge {
            vertex: VertexId(3),
            he: 2
        }
    );
    let opposites = reads
        .iter()
        .filter(|r| matches!(r, che::StarRead::Opposite { .. }))
        .count();
    assert_eq!(opposites, 3, "{reads:?}");
    let mut ring = Vec::new();
    l2.vertex_vertices(VertexId(3), |w| ring.push(w.0));
    ring.sort_unstable();
    assert_eq!(ring, vec![0, 1, 2]);
}

/// Nanoseconds this thread has run on a CPU (Linux `/proc/thread-self/schedstat`), so the
/// timings below do not count time spent waiting for a core on a shared machine.
fn thread_cpu_ns() -> Option<u64> {
    let s = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    s.split_whitespace().next()?.parse().ok()
}

/// Best of `runs` samples, each `reps` calls of `f` (so a sample lasts long enough for the
/// clock, which the kernel updates at its tick): seconds per call (on-CPU where the OS tells
/// it, else wall), and the last result.
fn best_of<T>(runs: usize, reps: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut best = f64::INFINITY;
    let mut out = None;
    for _ in 0..runs {
        let (cpu, wall) = (thread_cpu_ns(), std::time::Instant::now());
        for _ in 0..reps {
            out = Some(f());
        }
        let seconds = match (cpu, thread_cpu_ns()) {
            (Some(a), Some(b)) => (b - a) as f64 * 1e-9,
            _ => wall.elapsed().as_secs_f64(),
        };
        best = best.min(seconds / reps as f64);
    }
    (best, out.unwrap())
}

/// Timings on a 1M-triangle torus (not a pass/fail test: it prints numbers and asserts only
/// that the constructions agree). Run with
/// `cargo test --release -p topolab-structures --test che -- --ignored --nocapture`.
#[test]
#[ignore]
fn timings_at_one_million_triangles() {
    let soup = meshes::torus_with_triangles(1_000_000);
    let n2 = soup.num_faces() as f64;
    let n0 = soup.num_vertices() as f64;
    let v = soup.indices().to_vec();
    let (t_buckets, o_fast) = best_of(3, 8, || opposites_by_buckets(&v, soup.num_vertices()));
    let (t_map, o_map) = best_of(2, 2, || opposites_algorithm_1(&v));
    assert_eq!(o_fast.unwrap(), o_map);
    let (t_l1, l1) = best_of(3, 8, || CheL1::from_soup(&soup).unwrap());
    let (t_l1_chapter, l1_chapter) = best_of(2, 2, || CheL1::from_soup_chapter(&soup).unwrap());
    assert_eq!(l1, l1_chapter);
    let (t_l3, _) = best_of(3, 8, || CheL3::from_soup(&soup).unwrap());
    let l2 = CheL2::from_soup(&soup).unwrap();
    let (t_r00, sum) = best_of(3, 8, || {
        let mut sum = 0u64;
        for vertex in 0..soup.num_vertices() {
            l2.vertex_vertices(VertexId::new(vertex), |w| sum += w.0 as u64);
        }
        sum
    });
    assert!(sum > 0);
    let ns = |t: f64, n: f64| t * 1e9 / n;
    println!("{} triangles, {} vertices", n2, n0);
    println!(
        "O[] by buckets (opposites_by_buckets):      {:6.1} ns/triangle",
        ns(t_buckets, n2)
    );
    println!(
        "O[] by Algorithm 1 (HashMap):               {:6.1} ns/triangle",
        ns(t_map, n2)
    );
    println!(
        "CheL1::from_soup (checks + O[]):           {:6.1} ns/triangle",
        ns(t_l1, n2)
    );
    println!(
        "CheL1::from_soup_chapter:                   {:6.1} ns/triangle",
        ns(t_l1_chapter, n2)
    );
    println!(
        "CheL3::from_soup (all containers):          {:6.1} ns/triangle",
        ns(t_l3, n2)
    );
    println!(
        "R00 at level 2 over every vertex:           {:6.1} ns/vertex",
        ns(t_r00, n0)
    );
}

/// The fast pairing refuses what the chapter's map would pair wrongly, whatever the order the
/// half-edges arrive in: a third half-edge on a paired edge (before and after the pair
/// closes), two half-edges in the same direction, a vertex out of range or repeated, and a
/// `V[]` that is not whole triangles; and it pairs what Algorithm 1 pairs.
#[test]
fn pairing_by_buckets_refuses_bad_edges() {
    for (v, n) in [
        (vec![0u32, 1, 2, 1, 0, 3, 0, 1, 4], 5), // fin: the third comes after the pair
        (vec![0, 1, 4, 0, 1, 2, 1, 0, 3], 5),    // the two in one direction come first
        (vec![0, 1, 2, 0, 1, 3], 4),             // same direction
        (vec![0, 1, 7], 3),                      // out of range
        (vec![0, 1, 1], 3),                      // repeated vertex
        (vec![0, 1, 2, 2], 3),                   // not whole triangles
    ] {
        assert_eq!(opposites_by_buckets(&v, n), None, "{v:?}");
        assert_eq!(che::opposites_and_vertex_half_edges(&v, n), None, "{v:?}");
    }
    let soup = meshes::torus(9, 7);
    let v = soup.indices();
    assert_eq!(
        opposites_by_buckets(v, soup.num_vertices()),
        Some(opposites_algorithm_1(v))
    );
    let grid = meshes::grid(5, 4, true);
    let v = grid.indices();
    let o = opposites_by_buckets(v, grid.num_vertices()).unwrap();
    assert_eq!(o, opposites_algorithm_1(v));
    assert!(o.iter().any(|&h| h < 0), "a grid has a boundary");
}
