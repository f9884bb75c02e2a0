//! The editing suite ([`topolab_structures::testing::editing`]) on every structure that
//! implements `MeshEdit`: one line each.

topolab_structures::edit_conformance!(index_half_edge, topolab_structures::IndexHalfEdge);
topolab_structures::edit_conformance!(pointer_half_edge, topolab_structures::PointerHalfEdge);
topolab_structures::edit_conformance!(che_l0, topolab_structures::CheL0);
topolab_structures::edit_conformance!(che_l1, topolab_structures::CheL1);
topolab_structures::edit_conformance!(che_l2, topolab_structures::CheL2);
topolab_structures::edit_conformance!(che_l3, topolab_structures::CheL3);
