//! Build script of the `topolab-baselines` package: compiles the baselines (the C++ libraries and their
//! C API shims, and Qhull's C shim) with the `cc` crate at `-O3 -DNDEBUG` (the optimisation of
//! our release code), links them, and sets a cfg per baseline:
//!
//! | baseline | compiled here | links | cfg | off switch |
//! |---|---|---|---|---|
//! | OpenMesh | its Core and the Decimater's `Observer.cc` from the pinned source tree (static), `cpp/openmesh/*.cpp` | nothing more | `has_openmesh` | `TOPOLAB_NO_OPENMESH=1` |
//! | CGAL (header-only) | `cpp/cgal/*.cpp`, one translation unit per piece | `libgmp` (the hull's exact kernel) | `has_cgal` (`has_cgal_decimate` when Eigen is found too) | `TOPOLAB_NO_CGAL=1` |
//! | Qhull (reentrant C library) | `c/qhull/shim.c` | `libqhull_r` | `has_qhull` | `TOPOLAB_NO_QHULL=1` |
//! | the C++ heap counting, with either | `cpp/heap/heap.cpp` (global `operator new` and `delete`) | | `has_cpp_heap` | both of the above |
//!
//! OpenMesh is compiled from its own source, not linked from a system package: Debian's
//! `libopenmesh` is built without `-DNDEBUG`, so every handle step and status lookup of its
//! compiled functions ran an assertion. The source is PyPI's `openmesh` sdist, pinned by
//! version and sha256 in `third_party/sources.toml` and unpacked into the git-ignored
//! `third_party/openmesh/` by `third_party/fetch.py` (which `.ci/install-deps` runs; a build
//! script does not use the network); `TOPOLAB_OPENMESH_SOURCE` may name another OpenMesh
//! source tree (the folder holding `src/OpenMesh/Core`). Its `.cc` files are compiled with the
//! code-generation flags of OpenMesh's own CMake Release build (see [`openmesh_library`]) into
//! a static library, and its headers come from the same tree. The crate gets a description
//! of that build in `TOPOLAB_OPENMESH_BUILD` (the report's machine table shows it).
//!
//! A missing baseline (or one switched off, to simulate that) is left out with a warning that
//! says how to get it; the package builds without it.
//!
//! The translation units compile in parallel, as many at once as cargo's job count: CGAL's
//! are heavy (the hull's alone takes most of 20 s and 0.9 GB), and one at a time they would
//! take the sum of all.

use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// How a user gets OpenMesh's source; printed wherever it is missing.
const OPENMESH_HOW_TO_GET: &str = "fetch the pinned source (PyPI openmesh's sdist, \
third_party/sources.toml) with `bash .ci/install-deps` or `python3 third_party/fetch.py`, or set \
TOPOLAB_OPENMESH_SOURCE to an OpenMesh source tree (the folder holding src/OpenMesh/Core), \
then rebuild";
/// How a user gets CGAL.
const CGAL_HOW_TO_GET: &str = "install it with `apt-get install libcgal-dev` (Debian/Ubuntu) \
or `bash .ci/install-deps`, then rebuild";

/// Where `third_party/fetch.py` unpacks OpenMesh's source, relative to this package (the
/// workspace's `third_party/`, at the repository's root).
const OPENMESH_SOURCE: &str = "../third_party/openmesh";
/// The variable that points the build at another OpenMesh source tree.
const OPENMESH_SOURCE_VARIABLE: &str = "TOPOLAB_OPENMESH_SOURCE";
/// The stamp `third_party/fetch.py` writes into the folder it unpacked: the package it came
/// from (`client`, `package`, `version`, `sha256` lines).
const OPENMESH_STAMP: &str = ".topolab-source";
/// The Tools sources the report's Decimater needs: `BaseDecimaterT` keeps an `Observer`,
/// whose out-of-line members are here. The rest of OpenMeshTools is not used.
const OPENMESH_TOOLS_UNITS: [&str; 1] = ["src/OpenMesh/Tools/Decimater/Observer.cc"];
/// How a user gets Qhull's reentrant library.
const QHULL_HOW_TO_GET: &str = "install it with `apt-get install libqhull-dev` (Debian/Ubuntu) \
or `bash .ci/install-deps`, then rebuild";

