//! The texts beside a target's ratio: the same ratio from the size sweep's cells (the
//! structures timed one after another), and why a target is missed, measured.

use crate::measuring::kernels::{Kernel, Workload};
use crate::measuring::probe::Probe;
use crate::measuring::speed_limit::{limit_text, times_limit};
use crate::measuring::timing::turns::Spread;
use crate::results::{Limit, Measurement, Results, Status, Subject};
use crate::targets::measured::measured_chain;
use crate::targets::plan::{Against, Cell, Target, Turns, CHECKS};
use std::fmt::Write;
use topolab_structures::{Operator, Step};

/// The subject and kernel of the size sweep's cell that times what `cell` times; `None` for
/// the changing workloads, which have their own rows.
pub(crate) fn sequential_subject(cell: Cell) -> Option<(Subject, Kernel)> {
    match cell {
        Cell::R00Sweep => Some((Subject::Query(Operator::R00), Kernel::Sweep)),
        Cell::Smoothing => Some((Subject::Workload(Workload::Smoothing), Kernel::Workload)),
        Cell::Construction => Some((Subject::Construction, Kernel::Construction)),
        Cell::Changing(_) | Cell::Hull => None,
    }
}

/// The cell of the size sweep that times what a target's cell times (construction: its warm
/// builds), if it was measured; `None` for the changing workloads, which have their own rows.
pub fn sequential<'a>(
    measurements: &'a [Measurement],
    mesh: &str,
    s: &str,
    cell: Cell,
) -> Option<&'a Measurement> {
    let (subject, kernel) = sequential_subject(cell)?;
    measurements.iter().find(|m| {
        m.mesh == mesh
            && m.structure == s
            && m.operator == subject
            && m.kernel == kernel
            && m.status == Status::Measured
    })
}

/// The ratio of a target in the sequential cells (the structures timed one after another):
/// shown beside the one measured in turns, to see what taking turns changed.
pub(crate) fn one_after_another(r: &Results, mesh: &str, t: &Target) -> Option<f64> {
    if let Cell::Changing(w) = t.cell {
        let Against::Structure(b) = t.against else {
            return None;
        };
        return crate::studies::changing::ratio(&r.changing, w, t.structure, b);
    }
    if t.cell == Cell::Hull {
        // The hull table's medians of the same points, one algorithm after the other.
        let Against::Structure(b) = t.against else {
            return None;
        };
        let seconds =
            |a: &str| crate::studies::hull::bench::hull_target_row(&r.hull, a).map(|x| x.seconds);
        return Some(seconds(t.structure)? / seconds(b)?);
    }
    let a = sequential(&r.measurements, mesh, t.structure, t.cell)?;
    match t.against {
        Against::Structure(b) => {
            Some(a.ns_per_item? / sequential(&r.measurements, mesh, b, t.cell)?.ns_per_item?)
        }
        Against::Limit => times_limit(a),
    }
}

/// A construction target of one of the lab's structures against an outside one, measured with
/// the lab's checks as a third turn ([`CHECKS`]): how long the checks took in these rounds,
/// which the lab's build includes and the outside one's leaves out, and the ratio without
/// them (per round, the lab's build minus that round's checks, over the other's build).
/// `None` without that turn.
pub(crate) fn checks_text(turns: &[Turns], t: &Target, b: &str) -> Option<String> {
    let x = turns.iter().find(|x| {
        x.cell == Cell::Construction && x.runs(t.structure).is_some() && x.runs(b).is_some()
    })?;
    let (a_ns, b_ns, checks) = (x.runs(t.structure)?, x.runs(b)?, x.runs(CHECKS)?);
    let spent = Spread::of(checks.iter().copied())?;
    let without: Vec<f64> = a_ns.iter().zip(checks).map(|(a, c)| a - c).collect();
    let ratio = Spread::of_ratios(&without, b_ns)?;
    Some(format!(
        "{a}'s build includes its checks of the soup (indices in range, finite coordinates, the edge analysis, one fan per vertex), {c:.1} ns/face in these rounds ({cmin:.1}–{cmax:.1}), which {b}'s cell leaves out: the lab's checks run before its clock, as its users do not run them; without them {a} would be {r:.2}× ({rmin:.2}–{rmax:.2})",
        a = t.structure,
        c = spent.median,
        cmin = spent.min,
        cmax = spent.max,
        r = ratio.median,
        rmin = ratio.min,
        rmax = ratio.max,
    ))
}

/// Why `t.structure` misses its goal against `b`, measured: each side's bytes fetched per
/// element by its access model, its time as a multiple of its limit in the size sweep, and the
/// ratio of the two limits, which is as low as the ratio goes when both sides run at their
/// limits. `None` when a side has no limit.
pub(crate) fn versus_text(
    measurements: &[Measurement],
    mesh: &str,
    t: &Target,
    b: &str,
) -> Option<String> {
    let side = |s| {
        let m = sequential(measurements, mesh, s, t.cell)?;
        Some((s, m.limit.as_ref()?, times_limit(m)?))
    };
    let (a, b) = (side(t.structure)?, side(b)?);
    let text = |(s, l, x): (&str, &Limit, f64)| {
        format!(
            "{s} {x:.2}× its limit ({:.0} bytes per element at the {} bandwidth, {:.1} dependent loads)",
            l.bytes_per_item, l.bandwidth_level, l.loads_per_item
        )
    };
    Some(format!(
        "size sweep: {}; {}; at their limits the ratio would be {:.2}×",
        text(a),
        text(b),
        a.1.ns_per_item / b.1.ns_per_item
    ))
}

/// A sweep held to its limit against its chain at its own step's latency, in turns
/// ([`measured_chain`]), for a chain whose steps do work besides their load (for plain loads
/// it is the limit's latency bound again): shown on every such row, met or not. Below 1×, the
/// chains of consecutive queries overlapped.
pub(crate) fn chain_text(turns: &[Turns], t: &Target, l: &Limit) -> Option<String> {
    let c = measured_chain(turns, t, Some(l)).filter(|_| l.step != Step::Load)?;
    Some(format!(
        "against its chain at the step latency measured in each round ({} steps of {}, one query after another): {:.2}× in turns ({:.2}–{:.2})",
        l.loads_per_item,
        l.step.text(),
        c.median,
        c.min,
        c.max
    ))
}

/// Why a sweep misses its limit, measured: how the limit was set ([`limit_text`]), the sweep
/// against its chain ([`chain_text`]), and its chain at every level's latency of the run's
/// probe beside the sweep's median time in turns, which shows where the chain's loads would
/// have to come from to take that long.
pub(crate) fn missed_limit_text(turns: &[Turns], t: &Target, l: &Limit, probe: &Probe) -> String {
    let mut text = limit_text(l);
    if let Some(c) = chain_text(turns, t, l) {
        let _ = write!(text, "; {c}");
    }
    let sweep = turns
        .iter()
        .filter(|x| x.cell == t.cell)
        .find_map(|x| Spread::of(x.runs(t.structure)?.iter().copied()));
    if let (Some(s), true) = (sweep, l.loads_per_item > 0.0) {
        let levels: Vec<String> = probe
            .levels
            .iter()
            .map(|v| {
                let ns = l.loads_per_item * v.step_ns(l.step);
                format!("{} {ns:.1} ns", v.name)
            })
            .collect();
        let _ = write!(
            text,
            "; the sweep took {:.1} ns per element (median in turns), its chain at each level's latency: {}",
            s.median,
            levels.join(", ")
        );
    }
    text
}
