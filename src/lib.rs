//! # topolab
//!
//! The lab's command-line tool and everything that ties the crates together: the registry of
//! every structure (the ones of `topolab-structures`, later the OpenMesh baseline) and the
//! commands of the `topolab` binary.
#![deny(missing_docs)]
#![forbid(unsafe_code)]

pub mod check;
pub mod cli;
