//! The run's findings in Markdown (`FINDINGS.md`, written next to `results.json`): what the
//! page shows at length, in the few lines a reader of the repository looks for first. Every
//! sentence is computed from the [`Results`] of the same run, so the findings cannot drift from
//! the numbers they summarise; nothing here is written by hand about a particular run.

use crate::measuring::kernels::Kernel;
use crate::measuring::timing::turns::Spread;
use crate::results::{Measurement, Results, Status, Subject};
use crate::targets::measured::{ran, shown_turns};
use crate::targets::{measured, sequential, Against, TARGETS};
use std::fmt::Write;
use topolab_structures::summary::plural;
use topolab_structures::{Operator, Workload};

/// The findings of `r` as a Markdown document.
pub fn markdown(r: &Results) -> String {
    let mut md = String::new();
    let m = &r.machine;
    let _ = writeln!(md, "# Findings of this run\n");
    let _ = writeln!(
        md,
        "Written by the report from `results.json` (every number below is in it, with its runs). \
         Machine: {} ({} cores), {}; {}; commit {}, {}. Command: `{}`.\n",
        m.cpu, m.cores, m.memory, m.os, m.commit, m.date, r.settings.command
    );
    choosing(&mut md, r);
    targets(&mut md, r);
    limits(&mut md, r);
    hull(&mut md, r);
    if !r.notes.is_empty() {
        let _ = writeln!(md, "## Notes of the run\n");
        for n in &r.notes {
            let _ = writeln!(md, "- {n}");
        }
        md.push('\n');
    }
    md
}

/// The largest mesh of `family` measured in the run, with its triangles.
fn largest<'a>(r: &'a Results, family: &str) -> Option<(&'a str, usize)> {
    r.meshes
        .iter()
        .filter(|m| m.family == family)
        .max_by_key(|m| m.triangles)
        .map(|m| (m.name.as_str(), m.triangles))
}

/// The measured cell of `structure` for `subject` and `kernel` on `mesh`.
fn cell<'a>(
    r: &'a Results,
    mesh: &str,
    structure: &str,
    subject: Subject,
    kernel: Kernel,
) -> Option<&'a Measurement> {
    r.measurements.iter().find(|m| {
        m.mesh == mesh
            && m.structure == structure
            && m.operator == subject
            && m.kernel == kernel
            && m.status == Status::Measured
    })
}

/// Whether two cells' intervals separate (they can be told apart); without intervals, whether
/// their medians differ.
fn interval_separates(a: &Measurement, b: &Measurement) -> bool {
    match (a.ns_per_item_ci, b.ns_per_item_ci) {
        (Some([a0, a1]), Some([b0, b1])) => a1 < b0 || b1 < a0,
        _ => a.ns_per_item != b.ns_per_item,
    }
}

/// A number of nanoseconds with the digits it deserves.
fn ns(x: f64) -> String {
    if x >= 100.0 {
        format!("{x:.0}")
    } else {
        format!("{x:.1}")
    }
}

/// The structures on the largest torus: memory, construction, the 1-ring sweep and smoothing,
/// each structure's rank by the sweep.
fn choosing(md: &mut String, r: &Results) {
    let Some((mesh, tri)) = largest(r, "torus") else {
        return;
    };
    let row = |s: &str| {
        let build = cell(r, mesh, s, Subject::Construction, Kernel::Construction);
        let sweep = cell(r, mesh, s, Subject::Query(Operator::R00), Kernel::Sweep);
        let smooth = cell(
            r,
            mesh,
            s,
            Subject::Workload(Workload::Smoothing),
            Kernel::Workload,
        );
        (
            build.and_then(|m| Some(m.bytes? as f64 / m.triangles.max(1) as f64)),
            build,
            sweep,
            smooth,
        )
    };
    let mut rows: Vec<_> = r
        .structures
        .iter()
        .map(|s| (s.name.as_str(), row(&s.name)))
        .collect();
    if rows.iter().all(|(_, (_, _, sweep, _))| sweep.is_none()) {
        return;
    }
    let time = |m: Option<&Measurement>| m.and_then(|m| m.ns_per_item);
    rows.sort_by(|a, b| {
        let key = |x: Option<f64>| x.unwrap_or(f64::INFINITY);
        key(time(a.1 .2)).total_cmp(&key(time(b.1 .2)))
    });
    let _ = writeln!(
        md,
        "## The structures on {mesh} ({tri} triangles)\n\nSorted by the vertex 1-ring sweep (R00 over every vertex); each time the median of its rounds (each round on fresh builds of every structure, in a random order) with its interval in brackets. A row marked ≈ cannot be told apart from the row above it by the sweep: their intervals overlap. Bytes: the built structure's heap, geometry included, every block counted by its usable size.\n\n| structure | bytes/triangle | construction ns/face | R00 sweep ns/vertex | smoothing ns/vertex |\n|---|--:|--:|--:|--:|"
    );
    let opt = |m: Option<&Measurement>| match m.and_then(|m| Some((m.ns_per_item?, m))) {
        Some((x, m)) => match m.ns_per_item_ci {
            Some([lo, hi]) => format!("{} [{}–{}]", ns(x), ns(lo), ns(hi)),
            None => ns(x),
        },
        None => "–".into(),
    };
    let (measured, absent): (Vec<_>, Vec<_>) =
        rows.iter().partition(|(_, (bytes, build, sweep, smooth))| {
            bytes.is_some() || build.is_some() || sweep.is_some() || smooth.is_some()
        });
    let mut above: Option<&Measurement> = None;
    for (name, (bytes, build, sweep, smooth)) in measured {
        let tied = match (above, sweep) {
            (Some(a), Some(b)) => !interval_separates(a, b),
            _ => false,
        };
        above = sweep.or(above);
        let _ = writeln!(
            md,
            "| {}{name} | {} | {} | {} | {} |",
            if tied { "≈ " } else { "" },
            bytes
                .map(|b| format!("{b:.0}"))
                .unwrap_or_else(|| "–".into()),
            opt(build),
            opt(sweep),
            opt(smooth)
        );
    }
    if !absent.is_empty() {
        let names: Vec<&str> = absent.iter().map(|(name, _)| *name).collect();
        let _ = writeln!(
            md,
            "\nNot measured on this torus (they store grids only, or refused it): {}.",
            names.join(", ")
        );
    }
    md.push('\n');
}

