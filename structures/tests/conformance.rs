//! The conformance suite, one line per structure.

use topolab_structures::conformance;
use topolab_structures::{
    CheL0, CheL1, CheL2, CheL3, ExplicitStorage, HeightField, IndexHalfEdge, PointerHalfEdge,
    RegularGrid, VertexList,
};

conformance!(explicit, ExplicitStorage);
conformance!(vertex_list, VertexList);
conformance!(edge_list, topolab_structures::EdgeList);
conformance!(winged_edge, topolab_structures::WingedEdge);
conformance!(index_half_edge, IndexHalfEdge);
conformance!(pointer_half_edge, PointerHalfEdge);
conformance!(regular_grid, RegularGrid);
conformance!(height_field, HeightField);
conformance!(che_l0, CheL0);
conformance!(che_l1, CheL1);
conformance!(che_l2, CheL2);
conformance!(che_l3, CheL3);
