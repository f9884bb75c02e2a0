//! # topolab-structures
//!
//! Mesh data structures side by side behind one trait, [`MeshTopology`], with what they are built
//! from ([`PolygonSoup`]), read from ([`io`]), checked against ([`oracle`](testing::oracle),
//! [`conformance`](mod@testing::conformance)) and tested on ([`meshes`]), refined to any size ([`refine`])
//! and renumbered to measure the effect of element order ([`ordering`]); [`checks`] runs the
//! consistency checks of the lecture on polygon-mesh data structures on a file as written.
//!
//! The structures, one folder per family in [`families`], each registered once in
//! [`registry`] ([`for_each_structure!`]), from which the CLI, the report, the benches and the
//! conformance suite take their lists:
//!
//! | structure | name | stores | polygons | non-manifold vertices |
//! |---|---|---|---|---|
//! | [`ExplicitStorage`] | `explicit` | each polygon's corner coordinates | yes | yes |
//! | [`VertexList`] | `vertex-list` | shared positions, faces as vertex indices | yes | yes |
//! | [`EdgeList`] | `edge-list` | edges (start, end, left, right face), faces as edge indices | yes | yes |
//! | [`WingedEdge`] | `winged-edge` | the records of the lecture on 3D convex hulls: edges with 8 pointers, av(v), af(f) | yes | no |
//! | [`PointerHalfEdge`] | `pointer-half-edge` | the `HE_edge`/`HE_vert`/`HE_face` records of the lecture on polygon-mesh data structures, linked by pointers | yes | refused |
//! | [`IndexHalfEdge`] | `index-half-edge` | half-edge arrays of `u32` handles, twin `h ^ 1` (OpenMesh style) | yes | refused |
//! | [`RegularGrid`] | `regular-grid` | a grid's counts, origin and cell size; nothing per element | grids of quads or triangles | (none in a grid) |
//! | [`HeightField`] | `height-field` | a grid's counts and one position per vertex | grids of quads or triangles | (none in a grid) |
//! | [`CheL0`] | `che-l0` | Compact Half-Edge level 0: `G[]`, `V[]` (triangle soup) | no | no |
//! | [`CheL1`] | `che-l1` | CHE level 1: + opposite half-edges `O[]` | no | no |
//! | [`CheL2`] | `che-l2` | CHE level 2: + `VH[]` per vertex, edge map `EH` | no | no |
//! | [`CheL3`] | `che-l3` | CHE level 3: + boundary curves `CH[]` | no | no |
//!
//! The CHE's containers are also written as a memory-mappable `.che` file
//! ([`che::file`]) and queried in place through [`che::MappedChe`] (levels 1–3, not in the
//! registry: a structure over a file, enrolled in the conformance suite in
//! `structures/tests/che_file.rs`).
//!
//! [`hull`] builds the 3D convex hull of a point set on the [`WingedEdge`] with the three
//! algorithms of the lecture on 3D convex hulls (gift wrapping, incremental, randomized
//! incremental).
//!
//! Each structure's module documents what it stores, its bytes per element, and the cost of
//! each operator; [`MeshTopology::cost`] states those costs as data (`topolab list`).
//!
//! | folder | holds |
//! |---|---|
//! | [`core`](mod@core) | ids, the soup, the trait and its operators and costs, errors, attributes |
//! | [`families`] | the structures by family, each family's shared engine beside them |
//! | [`io`] | OBJ, OFF and PLY readers and writers |
//! | [`algorithms`] | the 3D convex hull, consistency checks and summary, refinement, orderings |
//! | [`meshes`] | canonical tiny meshes, generated grids, tori, spheres and random meshes, and their names on the command line |
//! | [`testing`] | the oracle, the conformance suite and the editing suite |
#![deny(missing_docs)]
// Unsafe code lives only where `allow(unsafe_code)` marks it: the pointer half-edge's links
// (real pointers are that structure's point), the CHE's unchecked walk (`families::che::fan`,
// and the two places that promise its ranges: `CheL2::fan`, `MappedChe::fan`), and the mapping
// of `.che` files (`families::che::mapped::map`); and the growth tests' thread CPU clock
// (`testing::growth`).
#![deny(unsafe_code)]

pub mod algorithms;
pub mod core;
pub mod families;
pub mod io;
pub mod meshes;
pub mod registry;
pub mod testing;

// The module paths the other crates use (`topolab_structures::hull::convex_hull`, ...).
pub use algorithms::{checks, hull, ordering, refine, repair, summary};
pub use families::che;

/// The vector crate of the trait's positions ([`MeshTopology::position`] returns a
/// `glam::DVec3`), re-exported so that a structure outside the lab uses the same version.
pub use glam;

pub use self::core::access::{Access, Container, Read, Step, Unit};
pub use self::core::attributes::{MeshAttributes, Plane};
pub use self::core::edit::{not_offered, refuse, Deletion, EditOp, MeshEdit, Offers, Refusal};
pub use self::core::error::{Error, Format, Location, Numbering, Result};
pub use self::core::family::Family;
pub use self::core::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
pub use self::core::soup::{Connectivity, PolygonSoup};
pub use self::core::topology::{
    BoundaryCurves, BuildFacts, Capabilities, Constructed, Cost, Element, Input, InputChecks,
    MeshTopology, NativeKernels, Operator, Sample, SampledRun, SeparateConstruction,
};
pub use self::core::workload::Workload;
pub use families::che::{CheL0, CheL1, CheL2, CheL3};
pub use families::corner_lists::explicit::ExplicitStorage;
pub use families::corner_lists::vertex_list::VertexList;
pub use families::edge_lists::edge_list::EdgeList;
pub use families::edge_lists::winged_edge::WingedEdge;
pub use families::half_edge::index::IndexHalfEdge;
pub use families::half_edge::pointer::PointerHalfEdge;
pub use families::regular_grid::{HeightField, RegularGrid};
