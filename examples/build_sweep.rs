//! What construction costs, structure against structure: warm builds from the same soup, timed
//! as the report times them (glibc told to keep freed memory, so each build reuses the pages
//! the build before it freed; the thread's CPU time; one build to warm up), with the
//! structures taking turns, one build each per round, so a busy machine slows them alike.
//!
//! ```sh
//! cargo run --release --example build_sweep                    # torus, 1M triangles, 7 rounds
//! cargo run --release --example build_sweep -- 1000000 torus 9 # TRIANGLES, torus|grid, ROUNDS
//! cargo run --release --example build_sweep -- 1000000 torus 9 che-l1,openmesh
//! ```
//!
//! Each cell is the median of the rounds (the lab's statistic), and again the fastest round,
//! with the ratio of the report's construction target (che-l1 against OpenMesh's `add_face`
//! build, which is OpenMesh's own construction as the report times it).

use topolab::alloc::{keep_freed_memory, thread_cpu_ns};
use topolab_structures::{
    meshes, CheL1, CheL2, CheL3, IndexHalfEdge, MeshTopology, PointerHalfEdge, PolygonSoup,
};

/// One build of a structure from `soup`; returns its number of faces (the check that the
/// build is whole).
type Build = fn(&PolygonSoup) -> usize;

fn build<M: MeshTopology>(soup: &PolygonSoup) -> usize {
    // The baseline's own construction when it has one, as the report times it.
    if let Some(built) = M::native().and_then(|k| k.construction(soup)) {
        return built.expect("native construction").num_faces();
    }
    M::from_soup(soup)
        .expect("the generated meshes are manifold")
        .num_faces()
}

fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    xs[xs.len() / 2]
}

fn fastest(xs: Vec<f64>) -> f64 {
    xs.into_iter().fold(f64::INFINITY, f64::min)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let triangles = args
        .first()
        .map_or(1_000_000, |a| a.parse().expect("TRIANGLES"));
    let grid = args.get(1).is_some_and(|a| a == "grid");
    let rounds: usize = args.get(2).map_or(7, |a| a.parse().expect("ROUNDS"));
    let only = args.get(3).cloned().filter(|s| s != "all");

    let soup = if grid {
        let side = ((triangles / 2) as f64).sqrt().round().max(1.0) as usize;
        meshes::grid(side, side, true)
    } else {
        meshes::torus_with_triangles(triangles)
    };
    let mut all: Vec<(&str, Build)> = vec![
        (CheL1::NAME, build::<CheL1>),
        (CheL2::NAME, build::<CheL2>),
        (CheL3::NAME, build::<CheL3>),
        (IndexHalfEdge::NAME, build::<IndexHalfEdge>),
        (PointerHalfEdge::NAME, build::<PointerHalfEdge>),
    ];
    #[cfg(has_openmesh)]
    all.push(("openmesh", build::<topolab::openmesh::OpenMesh>));
    all.retain(|(name, _)| {
        only.as_deref()
            .is_none_or(|s| s.split(',').any(|x| x == *name))
    });
    assert!(keep_freed_memory(), "glibc refused to keep freed memory");
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!(
        "{} {} vertices, {} triangles; {rounds} rounds taking turns, warm builds, \
         thread CPU ns/face; load {}",
        if grid { "grid" } else { "torus" },
        soup.num_vertices(),
        soup.num_faces(),
        load.split_whitespace()
            .take(3)
            .collect::<Vec<_>>()
            .join(" ")
    );
    // One build each to warm up (and to leave the freed pages the timed builds reuse).
    for (name, b) in &all {
        assert_eq!(b(&soup), soup.num_faces(), "{name} built another mesh");
    }
    let mut times = vec![Vec::new(); all.len()];
    for _ in 0..rounds {
        for (s, (_, b)) in all.iter().enumerate() {
            let start = thread_cpu_ns().expect("thread CPU clock");
            let faces = std::hint::black_box(b(&soup));
            let ns = thread_cpu_ns().expect("thread CPU clock") - start;
            assert_eq!(faces, soup.num_faces());
            times[s].push(ns as f64 / faces as f64);
        }
    }
    for (stat, pick) in [
        ("median", median as fn(Vec<f64>) -> f64),
        ("fastest", fastest),
    ] {
        println!("{stat:<28}{:>12}", "ns/face");
        let values: Vec<f64> = times.iter().map(|t| pick(t.clone())).collect();
        for ((name, _), t) in all.iter().zip(&values) {
            println!("{name:<28}{t:>12.1}");
        }
        let row = |name: &str| all.iter().position(|(n, _)| *n == name);
        for (a, b) in [
            ("che-l1", "openmesh"),
            ("che-l2", "openmesh"),
            ("index-half-edge", "openmesh"),
        ] {
            if let (Some(i), Some(j)) = (row(a), row(b)) {
                println!("{:<28}{:>12.3}", format!("{a}/{b}"), values[i] / values[j]);
            }
        }
    }
}
