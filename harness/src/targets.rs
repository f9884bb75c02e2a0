//! The Targets table: the project's performance targets, each a ratio measured with the two
//! sides taking turns.
//!
//! The size sweep times structures one after another, so on a shared machine a change of load
//! between two structures shows up in their ratio (a focused report once showed che-l2 /
//! index-half-edge at 3.09 on the vertex 1-ring sweep while che-l2's own runs ranged from
//! 10.6 to 27.1 ns). Here each target's two structures are built once on the largest torus
//! of the run and then run A, B, A, B, … for [`ROUNDS`] rounds, after one warm-up round; every
//! round gives one ratio, the table shows their median and their spread (the smallest and the
//! largest), and a load change hits both sides of a round alike. A target against a limit
//! (the vertex 1-ring sweep of the half-edge family against its access model, see
//! [`crate::limit`]) takes turns with the probe ([`with_probe`]: its read, its chases and its
//! checksum arithmetic) and divides each round of the sweep by the limit of that round, so the
//! limit follows the machine from round to round. Over six focused runs on one binary
//! (`topolab report --sections targets --sizes 1000000 --meshes torus`, 2026-12-02, load 1),
//! che-l2's R00 read 1.88–2.85× its limit with the latency and checksum bounds of the probe at
//! the start of the run and 2.18–2.34× with them measured in each round, the index half-edge
//! 0.80–1.21× and 0.88–1.06×, OpenMesh 1.50–2.31× and 1.79–2.03× (both from the same rounds).
//! A row held to a limit whose chain steps do arithmetic also shows the sweep against its
//! chain at its own step's latency ([`measured_chain`]): che-l2 1.11–1.28× in those runs.
//!
//! The runs are the size sweep's own: the harness kernels ([`crate::kernels::run`],
//! [`crate::kernels::run_workload`]), and a baseline's own loops for every run of a baseline
//! ([`topolab_structures::NativeKernels`]). Every run is timed in the measuring thread's CPU
//! time ([`Stopwatch`]), as the size sweep times construction: time slices given to other
//! processes do not count. Every run's answer must agree with the first run's; a disagreement
//! fails the report.

use crate::changing::MeshChecksum;
use crate::html::{esc, largest, limit_text, times_limit};
use crate::kernels::{run, run_workload, Kernel, Queries, Workload, WorkloadBuffers};
use crate::limit::Limit;
use crate::measure::{Builder, MemoryMeter};
use crate::probe::{Chase, Cycle, Probe, Reader, Terms};
use crate::results::{Measurement, Results, Status, Subject};
use crate::timing::median;
use std::fmt::Write;
use std::time::Instant;
use topolab_structures::algorithms::changing::Changing;
use topolab_structures::{BoundaryCurves, Constructed, MeshTopology, Operator, PolygonSoup, Step};

/// Timed rounds of every target, after one warm-up round. With 7, the median of one run
/// moved by more than the margins it was judged on: on one binary, seven runs of the che-l2 /
/// index-half-edge R00 target (torus-1M, 2026-12-01) read 1.16 to 1.26, their rounds 1.05 to
/// 1.38; with 21, two runs read 1.23 and 1.23, for about 4 s more in the report.
pub const ROUNDS: usize = 21;

/// Timed rounds of the changing workloads: each run is a fresh build and a whole workload
/// (about 1.5 s a round for the collapse test on a 1M-triangle torus), so fewer, to keep the
/// report within its time; no warm-up round, since every run starts from a fresh build.
pub const CHANGING_ROUNDS: usize = 3;

/// What a target times.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Cell {
    /// The vertex 1-ring sweep (R00 over every vertex), per vertex.
    R00Sweep,
    /// The smoothing workload, per vertex.
    Smoothing,
    /// Construction from the polygon soup, warm builds (reusing the memory the build before
    /// freed), per face.
    Construction,
    /// A changing workload from a fresh build (the build not timed), per face of the input.
    Changing(Changing),
}

impl Cell {
    /// The rounds a cell is timed: [`ROUNDS`], or [`CHANGING_ROUNDS`].
    pub fn rounds(self) -> usize {
        match self {
            Cell::Changing(_) => CHANGING_ROUNDS,
            _ => ROUNDS,
        }
    }

    /// Untimed rounds before them: one, but for the changing workloads.
    pub fn warm_up(self) -> usize {
        match self {
            Cell::Changing(_) => 0,
            _ => 1,
        }
    }

    /// The words the Targets table names it with.
    pub(crate) fn text(self) -> String {
        match self {
            Cell::R00Sweep => "vertex 1-ring sweep (r00)".into(),
            Cell::Smoothing => "smoothing".into(),
            Cell::Construction => "construction (warm builds)".into(),
            Cell::Changing(w) => w.name().into(),
        }
    }
}

/// What a target's structure is held against.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Against {
    /// Another structure, in the same rounds.
    Structure(&'static str),
    /// The cell's limit ([`crate::limit`]).
    Limit,
}

/// One performance target: `structure`'s `cell` at most `goal` times `against`'s.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Target {
    /// What is timed.
    pub cell: Cell,
    /// The structure held to the goal.
    pub structure: &'static str,
    /// What it is compared with.
    pub against: Against,
    /// The largest ratio that meets the target.
    pub goal: f64,
}