/// One row of the Targets: the ratio (`None`: not measured) with its spread in turns, when it
/// has one, against its goal.
fn target_line(what: &str, ratio: Option<f64>, spread: Option<&Spread>, goal: f64) -> String {
    let Some(v) = ratio else {
        return format!("| {what} | not measured | ≤ {goal}× | – |");
    };
    let spread = match spread {
        Some(s) => format!(
            "interval {:.2}–{:.2}, {} round{}",
            s.low,
            s.high,
            s.rounds,
            plural(s.rounds)
        ),
        None => "one after the other".into(),
    };
    let met = if v <= goal { "met" } else { "**missed**" };
    format!("| {what} | {v:.2}× ({spread}) | ≤ {goal}× | {met} |")
}

/// The Targets: each ratio measured in turns on the largest torus, against its goal.
fn targets(md: &mut String, r: &Results) {
    let Some((mesh, _)) = largest(r, "torus") else {
        return;
    };
    let ran = |s: &str| ran(r, s);
    let turns = shown_turns(r, mesh);
    let mut lines = Vec::new();
    for t in TARGETS.iter().filter(|t| ran(t.structure)) {
        let against = match t.against {
            Against::Structure(b) if !ran(b) => continue,
            Against::Structure(b) => b.to_string(),
            Against::Limit => "its limit".into(),
        };
        let limit =
            sequential(&r.measurements, mesh, t.structure, t.cell).and_then(|m| m.limit.as_ref());
        let what = format!("{} {} / {against}", t.structure, t.cell.text());
        let s = measured(&turns, t, limit);
        lines.push(target_line(&what, s.map(|s| s.median), s.as_ref(), t.goal));
    }
    // Decimation's row, timed in turns in its own section (as on the page).
    for row in crate::studies::decimate::targets(&r.decimate) {
        let what = format!("{} (in the Decimation section)", row.what);
        lines.push(target_line(&what, row.value, row.spread.as_ref(), row.goal));
    }
    if lines.is_empty() {
        return;
    }
    let met = lines.iter().filter(|l| l.ends_with("| met |")).count();
    let _ = writeln!(
        md,
        "## Targets\n\nOn {mesh} (the hull's on its own points): {met} of {} met. Each ratio is the median of per-round ratios, the two sides taking turns (the page's Targets section says how).\n\n| target | in turns (spread) | goal | |\n|---|--:|--:|---|",
        lines.len()
    );
    for l in lines {
        let _ = writeln!(md, "{l}");
    }
    md.push('\n');
}

/// How far the sweeps are from their limits: how many within 2×, and the farthest.
fn limits(md: &mut String, r: &Results) {
    let Some((mesh, _)) = largest(r, "torus") else {
        return;
    };
    let mut times: Vec<(f64, &Measurement)> = r
        .measurements
        .iter()
        .filter(|m| m.mesh == mesh && m.kernel == Kernel::Sweep && m.status == Status::Measured)
        .filter_map(|m| Some((m.ns_per_item? / m.limit.as_ref()?.ns_per_item, m)))
        // A limit of zero (nothing to read, e.g. the boundary of a closed mesh) has no ratio.
        .filter(|(x, _)| x.is_finite())
        .collect();
    if times.is_empty() {
        return;
    }
    times.sort_by(|a, b| b.0.total_cmp(&a.0));
    let within = times.iter().filter(|(x, _)| *x <= 2.0).count();
    let _ = writeln!(
        md,
        "## Sweeps against their limits on {mesh}\n\n{within} of {} sweeps of structures that declare their reads are within 2× of the time the machine's measured bandwidth and latency allow. The farthest (the page's Sweeps and their limits section gives each one's reason):\n",
        times.len()
    );
    for (x, m) in times.iter().take(5) {
        let _ = writeln!(md, "- {} {}: {x:.1}× its limit", m.structure, m.operator);
    }
    md.push('\n');
}

/// The convex hulls at the largest n: each algorithm's time against Qhull's.
fn hull(md: &mut String, r: &Results) {
    let Some(n) = r.hull.iter().map(|h| h.n).max() else {
        return;
    };
    let at_n: Vec<_> = r.hull.iter().filter(|h| h.n == n).collect();
    let _ = writeln!(
        md,
        "## Convex hulls of {n} points\n\nWarm medians; the ratio is to Qhull's time on the same point set when Qhull ran.\n\n| point set | algorithm | seconds | / Qhull |\n|---|---|--:|--:|"
    );
    for h in &at_n {
        let qhull = at_n
            .iter()
            .find(|q| q.shape == h.shape && q.algorithm == "qhull")
            .map(|q| format!("{:.2}×", h.seconds / q.seconds))
            .unwrap_or_else(|| "–".into());
        let _ = writeln!(
            md,
            "| {} | {} | {:.4} | {qhull} |",
            h.shape, h.algorithm, h.seconds
        );
    }
    md.push('\n');
}
