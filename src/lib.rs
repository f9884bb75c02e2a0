//! # topolab
//!
//! The lab's command-line tool and everything that ties the crates together: the registry of
//! every structure (the ones of `topolab-structures`, later the OpenMesh baseline) and the
//! commands of the `topolab` binary.
#![deny(missing_docs)]
#![forbid(unsafe_code)]

pub mod cli;
pub mod hull;
pub mod report;

/// The process's allocator, counting bytes so the report can measure each structure's heap
/// (current and peak). The counters add two atomic operations to every allocation.
#[global_allocator]
pub static ALLOCATOR: peak_alloc::PeakAlloc = peak_alloc::PeakAlloc;
