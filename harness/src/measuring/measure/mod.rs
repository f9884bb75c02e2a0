//! What measuring a structure on a mesh is made of, whatever runs it: how it is built
//! ([`Builder`]), the mesh and the plan ([`MeshCase`], [`Plan`]), which cells are too long to
//! run ([`Estimator`]: skipped with their estimate), one kernel timed on a built structure
//! ([`time_kernel`], the estimates' probes and the benches), and the check of every checksum
//! across structures ([`cross_check`]). The size sweep itself runs in rounds
//! ([`crate::measuring::rounds`]; [`crate::measuring::rounds::measure_structure`] is one structure's rounds alone).
//!
//! The estimate of a cell extrapolates its run at the last smaller size of the mesh's family
//! by the declared cost ([`Estimator`]). The first size of a family has nothing to
//! extrapolate from, so there the estimate is the structure's time per query on this mesh
//! times the cell's number of queries: the time per query of a probe of [`PROBE_QUERIES`] of
//! its sampled queries. Without it, a single `--sizes 1000000` ran the scanning structures'
//! quadratic sweeps in full (hours).
//!
//! A baseline behind an FFI ([`MeshTopology::native`]) is timed by its own loops in every
//! cell: construction, sweeps, sampled kernels (its queries handed over in the library's own
//! handles before the clock starts) and workloads, with the generic kernels' checksums. A
//! native kernel that fails is an error of the measurement, never a fallback to the generic
//! kernel, which would time the FFI instead of the library.

use crate::measuring::cells::{Measurement, Status, Subject};
use crate::measuring::kernels::{run, Kernel, Queries};
pub use crate::measuring::timing::meter::MemoryMeter;
use crate::measuring::timing::{time, Budget, Timing};
use std::collections::HashMap;
use std::time::Duration;
use topolab_structures::{
    BoundaryCurves, BuildFacts, Constructed, MeshTopology, Operator, PolygonSoup,
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
    pub(crate) fn failure(&self, e: topolab_structures::Error) -> String {
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
    /// The seed of its sampled queries: round `r` draws with `seed + r`
    /// ([`crate::measuring::rounds::round_sets`]), the same for every structure.
    pub seed: u64,
}

/// How many rounds a run of rounds makes.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct RoundPlan {
    /// Rounds every cell gets.
    pub min_rounds: usize,
    /// Rounds no cell passes (the sampled queries are drawn for this many).
    pub max_rounds: usize,
    /// Extra rounds for the cells whose interval is wide may take this share of the time the
    /// first `min_rounds` took.
    pub extra: f64,
    /// The first rounds that time a cold build before the warm one
    /// ([`crate::measuring::rounds::COLD_ROUNDS`] where cold builds are shown, else 0).
    pub cold_rounds: usize,
    /// The seed of the rounds' orders.
    pub seed: u64,
}

/// How a mesh is measured.
#[derive(Copy, Clone, Debug)]
pub struct Plan {
    /// Skip a cell whose single run is estimated above this.
    pub cell_max: Duration,
    /// Only construction and the R00 sweep (for meshes shown in one table, such as real ones).
    pub light: bool,
    /// Whether the sampled cells are timed (a mesh whose tables show sweeps only skips them).
    pub sampled: bool,
    /// Only construction and the boundary operators, but every cell of a structure that stores
    /// grids only: what the tables read of an open grid.
    pub boundary_only: bool,
    /// The rounds.
    pub rounds: RoundPlan,
    /// Sampled queries drawn per kind and round.
    pub samples: usize,
}

impl Plan {
    /// A plan of exactly `rounds` rounds, none extra (the first with a cold build), and
    /// `samples` sampled queries per kind and round: for tests and probes, which check what is
    /// measured rather than how surely.
    pub fn fixed(cell_max: Duration, rounds: usize, samples: usize, light: bool) -> Plan {
        Plan {
            cell_max,
            light,
            sampled: true,
            boundary_only: false,
            rounds: RoundPlan {
                min_rounds: rounds,
                max_rounds: rounds,
                extra: 0.0,
                cold_rounds: 1,
                seed: 1,
            },
            samples,
        }
    }
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
    pub(crate) last: HashMap<EstimatorKey, (usize, f64)>,
}

/// (structure, family, operator, kernel).
type EstimatorKey = (&'static str, String, Subject, Kernel);

impl Estimator {
    pub(crate) fn key(
        s: &'static str,
        fam: &str,
        subject: Subject,
        kernel: Kernel,
    ) -> EstimatorKey {
        (s, fam.into(), subject, kernel)
    }

    /// Estimated ns of one run at `triangles`, scaling the last run by `exponent`.
    pub(crate) fn estimate(
        &self,
        key: &EstimatorKey,
        triangles: usize,
        exponent: f64,
    ) -> Option<f64> {
        self.last
            .get(key)
            .map(|&(n, ns)| ns * (triangles as f64 / n as f64).max(1.0).powf(exponent))
    }
}

/// Marks `cell` skipped, with its estimated ns per item, when one run is estimated (`ns`)
/// above the plan's `cell_max`; returns whether it did.
pub(crate) fn skips(cell: &mut Measurement, ns: Option<f64>, plan: &Plan) -> bool {
    match ns {
        Some(ns) if ns > plan.cell_max.as_nanos() as f64 => {
            cell.status = Status::Skipped;
            cell.estimate_ns_per_item = Some(ns / cell.items.max(1) as f64);
            true
        }
        _ => false,
    }
}

/// Time per query of `op` on `m`, in ns: from `known` (an earlier probe), else timed on the `probe` queries and remembered. `None` when the probe
/// has no query of that kind (a mesh without edges).
pub(crate) fn per_query_ns<M: MeshTopology>(
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
pub(crate) fn measurement<M: MeshTopology>(
    subject: Subject,
    kernel: Kernel,
    case: &MeshCase,
) -> Measurement {
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
                    crate::measuring::checksum::sums_agree(a, b)
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
mod tests;
