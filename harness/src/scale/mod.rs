//! The scale run (`topolab scale`): the largest mesh each structure holds on this machine, and
//! how its construction, memory and sweeps change on the way there. Each cell (one structure,
//! one size of the [`LADDER`]) is measured in a process of its own, so its memory is the
//! kernel's count for that build alone and a build the memory cannot hold ends that process,
//! never the run; a size the estimate says will not fit is not run at all but shown refused,
//! with the estimate.
//!
//! Here: what a run records ([`ScaleResults`], written as `results.json` with its `scale` list
//! of [`ScaleCell`]s), how a cell times its kernels ([`Timing`]), the `/proc` readers
//! ([`proc`]), the run itself ([`run`]) and the page ([`page`]). The `topolab` program is the
//! run's front (`topolab scale`) and its workers.

pub mod page;
pub mod proc;
pub mod run;

use crate::measuring::machine::Machine;
use crate::measuring::probe::Level;
use proc::Faults;
use serde::{Deserialize, Serialize};
use std::time::Instant;
use topolab_structures::Family;

/// The format of a scale run's `results.json`.
pub const FORMAT: &str = "topolab-scale/1";

/// The sizes of the run, triangles of a torus: four times larger each step, from 1k to
/// 1.024 billion (below the 1.43 billion triangles `u32` ids number).
pub const LADDER: [u64; 11] = [
    1_000,
    4_000,
    16_000,
    64_000,
    250_000,
    1_000_000,
    4_000_000,
    16_000_000,
    64_000_000,
    256_000_000,
    1_024_000_000,
];

/// The most triangles `u32` ids number: three corner (half-edge) ids per triangle, each below
/// `u32::MAX`: about 1.43 billion, whatever the structure.
pub const ID_LIMIT_TRIANGLES: u64 = (u32::MAX as u64 - 1) / 3;

/// The largest size of the default run, which stays under 15 minutes on the lab's 2-core
/// machine; `--full` goes on up the ladder while the memory admits.
pub const DEFAULT_MAX_TRIANGLES: u64 = 64_000_000;

/// One scale run, as `results.json` holds it.
#[derive(Clone, Debug, Serialize)]
pub struct ScaleResults {
    /// [`FORMAT`].
    pub format: String,
    /// The command line that produced it.
    pub command: String,
    /// The machine and build.
    pub machine: Machine,
    /// The machine's memory (`MemTotal`), bytes.
    pub memory_total: u64,
    /// The memory available to the run when it started (the limits module's `available`),
    /// bytes: what each refusal was measured against, with the value of its moment.
    pub memory_available: u64,
    /// The structures of the run, in its order, with their families (for the plots' styles).
    pub structures: Vec<Entrant>,
    /// The memory probe's levels (load latency and bandwidth by working-set size), measured
    /// before the cells, alone.
    pub probe: Vec<Level>,
    /// The largest size asked for (`--max-triangles`, or the ladder's end with `--full`).
    pub max_triangles: u64,
    /// Every cell: one structure at one size, measured, refused or failed.
    pub scale: Vec<ScaleCell>,
    /// The CHE through memory-mapped `.che` files: open and sweep, in memory and beyond it.
    pub mapped: Vec<MappedRun>,
    /// Wall time of the whole run, seconds.
    pub seconds: f64,
    /// What the run noticed that a reader should know (a checksum disagreement first).
    pub notes: Vec<String>,
}

/// A structure of the run.
#[derive(Clone, Debug, Serialize)]
pub struct Entrant {
    /// Its registry name.
    pub name: String,
    /// Its family.
    pub family: Family,
}

/// One structure at one size.
#[derive(Clone, Debug, Serialize)]
pub struct ScaleCell {
    /// The structure's registry name.
    pub structure: String,
    /// The size asked for: triangles of the torus (the torus has the nearest count its
    /// rings allow: see [`Measure::faces`]).
    pub triangles: u64,
    /// What happened.
    #[serde(flatten)]
    pub outcome: Outcome,
}

