//! # topolab-harness
//!
//! The operator catalogue (what each operator takes and answers); timing, memory, fitting and
//! the report build on it.
#![deny(missing_docs)]
#![forbid(unsafe_code)]

pub mod catalogue;
pub mod checksum;
