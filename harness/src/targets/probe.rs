//! The rounds of a structure held to its limit: its sweep takes turns with the probe's read,
//! chases and checksum arithmetic, so that each round's limit is the machine's in that round.

use crate::measuring::probe::{Chase, Cycle, Probe, Reader, Terms};
use crate::measuring::timing::meter::MemoryMeter;
use crate::measuring::timing::turns::{take_turns, Answer, Run, Stopwatch};
use crate::results::Limit;
use crate::targets::plan::{Cell, Turns, PROBE, PROBE_CHECKSUM, PROBE_LOAD, PROBE_STEP};
use crate::targets::rounds::{turns, Built};
use std::time::Instant;
use topolab_structures::{MeshTopology, PolygonSoup, Step};

/// What the probe measures again in every round beside a structure held to its limit, so that
/// the limit of each round is the machine's in that round ([`ProbeTurns::for_limit`]).
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct ProbeTurns {
    /// The working set of the limit's bandwidth bound: the read's ([`PROBE`]).
    pub read_bytes: usize,
    /// Bytes the read reads in one turn.
    pub read_per_turn: usize,
    /// The chases, when the limit has a chain to time.
    pub chase: Option<ChaseTurns>,
}

/// The probe's chases in the rounds of a target against its limit.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct ChaseTurns {
    /// The working set of the latency bound.
    pub bytes: usize,
    /// Hops in one turn.
    pub hops: usize,
    /// The work of the chain's steps, as the access model declares it: the kind of the
    /// second chase ([`PROBE_STEP`]; none for a plain load, which the first chase times).
    pub step: Step,
}

/// How long one of the probe's turns takes, about: a few milliseconds, as a sweep's run of a
/// large mesh does. Turns of the probe's own length (0.04 to 0.2 ms) read 0.45–0.92 of the
/// index half-edge's limit from round to round, an interruption being most of a turn.
const PROBE_TURN_NS: f64 = 4e6;

impl ProbeTurns {
    /// What the probe measures beside a sweep whose limit is `l`, sized from the run's probe
    /// (`probe`) so each turn takes about 4 ms on its working set: the read of
    /// the bandwidth bound's level, the chases of the latency bound's level when the limit has
    /// dependent loads. `None` when the probe has no level of that name.
    pub fn for_limit(l: &Limit, probe: &Probe) -> Option<Self> {
        let read = probe.level(&l.bandwidth_level)?;
        let per_turn = PROBE_TURN_NS * 1e-9 * read.read_bytes_per_s;
        let chase = if l.loads_per_item > 0.0 {
            let level = probe.level(&l.latency_level)?;
            let hop_ns = level.step_ns(l.step).max(level.load_ns);
            Some(ChaseTurns {
                bytes: level.bytes,
                hops: ((PROBE_TURN_NS / hop_ns) as usize).clamp(1 << 10, 1 << 22),
                step: l.step,
            })
        } else {
            None
        };
        Some(Self {
            read_bytes: read.bytes,
            read_per_turn: (per_turn as usize).clamp(4 << 20, 1 << 30),
            chase,
        })
    }
}

/// Times `A` on `cells` taking turns with the probe ([`ProbeTurns`]): its read, its chases and
/// its checksum arithmetic, each timed by a [`Stopwatch`] as the sweep is: a structure held to
/// its limit. `A` is built afresh in each of its turns and swept once untimed before its timed
/// sweep.
pub fn with_probe<A: MeshTopology>(
    mesh: &str,
    soup: &PolygonSoup,
    cells: &[Cell],
    probe: ProbeTurns,
    meter: &dyn MemoryMeter,
) -> Result<Vec<Turns>, String> {
    let mut a: Option<Built<A>> = None;
    let reader = Reader::reading(probe.read_bytes, probe.read_per_turn);
    let cycle = probe.chase.map(|c| Cycle::new(c.bytes));
    let chase = |step| {
        let (cycle, c) = cycle.as_ref().zip(probe.chase)?;
        Some(Chase::through(cycle, step).hopping(c.hops))
    };
    let mut load = chase(Step::Load);
    let mut step = probe
        .chase
        .filter(|c| c.step != Step::Load)
        .and_then(|c| chase(c.step));
    let terms = Terms::with_passes(1024);
    let mut names = vec![A::NAME, PROBE];
    names.extend(load.is_some().then_some(PROBE_LOAD));
    names.extend(step.is_some().then_some(PROBE_STEP));
    names.push(PROBE_CHECKSUM);
    let timed = |work: &mut dyn FnMut() -> usize| {
        let watch = Stopwatch::start(meter);
        let units = work();
        Run {
            ns: watch.ns() / units.max(1) as f64,
            answer: Answer::Probe,
        }
    };
    let mut out = Vec::new();
    for &cell in cells {
        let start = Instant::now();
        let ns = take_turns(cell.warm_up(), cell.rounds(), &names, |i| {
            Ok(match names[i] {
                PROBE => timed(&mut || reader.run()),
                PROBE_LOAD => {
                    let chase = load.as_mut().ok_or("no plain chase")?;
                    timed(&mut || chase.run())
                }
                PROBE_STEP => {
                    let chase = step.as_mut().ok_or("no chase of the chain's step")?;
                    timed(&mut || chase.run())
                }
                PROBE_CHECKSUM => timed(&mut || terms.run()),
                // A fresh build every round, as the size sweep's rounds: no target is one
                // draw of where the structure's arrays landed. A warm-up run first, untimed.
                _ => {
                    a = None;
                    let a = a.insert(Built::<A>::new(soup)?);
                    a.run(cell, meter)?;
                    return a.run(cell, meter);
                }
            })
        })?;
        out.push(turns(cell, mesh, soup, &names, ns, start));
    }
    Ok(out)
}