/// What happened to a cell.
#[derive(Clone, Debug, Serialize)]
#[serde(tag = "outcome", rename_all = "kebab-case")]
pub enum Outcome {
    /// Built and measured.
    Measured(Measure),
    /// Not run: the estimated peak exceeds the memory available.
    Refused {
        /// The estimated peak of building it (the torus's soup and the structure), bytes.
        estimate_bytes: u64,
        /// What the estimate came from.
        basis: String,
        /// The memory available when it was refused, bytes.
        available_bytes: u64,
    },
    /// Run, but the cell's process failed (the structure refused the mesh, or the process
    /// was killed).
    Failed {
        /// Why, as the process said it or as it ended.
        reason: String,
    },
}

/// What one cell measured. Memory is the kernel's count for the cell's process
/// ([`proc`]); times are medians of [`Timing::reps`] runs after one untimed run.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Measure {
    /// Faces of the torus built.
    pub faces: u64,
    /// Vertices of the torus built.
    pub vertices: u64,
    /// Seconds to generate the torus straight into the soup the structure is built from
    /// (its arrays reserved at their final size, no other copy).
    pub generate_s: f64,
    /// Building the structure from the soup, one timed build, ns per face.
    pub construction_ns_per_face: f64,
    /// The process's resident memory before the torus was generated (its program and
    /// libraries), bytes: what does not grow with the mesh.
    pub start_bytes: u64,
    /// The process's highest resident memory (`VmHWM`), bytes: the soup, the structure and
    /// the build's temporaries at their highest, plus the program (a few MB).
    pub peak_bytes: u64,
    /// Resident memory with the structure built and the soup dropped, less the resident
    /// memory before the soup was generated, bytes: the structure as the kernel holds it.
    pub resident_bytes: u64,
    /// What the structure says its containers take (`MeshTopology::heap_bytes`), bytes.
    pub declared_bytes: u64,
    /// Page faults while building.
    pub build_faults: Faults,
    /// R00 (the vertices around each vertex) over every vertex in id order, ns per vertex;
    /// `None` for structures whose R00 scans (O(n) per query: O(n²) a sweep).
    pub r00_sweep: Option<Timing>,
    /// R00 on [`SAMPLED_QUERIES`] seeded random vertices, ns per query: every structure,
    /// the scanning ones included, so every checksum is compared.
    pub r00_sampled: Timing,
    /// Laplacian smoothing of every vertex (the workload), ns per vertex; `None` where R00
    /// or the boundary test scans.
    pub smoothing: Option<Timing>,
    /// Page faults during the sweeps and the smoothing: no major fault while the structure
    /// stays resident; the minor ones are the kernels' own buffers touched the first time (the
    /// list of every vertex, smoothing's output).
    pub sweep_faults: Faults,
}

/// Vertices of the sampled R00 of every cell.
pub const SAMPLED_QUERIES: usize = 16;

/// The result a timed kernel returns, compared across structures.
#[derive(Copy, Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Check {
    /// A query kernel's checksum of the answers (order-independent within a query).
    Exact(u64),
    /// A workload's sum of coordinates, equal up to rounding (the neighbours are summed in
    /// an order that depends on the structure).
    Float(f64),
}

impl Check {
    /// Whether two results agree: exactly, or for sums by the report's rule
    /// ([`crate::measuring::checksum::sums_agree`]).
    pub fn agrees(self, other: Check) -> bool {
        match (self, other) {
            (Check::Exact(a), Check::Exact(b)) => a == b,
            (Check::Float(a), Check::Float(b)) => crate::measuring::checksum::sums_agree(a, b),
            _ => false,
        }
    }
}

/// A kernel timed: the median, fastest and slowest of `reps` runs after one untimed run,
/// per element, and the result it returned.
#[derive(Copy, Clone, Debug, Serialize, Deserialize)]
pub struct Timing {
    /// Median, ns per element.
    pub ns: f64,
    /// Fastest run, ns per element.
    pub min: f64,
    /// Slowest run, ns per element.
    pub max: f64,
    /// Timed runs.
    pub reps: usize,
    /// What every run returned (the same each time, or the timing panics).
    pub check: Check,
}

