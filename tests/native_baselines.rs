//! Every baseline of the registry, a structure with native kernels (the C++ baselines this
//! build includes), is timed by its own loops in every cell the harness times, and each of its
//! loops answers exactly the queries the harness's generic kernel answers, with the same
//! checksum. The baselines are found through the registry, so a new one is covered here
//! without a new line.

mod common;

use common::{close, report_skip, NoMeter};
use std::time::Duration;
use topolab::registry::{self, StructureVisitor};
use topolab_harness::measuring::kernels::{run, run_workload, Kernel, Queries, QuerySet};
use topolab_harness::measuring::kernels::{Workload, WorkloadBuffers};
use topolab_harness::measuring::measure::{cross_check, Estimator, MeshCase, Plan};
use topolab_harness::measuring::rounds::measure_structure;
use topolab_harness::measuring::rounds::{round_sets, PASS};
use topolab_harness::results::{Measurement, Status, Subject};
use topolab_structures::{
    meshes, BoundaryCurves, EdgeId, FaceId, Input, MeshTopology, Operator, PolygonSoup, Sample,
    VertexId, VertexList,
};

/// What to check of one baseline.
#[derive(Copy, Clone)]
enum Check {
    /// The harness's cells on [`meshes_for`] the baseline.
    Cells,
    /// The sampled kernels on awkward samples.
    AwkwardSamples,
    /// The sampled kernels' refusals of bad samples.
    BadSamples,
}

/// Runs a [`Check`] on the structure it visits when that structure is a baseline (it has
/// native kernels); answers the baseline's name, or `None` for the lab's own structures.
struct Baseline(Check);

impl StructureVisitor for Baseline {
    type Output = Option<&'static str>;
    fn visit<M: MeshTopology>(self) -> Option<&'static str> {
        M::native()?;
        match self.0 {
            Check::Cells => meshes_for::<M>()
                .iter()
                .for_each(|(name, soup)| cells_are_native_with_generic_checksums::<M>(name, soup)),
            Check::AwkwardSamples => meshes_for::<M>()
                .iter()
                .for_each(|(name, soup)| awkward_samples_are_answered_alike::<M>(name, soup)),
            Check::BadSamples => bad_samples_are_refused::<M>(),
        }
        Some(M::NAME)
    }
}

/// Runs `check` on every baseline of the registry; returns their names (a skip is reported
/// when this build has none).
fn each_baseline(check: Check, what: &str) -> Vec<&'static str> {
    let names: Vec<&'static str> = registry::NAMES
        .iter()
        .filter_map(|name| registry::visit(name, Baseline(check)).flatten())
        .collect();
    if names.is_empty() {
        report_skip(what, "this build has no C++ baseline");
    }
    names
}

/// The meshes a baseline is measured on: a closed one, an open one, and polygons of 3 to 6
/// sides when it takes more than triangles.
fn meshes_for<M: MeshTopology>() -> Vec<(&'static str, PolygonSoup)> {
    let mut out = vec![
        ("torus", meshes::torus(6, 5)),
        ("grid", meshes::grid(5, 4, true)),
    ];
    if !M::capabilities().triangles_only {
        out.push(("polygons", meshes::mixed_grid(40)));
    }
    out
}

/// Every (subject, kernel) the harness times on a mesh, in no particular order.
fn timed_cells() -> Vec<(Subject, Kernel)> {
    let mut cells = vec![(Subject::Construction, Kernel::Construction)];
    for op in Operator::ALL {
        cells.push((Subject::Query(op), Kernel::Sweep));
        if op.input() != Input::Mesh {
            cells.push((Subject::Query(op), Kernel::Sampled));
        }
    }
    cells.extend(Workload::ALL.map(|w| (Subject::Workload(w), Kernel::Workload)));
    cells
}

