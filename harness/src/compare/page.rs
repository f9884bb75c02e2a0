//! A [`Comparison`] for people: text for the terminal, and a self-contained HTML page (inline
//! CSS, no script, no network).

use super::{Cell, Comparison, Run};
use crate::format::{esc, ns};
use std::fmt::Write;

/// One line on a run: its file, commit, date, machine and command.
fn run_line(label: &str, path: &str, r: &Run) -> String {
    format!(
        "{label}: {path}: commit {}, {}, {} ({} cores), `{}`{}",
        or_unknown(&r.machine.commit),
        or_unknown(&r.machine.date),
        or_unknown(&r.machine.cpu),
        r.machine.cores,
        r.command,
        if r.format_version == 0 {
            ", written before results.json had a format version"
        } else {
            ""
        }
    )
}

fn or_unknown(s: &str) -> &str {
    if s.is_empty() {
        "unknown"
    } else {
        s
    }
}

/// The run-wide shift, in words.
fn shift_line(c: &Comparison) -> String {
    let pct = 100.0 * (c.shift - 1.0);
    format!(
        "Run-wide shift: the new run's cells are {:.1}% {} than the old's (the median of every cell's new/old ratio): the machine's own drift, or a change that moved every cell alike. Flags are taken against it.",
        pct.abs(),
        if pct >= 0.0 { "slower" } else { "faster" }
    )
}

/// The counts under the two runs.
fn counts(c: &Comparison) -> String {
    let share = |n: usize| 100.0 * n as f64 / c.cells.len().max(1) as f64;
    let mut s = format!(
        "{} cells measured in both, {} flagged ({:.1}%: their intervals of the median separate once the run-wide shift is taken out; {} with it left in); {} ({:.1}%) differ by more than 10%, {} ({:.1}%) by more than 25%",
        c.cells.len(),
        c.flagged(),
        share(c.flagged()),
        c.moved(),
        c.differ_by_more_than(0.10),
        share(c.differ_by_more_than(0.10)),
        c.differ_by_more_than(0.25),
        share(c.differ_by_more_than(0.25)),
    );
    for (n, what) in [
        (c.only_old, "only in the old run"),
        (c.only_new, "only in the new run"),
        (
            c.not_measured,
            "in both but not measured in both (skipped or refused)",
        ),
        (
            c.repaired_in_one,
            "of meshes repaired in one run only (different meshes, not compared)",
        ),
    ] {
        if n > 0 {
            let _ = write!(s, "; {n} {what}");
        }
    }
    s
}

fn cell_name(c: &Cell) -> [String; 4] {
    [
        c.structure.clone(),
        c.operator.name().to_string(),
        c.kernel.name().to_string(),
        c.mesh.clone(),
    ]
}

/// `×1.23 slower` / `×0.81 faster`, or `same`.
fn change(ratio: f64) -> String {
    if ratio > 1.0 {
        format!("{ratio:.2}× slower")
    } else if ratio < 1.0 {
        format!("{ratio:.2}× faster")
    } else {
        "same".into()
    }
}

/// The comparison as text: both runs, the counts, then every cell, the largest change first.
pub fn text(c: &Comparison, old_path: &str, new_path: &str) -> String {
    let mut t = String::new();
    let _ = writeln!(t, "{}", run_line("old", old_path, &c.old));
    let _ = writeln!(t, "{}", run_line("new", new_path, &c.new));
    let _ = writeln!(t, "{}", shift_line(c));
    let _ = writeln!(t, "{}", counts(c));
    if c.cells.is_empty() {
        return t;
    }
    let _ = writeln!(
        t,
        "{:>7}  {:<4}  {:<18} {:<16} {:<12} {:<24} {:>10} {:>10}",
        "new/old", "flag", "structure", "operator", "kernel", "mesh", "old", "new"
    );
    for cell in &c.cells {
        let [s, o, k, m] = cell_name(cell);
        let _ = writeln!(
            t,
            "{:>7.3}  {:<4}  {s:<18} {o:<16} {k:<12} {m:<24} {:>10} {:>10}",
            cell.ratio,
            if cell.flagged { "*" } else { "" },
            ns(cell.old.median),
            ns(cell.new.median)
        );
    }
    t
}

const CSS: &str = "body{font-family:system-ui,sans-serif;margin:2em;max-width:1200px;color:#222}\
table{border-collapse:collapse;font-size:12px;margin:1em 0}\
th,td{border:1px solid #ccc;padding:3px 6px;text-align:right} th{background:#f3f3f3}\
td.l,th.l{text-align:left} tr.slower td.r{background:#ffebee} tr.faster td.r{background:#e8f5e9}\
.small{color:#555;font-size:12px}";

/// The comparison as a self-contained HTML page.
pub fn html(c: &Comparison, old_path: &str, new_path: &str) -> String {
    let mut h = String::new();
    let _ = write!(
        h,
        "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>topolab compare</title><style>{CSS}</style></head><body><h1>topolab compare</h1>"
    );
    h.push_str("<table>");
    for (label, path, r) in [("old", old_path, &c.old), ("new", new_path, &c.new)] {
        let _ = write!(
            h,
            "<tr><th class=l>{label}</th><td class=l>{}</td><td class=l>commit {}</td><td class=l>{}</td><td class=l>{} ({} cores)</td><td class=l><code>{}</code></td><td class=l>format {}</td></tr>",
            esc(path),
            esc(or_unknown(&r.machine.commit)),
            esc(or_unknown(&r.machine.date)),
            esc(or_unknown(&r.machine.cpu)),
            r.machine.cores,
            esc(&r.command),
            r.format_version
        );
    }
    let _ = write!(h, "</table><p>{}</p><p>{}.</p><p class=small>new/old: the new median time over the old; above 1 the new run is slower. Flagged (red or green): the cell moved against the rest of the run: its two intervals of the median separate once the new run is divided by the run-wide shift (for a run written before cells had intervals: the new median outside the old run's fastest–slowest and the old median outside the new run's). Unflagged changes are within what one run or the other cannot tell apart, or move with the whole run. Sorted by the size of the change, either way. Compare runs of one machine for speed; across machines, the ratios between structures within each run say more.</p>", esc(&shift_line(c)), esc(&counts(c)));
    h.push_str("<table><tr><th>new/old</th><th class=l>structure</th><th class=l>operator</th><th class=l>kernel</th><th class=l>mesh</th><th>old median</th><th>old min–max</th><th>new median</th><th>new min–max</th><th class=l>change</th></tr>");
    for cell in &c.cells {
        let [s, o, k, m] = cell_name(cell);
        let class = match (cell.flagged, cell.ratio > 1.0) {
            (false, _) => "",
            (true, true) => "slower",
            (true, false) => "faster",
        };
        let _ = write!(
            h,
            "<tr class=\"{class}\"><td class=r>{:.3}</td><td class=l>{}</td><td class=l>{}</td><td class=l>{}</td><td class=l>{}</td><td>{}</td><td>{}–{}</td><td>{}</td><td>{}–{}</td><td class=l>{}{}</td></tr>",
            cell.ratio,
            esc(&s),
            esc(&o),
            esc(&k),
            esc(&m),
            ns(cell.old.median),
            ns(cell.old.min),
            ns(cell.old.max),
            ns(cell.new.median),
            ns(cell.new.min),
            ns(cell.new.max),
            change(cell.ratio),
            if cell.flagged { ", flagged" } else { "" }
        );
    }
    h.push_str("</table></body></html>\n");
    h
}