/// The translation units of CGAL's shim, the slowest first (so the pool starts it first).
const CGAL_UNITS: [&str; 4] = [
    "cpp/cgal/hull.cpp",
    "cpp/cgal/surface_mesh.cpp",
    "cpp/cgal/polyhedron.cpp",
    "cpp/cgal/shim.cpp",
];

/// The translation units of OpenMesh's shim: building, queries and workloads; the
/// Decimater; `MeshEdit` (its Euler operations behind `cpp/openmesh/edit.h`); its own file
/// readers, for the differential test of the lab's readers.
const OPENMESH_SHIM_UNITS: [&str; 4] = [
    "cpp/openmesh/shim.cpp",
    "cpp/openmesh/decimate.cpp",
    "cpp/openmesh/edit.cpp",
    "cpp/openmesh/read.cpp",
];
// --- issue 18 (phase 2c): the baselines' editing operations, one translation unit each ---
/// CGAL's changing workloads and editing operations (behind `cpp/cgal/edit.h`), one unit per class.
const CGAL_EDIT_UNITS: &[&str] = &[
    "cpp/cgal/edit_surface_mesh.cpp",
    "cpp/cgal/edit_polyhedron.cpp",
];
// --- end of issue 18's block ---

/// One static library compiled here (a shim, OpenMesh itself, or the heap counting): its
/// compiler settings, sources, and what linking it needs.
/// Every loop of the C++ baselines starts on a 64-byte boundary, as every loop of the lab's
/// Rust code does (`-align-loops=64` in `.cargo/config.toml`): where a hot loop lands is
/// otherwise decided by unrelated code, and moved one sweep of the lab by 1.9x
/// (docs/fairness.md).
const LOOP_ALIGNMENT: &str = "-falign-loops=64";

struct Shim {
    /// The static library's name.
    library: &'static str,
    /// Compiler settings shared by its sources.
    build: cc::Build,
    sources: Vec<PathBuf>,
    /// System libraries to link (`cargo::rustc-link-lib=dylib=...`).
    links: Vec<&'static str>,
    /// The cfg it sets, if any (OpenMesh's library leaves that to its shim).
    cfg: Option<&'static str>,
}

fn main() {
    println!("cargo::rustc-check-cfg=cfg(has_openmesh)");
    println!("cargo::rustc-check-cfg=cfg(has_cgal)");
    println!("cargo::rustc-check-cfg=cfg(has_cgal_decimate)");
    println!("cargo::rustc-check-cfg=cfg(has_cpp_heap)");
    println!("cargo::rustc-check-cfg=cfg(has_qhull)");
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rerun-if-changed=cpp/openmesh");
    println!("cargo::rerun-if-changed=cpp/cgal");
    println!("cargo::rerun-if-changed=cpp/heap");
    println!("cargo::rerun-if-changed=cpp/common");
    println!("cargo::rerun-if-changed=c/qhull");
    println!("cargo::rerun-if-env-changed={OPENMESH_SOURCE_VARIABLE}");
    // The libraries in the order their sources are compiled (CGAL's first: the slowest) and
    // linked (each shim before the library it calls; the heap counting, which every C++ unit
    // calls through operator new, after the C++ ones).
    let mut shims = Vec::new();
    if switched_off("TOPOLAB_NO_CGAL", "the CGAL baselines") {
    } else if let Some(include_dir) = find_cgal() {
        shims.push(cgal_shim(&include_dir));
    } else {
        println!(
            "cargo::warning=CGAL not found, building without the CGAL baselines: {CGAL_HOW_TO_GET}"
        );
    }
    if switched_off("TOPOLAB_NO_OPENMESH", "the OpenMesh baseline") {
    } else {
        match find_openmesh() {
            Ok(source) => {
                shims.push(openmesh_shim(&source));
                shims.push(openmesh_library(&source));
                println!(
                    "cargo::rustc-env=TOPOLAB_OPENMESH_BUILD={}",
                    openmesh_description(&source)
                );
            }
            Err(missing) => println!(
                "cargo::warning=OpenMesh's source not found ({missing}), building without the OpenMesh baseline: {OPENMESH_HOW_TO_GET}"
            ),
        }
    }
    if !shims.is_empty() {
        shims.push(heap_library());
    }
    if switched_off("TOPOLAB_NO_QHULL", "the in-process Qhull") {
    } else if let Some(include_dirs) = find_qhull() {
        shims.push(qhull_shim(&include_dirs));
    } else {
        println!("cargo::warning=Qhull's reentrant library not found, building without the in-process Qhull (the report's hull section then has no Qhull): {QHULL_HOW_TO_GET}");
    }
    let objects = compile_in_parallel(&shims);
    let mut cfgs: Vec<&str> = shims.iter().filter_map(|s| s.cfg).collect();
    for (shim, objects) in shims.iter().zip(objects) {
        cc::Build::new()
            .cpp(true)
            .objects(objects)
            .compile(shim.library);
        for link in &shim.links {
            println!("cargo::rustc-link-lib=dylib={link}");
        }
        if let Some(cfg) = shim.cfg {
            println!("cargo::rustc-cfg={cfg}");
        }
    }
    if CGAL_DECIMATE.load(std::sync::atomic::Ordering::Relaxed) {
        cfgs.push("has_cgal_decimate");
    }
    // For the build scripts of the crates above (`links`): the same cfgs, comma-separated.
    println!("cargo::metadata=cfgs={}", cfgs.join(","));
}

