//! The 3D convex hull algorithms of `topolab_structures::hull` timed against n
//! ([`bench`](mod@bench)), and SciPy's Qhull run in a Python subprocess ([`qhull`]), the tests'
//! correctness reference. (The report times Qhull in-process, through its C library, and CGAL's
//! `convex_hull_3`: [`outside`] adds their rows, from `topolab-baselines`' plain results.) Timing and reference
//! runners live here, in the harness, so the structures crate stays free of clocks and
//! subprocesses.

pub mod bench;
pub mod outside;
pub mod qhull;
pub mod rows;
