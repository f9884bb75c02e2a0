//! One cell of the scale run, in its worker process (`topolab scale-cell`): one structure built
//! on one torus, measured ([`Measure`]). Run in a process of its own, so the kernel's count of
//! resident memory and page faults is this build's alone.

use crate::measuring::kernels::{self, sample_queries, Queries, WorkloadBuffers};
use crate::scale::proc::{faults, resident};
use crate::scale::{time_kernel, Check, Measure, SAMPLED_QUERIES};
use std::time::Instant;
use topolab_registry::{self as registry, StructureVisitor};
use topolab_structures::{meshes, BoundaryCurves, Cost, MeshTopology, Operator, Workload};

/// Seconds each kernel's repeated runs may take (at least 3 runs, at most 21).
const KERNEL_BUDGET_S: f64 = 0.5;

/// The seed of the sampled vertices, the same in every cell of a size, so the sampled R00 of
/// every structure answers the same queries.
const SAMPLE_SEED: u64 = 2026;

/// Whether a cost is a scan: O(n) or worse per query.
fn scans(cost: Cost) -> bool {
    matches!(
        cost,
        Cost::Linear | Cost::LocalTimesLinear | Cost::Quadratic
    )
}

struct Cell {
    triangles: usize,
}

impl StructureVisitor for Cell {
    type Output = Result<Measure, String>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        let before = resident();
        let t = Instant::now();
        let soup = meshes::torus_with_triangles(self.triangles);
        let generate_s = t.elapsed().as_secs_f64();
        let set = sample_queries(&soup, SAMPLED_QUERIES, SAMPLE_SEED);
        let (faces, vertices) = (soup.num_faces() as u64, soup.num_vertices() as u64);
        let faults_before = faults();
        let t = Instant::now();
        let m = M::from_soup(&soup).map_err(|e| e.to_string())?;
        let construction_ns_per_face = t.elapsed().as_secs_f64() * 1e9 / faces.max(1) as f64;
        let build_faults = faults().since(faults_before);
        let peak_bytes = resident().peak;
        drop(soup);
        let resident_bytes = resident().now.saturating_sub(before.now);
        let declared_bytes = m.heap_bytes() as u64;

        let faults_before = faults();
        let mut curves = BoundaryCurves::default();
        let sampled = Queries::sampled_vertices(&set);
        let r00_sampled = time_kernel(sampled.vertices.len() as u64, KERNEL_BUDGET_S, || {
            Check::Exact(kernels::run(&m, Operator::R00, &sampled, &mut curves))
        });
        let r00_sweep = (!scans(M::cost(Operator::R00))).then(|| {
            let every = Queries::every_vertex(&m);
            time_kernel(vertices, KERNEL_BUDGET_S, || {
                Check::Exact(kernels::run(&m, Operator::R00, &every, &mut curves))
            })
        });
        let local_smoothing =
            !scans(M::cost(Operator::R00)) && !scans(M::cost(Operator::BoundaryVertex));
        let smoothing = local_smoothing.then(|| {
            let mut buffers = WorkloadBuffers::default();
            time_kernel(vertices, KERNEL_BUDGET_S, || {
                Check::Float(kernels::run_workload(&m, Workload::Smoothing, &mut buffers))
            })
        });
        let sweep_faults = faults().since(faults_before);
        Ok(Measure {
            faces,
            vertices,
            generate_s,
            construction_ns_per_face,
            start_bytes: before.now,
            peak_bytes,
            resident_bytes,
            declared_bytes,
            build_faults,
            r00_sweep,
            r00_sampled,
            smoothing,
            sweep_faults,
        })
    }
}

/// Measures `structure` on a torus of about `triangles` triangles: `None` for a name this
/// build does not have, the structure's refusal of the torus as text.
pub fn measure(structure: &str, triangles: usize) -> Option<Result<Measure, String>> {
    registry::visit(structure, Cell { triangles })
}
