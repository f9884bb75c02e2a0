//! The lab's conformance suite on CGAL's two halfedge structures (compiled in when CGAL is
//! installed; see README.md).

#[cfg(has_cgal)]
topolab_structures::conformance!(cgal_surface_mesh, topolab::cgal::SurfaceMesh);
#[cfg(has_cgal)]
topolab_structures::conformance!(cgal_polyhedron, topolab::cgal::Polyhedron);

#[cfg(not(has_cgal))]
mod common;

#[cfg(not(has_cgal))]
#[test]
fn skipped_cgal_not_compiled_in() {
    common::report_skip("cgal conformance", topolab::CGAL_MISSING);
    // Without CGAL the registry must not offer its structures.
    for name in [
        topolab::registry::CGAL_SURFACE_MESH,
        topolab::registry::CGAL_POLYHEDRON,
    ] {
        assert!(!topolab::registry::NAMES.contains(&name), "{name}");
    }
}
