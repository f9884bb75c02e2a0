//! Build script of the `topolab` package: finds the baselines (C++ libraries, and Qhull's C
//! library), compiles their C API shims with the `cc` crate at `-O3 -DNDEBUG` (the
//! optimisation of our release code), links them, and sets a cfg per baseline:
//!
//! | baseline | shim | links | cfg | off switch |
//! |---|---|---|---|---|
//! | OpenMesh | `openmesh/shim.cpp`, `openmesh/decimate.cpp` | `libOpenMeshCore` | `has_openmesh` | `TOPOLAB_NO_OPENMESH=1` |
//! | CGAL (header-only) | `cgal/*.cpp`, one translation unit per piece | `libgmp` (the hull's exact kernel) | `has_cgal` (`has_cgal_decimate` when Eigen is found too) | `TOPOLAB_NO_CGAL=1` |
//! | Qhull (reentrant C library) | `qhull/shim.c` | `libqhull_r` | `has_qhull` | `TOPOLAB_NO_QHULL=1` |
//!
//! A missing baseline (or one switched off, to simulate that) is left out with a warning that
//! says how to get it; the package builds without it.
//!
//! The translation units compile in parallel, as many at once as cargo's job count: CGAL's
//! are heavy (the hull's alone takes most of 20 s and 0.9 GB), and one at a time they would
//! take the sum of all.

use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// How a user gets OpenMesh; printed wherever it is missing.
const OPENMESH_HOW_TO_GET: &str = "install it with `apt-get install libopenmesh-dev` \
(Debian/Ubuntu) or `bash .ci/install-deps`, then rebuild";
/// How a user gets CGAL.
const CGAL_HOW_TO_GET: &str = "install it with `apt-get install libcgal-dev` (Debian/Ubuntu) \
or `bash .ci/install-deps`, then rebuild";

/// How a user gets Qhull's reentrant library.
const QHULL_HOW_TO_GET: &str = "install it with `apt-get install libqhull-dev` (Debian/Ubuntu) \
or `bash .ci/install-deps`, then rebuild";

/// The translation units of CGAL's shim, the slowest first (so the pool starts it first).
const CGAL_UNITS: [&str; 4] = [
    "cgal/hull.cpp",
    "cgal/surface_mesh.cpp",
    "cgal/polyhedron.cpp",
    "cgal/shim.cpp",
];

// --- issue 18 (phase 2c): the baselines' editing operations, one translation unit each ---
/// OpenMesh's `MeshEdit` (its Euler operations behind `openmesh/edit.h`).
const OPENMESH_EDIT_UNITS: &[&str] = &["openmesh/edit.cpp"];
/// CGAL's changing workloads and editing operations (behind `cgal/edit.h`), one unit per class.
const CGAL_EDIT_UNITS: &[&str] = &["cgal/edit_surface_mesh.cpp", "cgal/edit_polyhedron.cpp"];
// --- end of issue 18's block ---

/// One shim library: its compiler settings, sources, and what linking it needs.
struct Shim {
    /// The static library's name.
    library: &'static str,
    /// Compiler settings shared by its sources.
    build: cc::Build,
    sources: Vec<&'static str>,
    /// Libraries to link (`cargo::rustc-link-lib=dylib=...`).
    links: Vec<&'static str>,
    /// The cfg it sets.
    cfg: &'static str,
}

fn main() {
    println!("cargo::rustc-check-cfg=cfg(has_openmesh)");
    println!("cargo::rustc-check-cfg=cfg(has_cgal)");
    println!("cargo::rustc-check-cfg=cfg(has_cgal_decimate)");
    println!("cargo::rustc-check-cfg=cfg(has_qhull)");
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rerun-if-changed=openmesh");
    println!("cargo::rerun-if-changed=cgal");
    println!("cargo::rerun-if-changed=qhull");
    let mut shims = Vec::new();
    if switched_off("TOPOLAB_NO_OPENMESH", "the OpenMesh baseline") {
    } else if let Some(include_dirs) = find_openmesh() {
        shims.push(openmesh_shim(&include_dirs));
    } else {
        println!("cargo::warning=OpenMesh not found, building without the OpenMesh baseline: {OPENMESH_HOW_TO_GET}");
    }
    if switched_off("TOPOLAB_NO_CGAL", "the CGAL baselines") {
    } else if let Some(include_dir) = find_cgal() {
        shims.push(cgal_shim(&include_dir));
    } else {
        println!(
            "cargo::warning=CGAL not found, building without the CGAL baselines: {CGAL_HOW_TO_GET}"
        );
    }
    if switched_off("TOPOLAB_NO_QHULL", "the in-process Qhull") {
    } else if let Some(include_dirs) = find_qhull() {
        shims.push(qhull_shim(&include_dirs));
    } else {
        println!("cargo::warning=Qhull's reentrant library not found, building without the in-process Qhull (the report's hull section then has no Qhull): {QHULL_HOW_TO_GET}");
    }
    let objects = compile_in_parallel(&shims);
    for (shim, objects) in shims.iter().zip(objects) {
        cc::Build::new()
            .cpp(true)
            .objects(objects)
            .compile(shim.library);
        for link in &shim.links {
            println!("cargo::rustc-link-lib=dylib={link}");
        }
        println!("cargo::rustc-cfg={}", shim.cfg);
    }
}

