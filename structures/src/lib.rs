//! # topolab-structures
//!
//! Mesh data structures side by side behind one trait, [`MeshTopology`], with what they are
//! built from ([`PolygonSoup`]), read from ([`io`]), checked against ([`oracle`],
//! [`conformance`]) and tested on ([`meshes`]), refined to any size ([`refine`]) and
//! renumbered to measure the effect of element order ([`ordering`]); [`checks`] runs the
//! lecture's consistency checks on a file as written.
//!
//! | structure | name | stores | polygons | non-manifold vertices |
//! |---|---|---|---|---|
//! | [`ExplicitStorage`] | `explicit` | each polygon's corner coordinates | yes | yes |
//! | [`VertexList`] | `vertex-list` | shared positions, faces as vertex indices | yes | yes |
//! | [`EdgeList`] | `edge-list` | edges (start, end, left, right face), faces as edge indices | yes | yes |
//! | [`WingedEdge`] | `winged-edge` | seed 004's records: edges with 8 pointers, av(v), af(f) | yes | no |
//! | [`PointerHalfEdge`] | `pointer-half-edge` | the lecture's `HE_edge`/`HE_vert`/`HE_face` records linked by pointers | yes | refused |
//! | [`IndexHalfEdge`] | `index-half-edge` | half-edge arrays of `u32` handles, twin `h ^ 1` (OpenMesh style) | yes | refused |
//! | [`RegularGrid`] | `regular-grid` | a grid's counts, origin and cell size; nothing per element | grids of quads or triangles | (none in a grid) |
//! | [`HeightField`] | `height-field` | a grid's counts and one position per vertex | grids of quads or triangles | (none in a grid) |
//! | [`CheL0`] | `che-l0` | Compact Half-Edge level 0: `G[]`, `V[]` (triangle soup) | no | no |
//! | [`CheL1`] | `che-l1` | CHE level 1: + opposite half-edges `O[]` | no | no |
//! | [`CheL2`] | `che-l2` | CHE level 2: + `VH[]` per vertex, edge map `EH` | no | no |
//! | [`CheL3`] | `che-l3` | CHE level 3: + boundary curves `CH[]` | no | no |
//!
//! [`hull`] builds the 3D convex hull of a point set on the [`WingedEdge`] with seed 004's
//! three algorithms (gift wrapping, incremental, randomized incremental).
//!
//! Each structure's module documents what it stores, its bytes per element, and the cost of
//! each operator; [`MeshTopology::cost`] states those costs as data (`topolab list`).
#![deny(missing_docs)]
// Unsafe code lives only in `pointer_half_edge::links` (real pointers are that structure's point).
#![deny(unsafe_code)]

pub mod attributes;
mod boundary_walk;
pub mod che;
pub mod checks;
pub mod conformance;
mod corner_scan;
pub mod edge_list;
pub mod error;
pub mod explicit;
pub mod half_edge;
pub mod hull;
pub mod ids;
pub mod index_half_edge;
pub mod io;
pub mod meshes;
pub mod oracle;
pub mod ordering;
pub mod pointer_half_edge;
pub mod refine;
pub mod registry;
pub mod regular_grid;
pub mod soup;
pub mod summary;
pub mod topology;
pub mod vertex_list;
pub mod winged_edge;
pub mod workload;

pub use attributes::{MeshAttributes, Plane};
pub use che::{CheL0, CheL1, CheL2, CheL3};
pub use edge_list::EdgeList;
pub use error::{Error, Format, Location, Result};
pub use explicit::ExplicitStorage;
pub use ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
pub use index_half_edge::IndexHalfEdge;
pub use pointer_half_edge::PointerHalfEdge;
pub use regular_grid::{HeightField, RegularGrid};
pub use soup::{Connectivity, PolygonSoup};
pub use topology::{
    BoundaryCurves, Capabilities, Cost, Element, Input, MeshTopology, NativeKernels, Operator,
};
pub use vertex_list::VertexList;
pub use winged_edge::WingedEdge;
pub use workload::Workload;
