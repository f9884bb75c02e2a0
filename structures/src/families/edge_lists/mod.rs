//! Structures with an explicit record per edge: the edge list of the lecture on polygon-mesh data
//! structures (start, end, left and right face) and its doubly linked variant, the winged-edge (the
//! edge also knows its predecessor and successor in both faces). Both know each edge's faces and
//! its successor in a face, from which `boundary_walk` walks the boundary curves for both.

pub(crate) mod boundary_walk;
pub mod edge_list;
pub mod winged_edge;