/// `true` (with a warning) when `variable` is set to switch `what` off.
fn switched_off(variable: &str, what: &str) -> bool {
    println!("cargo::rerun-if-env-changed={variable}");
    let off = std::env::var_os(variable).is_some_and(|v| !v.is_empty() && v != "0");
    if off {
        println!("cargo::warning={variable} is set: building without {what}");
    }
    off
}

/// Compiles every source of every shim, each in its own compiler process, at most cargo's job
/// count at a time; returns the object files per shim, in `shims` order. Panics (failing the
/// build with the compiler's message) when a source does not compile.
fn compile_in_parallel(shims: &[Shim]) -> Vec<Vec<PathBuf>> {
    let queue: Mutex<Vec<(usize, &'static str)>> = Mutex::new(
        shims
            .iter()
            .enumerate()
            .flat_map(|(i, s)| s.sources.iter().map(move |&f| (i, f)))
            .rev()
            .collect(),
    );
    let results: Mutex<Vec<Vec<PathBuf>>> = Mutex::new(vec![Vec::new(); shims.len()]);
    let jobs = std::env::var("NUM_JOBS")
        .ok()
        .and_then(|n| n.parse::<usize>().ok())
        .unwrap_or(1)
        .max(1);
    std::thread::scope(|scope| {
        for _ in 0..jobs {
            scope.spawn(|| loop {
                let Some((i, source)) = queue.lock().expect("queue").pop() else {
                    return;
                };
                let objects = shims[i].build.clone().file(source).compile_intermediates();
                results.lock().expect("results")[i].extend(objects);
            });
        }
    });
    results.into_inner().expect("results")
}

/// The include directories of OpenMesh when its headers and `libOpenMeshCore` are installed:
/// from pkg-config (which also tells cargo where to link), else from the Debian layout.
fn find_openmesh() -> Option<Vec<PathBuf>> {
    let header = "OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh";
    // The libraries to link are openmesh_shim's (pkg-config's list is not used).
    if let Ok(lib) = pkg_config::Config::new()
        .cargo_metadata(false)
        .env_metadata(true)
        .probe("openmesh")
    {
        let mut dirs = lib.include_paths.clone();
        dirs.push(PathBuf::from("/usr/include"));
        if dirs.iter().any(|d| d.join(header).exists()) {
            for dir in &lib.link_paths {
                println!("cargo::rustc-link-search=native={}", dir.display());
            }
            return Some(lib.include_paths);
        }
    }
    let system = Path::new("/usr/include");
    watch_for(&[system.to_path_buf()], header);
    let library = [
        "/usr/lib/x86_64-linux-gnu",
        "/usr/lib64",
        "/usr/lib",
        "/usr/local/lib",
    ]
    .iter()
    .find(|d| Path::new(d).join("libOpenMeshCore.so").exists())?;
    if !system.join(header).exists() {
        return None;
    }
    println!("cargo::rustc-link-search=native={library}");
    Some(Vec::new())
}

fn openmesh_shim(include_dirs: &[PathBuf]) -> Shim {
    let mut build = cc::Build::new();
    build
        .cpp(true)
        .include("openmesh")
        .includes(include_dirs)
        .std("c++17")
        .opt_level(3)
        .define("NDEBUG", None)
        // One known warning inside OpenMesh's Property.hh, not in our code.
        .flag_if_supported("-Wno-maybe-uninitialized")
        .warnings(true);
    Shim {
        library: "topolab_openmesh_shim",
        build,
        sources: [
            &["openmesh/shim.cpp", "openmesh/decimate.cpp"][..],
            OPENMESH_EDIT_UNITS,
        ]
        .concat(),
        // OpenMeshTools: the Decimater's observer (openmesh/decimate.cpp).
        links: vec!["OpenMeshCore", "OpenMeshTools"],
        cfg: "has_openmesh",
    }
}

