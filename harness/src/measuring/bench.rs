//! `cargo bench` over the harness's kernels for any list of structures: one criterion group per
//! operator (and one for construction and each workload), `BenchmarkId::new(structure,
//! triangles)`, throughput in queries, meshes and queries built outside `b.iter`. A baseline
//! behind an FFI runs its own loops, as in the report. The lab's
//! `benches/operators.rs` and a crate outside the lab run the same groups:
//!
//! ```ignore
//! // benches/operators.rs of a crate with its own structure, beside the lab's registered ones
//! // (declare `[[bench]] name = "operators"`, `harness = false` in its Cargo.toml):
//! topolab_harness::bench_main!(my_crate::MyStructure, topolab_structures::registry::Registered);
//! ```
//!
//! Sizes of the torus: `TOPOLAB_BENCH_SIZES=1000,16000` (default). Structures:
//! `TOPOLAB_BENCH_STRUCTURES` (default every structure of the list). One group: `cargo bench
//! --bench operators -- r00`. Criterion is re-exported ([`criterion`]), so the calling crate
//! needs no criterion dependency of its own.

pub use criterion;

use crate::measuring::cells::Subject;
use crate::measuring::kernels::{
    run, run_workload, sample_queries, Queries, QuerySet, Workload, WorkloadBuffers,
};
use crate::measuring::measure::Builder;
use criterion::measurement::WallTime;
use criterion::{BatchSize, BenchmarkGroup, BenchmarkId, Criterion, Throughput};
use std::time::Duration;
use topolab_structures::registry::{duplicate_name, names, StructureVisitor, Structures};
use topolab_structures::{meshes, BoundaryCurves, MeshTopology, Operator, PolygonSoup};

/// What the groups measure.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Config {
    /// Triangle counts of the tori.
    pub sizes: Vec<usize>,
    /// The structures of the list to measure, by name; `None`: all of them.
    pub structures: Option<Vec<String>>,
}

impl Default for Config {
    fn default() -> Self {
        Self {
            sizes: vec![1_000, 16_000],
            structures: None,
        }
    }
}

impl Config {
    /// The defaults, changed by `TOPOLAB_BENCH_SIZES` and `TOPOLAB_BENCH_STRUCTURES` (comma
    /// separated); an error names a value that is not a size of at least one triangle.
    pub fn from_env() -> Result<Self, String> {
        Self::parse(
            std::env::var("TOPOLAB_BENCH_SIZES").ok().as_deref(),
            std::env::var("TOPOLAB_BENCH_STRUCTURES").ok().as_deref(),
        )
    }

    /// [`Config::from_env`] from the two variables' values.
    pub fn parse(sizes: Option<&str>, structures: Option<&str>) -> Result<Self, String> {
        let list =
            |v: &str| -> Vec<String> { v.split(',').map(|s| s.trim().to_string()).collect() };
        let mut config = Self::default();
        if let Some(v) = sizes {
            config.sizes = list(v)
                .iter()
                .map(|s| match s.parse::<usize>() {
                    Ok(n) if n > 0 => Ok(n),
                    _ => Err(format!(
                        "TOPOLAB_BENCH_SIZES: {s:?} is not a triangle count (a whole number > 0)"
                    )),
                })
                .collect::<Result<_, _>>()?;
        }
        config.structures = structures.map(list);
        Ok(config)
    }

    /// The names of the list `S` to measure: the configured ones, each checked to be in `S`,
    /// or all of `S`'s. An error names an unknown structure, or a name `S` holds twice.
    pub fn structures_of<S: Structures>(&self) -> Result<Vec<&'static str>, String> {
        let all = names::<S>();
        if let Some(name) = duplicate_name(&all) {
            return Err(format!("two structures of the list are called {name:?}"));
        }
        match &self.structures {
            None => Ok(all),
            Some(chosen) => chosen
                .iter()
                .map(|n| {
                    all.iter().copied().find(|a| a == n).ok_or_else(|| {
                        format!(
                            "TOPOLAB_BENCH_STRUCTURES: unknown structure {n:?}; known: {}",
                            all.join(", ")
                        )
                    })
                })
                .collect(),
        }
    }
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
        // A structure that cannot store the torus (a grid-only one) has nothing to time.
        let Ok(mut m) = M::from_soup(self.soup) else {
            return;
        };
        // A baseline behind an FFI runs its own loops, as the report times it
        // (`crate::measuring::measure`); a failure inside one ends the bench with the library's error.
        let native = M::native();
        let what = (M::NAME, self.what);
        match self.what {
            Subject::Construction => {
                // As the report times construction (`Builder`): a baseline's own, told its
                // counts by the lab's checks before the timing, and every structure dropped
                // after it (one at a time: a batch of large meshes would not fit).
                let Ok(builder) = Builder::<M>::new(self.soup) else {
                    return;
                };
                self.group
                    .throughput(Throughput::Elements(self.soup.num_faces() as u64));
                self.group.bench_function(id, |b| {
                    b.iter_batched(|| (), |()| builder.build(), BatchSize::PerIteration)
                });
            }
            Subject::Query(op) => {
                let q = Queries::sampled(&m, self.set);
                let mut curves = BoundaryCurves::default();
                self.group
                    .throughput(Throughput::Elements(q.count(op) as u64));
                match (native, q.sample(op)) {
                    // The sampled queries handed to the library before anything is timed.
                    (Some(k), Some(sample)) => {
                        let sampled = answered(what, k.sampled(&m, op, sample));
                        self.group
                            .bench_function(id, |b| b.iter(|| answered(what, sampled())));
                    }
                    // Boundary curves, a question about the whole mesh: the baseline's sweep.
                    (Some(k), None) => {
                        self.group
                            .bench_function(id, |b| b.iter(|| answered(what, k.sweep(&m, op))));
                    }
                    (None, _) => {
                        self.group
                            .bench_function(id, |b| b.iter(|| run(&m, op, &q, &mut curves)));
                    }
                }
            }
            Subject::Workload(w) => {
                let mut buf = WorkloadBuffers::default();
                self.group.throughput(Throughput::Elements(
                    w.items(m.num_vertices(), m.num_faces()) as u64,
                ));
                match native {
                    Some(k) => self
                        .group
                        .bench_function(id, |b| b.iter(|| answered(what, k.workload(&mut m, w)))),
                    None => self
                        .group
                        .bench_function(id, |b| b.iter(|| run_workload(&m, w, &mut buf))),
                };
            }
        }
    }
}