const fn versus(cell: Cell, structure: &'static str, against: &'static str, goal: f64) -> Target {
    Target {
        cell,
        structure,
        against: Against::Structure(against),
        goal,
    }
}

const fn limit(structure: &'static str) -> Target {
    Target {
        cell: Cell::R00Sweep,
        structure,
        against: Against::Limit,
        goal: 2.0,
    }
}

/// The targets of issue 15 (and the changing workloads'), in the table's order.
pub const TARGETS: [Target; 15] = [
    versus(Cell::Construction, "che-l1", "openmesh", 0.1),
    versus(Cell::R00Sweep, "che-l2", "index-half-edge", 1.2),
    versus(Cell::Smoothing, "che-l2", "index-half-edge", 1.2),
    versus(Cell::R00Sweep, "che-l2", "openmesh", 0.6),
    versus(Cell::Smoothing, "che-l2", "openmesh", 0.6),
    versus(Cell::R00Sweep, "index-half-edge", "openmesh", 0.5),
    // The half-edge family: the two half-edge storages, the CHE levels and OpenMesh.
    limit("index-half-edge"),
    limit("pointer-half-edge"),
    limit("che-l0"),
    limit("che-l1"),
    limit("che-l2"),
    limit("che-l3"),
    limit("openmesh"),
    versus(
        Cell::Changing(Changing::Sqrt3),
        "index-half-edge",
        "openmesh",
        0.7,
    ),
    versus(
        Cell::Changing(Changing::Collapse),
        "index-half-edge",
        "openmesh",
        0.7,
    ),
];

/// One group of structures that take turns on some cells.
#[derive(Clone, Debug, PartialEq)]
pub struct Group {
    /// The structures, in the order of their turns (one or two).
    pub structures: Vec<&'static str>,
    /// The cells they are timed on, one after another.
    pub cells: Vec<Cell>,
}

/// The groups that measure every target whose structures `can` run its cell (in the report:
/// the structure ran and the size sweep measured that cell, not skipped it as too long, such as
/// the vertex 1-ring sweep of a CHE level without a vertex-to-corner map): each pair of
/// structures once with all its cells; a structure held to its limit with the probe's read
/// ([`PROBE`]).
pub fn plan(can: impl Fn(&str, Cell) -> bool) -> Vec<Group> {
    let mut groups: Vec<Group> = Vec::new();
    for t in TARGETS.iter().filter(|t| can(t.structure, t.cell)) {
        let structures = match t.against {
            Against::Structure(b) if can(b, t.cell) => vec![t.structure, b],
            Against::Structure(_) => continue,
            Against::Limit => vec![t.structure, PROBE],
        };
        match groups.iter_mut().find(|g| g.structures == structures) {
            Some(g) if !g.cells.contains(&t.cell) => g.cells.push(t.cell),
            Some(_) => {}
            None => groups.push(Group {
                structures,
                cells: vec![t.cell],
            }),
        }
    }
    groups
}

/// The name of the probe's turn in the rounds of a target against its limit: a sequential read
/// of the working set whose bandwidth sets the limit's bandwidth bound ([`Reader`]).
pub const PROBE: &str = "probe";

/// What one run answered, to compare with the other runs.
#[derive(Copy, Clone, Debug, PartialEq)]
pub enum Answer {
    /// A sweep's checksum: equal, bit for bit.
    Sum(u64),
    /// A workload's float checksum: equal within a relative 1e-6 (each structure sums in its
    /// own order).
    Value(f64),
    /// A built mesh's vertices, edges and faces.
    Counts([usize; 3]),
    /// A changed mesh.
    Mesh(MeshChecksum),
    /// The probe's read, which answers nothing about the mesh: compared with nothing.
    Probe,
}

impl Answer {
    /// Whether two runs gave the same answer.
    pub fn agrees(&self, other: &Answer) -> bool {
        match (self, other) {
            (Answer::Value(a), Answer::Value(b)) => {
                (a - b).abs() <= 1e-6 * a.abs().max(b.abs()).max(1.0)
            }
            (Answer::Probe, _) | (_, Answer::Probe) => true,
            _ => self == other,
        }
    }
}

/// One timed run.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Run {
    /// Nanoseconds per item.
    pub ns: f64,
    /// What it answered.
    pub answer: Answer,
}

/// Runs `names.len()` contenders in turns: `warm_up` untimed rounds, then `rounds` timed ones,
/// each contender once per round in the order of `names` (`run(i)` runs contender `i` once).
/// Returns the ns of every timed run, by contender then round. Fails when a run fails or
/// answers differently from the first run (of any round, warm-up included), naming both.
pub fn take_turns(
    warm_up: usize,
    rounds: usize,
    names: &[&str],
    mut run: impl FnMut(usize) -> Result<Run, String>,
) -> Result<Vec<Vec<f64>>, String> {
    let mut ns = vec![Vec::with_capacity(rounds); names.len()];
    let mut first: Option<(&str, Answer)> = None;
    for round in 0..warm_up + rounds {
        for (i, &name) in names.iter().enumerate() {
            let got = run(i).map_err(|e| format!("{name}, round {}: {e}", round + 1))?;
            match first {
                None => first = Some((name, got.answer)),
                Some((who, answer)) if !answer.agrees(&got.answer) => {
                    return Err(format!(
                        "checksum mismatch in round {}: {name} answered {:?}, {who} answered {answer:?}",
                        round + 1,
                        got.answer
                    ))
                }
                Some(_) => {}
            }
            if round >= warm_up {
                ns[i].push(got.ns);
            }
        }
    }
    Ok(ns)
}

