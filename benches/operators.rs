//! `cargo bench`: the criterion groups of `topolab_harness::measuring::bench` (one per operator, one for
//! construction and each workload; `BenchmarkId::new(structure, triangles)`) for every
//! structure of the lab, the C++ baselines included.
//!
//! Sizes: `TOPOLAB_BENCH_SIZES=1000,16000` (default). Structures: `TOPOLAB_BENCH_STRUCTURES`
//! (default all). Run one group with `cargo bench --bench operators -- r00`.

topolab_harness::bench_main!(topolab_registry::Lab);
