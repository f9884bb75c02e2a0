//! One structure on one mesh, as the rounds time it ([`Entry`]): set up once (its memory
//! counted, its queries prepared in its own ids, the cells too long to run skipped with their
//! estimates), then built afresh and run once per round, its round values kept until
//! [`Contender::finish`] makes them the mesh's cells.

use crate::measuring::cells::{Measurement, Status, Subject};
use crate::measuring::kernels::{run, run_workload, Kernel, Queries, QuerySet, WorkloadBuffers};
use crate::measuring::measure::{
    measurement, per_query_ns, skips, Builder, Estimator, MeshCase, Plan,
};
use crate::measuring::rounds::{
    CellKey, Said, BATCH_NS, PASS_CHECK_NS, ROUND_NS, WARM_UP_BELOW_NS,
};
use crate::measuring::timing::interval::Interval;
use crate::measuring::timing::median;
use crate::measuring::timing::meter::MemoryMeter;
use crate::measuring::timing::turns::{Answer, Stopwatch};
use std::collections::HashMap;
use std::time::Instant;
use topolab_structures::{BoundaryCurves, Input, MeshTopology, Operator};

/// What the rounds ask of one structure on one mesh, whatever its type: a fresh build, one
/// round of a cell, and at the end its cells.
pub trait Contender {
    /// The structure's name.
    fn name(&self) -> &'static str;
    /// The mesh's name.
    fn mesh(&self) -> &str;
    /// The cells it times besides construction, in the sweep's order.
    fn cells(&self) -> Vec<CellKey>;
    /// Drops this round's structure.
    fn release(&mut self);
    /// Builds the structure afresh, timed, and keeps it for the round's cells; with `cold`, one
    /// build after the allocator returned its free memory is timed first and dropped.
    fn build(&mut self, round: usize, cold: bool, meter: &dyn MemoryMeter) -> Result<(), String>;
    /// One round of `cell` on the structure built for `round`: what it answered.
    fn run(&mut self, cell: CellKey, round: usize, meter: &dyn MemoryMeter)
        -> Result<Said, String>;
    /// The values of `cell` (construction included) by round: (round, ns per item).
    fn rounds(&self, cell: CellKey) -> &[(usize, f64)];
    /// The rounds of the structure's own input checks timed alone after its build, when asked
    /// for ([`SetUp::checks`]): (round, ns per face).
    fn checks(&self) -> &[(usize, f64)];
    /// The cells, measured, skipped or refused; the estimator learns their run times.
    fn finish(self: Box<Self>, est: &mut Estimator) -> Vec<Measurement>;
}

/// One timed cell's rounds.
struct Timed {
    /// Its place in the sweep's order of cells.
    index: usize,
    key: CellKey,
    /// Items of one run: queries of a sweep or workload; for a sampled cell, the queries of
    /// its first round.
    items: usize,
    /// Wall ns of one run, from its first round's warm-up (batches and warm-ups are sized by
    /// it).
    one_run_ns: Option<f64>,
    /// Whether each query (or each element of a workload) scans the mesh (a declared cost of
    /// O(n) or more): such a run reads the whole structure again and again, so it is its own
    /// warm-up and gets none.
    scans: bool,
    /// (round, ns per item).
    values: Vec<(usize, f64)>,
    /// Timed runs (sampled: passes) over every round.
    runs: usize,
    /// The first round's answer, as results show it.
    checksum: Option<String>,
    native: bool,
}

/// The builds' rounds.
#[derive(Default)]
struct Builds {
    /// (round, ns per face) of the warm builds, each the round's structure.
    warm: Vec<(usize, f64)>,
    /// ns per face of the cold builds.
    cold: Vec<f64>,
    warm_faults: Vec<f64>,
    cold_faults: Vec<f64>,
    faces: Option<usize>,
    /// Whether the input checks are timed alone after each build.
    time_checks: bool,
    /// (round, ns per face) of the input checks alone.
    checks: Vec<(usize, f64)>,
}

