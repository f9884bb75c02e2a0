//! The editing suite ([`topolab_structures::testing::editing`]) on the C++ baselines that edit
//! through their own Euler operations: one line each. Each structure's tests run in parallel
//! threads on independent meshes, as the conformance tests do (the shims' one process-wide
//! set-up is thread-safe: `tests/openmesh_threads.rs`, `tests/cgal_threads.rs`).

#[cfg(has_openmesh)]
topolab_structures::edit_conformance!(
    openmesh,
    topolab::openmesh::OpenMesh,
    not_implemented_on_polygons
);

#[cfg(has_cgal)]
topolab_structures::edit_conformance!(cgal_surface_mesh, topolab::cgal::SurfaceMesh);

#[cfg(has_cgal)]
topolab_structures::edit_conformance!(cgal_polyhedron, topolab::cgal::Polyhedron);

#[cfg(not(any(has_openmesh, has_cgal)))]
mod common;

#[cfg(not(any(has_openmesh, has_cgal)))]
#[test]
fn skipped_no_baseline_compiled_in() {
    common::report_skip("foreign editing", topolab::OPENMESH_MISSING);
    assert!(!topolab::registry::NAMES.contains(&topolab::registry::OPENMESH));
}
