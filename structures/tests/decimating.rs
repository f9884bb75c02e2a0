//! The decimation suite ([`topolab_structures::testing::decimating`]): quadric-error
//! decimation then reconstruction by vertex splits, on every structure that implements
//! `MeshEdit`: one line each.

use topolab_structures::{
    CheL0, CheL1, CheL2, CheL3, EdgeList, IndexHalfEdge, PointerHalfEdge, VertexList, WingedEdge,
};

topolab_structures::decimate_conformance!(vertex_list, VertexList);
topolab_structures::decimate_conformance!(edge_list, EdgeList);
topolab_structures::decimate_conformance!(winged_edge, WingedEdge);
topolab_structures::decimate_conformance!(pointer_half_edge, PointerHalfEdge);
topolab_structures::decimate_conformance!(index_half_edge, IndexHalfEdge);
topolab_structures::decimate_conformance!(che_l0, CheL0);
topolab_structures::decimate_conformance!(che_l1, CheL1);
topolab_structures::decimate_conformance!(che_l2, CheL2);
topolab_structures::decimate_conformance!(che_l3, CheL3);

/// A structure made editable later must be enrolled above: the enrolled ones are exactly the
/// registry's editable structures.
#[test]
fn every_editable_structure_is_enrolled() {
    use topolab_structures::MeshTopology;
    let enrolled = [
        VertexList::NAME,
        EdgeList::NAME,
        WingedEdge::NAME,
        PointerHalfEdge::NAME,
        IndexHalfEdge::NAME,
        CheL0::NAME,
        CheL1::NAME,
        CheL2::NAME,
        CheL3::NAME,
    ];
    assert_eq!(enrolled, *topolab_structures::registry::editable_names());
}