/// Measures `M` on `soup` as the report does (with budgets that skip nothing) and checks each
/// cell: measured, native, and with the checksum of the generic kernel run on the same built
/// structure over the same queries; then cross-checks every cell with the vertex list's.
fn cells_are_native_with_generic_checksums<M: MeshTopology>(mesh: &str, soup: &PolygonSoup) {
    // Fewer sampled queries than elements, so that a kernel answering other queries than the
    // sample's (every element, or every edge of a sampled face) gives another checksum.
    let case = MeshCase {
        name: mesh,
        family: mesh,
        soup,
        seed: 3,
    };
    let plan = Plan::fixed(Duration::from_secs(60), 2, 8, false);
    let (mut out, mut est) = (Vec::new(), Estimator::default());
    measure_structure::<M>(&case, &plan, &NoMeter, &mut est, &mut out).unwrap();
    let m = M::from_soup(soup).unwrap();
    // A sampled cell's checksum is its first round's first pass.
    let set = &round_sets(&case, &plan)[0];
    let all = Queries::all(&m, soup);
    let sampled = Queries::sampled(&m, set).passes(PASS).remove(0);
    let (mut curves, mut buf) = (BoundaryCurves::default(), WorkloadBuffers::default());
    let cells = timed_cells();
    assert_eq!(out.len(), cells.len(), "{} on {mesh}: {out:?}", M::NAME);
    for (subject, kernel) in cells {
        let what = format!("{} {subject} {kernel} on {mesh}", M::NAME);
        let cell: &Measurement = out
            .iter()
            .find(|c| c.operator == subject && c.kernel == kernel)
            .unwrap_or_else(|| panic!("{what}: no cell"));
        assert_eq!(cell.status, Status::Measured, "{what}: {cell:?}");
        assert!(
            cell.native,
            "{what} was not timed by the baseline's own loop"
        );
        let checksum = cell.checksum.as_deref();
        match subject {
            Subject::Construction => assert_eq!(checksum, None, "{what}"),
            Subject::Query(op) => {
                let q = if kernel == Kernel::Sweep {
                    &all
                } else {
                    &sampled
                };
                let generic = run(&m, op, q, &mut curves).to_string();
                assert_eq!(checksum, Some(generic.as_str()), "{what}");
            }
            Subject::Workload(w) => {
                let native: f64 = checksum.expect("a workload's result").parse().unwrap();
                let generic = run_workload(&m, w, &mut buf);
                assert!(close(native, generic), "{what}: {native} vs {generic}");
            }
        }
    }
    measure_structure::<VertexList>(&case, &plan, &NoMeter, &mut est, &mut out).unwrap();
    cross_check(&out, mesh).unwrap();
}

/// The natively run sampled kernel of `op` over `q` on `m`.
fn native_sampled<M: MeshTopology>(m: &M, op: Operator, q: &Queries) -> u64 {
    let kernels = M::native().expect("a baseline");
    let sample = q.sample(op).expect("an operator with queries");
    let run = kernels
        .sampled(m, op, sample)
        .unwrap_or_else(|e| panic!("{} {}: {e}", M::NAME, op.name()));
    run().unwrap_or_else(|e| panic!("{} {}: {e}", M::NAME, op.name()))
}

/// A sample that a kernel answering other queries than the sample's would get wrong: ids at
/// both ends and repeated (a repeated query counts twice), an edge named by its ends in both
/// orders, and (edge, face) pairs whose edge does not bound the face, which ask for no
/// successor or predecessor (the last two queries).
fn awkward_set(soup: &PolygonSoup) -> QuerySet {
    let ends = |n: usize| {
        let n = n as u32;
        vec![n - 1, 0, n / 2, n / 2]
    };
    let corner = |c: usize| {
        let f = soup.offsets().partition_point(|&o| o as usize <= c) - 1;
        (
            soup.indices()[c],
            soup.indices()[soup.next_corner(c, f)],
            f as u32,
        )
    };
    // The last face without edge (x, y).
    let apart = |x: u32, y: u32| {
        let g = (0..soup.num_faces())
            .rev()
            .find(|&g| !(soup.face(g).contains(&x) && soup.face(g).contains(&y)))
            .expect("a face away from the edge");
        g as u32
    };
    let (a, b, f) = corner(0);
    let (c, d, g) = corner(soup.num_corners() - 1);
    QuerySet {
        vertices: ends(soup.num_vertices()),
        faces: ends(soup.num_faces()),
        edges: vec![
            (a, b, f),
            (b, a, f),
            (c, d, g),
            (a, b, f),
            (a, b, apart(a, b)),
            (c, d, apart(c, d)),
        ],
    }
}

