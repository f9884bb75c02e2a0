//! Measuring one structure on one mesh: construction (time and memory), every operator's sweep
//! and sampled kernels, the workloads. Cells whose estimated time exceeds the budget are
//! skipped with the estimate; checksums are compared across structures by [`cross_check`].

use crate::kernels::{run, run_workload, Kernel, Queries, QuerySet, Workload, WorkloadBuffers};
use crate::results::{Measurement, Status};
use crate::timing::{time, Budget};
use std::collections::HashMap;
use std::time::Duration;
use topolab_structures::{BoundaryCurves, MeshTopology, Operator, PolygonSoup};

/// Reads the process's heap use (the report binary's counting allocator).
pub trait MemoryMeter {
    /// Bytes allocated now.
    fn current(&self) -> usize;
    /// Highest `current()` since the last reset.
    fn peak(&self) -> usize;
    /// Starts a new peak at `current()`.
    fn reset_peak(&self);
}

/// The counting allocator the report binary (and the hull benchmark example) installs.
impl MemoryMeter for peak_alloc::PeakAlloc {
    fn current(&self) -> usize {
        self.current_usage()
    }
    fn peak(&self) -> usize {
        self.peak_usage()
    }
    fn reset_peak(&self) {
        self.reset_peak_usage()
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

/// The last measured run time of every (structure, family, operator, kernel), to estimate the
/// next size's before running it.
#[derive(Clone, Debug, Default)]
pub struct Estimator {
    last: HashMap<EstimatorKey, (usize, f64)>,
}

/// (structure, family, operator, kernel).
type EstimatorKey = (String, String, String, String);

impl Estimator {
    fn key(s: &str, fam: &str, op: &str, k: &str) -> EstimatorKey {
        (s.into(), fam.into(), op.into(), k.into())
    }

    /// Marks `cell` skipped, with its estimated ns per item, when one run at `triangles` is
    /// estimated above the plan's `cell_max`; returns whether it did.
    fn skips(
        &self,
        key: &EstimatorKey,
        triangles: usize,
        exponent: f64,
        plan: &Plan,
        cell: &mut Measurement,
    ) -> bool {
        match self.estimate(key, triangles, exponent) {
            Some(ns) if ns > plan.cell_max.as_nanos() as f64 => {
                cell.status = Status::Skipped;
                cell.estimate_ns_per_item = Some(ns / cell.items.max(1) as f64);
                true
            }
            _ => false,
        }
    }

    /// Estimated ns of one run at `triangles`, scaling the last run by `exponent`.
    fn estimate(&self, key: &EstimatorKey, triangles: usize, exponent: f64) -> Option<f64> {
        self.last
            .get(key)
            .map(|&(n, ns)| ns * (triangles as f64 / n as f64).max(1.0).powf(exponent))
    }
}

fn measurement(structure: &str, op: &str, kernel: &str, case: &MeshCase) -> Measurement {
    Measurement {
        structure: structure.into(),
        operator: op.into(),
        kernel: kernel.into(),
        mesh: case.name.into(),
        family: case.family.into(),
        triangles: case.soup.num_faces(),
        status: Status::Measured,
        ns_per_item: None,
        min_ns_per_item: None,
        max_ns_per_item: None,
        items: 0,
        reps: 0,
        checksum: None,
        bytes: None,
        peak_bytes: None,
        declared_bytes: None,
        estimate_ns_per_item: None,
        native: false,
        note: None,
    }
}

/// Measures `M` on `case`: appends one [`Measurement`] per cell to `out`. Fails only when a
/// kernel is not deterministic.
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
    // Construction: memory first (one build, measured by the allocator), then the timing.
    let mut cons = measurement(M::NAME, "construction", "construction", case);
    meter.reset_peak();
    let before = meter.current();
    let built = M::from_soup(case.soup);
    let peak = meter.peak().saturating_sub(before);
    let mut m = match built {
        Ok(m) => m,
        Err(e) => {
            cons.status = Status::Refused;
            cons.note = Some(format!("{}: {e}", e.kind()));
            out.push(cons);
            return Ok(());
        }
    };
    let held = meter.current().saturating_sub(before);
    cons.bytes = Some(held as u64);
    cons.peak_bytes = Some(peak as u64);
    cons.declared_bytes = Some(m.heap_bytes() as u64);
    // Construction is timed with at least three runs and a second's budget whatever the cell
    // budget: one build of a 1M-triangle mesh is a single noisy sample otherwise.
    let (t, _) = time(
        Budget {
            time: budget.time.max(Duration::from_secs(1)),
            min_reps: 3,
            max_reps: plan.max_reps.min(7),
        },
        || {
            M::native_construction(case.soup)
                .unwrap_or_else(|| M::from_soup(case.soup))
                .map(|m| m.num_faces())
                .unwrap_or(0)
        },
    )?;
    cons.native = M::native_construction(case.soup).is_some();
    fill(&mut cons, t, n.max(1), None);
    out.push(cons);

    let all = Queries::all(&m, case.soup);
    let sampled = Queries::sampled(&m, case.queries);
    let mut curves = BoundaryCurves::default();
    for op in Operator::ALL {
        let kernels: &[Kernel] = if op == Operator::BoundaryCurves {
            &[Kernel::Sweep]
        } else {
            &[Kernel::Sweep, Kernel::Sampled]
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
            let mut cell = measurement(M::NAME, op.name(), kernel.name(), case);
            cell.items = items;
            // A sweep's run grows with n^(1+e), a sampled run (fixed count) with n^e.
            let e =
                M::cost(op).expected_exponent() + if kernel == Kernel::Sweep { 1.0 } else { 0.0 };
            let key = Estimator::key(M::NAME, case.family, op.name(), kernel.name());
            if est.skips(&key, n, e, plan, &mut cell) {
                out.push(cell);
                continue;
            }
            let (t, sum, native) =
                time_kernel(&m, op, kernel, q, &mut curves, budget).map_err(|e| {
                    format!(
                        "{} {} {} on {}: {e}",
                        M::NAME,
                        op.name(),
                        kernel.name(),
                        case.name
                    )
                })?;
            cell.native = native;
            fill(&mut cell, t, items.max(1), Some(sum.to_string()));
            est.last.insert(key, (n, t.median_ns));
            out.push(cell);
        }
    }
    let mut buf = WorkloadBuffers::default();
    for w in Workload::ALL.into_iter().filter(|_| !plan.light) {
        let mut cell = measurement(M::NAME, w.name(), "workload", case);
        let items = w.items(&m);
        cell.items = items;
        // A workload asks its relations once per element: its run grows like n^(1+e) for the
        // costliest relation it uses.
        let e = 1.0
            + w.relations()
                .iter()
                .map(|&op| M::cost(op).expected_exponent())
                .fold(0.0, f64::max);
        let key = Estimator::key(M::NAME, case.family, w.name(), "workload");
        if est.skips(&key, n, e, plan, &mut cell) {
            out.push(cell);
            continue;
        }
        let native = m.native_workload(w.name()).is_some();
        let (t, r) = if native {
            time(budget, || {
                m.native_workload(w.name()).unwrap_or_default().to_bits()
            })
        } else {
            time(budget, || run_workload(&m, w, &mut buf).to_bits())
        }
        .map_err(|e| format!("{} {} on {}: {e}", M::NAME, w.name(), case.name))?;
        cell.native = native;
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

/// Times one kernel of `op` on a built structure: the structure's native loop when it has one
/// (a baseline behind FFI), the harness's generic kernel otherwise. Returns the timing, the
/// checksum and whether it ran natively.
pub fn time_kernel<M: MeshTopology>(
    m: &M,
    op: Operator,
    kernel: Kernel,
    q: &Queries,
    curves: &mut BoundaryCurves,
    budget: Budget,
) -> Result<(crate::timing::Timing, u64, bool), String> {
    let ids: Vec<u32> = match op {
        Operator::R00 | Operator::R01 | Operator::R02 | Operator::BoundaryVertex => {
            q.vertices.iter().map(|v| v.0).collect()
        }
        Operator::R20 | Operator::R21 | Operator::R22 => q.faces.iter().map(|f| f.0).collect(),
        _ => Vec::new(),
    };
    let native = match kernel {
        Kernel::Sweep => m.native_sweep(op).is_some(),
        Kernel::Sampled => !ids.is_empty() && m.native_sampled(op, &ids).is_some(),
    };
    let (t, sum) = if native {
        time(budget, || match kernel {
            Kernel::Sweep => m.native_sweep(op).unwrap_or_default(),
            Kernel::Sampled => m.native_sampled(op, &ids).unwrap_or_default(),
        })
    } else {
        time(budget, || run(m, op, q, curves))
    }?;
    Ok((t, sum, native))
}

/// Builds `M` from `case` and times one sweep of `op` over every element (for comparisons
/// of one operator across meshes, such as element orderings). A refusal is a refused cell.
pub fn measure_sweep<M: MeshTopology>(
    case: &MeshCase,
    op: Operator,
    plan: &Plan,
) -> Result<Measurement, String> {
    let mut cell = measurement(M::NAME, op.name(), Kernel::Sweep.name(), case);
    let m = match M::from_soup(case.soup) {
        Ok(m) => m,
        Err(e) => {
            cell.status = Status::Refused;
            cell.note = Some(format!("{}: {e}", e.kind()));
            return Ok(cell);
        }
    };
    let q = Queries::all(&m, case.soup);
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
    let mut first: HashMap<(&str, &str), (&str, &str)> = HashMap::new();
    for m in measurements
        .iter()
        .filter(|m| m.mesh == mesh && m.status == Status::Measured)
    {
        let Some(sum) = m.checksum.as_deref() else {
            continue;
        };
        match first.get(&(m.operator.as_str(), m.kernel.as_str())) {
            None => {
                first.insert((&m.operator, &m.kernel), (&m.structure, sum));
            }
            Some(&(s0, sum0)) => {
                let same = if m.kernel == "workload" {
                    let (a, b) = (
                        sum0.parse::<f64>().unwrap_or(f64::NAN),
                        sum.parse::<f64>().unwrap_or(f64::NAN),
                    );
                    (a - b).abs() <= 1e-6 * a.abs().max(b.abs()).max(1.0)
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
    use topolab_structures::{meshes, ExplicitStorage, VertexList};

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
        let plan = Plan {
            cell_budget: Duration::from_millis(1),
            cell_max: Duration::from_secs(1),
            min_reps: 1,
            max_reps: 3,
            light: false,
        };
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
            .position(|m| m.structure == "explicit" && m.operator == "r22")
            .unwrap();
        out[i].checksum = Some("1".into());
        let err = cross_check(&out, "t").unwrap_err();
        assert!(
            err.contains("r22") && err.contains("explicit") && err.contains("mesh t"),
            "{err}"
        );
    }

    #[test]
    fn a_cell_estimated_over_budget_is_skipped_with_its_estimate() {
        let mut est = Estimator::default();
        let key = Estimator::key("s", "torus", "r00", "sweep");
        est.last.insert(key.clone(), (1000, 1e6));
        // 16x the size at exponent 2: 256 ms.
        assert_eq!(est.estimate(&key, 16000, 2.0), Some(256e6));
    }
}