/// A structure `M` on a mesh: its builder, this round's structure, the queries, the cells.
pub struct Entry<'a, M: MeshTopology> {
    case: &'a MeshCase<'a>,
    builder: Builder<'a, M>,
    m: Option<M>,
    /// The construction cell, its memory filled in by the counting build.
    construction: Measurement,
    builds: Builds,
    /// Every element (the sweeps' queries).
    all: Queries,
    /// Per round, its sampled queries in passes of [`crate::measuring::rounds::PASS`].
    passes: Vec<Vec<Queries>>,
    curves: BoundaryCurves,
    buf: WorkloadBuffers,
    timed: Vec<Timed>,
    /// Cells not run (skipped), in their place of the sweep's order: (index in the cells'
    /// order, the cell).
    untimed: Vec<(usize, Measurement)>,
}

/// What setting a structure up gave: a contender, or the refused construction cell.
pub enum Setup<'a> {
    /// The structure stores the mesh: it takes part in the rounds.
    Ready(Box<dyn Contender + 'a>),
    /// It refused the mesh: its construction cell, marked refused.
    Refused(Box<Measurement>),
}

impl<'a, M: MeshTopology> Entry<'a, M> {
    /// Sets `M` up on `case`: admits and builds it once with the allocator counting (its
    /// memory), prepares the sweeps' queries and each round's sampled `sets` in its ids, and
    /// decides which cells run (the others are skipped with their estimate, from `est` or from
    /// a probe of its sampled queries).
    pub fn set_up(
        case: &'a MeshCase<'a>,
        sets: &[QuerySet],
        plan: &Plan,
        meter: &dyn MemoryMeter,
        est: &Estimator,
        checks: bool,
    ) -> Result<Setup<'a>, String> {
        let mut cons = measurement::<M>(Subject::Construction, Kernel::Construction, case);
        let refused = |mut cons: Measurement, e: topolab_structures::Error| {
            cons.status = Status::Refused;
            cons.note = Some(format!("{}: {e}", e.kind()));
            Ok(Setup::Refused(Box::new(cons)))
        };
        let builder = match Builder::<M>::new(case.soup) {
            Ok(builder) => builder,
            Err(e) => return refused(cons, e),
        };
        meter.counting(true);
        meter.reset_peak();
        let before = meter.current();
        let built = builder.build().and_then(|b| builder.finish(b));
        let peak = meter.peak().saturating_sub(before);
        let held = meter.current().saturating_sub(before);
        meter.counting(false);
        let m = match built {
            Ok(m) => m,
            Err(e) => return refused(cons, e),
        };
        cons.bytes = Some(held as u64);
        cons.peak_bytes = Some(peak as u64);
        cons.declared_bytes = Some(m.heap_bytes() as u64);
        cons.native = builder.is_native();
        // A light plan times the vertex 1-ring sweep only: its queries are the vertices,
        // without the edges and (edge, face) pairs whose hash map of edges took longer than the
        // sweep itself on the 3.3M refined armadillo.
        let (all, sampled) = if plan.light {
            let probe = sets.first().map(Queries::sampled_vertices);
            (Queries::every_vertex(&m), probe.into_iter().collect())
        } else {
            Queries::all_and_sampled(&m, case.soup, sets)
        };
        let passes: Vec<Vec<Queries>> = sampled
            .iter()
            .map(|q| q.passes(crate::measuring::rounds::PASS))
            .collect();
        let mut entry = Entry {
            case,
            builder,
            m: None,
            construction: cons,
            builds: Builds {
                time_checks: checks && M::input_checks().is_some(),
                ..Builds::default()
            },
            all,
            passes,
            curves: BoundaryCurves::default(),
            buf: WorkloadBuffers::default(),
            timed: Vec::new(),
            untimed: Vec::new(),
        };
        entry.plan_cells(&m, plan, est)?;
        Ok(Setup::Ready(Box::new(entry)))
    }

    /// Decides which cells run: a cell whose one run is estimated above the plan's
    /// `cell_max` is skipped with its estimate. The estimate extrapolates the last smaller
    /// size of the family by the declared cost; at a family's first size it is the time per
    /// query of a probe of the first round's sampled queries times the cell's queries.
    fn plan_cells(&mut self, m: &M, plan: &Plan, est: &Estimator) -> Result<(), String> {
        let case = self.case;
        let n = case.soup.num_faces();
        let probe = match self.passes.first() {
            Some(round) => join(round).spread(crate::measuring::measure::PROBE_QUERIES),
            None => Queries::default(),
        };
        let mut per_query: HashMap<Operator, f64> = HashMap::new();
        let mut curves = BoundaryCurves::default();
        let native = M::native().is_some();
        // On a grid, the tables read the boundary operators (and everything of a structure that
        // stores grids only): nothing else is measured there.
        let shown = |subject: Subject| {
            !plan.boundary_only
                || M::capabilities().grids_only
                || matches!(subject, Subject::Query(op) if crate::measuring::rounds::boundary(op))
        };
        for (index, key) in crate::measuring::rounds::cells(plan.light, plan.sampled)
            .into_iter()
            .enumerate()
            .filter(|(_, key)| shown(key.0))
        {
            let (subject, kernel) = key;
            let mut cell = measurement::<M>(subject, kernel, case);
            let (items, e, estimate) = match subject {
                Subject::Query(op) => {
                    let items = if kernel == Kernel::Sweep {
                        self.all.count(op)
                    } else {
                        crate::measuring::rounds::PASS.min(probe.count(op).max(1))
                    };
                    // A sweep's run grows with n^(1+e), a pass of sampled queries with n^e.
                    let e = M::cost(op).expected_exponent()
                        + if kernel == Kernel::Sweep { 1.0 } else { 0.0 };
                    let context = |e: String| {
                        format!("{} {} {kernel} on {}: {e}", M::NAME, op.name(), case.name)
                    };
                    let first = if op.input() == Input::Mesh {
                        // Finding the boundary curves decides for every edge whether it is on
                        // the boundary: a boundary-edge sweep's estimate.
                        let edge = Operator::BoundaryEdge;
                        per_query_ns(m, edge, &probe, &mut per_query, &mut curves)
                            .map_err(context)?
                            .map(|ns| ns * self.all.count(edge) as f64)
                    } else {
                        per_query_ns(m, op, &probe, &mut per_query, &mut curves)
                            .map_err(context)?
                            .map(|ns| ns * items as f64)
                    };
                    (items, e, first)
                }
                Subject::Workload(w) => {
                    let items = w.items(m.num_vertices(), m.num_faces());
                    // A workload asks its relations once per element.
                    let e = 1.0
                        + w.relations()
                            .iter()
                            .map(|&op| M::cost(op).expected_exponent())
                            .fold(0.0, f64::max);
                    let mut ns = 0.0;
                    for &op in w.relations() {
                        let per = per_query_ns(m, op, &probe, &mut per_query, &mut curves)
                            .map_err(|e| {
                                format!("{} {} on {}: {e}", M::NAME, w.name(), case.name)
                            })?;
                        ns += per.unwrap_or(0.0) * self.all.count(op) as f64;
                    }
                    (items, e, Some(ns))
                }
                Subject::Construction => unreachable!("construction is not among the cells"),
            };
            cell.items = items;
            // The run's exponent beyond its items: 1 or more when every query scans.
            let per_item = if kernel == Kernel::Sampled {
                e
            } else {
                e - 1.0
            };
            let key_est = Estimator::key(M::NAME, case.family, subject, kernel);
            let estimate = est.estimate(&key_est, n, e).or(estimate);
            if skips(&mut cell, estimate, plan) {
                self.untimed.push((index, cell));
                continue;
            }
            self.timed.push(Timed {
                index,
                key,
                items,
                one_run_ns: None,
                scans: per_item >= 1.0,
                values: Vec::new(),
                runs: 0,
                checksum: None,
                native,
            });
        }
        Ok(())
    }

    /// One timed build of `builder`: ns per face, minor faults and the structure (finished
    /// after the clock).
    fn timed_build(&self, meter: &dyn MemoryMeter) -> Result<(f64, Option<f64>, M), String> {
        let before = meter.minor_faults();
        let watch = Stopwatch::start(meter);
        let built = std::hint::black_box(self.builder.build());
        let ns = watch.ns();
        let faults = before
            .zip(meter.minor_faults())
            .map(|(a, b)| b.saturating_sub(a) as f64);
        let m = built
            .and_then(|b| self.builder.finish(b))
            .map_err(|e| self.builder.failure(e))?;
        let faces = m.num_faces();
        if let Some(first) = self.builds.faces.filter(|&f| f != faces) {
            return Err(format!("a build has {faces} faces, the first had {first}"));
        }
        Ok((ns / faces.max(1) as f64, faults, m))
    }
}