/// Times `kernel` over `elements` elements: one untimed run, then runs until `budget_s`
/// seconds have gone by, at least 3 and at most 21; only one when the untimed run alone took
/// more than a third of the budget (a scan on a large mesh: seconds a run). Panics if two runs
/// return different results: a kernel that is not deterministic cannot be compared.
pub fn time_kernel(elements: u64, budget_s: f64, kernel: impl FnMut() -> Check) -> Timing {
    time_kernel_runs(elements, budget_s, 1, kernel)
}

/// [`time_kernel`] with at least `fewest` timed runs however long each takes (and 3 while
/// they are short): for a few slow runs that must still be a median.
pub fn time_kernel_runs(
    elements: u64,
    budget_s: f64,
    fewest: usize,
    mut kernel: impl FnMut() -> Check,
) -> Timing {
    let untimed = Instant::now();
    let first = kernel();
    let at_least = if 3.0 * untimed.elapsed().as_secs_f64() > budget_s {
        fewest.max(1)
    } else {
        fewest.max(3)
    };
    let mut times = Vec::new();
    let start = Instant::now();
    while times.len() < at_least || (times.len() < 21 && start.elapsed().as_secs_f64() < budget_s) {
        let t = Instant::now();
        let check = std::hint::black_box(kernel());
        times.push(t.elapsed().as_secs_f64() * 1e9 / elements.max(1) as f64);
        assert!(
            check.agrees(first),
            "a kernel returned {check:?} after {first:?}"
        );
    }
    times.sort_by(f64::total_cmp);
    Timing {
        ns: times[times.len() / 2],
        min: times[0],
        max: times[times.len() - 1],
        reps: times.len(),
        check: first,
    }
}

/// The CHE read from a memory-mapped `.che` file.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct MappedRun {
    /// Triangles of the torus in the file.
    pub triangles: u64,
    /// The CHE level of the file.
    pub level: u8,
    /// The file's size, bytes.
    pub file_bytes: u64,
    /// Seconds `topolab convert` took to write it.
    pub convert_s: f64,
    /// Milliseconds of each open (header read, length checked, mapped), in order.
    pub open_ms: Vec<f64>,
    /// Milliseconds of the verification (`CheFile::check`: one pass over the file).
    pub verify_ms: f64,
    /// The memory limit the sweeping process ran under (a memory cgroup), bytes; `None`:
    /// only the machine's memory.
    pub memory_limit: Option<u64>,
    /// How the limit was set, or why none could be.
    pub limit_how: String,
    /// The first R00 sweep after opening, before the verification (the bounds-checked reads),
    /// the file's pages dropped from the page cache before: every page read from the disk (a
    /// single run).
    pub first_sweep: Timing,
    /// Page faults of the first sweep.
    pub first_faults: Faults,
    /// The later sweeps (median of their runs): warm when the file fits the memory, read from
    /// the disk again when it does not.
    pub later_sweeps: Timing,
    /// Page faults of the later sweeps, all runs.
    pub later_faults: Faults,
    /// Without a memory limit: the later sweeps again after each further fill of the page
    /// cache (the file unmapped, its pages dropped, the file opened and verified again, which
    /// reads it in anew). Where the page cache places a file's pages changes a warm sweep's
    /// time from one fill to the next while the runs of one fill agree (docs/scale.md), so the
    /// warm figure is the median over fills ([`MappedRun::warm`]). Empty in a limited run,
    /// whose sweeps read the disk.
    #[serde(default)]
    pub refills: Vec<Timing>,
    /// The highest memory the cgroup charged (its resident memory and page cache), bytes.
    pub group_peak_bytes: Option<u64>,
    /// The in-memory CHE's R00 sweep result on the same torus, when the run measured it.
    pub in_memory_check: Option<Check>,
}

