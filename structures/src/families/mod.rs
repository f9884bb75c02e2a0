//! The structures, one folder per family, grouped by what a structure stores to answer
//! adjacency; the engine a family's structures share lives in the family's folder, beside them.
//!
//! | family | structures | what they store for adjacency | shared engine |
//! |---|---|---|---|
//! | [`corner_lists`] | [`ExplicitStorage`](crate::ExplicitStorage), [`VertexList`](crate::VertexList) | nothing: faces as lists of corners (coordinates or vertex indices) | `corner_scan`: every relation by scanning the corners, and the cost table of that scan |
//! | [`edge_lists`] | [`EdgeList`](crate::EdgeList), [`WingedEdge`](crate::WingedEdge) | edge records with their faces (and, winged, their wings) | `boundary_walk`: boundary curves from the edges' faces and successors |
//! | [`half_edge`] | [`PointerHalfEdge`](crate::PointerHalfEdge), [`IndexHalfEdge`](crate::IndexHalfEdge) | half-edges with `next` and `pair` | [`half_edge::HalfEdge`]: every operator written once over the storage's primitives |
//! | [`regular_grid`] | [`RegularGrid`](crate::RegularGrid), [`HeightField`](crate::HeightField) | nothing: the topology is arithmetic on a grid's counts | [`regular_grid::Grid`]: the grid arithmetic, over either geometry |
//! | [`che`] | [`CheL0`](crate::CheL0) … [`CheL3`](crate::CheL3) | integer arrays, one more container per level | [`che::CheLevel`]: the relations of all levels written once over each level's vertex star |
//!
//! The grouping follows the lecture on polygon-mesh data structures, which presents explicit
//! storage and the vertex list, then the edge list and its doubly linked variant (the
//! winged-edge), then the half-edge, and the regular and mixed structures apart; the CHE
//! thesis chapter adds the Compact Half-Edge. Every structure is registered once, in
//! [`crate::registry`].

pub mod che;
pub mod corner_lists;
pub mod edge_lists;
pub mod half_edge;
pub mod regular_grid;
