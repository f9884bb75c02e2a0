//! The measurement's tests: one structure measured in rounds, with the plan's budgets.

use super::*;
use crate::measuring::kernels::Workload;
use crate::measuring::rounds::measure_structure;
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

/// Two rounds of 16 sampled queries; cells estimated above `cell_max` skipped.
fn short_plan(cell_max: Duration) -> Plan {
    Plan::fixed(cell_max, 2, 16, false)
}

#[test]
fn with_no_smaller_size_the_scans_are_skipped_by_their_time_per_query() {
    // One size only, as `topolab report --sizes 20000`: nothing to extrapolate from. The
    // vertex list scans the mesh for every query, so its sweeps of those operators, its
    // boundary curves and the workloads built on them are quadratic: ~10k queries of
    // ~60k corners each, seconds each; the budget is 20 ms.
    let soup = meshes::torus_with_triangles(20_000);
    let case = MeshCase {
        name: "torus-20k",
        family: "torus",
        soup: &soup,
        seed: 3,
    };
    // The estimates come from medians of at least five runs of a probe (unless its warm-up
    // alone outlasts the 50 ms budget), so that a run or two stretched by the scheduler
    // cannot decide. The budget sits between what runs and what scans, in this unoptimized
    // test build: 16 scanning queries take ~0.6 ms, the cheapest quadratic sweep (R00)
    // ~0.4 s.
    let plan = short_plan(Duration::from_millis(20));
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
fn a_light_plan_skips_a_quadratic_sweep_by_its_probe_too() {
    // The refined meshes are measured light (construction and the R00 sweep), at their
    // family's first size: only the probe of the first round's vertices can tell that the
    // vertex list's sweep is quadratic. Without it, a 3.3M-triangle mesh swept for hours.
    let soup = meshes::torus_with_triangles(20_000);
    let case = MeshCase {
        name: "torus-20k",
        family: "refined",
        soup: &soup,
        seed: 3,
    };
    let plan = Plan::fixed(Duration::from_millis(20), 2, 16, true);
    let (mut out, mut est) = (Vec::new(), Estimator::default());
    measure_structure::<VertexList>(&case, &plan, &NoMeter(Cell::new(0)), &mut est, &mut out)
        .unwrap();
    let kinds: Vec<(Subject, Kernel, Status)> = out
        .iter()
        .map(|m| (m.operator, m.kernel, m.status))
        .collect();
    assert_eq!(
        kinds,
        [
            (
                Subject::Construction,
                Kernel::Construction,
                Status::Measured
            ),
            (
                Subject::Query(Operator::R00),
                Kernel::Sweep,
                Status::Skipped
            )
        ]
    );
}

#[test]
fn measures_every_cell_and_cross_checks() {
    let soup = meshes::torus(6, 5);
    let case = MeshCase {
        name: "t",
        family: "torus",
        soup: &soup,
        seed: 3,
    };
    let plan = short_plan(Duration::from_secs(1));
    let (mut out, mut est) = (Vec::new(), Estimator::default());
    measure_structure::<VertexList>(&case, &plan, &NoMeter(Cell::new(0)), &mut est, &mut out)
        .unwrap();
    measure_structure::<ExplicitStorage>(&case, &plan, &NoMeter(Cell::new(0)), &mut est, &mut out)
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
