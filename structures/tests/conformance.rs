//! The conformance suite, one line per structure.

use topolab_structures::conformance;
use topolab_structures::{
    ExplicitStorage, HeightField, IndexHalfEdge, PointerHalfEdge, RegularGrid, VertexList,
};

conformance!(explicit, ExplicitStorage);
conformance!(vertex_list, VertexList);
conformance!(edge_list, topolab_structures::EdgeList);
conformance!(winged_edge, topolab_structures::WingedEdge);
conformance!(index_half_edge, IndexHalfEdge);
conformance!(pointer_half_edge, PointerHalfEdge);
conformance!(regular_grid, RegularGrid);
conformance!(height_field, HeightField);
