//! The lab extended from outside: a crate with its own structure (implementing
//! [`MeshTopology`](topolab_structures::MeshTopology)) gets the lab's report with its structure
//! beside the registered ones and the C++ baselines, without editing the lab.
//!
//! The crate's report binary is one line, and takes the options of `topolab report`:
//!
//! ```ignore
//! // src/bin/report.rs (or src/main.rs) of a crate that depends on `topolab`:
//! fn main() -> std::process::ExitCode {
//!     topolab::extend::report_main::<my_crate::MyStructure>()
//! }
//! ```
//!
//! `cargo run --release --bin report -- --quick` then writes `reports/latest/index.html` and
//! `results.json` with `MyStructure` in every table. The type parameter is a
//! [`Structures`] list: one structure, or a tuple of several. `extend/sorted-edge-table/` is
//! the worked example, and `docs/extend.md` ("Benchmark your own structure") the guide.

use crate::commands::report::{report_with, ReportArgs};
use clap::Parser;
use std::process::ExitCode;
use topolab_structures::registry::Structures;

/// The command line of [`report_main`]: the options of `topolab report`.
#[derive(Parser, Debug)]
#[command(
    about = "Measure every operator on the lab's structures and the added ones; write results.json and index.html"
)]
pub struct ReportCli {
    /// The options of `topolab report`.
    #[command(flatten)]
    pub args: ReportArgs,
}

/// The `main` of a report binary outside the lab: parses the options of `topolab report` from
/// the command line and runs the report with the structures of `X` added (see the module
/// docs). Exit codes as `topolab report`: 0 written, 1 when two structures disagree, 2 on a
/// usage error (also for a name of `X` that the lab already uses).
pub fn report_main<X: Structures>() -> ExitCode {
    let cli = ReportCli::parse();
    let command = std::env::args().collect::<Vec<_>>().join(" ");
    match report_with::<X>(&cli.args, command).and_then(|text| crate::output::print(&text)) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("report: {}", e.message);
            ExitCode::from(e.code)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_added_structure_named_like_one_of_the_lab_is_a_usage_error() {
        let cli = ReportCli::try_parse_from(["report", "--quick"]).unwrap();
        // Refused before anything is measured or written.
        let e =
            report_with::<topolab_structures::VertexList>(&cli.args, String::new()).unwrap_err();
        assert_eq!(e.code, 2);
        assert!(
            e.message
                .contains(r#"two structures are called "vertex-list""#),
            "{}",
            e.message
        );
    }
}
