//! The clock of `topolab report`'s sections ([`topolab_harness::phases`]): the wall time and the
//! process's CPU time (its own threads and the subprocesses it waited for) of each section, one
//! stderr line as each finishes, all of them into `results.json` and the page's run facts.

use crate::alloc::{cpu_seconds, Who};
use std::time::Instant;
use topolab_harness::phases::{Phase, PhaseTime};

/// The times so far since the last lap.
pub struct Clock {
    wall: Instant,
    cpu: f64,
    children: f64,
    started: Instant,
    times: Vec<PhaseTime>,
}

/// (process, children) CPU seconds; 0 where `getrusage` is unavailable (the table then shows
/// zero CPU rather than failing the report).
fn cpu_now() -> (f64, f64) {
    (
        cpu_seconds(Who::Process).unwrap_or(0.0),
        cpu_seconds(Who::Children).unwrap_or(0.0),
    )
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

    /// The sections timed so far.
    pub fn times(&self) -> &[PhaseTime] {
        &self.times
    }
}
