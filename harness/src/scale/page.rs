//! The scale run's page (`index.html` beside its `results.json`), in the report's format:
//! the "Which structure fits my mesh" table first, then the targets, the capacity of each
//! structure with its refusals, the plots against size, every cell, the CHE read from
//! memory-mapped files, and the machine.

use super::{Check, Measure, Outcome, ScaleCell, ScaleResults, Timing, ID_LIMIT_TRIANGLES};
use crate::format::{bytes, esc, ns};
use crate::page::plot::{self, Line, Point, Style};
use crate::report::page::CSS;
use std::fmt::Write;
use topolab_structures::Family;

/// The cells of `structure` that were measured, smallest first.
pub fn measured<'a>(r: &'a ScaleResults, structure: &str) -> Vec<(u64, &'a Measure)> {
    r.scale
        .iter()
        .filter(|c| c.structure == structure)
        .filter_map(|c| match &c.outcome {
            Outcome::Measured(m) => Some((c.triangles, m)),
            _ => None,
        })
        .collect()
}

/// The cell where `structure` stopped: refused or failed; `None` when it was measured up to
/// the largest size asked for.
pub fn stop<'a>(r: &'a ScaleResults, structure: &str) -> Option<&'a ScaleCell> {
    r.scale
        .iter()
        .find(|c| c.structure == structure && !matches!(c.outcome, Outcome::Measured(_)))
}

/// How many triangles `memory` bytes hold at `per_triangle` bytes each, at most the
/// [`ID_LIMIT_TRIANGLES`] `u32` ids number.
pub fn holds(memory: u64, per_triangle: f64) -> u64 {
    ((memory as f64 / per_triangle.max(1e-9)) as u64).min(ID_LIMIT_TRIANGLES)
}

fn per_tri(b: u64, m: &Measure) -> f64 {
    b as f64 / m.faces.max(1) as f64
}

fn count(n: u64) -> String {
    match n {
        n if n >= 1_000_000_000 => format!("{:.2} G", n as f64 / 1e9),
        n if n >= 1_000_000 => format!("{:.1} M", n as f64 / 1e6),
        n if n >= 1_000 => format!("{:.0} k", n as f64 / 1e3),
        n => n.to_string(),
    }
}

fn timing(t: Option<&Timing>) -> String {
    t.map_or("–".into(), |t| {
        format!(
            "{}<br><span class=small>{}–{}, {} runs</span>",
            ns(t.ns),
            ns(t.min),
            ns(t.max),
            t.reps
        )
    })
}

/// The page.
pub fn render(r: &ScaleResults) -> String {
    let mut h = String::new();
    let _ = write!(h, "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>topolab scale</title><style>{CSS}</style></head><body><h1>topolab scale</h1><p>The largest mesh each structure holds on this machine, and how its construction, memory and sweeps change on the way there. Produced by <code>{}</code> in {:.0} s.</p>", esc(&r.command), r.seconds);
    for n in &r.notes {
        let _ = write!(h, "<p class=bad><b>{}</b></p>", esc(n));
    }
    fits(&mut h, r);
    targets(&mut h, r);
    capacity(&mut h, r);
    plots(&mut h, r);
    cells(&mut h, r);
    mapped(&mut h, r);
    machine(&mut h, r);
    h.push_str("</body></html>\n");
    h
}