/// Whether `cgal_shim` compiled CGAL's decimater (Eigen was found).
static CGAL_DECIMATE: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

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
    let queue: Mutex<Vec<(usize, &Path)>> = Mutex::new(
        shims
            .iter()
            .enumerate()
            .flat_map(|(i, s)| s.sources.iter().map(move |f| (i, f.as_path())))
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
                let objects = shims[i]
                    .build
                    .clone()
                    .flag(LOOP_ALIGNMENT)
                    .file(source)
                    .compile_intermediates();
                results.lock().expect("results")[i].extend(objects);
            });
        }
    });
    results.into_inner().expect("results")
}

/// An OpenMesh source tree: the folder holding `src/OpenMesh/Core`.
struct OpenMeshSource {
    root: PathBuf,
    /// Whether it is the fetched tree (else `TOPOLAB_OPENMESH_SOURCE`'s).
    fetched: bool,
}

/// The OpenMesh source tree to compile: `TOPOLAB_OPENMESH_SOURCE` if set (relative to the
/// repository's root, where the lab's commands run), else `third_party/openmesh`; or why there
/// is none.
fn find_openmesh() -> Result<OpenMeshSource, String> {
    let package = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").unwrap_or_default());
    let (root, fetched) = match std::env::var_os(OPENMESH_SOURCE_VARIABLE) {
        Some(dir) if !dir.is_empty() => (package.join("..").join(dir), false),
        _ => (package.join(OPENMESH_SOURCE), true),
    };
    // Rerun when the tree changes (cargo scans a folder's files) or appears (its parent
    // changes); never a path that does not exist (see `watch_for`), nor a folder further up,
    // which cargo would scan whole.
    if let Some(watched) = [root.as_path(), root.parent().unwrap_or(&root)]
        .into_iter()
        .find(|d| d.is_dir())
    {
        println!("cargo::rerun-if-changed={}", watched.display());
    }
    let probe = "src/OpenMesh/Core/Mesh/PolyConnectivity.cc";
    if !root.join(probe).is_file() {
        let by = if fetched {
            String::new()
        } else {
            format!(", {OPENMESH_SOURCE_VARIABLE}")
        };
        return Err(format!("no {probe} in {}{by}", root.display()));
    }
    Ok(OpenMeshSource { root, fetched })
}

