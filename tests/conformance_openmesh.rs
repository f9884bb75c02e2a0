//! The lab's conformance suite on the OpenMesh baseline (compiled in when OpenMesh is
//! installed; see README.md).

#[cfg(has_openmesh)]
topolab_structures::conformance!(openmesh, topolab::openmesh::OpenMesh);

#[cfg(not(has_openmesh))]
#[test]
fn openmesh_conformance_skipped() {
    eprintln!(
        "SKIPPED openmesh conformance: {}",
        topolab::OPENMESH_MISSING
    );
    assert!(!topolab::HAS_OPENMESH);
}
