//! How sure a number is, on the page: a cell's interval where its value is shown (a hover
//! title: [`interval_title`], [`ns_with_interval`]), whether two cells can be told apart
//! ([`tied`]), and in the Machine section the rounds each mesh got and the drift probe read
//! before every mesh ([`machine`]).

use crate::format::{esc, ns};
use crate::measuring::timing::interval::Interval;
use crate::results::{Measurement, Results};
use std::fmt::Write;
use topolab_structures::summary::plural;

/// A measured cell's interval, if it has one.
pub(crate) fn interval(m: &Measurement) -> Option<Interval> {
    let [low, high] = m.ns_per_item_ci?;
    Some(Interval {
        low,
        high,
        coverage: m.ci_coverage.unwrap_or(0.0),
    })
}

/// The hover title of a cell's value: its interval, its coverage and its rounds.
pub(crate) fn interval_title(m: &Measurement) -> String {
    match interval(m) {
        Some(ci) => format!(
            "{:.0}% interval {} to {}, median of {} round{}, each on a fresh build",
            ci.coverage * 100.0,
            ns(ci.low),
            ns(ci.high),
            m.rounds,
            plural(m.rounds)
        ),
        None => String::new(),
    }
}

/// A cell's ns per item in a `<span>` whose title is its interval ([`interval_title`]).
pub(crate) fn ns_with_interval(m: &Measurement) -> String {
    let Some(x) = m.ns_per_item else {
        return String::new();
    };
    match interval(m) {
        Some(_) => format!(
            "<span title=\"{}\">{}</span>",
            esc(&interval_title(m)),
            ns(x)
        ),
        None => ns(x),
    }
}

/// Whether two cells cannot be told apart: their intervals overlap (or one has none).
pub(crate) fn tied(a: &Measurement, b: &Measurement) -> bool {
    match (interval(a), interval(b)) {
        (Some(x), Some(y)) => !x.separates(&y),
        _ => true,
    }
}

/// The Machine section's part on how sure the numbers are: the rounds of each mesh, how wide
/// the intervals came out, and the drift probe over the run.
pub(crate) fn machine(h: &mut String, r: &Results) {
    let measured: Vec<&Measurement> = r
        .measurements
        .iter()
        .filter(|m| m.ns_per_item.is_some() && m.ns_per_item_ci.is_some())
        .collect();
    if !measured.is_empty() {
        let width = |m: &&Measurement| {
            let ci = interval(m).expect("filtered");
            ci.relative_width(m.ns_per_item.unwrap_or(0.0))
        };
        let share = |limit: f64| {
            measured.iter().filter(|m| width(m) <= limit).count() as f64 / measured.len() as f64
        };
        let _ = write!(
            h,
            "<h3>How sure the numbers are</h3><p>Every cell was measured in rounds, each on fresh builds of every structure in a random order (see the timing row above). Of {} cells with an interval, {:.0}% have an interval narrower than 10% of their value, {:.0}% narrower than 25%. Two cells differ only where their intervals do not overlap; the chooser and the findings say <i>tied</i> otherwise.</p>",
            measured.len(),
            100.0 * share(0.10),
            100.0 * share(0.25)
        );
    }
    if !r.rounds.is_empty() {
        h.push_str("<table><tr><th class=l>mesh</th><th>rounds</th><th>of them extra</th><th>time</th></tr>");
        for row in &r.rounds {
            let _ = write!(
                h,
                "<tr><th class=l>{}</th><td>{}</td><td>{}</td><td>{:.1} s</td></tr>",
                esc(&row.mesh),
                row.rounds,
                row.extra,
                row.seconds
            );
        }
        h.push_str("</table>");
    }
    if r.drift.len() >= 2 {
        let _ = write!(
            h,
            "<h3>The machine over the run</h3><p>The same probe before every mesh: a sequential read and a dependent chase through {}, and the checksum arithmetic in L1, each the median of {} runs. Nothing of a structure is in it: what moves here is the machine.</p>",
            crate::format::bytes(crate::measuring::probe::DRIFT_BYTES as f64),
            crate::measuring::probe::DRIFT_RUNS
        );
        h.push_str(&drift_svg(&r.drift));
        let (lo, hi) = r
            .drift
            .iter()
            .map(|d| d.read_bytes_per_s)
            .fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)));
        let _ = write!(
            h,
            "<p>Read bandwidth between {:.1} and {:.1} GB/s over the run ({:.0}% apart).</p>",
            lo / 1e9,
            hi / 1e9,
            100.0 * (hi / lo - 1.0)
        );
    }
}