impl MappedRun {
    /// The later sweeps of every fill of the page cache: the first fill's, then the refills'.
    pub fn fills(&self) -> impl Iterator<Item = &Timing> {
        std::iter::once(&self.later_sweeps).chain(&self.refills)
    }

    /// The warm sweep: the fill whose median time is the median of the fills' (the upper one
    /// of an even count).
    pub fn warm(&self) -> Timing {
        let mut fills: Vec<&Timing> = self.fills().collect();
        fills.sort_by(|a, b| a.ns.total_cmp(&b.ns));
        *fills[fills.len() / 2]
    }
}

#[cfg(test)]
mod tests {
    use super::page::holds;
    use super::*;

    #[test]
    fn sums_agree_to_rounding_and_checksums_exactly() {
        assert!(Check::Float(1.0).agrees(Check::Float(1.0 + 1e-9)));
        assert!(Check::Float(9.74e-7).agrees(Check::Float(9.76e-7)));
        assert!(!Check::Float(1.0).agrees(Check::Float(1.0 + 1e-5)));
        assert!(!Check::Float(1e6).agrees(Check::Float(1e6 + 10.0)));
        assert!(Check::Exact(7).agrees(Check::Exact(7)));
        assert!(!Check::Exact(7).agrees(Check::Exact(8)));
        assert!(!Check::Exact(7).agrees(Check::Float(7.0)));
    }

    #[test]
    fn capacity_divides_memory_and_stops_at_the_ids_limit() {
        assert_eq!(holds(1_000, 10.0), 100);
        assert_eq!(holds(u64::MAX, 1.0), ID_LIMIT_TRIANGLES);
        assert_eq!(ID_LIMIT_TRIANGLES, 1_431_655_764);
        assert!(LADDER.iter().all(|&n| n <= ID_LIMIT_TRIANGLES));
        assert!(LADDER.windows(2).all(|w| w[1] > 3 * w[0]));
    }

    #[test]
    fn a_fast_kernel_is_timed_21_times_a_slow_one_once_and_the_result_kept() {
        let mut calls = 0;
        let t = time_kernel(10, 10.0, || {
            calls += 1;
            Check::Exact(5)
        });
        assert_eq!((t.reps, calls), (21, 22));
        assert_eq!(t.check, Check::Exact(5));
        assert!(t.min <= t.ns && t.ns <= t.max);
        let mut calls = 0;
        let t = time_kernel(10, 0.0, || {
            calls += 1;
            Check::Exact(6)
        });
        assert_eq!((t.reps, calls), (1, 2));
        assert_eq!(t.check, Check::Exact(6));
    }

    #[test]
    fn the_warm_sweep_of_a_mapped_file_is_the_median_fill() {
        let at = |ns: f64| Timing {
            ns,
            min: ns,
            max: ns,
            reps: 3,
            check: Check::Exact(1),
        };
        let mut run = MappedRun {
            triangles: 1,
            level: 2,
            file_bytes: 1,
            convert_s: 0.0,
            open_ms: vec![],
            verify_ms: 0.0,
            memory_limit: None,
            limit_how: String::new(),
            first_sweep: at(90.0),
            first_faults: Faults::default(),
            later_sweeps: at(20.0),
            later_faults: Faults::default(),
            refills: vec![],
            group_peak_bytes: None,
            in_memory_check: None,
        };
        // One fill (a limited run, or a run recorded before the refills): its own sweeps.
        assert_eq!(run.warm().ns, 20.0);
        // The slow first fill is outvoted; the cold first sweep never counts.
        run.refills = vec![at(11.0), at(12.0)];
        assert_eq!(run.warm().ns, 12.0);
        assert_eq!(run.fills().count(), 3);
        // An even count takes the upper of the two middle fills.
        run.refills.push(at(10.0));
        assert_eq!(run.warm().ns, 12.0);
    }
}
