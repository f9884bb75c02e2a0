//! The ratio a target measured in turns, per round: against another structure, against its
//! limit at the probe's figures of that round, or against its chain.

use crate::measuring::timing::turns::Spread;
use crate::results::{Limit, Results};
use crate::targets::plan::{
    Against, Cell, Target, Turns, PROBE, PROBE_CHECKSUM, PROBE_LOAD, PROBE_STEP,
};
use topolab_structures::Step;

/// Whether `name` ran in `r`: a structure of the run, or an algorithm of the hull section.
pub fn ran(r: &Results, name: &str) -> bool {
    r.structures.iter().any(|x| x.name == name) || r.hull.iter().any(|x| x.algorithm == name)
}

/// The turns the Targets show for the largest torus `mesh`: those taken on it, and the hull's,
/// taken on its own points.
pub fn shown_turns(r: &Results, mesh: &str) -> Vec<Turns> {
    r.targets
        .iter()
        .filter(|t| t.mesh == mesh || t.cell == Cell::Hull)
        .cloned()
        .collect()
}

/// The ratio a target measured in turns: per round, `structure`'s run over `against`'s. Against
/// its limit (the size sweep's cell's, `limit`), over the limit of that round: its bandwidth,
/// latency and checksum bounds at the bandwidth, load latency and time per checksum term the
/// probe's turns measured in that round ([`with_probe`](crate::targets::probe::with_probe); the run's probe's, for rounds
/// measured without the chase and the checksum turns).
pub fn measured(turns: &[Turns], t: &Target, limit: Option<&Limit>) -> Option<Spread> {
    let mut of_cell = turns.iter().filter(|x| x.cell == t.cell);
    match t.against {
        Against::Structure(b) => {
            of_cell.find_map(|x| Spread::of_ratios(x.runs(t.structure)?, x.runs(b)?))
        }
        Against::Limit => {
            let l = limit?;
            let x = of_cell.find(|x| x.runs(t.structure).is_some() && x.runs(PROBE).is_some())?;
            let runs = x.runs(t.structure)?;
            // A probe's turns, if it took them: as many rounds as the sweep's, or no ratio.
            let probe = |name| match x.runs(name) {
                Some(r) if r.len() != runs.len() => Err(()),
                r => Ok(r),
            };
            let (read, load, terms) = (
                probe(PROBE).ok()??,
                probe(PROBE_LOAD).ok()?,
                probe(PROBE_CHECKSUM).ok()?,
            );
            Spread::of(runs.iter().enumerate().map(|(i, ns)| {
                let latency = load.map_or(l.latency_ns_per_item, |r| l.loads_per_item * r[i]);
                let checksum =
                    terms.map_or(l.checksum_ns_per_item, |r| l.checksum_terms_per_item * r[i]);
                ns / (l.bytes_per_item * read[i]).max(latency).max(checksum)
            }))
        }
    }
}

/// A target against its limit, against its chain instead: per round, the sweep over its
/// chain's dependent loads at the latency of a step doing the chain's work
/// ([`Limit::step`]), as the probe's chase of that kind measured it in the same round. What it
/// leaves of "× limit" is the work off the chain; `None` without those turns.
pub fn measured_chain(turns: &[Turns], t: &Target, limit: Option<&Limit>) -> Option<Spread> {
    let l = limit.filter(|l| t.against == Against::Limit && l.loads_per_item > 0.0)?;
    let chase = if l.step == Step::Load {
        PROBE_LOAD
    } else {
        PROBE_STEP
    };
    turns
        .iter()
        .filter(|x| x.cell == t.cell)
        .find_map(|x| Spread::of_ratios(x.runs(t.structure)?, x.runs(chase)?))
        .map(|s| Spread {
            median: s.median / l.loads_per_item,
            min: s.min / l.loads_per_item,
            max: s.max / l.loads_per_item,
            low: s.low / l.loads_per_item,
            high: s.high / l.loads_per_item,
            ..s
        })
}