/// The median of per-round values and their spread.
#[derive(Copy, Clone, Debug, PartialEq, serde::Serialize)]
pub struct Spread {
    /// The median.
    pub median: f64,
    /// The smallest.
    pub min: f64,
    /// The largest.
    pub max: f64,
    /// How many values.
    pub rounds: usize,
}

impl Spread {
    /// The spread of `values`; `None` when there is none or one is not a positive finite
    /// number (a run that took no time, or a limit of zero, makes no ratio).
    pub fn of(values: impl IntoIterator<Item = f64>) -> Option<Spread> {
        let mut v: Vec<f64> = values.into_iter().collect();
        if v.is_empty() || v.iter().any(|x| !x.is_finite() || *x <= 0.0) {
            return None;
        }
        v.sort_by(f64::total_cmp);
        Some(Spread {
            median: median(&v),
            min: v[0],
            max: v[v.len() - 1],
            rounds: v.len(),
        })
    }

    /// The per-round ratios `a[i] / b[i]` of two contenders' runs in the same rounds; `None`
    /// when their rounds do not match or a ratio cannot be made ([`Spread::of`]).
    pub fn of_ratios(a: &[f64], b: &[f64]) -> Option<Spread> {
        if a.len() != b.len() {
            return None;
        }
        Spread::of(a.iter().zip(b).map(|(x, y)| x / y))
    }
}

/// The rounds of one cell: the structures that took turns and each one's runs.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Turns {
    /// What was timed.
    pub cell: Cell,
    /// On which mesh.
    pub mesh: String,
    /// Items per run (vertices or faces).
    pub items: usize,
    /// The structures, in the order of their turns.
    pub structures: Vec<String>,
    /// Nanoseconds per item of every timed run, by structure (as `structures`) then round.
    pub ns_per_item: Vec<Vec<f64>>,
    /// Untimed warm-up rounds before them.
    pub warm_up: usize,
    /// Wall time of all the rounds, warm-up included, seconds.
    pub seconds: f64,
}

impl Turns {
    /// The runs of `structure`, if it took turns.
    pub fn runs(&self, structure: &str) -> Option<&[f64]> {
        let i = self.structures.iter().position(|s| s == structure)?;
        self.ns_per_item.get(i).map(Vec::as_slice)
    }
}

/// The ratio a target measured in turns: per round, `structure`'s run over `against`'s. Against
/// its limit (the size sweep's cell's, `limit`), over the limit of that round: its bandwidth,
/// latency and checksum bounds at the bandwidth, load latency and time per checksum term the
/// probe's turns measured in that round ([`with_probe`]; the run's probe's, for rounds
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
            ..s
        })
}

/// Times one run in the measuring thread's CPU time when the meter knows it
/// ([`MemoryMeter::thread_cpu_ns`]), else by the wall clock. On a machine with more runnable
/// processes than cores, a run of a few milliseconds is preempted for whole time slices, which
/// the wall clock counts and the thread's CPU time does not: the rounds of a target then
/// differ by what the structures did, not by when the scheduler took the core away.
pub struct Stopwatch<'a> {
    meter: &'a dyn MemoryMeter,
    cpu: Option<u64>,
    wall: Instant,
}

impl<'a> Stopwatch<'a> {
    /// Starts timing.
    pub fn start(meter: &'a dyn MemoryMeter) -> Self {
        Self {
            meter,
            cpu: meter.thread_cpu_ns(),
            wall: Instant::now(),
        }
    }

    /// Nanoseconds since the start.
    pub fn ns(&self) -> f64 {
        match (self.cpu, self.meter.thread_cpu_ns()) {
            (Some(a), Some(b)) => b.saturating_sub(a) as f64,
            _ => self.wall.elapsed().as_nanos() as f64,
        }
    }
}

/// A structure built once, with what its timed runs need.
pub struct Built<M> {
    m: M,
    q: Queries,
    curves: BoundaryCurves,
    buf: WorkloadBuffers,
}

impl<M: MeshTopology> Built<M> {
    /// Builds `M` from `soup`.
    pub fn new(soup: &PolygonSoup) -> Result<Self, String> {
        let m = M::from_soup(soup).map_err(|e| format!("cannot build {}: {e}", M::NAME))?;
        // Every vertex, the sweep's queries of R00 as `Queries::all` has them; no cell of a
        // target reads the others.
        let q = Queries::every_vertex(&m);
        Ok(Self {
            m,
            q,
            curves: BoundaryCurves::default(),
            buf: WorkloadBuffers::default(),
        })
    }