/// The answer of a native kernel of `what` (structure, subject): a failure inside the library
/// ends the bench with its error, as it stops the report.
fn answered<T>(what: (&str, Subject), answer: topolab_structures::Result<T>) -> T {
    answer.unwrap_or_else(|e| panic!("{} {}: native kernel failed: {e}", what.0, what.1))
}

/// Every group (each operator, construction, each workload) for the structures of `S` that
/// `config` chooses, on tori of `config.sizes` triangles; an error (before anything is
/// measured) names an unknown or doubly named structure.
pub fn operators<S: Structures>(c: &mut Criterion, config: &Config) -> Result<(), String> {
    let structures = config.structures_of::<S>()?;
    let meshes: Vec<(PolygonSoup, QuerySet)> = config
        .sizes
        .iter()
        .map(|&n| {
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
            for name in &structures {
                let bench = Bench {
                    group: &mut group,
                    what,
                    soup,
                    set,
                };
                if S::visit(name, bench).is_err() {
                    unreachable!("{name} is a name of the list");
                }
            }
        }
        group.finish();
    }
    Ok(())
}

/// [`operators`] with [`Config::from_env`]; a bad variable or list ends the process with the
/// message and exit code 2 (a bench binary has no caller to hand the error to).
pub fn operators_from_env<S: Structures>(c: &mut Criterion) {
    if let Err(e) = Config::from_env().and_then(|config| operators::<S>(c, &config)) {
        eprintln!("cargo bench: {e}");
        std::process::exit(2);
    }
}

/// The `main` of a `cargo bench` target (`harness = false`) that runs every group of this
/// module for the structure lists given, in order (see the module docs). Each argument is a
/// [`Structures`] list: a structure type, [`Registered`](topolab_structures::registry::Registered),
/// the `topolab` crate's `Lab` (which adds the C++ baselines), or a tuple of them.
#[macro_export]
macro_rules! bench_main {
    ($($list:ty),+ $(,)?) => {
        fn topolab_bench_groups(c: &mut $crate::measuring::bench::criterion::Criterion) {
            $crate::measuring::bench::operators_from_env::<($($list,)+)>(c)
        }
        $crate::measuring::bench::criterion::criterion_group!(benches, topolab_bench_groups);
        $crate::measuring::bench::criterion::criterion_main!(benches);
    };
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::registry::Registered;
    use topolab_structures::{CheL2, VertexList};

    #[test]
    fn the_variables_choose_sizes_and_structures_and_bad_values_are_named() {
        assert_eq!(Config::parse(None, None), Ok(Config::default()));
        let config = Config::parse(Some("200, 800"), Some("che-l2")).unwrap();
        assert_eq!(config.sizes, [200, 800]);
        assert_eq!(config.structures_of::<Registered>(), Ok(vec!["che-l2"]));
        for bad in ["1k", "0", "", "12,,3"] {
            let e = Config::parse(Some(bad), None).unwrap_err();
            assert!(e.contains("TOPOLAB_BENCH_SIZES"), "{bad:?}: {e}");
        }
        let e = Config::parse(None, Some("che-l2,nope"))
            .unwrap()
            .structures_of::<(VertexList, CheL2)>()
            .unwrap_err();
        assert!(
            e.contains(r#"unknown structure "nope"; known: vertex-list, che-l2"#),
            "{e}"
        );
        let e = Config::default()
            .structures_of::<(Registered, VertexList)>()
            .unwrap_err();
        assert!(e.contains(r#""vertex-list""#), "{e}");
    }
}
