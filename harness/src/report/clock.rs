//! The clock of the report's phases ([`crate::measuring::phases`]): the wall time and the
//! process's CPU time (its own threads and the subprocesses it waited for) of each section, one
//! stderr line as each finishes, all of them into `results.json` and the page's run facts.
//!
//! The full report is meant to take under 15 minutes alone on the 2-core reference machine
//! (`docs/report.md`). What was cut to keep it there is here, with the reasons the page's notes
//! give.

use crate::measuring::measure::Plan;
use crate::measuring::phases::{Phase, PhaseTime};
use crate::measuring::rounds::RoundPlan;
use crate::measuring::timing::interval::ROUNDS_FOR_LEVEL;
use std::time::{Duration, Instant};

/// (process, children) CPU seconds; 0 where `getrusage` is unavailable (the table then shows
/// zero CPU rather than failing the report).
fn cpu_now() -> (f64, f64) {
    use topolab_alloc::{cpu_seconds, Who};
    (
        cpu_seconds(Who::Process).unwrap_or(0.0),
        cpu_seconds(Who::Children).unwrap_or(0.0),
    )
}

/// The times so far since the last lap.
pub struct Clock {
    wall: Instant,
    cpu: f64,
    children: f64,
    started: Instant,
    times: Vec<PhaseTime>,
}

impl Clock {
    /// Starts the clock (the first section starts now).
    pub fn start() -> Clock {
        let (cpu, children) = cpu_now();
        let now = Instant::now();
        Clock {
            wall: now,
            cpu,
            children,
            started: now,
            times: Vec::new(),
        }
    }

    /// Ends the current section as `phase` (of `mesh`, for a mesh's measurement), prints its
    /// line, and starts the next one.
    pub fn lap(&mut self, phase: Phase, mesh: Option<&str>) {
        let (cpu, children) = cpu_now();
        let now = Instant::now();
        let t = PhaseTime {
            phase,
            mesh: mesh.map(str::to_string),
            wall_s: (now - self.wall).as_secs_f64(),
            cpu_s: (cpu - self.cpu).max(0.0),
            children_cpu_s: (children - self.children).max(0.0),
        };
        let what = match mesh {
            Some(m) => format!("{} of {m}", phase.label()),
            None => phase.label().to_string(),
        };
        eprintln!(
            "topolab report: {what} took {:.1} s wall, {:.1} s CPU ({:.0} s since the start)",
            t.wall_s,
            t.cpu_total_s(),
            (now - self.started).as_secs_f64()
        );
        self.times.push(t);
        self.wall = now;
        self.cpu = cpu;
        self.children = children;
    }

    /// Seconds since the clock started.
    pub fn since_start(&self) -> f64 {
        self.started.elapsed().as_secs_f64()
    }

    /// The sections timed so far.
    pub fn times(&self) -> &[PhaseTime] {
        &self.times
    }
}

/// The plan of the size sweep ([`crate::measuring::rounds`]): every cell in at least
/// [`ROUNDS_FOR_LEVEL`] rounds (the fewest whose interval reaches 95%), a cell whose interval is
/// still wide in extra rounds that may take 30% of that time again, at most [`MAX_ROUNDS`]
/// rounds ([`FULL_MAX_ROUNDS`] with `--full`); a cell whose one run is estimated above 0.15 s
/// is skipped with its estimate (its rounds would take seconds, and the sizes below it show its
/// growth). The pipeline adjusts it per mesh ([`plan_for`]).
pub fn plan(quick: bool, full: bool) -> Plan {
    Plan {
        cell_max: Duration::from_millis(150),
        light: false,
        sampled: true,
        boundary_only: false,
        rounds: RoundPlan {
            min_rounds: ROUNDS_FOR_LEVEL,
            max_rounds: if full { FULL_MAX_ROUNDS } else { MAX_ROUNDS },
            extra: if quick { 0.0 } else { 0.3 },
            cold_rounds: 0,
            seed: 2026,
        },
        samples: if quick {
            1024
        } else {
            crate::measuring::rounds::SAMPLES
        },
    }
}

