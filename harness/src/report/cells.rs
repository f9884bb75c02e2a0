//! Looking cells up in the results, for the sections that draw them: a structure's cells of
//! one kind by size, their plot lines, the largest mesh of a family, a sweep against its limit.

use crate::measuring::kernels::Kernel;
use crate::page::plot;
use crate::page::plot::Style;
use crate::results::{Measurement, Results, Subject};
use topolab_structures::{Input, Operator};

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
    if crate::measuring::rounds::boundary(op) {
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
