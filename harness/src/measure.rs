//! Measuring one structure on one mesh: construction (time and memory), every operator's sweep
//! and sampled kernels, the workloads. Cells whose estimated time exceeds the budget are
//! skipped with the estimate; checksums are compared across structures by [`cross_check`].
//!
//! The estimate of a cell extrapolates its run at the last smaller size of the mesh's family
//! by the declared cost ([`Estimator`]). The first size of a family has nothing to
//! extrapolate from, so there the estimate is the structure's time per query on this mesh
//! times the cell's number of queries: the time per query of the operator's sampled cell
//! (measured before its sweep for that reason), or of a probe of [`PROBE_QUERIES`] of its
//! sampled queries when the sampled cell has not run. Without it, a single
//! `--sizes 1000000` ran the scanning structures' quadratic sweeps in full (hours).
//!
//! A baseline behind an FFI ([`MeshTopology::native`]) is timed by its own loops in every
//! cell: construction, sweeps, sampled kernels (its queries handed over in the library's own
//! handles before the clock starts) and workloads, with the generic kernels' checksums. A
//! native kernel that fails is an error of the measurement, never a fallback to the generic
//! kernel, which would time the FFI instead of the library.

use crate::kernels::{run, run_workload, Kernel, Queries, QuerySet, Workload, WorkloadBuffers};
use crate::results::{Measurement, Status, Subject};
pub use crate::timing::meter::MemoryMeter;
use crate::timing::{median, time, Budget, Timing};
use std::collections::HashMap;
use std::time::{Duration, Instant};
use topolab_structures::{
    BoundaryCurves, BuildFacts, Constructed, Input, MeshTopology, Operator, PolygonSoup,
    SeparateConstruction,
};

/// How the harness builds `M` from a soup, decided before any clock: an outside project's
/// own construction ([`SeparateConstruction::construction`]: a C++ baseline's, a Rust
/// crate's) told the facts its [`SeparateConstruction::admit`] found, else
/// [`MeshTopology::from_soup`]. [`Builder::build`] is what a clock covers: the project's
/// construction alone for an outside structure; the caller finishes the structure
/// ([`Builder::finish`]) and drops it after the clock, as it does for every structure.
pub struct Builder<'a, M: MeshTopology> {
    soup: &'a PolygonSoup,
    separate: Option<(&'a dyn SeparateConstruction<M>, BuildFacts<'a>)>,
}

impl<'a, M: MeshTopology> Builder<'a, M> {
    /// Prepares the builds of `M` from `soup`: for an outside structure, its
    /// [`SeparateConstruction::admit`] (the lab's checks, whose refusal is the structure's, and
    /// the facts); nothing for the lab's structures, whose checks are part of their
    /// construction.
    pub fn new(soup: &'a PolygonSoup) -> topolab_structures::Result<Self> {
        let separate = match M::separate_construction() {
            Some(construction) => Some((construction, construction.admit(soup)?)),
            None => None,
        };
        Ok(Self { soup, separate })
    }

    /// Whether the builds are an outside project's own construction, without the lab's
    /// checks.
    pub fn is_native(&self) -> bool {
        self.separate.is_some()
    }

    /// One build, the part a clock covers.
    pub fn build(&self) -> topolab_structures::Result<Constructed<M>> {
        match &self.separate {
            Some((construction, facts)) => construction.construction(facts),
            None => M::from_soup(self.soup).map(Constructed::ready),
        }
    }

    /// Finishes a build after the clock ([`Constructed::finish`] with this builder's soup).
    pub fn finish(&self, built: Constructed<M>) -> topolab_structures::Result<M> {
        built.finish(self.soup)
    }

    /// The message for a build that failed after the first one succeeded.
    fn failure(&self, e: topolab_structures::Error) -> String {
        if self.is_native() {
            format!("native kernel failed: {e}")
        } else {
            format!("a later build failed: {e}")
        }
    }
}

