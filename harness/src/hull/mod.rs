//! The 3D convex hull algorithms of `topolab_structures::hull` timed against n
//! ([`bench`](mod@bench)), next to the Qhull reference run through SciPy in a Python subprocess
//! ([`qhull`]). Timing and reference runners live here, in the harness, so the structures crate
//! stays free of clocks and subprocesses.

pub mod bench;
pub mod qhull;
