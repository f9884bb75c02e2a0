//! # The Rust crates a Rust user would pick, as structures of the lab
//!
//! Each module adapts one structure of a crate from crates.io to
//! [`MeshTopology`](topolab_structures::MeshTopology), so the conformance suite, the
//! registry and the report treat it like the lab's own structures:
//!
//! | structure | crate | what it stores |
//! |---|---|---|
//! | [`lox-half-edge`](lox_half_edge) | lox `HalfEdgeMesh` | half-edges, twin `h ^ 1` |
//! | [`lox-directed-edge`](lox_directed_edge) | lox `DirectedEdgeMesh` | twin and target per corner |
//! | [`baby-shark-corner-table`](baby_shark_corner_table) | baby_shark `CornerTable` | opposite corner and vertex per corner |
//! | [`tri-mesh`](tri_mesh) | tri-mesh `Mesh` | half-edges with `Option` fields behind `RefCell` |
//!
//! Each adapter builds the crate's structure through the crate's documented API and answers
//! each query with the crate's own query where it has one; where it has none, the adapter
//! composes the answer from the crate's primitives (the [`compose`] helpers) and declares the
//! cost of that composition in `cost()`. Input the crate would mis-handle (a third face on an
//! edge, faces that disagree on orientation, a vertex with several fans, polygons where the
//! crate stores triangles) is refused with the lab's typed error before the crate sees it
//! ([`compose::admit`]), so no crate panics and none silently stores something else.
//!
//! Each also implements [`MeshEdit`](topolab_structures::MeshEdit) for the operations its
//! crate does, by the crate's own calls after the lab's checks, and refuses the others as not
//! implemented ([`edit`]).
//!
//! [`registry::Peers`] lists the four as one `Structures` list, which the lab's registry
//! (`topolab_registry`, behind its feature `peers`) chains after the C++
//! baselines; [`CRATES`] names each crate's exact version for `topolab list` and the report.
//! This crate depends on `topolab-structures` only.

#![deny(missing_docs)]

pub mod baby_shark_corner_table;
pub mod compose;
pub mod crates;
pub mod edit;
pub mod lox_directed_edge;
pub mod lox_half_edge;
pub mod registry;
pub mod tri_mesh;
pub mod versions;

pub use baby_shark_corner_table::BabySharkCornerTable;
pub use crates::{crate_of, PeerCrate, CRATES, NAMES};
pub use lox_directed_edge::LoxDirectedEdge;
pub use lox_half_edge::LoxHalfEdge;
pub use registry::Peers;
pub use tri_mesh::TriMesh;
pub use versions::{BABY_SHARK_VERSION, LOX_VERSION, TRI_MESH_VERSION};
