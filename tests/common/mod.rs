//! The checksums of `topolab_harness::measuring::checksum`, written over [`MeshTopology`] for any
//! structure, to check the baselines (OpenMesh's C++ sweeps, libigl's outputs) against.

// Each test crate that includes this module uses part of it.
#![allow(dead_code)]

pub mod run;
/// The helpers shared with the baselines crate's tests.
#[path = "../../baselines/tests/common/mod.rs"]
mod shared;
#[allow(unused_imports)]
pub use shared::{broken_soups, closed_fan_soups, report_skip};

use glam::DVec3;
use std::time::Duration;
use topolab_harness::measuring::checksum::{edge_key, mix};
use topolab_harness::measuring::kernels::Kernel;
use topolab_harness::measuring::measure::{Estimator, MemoryMeter, MeshCase, Plan};
use topolab_harness::measuring::rounds::measure_structure;
use topolab_harness::results::Measurement;
use topolab_structures::meshes::{self, RandomMeshParams};
use topolab_structures::{
    BoundaryCurves, EdgeId, FaceId, Input, MeshTopology, Operator, PolygonSoup, VertexId,
    VertexList, Workload,
};

fn key<M: MeshTopology>(m: &M, e: EdgeId) -> u64 {
    let [a, b] = m.edge_vertices(e);
    edge_key(a.0, b.0)
}

/// How many query elements a sweep of operator `op` walks in `m`: vertices, edges or faces by
/// its input (faces for successor and predecessor, asked about every edge of each face; one
/// mesh).
fn query_count<M: MeshTopology>(m: &M, op: Operator) -> usize {
    match op.input() {
        Input::Vertex => m.num_vertices(),
        Input::Edge => m.num_edges(),
        Input::Face | Input::EdgeOfFace => m.num_faces(),
        Input::Mesh => 1,
    }
}

/// The checksum term of query element `id` (vertex, edge or face id by the operator).
fn term<M: MeshTopology>(m: &M, op: Operator, id: u32) -> u64 {
    let mut sum = 0u64;
    let mut add = |x: u64| sum = sum.wrapping_add(x);
    let (v, e, f) = (VertexId(id), EdgeId(id), FaceId(id));
    let q = id as u64;
    match op {
        Operator::R00 => m.vertex_vertices(v, |w| add(mix(q, w.0 as u64))),
        Operator::R01 => m.vertex_edges(v, |x| add(mix(q, key(m, x)))),
        Operator::R02 => m.vertex_faces(v, |g| add(mix(q, g.0 as u64))),
        Operator::R10 => {
            let [a, b] = m.edge_vertices(e);
            add(mix(a.0.min(b.0) as u64, a.0.max(b.0) as u64));
        }
        Operator::R11 => m.edge_edges(e, |x| add(mix(key(m, e), key(m, x)))),
        Operator::R12 => m.edge_faces(e, |g| add(mix(key(m, e), g.0 as u64))),
        Operator::R20 => m.face_vertices(f, |w| add(mix(q, w.0 as u64))),
        Operator::R21 => m.face_edges(f, |x| add(mix(q, key(m, x)))),
        Operator::R22 => m.face_faces(f, |g| add(mix(q, g.0 as u64))),
        Operator::BoundaryVertex if m.is_boundary_vertex(v) => add(mix(q, 1)),
        Operator::BoundaryEdge if m.is_boundary_edge(e) => add(mix(key(m, e), 1)),
        Operator::EdgeSuccessor | Operator::EdgePredecessor => m.face_edges(f, |x| {
            let other = if op == Operator::EdgeSuccessor {
                m.edge_successor(x, f)
            } else {
                m.edge_predecessor(x, f)
            };
            let other = other.expect("an edge of a face has a successor and a predecessor in it");
            add(mix(key(m, x), key(m, other)));
        }),
        _ => {}
    }
    sum
}

/// The sweep checksum of `op` over every element of `m`.
pub fn checksum<M: MeshTopology>(m: &M, op: Operator) -> u64 {
    if op == Operator::BoundaryCurves {
        let mut curves = BoundaryCurves::default();
        m.boundary_curves(&mut curves);
        let mut sum = 0u64;
        for i in 0..curves.len() {
            let curve = curves.curve(i);
            for &e in curve {
                sum = sum.wrapping_add(mix(curve.len() as u64, key(m, e)));
            }
        }
        return sum;
    }
    let ids: Vec<u32> = match op.input() {
        // Edge ids are each structure's own: enumerate them.
        Input::Edge => {
            let mut ids = Vec::with_capacity(m.num_edges());
            m.for_each_edge(|e| ids.push(e.0));
            ids
        }
        _ => (0..query_count(m, op) as u32).collect(),
    };
    ids.iter()
        .fold(0u64, |sum, &id| sum.wrapping_add(term(m, op, id)))
}

/// Unit normal of a polygon (Newell's method; for a triangle, the normalised cross product).
fn face_normal(p: &[DVec3]) -> DVec3 {
    let mut n = DVec3::ZERO;
    for i in 0..p.len() {
        let (a, b) = (p[i], p[(i + 1) % p.len()]);
        n += DVec3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        );
    }
    n.normalize_or_zero()
}