fn fits(h: &mut String, r: &ScaleResults) {
    let mem = r.memory_available;
    let _ = write!(h, "<h2>Which structure fits my mesh</h2><div class=read><b>How to read it.</b> Per structure, the largest torus built and measured on this machine, and what each triangle took there: <i>resident</i>, the structure alone as the kernel holds it once built; <i>peak</i>, the whole building process at its highest (the soup it is built from, the structure, the build's temporaries). The last columns divide memory by the peak per triangle (less the program's few MB): on this machine, the memory available when the next size was refused (else {}, available when the run started), an estimate consistent with that refusal; and on machines with 10× and 100× its memory it is <b>extrapolated</b> on paper, nothing measured; no structure of the lab goes past {} triangles, the most its <code>u32</code> ids number (three corner ids per triangle, below 2<sup>32</sup>).</div>", bytes(mem as f64), count(ID_LIMIT_TRIANGLES));
    let _ = write!(h, "<table><tr><th class=l>structure</th><th>largest measured</th><th>resident bytes / triangle</th><th>peak bytes / triangle</th><th>next size</th><th>fits here (estimate)</th><th>10× memory, {} (extrapolated)</th><th>100× memory, {} (extrapolated)</th></tr>", bytes(10.0 * mem as f64), bytes(100.0 * mem as f64));
    for e in &r.structures {
        let rows = measured(r, &e.name);
        let Some(&(_, m)) = rows.last() else {
            let why = stop(r, &e.name).map_or(String::new(), stop_text);
            let _ = write!(
                h,
                "<tr><td class=l>{}</td><td class=l colspan=7>none: {why}</td></tr>",
                esc(&e.name)
            );
            continue;
        };
        let peak = per_tri(m.peak_bytes, m);
        let stopped = stop(r, &e.name);
        let next = stopped.map_or("not asked".into(), stop_text);
        // The memory the refusal saw, else the run's at its start; less the program's own.
        let here = match stopped.map(|c| &c.outcome) {
            Some(Outcome::Refused {
                available_bytes, ..
            }) => *available_bytes,
            _ => mem,
        };
        let grows = per_tri(m.peak_bytes.saturating_sub(m.start_bytes), m);
        let cell = |memory: u64| {
            let n = holds(memory.saturating_sub(m.start_bytes), grows);
            if n == ID_LIMIT_TRIANGLES {
                format!("{} (the ids' limit)", count(n))
            } else {
                count(n)
            }
        };
        let _ = write!(
            h,
            "<tr><td class=l>{}</td><td>{}</td><td>{:.1}</td><td>{:.1}</td><td class=l>{}</td><td>{}</td><td class=skip>{}</td><td class=skip>{}</td></tr>",
            esc(&e.name),
            count(m.faces),
            per_tri(m.resident_bytes, m),
            peak,
            next,
            cell(here),
            cell(mem.saturating_mul(10)),
            cell(mem.saturating_mul(100)),
        );
    }
    h.push_str("</table>");
}

fn stop_text(c: &ScaleCell) -> String {
    match &c.outcome {
        Outcome::Refused {
            estimate_bytes,
            basis,
            available_bytes,
        } => format!(
            "{} refused: needs about {} ({}), {} available",
            count(c.triangles),
            bytes(*estimate_bytes as f64),
            esc(basis),
            bytes(*available_bytes as f64)
        ),
        Outcome::Failed { reason } => format!("{} failed: {}", count(c.triangles), esc(reason)),
        Outcome::Measured(_) => String::new(),
    }
}

/// One target of the scale run, as measured.
pub struct TargetRow {
    /// What the target asks.
    pub what: String,
    /// The measured value and whether it meets the goal; or why this run did not measure it.
    pub got: Result<(String, bool), String>,
    /// The goal.
    pub goal: String,
}

/// The run's targets: each measured value, its goal, and whether it is met.
pub fn target_rows(r: &ScaleResults) -> Vec<TargetRow> {
    target_tuples(r)
        .into_iter()
        .map(|(what, got, goal)| TargetRow { what, got, goal })
        .collect()
}

type Tuple = (String, Result<(String, bool), String>, String);

