//! What construction costs, structure against structure: warm builds from the same soup, timed
//! as the report times them (glibc told to keep freed memory, so each build reuses the pages
//! the build before it freed; the thread's CPU time; one build to warm up), with the
//! structures taking turns, one build each per round, so a busy machine slows them alike.
//!
//! ```sh
//! cargo run --release --example build_sweep                    # torus, 1M triangles, 7 rounds
//! cargo run --release --example build_sweep -- 1000000 torus 9 # TRIANGLES, torus|grid, ROUNDS
//! cargo run --release --example build_sweep -- 1000000 torus 9 che-l1,openmesh
//! cargo run --release --example build_sweep -- 1000000 torus 9 che-l1,openmesh cold
//! cargo run --release --example build_sweep -- 1000000 torus 9 all passes
//! ```
//!
//! Each cell is the median of the rounds (the lab's statistic), and again the fastest round,
//! with the ratio of the report's construction target (che-l1 against OpenMesh's `add_face`
//! build, which is OpenMesh's own construction as the report times it).
//!
//! `cold` times cold builds instead: glibc returns its free memory to the kernel before each
//! build, so every page the build touches is a first-touch page fault (the report's Construction
//! time table shows both); the minor page faults per build are printed beside the times.
//! `passes` times che-l1's construction pass by pass, each in turns with the whole build and
//! OpenMesh's: what each pass costs, and what the target leaves for them (0.3× OpenMesh).

use topolab::alloc::{keep_freed_memory, minor_faults, release_free_memory, thread_cpu_ns};
use topolab_harness::measuring::measure::Builder;
use topolab_harness::measuring::timing::turns::{take_turns, Answer, Run as Turn};
use topolab_structures::{
    che, meshes, CheL1, CheL2, CheL3, IndexHalfEdge, MeshTopology, PointerHalfEdge, PolygonSoup,
};

/// One build, as the report times it.
struct Timed {
    /// Thread CPU time of the construction alone: the baseline's own (its lab checks come
    /// before), without finishing or dropping the structure.
    ns: u64,
    /// Minor page faults in that time.
    faults: u64,
    /// Faces of the structure built (the check that the build is whole).
    faces: usize,
}

/// One build of a structure from `soup`.
type Build = fn(&PolygonSoup) -> Timed;