/// The passes of one round joined back into one set (the probe of the estimates).
fn join(passes: &[Queries]) -> Queries {
    let mut q = Queries::default();
    for p in passes {
        q.vertices.extend_from_slice(&p.vertices);
        q.edges.extend_from_slice(&p.edges);
        q.faces.extend_from_slice(&p.faces);
        q.edge_faces.extend_from_slice(&p.edge_faces);
    }
    q
}

/// Runs `once` for one round of a sweep or a workload: an untimed warm-up first when a run is
/// shorter than [`WARM_UP_BELOW_NS`] and does not scan the mesh per query (`scans`; in the
/// first round always: it sizes the rest), then
/// batches of runs, each batch timed by one reading of the [`Stopwatch`] and long enough
/// ([`BATCH_NS`]) for the clock's cost not to count, until the round has [`ROUND_NS`] of timed
/// runs. Returns the median batch's ns per run, the timed runs and the answer; every run must
/// answer as the first did.
fn repeat(
    (one_run_ns, scans): (&mut Option<f64>, bool),
    meter: &dyn MemoryMeter,
    mut once: impl FnMut() -> Result<Answer, String>,
) -> Result<(f64, usize, Answer), String> {
    let mut first = None;
    if one_run_ns.is_none() || (!scans && one_run_ns.is_some_and(|ns| ns < WARM_UP_BELOW_NS)) {
        let t = Instant::now();
        first = Some(once()?);
        one_run_ns.get_or_insert(t.elapsed().as_nanos() as f64);
    }
    let per_batch = one_run_ns
        .map_or(1.0, |ns| (BATCH_NS / ns.max(1.0)).ceil())
        .clamp(1.0, 65536.0) as usize;
    let (start, mut batches, mut runs) = (Instant::now(), Vec::new(), 0);
    while batches.is_empty() || (start.elapsed().as_nanos() as f64) < ROUND_NS {
        let watch = Stopwatch::start(meter);
        for _ in 0..per_batch {
            let got = std::hint::black_box(once()?);
            match &first {
                None => first = Some(got),
                Some(a) if !a.agrees(&got) => {
                    return Err(format!(
                        "run {} gave {got:?}, the first gave {a:?}",
                        runs + 1
                    ))
                }
                Some(_) => {}
            }
            runs += 1;
        }
        batches.push(watch.ns() / per_batch as f64);
    }
    batches.sort_by(f64::total_cmp);
    Ok((median(&batches), runs, first.expect("at least one run")))
}