fn target_tuples(r: &ScaleResults) -> Vec<Tuple> {
    let mut rows = Vec::new();
    // CHE level 1 against OpenMesh: triangles per memory, at the largest size both built.
    let ratio = {
        let (che, om) = (measured(r, "che-l1"), measured(r, "openmesh"));
        che.iter()
            .rev()
            .find_map(|(n, c)| om.iter().find(|(m, _)| m == n).map(|(_, o)| (*n, c, o)))
            .map(|(n, c, o)| {
                let x = per_tri(o.resident_bytes, o) / per_tri(c.resident_bytes, c);
                (
                    format!(
                        "{x:.2}× (resident bytes per triangle at {}: {:.1} against {:.1})",
                        count(n),
                        per_tri(o.resident_bytes, o),
                        per_tri(c.resident_bytes, c)
                    ),
                    x >= 1.8,
                )
            })
            .ok_or_else(|| {
                "not measured: the run needs che-l1 and openmesh at one size".to_string()
            })
    };
    rows.push((
        "CHE level 1 holds ≥ 1.8× the triangles OpenMesh holds in the same memory".into(),
        ratio,
        "≥ 1.8×".into(),
    ));
    let open = r
        .mapped
        .iter()
        .flat_map(|m| m.open_ms.iter().map(move |&t| (t, m)))
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(t, m)| {
            (
                format!(
                    "{t:.3} ms (slowest open, {} file)",
                    bytes(m.file_bytes as f64)
                ),
                t < 50.0,
            )
        })
        .ok_or_else(|| "not measured: the run opened no .che file".to_string());
    rows.push((
        "a memory-mapped .che opens in under 50 ms".into(),
        open,
        "< 50 ms".into(),
    ));
    let l2 = measured(r, "che-l2");
    let at = |n: u64| {
        l2.iter()
            .find(|(m, _)| *m == n)
            .and_then(|(_, m)| m.r00_sweep)
    };
    // At 256M in memory, or else the warm sweeps of a level-2 file of 256M mapped whole.
    let mapped_whole = r.mapped.iter().find(|m| {
        m.memory_limit.is_none()
            && m.level == 2
            && m.triangles.abs_diff(256_000_000) * 50 < 256_000_000
    });
    let large = at(256_000_000).map(|t| (t, "in memory")).or_else(|| {
        mapped_whole.map(|m| {
            (
                m.warm(),
                "from the memory-mapped .che file, warm: the median of its fills of the page cache (the in-memory build was refused)",
            )
        })
    });
    let sweep = match (at(1_000_000), large) {
        (Some(small), Some((large, how))) => {
            let x = large.ns / small.ns;
            Ok((
                format!(
                    "{x:.2}× ({} {how}, against {} per vertex at 1M)",
                    ns(large.ns),
                    ns(small.ns)
                ),
                x <= 2.0,
            ))
        }
        _ => Err("not measured: needs che-l2 at 1M triangles and at 256M, in memory or from a .che file (`topolab scale --full --mapped-triangles 256000000`)".to_string()),
    };
    rows.push((
        "CHE level 2's R00 sweep at 256M triangles, warm, within 2× its 1M time per vertex".into(),
        sweep,
        "≤ 2×".into(),
    ));
    let full = r.max_triangles > super::DEFAULT_MAX_TRIANGLES;
    let time = if full {
        Err(format!(
            "the run went beyond the default sizes (--full): {:.0} s",
            r.seconds
        ))
    } else {
        Ok((format!("{:.0} s", r.seconds), r.seconds < 900.0))
    };
    rows.push((
        "the default scale run takes under 15 minutes".into(),
        time,
        "< 900 s".into(),
    ));
    rows
}

fn targets(h: &mut String, r: &ScaleResults) {
    h.push_str("<h2>Targets</h2><div class=read><b>How to read it.</b> The goals the lab set for scale, each measured by this run; a goal this run did not measure says what would.</div><table><tr><th class=l>target</th><th class=l>measured</th><th>goal</th><th>met</th></tr>");
    for TargetRow { what, got, goal } in target_rows(r) {
        let (text, met, class) = match got {
            Ok((t, true)) => (t, "yes", "ok"),
            Ok((t, false)) => (t, "no", "bad"),
            Err(why) => (why, "–", "skip"),
        };
        let _ = write!(h, "<tr><td class=l>{}</td><td class=l>{}</td><td>{}</td><td class={class}>{met}</td></tr>", esc(&what), esc(&text), esc(&goal));
    }
    h.push_str("</table>");
}

