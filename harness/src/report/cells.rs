//! Looking cells up in the results, for the sections that draw them: a structure's cells of
//! one kind by size, their plot lines, the largest mesh of a family, a sweep against its limit.

use crate::kernels::Kernel;
use crate::plot;
use crate::plot::Style;
use crate::report::format::ns;
use crate::results::{Bound, Limit};
use crate::results::{Measurement, Results, Subject};
use std::fmt::Write;
use topolab_structures::{Input, Operator, Step};

/// The measured cells of one (structure, operator, kernel, family), by size.
pub(crate) fn cells<'a>(
    r: &'a Results,
    s: &str,
    op: Subject,
    kernel: Kernel,
    family: &str,
) -> Vec<&'a Measurement> {
    let mut v: Vec<&Measurement> = r
        .measurements
        .iter()
        .filter(|m| {
            m.structure == s && m.operator == op && m.kernel == kernel && m.family == family
        })
        .collect();
    v.sort_by_key(|m| m.triangles);
    v
}

/// One plot line per structure: its measured ns per item against triangles.
pub(crate) fn lines(
    r: &Results,
    op: Subject,
    kernel: Kernel,
    family: &str,
    ci: &dyn Fn(&str) -> Style,
) -> Vec<plot::Line> {
    r.structures
        .iter()
        .map(|s| plot::Line {
            name: s.name.clone(),
            style: ci(&s.name),
            points: cells(r, &s.name, op, kernel, family)
                .iter()
                .filter_map(|m| {
                    Some(plot::Point {
                        x: m.triangles as f64,
                        y: m.ns_per_item?,
                        low: m.ns_per_item_ci.map(|c| c[0]),
                        high: m.ns_per_item_ci.map(|c| c[1]),
                        rounds: m.rounds,
                    })
                })
                .collect(),
        })
        .collect()
}

/// The kernel an operator's row of Table 4.1 and its plot show: the sampled queries, or the
/// sweep for boundary curves (one query per mesh, nothing to sample).
pub(crate) fn table_kernel(op: Operator) -> Kernel {
    if op.input() == Input::Mesh {
        Kernel::Sweep
    } else {
        Kernel::Sampled
    }
}

pub(crate) fn family_of(op: Operator) -> &'static str {
    if crate::rounds::boundary(op) {
        "grid"
    } else {
        "torus"
    }
}

pub(crate) fn largest<'a>(r: &'a Results, family: &str) -> Option<(&'a str, usize)> {
    r.meshes
        .iter()
        .filter(|m| m.family == family)
        .max_by_key(|m| m.triangles)
        .map(|m| (m.name.as_str(), m.triangles))
}

/// A measured cell's time as a multiple of its limit.
pub(crate) fn times_limit(m: &Measurement) -> Option<f64> {
    Some(m.ns_per_item? / m.limit.as_ref()?.ns_per_item)
}

/// How a limit was set, for a cell's tooltip and a target's reason.
pub(crate) fn limit_text(l: &Limit) -> String {
    let bound = match l.bound {
        Bound::Latency => "latency",
        Bound::Bandwidth => "bandwidth",
        Bound::Checksum => "checksum",
    };
    let mut t = format!(
        "{bound} bound; latency: {:.1} dependent loads per element at the {} latency ({}); bandwidth: {:.1} bytes per element at the {} bandwidth ({}); checksum arithmetic: {}",
        l.loads_per_item,
        l.latency_level,
        ns(l.latency_ns_per_item),
        l.bytes_per_item,
        l.bandwidth_level,
        ns(l.bandwidth_ns_per_item),
        ns(l.checksum_ns_per_item)
    );
    if l.step != Step::Load && l.chain_ns_per_item > 0.0 {
        let _ = write!(
            t,
            "; the chain's arithmetic, measured: a step of {} takes {:.2}× a plain load at the {} latency, so the chain alone takes {}",
            l.step.text(),
            l.chain_ns_per_item / l.latency_ns_per_item,
            l.latency_level,
            ns(l.chain_ns_per_item)
        );
    }
    if let Some(n) = &l.note {
        let _ = write!(t, "; not in the model: {n}");
    }
    t
}