/// The include directory holding `CGAL/Surface_mesh.h` (CGAL 5 is header-only; it has no
/// pkg-config file): `CGAL_INCLUDE_DIR` if set, else the usual system directories. Its
/// dependencies (Boost, GMP) come with Debian's libcgal-dev.
fn find_cgal() -> Option<PathBuf> {
    println!("cargo::rerun-if-env-changed=CGAL_INCLUDE_DIR");
    let header = "CGAL/Surface_mesh.h";
    let candidates: Vec<PathBuf> = match std::env::var_os("CGAL_INCLUDE_DIR") {
        Some(dir) => vec![PathBuf::from(dir)],
        None => vec!["/usr/include".into(), "/usr/local/include".into()],
    };
    watch_for(&candidates, header);
    candidates.into_iter().find(|d| d.join(header).exists())
}

/// Has cargo rerun this script when `header` appears in (or changes in) one of `dirs`: the
/// header itself where it exists, else each directory that exists (installing the library
/// changes it). Never a path that does not exist: cargo would rerun the script, and recompile
/// every shim, on every build.
fn watch_for(dirs: &[PathBuf], header: &str) {
    match dirs.iter().map(|d| d.join(header)).find(|h| h.exists()) {
        Some(found) => println!("cargo::rerun-if-changed={}", found.display()),
        None => {
            for dir in dirs.iter().filter(|d| d.is_dir()) {
                println!("cargo::rerun-if-changed={}", dir.display());
            }
        }
    }
}

fn cgal_shim(include_dir: &Path) -> Shim {
    let mut build = cc::Build::new();
    build
        .cpp(true)
        .include("cgal")
        .include(include_dir)
        .std("c++17")
        .opt_level(3)
        .define("NDEBUG", None)
        .warnings(true);
    let mut sources = CGAL_UNITS.to_vec();
    // The Garland-Heckbert policies of cgal/decimate.cpp need Eigen (libeigen3-dev): without
    // it the CGAL decimater is left out and the report says so.
    let eigen = Path::new("/usr/include/eigen3");
    watch_for(&[PathBuf::from("/usr/include")], "eigen3/Eigen/Core");
    if eigen.join("Eigen/Core").exists() {
        build
            .flag("-isystem")
            .flag(eigen.to_str().unwrap_or("/usr/include/eigen3"));
        sources.insert(0, "cgal/decimate.cpp");
        println!("cargo::rustc-cfg=has_cgal_decimate");
    } else {
        println!("cargo::warning=Eigen not found, building without CGAL's decimater: apt-get install libeigen3-dev");
    }
    Shim {
        library: "topolab_cgal_shim",
        build,
        sources: [&sources[..], CGAL_EDIT_UNITS].concat(),
        // The hull's Exact_predicates_inexact_constructions_kernel falls back to GMP's exact
        // rationals (CGAL uses GMP whenever its header is found; no MPFR function is used).
        links: vec!["gmp"],
        cfg: "has_cgal",
    }
}

/// The include directories of Qhull's reentrant library (`libqhull_r/libqhull_r.h`) when it is
/// installed with its pkg-config file `qhull_r` (Debian's libqhull-dev has it), which also says
/// where to link from.
fn find_qhull() -> Option<Vec<PathBuf>> {
    let header = "libqhull_r/libqhull_r.h";
    let library = pkg_config::Config::new()
        .cargo_metadata(false)
        .env_metadata(true)
        .probe("qhull_r");
    let mut dirs = library
        .as_ref()
        .map(|l| l.include_paths.clone())
        .unwrap_or_default();
    dirs.push(PathBuf::from("/usr/include"));
    watch_for(&dirs, header);
    let library = library.ok()?;
    if !dirs.iter().any(|d| d.join(header).exists()) {
        return None;
    }
    for dir in &library.link_paths {
        println!("cargo::rustc-link-search=native={}", dir.display());
    }
    Some(library.include_paths)
}

/// The shim over `libqhull_r`: C, because Qhull leaves an error by `longjmp`, which would skip
/// C++ destructors.
fn qhull_shim(include_dirs: &[PathBuf]) -> Shim {
    let mut build = cc::Build::new();
    build
        .include("qhull")
        .includes(include_dirs)
        .std("c11")
        .opt_level(3)
        .define("NDEBUG", None)
        .warnings(true);
    Shim {
        library: "topolab_qhull_shim",
        build,
        sources: vec!["qhull/shim.c"],
        links: vec!["qhull_r"],
        cfg: "has_qhull",
    }
}
