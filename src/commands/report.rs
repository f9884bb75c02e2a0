//! `topolab report`: its options, checked ([`report_with`]: names, families, and what the
//! machine and the output folder admit) and handed to the harness's report run
//! ([`topolab_harness::report::pipeline`]) as a plain request, with what only this program has
//! ([`Host`]: its counting allocator, and what the machine it runs on admits). [`report_with`] is the
//! same report with structures from outside the lab beside the lab's (see [`crate::extend`]).

use crate::input::Failure;
use std::marker::PhantomData;
use std::path::PathBuf;
use topolab_harness::measuring::measure::MemoryMeter;
use topolab_harness::report::pipeline::{self, Host};
use topolab_harness::report::run::{MeshFamily, ReportError, Request};
use topolab_harness::report::sections::libigl::LIBIGL;
use topolab_registry::Lab;
use topolab_structures::registry::{duplicate_name, names, Structures};

/// Options of `topolab report`.
#[derive(clap::Args, Debug, Clone)]
pub struct ReportArgs {
    /// A smaller, faster run (three sizes up to 16k triangles, short budgets): under 2 minutes.
    #[arg(long)]
    pub quick: bool,
    /// The full measurement, beyond the default's 15-minute budget: the hull on a sphere up to
    /// 1M points and the slow hull algorithms' larger sizes, the 3.3M refined armadillo
    /// measured like the 1.2M bunny, and five runs of the changing workloads on the 1M torus.
    #[arg(long, conflicts_with = "quick")]
    pub full: bool,
    /// Triangle counts of the size sweep, comma separated, each from 1 to 2^30, measured smallest
    /// first (default 1000,4000,16000,64000,256000,1000000).
    #[arg(long, value_delimiter = ',')]
    pub sizes: Option<Vec<usize>>,
    /// Structures to measure, comma separated (default: all; see `topolab list`). Given, the
    /// libigl section runs only when it names `libigl`, the hull section only when it names
    /// `winged-edge` (the structure the hull algorithms build).
    #[arg(long, value_delimiter = ',')]
    pub structures: Option<Vec<String>>,
    /// Sections of the page to measure and show, comma separated (default: all): chooser,
    /// table-4-1, plots, sweeps, workloads, memory, construction, orderings, real-meshes,
    /// real-at-scale, libigl, hull, changing, edit-ops, decimate, teaching, meshes, targets. Only what
    /// they are drawn from is measured.
    #[arg(long, value_delimiter = ',', value_parser = super::report_sections::section)]
    pub sections: Option<Vec<String>>,
    /// Mesh families, comma separated: `torus` (closed), `grid` (open, with boundary), `real`
    /// (the meshes `make data` fetched into bench-data/cache/, when present), `refined` (two of
    /// them refined by Loop subdivision to 1.2M and 3.3M triangles, measured like the tori).
    #[arg(long, value_delimiter = ',', default_value = "torus,grid,real,refined")]
    pub meshes: Vec<String>,
    /// Output folder.
    #[arg(long, default_value = "reports/latest")]
    pub out: PathBuf,
    /// Size of the memory probe's arrays, MiB, from 1 to 4096 (default 256, 64 with --quick).
    #[arg(long, hide = true, value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(1..=4096))]
    pub probe_mb: Option<usize>,
}

/// Runs the report; returns a summary line or a failure (exit 1 on a checksum mismatch).
pub fn report(args: &ReportArgs, command: String) -> Result<String, Failure> {
    report_with::<()>(args, command)
}

