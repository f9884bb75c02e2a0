//! The `topolab` command-line tool; see `topolab --help`.

use clap::Parser;
use std::process::ExitCode;

fn main() -> ExitCode {
    ExitCode::from(topolab::cli::run(topolab::cli::Cli::parse()))
}