impl<'a, M: MeshTopology> Contender for Entry<'a, M> {
    fn name(&self) -> &'static str {
        M::NAME
    }

    fn mesh(&self) -> &str {
        self.case.name
    }

    fn cells(&self) -> Vec<CellKey> {
        self.timed.iter().map(|t| t.key).collect()
    }

    fn release(&mut self) {
        self.m = None;
    }

    fn build(&mut self, round: usize, cold: bool, meter: &dyn MemoryMeter) -> Result<(), String> {
        self.m = None;
        if cold {
            meter.release_free_memory();
            let (ns, faults, m) = self.timed_build(meter)?;
            drop(m);
            self.builds.cold.push(ns);
            self.builds.cold_faults.extend(faults);
        }
        let (ns, faults, m) = self.timed_build(meter)?;
        self.builds.faces.get_or_insert(m.num_faces());
        self.builds.warm.push((round, ns));
        self.builds.warm_faults.extend(faults);
        self.m = Some(m);
        if let Some(input_checks) = M::input_checks().filter(|_| self.builds.time_checks) {
            let soup = self.case.soup;
            let watch = Stopwatch::start(meter);
            let checked = std::hint::black_box(input_checks(soup));
            let ns = watch.ns();
            checked.map_err(|e| format!("the input checks refused the soup: {e}"))?;
            self.builds
                .checks
                .push((round, ns / soup.num_faces().max(1) as f64));
        }
        Ok(())
    }

    fn run(
        &mut self,
        cell: CellKey,
        round: usize,
        meter: &dyn MemoryMeter,
    ) -> Result<Said, String> {
        let Entry {
            m,
            timed,
            all,
            passes,
            curves,
            buf,
            ..
        } = self;
        let m = m.as_mut().ok_or("run before a build")?;
        let t = timed
            .iter_mut()
            .find(|t| t.key == cell)
            .ok_or_else(|| format!("{} times no {cell:?}", M::NAME))?;
        let native = M::native();
        let (ns_per_item, said) = match cell {
            (Subject::Query(op), Kernel::Sampled) => {
                let round_passes = passes
                    .get(round - 1)
                    .ok_or_else(|| format!("no sampled queries drawn for round {round}"))?;
                let (ns, queries, sums) = sampled(m, op, round_passes, &mut t.one_run_ns, meter)?;
                t.runs += sums.len();
                if t.values.is_empty() {
                    t.items = queries;
                }
                (ns / queries.max(1) as f64, Said::Passes(sums))
            }
            (Subject::Query(op), Kernel::Sweep) => {
                let (ns, runs, answer) = repeat((&mut t.one_run_ns, t.scans), meter, || {
                    Ok(Answer::Sum(match native {
                        Some(k) => k
                            .sweep(m, op)
                            .map_err(|e| format!("native kernel failed: {e}"))?,
                        None => run(m, op, all, curves),
                    }))
                })?;
                t.runs += runs;
                (ns / t.items.max(1) as f64, Said::One(answer))
            }
            (Subject::Workload(w), Kernel::Workload) => {
                let (ns, runs, answer) = repeat((&mut t.one_run_ns, t.scans), meter, || {
                    Ok(Answer::Value(match native {
                        Some(k) => k
                            .workload(m, w)
                            .map_err(|e| format!("native kernel failed: {e}"))?,
                        None => run_workload(m, w, buf),
                    }))
                })?;
                t.runs += runs;
                (ns / t.items.max(1) as f64, Said::One(answer))
            }
            _ => return Err(format!("{cell:?} is not a cell of the rounds")),
        };
        if t.checksum.is_none() {
            t.checksum = Some(said.checksum());
        }
        t.values.push((round, ns_per_item));
        Ok(said)
    }

    fn rounds(&self, cell: CellKey) -> &[(usize, f64)] {
        if cell.0 == Subject::Construction {
            return &self.builds.warm;
        }
        self.timed
            .iter()
            .find(|t| t.key == cell)
            .map_or(&[], |t| &t.values)
    }

    fn checks(&self) -> &[(usize, f64)] {
        &self.builds.checks
    }

    fn finish(self: Box<Self>, est: &mut Estimator) -> Vec<Measurement> {
        let Entry {
            case,
            mut construction,
            builds,
            timed,
            untimed,
            ..
        } = *self;
        let n = case.soup.num_faces();
        let values = |v: &[(usize, f64)]| v.iter().map(|x| x.1).collect::<Vec<f64>>();
        let middle = |v: &[f64]| {
            let mut v = v.to_vec();
            v.sort_by(f64::total_cmp);
            (!v.is_empty()).then(|| median(&v))
        };
        fill(&mut construction, &values(&builds.warm), builds.warm.len());
        construction.cold_ns_per_item = middle(&builds.cold);
        construction.page_faults = middle(&builds.warm_faults).map(|f| f as u64);
        construction.cold_page_faults = middle(&builds.cold_faults).map(|f| f as u64);
        construction.items = n;
        let mut out = vec![construction];
        let mut cells: Vec<(usize, Measurement)> = untimed;
        for t in &timed {
            let (subject, kernel) = t.key;
            let mut cell = Measurement {
                native: t.native,
                ..Measurement::new(M::NAME, subject, kernel, case.name, case.family, n)
            };
            cell.items = t.items;
            cell.checksum = t.checksum.clone();
            fill(&mut cell, &values(&t.values), t.runs);
            if let Some(ns) = cell.ns_per_item {
                est.last.insert(
                    Estimator::key(M::NAME, case.family, subject, kernel),
                    (n, ns * t.items.max(1) as f64),
                );
            }
            cells.push((t.index, cell));
        }
        cells.sort_by_key(|c| c.0);
        out.extend(cells.into_iter().map(|c| c.1));
        out
    }
}

