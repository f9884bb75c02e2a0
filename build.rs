//! Build script of the `topolab` package: finds OpenMesh for the baseline (a later step
//! compiles the C++ shim here). For now it only sets `cfg(has_openmesh)` when the headers and
//! library are installed, and says so.

fn main() {
    println!("cargo::rustc-check-cfg=cfg(has_openmesh)");
    println!("cargo::rerun-if-changed=build.rs");
    let header = std::path::Path::new("/usr/include/OpenMesh/Core/Mesh/TriMeshT.hh");
    println!("cargo::rerun-if-changed={}", header.display());
    if header.exists() {
        println!("cargo::rustc-cfg=has_openmesh");
    }
}
