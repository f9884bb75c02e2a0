//! The lab's conformance suite on every peer: each canonical mesh and random meshes against
//! the oracle, refusals included (one line per structure, as the baselines enrol).

topolab_structures::conformance!(lox_half_edge, topolab_peers::LoxHalfEdge);
topolab_structures::conformance!(lox_directed_edge, topolab_peers::LoxDirectedEdge);
topolab_structures::conformance!(baby_shark_corner_table, topolab_peers::BabySharkCornerTable);
topolab_structures::conformance!(tri_mesh, topolab_peers::TriMesh);

/// The lines above enrol exactly the peers the registry shows: a peer added to
/// `topolab_peers::NAMES` without its line here fails.
#[test]
fn every_peer_is_conformance_tested() {
    use topolab_structures::MeshTopology;
    let tested = [
        topolab_peers::LoxHalfEdge::NAME,
        topolab_peers::LoxDirectedEdge::NAME,
        topolab_peers::BabySharkCornerTable::NAME,
        topolab_peers::TriMesh::NAME,
    ];
    if let Err(msg) =
        topolab_structures::testing::conformance::check_enrolment(&tested, &topolab_peers::NAMES)
    {
        panic!("{msg}");
    }
}
