//! The `topolab` command-line tool; see `topolab --help`.

use clap::Parser;
use std::process::ExitCode;

fn main() -> ExitCode {
    match topolab::cli::Cli::try_parse() {
        Ok(cli) => ExitCode::from(topolab::cli::run(cli)),
        Err(e) => topolab::cli::usage_error(e),
    }
}
