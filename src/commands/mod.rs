//! The subcommands of `topolab`, one module each; [`crate::cli`] parses the command line and
//! calls them. Each returns the text to print or a [`crate::input::Failure`] (`check` and
//! `repair` return their exit code themselves: they print their findings either way).

pub mod check;
pub mod compare;
pub mod convert;
pub mod decimate;
pub mod explain;
pub mod explain_che;
pub mod explain_costs;
mod explain_counted;
pub mod explain_edit;
pub mod explain_trace;
pub mod hull;
pub mod info;
mod info_che;
mod info_text;
pub mod list;
pub mod list_counted;
pub mod reconstruct;
pub mod refine;
pub mod refine_adaptive;
pub mod repair;
pub mod report;
pub mod report_sections;
pub mod scale;
pub mod subdivide;
