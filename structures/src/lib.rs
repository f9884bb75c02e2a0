//! # topolab-structures
//!
//! Mesh data structures side by side behind one trait, [`MeshTopology`], with what they are
//! built from ([`PolygonSoup`]), read from ([`io`]), checked against ([`oracle`],
//! [`conformance`]) and tested on ([`meshes`]).
//!
//! | structure | name | stores | polygons | non-manifold vertices |
//! |---|---|---|---|---|
//! | [`ExplicitStorage`] | `explicit` | each polygon's corner coordinates | yes | yes |
//! | [`VertexList`] | `vertex-list` | shared positions, faces as vertex indices | yes | yes |
//! | [`EdgeList`] | `edge-list` | edges (start, end, left, right face), faces as edge indices | yes | yes |
//! | [`WingedEdge`] | `winged-edge` | seed 004's records: edges with 8 pointers, av(v), af(f) | yes | no |
//!
//! [`hull`] builds the 3D convex hull of a point set on the [`WingedEdge`] with seed 004's
//! three algorithms (gift wrapping, incremental, randomized incremental).
//!
//! Each structure's module documents what it stores, its bytes per element, and the cost of
//! each operator; [`MeshTopology::cost`] states those costs as data (`topolab list`).
#![deny(missing_docs)]
#![forbid(unsafe_code)]

pub mod attributes;
mod boundary_walk;
pub mod conformance;
mod corner_scan;
pub mod edge_list;
pub mod error;
pub mod explicit;
pub mod hull;
pub mod ids;
pub mod io;
pub mod meshes;
pub mod oracle;
pub mod registry;
pub mod soup;
pub mod summary;
pub mod topology;
pub mod vertex_list;
pub mod winged_edge;

pub use attributes::{MeshAttributes, Plane};
pub use edge_list::EdgeList;
pub use error::{Error, Format, Location, Result};
pub use explicit::ExplicitStorage;
pub use ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
pub use soup::{Connectivity, PolygonSoup};
pub use topology::{BoundaryCurves, Capabilities, Cost, MeshTopology, Operator};
pub use vertex_list::VertexList;
pub use winged_edge::WingedEdge;