fn capacity(h: &mut String, r: &ScaleResults) {
    h.push_str("<h2>Capacity, size by size</h2><div class=read><b>How to read it.</b> Every size of the ladder for every structure: ✓ measured, or where the structure stopped. A size is run only when the limits module's estimate of its peak fits the memory available at that moment: the peak per triangle the previous size measured (or, for the first, a build of a small grid under the counting allocator, scaled), times the triangles. A refused size is never run into swap or the OOM killer; a failed one is a process that ended without its measurement (its reason beside it).</div><table><tr><th class=l>structure</th>");
    let sizes: Vec<u64> = super::LADDER
        .iter()
        .copied()
        .filter(|&n| n <= r.max_triangles)
        .collect();
    for &n in &sizes {
        let _ = write!(h, "<th>{}</th>", count(n));
    }
    h.push_str("</tr>");
    for e in &r.structures {
        let _ = write!(h, "<tr><td class=l>{}</td>", esc(&e.name));
        for &n in &sizes {
            match r
                .scale
                .iter()
                .find(|c| c.structure == e.name && c.triangles == n)
            {
                Some(ScaleCell {
                    outcome: Outcome::Measured(_),
                    ..
                }) => h.push_str("<td class=ok>✓</td>"),
                Some(c) => {
                    let _ = write!(
                        h,
                        "<td class=bad title=\"{}\">{}</td>",
                        stop_text(c),
                        if matches!(c.outcome, Outcome::Refused { .. }) {
                            "refused"
                        } else {
                            "failed"
                        }
                    );
                }
                None => h.push_str("<td class=skip></td>"),
            }
        }
        h.push_str("</tr>");
    }
    h.push_str("</table>");
}

/// One line per structure of `y` against triangles.
fn lines(r: &ScaleResults, styles: &[Style], y: impl Fn(&Measure) -> Option<f64>) -> Vec<Line> {
    r.structures
        .iter()
        .zip(styles)
        .map(|(e, &style)| Line {
            name: e.name.clone(),
            style,
            points: measured(r, &e.name)
                .into_iter()
                .filter_map(|(_, m)| {
                    let value = y(m)?;
                    Some(Point {
                        x: m.faces as f64,
                        y: value,
                        // A scale cell's runs share one build: their range is no interval.
                        low: None,
                        high: None,
                        rounds: 0,
                    })
                })
                .collect(),
        })
        .collect()
}

fn plots(h: &mut String, r: &ScaleResults) {
    let families: Vec<Family> = r.structures.iter().map(|e| e.family).collect();
    let styles = plot::styles(&families);
    h.push_str("<h2>Against size</h2><div class=read><b>How to read them.</b> Both axes are logarithmic. A structure whose cost per element stays flat scales; a step up shows where its arrays outgrow a cache level (the grey lines: the probe's latency of one dependent load from each level, for scale) or the memory. Bytes per triangle fall at first (fixed costs spread) and then stay flat: a structure's memory is linear in the mesh.</div><div class=plots>");
    let (lo, hi) = r
        .scale
        .iter()
        .filter_map(|c| match &c.outcome {
            Outcome::Measured(m) => Some(m.faces as f64),
            _ => None,
        })
        .fold((f64::MAX, 0.0f64), |(a, b), x| (a.min(x), b.max(x)));
    let grey = plot::styles(&[Family::CornerLists])[0];
    let mut r00 = lines(r, &styles, |m| m.r00_sweep.as_ref().map(|t| t.ns));
    if hi > 0.0 {
        r00.extend(r.probe.iter().map(|l| {
            Line {
                name: format!("probe: {} load", l.name),
                style: Style {
                    dashed: true,
                    ..grey
                },
                points: [lo, hi]
                    .iter()
                    .map(|&x| Point {
                        x,
                        y: l.load_ns,
                        low: None,
                        high: None,
                        rounds: 0,
                    })
                    .collect(),
            }
        }));
    }
    h.push_str(&plot::loglog(
        "construction",
        "triangles",
        "ns per face",
        "ns per face",
        &lines(r, &styles, |m| Some(m.construction_ns_per_face)),
    ));
    h.push_str(&plot::loglog(
        "R00 sweep (warm)",
        "triangles",
        "ns per vertex",
        "ns per vertex",
        &r00,
    ));
    h.push_str(&plot::loglog(
        "smoothing",
        "triangles",
        "ns per vertex",
        "ns per vertex",
        &lines(r, &styles, |m| m.smoothing.as_ref().map(|t| t.ns)),
    ));
    h.push_str(&plot::loglog(
        "memory: resident",
        "triangles",
        "bytes per triangle",
        "bytes per triangle",
        &lines(r, &styles, |m| Some(per_tri(m.resident_bytes, m))),
    ));
    h.push_str(&plot::loglog(
        "memory: peak while building",
        "triangles",
        "bytes per triangle",
        "bytes per triangle",
        &lines(r, &styles, |m| Some(per_tri(m.peak_bytes, m))),
    ));
    h.push_str("</div>");
}

