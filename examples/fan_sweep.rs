//! What walking a vertex's fan costs in each structure that walks one: the vertex sweeps (R00,
//! R01, R02, boundary vertex) and the smoothing workload of the CHE level 2, the index and the
//! pointer half-edge, the winged-edge and OpenMesh, run through the harness's own kernels (and
//! OpenMesh's native loops, as the report runs them), with the harness checksums compared.
//!
//! The structures take turns, one run each per round, so a busy machine slows them alike.
//! Each cell is the median of the rounds (the lab's statistic), and again the fastest round
//! (the one least disturbed by other processes), with the ratios of the report's targets.
//!
//! ```sh
//! cargo run --release --example fan_sweep                    # torus, 1M triangles, 9 rounds
//! cargo run --release --example fan_sweep -- 1000000 grid 15 # TRIANGLES, torus|grid, ROUNDS
//! cargo run --release --example fan_sweep -- 1000000 torus 9 che-l2,openmesh smoothing
//! ```
//!
//! The last form (STRUCTURES, comma separated or `all`, then one CELL) also serves instruction
//! counts: `valgrind --tool=callgrind --toggle-collect='topolab_harness::measuring::kernels::run*'` on a
//! one-round run counts the timed kernel only.

use std::time::Instant;
use topolab_harness::measuring::kernels::{run, run_workload, Queries, Workload, WorkloadBuffers};
use topolab_harness::measuring::timing::turns::{take_turns, Answer, Run as Turn};
use topolab_structures::{
    meshes, BoundaryCurves, CheL2, IndexHalfEdge, MeshTopology, Operator, PointerHalfEdge,
    PolygonSoup, WingedEdge,
};

/// A timed cell: a sweep of one operator, or the smoothing workload.
#[derive(Copy, Clone, PartialEq)]
enum Cell {
    Sweep(Operator),
    Smoothing,
}

impl Cell {
    const ALL: [Cell; 5] = [
        Cell::Sweep(Operator::R00),
        Cell::Sweep(Operator::R01),
        Cell::Sweep(Operator::R02),
        Cell::Sweep(Operator::BoundaryVertex),
        Cell::Smoothing,
    ];

    fn name(self) -> &'static str {
        match self {
            Cell::Sweep(op) => op.name(),
            Cell::Smoothing => Workload::Smoothing.name(),
        }
    }
}

/// One structure, built, with what its runs need.
trait Timed {
    fn name(&self) -> &'static str;
    /// One run of `cell`: nanoseconds per vertex and the result's bits (the harness checksum).
    fn run(&mut self, cell: Cell) -> (f64, u64);
}

struct Built<M> {
    m: M,
    q: Queries,
    curves: BoundaryCurves,
    buf: WorkloadBuffers,
}

impl<M: MeshTopology> Timed for Built<M> {
    fn name(&self) -> &'static str {
        M::NAME
    }
    fn run(&mut self, cell: Cell) -> (f64, u64) {
        let start = Instant::now();
        // Natively when the structure has its own loop (OpenMesh), as the report times it.
        let native = M::native();
        let bits = match cell {
            Cell::Sweep(op) => match native {
                Some(k) => k.sweep(&self.m, op).expect("native sweep"),
                None => run(&self.m, op, &self.q, &mut self.curves),
            },
            Cell::Smoothing => match native {
                Some(k) => k
                    .workload(&mut self.m, Workload::Smoothing)
                    .expect("native workload")
                    .to_bits(),
                None => run_workload(&self.m, Workload::Smoothing, &mut self.buf).to_bits(),
            },
        };
        let ns = start.elapsed().as_nanos() as f64 / self.m.num_vertices() as f64;
        (ns, std::hint::black_box(bits))
    }
}

/// Builds a structure for its turns.
type Builder = fn(&PolygonSoup) -> Box<dyn Timed>;

fn build<M: MeshTopology + 'static>(soup: &PolygonSoup) -> Box<dyn Timed> {
    let m = M::from_soup(soup).expect("the generated meshes are manifold");
    let q = Queries::all(&m, soup);
    Box::new(Built {
        m,
        q,
        curves: BoundaryCurves::default(),
        buf: WorkloadBuffers::default(),
    })
}

fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    xs[xs.len() / 2]
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let triangles = args
        .first()
        .map_or(1_000_000, |a| a.parse().expect("TRIANGLES"));
    let grid = args.get(1).is_some_and(|a| a == "grid");
    let rounds: usize = args.get(2).map_or(9, |a| a.parse().expect("ROUNDS"));
    let only_structure = args.get(3).cloned().filter(|s| s != "all");
    let only_cell = args.get(4).cloned();

    let soup = if grid {
        let side = ((triangles / 2) as f64).sqrt().round().max(1.0) as usize;
        meshes::grid(side, side, true)
    } else {
        meshes::torus_with_triangles(triangles)
    };
    let mut all: Vec<(&str, Builder)> = vec![
        (CheL2::NAME, build::<CheL2>),
        (IndexHalfEdge::NAME, build::<IndexHalfEdge>),
        (PointerHalfEdge::NAME, build::<PointerHalfEdge>),
        (WingedEdge::NAME, build::<WingedEdge>),
    ];
    #[cfg(has_openmesh)]
    all.push(("openmesh", build::<topolab::openmesh::OpenMesh>));
    all.retain(|(name, _)| {
        only_structure
            .as_deref()
            .is_none_or(|s| s.split(',').any(|x| x == *name))
    });
    let cells: Vec<Cell> = Cell::ALL
        .into_iter()
        .filter(|c| only_cell.as_deref().is_none_or(|s| s == c.name()))
        .collect();
    let mut built: Vec<Box<dyn Timed>> = all.iter().map(|(_, b)| b(&soup)).collect();

    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!(
        "{} {} vertices, {} triangles; median of {rounds} interleaved rounds, ns/vertex; load {}",
        if grid { "grid" } else { "torus" },
        soup.num_vertices(),
        soup.num_faces(),
        load.split_whitespace()
            .take(3)
            .collect::<Vec<_>>()
            .join(" ")
    );
    // times[s][c]: the runs of structure s on cell c, the structures taking turns on each cell
    // (no warm-up round: each structure was just built and its queries drawn), every run's
    // checksum compared with the first's (sweeps exactly, smoothing's float sum within 1e-6,
    // since each structure sums in its own order).
    let names: Vec<&str> = built.iter().map(|b| b.name()).collect();
    let mut times = vec![vec![Vec::new(); cells.len()]; built.len()];
    for (c, &cell) in cells.iter().enumerate() {
        let ns = take_turns(0, rounds, &names, |s| {
            let (ns, bits) = built[s].run(cell);
            let answer = match cell {
                Cell::Sweep(_) => Answer::Sum(bits),
                Cell::Smoothing => Answer::Value(f64::from_bits(bits)),
            };
            Ok(Turn { ns, answer })
        })
        .unwrap_or_else(|e| panic!("{}: {e}", cell.name()));
        for (s, runs) in ns.into_iter().enumerate() {
            times[s][c] = runs;
        }
    }
    let stat = |pick: fn(Vec<f64>) -> f64| -> Vec<Vec<f64>> {
        times
            .iter()
            .map(|row| row.iter().map(|runs| pick(runs.clone())).collect())
            .collect()
    };
    // The median is the lab's statistic; the fastest run is the one least disturbed by a
    // busy machine.
    table("median", &cells, &built, &stat(median));
    table("fastest", &cells, &built, &stat(fastest));
}

fn fastest(xs: Vec<f64>) -> f64 {
    xs.into_iter().fold(f64::INFINITY, f64::min)
}

/// Prints one statistic of every cell, then the ratios the issue's targets name.
fn table(stat: &str, cells: &[Cell], built: &[Box<dyn Timed>], values: &[Vec<f64>]) {
    print!("{:<26}", stat);
    for cell in cells {
        print!("{:>16}", cell.name());
    }
    println!();
    for (b, row) in built.iter().zip(values) {
        print!("{:<26}", b.name());
        for t in row {
            print!("{t:>16.2}");
        }
        println!();
    }
    let row = |name: &str| built.iter().position(|b| b.name() == name);
    for (a, b) in [
        ("che-l2", "index-half-edge"),
        ("che-l2", "openmesh"),
        ("index-half-edge", "openmesh"),
    ] {
        if let (Some(i), Some(j)) = (row(a), row(b)) {
            print!("{:<26}", format!("{a}/{b}"));
            for (x, y) in values[i].iter().zip(&values[j]) {
                print!("{:>16.2}", x / y);
            }
            println!();
        }
    }
}
