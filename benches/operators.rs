//! `cargo bench`: criterion benchmarks over the harness's kernels, one group per operator (and
//! one for construction and each workload), `BenchmarkId::new(structure, triangles)`,
//! throughput in queries, meshes and queries built outside `b.iter`.
//!
//! Sizes: `TOPOLAB_BENCH_SIZES=1000,16000` (default). Structures: `TOPOLAB_BENCH_STRUCTURES`
//! (default all). Run one group with `cargo bench --bench operators -- r00`.

use criterion::measurement::WallTime;
use criterion::{
    criterion_group, criterion_main, BenchmarkGroup, BenchmarkId, Criterion, Throughput,
};
use std::time::Duration;
use topolab::registry::{self, StructureVisitor};
use topolab_harness::kernels::{
    run, run_workload, sample_queries, Queries, QuerySet, Workload, WorkloadBuffers,
};
use topolab_harness::results::Subject;
use topolab_structures::{meshes, BoundaryCurves, MeshTopology, Operator, PolygonSoup};

fn env_list(name: &str) -> Option<Vec<String>> {
    std::env::var(name)
        .ok()
        .map(|v| v.split(',').map(|s| s.trim().to_string()).collect())
}

fn sizes() -> Vec<usize> {
    env_list("TOPOLAB_BENCH_SIZES")
        .map(|v| v.iter().filter_map(|s| s.parse().ok()).collect())
        .unwrap_or_else(|| vec![1_000, 16_000])
}

fn structures() -> Vec<String> {
    env_list("TOPOLAB_BENCH_STRUCTURES")
        .unwrap_or_else(|| registry::NAMES.iter().map(|s| s.to_string()).collect())
}

struct Bench<'a, 'g> {
    group: &'a mut BenchmarkGroup<'g, WallTime>,
    what: Subject,
    soup: &'a PolygonSoup,
    set: &'a QuerySet,
}

impl StructureVisitor for Bench<'_, '_> {
    type Output = ();
    fn visit<M: MeshTopology>(self) {
        let id = BenchmarkId::new(M::NAME, self.soup.num_faces());
        let Ok(m) = M::from_soup(self.soup) else {
            return;
        };
        match self.what {
            Subject::Construction => {
                self.group
                    .throughput(Throughput::Elements(self.soup.num_faces() as u64));
                self.group.bench_function(id, |b| {
                    b.iter(|| M::from_soup(self.soup).map(|m| m.num_faces()))
                });
            }
            Subject::Query(op) => {
                let q = Queries::sampled(&m, self.set);
                let mut curves = BoundaryCurves::default();
                self.group
                    .throughput(Throughput::Elements(q.count(op) as u64));
                self.group
                    .bench_function(id, |b| b.iter(|| run(&m, op, &q, &mut curves)));
            }
            Subject::Workload(w) => {
                let mut buf = WorkloadBuffers::default();
                self.group
                    .throughput(Throughput::Elements(w.items(&m) as u64));
                self.group
                    .bench_function(id, |b| b.iter(|| run_workload(&m, w, &mut buf)));
            }
        }
    }
}

fn operators(c: &mut Criterion) {
    let meshes: Vec<(PolygonSoup, QuerySet)> = sizes()
        .into_iter()
        .map(|n| {
            let soup = meshes::torus_with_triangles(n);
            let set = sample_queries(&soup, 64, 2026);
            (soup, set)
        })
        .collect();
    let groups = Operator::ALL
        .map(Subject::Query)
        .into_iter()
        .chain([Subject::Construction])
        .chain(Workload::ALL.map(Subject::Workload));
    for what in groups {
        let mut group = c.benchmark_group(what.name());
        group
            .sample_size(10)
            .warm_up_time(Duration::from_millis(300))
            .measurement_time(Duration::from_secs(1));
        for (soup, set) in &meshes {
            for s in structures() {
                registry::visit(
                    &s,
                    Bench {
                        group: &mut group,
                        what,
                        soup,
                        set,
                    },
                );
            }
        }
        group.finish();
    }
}

criterion_group!(benches, operators);
criterion_main!(benches);
