//! The subcommands of `topolab`, one module each; [`crate::cli`] parses the command line and
//! calls them. Each returns the text to print or a [`crate::input::Failure`] (`check` returns
//! its exit code itself: it prints findings either way).

pub mod check;
pub mod explain;
pub mod explain_che;
pub mod hull;
pub mod info;
pub mod list;
pub mod refine;
pub mod report;
pub mod report_scale;