/// One round of a sampled cell: the round's passes of [`crate::measuring::rounds::PASS`] fresh queries
/// each, in order, until the round has [`ROUND_NS`] of them (at least one pass), timed as one
/// run by the [`Stopwatch`]; the clock is looked at every few passes ([`PASS_CHECK_NS`], from
/// the first round's first pass). A baseline's passes are handed to it in its own handles
/// before the clock starts. Returns the ns of all, the queries and each pass's checksum.
fn sampled<M: MeshTopology>(
    m: &M,
    op: Operator,
    passes: &[Queries],
    one_pass_ns: &mut Option<f64>,
    meter: &dyn MemoryMeter,
) -> Result<(f64, usize, Vec<u64>), String> {
    let passes: Vec<&Queries> = passes.iter().take_while(|p| p.count(op) > 0).collect();
    if passes.is_empty() {
        return Err(format!("no sampled queries of {}", op.name()));
    }
    let every = one_pass_ns.map_or(1, |ns| (PASS_CHECK_NS / ns.max(1.0)).ceil() as usize);
    let mut curves = BoundaryCurves::default();
    let mut sums = Vec::with_capacity(passes.len());
    let mut queries = 0;
    let ns = match M::native() {
        Some(k) => {
            let runs = passes
                .iter()
                .map(|p| {
                    let sample = p.sample(op).ok_or("an operator without sampled queries")?;
                    k.sampled(m, op, sample)
                        .map_err(|e| format!("native kernel failed: {e}"))
                })
                .collect::<Result<Vec<_>, String>>()?;
            let (start, watch) = (Instant::now(), Stopwatch::start(meter));
            for (j, (p, r)) in passes.iter().zip(&runs).enumerate() {
                sums.push(std::hint::black_box(
                    r().map_err(|e| format!("native kernel failed: {e}"))?,
                ));
                queries += p.count(op);
                if j == 0 && one_pass_ns.is_none() {
                    *one_pass_ns = Some(start.elapsed().as_nanos() as f64);
                }
                if (j + 1) % every == 0 && start.elapsed().as_nanos() as f64 >= ROUND_NS {
                    break;
                }
            }
            watch.ns()
        }
        None => {
            let (start, watch) = (Instant::now(), Stopwatch::start(meter));
            for (j, p) in passes.iter().enumerate() {
                sums.push(std::hint::black_box(run(m, op, p, &mut curves)));
                queries += p.count(op);
                if j == 0 && one_pass_ns.is_none() {
                    *one_pass_ns = Some(start.elapsed().as_nanos() as f64);
                }
                if (j + 1) % every == 0 && start.elapsed().as_nanos() as f64 >= ROUND_NS {
                    break;
                }
            }
            watch.ns()
        }
    };
    Ok((ns, queries, sums))
}