/// The `.cc` files under `dir`, recursively, sorted (so the build is the same on every
/// machine).
fn cc_files(dir: &Path) -> Vec<PathBuf> {
    let mut found = Vec::new();
    let mut folders = vec![dir.to_path_buf()];
    while let Some(folder) = folders.pop() {
        let Ok(entries) = std::fs::read_dir(&folder) else {
            continue;
        };
        for path in entries.filter_map(|e| e.ok()).map(|e| e.path()) {
            if path.is_dir() {
                folders.push(path);
            } else if path.extension().is_some_and(|e| e == "cc") {
                found.push(path);
            }
        }
    }
    found.sort();
    found
}

/// OpenMesh's library, compiled as its own CMake Release build compiles it (OpenMesh's
/// `CMakeLists.txt`: C++11 with GNU extensions, `CMAKE_CXX_STANDARD 11`; CMake's Release flags
/// `-O3 -DNDEBUG`; `cmake-library/VCI/VCICompiler.cmake`: `-DNDEBUG`, `-DINCLUDE_TEMPLATES`;
/// position-independent, as PyPI's openmesh builds it), and static, as PyPI's openmesh links
/// it (`OpenMeshCoreStatic`). Its warning flags are left out, so that the warnings of its
/// code are not printed as ours; they do not change the code. The sources: every `.cc` of
/// its Core (the `OpenMeshCore` library: the mesh kernel and connectivity, its I/O, streams
/// and properties), and of its Tools only what the report's Decimater calls.
fn openmesh_library(source: &OpenMeshSource) -> Shim {
    let mut build = cc::Build::new();
    build
        .cpp(true)
        .include(source.root.join("src"))
        .std("gnu++11")
        .opt_level(3)
        .define("NDEBUG", None)
        .define("INCLUDE_TEMPLATES", None)
        .pic(true)
        .warnings(false);
    let mut sources = cc_files(&source.root.join("src/OpenMesh/Core"));
    sources.extend(OPENMESH_TOOLS_UNITS.iter().map(|f| source.root.join(f)));
    Shim {
        library: "topolab_openmesh",
        build,
        sources,
        links: Vec::new(),
        cfg: None,
    }
}

/// What the report says of the OpenMesh it measures: its version (`OM_VERSION` of its
/// `config.h`), where its source came from, and how it was compiled here.
fn openmesh_description(source: &OpenMeshSource) -> String {
    let config = source.root.join("src/OpenMesh/Core/System/config.h");
    let version = std::fs::read_to_string(config)
        .ok()
        .and_then(|text| om_version(&text))
        .unwrap_or_else(|| "(version unknown)".into());
    let stamp = std::fs::read_to_string(source.root.join(OPENMESH_STAMP)).unwrap_or_default();
    let field = |key: &str| {
        stamp.lines().find_map(|line| {
            let (k, v) = line.split_once('=')?;
            (k.trim() == key).then(|| v.trim().trim_matches('"').to_string())
        })
    };
    let origin = match (
        field("client").as_deref(),
        field("package"),
        field("version"),
    ) {
        (Some("pip"), Some(package), Some(v)) => format!("PyPI {package} {v}'s source"),
        (Some(client), Some(package), Some(v)) => format!("{client} {package} {v}'s source"),
        _ if source.fetched => format!("the source in {OPENMESH_SOURCE}"),
        _ => format!(
            "the source tree {} ({OPENMESH_SOURCE_VARIABLE})",
            source.root.display()
        ),
    };
    format!(
        "OpenMesh {version}, compiled here from {origin}: its Core and the Decimater's \
         Observer as a static library, -std=gnu++11 -O3 -DNDEBUG (its CMake Release build's \
         flags)"
    )
}

/// The version `major.minor.patch` of `#define OM_VERSION 0x90100` in OpenMesh's `config.h`
/// (one hex digit of major, two each of minor and patch, as its `OM_GET_*` macros read it).
fn om_version(config_h: &str) -> Option<String> {
    let hex = config_h.lines().find_map(|line| {
        let mut words = line.split_whitespace();
        (words.next()? == "#define" && words.next()? == "OM_VERSION")
            .then(|| words.next())
            .flatten()
    })?;
    let v = u32::from_str_radix(hex.strip_prefix("0x")?, 16).ok()?;
    Some(format!(
        "{}.{}.{}",
        (v & 0xf0000) >> 16,
        (v & 0x0ff00) >> 8,
        v & 0xff
    ))
}

