//! The crates from crates.io this build measures ([`CRATES`]), the structures adapted from
//! each, and what differs from the lab's own structures.

use crate::baby_shark_corner_table;
use crate::lox_directed_edge;
use crate::lox_half_edge;
use crate::tri_mesh;
use crate::versions::{BABY_SHARK_VERSION, LOX_VERSION, TRI_MESH_VERSION};

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