fn cells(h: &mut String, r: &ScaleResults) {
    h.push_str("<h2>Every cell</h2><div class=read><b>How to read it.</b> One row per structure and size. Times: median of the runs after one untimed run (at least 3, or 1 where the untimed run took over a sixth of a second), fastest–slowest below; construction is one build. Page faults: minor (a page mapped from memory) and major (read from the disk), while building and while sweeping; a structure that stays resident sweeps without major faults (the minor ones while sweeping are the kernels' own buffers touched the first time: the list of every vertex, smoothing's output). R00 is swept over every vertex only where it is local (O(k)); the scanning structures (O(n) per query) are timed on the sampled vertices, every structure is, and every result is compared across structures at each size.</div><table><tr><th class=l>structure</th><th>triangles</th><th>generate</th><th>construction ns/face</th><th>resident B/tri</th><th>peak B/tri</th><th>declared B/tri</th><th>build faults (minor, major)</th><th>R00 sweep ns/vertex</th><th>R00 sampled ns/query</th><th>smoothing ns/vertex</th><th>sweep faults</th></tr>");
    for c in &r.scale {
        let Outcome::Measured(m) = &c.outcome else {
            continue;
        };
        let _ = write!(
            h,
            "<tr><td class=l>{}</td><td>{}</td><td>{:.2} s</td><td>{:.1}</td><td>{:.1}</td><td>{:.1}</td><td>{:.1}</td><td>{}, {}</td><td>{}</td><td>{}</td><td>{}</td><td>{}, {}</td></tr>",
            esc(&c.structure), count(m.faces), m.generate_s, m.construction_ns_per_face,
            per_tri(m.resident_bytes, m), per_tri(m.peak_bytes, m), per_tri(m.declared_bytes, m),
            m.build_faults.minor, m.build_faults.major,
            timing(m.r00_sweep.as_ref()), timing(Some(&m.r00_sampled)), timing(m.smoothing.as_ref()),
            m.sweep_faults.minor, m.sweep_faults.major,
        );
    }
    h.push_str("</table>");
}

