//! # topolab
//!
//! The lab's command-line tool: the commands of the `topolab` binary ([`cli`] parses them,
//! [`commands`] runs them, with the helpers of [`input`], [`limits`] and [`output`]) over the
//! registry of every structure of `topolab-baselines` (the ones of `topolab-structures` plus
//! the C++ baselines OpenMesh and CGAL, when compiled in; Qhull, in-process, for the hull
//! section); [`extend`] runs the report with structures of other crates added. It declares
//! the process's counting allocator ([`ALLOCATOR`]).
#![deny(missing_docs)]
// The FFI and the allocator, the only `unsafe` code, are in the crates below.
#![forbid(unsafe_code)]

pub mod cli;
pub mod commands;
pub mod extend;
pub mod failure;
pub mod input;
pub mod limits;
pub mod output;

// The crates below, under the names the commands and the examples use.
pub use topolab_alloc as alloc;
#[cfg(has_cgal)]
pub use topolab_baselines::cgal;
#[cfg(has_openmesh)]
pub use topolab_baselines::openmesh;
#[cfg(has_qhull)]
pub use topolab_baselines::qhull;
pub use topolab_baselines::{
    native_decimate, CGAL_MISSING, HAS_CGAL, HAS_OPENMESH, HAS_QHULL, OPENMESH_BUILD,
    OPENMESH_MISSING, QHULL_MISSING,
};
pub use topolab_registry as registry;

/// The process's allocator: glibc's, counting a thread's bytes, Rust's and the C++ baselines',
/// only while the report measures a structure's heap (see [`alloc`]).
#[global_allocator]
pub static ALLOCATOR: alloc::CountingAllocator =
    alloc::CountingAllocator::with_foreign(topolab_baselines::heap::CPP_HEAP);