/// The `normals` workload's result: vertex normals as the normalised sum of the unit normals
/// of their faces, and the sum of all their coordinates.
pub fn uniform_vertex_normals_sum(soup: &PolygonSoup) -> f64 {
    let mut vertex_normals = vec![DVec3::ZERO; soup.num_vertices()];
    for face in soup.faces() {
        let p: Vec<DVec3> = face.iter().map(|&v| soup.positions[v as usize]).collect();
        let n = face_normal(&p);
        face.iter().for_each(|&v| vertex_normals[v as usize] += n);
    }
    vertex_normals
        .iter()
        .map(|n| n.normalize_or_zero().element_sum())
        .sum()
}

/// `a` and `b` agree to about 1e-9, relative.
pub fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
}

/// A memory meter that measures nothing (the heap is measured in tests of its own, with the
/// lab's allocator: [`construction_cell`]).
pub struct NoMeter;
impl MemoryMeter for NoMeter {
    fn current(&self) -> usize {
        0
    }
    fn peak(&self) -> usize {
        0
    }
    fn reset_peak(&self) {}
}

/// The meshes the baselines' native kernels are checked on: a torus (closed), a triangle grid
/// (boundary), a quad grid and mixed polygons, and a shuffled random mesh with holes and
/// corner-touching cells.
pub fn baseline_meshes() -> Vec<(&'static str, PolygonSoup)> {
    vec![
        ("torus", meshes::torus(12, 7)),
        ("grid", meshes::grid(6, 4, true)),
        ("quad-grid", meshes::grid(5, 3, false)),
        ("mixed-polygons", meshes::mixed_polygons()),
        (
            "random",
            meshes::random_mesh(7, RandomMeshParams::default()),
        ),
    ]
}

/// The result of one step of the `smoothing` workload on `soup`, computed through `reference`
/// (a lab structure): the sum of every vertex's new coordinates.
pub fn smoothing_sum<M: MeshTopology>(soup: &PolygonSoup, reference: &M) -> f64 {
    (0..soup.num_vertices())
        .map(|v| {
            let v = VertexId::new(v);
            let (mut sum, mut k) = (DVec3::ZERO, 0.0);
            reference.vertex_vertices(v, |w| {
                sum += soup.positions[w.index()];
                k += 1.0;
            });
            if reference.is_boundary_vertex(v) || k == 0.0 {
                soup.positions[v.index()]
            } else {
                sum / k
            }
        })
        .map(|p| p.element_sum())
        .sum()
}

/// A plan of two rounds (the tests check what is measured, not how surely); `light`, the
/// construction and the R00 sweep only.
fn small_plan(light: bool) -> Plan {
    Plan::fixed(Duration::from_secs(10), 2, 8, light)
}

/// The construction cell of `M` on `soup` as the report measures it, its heap counted by the
/// lab's allocator (the C++ baselines' blocks too, on this thread only, so tests measure in
/// parallel), with a light plan: the construction and one sweep.
pub fn construction_cell<M: MeshTopology>(soup: &PolygonSoup) -> Measurement {
    let case = MeshCase {
        name: "mesh",
        family: "torus",
        soup,
        seed: 3,
    };
    let plan = small_plan(true);
    let (mut out, mut est) = (Vec::new(), Estimator::default());
    measure_structure::<M>(&case, &plan, &topolab::ALLOCATOR, &mut est, &mut out).unwrap();
    out.into_iter()
        .find(|m| m.kernel == Kernel::Construction)
        .expect("a construction cell")
}

/// Checks a baseline's native workloads on every mesh of [`baseline_meshes`] against what the
/// benchmark says each computes: `build` builds the baseline, `run` runs a workload on it
/// (after `prepare` for the normals, as the report does), `position` reads a position back.
pub fn check_native_workloads<M>(
    build: impl Fn(&PolygonSoup) -> M,
    prepare: impl Fn(&mut M, Workload),
    run: impl Fn(&mut M, Workload) -> f64,
    position: impl Fn(&M, usize) -> DVec3,
) {
    for (name, soup) in baseline_meshes() {
        let mut mesh = build(&soup);
        let reference = VertexList::from_soup(&soup).unwrap();
        let circulators = run(&mut mesh, Workload::Circulators);
        assert_eq!(
            circulators,
            soup.num_corners() as f64,
            "circulators on {name}"
        );

        let mean = soup.positions.iter().sum::<DVec3>() / soup.num_vertices() as f64;
        let barycenter = run(&mut mesh, Workload::Barycenter);
        assert!(
            close(barycenter, mean.element_sum()),
            "barycenter on {name}"
        );

        let expected = uniform_vertex_normals_sum(&soup);
        prepare(&mut mesh, Workload::Normals);
        let normals = run(&mut mesh, Workload::Normals);
        assert!(
            close(normals, expected),
            "normals on {name}: {normals} vs {expected}"
        );

        let expected = smoothing_sum(&soup, &reference);
        let smoothing = run(&mut mesh, Workload::Smoothing);
        assert!(close(smoothing, expected), "smoothing on {name}");
        // The step is computed into a buffer: the mesh keeps its positions, so a second run
        // computes the same step.
        for (v, p) in soup.positions.iter().enumerate() {
            assert_eq!(position(&mesh, v), *p, "smoothing moved v{v} on {name}");
        }
        assert_eq!(run(&mut mesh, Workload::Smoothing), smoothing, "{name}");
    }
}
