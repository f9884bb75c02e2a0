//! Build script of the `topolab` package: finds OpenMesh (the C++ baseline), compiles the
//! C API shim in `openmesh/` with the `cc` crate at `-O3 -DNDEBUG` (the optimisation of our
//! release code), links it with `libOpenMeshCore`, and sets `cfg(has_openmesh)`.
//!
//! Without OpenMesh (or with `TOPOLAB_NO_OPENMESH=1`, to simulate that) the package builds
//! without the baseline and says how to get it.

use std::path::{Path, PathBuf};

/// How a user gets OpenMesh; printed wherever it is missing.
const HOW_TO_GET: &str = "install it with `apt-get install libopenmesh-dev` (Debian/Ubuntu) \
or `bash .ci/install-deps`, then rebuild";

fn main() {
    println!("cargo::rustc-check-cfg=cfg(has_openmesh)");
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rerun-if-changed=openmesh/shim.cpp");
    println!("cargo::rerun-if-changed=openmesh/shim.h");
    println!("cargo::rerun-if-env-changed=TOPOLAB_NO_OPENMESH");
    if std::env::var_os("TOPOLAB_NO_OPENMESH").is_some_and(|v| !v.is_empty() && v != "0") {
        println!(
            "cargo::warning=TOPOLAB_NO_OPENMESH is set: building without the OpenMesh baseline"
        );
        return;
    }
    match find_openmesh() {
        Some(include_dirs) => compile_shim(&include_dirs),
        None => println!("cargo::warning=OpenMesh not found, building without the OpenMesh baseline: {HOW_TO_GET}"),
    }
}

/// The include directories of OpenMesh when its headers and `libOpenMeshCore` are installed:
/// from pkg-config (which also tells cargo where to link), else from the Debian layout.
fn find_openmesh() -> Option<Vec<PathBuf>> {
    let header = "OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh";
    // Only OpenMeshCore is needed (pkg-config would also link OpenMeshTools).
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
    println!("cargo::rerun-if-changed={}", system.join(header).display());
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

fn compile_shim(include_dirs: &[PathBuf]) {
    let mut build = cc::Build::new();
    build
        .cpp(true)
        .file("openmesh/shim.cpp")
        .include("openmesh")
        .includes(include_dirs)
        .std("c++17")
        .opt_level(3)
        .define("NDEBUG", None)
        // One known warning inside OpenMesh's Property.hh, not in our code.
        .flag_if_supported("-Wno-maybe-uninitialized")
        .warnings(true);
    build.compile("topolab_openmesh_shim");
    println!("cargo::rustc-link-lib=dylib=OpenMeshCore");
    println!("cargo::rustc-cfg=has_openmesh");
}
