//! The editing suite ([`topolab_structures::testing::editing`]) on every structure that
//! implements `MeshEdit`: one line each.

topolab_structures::edit_conformance!(index_half_edge, topolab_structures::IndexHalfEdge);
topolab_structures::edit_conformance!(pointer_half_edge, topolab_structures::PointerHalfEdge);
topolab_structures::edit_conformance!(winged_edge, topolab_structures::WingedEdge);
topolab_structures::edit_conformance!(edge_list, topolab_structures::EdgeList);
topolab_structures::edit_conformance!(vertex_list, topolab_structures::VertexList);