    /// One run of a sweep or of smoothing, natively for a baseline, as the size sweep runs it,
    /// timed by a [`Stopwatch`] on `meter`.
    pub fn run(&mut self, cell: Cell, meter: &dyn MemoryMeter) -> Result<Run, String> {
        let native = M::native();
        let watch = Stopwatch::start(meter);
        let (items, answer) = match cell {
            Cell::R00Sweep => {
                let op = Operator::R00;
                let sum = match native {
                    Some(k) => k
                        .sweep(&self.m, op)
                        .map_err(|e| format!("native kernel failed: {e}"))?,
                    None => run(&self.m, op, &self.q, &mut self.curves),
                };
                (self.q.count(op), Answer::Sum(sum))
            }
            Cell::Smoothing => {
                let w = Workload::Smoothing;
                let value = match native {
                    Some(k) => k
                        .workload(&mut self.m, w)
                        .map_err(|e| format!("native kernel failed: {e}"))?,
                    None => run_workload(&self.m, w, &mut self.buf),
                };
                (
                    w.items(self.m.num_vertices(), self.m.num_faces()),
                    Answer::Value(value),
                )
            }
            Cell::Construction | Cell::Changing(_) => {
                return Err(format!("{cell:?} is not run on a built structure"))
            }
        };
        let ns = watch.ns();
        Ok(Run {
            ns: std::hint::black_box(ns) / items.max(1) as f64,
            answer,
        })
    }
}

/// One build of `M`, as the size sweep times construction ([`Builder`]: the baseline's own
/// construction when it has one), timed by a [`Stopwatch`] on `meter`; the structure is
/// finished and dropped after the clock.
pub fn build<M: MeshTopology>(
    builder: &Builder<M>,
    meter: &dyn MemoryMeter,
) -> Result<Run, String> {
    let watch = Stopwatch::start(meter);
    let built = std::hint::black_box(builder.build());
    let ns = watch.ns();
    let m = built
        .and_then(Constructed::finish)
        .map_err(|e| format!("cannot build {}: {e}", M::NAME))?;
    let answer = Answer::Counts([m.num_vertices(), m.num_edges(), m.num_faces()]);
    let faces = m.num_faces();
    drop(m);
    Ok(Run {
        ns: ns / faces.max(1) as f64,
        answer,
    })
}

/// Times `A` and `B` on `mesh` taking turns on each of `cells` (sweeps, smoothing,
/// construction; not the changing workloads, which need editing): both are built once first,
/// when a cell needs them built.
pub fn pair<A: MeshTopology, B: MeshTopology>(
    mesh: &str,
    soup: &PolygonSoup,
    cells: &[Cell],
    meter: &dyn MemoryMeter,
) -> Result<Vec<Turns>, String> {
    let names = [A::NAME, B::NAME];
    let mut built = None;
    let mut out = Vec::new();
    for &cell in cells {
        let start = Instant::now();
        let ns = if cell == Cell::Construction {
            // The lab's checks and the facts a baseline is told, once, before any clock.
            let cannot =
                |name: &str, e: topolab_structures::Error| format!("cannot build {name}: {e}");
            let a = Builder::<A>::new(soup).map_err(|e| cannot(A::NAME, e))?;
            let b = Builder::<B>::new(soup).map_err(|e| cannot(B::NAME, e))?;
            take_turns(cell.warm_up(), cell.rounds(), &names, |i| match i {
                0 => build(&a, meter),
                _ => build(&b, meter),
            })?
        } else {
            if built.is_none() {
                built = Some((Built::<A>::new(soup)?, Built::<B>::new(soup)?));
            }
            let (a, b) = built.as_mut().expect("built above");
            take_turns(cell.warm_up(), cell.rounds(), &names, |i| match i {
                0 => a.run(cell, meter),
                _ => b.run(cell, meter),
            })?
        };
        out.push(turns(cell, mesh, soup, &names, ns, start));
    }
    Ok(out)
}

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

/// The probe's plain chase in the rounds of a target against its limit: ns per dependent load
/// at the latency bound's working set ([`crate::probe::Chase`]).
pub const PROBE_LOAD: &str = "probe-load";
/// The probe's chase whose steps do the chain's work ([`ChaseTurns::step`]): ns per step.
pub const PROBE_STEP: &str = "probe-step";
/// The probe's checksum arithmetic ([`crate::probe::Terms`]): ns per term.
pub const PROBE_CHECKSUM: &str = "probe-checksum";

/// Times `A` on `cells` taking turns with the probe ([`ProbeTurns`]): its read, its chases and
/// its checksum arithmetic, each timed by a [`Stopwatch`] as the sweep is: a structure held to
/// its limit.
pub fn with_probe<A: MeshTopology>(
    mesh: &str,
    soup: &PolygonSoup,
    cells: &[Cell],
    probe: ProbeTurns,
    meter: &dyn MemoryMeter,
) -> Result<Vec<Turns>, String> {
    let mut a = Built::<A>::new(soup)?;
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
                _ => return a.run(cell, meter),
            })
        })?;
        out.push(turns(cell, mesh, soup, &names, ns, start));
    }
    Ok(out)
}

/// The [`Turns`] of `cell`'s runs `ns`, timed since `start`.
pub fn turns(
    cell: Cell,
    mesh: &str,
    soup: &PolygonSoup,
    names: &[&str],
    ns: Vec<Vec<f64>>,
    start: Instant,
) -> Turns {
    let items = match cell {
        Cell::R00Sweep | Cell::Smoothing => soup.num_vertices(),
        Cell::Construction | Cell::Changing(_) => soup.num_faces(),
    };
    Turns {
        cell,
        mesh: mesh.into(),
        items,
        structures: names.iter().map(|s| s.to_string()).collect(),
        ns_per_item: ns,
        warm_up: cell.warm_up(),
        seconds: start.elapsed().as_secs_f64(),
    }
}