/// Fills `cell`'s times from its round values (ns per item): the median, the interval of the
/// median, the smallest and largest round, the rounds and the timed runs.
fn fill(cell: &mut Measurement, rounds: &[f64], runs: usize) {
    let Some(ci) = Interval::of_median(rounds) else {
        return;
    };
    cell.round_ns_per_item = rounds.to_vec();
    let mut v = rounds.to_vec();
    v.sort_by(f64::total_cmp);
    cell.ns_per_item = Some(median(&v));
    cell.min_ns_per_item = v.first().copied();
    cell.max_ns_per_item = v.last().copied();
    cell.ns_per_item_ci = Some([ci.low, ci.high]);
    cell.ci_coverage = Some(ci.coverage);
    cell.rounds = v.len();
    cell.reps = runs;
}

impl Said {
    /// The checksum results show: a sweep's sum, a workload's value, a sampled round's first
    /// pass.
    fn checksum(&self) -> String {
        match self {
            Said::One(Answer::Sum(s)) => s.to_string(),
            Said::One(Answer::Value(v)) => format!("{v:.9e}"),
            Said::One(a) => format!("{a:?}"),
            Said::Passes(p) => p.first().map_or_else(String::new, u64::to_string),
        }
    }
}

/// The visitor that sets a structure of a list up on a mesh ([`Entry::set_up`]).
pub struct SetUp<'a, 'b> {
    /// The mesh.
    pub case: &'a MeshCase<'a>,
    /// Each round's sampled queries.
    pub sets: &'b [QuerySet],
    /// The plan.
    pub plan: &'b Plan,
    /// The meter.
    pub meter: &'b dyn MemoryMeter,
    /// The run times so far.
    pub est: &'b Estimator,
    /// Whether to time the structure's own input checks alone after each build (a Target of
    /// construction shows how much of the build they are).
    pub checks: bool,
}

impl<'a> topolab_structures::registry::StructureVisitor for SetUp<'a, '_> {
    type Output = Result<Setup<'a>, String>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        Entry::<M>::set_up(
            self.case,
            self.sets,
            self.plan,
            self.meter,
            self.est,
            self.checks,
        )
    }
}