fn build<M: MeshTopology>(soup: &PolygonSoup) -> Timed {
    let builder = Builder::<M>::new(soup).expect("the generated meshes are manifold");
    let first = minor_faults().unwrap_or(0);
    let start = thread_cpu_ns().expect("thread CPU clock");
    let built = std::hint::black_box(builder.build());
    let ns = thread_cpu_ns().expect("thread CPU clock") - start;
    let faults = minor_faults().unwrap_or(0) - first;
    let faces = built
        .and_then(|b| builder.finish(b))
        .expect("the generated meshes are manifold")
        .num_faces();
    Timed { ns, faults, faces }
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
    let mode = args.get(4).map_or("warm", String::as_str);
    assert!(
        ["warm", "cold", "passes"].contains(&mode),
        "MODE is warm, cold or passes"
    );

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
    if mode == "passes" {
        return passes(&soup, rounds);
    }
    let cold = mode == "cold";
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!(
        "{} {} vertices, {} triangles; {rounds} rounds taking turns, {mode} builds, \
         thread CPU ns/face; load {}",
        if grid { "grid" } else { "torus" },
        soup.num_vertices(),
        soup.num_faces(),
        load.split_whitespace()
            .take(3)
            .collect::<Vec<_>>()
            .join(" ")
    );
    // The structures take turns, one build each per round after one round to warm up (and to
    // leave the freed pages the timed builds reuse); every build must hold the soup's faces.
    let names: Vec<&str> = all.iter().map(|(name, _)| *name).collect();
    let mut faults = vec![Vec::new(); all.len()];
    let mut warming = all.len();
    let times = take_turns(1, rounds, &names, |s| {
        if cold {
            release_free_memory();
        }
        let t = (all[s].1)(&soup);
        if t.faces != soup.num_faces() {
            return Err(format!("built {} faces of {}", t.faces, soup.num_faces()));
        }
        if warming > 0 {
            warming -= 1;
        } else {
            faults[s].push(t.faults as f64);
        }
        Ok(Turn {
            ns: t.ns as f64 / t.faces as f64,
            answer: Answer::Counts([0, 0, t.faces]),
        })
    })
    .unwrap_or_else(|e| panic!("{e}"));
    println!("{:<28}{:>12}", "page faults per build", "median");
    for ((name, _), f) in all.iter().zip(&faults) {
        println!("{name:<28}{:>12.0}", median(f.clone()));
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

/// The passes of che-l1's construction (`CheL1::from_soup`: the containers copied and checked,
/// `O[]` paired, Algorithm 3's `VH[]`, the one-fan walk), each timed on its own in turns with
/// the whole build and OpenMesh's, warm, in ns/face: the breakdown the report's construction
/// target quotes.
fn passes(soup: &PolygonSoup, rounds: usize) {
    let n = soup.num_vertices();
    let faces = soup.num_faces() as f64;
    let mut rows: Vec<(&str, Vec<f64>)> = [
        "copy G[]",
        "check G[] finite",
        "copy V[]",
        "pair O[] (opposites_by_buckets)",
        "VH[] (Algorithm 3)",
        "one-fan walk (every_vertex_one_fan)",
        "sum of the passes",
        "whole che-l1 build",
        "openmesh build",
    ]
    .into_iter()
    .map(|name| (name, Vec::new()))
    .collect();
    let time = |f: &mut dyn FnMut()| {
        let start = thread_cpu_ns().expect("thread CPU clock");
        f();
        (thread_cpu_ns().expect("thread CPU clock") - start) as f64 / faces
    };
    // One round more than asked: the first warms up and is dropped.
    for round in 0..=rounds {
        let (mut g, mut v, mut o, mut vh) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let (mut finite, mut one_fan) = (false, false);
        let mut t = vec![
            time(&mut || g = soup.positions.clone()),
            time(&mut || finite = g.iter().all(|p| p.is_finite())),
            time(&mut || v = soup.indices().to_vec()),
            time(&mut || o = che::opposites_by_buckets(&v, n).expect("a manifold mesh")),
            time(&mut || vh = che::vertex_half_edges_algorithm_3(&v, &o, n)),
            time(&mut || one_fan = che::every_vertex_one_fan(&o, &vh)),
        ];
        assert!(finite && one_fan, "the generated meshes are manifold");
        drop((g, v, o, vh));
        t.push(t.iter().sum());
        t.push(build::<CheL1>(soup).ns as f64 / faces);
        #[cfg(has_openmesh)]
        t.push(build::<topolab::openmesh::OpenMesh>(soup).ns as f64 / faces);
        if round > 0 {
            for ((_, times), x) in rows.iter_mut().zip(t) {
                times.push(x);
            }
        }
    }
    rows.retain(|(_, t)| !t.is_empty());
    println!(
        "che-l1 construction by pass, {} triangles, {rounds} rounds, warm, thread CPU ns/face",
        soup.num_faces()
    );
    println!("{:<40}{:>8}{:>8}{:>8}", "", "median", "min", "max");
    for (name, t) in &rows {
        let (lo, hi) = (fastest(t.clone()), -fastest(t.iter().map(|x| -x).collect()));
        println!("{name:<40}{:>8.2}{lo:>8.2}{hi:>8.2}", median(t.clone()));
    }
    if let Some((_, om)) = rows.iter().find(|(name, _)| *name == "openmesh build") {
        println!(
            "{:<40}{:>8.2}",
            "0.3 × openmesh (the target's budget)",
            0.3 * median(om.clone())
        );
    }
}
