//! The conformance suite, one line per structure.

use topolab_structures::conformance;
use topolab_structures::{ExplicitStorage, VertexList};

conformance!(explicit, ExplicitStorage);
conformance!(vertex_list, VertexList);
conformance!(edge_list, topolab_structures::EdgeList);
conformance!(winged_edge, topolab_structures::WingedEdge);
