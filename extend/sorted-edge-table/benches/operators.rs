//! The lab's `cargo bench` groups for the sorted edge table beside every structure of the lab:
//!
//! `TOPOLAB_BENCH_STRUCTURES=sorted-edge-table,index-half-edge cargo bench -p sorted-edge-table --bench operators -- r00`

topolab_harness::bench_main!(sorted_edge_table::SortedEdgeTable, topolab_registry::Lab);
