//! The lab's report with the sorted edge table beside the lab's structures and baselines: the
//! options of `topolab report` (`--quick`, `--sizes`, `--structures`, `--meshes`, `--out`).
//!
//! `cargo run --release -p sorted-edge-table --bin report -- --quick`

fn main() -> std::process::ExitCode {
    topolab::extend::report_main::<sorted_edge_table::SortedEdgeTable>()
}