/// [`report`] with the structures of the list `X` (structures outside the lab) measured beside
/// the lab's, after them in every table. A name of `X` that is already taken is a usage error.
pub fn report_with<X: Structures>(args: &ReportArgs, command: String) -> Result<String, Failure> {
    let all = names::<(Lab, X)>();
    if let Some(name) = duplicate_name(&all) {
        return Err(Failure::usage(format!(
            "two structures are called {name:?}: a structure added to the report needs a name \
             of its own (see `topolab list`)"
        )));
    }
    let quick = args.quick;
    let mut sizes = args.sizes.clone().unwrap_or_else(|| {
        if quick {
            vec![1_000, 4_000, 16_000]
        } else {
            vec![1_000, 4_000, 16_000, 64_000, 256_000, 1_000_000]
        }
    });
    // Smallest first, each once: the skip-by-estimate extrapolates from the sizes before.
    sizes.sort_unstable();
    sizes.dedup();
    let names: Vec<String> = match &args.structures {
        Some(list) => {
            let mut names: Vec<String> = Vec::with_capacity(list.len());
            for n in list.iter().filter(|n| *n != LIBIGL) {
                if !all.contains(&n.as_str()) {
                    return Err(crate::input::unknown_structure(n));
                }
                if !names.contains(n) {
                    names.push(n.clone());
                }
            }
            names
        }
        None => all.iter().map(|s| s.to_string()).collect(),
    };
    let mut families: Vec<MeshFamily> = Vec::with_capacity(args.meshes.len());
    for f in &args.meshes {
        let f = MeshFamily::from_name(f).map_err(failure)?;
        if !families.contains(&f) {
            families.push(f);
        }
    }
    let probe_mb = args.probe_mb.unwrap_or(if quick { 64 } else { 256 });
    // Refused here, before anything is measured: sizes past u32 ids, more memory than there
    // is, an output folder that cannot be written (it used to fail after the whole run).
    let generated: Vec<&str> = families
        .iter()
        .filter(|f| f.generated())
        .map(|f| f.name())
        .collect();
    crate::limits::admit_report(&sizes, &generated, &names, probe_mb)?;
    crate::output::check_folder(&args.out, &["results.json", "index.html", "FINDINGS.md"])?;
    let request = Request {
        quick,
        full: args.full,
        sizes,
        names,
        structures: args.structures.clone(),
        added: topolab_structures::registry::names::<X>()
            .into_iter()
            .map(str::to_string)
            .collect(),
        sections: args.sections.clone(),
        meshes: families,
        out: args.out.clone(),
        probe_mb,
        command,
    };
    pipeline::report::<(Lab, X)>(&request, &Cli::<X>(PhantomData)).map_err(failure)
}

/// The CLI's failure of a report's error: exit 2 for a request that cannot run or a report
/// that cannot be written, 1 for a measurement that failed.
fn failure(e: ReportError) -> Failure {
    let code = match e {
        ReportError::Measurement(_) => 1,
        ReportError::Usage(_) | ReportError::Output(_) => 2,
    };
    Failure {
        message: e.message().to_string(),
        code,
    }
}

/// A report's error of the CLI's failure: a measurement's when it exits 1, else a usage one.
fn report_error(f: Failure) -> ReportError {
    match f.code {
        1 => ReportError::Measurement(f.message),
        _ => ReportError::Usage(f.message),
    }
}

/// This program as the report's host, with the structures of `X` beside the lab's.
struct Cli<X>(PhantomData<X>);

impl<X: Structures> Host for Cli<X> {
    fn meter(&self) -> &dyn MemoryMeter {
        &crate::ALLOCATOR
    }

    fn admit_refined(&self, faces: usize, structures: &[String]) -> Result<(), ReportError> {
        // As a torus of as many triangles, with two builds of the largest structure.
        crate::limits::admit_report(&[faces], &["torus"], structures, 0).map_err(report_error)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser as _;

    fn args(line: &[&str]) -> Result<ReportArgs, clap::Error> {
        crate::cli::Cli::try_parse_from(line).map(|cli| match cli.command {
            crate::cli::Command::Report(args) => args,
            _ => panic!("not a report"),
        })
    }

    #[test]
    fn full_is_an_option_of_its_own_and_not_with_quick() {
        let full = args(&["topolab", "report", "--full"]).expect("--full parses");
        assert!(full.full && !full.quick);
        assert!(!args(&["topolab", "report"]).expect("parses").full);
        let both = args(&["topolab", "report", "--quick", "--full"]).map(|_| ());
        assert_eq!(
            both.expect_err("conflict").kind(),
            clap::error::ErrorKind::ArgumentConflict
        );
    }
}