fn mapped(h: &mut String, r: &ScaleResults) {
    h.push_str("<h2>The CHE from a memory-mapped file</h2><div class=read><b>How to read it.</b> A torus written by <code>topolab convert --to che</code> (docs/che-format.md) and opened in place: the sweeping process first drops the file's pages from the page cache, then opens it three times (the first open reads the header from the disk; opening reads the header and maps the file, whatever its size); the first sweep runs before the verification, with bounds-checked reads, every page from the disk; the verification (one pass: the checksum, every id's range) follows, then the later sweeps with the verified walk, which find the pages mapped while the file fits the memory. Without a limit, the page cache is filled twice more (the file unmapped, its pages dropped, the file opened and verified again) and swept after each fill: where the kernel places the file's pages changes the warm time from one fill to the next while the runs of one fill agree, so the warm figure is the median over the fills. Where the sweeping process runs in a memory cgroup whose limit is a quarter of the file, the file cannot stay resident: every pass reads most of it from the disk again, and the answers are still exact (compared with the in-memory CHE's on the same torus where the run built one, and between the sweeps of the file). Faults count the kernel's faults, not pages: readahead brings many pages per major fault.</div>");
    if r.mapped.is_empty() {
        h.push_str("<p>This run opened no .che file.</p>");
        return;
    }
    h.push_str("<table><tr><th>triangles</th><th>level</th><th>file</th><th>convert</th><th>opens</th><th>verify</th><th class=l>memory limit</th><th>first sweep ns/vertex (faults minor, major)</th><th>later sweeps ns/vertex (faults)</th><th>warm after each fill of the page cache, ns/vertex</th><th>peak charged to the group</th><th>result</th></tr>");
    for m in &r.mapped {
        let limit = m
            .memory_limit
            .map_or("the machine's".to_string(), |b| bytes(b as f64));
        let agree = match m.in_memory_check {
            Some(c) if c.agrees(m.first_sweep.check) && m.fills().all(|t| c.agrees(t.check)) => {
                "the in-memory CHE's".to_string()
            }
            Some(Check::Exact(c)) => format!("<b>differs from the in-memory CHE's ({c:x})</b>"),
            Some(_) => "<b>differs</b>".to_string(),
            None if r.mapped.iter().all(|o| {
                o.triangles != m.triangles
                    || (o.first_sweep.check.agrees(m.first_sweep.check)
                        && o.fills().all(|t| t.check.agrees(m.first_sweep.check)))
            }) =>
            {
                "not compared with an in-memory CHE (none at this size); every sweep of the file the same, with and without the limit".to_string()
            }
            None => "<b>differs between the sweeps of the file</b>".to_string(),
        };
        let opens: Vec<String> = m.open_ms.iter().map(|t| format!("{t:.3}")).collect();
        let fills = if m.refills.is_empty() {
            "–".to_string()
        } else {
            let each: Vec<String> = m.fills().map(|t| ns(t.ns)).collect();
            format!("{} (median {})", each.join(", "), ns(m.warm().ns))
        };
        let _ = write!(
            h,
            "<tr><td>{}</td><td>{}</td><td>{}</td><td>{:.1} s</td><td>{} ms</td><td>{:.0} ms</td><td class=l>{} ({})</td><td>{} ({}, {})</td><td>{} ({}, {})</td><td>{fills}</td><td>{}</td><td class=l>{agree}</td></tr>",
            count(m.triangles), m.level, bytes(m.file_bytes as f64), m.convert_s, opens.join(", "), m.verify_ms,
            limit, esc(&m.limit_how),
            ns(m.first_sweep.ns), m.first_faults.minor, m.first_faults.major,
            timing(Some(&m.later_sweeps)), m.later_faults.minor, m.later_faults.major,
            m.group_peak_bytes.map_or("–".into(), |b| bytes(b as f64)),
        );
    }
    h.push_str("</table>");
}

fn machine(h: &mut String, r: &ScaleResults) {
    let m = &r.machine;
    let levels: Vec<String> = r
        .probe
        .iter()
        .map(|l| {
            format!(
                "{} ({}): {:.1} ns per load, {:.1} GB/s",
                l.name,
                bytes(l.bytes as f64),
                l.load_ns,
                l.read_bytes_per_s / 1e9
            )
        })
        .collect();
    let _ = write!(h, "<h2>Machine</h2><table><tr><th class=l>CPU</th><td class=l>{}</td></tr><tr><th class=l>cores</th><td class=l>{}</td></tr><tr><th class=l>caches</th><td class=l>{}</td></tr><tr><th class=l>memory</th><td class=l>{} ({} available at the start)</td></tr><tr><th class=l>compiler</th><td class=l>{}</td></tr><tr><th class=l>OpenMesh</th><td class=l>{}</td></tr><tr><th class=l>commit, date</th><td class=l>{}, {}</td></tr><tr><th class=l>probe</th><td class=l>{}</td></tr><tr><th class=l>timing</th><td class=l>wall clock, one process per cell, one cell at a time; construction: one build; kernels: median of at least 3 runs after an untimed one (a single run where the untimed one took over a third of the half-second budget)</td></tr></table>",
        esc(&m.cpu), m.cores, esc(&m.caches), bytes(r.memory_total as f64), bytes(r.memory_available as f64), esc(&m.rustc), esc(&m.openmesh), esc(&m.commit), esc(&m.date), esc(&levels.join("; ")));
}
