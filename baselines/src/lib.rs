//! # topolab-baselines
//!
//! The lab's outside baselines, each behind a safe wrapper of its C or C++ API: OpenMesh
//! ([`openmesh`]) and CGAL ([`cgal`]) when compiled in, named and visited by name in
//! [`compiled`] (the registry of every structure, `topolab-registry`, chains them after the
//! lab's own), and Qhull ([`qhull`]), in-process, for the hull section. `build.rs` compiles them (their sources are
//! under `cpp/` and `c/`) and sets one cfg per baseline; the consts below tell the crates
//! above what this build has, so that they need no cfg to ask.
//!
//! Results come back plain (ids, counts, checksums, times): the harness builds its rows from
//! them, so this crate depends on the structures and the allocator only.
#![deny(missing_docs)]
// Only the FFI modules (C++ and Qhull's C) may use `unsafe` (each allows it for itself alone).
#![deny(unsafe_code)]

#[cfg(has_cgal)]
#[allow(unsafe_code)]
pub mod cgal;
pub mod compiled;
#[cfg(any(has_openmesh, has_cgal))]
#[allow(unsafe_code)]
mod foreign;
#[allow(unsafe_code)]
pub mod heap;
pub mod hulls;
#[allow(unsafe_code)]
pub mod native_decimate;
#[cfg(has_openmesh)]
#[allow(unsafe_code)]
pub mod openmesh;
#[cfg(has_qhull)]
#[allow(unsafe_code)]
pub mod qhull;

/// What to do when the OpenMesh baseline is not compiled in (OpenMesh's source was missing at
/// build time, or `TOPOLAB_NO_OPENMESH=1` was set).
pub const OPENMESH_MISSING: &str = "the OpenMesh baseline is not compiled in: fetch OpenMesh's \
pinned source (`bash .ci/install-deps`, or `python3 third_party/fetch.py`; the baselines' \
build.rs compiles it), unset TOPOLAB_NO_OPENMESH, and rebuild";

/// The OpenMesh this build measures: its version, where its source came from and how
/// `build.rs` compiled it (e.g. `OpenMesh 9.1.0, compiled here from PyPI openmesh 1.2.1's
/// source: ...`); `None` when the baseline is not compiled in.
pub const OPENMESH_BUILD: Option<&str> = if HAS_OPENMESH {
    option_env!("TOPOLAB_OPENMESH_BUILD")
} else {
    // Not a variable of someone's shell that happens to have the name.
    None
};

/// [`OPENMESH_BUILD`], or why this build has no OpenMesh: the line a run's Machine block shows.
pub fn openmesh_description() -> String {
    OPENMESH_BUILD
        .map(str::to_string)
        .unwrap_or_else(|| format!("not in this build: {OPENMESH_MISSING}"))
}

/// `true` when this build includes the OpenMesh baseline.
pub const HAS_OPENMESH: bool = cfg!(has_openmesh);

/// What to do when the CGAL baselines are not compiled in (CGAL was missing at build time, or
/// `TOPOLAB_NO_CGAL=1` was set).
pub const CGAL_MISSING: &str = "the CGAL baselines (cgal-surface-mesh, cgal-polyhedron, \
convex_hull_3) are not compiled in: install CGAL (`apt-get install libcgal-dev` on \
Debian/Ubuntu, or `bash .ci/install-deps`), unset TOPOLAB_NO_CGAL, and rebuild";

/// `true` when this build includes the CGAL baselines.
pub const HAS_CGAL: bool = cfg!(has_cgal);

/// `true` when this build includes CGAL's decimater (CGAL and Eigen were found).
pub const HAS_CGAL_DECIMATE: bool = cfg!(has_cgal_decimate);

/// What to do when the in-process Qhull is not compiled in (Qhull's reentrant library was
/// missing at build time, or `TOPOLAB_NO_QHULL=1` was set): the report's hull section then has
/// no Qhull.
pub const QHULL_MISSING: &str = "the in-process Qhull is not compiled in: install Qhull's \
reentrant library (`apt-get install libqhull-dev` on Debian/Ubuntu, or `bash .ci/install-deps`), \
unset TOPOLAB_NO_QHULL, and rebuild";

/// `true` when this build includes the in-process Qhull.
pub const HAS_QHULL: bool = cfg!(has_qhull);

/// `true` when the C++ heap counting is linked (with any C++ baseline): see [`heap`].
pub const HAS_CPP_HEAP: bool = cfg!(has_cpp_heap);