/// The drift probe's three readings over the run as lines on a linear plot, each relative to
/// its own median over the run (1 = its usual value; above 1, slower).
fn drift_svg(points: &[crate::measuring::probe::DriftPoint]) -> String {
    type Get = fn(&crate::measuring::probe::DriftPoint) -> f64;
    let series: [(&str, &str, Get); 3] = [
        ("read time per byte", "#1f77b4", |d| {
            1.0 / d.read_bytes_per_s
        }),
        ("load latency", "#d62728", |d| d.load_ns),
        ("checksum term", "#2ca02c", |d| d.term_ns),
    ];
    let (w, hgt, left, right, top, bottom) = (640.0, 200.0, 56.0, 170.0, 12.0, 34.0);
    let t_max = points.iter().map(|d| d.at_s).fold(1.0, f64::max);
    let rel: Vec<Vec<f64>> = series
        .iter()
        .map(|(_, _, get)| {
            let mut v: Vec<f64> = points.iter().map(get).collect();
            let mut sorted = v.clone();
            sorted.sort_by(f64::total_cmp);
            let mid = crate::measuring::timing::median(&sorted);
            v.iter_mut().for_each(|x| *x /= mid);
            v
        })
        .collect();
    let (lo, hi) = rel
        .iter()
        .flatten()
        .fold((0.9f64, 1.1f64), |(a, b), &x| (a.min(x), b.max(x)));
    let x = |t: f64| left + (w - left - right) * t / t_max;
    let y = |v: f64| top + (hgt - top - bottom) * (hi - v) / (hi - lo);
    let mut svg = format!(
        "<svg class=drift width={w} height={hgt} viewBox=\"0 0 {w} {hgt}\" role=img aria-label=\"the drift probe over the run\"><rect x={left} y={top} width={} height={} fill=none stroke=#999 />",
        w - left - right,
        hgt - top - bottom
    );
    for v in [lo, 1.0, hi] {
        let _ = write!(
            svg,
            "<text x={} y={:.1} font-size=11 text-anchor=end>{v:.2}</text>",
            left - 4.0,
            y(v) + 4.0
        );
    }
    let _ = write!(
        svg,
        "<line x1={left} x2={} y1={:.1} y2={:.1} stroke=#ccc /><text x={left} y={} font-size=11>0 s</text><text x={} y={} font-size=11 text-anchor=end>{t_max:.0} s since the start</text>",
        w - right,
        y(1.0),
        y(1.0),
        hgt - 16.0,
        w - right,
        hgt - 16.0
    );
    for (k, ((name, colour, _), v)) in series.iter().zip(&rel).enumerate() {
        let pts: Vec<String> = points
            .iter()
            .zip(v)
            .map(|(d, &r)| format!("{:.1},{:.1}", x(d.at_s), y(r)))
            .collect();
        let _ = write!(
            svg,
            "<polyline fill=none stroke=\"{colour}\" stroke-width=1.5 points=\"{}\" /><text x={} y={} font-size=12 fill=\"{colour}\">{name}</text>",
            pts.join(" "),
            w - right + 8.0,
            top + 14.0 + 16.0 * k as f64
        );
    }
    svg.push_str("</svg>");
    svg
}
