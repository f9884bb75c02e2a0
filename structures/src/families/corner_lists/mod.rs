//! Structures that store only the faces' corners and find every adjacency by scanning them,
//! as the lecture on polygon-mesh data structures describes explicit storage and the vertex
//! list. The scans and their cost table are shared (`corner_scan`).

pub(crate) mod corner_scan;
pub mod explicit;
pub mod vertex_list;