/// The sampled kernels of `M` on the awkward sample of `soup` give the generic kernel's
/// checksums, on `M` itself and on the vertex list.
fn awkward_samples_are_answered_alike<M: MeshTopology>(mesh: &str, soup: &PolygonSoup) {
    let set = awkward_set(soup);
    let m = M::from_soup(soup).unwrap();
    let reference = VertexList::from_soup(soup).unwrap();
    let (q, reference_q) = (
        Queries::sampled(&m, &set),
        Queries::sampled(&reference, &set),
    );
    let mut curves = BoundaryCurves::default();
    for op in Operator::ALL
        .into_iter()
        .filter(|op| op.input() != Input::Mesh)
    {
        let what = format!("{} sampled {} on {mesh}", M::NAME, op.name());
        let native = native_sampled(&m, op, &q);
        assert_eq!(native, run(&m, op, &q, &mut curves), "{what}");
        assert_eq!(
            native,
            run(&reference, op, &reference_q, &mut curves),
            "{what} vs the vertex list"
        );
    }
    // The two pairs whose edge does not bound the face count nothing.
    let mut unrelated = set.clone();
    unrelated.edges.drain(..unrelated.edges.len() - 2);
    let unrelated = Queries::sampled(&m, &unrelated);
    for op in [Operator::EdgeSuccessor, Operator::EdgePredecessor] {
        assert_eq!(native_sampled(&m, op, &unrelated), 0, "{} {op:?}", M::NAME);
        assert_ne!(native_sampled(&m, op, &q), 0, "{} {op:?}", M::NAME);
    }
}

/// A sample with an id the mesh does not have, or of another kind of query than the
/// operator's, is refused with a typed error before anything runs; so is a sampled kernel of
/// boundary curves, a question about the whole mesh.
fn bad_samples_are_refused<M: MeshTopology>() {
    let m = M::from_soup(&meshes::torus(6, 5)).unwrap();
    let kernels = M::native().expect("a baseline");
    let (v, e, f) = (
        m.num_vertices() as u32,
        m.num_edges() as u32,
        m.num_faces() as u32,
    );
    let refusal = |op: Operator, sample: Sample<'_>| {
        kernels
            .sampled(&m, op, sample)
            .err()
            .unwrap_or_else(|| panic!("{} {op:?} took a bad sample", M::NAME))
    };
    for (op, sample) in [
        (Operator::R00, Sample::Vertices(&[VertexId(0), VertexId(v)])),
        (Operator::R11, Sample::Edges(&[EdgeId(e)])),
        (Operator::R20, Sample::Faces(&[FaceId(f)])),
        (
            Operator::EdgeSuccessor,
            Sample::EdgesOfFaces(&[(EdgeId(0), FaceId(f))]),
        ),
        (
            Operator::EdgePredecessor,
            Sample::EdgesOfFaces(&[(EdgeId(e), FaceId(0))]),
        ),
    ] {
        let error = refusal(op, sample);
        assert_eq!(error.kind(), "element-out-of-range", "{}: {error}", M::NAME);
    }
    for (op, sample) in [
        (Operator::R10, Sample::Vertices(&[VertexId(0)])),
        (Operator::EdgeSuccessor, Sample::Faces(&[FaceId(0)])),
        (Operator::BoundaryCurves, Sample::Edges(&[EdgeId(0)])),
    ] {
        let error = refusal(op, sample);
        assert_eq!(error.kind(), "unsupported", "{}: {error}", M::NAME);
    }
}

#[test]
fn the_registrys_baselines_are_the_structures_with_native_kernels() {
    let baselines = each_baseline(Check::BadSamples, "the baselines' bad samples");
    let expected: Vec<&str> = registry::CPP_BASELINES
        .into_iter()
        .filter(|name| registry::NAMES.contains(name))
        .collect();
    assert_eq!(baselines, expected);
}

#[test]
fn every_timed_cell_of_a_baseline_is_its_own_loop_with_the_generic_checksum() {
    each_baseline(Check::Cells, "the baselines' timed cells");
}

#[test]
fn a_baselines_sampled_kernels_answer_exactly_the_generic_kernels_queries() {
    each_baseline(Check::AwkwardSamples, "the baselines' sampled kernels");
}
