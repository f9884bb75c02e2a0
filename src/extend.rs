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
//! [`Structures`] list: one structure, or a tuple of several. `templates/sorted-edge-table/` is
//! the worked example, and the README's section "Benchmark your own structure" the guide.

use crate::commands::report::{report_with, ReportArgs};
use crate::registry::{self, StructureVisitor};
use clap::Parser;
use std::process::ExitCode;
use topolab_structures::registry::Structures;

/// Every structure of this build of the lab (the [`registry`]: the structures of
/// `topolab-structures`, then the C++ baselines compiled in) as a [`Structures`] list, for
/// the report and the `cargo bench` groups of `topolab_harness::bench`.
#[derive(Copy, Clone, Debug)]
pub struct Lab;

impl Structures for Lab {
    fn names(out: &mut Vec<&'static str>) {
        out.extend_from_slice(registry::NAMES);
    }
    fn visit<V: StructureVisitor>(name: &str, visitor: V) -> Result<V::Output, V> {
        if registry::NAMES.contains(&name) {
            Ok(registry::visit(name, visitor).expect("a registered name visits its structure"))
        } else {
            Err(visitor)
        }
    }
}

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

    struct Name;
    impl StructureVisitor for Name {
        type Output = &'static str;
        fn visit<M: topolab_structures::MeshTopology>(self) -> &'static str {
            M::NAME
        }
    }

    #[test]
    fn the_lab_is_every_registered_structure_and_only_those() {
        assert_eq!(
            topolab_structures::registry::names::<Lab>(),
            registry::NAMES
        );
        for &name in registry::NAMES {
            assert_eq!(Lab::visit(name, Name).ok(), Some(name));
        }
        assert!(Lab::visit("no-such-structure", Name).is_err());
    }

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
