//! The lab's conformance suite on CGAL's two halfedge structures (compiled in when CGAL is
//! installed; see `docs/fairness.md`).

#[cfg(has_cgal)]
topolab_structures::conformance!(cgal_surface_mesh, topolab_baselines::cgal::SurfaceMesh);
#[cfg(has_cgal)]
topolab_structures::conformance!(cgal_polyhedron, topolab_baselines::cgal::Polyhedron);

#[cfg(not(has_cgal))]
mod common;

#[cfg(not(has_cgal))]
#[test]
fn skipped_cgal_not_compiled_in() {
    common::report_skip("cgal conformance", topolab_baselines::CGAL_MISSING);
    // Without CGAL the registry must not offer its structures.
    for name in [
        topolab_baselines::compiled::CGAL_SURFACE_MESH,
        topolab_baselines::compiled::CGAL_POLYHEDRON,
    ] {
        assert!(
            !topolab_baselines::compiled::COMPILED.contains(&name),
            "{name}"
        );
    }
}