/// What the run's `plan` becomes for one mesh of `family`, by what its tables show: cold
/// builds only on the largest torus (`shows_cold`: the construction table's); extra rounds only
/// on the generated tori and grids (the size plots and the Targets); on a grid, construction
/// and the boundary operators only (but everything of a structure that stores grids only); no
/// sampled cell on the refined meshes, whose table shows sweeps; `light`: the construction and
/// the vertex 1-ring sweep alone.
pub fn plan_for(plan: &Plan, light: bool, family: &str, shows_cold: bool) -> Plan {
    let generated = family == "torus" || family == "grid";
    Plan {
        light,
        sampled: plan.sampled && family != crate::report::sections::real_at_scale::FAMILY,
        boundary_only: family == "grid",
        rounds: RoundPlan {
            extra: if generated { plan.rounds.extra } else { 0.0 },
            cold_rounds: if shows_cold {
                crate::measuring::rounds::COLD_ROUNDS
            } else {
                0
            },
            ..plan.rounds
        },
        ..*plan
    }
}

/// The most rounds a cell gets in the default report.
pub const MAX_ROUNDS: usize = 12;

/// The most rounds a cell gets with `--full`.
pub const FULL_MAX_ROUNDS: usize = 21;

/// The timed runs of each changing workload on a torus of `faces` faces: 3 from the 1M torus
/// on, 3 with `--quick`, 5 otherwise and with `--full`. The 1M torus has 999,600 faces, so the
/// bound is half a million: `>= 1_000_000` missed it and ran 5 (`topolab report --sections
/// changing --sizes 1000000 --meshes torus` took 142 s of CPU with 5 runs, 86 s with 3, both
/// under the same load).
pub fn changing_runs(faces: usize, quick: bool, full: bool) -> usize {
    if quick || (faces >= 500_000 && !full) {
        3
    } else {
        5
    }
}

/// The notes that say what the default report leaves out to stay within its time budget, and
/// why (none with `--quick`, which is small by design, or `--full`, which leaves out nothing).
pub fn budget_notes(quick: bool, full: bool) -> Vec<String> {
    if quick || full {
        return Vec::new();
    }
    let mut notes = vec![format!(
        "To keep the full report within 15 minutes alone on the 2-core machine, a cell gets at most {MAX_ROUNDS} rounds ({FULL_MAX_ROUNDS} with `topolab report --full`), extra rounds beyond the first {ROUNDS_FOR_LEVEL} only on the generated tori and grids and only while they take less than 30% of the time the first took, cold builds only on the largest torus, and the refined meshes, whose table shows sweeps, no sampled cells."
    )];
    let light: Vec<String> = crate::report::refined::FULL
        .iter()
        .filter(|r| r.light)
        .map(|r| r.name())
        .collect();
    if !light.is_empty() {
        notes.push(format!(
            "For the same budget, {} is measured for construction, memory and the vertex 1-ring sweep only (its other operators took about 45 s alone; the refined bunny shows them at 1.2M; `--full` measures them).",
            light.join(", ")
        ));
    }
    notes.push(format!(
        "For the same budget, the 3D convex hulls stop at 100k points on the sphere (1M in a ball): on a sphere every point is on the hull, and 1M points there took 44 s alone for the n log n growth the smaller sizes show. Gift wrapping and the incremental algorithm run a size only when its predicted Volume6 tests are at most {:.0e}: the incremental algorithm's 1M ball and 100k sphere (53 s alone) are left out, its O(n²) shown on the sizes before. The changing workloads run {} times on the 1M torus (5 on the smaller ones). `--full` runs all of these further.",
        crate::studies::hull::bench::MAX_TESTS,
        changing_runs(1_000_000, false, false)
    ));
    notes
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_1m_torus_runs_the_changing_workloads_three_times_and_full_five() {
        // torus:1000000 makes 999,600 faces.
        assert_eq!(changing_runs(999_600, false, false), 3);
        assert_eq!(changing_runs(999_600, false, true), 5);
        assert_eq!(changing_runs(255_852, false, false), 5);
        assert_eq!(changing_runs(4_004, true, false), 3);
    }

    #[test]
    fn the_default_says_what_it_leaves_out_and_full_leaves_out_nothing() {
        let notes = budget_notes(false, false).join(" ");
        for said in ["at most 12 rounds", "100k points on the sphere", "--full"] {
            assert!(notes.contains(said), "{said}: {notes}");
        }
        assert!(budget_notes(false, true).is_empty());
        assert!(budget_notes(true, false).is_empty());
    }
}
