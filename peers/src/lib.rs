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
//! (`topolab_baselines::registry`, behind its feature `peers`) chains after the C++
//! baselines; [`CRATES`] names each crate's exact version for `topolab list` and the report.
//! This crate depends on `topolab-structures` only.

#![deny(missing_docs)]

pub mod baby_shark_corner_table;
pub mod compose;
pub mod edit;
pub mod lox_directed_edge;
pub mod lox_half_edge;
pub mod registry;
pub mod tri_mesh;

pub use baby_shark_corner_table::BabySharkCornerTable;
pub use lox_directed_edge::LoxDirectedEdge;
pub use lox_half_edge::LoxHalfEdge;
pub use registry::Peers;
pub use tri_mesh::TriMesh;

/// A crate from crates.io that this build measures, pinned by exact version in
/// `peers/Cargo.toml` (Cargo.lock records its checksum).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct PeerCrate {
    /// Its name on crates.io.
    pub name: &'static str,
    /// The exact version this build compiles.
    pub version: &'static str,
    /// The lab's names of the structures adapted from it.
    pub structures: &'static [&'static str],
    /// How the adapters use it: the types, constructors and queries.
    pub used_as: &'static str,
    /// What differs from the lab's own structures and stays, each with its reason (the
    /// report's "How the baselines are run").
    pub differences: &'static [&'static str],
}

/// lox's version, pinned in `peers/Cargo.toml`.
pub const LOX_VERSION: &str = "0.1.1";
/// baby_shark's version, pinned in `peers/Cargo.toml`.
pub const BABY_SHARK_VERSION: &str = "0.3.12";
/// tri-mesh's version, pinned in `peers/Cargo.toml`.
pub const TRI_MESH_VERSION: &str = "0.6.1";

/// Every crate of this build, in registry order.
pub const CRATES: [PeerCrate; 3] = [
    PeerCrate {
        name: "lox",
        version: LOX_VERSION,
        structures: &[lox_half_edge::NAME, lox_directed_edge::NAME],
        used_as: "HalfEdgeMesh<PolyConfig> and DirectedEdgeMesh<DefaultConfig>, built with reserve_for_vertices, reserve_for_faces, add_vertex and add_face (add_triangle); queried with the FullAdj, BasicAdj and (half-edge) EdgeAdj traits (is_isolated_vertex beside is_boundary_vertex, which says true of an isolated vertex); edited with MeshMut's add_vertex, add_face (add_triangle) and split_face",
        differences: &[
            "lox stores no positions: the adapters keep them in a Vec beside the mesh (in their bytes), as lox's documentation keeps properties in a map beside it.",
            "Queries lox does not have are composed from its own and declared at their cost (docs/peers.md): R11, boundary curves, successor and predecessor; on the directed-edge mesh, which has no edges, also the edges and R01, R10, R12, R21.",
        ],
    },
    PeerCrate {
        name: "baby_shark",
        version: BABY_SHARK_VERSION,
        structures: &[baby_shark_corner_table::NAME],
        used_as: "CornerTable<f64> built with from_vertex_and_face_iters; queried with vertices_around_vertex, edges_around_vertex, faces_around_vertex, edge_vertices, edge_faces, opposite_edge, previous_edge, face_vertices, face_edges, is_vertex_on_boundary, is_edge_on_boundary, boundary_rings and boundary_edges; edited with flip_edge, collapse_edge and Vertex::set_position",
        differences: &[
            "baby_shark's ids are opaque (private constructors): the adapter keeps tables from the lab's ids to the crate's and back, one more read per answer and their bytes counted; they are made after the construction's clock.",
            "A vertex no face uses has no id in baby_shark: the adapter answers for it itself.",
        ],
    },
    PeerCrate {
        name: "tri-mesh",
        version: TRI_MESH_VERSION,
        structures: &[tri_mesh::NAME],
        used_as: "Mesh::new from a three_d_asset::TriMesh with f64 positions and u32 indices; queried with vertex_halfedge_iter, face_halfedge_iter, edge_iter and its walkers; edited with add_vertex, add_face, flip_edge, split_edge, split_face and set_vertex_position",
        differences: &[
            "The adapter keeps the ids tri-mesh's iterators gave (one u32 per vertex, face and half-edge), read after the construction's clock, rather than calling its unsafe constructor meant for tests: one more read per answer.",
            "tri-mesh's build converts the positions and copies the indices into its input type (three_d_asset::TriMesh), as its documentation builds a mesh; that is inside the clock.",
        ],
    },
];

/// Names of every structure of this crate, in registry order.
pub const NAMES: [&str; 4] = [
    lox_half_edge::NAME,
    lox_directed_edge::NAME,
    baby_shark_corner_table::NAME,
    tri_mesh::NAME,
];

/// The crate a structure called `name` comes from, `None` when it is not one of this crate's.
pub fn crate_of(name: &str) -> Option<&'static PeerCrate> {
    CRATES.iter().find(|c| c.structures.contains(&name))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The versions the report names are the ones Cargo.lock pinned.
    #[test]
    fn every_version_named_is_the_one_cargo_lock_pins() {
        let lock = include_str!("../../Cargo.lock");
        for c in CRATES {
            let entry = format!("name = \"{}\"\nversion = \"{}\"", c.name, c.version);
            assert!(
                lock.contains(&entry),
                "{} {} not in Cargo.lock",
                c.name,
                c.version
            );
            let manifest = include_str!("../Cargo.toml");
            assert!(
                manifest.contains(&format!("{} = \"={}\"", c.name, c.version)),
                "{} is not pinned to ={} in peers/Cargo.toml",
                c.name,
                c.version
            );
        }
    }

    #[test]
    fn every_structure_has_one_crate() {
        for name in NAMES {
            assert_eq!(
                CRATES
                    .iter()
                    .filter(|c| c.structures.contains(&name))
                    .count(),
                1,
                "{name}"
            );
        }
        assert_eq!(crate_of("index-half-edge"), None);
    }
}
