//! The lab's conformance suite on the OpenMesh baseline (compiled in when OpenMesh is
//! installed; see `docs/fairness.md`).

#[cfg(has_openmesh)]
topolab_structures::conformance!(openmesh, topolab_baselines::openmesh::OpenMesh);

#[cfg(not(has_openmesh))]
mod common;

#[cfg(not(has_openmesh))]
#[test]
fn skipped_openmesh_not_compiled_in() {
    common::report_skip("openmesh conformance", topolab_baselines::OPENMESH_MISSING);
    // Without OpenMesh the registry must not offer it.
    assert!(!topolab_baselines::compiled::COMPILED.contains(&topolab_baselines::compiled::OPENMESH));
}
