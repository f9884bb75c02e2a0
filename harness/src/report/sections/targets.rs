//! "Targets": every target measured in turns on the largest torus of the run, its ratio
//! beside its goal, with the same ratio one after another and, for a missed one, why.

use crate::phases::Phase;
use crate::report::cells::largest;
use crate::report::format::{against_goal, class_of, esc};
use crate::report::section::{Needs, Page, Section, SizeSweep};
use crate::results::{Results, Status};
use crate::targets::measured::measured;
use crate::targets::plan::{Against, Cell, Turns, CHANGING_ROUNDS, ROUNDS, TARGETS};
use crate::targets::text::{
    chain_text, missed_limit_text, one_after_another, sequential, sequential_subject, versus_text,
};
use std::fmt::Write;

/// The Targets section: every target measured in turns, on the largest torus of the run.
fn render(h: &mut String, r: &Results) {
    let Some((mesh, tri)) = largest(r, "torus") else {
        return;
    };
    let ran = |s: &str| r.structures.iter().any(|x| x.name == s);
    // Measured on the largest torus of the cases, which is this one.
    let turns: Vec<Turns> = r
        .targets
        .iter()
        .filter(|t| t.mesh == mesh)
        .cloned()
        .collect();
    let _ = write!(
        h,
        "<h2>Targets ({mesh}, {tri} triangles, this run)</h2><div class=read><b>How to read it.</b> Each target is a ratio of two times measured with both sides taking turns: the two structures are built once, then run A, B, A, B, … for {ROUNDS} rounds after one warm-up round ({CHANGING_ROUNDS} rounds for the changing workloads, each run from a fresh build), so that a change of load on the machine slows both sides of a round alike; every run is timed in the measuring thread's CPU time, so time slices the machine gives to other processes do not count. Each round gives one ratio; <i>in turns</i> is their median, <i>spread</i> the smallest and the largest, and the target is met when the median is at most the goal. Against a limit (see Sweeps and their limits), the sweep takes turns with the probe: its sequential read of the working set that sets the limit's bandwidth bound, its chase through the working set that sets the latency bound (plain loads, and steps doing the chain's own arithmetic), and its checksum arithmetic; each round's sweep is divided by the limit at the bandwidth, load latency and time per term of that round. <i>One after another</i> is the same ratio from the size sweep's cells, where structures are timed one after the other: it moves with the load between them. Every run's checksum agrees with the first, or the report stops.</div><table><tr><th class=l>target</th><th>in turns (median)</th><th>spread</th><th>rounds</th><th>one after another</th><th>goal</th><th>met</th></tr>"
    );
    for t in TARGETS.iter().filter(|t| ran(t.structure)) {
        let against = match t.against {
            Against::Structure(b) if !ran(b) => continue,
            Against::Structure(b) => format!("{b}'s"),
            Against::Limit => "its limit".into(),
        };
        let cold = match (t.cell, t.against) {
            (Cell::Construction, Against::Structure(b)) => {
                let cold =
                    |s| sequential(&r.measurements, mesh, s, Cell::Construction)?.cold_ns_per_item;
                cold(t.structure)
                    .zip(cold(b))
                    .map(|(a, b)| format!("; cold builds, one after another: {:.2}×", a / b))
                    .unwrap_or_default()
            }
            _ => String::new(),
        };
        let limit =
            sequential(&r.measurements, mesh, t.structure, t.cell).and_then(|m| m.limit.as_ref());
        let spread = measured(&turns, t, limit);
        let (value, range, rounds, met) = match spread {
            Some(s) => (
                against_goal(s.median, t.goal),
                format!("{:.2}–{:.2}", s.min, s.max),
                s.rounds.to_string(),
                if s.median <= t.goal { "yes" } else { "no" },
            ),
            None => ("not measured".into(), "–".into(), "–".into(), "–"),
        };
        let class = class_of(met);
        let skipped = || {
            r.measurements.iter().any(|m| {
                m.mesh == mesh
                    && m.structure == t.structure
                    && m.status == Status::Skipped
                    && sequential_subject(t.cell) == Some((m.operator, m.kernel))
            })
        };
        let why = match (t.against, limit) {
            (Against::Limit, Some(l)) if met == "no" => {
                esc(&missed_limit_text(&turns, t, l, &r.probe))
            }
            (Against::Limit, Some(l)) => esc(&chain_text(&turns, t, l).unwrap_or_default()),
            (Against::Structure(b), _) if met == "no" => {
                esc(&versus_text(&r.measurements, mesh, t, b).unwrap_or_default())
            }
            _ if spread.is_none() && skipped() => {
                "not timed in turns: the size sweep skipped this cell as too long".into()
            }
            _ => String::new(),
        };
        let why = if why.is_empty() {
            why
        } else {
            format!("<br><span class=small>{why}</span>")
        };
        let seq = one_after_another(r, mesh, t)
            .map(|x| format!("{x:.2}×"))
            .unwrap_or_else(|| "–".into());
        let _ = write!(
            h,
            "<tr><td class=l>{} {} / {against}{cold}{why}</td><td>{value}</td><td>{range}</td><td>{rounds}</td><td>{seq}</td><td>≤ {}×</td><td class={class}>{met}</td></tr>",
            t.structure,
            t.cell.text(),
            t.goal
        );
    }
    // Decimation is timed in its own section, the index half-edge and OpenMesh taking turns on
    // the run's largest torus there: its row shows the median of their per-round ratios.
    for row in crate::decimate::targets(&r.decimate) {
        let (value, met) = match row.value {
            Some(v) => (
                against_goal(v, row.goal),
                if v <= row.goal { "yes" } else { "no" },
            ),
            None => ("not measured".into(), "–"),
        };
        let (range, rounds) = match row.spread {
            Some(s) => (format!("{:.2}–{:.2}", s.min, s.max), s.rounds.to_string()),
            None => ("–".into(), "–".into()),
        };
        let class = class_of(met);
        let _ = write!(
            h,
            "<tr><td class=l>{}<br><span class=small>timed in turns in the Decimation section</span></td><td>{value}</td><td>{range}</td><td>{rounds}</td><td>–</td><td>≤ {}×</td><td class={class}>{met}</td></tr>",
            esc(&row.what),
            row.goal
        );
    }
    let seconds: f64 = turns.iter().map(|t| t.seconds).sum();
    let _ = write!(
        h,
        "</table><p class=small>The rounds of this table took {seconds:.1} s. Warm builds reuse the memory the build before them freed (see Construction time for cold builds and page faults). Limits: see Sweeps and their limits. Bytes per triangle, measured: see Memory per triangle.</p>"
    );
}

/// The project's performance targets on the largest torus, last: the project's own
/// bookkeeping, after what a reader came for.
pub struct Targets;

impl Section for Targets {
    fn name(&self) -> &'static str {
        "targets"
    }

    fn needs(&self) -> Needs {
        Needs::size_sweep(SizeSweep::Full)
    }

    fn phase(&self) -> Option<Phase> {
        Some(Phase::new("targets", "Targets turns"))
    }

    fn render(&self, h: &mut String, page: &Page) {
        render(h, page.r);
    }
}
