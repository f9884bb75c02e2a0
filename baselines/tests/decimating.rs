//! The decimation suite ([`topolab_structures::testing::decimating`]) on the C++ baselines
//! that offer the vertex split reconstruction needs (OpenMesh and CGAL's two structures,
//! through their own Euler operations): one line each. The Rust crates of `topolab-peers`
//! offer no vertex split (`MeshEdit::supports(EditOp::SplitVertex)` is false for each), so a
//! decimation on them could not be undone: they are not enrolled.

#[cfg(has_openmesh)]
topolab_structures::decimate_conformance!(openmesh, topolab_baselines::openmesh::OpenMesh);
#[cfg(has_cgal)]
topolab_structures::decimate_conformance!(cgal_surface_mesh, topolab_baselines::cgal::SurfaceMesh);
#[cfg(has_cgal)]
topolab_structures::decimate_conformance!(cgal_polyhedron, topolab_baselines::cgal::Polyhedron);

#[cfg(not(all(has_openmesh, has_cgal)))]
mod common;

#[cfg(not(all(has_openmesh, has_cgal)))]
#[test]
fn skipped_a_baseline_not_compiled_in() {
    #[cfg(not(has_openmesh))]
    common::report_skip("openmesh decimation", topolab_baselines::OPENMESH_MISSING);
    #[cfg(not(has_cgal))]
    common::report_skip("cgal decimation", topolab_baselines::CGAL_MISSING);
}
