//! The conformance suite, one line per structure.

use topolab_structures::conformance;
use topolab_structures::{ExplicitStorage, IndexHalfEdge, VertexList};

conformance!(explicit, ExplicitStorage);
conformance!(vertex_list, VertexList);
conformance!(index_half_edge, IndexHalfEdge);
