//! [`MeshEdit`](topolab_structures::MeshEdit) for [`OpenMesh`] through OpenMesh's own
//! operations, one C function each (`openmesh/edit.h`, `openmesh/edit.cpp`, reached through
//! the forwarding layer of [`crate::foreign::edit`]): `add_vertex`, `add_face`, `delete_face`,
//! `delete_vertex`, `TriConnectivity::flip` after `is_flip_ok`, the 2-to-4 `split(EdgeHandle,
//! VertexHandle)`, the face split `split(FaceHandle, VertexHandle)`, `collapse` after
//! `is_collapse_ok`, and `vertex_split`; and the vertex weld, which OpenMesh lacks (its API has
//! no weld: `remove_edge` merges two faces, not two vertices), written as the lab's half-edges
//! do it with OpenMesh's low-level connectivity setters (`set_vertex_handle`,
//! `set_next_halfedge_handle`, `set_face_handle`, `set_halfedge_handle`), the way its own
//! `collapse_edge` and `remove_edge` are written: every halfedge into `b` ends at `a`, and where
//! the two boundaries meet along an edge, each pair of boundary edges becomes one interior edge
//! (b's marked deleted). Face ids stay, which deleting `b`'s faces and adding them again with
//! `a` through the documented API would not keep. The first edit requests OpenMesh's status attributes,
//! where its deletion marks live ([`Deletion::Marked`](topolab_structures::Deletion::Marked), OpenMesh's choice).
//!
//! Every check runs in C++ before OpenMesh is called, so a refused edit changes nothing and
//! OpenMesh is never called outside its preconditions (its own checks of them are assertions,
//! compiled out of the release build `build.rs` makes): the lab's rules (an oriented manifold with one fan per
//! vertex after every edit; pmp's `is_collapse_ok`, the tests of OpenMesh's own, refused as
//! [`Refusal::LinkCondition`](topolab_structures::Refusal::LinkCondition), with the
//! tetrahedron test OpenMesh's Decimater adds in `is_collapse_legal`, refused as
//! [`Refusal::TetrahedronTest`](topolab_structures::Refusal::TetrahedronTest)) and OpenMesh's
//! own predicates. Where OpenMesh allows more than the lab (a face
//! making a second fan at a vertex, a deletion splitting a vertex's fan, the collapse that
//! leaves two triangles on three vertices), the edit is refused with the lab's reason.
//!
//! Ids: OpenMesh's handles are indices and it appends new elements, so the new vertex of a
//! split is vertex `num_vertices()` before the call, and `EdgeId` stays OpenMesh's edge index
//! (as for the queries).
//!
//! What OpenMesh cannot do, refused with [`Refusal::NotImplemented`](topolab_structures::Refusal::NotImplemented):
//! - on a PolyMesh (polygon input), the edge flip, the 2-to-4 edge split and the vertex split:
//!   they are `TriConnectivity`'s, and `PolyConnectivity` has none of them (its `split_edge`
//!   inserts a vertex into the edge, turning the triangles beside it into quads);
//! - on a TriMesh, `add_face` with more than three corners (OpenMesh would triangulate it into
//!   several faces), refused as [`Refusal::NotTriangles`](topolab_structures::Refusal::NotTriangles).
//!
//! Garbage collection keeps the survivors' order, as `MeshEdit` promises; OpenMesh's own
//! `garbage_collection` fills each hole with the last live element, renumbering survivors, so
//! the shim compacts by building the mesh again from its live elements in order (`add_vertex`,
//! `add_face`), O(n) like the half-edge family's own collection. The changing workloads
//! (`topolab_om_changing`) call OpenMesh's `garbage_collection` itself, as the benchmark does.
//!
//! | operation | OpenMesh's call | cost |
//! |---|---|---|
//! | add vertex | `add_vertex` | O(1) |
//! | add face | `find_halfedge` per side (checks), `add_face` | O(k) |
//! | delete face | fan check per corner, `delete_face(f, false)` | O(k) |
//! | delete vertex | fan check per neighbour, `delete_vertex(v, false)` | O(k) |
//! | flip edge | `find_halfedge`, `is_flip_ok`, `flip` | O(k) |
//! | split edge | `add_vertex`, `split(e, v)` | O(1) |
//! | split face | `add_vertex`, `split(f, v)` | O(k) |
//! | collapse edge | the lab's link condition and tetrahedron test (each neighbour of one end looked for by `find_halfedge` around the other, O(k²)), `is_collapse_ok`, `collapse` | O(k²) |
//! | split vertex | `add_vertex`, `vertex_split` | O(k) |
//! | weld vertices | the faces around `b` and the neighbours of both (checks), the halfedges into `b` renamed, one or two boundary edge pairs merged | O(k) |
//! | garbage collection | rebuild from the live elements in order | O(n) |

use super::OpenMesh;
use crate::foreign::edit::{edit_api, impl_mesh_edit, ForeignEdit};
use topolab_structures::Result;

edit_api!(API: super::ffi::RawMesh = [
    topolab_om_edit_add_vertex,
    topolab_om_edit_set_position,
    topolab_om_edit_add_face,
    topolab_om_edit_delete_face,
    topolab_om_edit_delete_vertex,
    topolab_om_edit_flip,
    topolab_om_edit_split_edge,
    topolab_om_edit_split_face,
    topolab_om_edit_collapse,
    topolab_om_edit_split_vertex,
    topolab_om_edit_weld,
    topolab_om_edit_is_deleted,
    topolab_om_edit_garbage_collection,
    topolab_om_edit_reserve,
]);

impl ForeignEdit for OpenMesh {
    const API: crate::foreign::edit::EditApi<super::ffi::RawMesh> = API;
    /// OpenMesh's handles are `int`s: no element count may pass `i32::MAX`.
    const MAX_ELEMENTS: u64 = i32::MAX as u64;

    fn refresh_counts(&mut self) -> Result<()> {
        self.read_counts()
    }
}

impl_mesh_edit!(OpenMesh);