/// The subject and kernel of the size sweep's cell that times what `cell` times; `None` for
/// the changing workloads, which have their own rows.
fn sequential_subject(cell: Cell) -> Option<(Subject, Kernel)> {
    match cell {
        Cell::R00Sweep => Some((Subject::Query(Operator::R00), Kernel::Sweep)),
        Cell::Smoothing => Some((Subject::Workload(Workload::Smoothing), Kernel::Workload)),
        Cell::Construction => Some((Subject::Construction, Kernel::Construction)),
        Cell::Changing(_) => None,
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
fn one_after_another(r: &Results, mesh: &str, t: &Target) -> Option<f64> {
    if let Cell::Changing(w) = t.cell {
        let Against::Structure(b) = t.against else {
            return None;
        };
        return crate::changing::ratio(&r.changing, w, t.structure, b);
    }
    let a = sequential(&r.measurements, mesh, t.structure, t.cell)?;
    match t.against {
        Against::Structure(b) => {
            Some(a.ns_per_item? / sequential(&r.measurements, mesh, b, t.cell)?.ns_per_item?)
        }
        Against::Limit => times_limit(a),
    }
}

/// Why `t.structure` misses its goal against `b`, measured: each side's bytes fetched per
/// element by its access model, its time as a multiple of its limit in the size sweep, and the
/// ratio of the two limits, which is as low as the ratio goes when both sides run at their
/// limits. `None` when a side has no limit.
fn versus_text(measurements: &[Measurement], mesh: &str, t: &Target, b: &str) -> Option<String> {
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
fn chain_text(turns: &[Turns], t: &Target, l: &Limit) -> Option<String> {
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
fn missed_limit_text(turns: &[Turns], t: &Target, l: &Limit, probe: &Probe) -> String {
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

/// A ratio as the table shows it beside its goal: two decimals, more where two would read as
/// the goal itself while the ratio is not (1.2016 missing a goal of 1.2 reads 1.202×, not
/// 1.20×, beside its "no"; 1.1996 meeting it reads 1.1996×).
fn against_goal(ratio: f64, goal: f64) -> String {
    let digits = (2..6)
        .find(|&d| ratio == goal || format!("{ratio:.d$}") != format!("{goal:.d$}"))
        .unwrap_or(6);
    format!("{ratio:.digits$}×")
}

/// The table cell's class for a "met" column of "yes", "no" or "–".
fn class_of(met: &str) -> &'static str {
    match met {
        "yes" => "ok",
        "no" => "bad",
        _ => "skip",
    }
}

/// Why che-l1's construction misses its target, shown under the row when it does: the build's
/// passes as measured pass by pass (see the CHE build module's docs, where the alternatives
/// tried are measured too).
pub const CHE_L1_CONSTRUCTION: &str = "Measured separately on 2026-12-01, not in this run, pass by pass (torus-1M, warm, median of 9 rounds in turns with OpenMesh, ns/face; `cargo run --release --example build_sweep -- 1000000 torus 9 all passes`): copy G[] 1.2 and check it finite 0.6, copy V[] 1.1, pair O[] 10.4, VH[] (Algorithm 3) 2.0, one-fan walk 3.2; whole build 18.9 against OpenMesh's 72.9 (its add_face compiled here at -O3 without assertions), so the target leaves 7.3 ns/face, less than the pairing alone. The pairing waits on its bucket walk (one dependent load per step), and pairing by a counting sort, by vertex stars or by fixed slots measured no faster.";

/// The measured reason shown under a target that is not met and has one ([`CHE_L1_CONSTRUCTION`]).
fn reason(t: &Target, met: &str) -> Option<&'static str> {
    (met == "no" && t.cell == Cell::Construction && t.structure == "che-l1")
        .then_some(CHE_L1_CONSTRUCTION)
}

/// The Targets section: every target measured in turns, on the largest torus of the run.
pub fn render(h: &mut String, r: &Results) {
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
        let why = match (t.against, limit, reason(t, met)) {
            (Against::Limit, Some(l), _) if met == "no" => {
                esc(&missed_limit_text(&turns, t, l, &r.probe))
            }
            (Against::Limit, Some(l), _) => esc(&chain_text(&turns, t, l).unwrap_or_default()),
            (_, _, Some(measured)) => esc(measured),
            (Against::Structure(b), _, _) if met == "no" => {
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

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::{meshes, CheL2, IndexHalfEdge};

    fn sum(ns: f64, s: u64) -> Result<Run, String> {
        Ok(Run {
            ns,
            answer: Answer::Sum(s),
        })
    }

    #[test]
    fn the_median_of_the_round_ratios_and_their_spread() {
        // Round 2 is disturbed: both sides slow, their ratio stays.
        let a = [10.0, 40.0, 12.0, 11.0, 30.0];
        let b = [5.0, 20.0, 4.0, 5.5, 10.0];
        let s = Spread::of_ratios(&a, &b).unwrap();
        assert_eq!(
            s,
            Spread {
                median: 2.0,
                min: 2.0,
                max: 3.0,
                rounds: 5
            }
        );
        let even = Spread::of([1.0, 4.0, 2.0, 3.0]).unwrap();
        assert_eq!((even.median, even.min, even.max), (2.5, 1.0, 4.0));
        // Rounds that do not match, nothing, or a zero time make no ratio.
        assert_eq!(Spread::of_ratios(&a, &b[..4]), None);
        assert_eq!(Spread::of([]), None);
        assert_eq!(Spread::of_ratios(&[1.0], &[0.0]), None);
    }

    #[test]
    fn turns_alternate_and_a_different_checksum_fails_loudly() {
        let mut order = Vec::new();
        let ns = take_turns(1, 3, &["a", "b"], |i| {
            order.push(i);
            sum(10.0 * (order.len()) as f64, 7)
        })
        .unwrap();
        assert_eq!(order, [0, 1, 0, 1, 0, 1, 0, 1]);
        // The warm-up round is not kept.
        assert_eq!(ns, vec![vec![30.0, 50.0, 70.0], vec![40.0, 60.0, 80.0]]);
        // b answers differently in its third run.
        let mut runs = 0;
        let err = take_turns(0, 3, &["a", "b"], |i| {
            runs += 1;
            sum(1.0, if i == 1 && runs == 6 { 8 } else { 7 })
        })
        .unwrap_err();
        assert!(
            err.contains("checksum mismatch in round 3") && err.contains("b answered Sum(8)"),
            "{err}"
        );
        // A failed run names its contender and round.
        let err = take_turns(0, 2, &["a", "b"], |i| {
            if i == 0 {
                sum(1.0, 7)
            } else {
                Err("native kernel failed".into())
            }
        })
        .unwrap_err();
        assert_eq!(err, "b, round 1: native kernel failed");
        // Floats agree within a relative 1e-6, not beyond.
        assert!(Answer::Value(1e6).agrees(&Answer::Value(1e6 + 0.5)));
        assert!(!Answer::Value(1e6).agrees(&Answer::Value(1e6 + 2.0)));
    }

    #[test]
    fn the_plan_times_each_pair_once_and_a_limit_alone_only_when_untimed() {
        let all = plan(|_, _| true);
        let find = |s: &[&str]| all.iter().find(|g| g.structures == s);
        assert_eq!(
            find(&["che-l2", "index-half-edge"]).unwrap().cells,
            [Cell::R00Sweep, Cell::Smoothing]
        );
        assert_eq!(
            find(&["index-half-edge", "openmesh"]).unwrap().cells,
            [
                Cell::R00Sweep,
                Cell::Changing(Changing::Sqrt3),
                Cell::Changing(Changing::Collapse)
            ]
        );
        assert_eq!(
            find(&["che-l1", "openmesh"]).unwrap().cells,
            [Cell::Construction]
        );
        // Every structure held to its limit takes turns with the probe's read.
        for s in ["che-l2", "openmesh", "che-l1", "pointer-half-edge"] {
            assert_eq!(find(&[s, PROBE]).unwrap().cells, [Cell::R00Sweep], "{s}");
        }
        assert_eq!(all.len(), 4 + 7);
        // Without OpenMesh, its pairs and its limit go.
        let without = plan(|s, _| s != "openmesh");
        assert!(without.iter().all(|g| !g.structures.contains(&"openmesh")));
        assert_eq!(without.len(), 1 + 6);
        // A cell the size sweep skipped is not run in turns either.
        let slow = plan(|s, c| !(s == "che-l1" && c == Cell::R00Sweep));
        assert!(slow.iter().all(|g| g.structures != ["che-l1", PROBE]));
        assert!(slow.iter().any(|g| g.structures == ["che-l1", "openmesh"]));
        // A structure held only to its limit.
        assert_eq!(
            plan(|s, _| s == "che-l2"),
            [Group {
                structures: vec!["che-l2", PROBE],
                cells: vec![Cell::R00Sweep]
            }]
        );
    }

    #[test]
    fn two_structures_take_turns_with_equal_checksums() {
        let soup = meshes::torus(12, 9);
        struct Wall;
        impl MemoryMeter for Wall {
            fn current(&self) -> usize {
                0
            }
            fn peak(&self) -> usize {
                0
            }
            fn reset_peak(&self) {}
        }
        let cells = [Cell::R00Sweep, Cell::Smoothing, Cell::Construction];
        let turns = pair::<CheL2, IndexHalfEdge>("t", &soup, &cells, &Wall).unwrap();
        assert_eq!(turns.len(), 3);
        for t in &turns {
            assert_eq!(t.structures, ["che-l2", "index-half-edge"]);
            assert!(t.ns_per_item.iter().all(|r| r.len() == ROUNDS));
        }
        let target = pair_target(Cell::Smoothing);
        let s = measured(&turns, &target, None).unwrap();
        assert_eq!(s.rounds, ROUNDS);
        assert!(s.min <= s.median && s.median <= s.max);
        // Against a limit: the sweep takes turns with the probe's read.
        let target = Target {
            against: Against::Limit,
            ..pair_target(Cell::R00Sweep)
        };
        // What the probe takes turns with, from the limit: the level's working sets, about
        // 4 ms of work a turn on the run's probe's machine.
        let mut l = limit_of(0.0, 0.0, 0.0);
        (l.loads_per_item, l.step) = (3.0, Step::Corner);
        let probe = ProbeTurns::for_limit(&l, &machine()).unwrap();
        let chase = ChaseTurns {
            bytes: 1 << 14,
            hops: 2_000_000,
            step: Step::Corner,
        };
        let expected = ProbeTurns {
            read_bytes: 1 << 14,
            read_per_turn: 400_000_000,
            chase: Some(chase),
        };
        assert_eq!(probe, expected);
        // No chain, no chases; no level of that name, no turns.
        let flat = ProbeTurns::for_limit(&limit_of(0.0, 0.0, 0.0), &machine()).unwrap();
        assert_eq!(flat.chase, None);
        l.latency_level = "L7".into();
        assert_eq!(ProbeTurns::for_limit(&l, &machine()), None);
        // Shorter turns for the test.
        let probe = ProbeTurns {
            read_per_turn: 1 << 20,
            chase: Some(ChaseTurns {
                hops: 1 << 12,
                ..chase
            }),
            ..probe
        };
        let turns = with_probe::<CheL2>("t", &soup, &[Cell::R00Sweep], probe, &Wall).unwrap();
        assert_eq!(
            turns[0].structures,
            ["che-l2", PROBE, PROBE_LOAD, PROBE_STEP, PROBE_CHECKSUM]
        );
        assert_eq!(measured(&turns, &target, None), None);
        let probe_runs = |name| {
            let r = turns[0].runs(name).unwrap();
            assert!(
                r.iter().all(|&ns| ns > 0.0 && ns.is_finite()),
                "{name}: {r:?}"
            );
            assert_eq!(r.len(), ROUNDS);
            r
        };
        let (read, load, step, terms) = (
            probe_runs(PROBE),
            probe_runs(PROBE_LOAD),
            probe_runs(PROBE_STEP),
            probe_runs(PROBE_CHECKSUM),
        );
        let runs = turns[0].runs("che-l2").unwrap();
        // Each round's sweep over that round's limit, the largest of its three bounds.
        let expect = |l: &Limit, bound: &dyn Fn(usize) -> f64| {
            assert_eq!(
                measured(&turns, &target, Some(l)).unwrap().median,
                median_of((0..ROUNDS).map(|i| runs[i] / bound(i)))
            );
        };
        // A bandwidth bound: the bytes at that round's read.
        let mut l = limit_of(1000.0, 0.0, 0.0);
        expect(&l, &|i| 1000.0 * read[i]);
        // A latency bound far above it: the loads at that round's chase, not the run's probe's.
        (l.loads_per_item, l.latency_ns_per_item) = (1e9, 1.0);
        expect(&l, &|i| 1e9 * load[i]);
        // A checksum bound above both: the terms at that round's time per term.
        (l.checksum_terms_per_item, l.checksum_ns_per_item) = (1e12, 1.0);
        expect(&l, &|i| 1e12 * terms[i]);
        // Rounds measured without the chase and the checksum turns take the run's probe's.
        let old = without_probe_turns(&turns);
        (l.checksum_terms_per_item, l.checksum_ns_per_item) = (0.0, 0.0);
        l.latency_ns_per_item = 1e6;
        assert_eq!(
            measured(&old, &target, Some(&l)).unwrap().median,
            median_of(runs.iter().map(|r| r / 1e6))
        );
        // A probe's turn with fewer rounds than the sweep's makes no ratio.
        let mut short = turns.clone();
        short[0].ns_per_item[2].pop();
        assert_eq!(measured(&short, &target, Some(&l)), None);
        // Against its chain: the loads at that round's chase of the chain's own step; a plain
        // load's chain is the plain chase.
        l.loads_per_item = 3.0;
        for (kind, chase) in [(Step::Corner, step), (Step::Load, load)] {
            l.step = kind;
            let expected = median_of((0..ROUNDS).map(|i| runs[i] / (3.0 * chase[i])));
            let chain = measured_chain(&turns, &target, Some(&l)).unwrap();
            assert!(
                (chain.median - expected).abs() <= 1e-12 * chain.median,
                "{kind:?}: {chain:?}"
            );
        }
        // No chain without its turns.
        assert_eq!(measured_chain(&old, &target, Some(&l)), None);
    }

    #[test]
    fn only_a_missed_che_l1_construction_shows_its_breakdown() {
        let construction = TARGETS[0];
        assert_eq!(
            (construction.cell, construction.structure),
            (Cell::Construction, "che-l1")
        );
        assert_eq!(reason(&construction, "no"), Some(CHE_L1_CONSTRUCTION));
        assert_eq!(reason(&construction, "yes"), None);
        assert_eq!(reason(&construction, "–"), None);
        assert_eq!(reason(&pair_target(Cell::Smoothing), "no"), None);
        // The breakdown names every pass of the build.
        for pass in ["G[]", "V[]", "O[]", "VH[]", "one-fan walk", "OpenMesh"] {
            assert!(CHE_L1_CONSTRUCTION.contains(pass), "{pass}");
        }
    }

    #[test]
    fn a_ratio_beside_its_goal_never_rounds_to_it() {
        assert_eq!(against_goal(1.2016, 1.2), "1.202×");
        assert_eq!(against_goal(1.2004, 1.2), "1.2004×");
        assert_eq!(against_goal(1.1996, 1.2), "1.1996×");
        assert_eq!(against_goal(1.2, 1.2), "1.20×");
        assert_eq!(against_goal(1.27, 1.2), "1.27×");
        assert_eq!(against_goal(0.6449, 0.6), "0.64×");
    }

    #[test]
    fn a_missed_limit_says_how_far_the_sweep_is_from_its_chain() {
        let target = Target {
            against: Against::Limit,
            ..pair_target(Cell::R00Sweep)
        };
        let names = ["che-l2", PROBE, PROBE_LOAD, PROBE_STEP, PROBE_CHECKSUM];
        let turns = vec![Turns {
            cell: Cell::R00Sweep,
            mesh: "t".into(),
            items: 100,
            structures: names.iter().map(|s| s.to_string()).collect(),
            // The sweep 9, 12 and 15 ns; a corner step 2 ns, then 2, then 2.5.
            ns_per_item: vec![
                vec![9.0, 12.0, 15.0],
                vec![0.01; 3],
                vec![1.0; 3],
                vec![2.0, 2.0, 2.5],
                vec![0.5; 3],
            ],
            warm_up: 1,
            seconds: 1.0,
        }];
        let mut l = limit_of(52.0, 3.0, 3.0);
        (l.loads_per_item, l.step, l.chain_ns_per_item) = (3.0, Step::Corner, 6.0);
        let probe = machine();
        let text = missed_limit_text(&turns, &target, &l, &probe);
        // Per round 9 / 6, 12 / 6, 15 / 7.5: a median of 2, from 1.5 to 2.
        assert!(
            text.contains(
                "3 steps of the CHE's prev(h), then the load, one query after another): 2.00× in turns (1.50–2.00)"
            ),
            "{text}"
        );
        assert!(
            text.contains("the sweep took 12.0 ns per element"),
            "{text}"
        );
        assert!(text.contains("L1 6.0 ns, memory 600.0 ns"), "{text}");
        // The chain measured once, beside the limit.
        assert!(
            text.contains(
                "takes 2.00× a plain load at the L1 latency, so the chain alone takes 6.0 ns"
            ),
            "{text}"
        );
        // Without the probe's chases nothing is said of the chain in turns.
        let old = without_probe_turns(&turns);
        assert!(!missed_limit_text(&old, &target, &l, &probe).contains("against its chain"));
    }

    #[test]
    fn a_missed_target_between_two_structures_says_how_far_each_is_from_its_limit() {
        let sweep = |s: &str, ns: f64, bytes: f64, limit_ns: f64| {
            let mut l = limit_of(bytes, 0.0, 0.0);
            (l.ns_per_item, l.bandwidth_level) = (limit_ns, "memory".into());
            Measurement {
                ns_per_item: Some(ns),
                items: 500_000,
                reps: 1,
                limit: Some(l),
                ..Measurement::new(
                    s,
                    Subject::Query(Operator::R00),
                    Kernel::Sweep,
                    "torus-1M",
                    "torus",
                    1_000_000,
                )
            }
        };
        let t = Target {
            cell: Cell::R00Sweep,
            structure: "index-half-edge",
            against: Against::Structure("openmesh"),
            goal: 0.5,
        };
        let ms = [
            sweep("index-half-edge", 9.2, 52.0, 8.0),
            sweep("openmesh", 16.0, 100.0, 15.0),
        ];
        let text = versus_text(&ms, "torus-1M", &t, "openmesh").unwrap();
        assert!(
            text.contains("index-half-edge 1.15× its limit (52 bytes"),
            "{text}"
        );
        assert!(
            text.contains("openmesh 1.07× its limit (100 bytes"),
            "{text}"
        );
        assert!(text.contains("the ratio would be 0.53×"), "{text}");
        // Without a limit on one side there is nothing measured to say.
        assert_eq!(versus_text(&ms[..1], "torus-1M", &t, "openmesh"), None);
    }

    /// L1 of 16 kB at 100 GB/s and 1 ns a load (a CHE corner step 2 ns), memory of 1 MiB at
    /// 10 GB/s and 100 ns a load.
    fn machine() -> Probe {
        use crate::probe::Level;
        Probe {
            read_bytes_per_s: 1e10,
            read_array_bytes: 1 << 20,
            chase_ns_per_hop: 100.0,
            chase_array_bytes: 1 << 20,
            levels: vec![
                Level::for_tests("L1", 1 << 14, 100.0, 1.0),
                Level::for_tests("memory", 1 << 20, 10.0, 100.0),
            ],
            checksum_ns: 0.5,
        }
    }

    /// The median of `values`.
    fn median_of(values: impl IntoIterator<Item = f64>) -> f64 {
        let mut v: Vec<f64> = values.into_iter().collect();
        v.sort_by(f64::total_cmp);
        median(&v)
    }

    /// `turns` as measured before the probe took its chase and checksum turns: the structure
    /// and the probe's read only.
    fn without_probe_turns(turns: &[Turns]) -> Vec<Turns> {
        let mut old = turns.to_vec();
        for t in &mut old {
            t.structures.truncate(2);
            t.ns_per_item.truncate(2);
        }
        old
    }

    fn limit_of(bytes: f64, latency: f64, checksum: f64) -> Limit {
        Limit {
            ns_per_item: 0.0,
            bound: crate::limit::Bound::Bandwidth,
            bytes_per_item: bytes,
            bandwidth_ns_per_item: 0.0,
            bandwidth_level: "L1".into(),
            loads_per_item: 0.0,
            latency_ns_per_item: latency,
            latency_level: "L1".into(),
            checksum_ns_per_item: checksum,
            checksum_terms_per_item: 0.0,
            step: Step::Load,
            chain_ns_per_item: 0.0,
            note: None,
        }
    }

    fn pair_target(cell: Cell) -> Target {
        Target {
            cell,
            structure: "che-l2",
            against: Against::Structure("index-half-edge"),
            goal: 1.2,
        }
    }
}