/// A mesh to measure on.
#[derive(Clone, Debug)]
pub struct MeshCase<'a> {
    /// Its name.
    pub name: &'a str,
    /// Its family (for fits and skip estimates across sizes).
    pub family: &'a str,
    /// The mesh.
    pub soup: &'a PolygonSoup,
    /// The sampled queries (the same for every structure).
    pub queries: &'a QuerySet,
}

/// Budgets of a run.
#[derive(Copy, Clone, Debug)]
pub struct Plan {
    /// Time for repeating one cell.
    pub cell_budget: Duration,
    /// Skip a cell whose single run is estimated above this.
    pub cell_max: Duration,
    /// At least this many timed runs per cell.
    pub min_reps: usize,
    /// At most this many.
    pub max_reps: usize,
    /// Only construction and the R00 sweep (for meshes shown in one table, such as real ones).
    pub light: bool,
}

/// Sampled queries timed to estimate a cell with no smaller size before it: few enough that
/// even a query that scans the mesh keeps the probe short on the largest meshes.
pub const PROBE_QUERIES: usize = 8;

/// How a probe is timed: one warm-up, then at least five runs and as many more as fit in
/// 50 ms (nine at most), so that a probe of constant-time queries is not just the clock's
/// resolution and the median is not one run the scheduler stretched (a 10 ms time slice in a
/// probe of 8 queries would make an O(k) sweep look quadratic and skip it). Only a warm-up
/// longer than that, a probe of scanning queries on a large mesh, is run once more.
const PROBE_BUDGET: Budget = Budget {
    time: Duration::from_millis(50),
    min_reps: 5,
    max_reps: 9,
};

/// The last measured run time of every (structure, family, operator, kernel), to estimate the
/// next size's before running it.
#[derive(Clone, Debug, Default)]
pub struct Estimator {
    last: HashMap<EstimatorKey, (usize, f64)>,
}