/// The shim over OpenMesh, compiled against the headers of the same source tree. They are a
/// system include folder for the compiler, as an installed OpenMesh's would be: warnings are
/// reported of our code, not of OpenMesh's headers.
fn openmesh_shim(source: &OpenMeshSource) -> Shim {
    let mut build = cc::Build::new();
    build
        .cpp(true)
        .include("cpp/openmesh")
        .flag("-isystem")
        .flag(source.root.join("src").display().to_string())
        .std("c++17")
        .opt_level(3)
        .define("NDEBUG", None)
        // One known warning inside OpenMesh's Property.hh (PropertyT::push_back), reported at
        // the standard library's line it inlines into, not in our code.
        .flag_if_supported("-Wno-maybe-uninitialized")
        .warnings(true);
    Shim {
        library: "topolab_openmesh_shim",
        build,
        sources: OPENMESH_SHIM_UNITS.iter().map(PathBuf::from).collect(),
        links: Vec::new(),
        cfg: Some("has_openmesh"),
    }
}

/// The C++ side of the heap counting (`cpp/heap/heap.cpp`: the global `operator new` and `delete`,
/// counting like `topolab-alloc`), linked whenever a baseline is: a library of its own, because a
/// program defines those functions once and each baseline's shim is a separate library. Last in
/// the list, so that it follows the shims that call `operator new` on the linker's line.
fn heap_library() -> Shim {
    let mut build = cc::Build::new();
    build
        .cpp(true)
        .include("cpp/heap")
        .std("c++17")
        .opt_level(3)
        .define("NDEBUG", None)
        .warnings(true);
    Shim {
        library: "topolab_heap",
        build,
        sources: vec!["cpp/heap/heap.cpp".into()],
        links: Vec::new(),
        cfg: Some("has_cpp_heap"),
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
        .include("cpp/cgal")
        .include(include_dir)
        .std("c++17")
        .opt_level(3)
        .define("NDEBUG", None)
        .warnings(true);
    let mut sources = CGAL_UNITS.to_vec();
    // The Garland-Heckbert policies of cpp/cgal/decimate.cpp need Eigen (libeigen3-dev): without
    // it the CGAL decimater is left out and the report says so.
    let eigen = Path::new("/usr/include/eigen3");
    watch_for(&[PathBuf::from("/usr/include")], "eigen3/Eigen/Core");
    if eigen.join("Eigen/Core").exists() {
        build
            .flag("-isystem")
            .flag(eigen.to_str().unwrap_or("/usr/include/eigen3"));
        sources.insert(0, "cpp/cgal/decimate.cpp");
        println!("cargo::rustc-cfg=has_cgal_decimate");
        CGAL_DECIMATE.store(true, std::sync::atomic::Ordering::Relaxed);
    } else {
        println!("cargo::warning=Eigen not found, building without CGAL's decimater: apt-get install libeigen3-dev");
    }
    Shim {
        library: "topolab_cgal_shim",
        build,
        sources: [&sources[..], CGAL_EDIT_UNITS]
            .concat()
            .into_iter()
            .map(PathBuf::from)
            .collect(),
        // The hull's Exact_predicates_inexact_constructions_kernel falls back to GMP's exact
        // rationals (CGAL uses GMP whenever its header is found; no MPFR function is used).
        links: vec!["gmp"],
        cfg: Some("has_cgal"),
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
        .include("c/qhull")
        .includes(include_dirs)
        .std("c11")
        .opt_level(3)
        .define("NDEBUG", None)
        .warnings(true);
    Shim {
        library: "topolab_qhull_shim",
        build,
        sources: vec!["c/qhull/shim.c".into()],
        links: vec!["qhull_r"],
        cfg: Some("has_qhull"),
    }
}