/// (structure, family, operator, kernel).
type EstimatorKey = (&'static str, String, Subject, Kernel);

impl Estimator {
    fn key(s: &'static str, fam: &str, subject: Subject, kernel: Kernel) -> EstimatorKey {
        (s, fam.into(), subject, kernel)
    }

    /// Estimated ns of one run at `triangles`, scaling the last run by `exponent`.
    fn estimate(&self, key: &EstimatorKey, triangles: usize, exponent: f64) -> Option<f64> {
        self.last
            .get(key)
            .map(|&(n, ns)| ns * (triangles as f64 / n as f64).max(1.0).powf(exponent))
    }
}

/// Marks `cell` skipped, with its estimated ns per item, when one run is estimated (`ns`)
/// above the plan's `cell_max`; returns whether it did.
fn skips(cell: &mut Measurement, ns: Option<f64>, plan: &Plan) -> bool {
    match ns {
        Some(ns) if ns > plan.cell_max.as_nanos() as f64 => {
            cell.status = Status::Skipped;
            cell.estimate_ns_per_item = Some(ns / cell.items.max(1) as f64);
            true
        }
        _ => false,
    }
}

/// Time per query of `op` on `m`, in ns: from `known` (the operator's sampled cell, or an
/// earlier probe), else timed on the `probe` queries and remembered. `None` when the probe
/// has no query of that kind (a mesh without edges).
fn per_query_ns<M: MeshTopology>(
    m: &M,
    op: Operator,
    probe: &Queries,
    known: &mut HashMap<Operator, f64>,
    curves: &mut BoundaryCurves,
) -> Result<Option<f64>, String> {
    if let Some(&ns) = known.get(&op) {
        return Ok(Some(ns));
    }
    let count = probe.count(op);
    if count == 0 {
        return Ok(None);
    }
    let (t, _, _) = time_kernel(m, op, Kernel::Sampled, probe, curves, PROBE_BUDGET)?;
    let ns = t.median_ns / count as f64;
    known.insert(op, ns);
    Ok(Some(ns))
}

/// An empty cell of `M`, marked native for a baseline, whose every cell is timed (or, skipped,
/// would be) by its own loop; a timed cell is marked again by the loop that ran.
fn measurement<M: MeshTopology>(subject: Subject, kernel: Kernel, case: &MeshCase) -> Measurement {
    Measurement {
        native: M::native().is_some(),
        ..Measurement::new(
            M::NAME,
            subject,
            kernel,
            case.name,
            case.family,
            case.soup.num_faces(),
        )
    }
}

/// Measures `M` on `case`: appends one [`Measurement`] per cell to `out`. Fails when a kernel
/// is not deterministic or a baseline's native kernel fails.
pub fn measure_structure<M: MeshTopology>(
    case: &MeshCase,
    plan: &Plan,
    meter: &dyn MemoryMeter,
    est: &mut Estimator,
    out: &mut Vec<Measurement>,
) -> Result<(), String> {
    let budget = Budget {
        time: plan.cell_budget,
        min_reps: plan.min_reps,
        max_reps: plan.max_reps,
    };
    let n = case.soup.num_faces();
    // Construction: memory first (one build, counted by the allocator and kept for the
    // queries), then the timed builds with nothing counted. The build is the one the clock
    // times, a baseline's own construction included (not `from_soup`, whose checks and edge
    // analysis are the lab's), and its finishing step, whose tables the structure keeps.
    let mut cons = measurement::<M>(Subject::Construction, Kernel::Construction, case);
    let refused = |mut cons: Measurement, e: topolab_structures::Error, out: &mut Vec<_>| {
        cons.status = Status::Refused;
        cons.note = Some(format!("{}: {e}", e.kind()));
        out.push(cons);
        Ok(())
    };
    let builder = match Builder::<M>::new(case.soup) {
        Ok(builder) => builder,
        Err(e) => return refused(cons, e, out),
    };
    meter.counting(true);
    meter.reset_peak();
    let before = meter.current();
    let built = builder.build().and_then(|b| builder.finish(b));
    let peak = meter.peak().saturating_sub(before);
    let held = meter.current().saturating_sub(before);
    meter.counting(false);
    let mut m = match built {
        Ok(m) => m,
        Err(e) => return refused(cons, e, out),
    };
    cons.bytes = Some(held as u64);
    cons.peak_bytes = Some(peak as u64);
    cons.declared_bytes = Some(m.heap_bytes() as u64);
    // Construction is timed with at least three runs and a second's budget whatever the cell
    // budget: one build of a 1M-triangle mesh is a single noisy sample otherwise.
    let construction_budget = Budget {
        time: budget.time.max(Duration::from_secs(1)),
        min_reps: 3,
        max_reps: plan.max_reps.min(7),
    };
    let builds = time_construction(&builder, construction_budget, meter)
        .map_err(|e| format!("{} construction on {}: {e}", M::NAME, case.name))?;
    let faces = n.max(1);
    cons.native = builds.native;
    fill(&mut cons, builds.warm, faces, None);
    cons.page_faults = builds.warm_faults;
    cons.cold_ns_per_item = Some(builds.cold.median_ns / faces as f64);
    cons.cold_page_faults = builds.cold_faults;
    out.push(cons);

    // A light plan times the vertex 1-ring sweep only: its queries are the vertices, without
    // the edges and (edge, face) pairs whose hash map of edges, built twice per structure,
    // took longer than the sweep itself on the 3.3M refined armadillo.
    let (all, sampled) = if plan.light {
        (
            Queries::every_vertex(&m),
            Queries::sampled_vertices(case.queries),
        )
    } else {
        (
            Queries::all(&m, case.soup),
            Queries::sampled(&m, case.queries),
        )
    };
    let probe = sampled.spread(PROBE_QUERIES);
    // Time per query of each operator on this mesh, for cells with no smaller size before.
    let mut per_query: HashMap<Operator, f64> = HashMap::new();
    let mut curves = BoundaryCurves::default();
    for op in Operator::ALL {
        // Boundary curves are one question about the whole mesh: nothing to sample. Sampled
        // first otherwise: its time per query is the estimate of the sweep after it.
        let kernels: &[Kernel] = if op.input() == Input::Mesh {
            &[Kernel::Sweep]
        } else {
            &[Kernel::Sampled, Kernel::Sweep]
        };
        for &kernel in kernels {
            if plan.light && (op != Operator::R00 || kernel != Kernel::Sweep) {
                continue;
            }
            let q = if kernel == Kernel::Sweep {
                &all
            } else {
                &sampled
            };
            let items = q.count(op);
            let mut cell = measurement::<M>(Subject::Query(op), kernel, case);
            cell.items = items;
            // A sweep's run grows with n^(1+e), a sampled run (fixed count) with n^e.
            let e =
                M::cost(op).expected_exponent() + if kernel == Kernel::Sweep { 1.0 } else { 0.0 };
            let key = Estimator::key(M::NAME, case.family, Subject::Query(op), kernel);
            let context =
                |e: String| format!("{} {} {kernel} on {}: {e}", M::NAME, op.name(), case.name);
            let estimate = match est.estimate(&key, n, e) {
                Some(ns) => Some(ns),
                // Boundary curves have no sampled kernel. Finding them decides for every edge
                // whether it is on the boundary, so their estimate is a boundary-edge sweep's
                // (the scanning structures' O(n) test per edge is their O(n²)).
                None if op.input() == Input::Mesh => {
                    let edge = Operator::BoundaryEdge;
                    per_query_ns(&m, edge, &probe, &mut per_query, &mut curves)
                        .map_err(context)?
                        .map(|ns| ns * all.count(edge) as f64)
                }
                None => per_query_ns(&m, op, &probe, &mut per_query, &mut curves)
                    .map_err(context)?
                    .map(|ns| ns * items as f64),
            };
            if skips(&mut cell, estimate, plan) {
                out.push(cell);
                continue;
            }
            let (t, sum, native) =
                time_kernel(&m, op, kernel, q, &mut curves, budget).map_err(context)?;
            if kernel == Kernel::Sampled && items > 0 {
                per_query.insert(op, t.median_ns / items as f64);
            }
            cell.native = native;
            fill(&mut cell, t, items.max(1), Some(sum.to_string()));
            est.last.insert(key, (n, t.median_ns));
            out.push(cell);
        }
    }
    let native = M::native();
    let mut buf = WorkloadBuffers::default();
    for w in Workload::ALL.into_iter().filter(|_| !plan.light) {
        let mut cell = measurement::<M>(Subject::Workload(w), Kernel::Workload, case);
        let items = w.items(m.num_vertices(), m.num_faces());
        cell.items = items;
        // A workload asks its relations once per element: its run grows like n^(1+e) for the
        // costliest relation it uses.
        let e = 1.0
            + w.relations()
                .iter()
                .map(|&op| M::cost(op).expected_exponent())
                .fold(0.0, f64::max);
        let key = Estimator::key(M::NAME, case.family, Subject::Workload(w), Kernel::Workload);
        let estimate = match est.estimate(&key, n, e) {
            Some(ns) => Some(ns),
            // With no smaller size: the relations it asks, once per element, at this mesh's
            // time per query (the sampled cells measured above).
            None => {
                let mut ns = 0.0;
                for &op in w.relations() {
                    let per = per_query_ns(&m, op, &probe, &mut per_query, &mut curves)
                        .map_err(|e| format!("{} {} on {}: {e}", M::NAME, w.name(), case.name))?;
                    ns += per.unwrap_or(0.0) * all.count(op) as f64;
                }
                Some(ns)
            }
        };
        if skips(&mut cell, estimate, plan) {
            out.push(cell);
            continue;
        }
        cell.native = native.is_some();
        let (t, r) = match native {
            Some(k) => time_native(budget, || k.workload(&mut m, w).map(f64::to_bits)),
            None => time(budget, || run_workload(&m, w, &mut buf).to_bits()),
        }
        .map_err(|e| format!("{} {} on {}: {e}", M::NAME, w.name(), case.name))?;
        fill(
            &mut cell,
            t,
            items.max(1),
            Some(format!("{:.9e}", f64::from_bits(r))),
        );
        est.last.insert(key, (n, t.median_ns));
        out.push(cell);
    }
    Ok(())
}

/// Construction timed two ways. *Warm*: after one build to warm up, the median of builds that
/// reuse the memory the build before them freed (with glibc told to keep freed memory, as the
/// report does, they take no page fault whatever ran before). *Cold*: each build right after
/// the allocator returned its free memory to the kernel, so it faults in every page it
/// touches. The page faults of each are counted around the builds, and each build is timed in
/// the thread's CPU time when the meter knows it ([`MemoryMeter::thread_cpu_ns`]; page faults
/// are system time, so they count). Only [`Builder::build`] is timed: each structure is
/// finished and dropped after the clock (a destructor that frees a million records is not
/// construction).
struct Builds {
    /// The warm builds.
    warm: Timing,
    /// Median minor page faults of a warm build.
    warm_faults: Option<u64>,
    /// The cold builds.
    cold: Timing,
    /// Median minor page faults of a cold build.
    cold_faults: Option<u64>,
    /// Whether the baseline's own construction was timed
    /// ([`topolab_structures::SeparateConstruction`]).
    native: bool,
}

/// At most this many cold builds: each one faults in the whole structure, and their spread is
/// the kernel's, not the structure's.
const COLD_BUILDS: usize = 3;

/// Times the builds of `builder` (see [`Builds`]): the baseline's own construction when it has
/// one, [`MeshTopology::from_soup`] otherwise. Fails when a build fails or builds a different
/// number of faces than the first.
fn time_construction<M: MeshTopology>(
    builder: &Builder<M>,
    budget: Budget,
    meter: &dyn MemoryMeter,
) -> Result<Builds, String> {
    // After the clock: the structure finished, its faces counted (the check that each build
    // is whole), and the structure dropped.
    let faces = |built: topolab_structures::Result<Constructed<M>>| {
        built
            .and_then(|b| builder.finish(b))
            .map(|m| m.num_faces())
            .map_err(|e| builder.failure(e))
    };
    let warm_up = Instant::now();
    let built = builder.build();
    let long = warm_up.elapsed() > budget.time;
    let first = faces(built)?;
    // A build longer than the budget is timed once (its work dominates its noise).
    let min_reps = if long { 1 } else { budget.min_reps };
    let runs = |cold: bool, max_reps: usize| -> Result<(Timing, Option<u64>), String> {
        let (mut ns, mut faults) = (Vec::new(), Vec::new());
        let start = Instant::now();
        while ns.len() < min_reps.min(max_reps)
            || (ns.len() < max_reps && start.elapsed() < budget.time)
        {
            if cold {
                meter.release_free_memory();
            }
            let before = meter.minor_faults();
            let (cpu, t) = (meter.thread_cpu_ns(), Instant::now());
            let built = std::hint::black_box(builder.build());
            let wall = t.elapsed().as_nanos() as u64;
            ns.push(match (cpu, meter.thread_cpu_ns()) {
                (Some(a), Some(b)) => b.saturating_sub(a),
                _ => wall,
            } as f64);
            if let (Some(a), Some(b)) = (before, meter.minor_faults()) {
                faults.push(b.saturating_sub(a) as f64);
            }
            let built = faces(built)?;
            if built != first {
                return Err(format!(
                    "build {} has {built} faces, the first had {first}",
                    ns.len()
                ));
            }
        }
        faults.sort_by(f64::total_cmp);
        let faults = (faults.len() == ns.len()).then(|| median(&faults) as u64);
        Ok((Timing::of(ns), faults))
    };
    let (warm, warm_faults) = runs(false, budget.max_reps)?;
    let (cold, cold_faults) = runs(true, COLD_BUILDS.min(budget.max_reps))?;
    Ok(Builds {
        warm,
        warm_faults,
        cold,
        cold_faults,
        native: builder.is_native(),
    })
}

/// Times one kernel of `op` on a built structure: the structure's native loop when it is a
/// baseline behind an FFI (its sampled queries prepared in the library's handles before the
/// clock), the harness's generic kernel otherwise. Returns the timing, the checksum and
/// whether the native loop ran. `kernel` is [`Kernel::Sweep`] or [`Kernel::Sampled`].
pub fn time_kernel<M: MeshTopology>(
    m: &M,
    op: Operator,
    kernel: Kernel,
    q: &Queries,
    curves: &mut BoundaryCurves,
    budget: Budget,
) -> Result<(Timing, u64, bool), String> {
    let Some(k) = M::native() else {
        return match kernel {
            Kernel::Sweep | Kernel::Sampled => time(budget, || run(m, op, q, curves)),
            Kernel::Workload | Kernel::Construction => Err(not_an_operator_kernel(kernel)),
        }
        .map(|(t, sum)| (t, sum, false));
    };
    match kernel {
        Kernel::Sweep => time_native(budget, || k.sweep(m, op)),
        Kernel::Sampled => {
            let sample = q
                .sample(op)
                .ok_or_else(|| format!("{} has no sampled kernel", op.name()))?;
            let sampled = k
                .sampled(m, op, sample)
                .map_err(|e| format!("native kernel failed: {e}"))?;
            time_native(budget, sampled)
        }
        Kernel::Workload | Kernel::Construction => Err(not_an_operator_kernel(kernel)),
    }
    .map(|(t, sum)| (t, sum, true))
}

fn not_an_operator_kernel(kernel: Kernel) -> String {
    format!("{kernel} is not a kernel of an operator")
}

/// Times a baseline's native kernel `native` (see [`topolab_structures::NativeKernels`]). A
/// failure inside the loop, in any run, fails the measurement with the library's error
/// instead of timing a zero.
fn time_native<T: PartialEq + std::fmt::Debug>(
    budget: Budget,
    mut native: impl FnMut() -> topolab_structures::Result<T>,
) -> Result<(Timing, T), String> {
    let mut failure = None;
    // A failed run answers `None`: `time` stops at the first answer that differs from the
    // warm-up's, and the first failure is the one reported.
    let timed = time(budget, || match native() {
        Ok(answer) => Some(answer),
        Err(e) => {
            failure.get_or_insert(e.to_string());
            None
        }
    });
    let (t, answer) = match failure {
        Some(e) => return Err(format!("native kernel failed: {e}")),
        None => timed?,
    };
    // With no failure, every run answered.
    answer
        .map(|answer| (t, answer))
        .ok_or_else(|| "native kernel failed without an error".into())
}

/// Builds `M` from `case` and times one sweep of `op` over every element (for comparisons
/// of one operator across meshes, such as element orderings). A refusal is a refused cell.
pub fn measure_sweep<M: MeshTopology>(
    case: &MeshCase,
    op: Operator,
    plan: &Plan,
) -> Result<Measurement, String> {
    let mut cell = measurement::<M>(Subject::Query(op), Kernel::Sweep, case);
    let m = match M::from_soup(case.soup) {
        Ok(m) => m,
        Err(e) => {
            cell.status = Status::Refused;
            cell.note = Some(format!("{}: {e}", e.kind()));
            return Ok(cell);
        }
    };
    // A vertex operator's sweep needs the vertices only (see `Queries::every_vertex`).
    let q = if op.input() == Input::Vertex {
        Queries::every_vertex(&m)
    } else {
        Queries::all(&m, case.soup)
    };
    cell.items = q.count(op);
    let budget = Budget {
        time: plan.cell_budget,
        min_reps: plan.min_reps,
        max_reps: plan.max_reps,
    };
    let (t, sum, native) = time_kernel(
        &m,
        op,
        Kernel::Sweep,
        &q,
        &mut BoundaryCurves::default(),
        budget,
    )
    .map_err(|e| format!("{} {} on {}: {e}", M::NAME, op.name(), case.name))?;
    cell.native = native;
    let items = cell.items.max(1);
    fill(&mut cell, t, items, Some(sum.to_string()));
    Ok(cell)
}

fn fill(cell: &mut Measurement, t: crate::timing::Timing, items: usize, checksum: Option<String>) {
    let per = |ns: f64| ns / items as f64;
    cell.ns_per_item = Some(per(t.median_ns));
    cell.min_ns_per_item = Some(per(t.min_ns));
    cell.max_ns_per_item = Some(per(t.max_ns));
    cell.reps = t.reps;
    cell.checksum = checksum;
}

/// Compares every measured checksum of `mesh` across structures; an error names the operator,
/// kernel, mesh and the structures that disagree. Workload results (floats) agree within a
/// relative 1e-6.
pub fn cross_check(measurements: &[Measurement], mesh: &str) -> Result<(), String> {
    let mut first: HashMap<(Subject, Kernel), (&str, &str)> = HashMap::new();
    for m in measurements
        .iter()
        .filter(|m| m.mesh == mesh && m.status == Status::Measured)
    {
        let Some(sum) = m.checksum.as_deref() else {
            continue;
        };
        match first.get(&(m.operator, m.kernel)) {
            None => {
                first.insert((m.operator, m.kernel), (&m.structure, sum));
            }
            Some(&(s0, sum0)) => {
                let same = if m.kernel == Kernel::Workload {
                    let (a, b) = (
                        sum0.parse::<f64>().unwrap_or(f64::NAN),
                        sum.parse::<f64>().unwrap_or(f64::NAN),
                    );
                    crate::checksum::sums_agree(a, b)
                } else {
                    sum0 == sum
                };
                if !same {
                    return Err(format!(
                        "checksum mismatch on mesh {mesh}, operator {} ({}): {s0} gives {sum0}, {} gives {sum}",
                        m.operator, m.kernel, m.structure
                    ));
                }
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernels::sample_queries;
    use std::cell::Cell;
    use topolab_structures::{meshes, Error, ExplicitStorage, MeshTopology, Result, VertexList};

    struct NoMeter(Cell<usize>);
    impl MemoryMeter for NoMeter {
        fn current(&self) -> usize {
            self.0.get()
        }
        fn peak(&self) -> usize {
            self.0.get()
        }
        fn reset_peak(&self) {}
    }

    /// Few, short repetitions; cells estimated above `cell_max` skipped.
    fn short_plan(cell_max: Duration) -> Plan {
        Plan {
            cell_budget: Duration::from_millis(1),
            cell_max,
            min_reps: 1,
            max_reps: 3,
            light: false,
        }
    }

    #[test]
    fn with_no_smaller_size_the_scans_are_skipped_by_their_time_per_query() {
        // One size only, as `topolab report --sizes 20000`: nothing to extrapolate from. The
        // vertex list scans the mesh for every query, so its sweeps of those operators, its
        // boundary curves and the workloads built on them are quadratic: ~10k queries of
        // ~60k corners each, seconds each; the budget is 20 ms.
        let soup = meshes::torus_with_triangles(20_000);
        let q = sample_queries(&soup, 16, 3);
        let case = MeshCase {
            name: "torus-20k",
            family: "torus",
            soup: &soup,
            queries: &q,
        };
        // The estimates come from medians of at least five runs (the probes' and the sampled
        // cells', unless a warm-up alone outlasts the 50 ms budget), so that a run or two
        // stretched by the scheduler cannot decide. The budget
        // sits between what runs and what scans, in this unoptimized test build: 16 scanning
        // queries take ~0.6 ms, the cheapest quadratic sweep (R00) ~0.4 s.
        let plan = Plan {
            cell_budget: Duration::from_millis(50),
            min_reps: 5,
            max_reps: 9,
            ..short_plan(Duration::from_millis(20))
        };
        let (mut out, mut est) = (Vec::new(), Estimator::default());
        measure_structure::<VertexList>(&case, &plan, &NoMeter(Cell::new(0)), &mut est, &mut out)
            .unwrap();
        let cell = |subject: Subject, kernel: Kernel| {
            out.iter()
                .find(|m| m.operator == subject && m.kernel == kernel)
                .unwrap_or_else(|| panic!("no {subject:?} {kernel:?} cell"))
        };
        let scans: Vec<Operator> = Operator::ALL
            .into_iter()
            .filter(|&op| VertexList::cost(op).expected_exponent() >= 1.0)
            .collect();
        assert!(scans.contains(&Operator::R00) && scans.contains(&Operator::BoundaryCurves));
        for &op in &scans {
            let m = cell(Subject::Query(op), Kernel::Sweep);
            assert_eq!(m.status, Status::Skipped, "{op:?} sweep: {m:?}");
            assert!(m.estimate_ns_per_item.is_some_and(|ns| ns > 0.0), "{m:?}");
            assert!(m.checksum.is_none() && m.ns_per_item.is_none(), "{m:?}");
        }
        for w in [Workload::Circulators, Workload::Smoothing] {
            assert_eq!(
                cell(Subject::Workload(w), Kernel::Workload).status,
                Status::Skipped
            );
        }
        // What does not scan still runs: 16 sampled queries, an O(k) sweep, no relation at all.
        for (subject, kernel) in [
            (Subject::Query(Operator::R00), Kernel::Sampled),
            (Subject::Query(Operator::R20), Kernel::Sweep),
            (Subject::Workload(Workload::Barycenter), Kernel::Workload),
        ] {
            let m = cell(subject, kernel);
            assert_eq!(m.status, Status::Measured, "{subject:?} {kernel:?}: {m:?}");
            assert!(m.checksum.is_some());
        }
    }

    #[test]
    fn measures_every_cell_and_cross_checks() {
        let soup = meshes::torus(6, 5);
        let q = sample_queries(&soup, 8, 3);
        let case = MeshCase {
            name: "t",
            family: "torus",
            soup: &soup,
            queries: &q,
        };
        let plan = short_plan(Duration::from_secs(1));
        let (mut out, mut est) = (Vec::new(), Estimator::default());
        measure_structure::<VertexList>(&case, &plan, &NoMeter(Cell::new(0)), &mut est, &mut out)
            .unwrap();
        measure_structure::<ExplicitStorage>(
            &case,
            &plan,
            &NoMeter(Cell::new(0)),
            &mut est,
            &mut out,
        )
        .unwrap();
        // 1 construction + 13 × 2 + 1 operator cells + 4 workloads, per structure.
        assert_eq!(out.len(), 2 * (1 + 27 + 4));
        cross_check(&out, "t").unwrap();
        // A tampered checksum is caught and named.
        let i = out
            .iter()
            .position(|m| m.structure == "explicit" && m.operator == Subject::Query(Operator::R22))
            .unwrap();
        out[i].checksum = Some("1".into());
        let err = cross_check(&out, "t").unwrap_err();
        assert!(
            err.contains("r22") && err.contains("explicit") && err.contains("mesh t"),
            "{err}"
        );
    }

    fn foreign() -> Error {
        Error::Foreign {
            library: "Baseline",
            call: "sweep",
            reason: "a test failure",
        }
    }

    /// Times `answers` as a native kernel: one per run, then 5 for every later run.
    fn time_answers(answers: Vec<Result<u64>>) -> Result<u64, String> {
        let budget = Budget {
            time: Duration::from_millis(1),
            min_reps: 2,
            max_reps: 3,
        };
        let mut answers = answers.into_iter();
        time_native(budget, || answers.next().unwrap_or(Ok(5))).map(|(_, sum)| sum)
    }

    #[test]
    fn native_kernels_are_timed_when_they_answer_and_fail_loudly() {
        assert_eq!(time_answers(Vec::new()), Ok(5));
        // A failure in the warm-up, or in a timed run, is the library's error, not a 0.
        for answers in [vec![Err(foreign())], vec![Ok(5), Ok(5), Err(foreign())]] {
            let err = time_answers(answers).unwrap_err();
            assert!(
                err.contains("native kernel failed") && err.contains("a test failure"),
                "{err}"
            );
        }
        // A kernel whose answer changes between runs fails like a generic one.
        let err = time_answers(vec![Ok(5), Ok(6)]).unwrap_err();
        assert!(err.contains("gave Some(6)"), "{err}");
    }

    #[test]
    fn a_cell_estimated_over_budget_is_skipped_with_its_estimate() {
        let mut est = Estimator::default();
        let key = Estimator::key("s", "torus", Subject::Query(Operator::R00), Kernel::Sweep);
        est.last.insert(key.clone(), (1000, 1e6));
        // 16x the size at exponent 2: 256 ms.
        assert_eq!(est.estimate(&key, 16000, 2.0), Some(256e6));
    }
}
