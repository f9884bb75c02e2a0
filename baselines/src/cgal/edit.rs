//! [`MeshEdit`](topolab_structures::MeshEdit) for CGAL's `Surface_mesh` ([`SurfaceMesh`]) and
//! `Polyhedron_3` ([`Polyhedron`]) through CGAL's Euler operations, one C function each
//! (`cgal/edit.h`; `cgal/edit_surface_mesh.cpp`, `cgal/edit_polyhedron.cpp`), reached through
//! the forwarding layer of [`crate::foreign::edit`].
//!
//! ## `Surface_mesh`
//!
//! `Euler::add_face`,
//! `Euler::remove_face` (keeping the vertices it isolates), `Euler::flip_edge`,
//! `Euler::split_edge` followed by `Euler::split_face` on each side (the 2-to-4 split),
//! `Euler::add_center_vertex`, `Euler::collapse_edge` after `does_satisfy_link_condition`,
//! and `Euler::split_vertex` followed by two `Euler::split_face` (OpenMesh's vertex split).
//!
//! The vertex weld (`b` into `a`) is what CGAL documents for joining borders:
//! `Polygon_mesh_processing::stitch_borders` with explicit pairs of border halfedges, the one
//! or two pairs where the boundaries of `a` and `b` meet along an edge (b's halfedge first, so
//! that b's edges stay and a's go, and CGAL keeps `a`: checked after the call); where `b` has
//! no faces it is removed (`remove_vertex`), and where `a` has none, every halfedge into `b`
//! is set to end at `a` (`set_target`, the BGL setter) before `b` is removed. One BGL template
//! (`cgal/edit_rules.h`) serves both classes, with each class's id table. Its refusals are the
//! lab's half-edges', checked first and in their order, so the shared cases agree.
//! The first edit switches `Surface_mesh`'s recycling of removed slots off, so new elements
//! are appended and removed ones keep their slots, marked
//! ([`Deletion::Marked`](topolab_structures::Deletion::Marked), CGAL's `is_removed`).
//!
//! Every check runs in C++ before CGAL is called, so a refused edit changes nothing and no
//! CGAL precondition is violated: the lab's rules (the half-edge family's) and CGAL's own
//! `does_satisfy_link_condition`. Ids: `Surface_mesh`'s indices, as for the queries (edge `e`
//! has halfedges `2e` and `2e + 1`).
//!
//! Garbage collection keeps the survivors' order, as [`MeshEdit`] promises; `collect_garbage`
//! fills each hole with the last live element, so the shim builds the mesh again from its live
//! elements in order (O(n), like the half-edge family's own collection). The changing
//! workloads call `collect_garbage` itself, as the benchmark does.
//!
//! | operation | CGAL's calls | cost |
//! |---|---|---|
//! | add vertex | `add_vertex` | O(1) |
//! | add face | `halfedge(a, b)` per side (checks), `Euler::add_face` | O(k) |
//! | delete face | fan check per corner, `Euler::remove_face` | O(k) |
//! | delete vertex | fan check per neighbour, `remove_face` per face, `remove_vertex` | O(k) |
//! | flip edge | `halfedge(x, y)`, `Euler::flip_edge` | O(k) |
//! | split edge | `Euler::split_edge`, `Euler::split_face` twice | O(1) |
//! | split face | `Euler::add_center_vertex` | O(k) |
//! | collapse edge | the lab's link condition and tetrahedron test (each neighbour of one end looked for around the other, O(k²)), `does_satisfy_link_condition`, `Euler::collapse_edge` | O(k²) |
//! | split vertex | `Euler::split_vertex` (O(k)), `Euler::split_face` twice | O(k) |
//! | weld vertices | the faces around `b` and the neighbours of both (checks), `PMP::stitch_borders` on one or two pairs, or `set_target` around `b` | O(k) |
//! | garbage collection | rebuild from the live elements in order | O(n) |

//!
//! ## `Polyhedron_3`
//!
//! The same Euler operations and the same checks (`cgal/edit_polyhedron.cpp`), on the BGL
//! interface `Polyhedron_3` models: `Euler::add_face`, `remove_face` keeping the vertices it
//! isolates, `Euler::flip_edge`, `Euler::split_edge` and `Euler::split_face` twice,
//! `Euler::add_center_vertex`, `Euler::collapse_edge` after `does_satisfy_link_condition`,
//! `Euler::split_vertex` and `Euler::split_face` twice, and the same weld template
//! (`stitch_borders`). A vertex's halfedge is any halfedge into it (its border test
//! circulates), so no border halfedge is restored after an edit.
//!
//! Ids: a `Polyhedron_3` erases an element from its list at once, so the lab's stable ids are
//! tables kept beside it (`cgal/polyhedron.h`): handles by id, and ids by handle in the id
//! fields of `Polyhedron_items_with_id_3`. CGAL appends new elements to its lists; an edit
//! that creates gives them the next ids (the lists' old ends are remembered, O(1) per new
//! element). An edit that erases reads the ids of what CGAL will erase first and puts a
//! tombstone into their slots (a vertex, a halfedge pair and a facet outside the polyhedron,
//! linked to each other, so a query about a deleted id reads a harmless record and no query
//! tests liveness): ids and counts stay, deletions are marked
//! ([`Deletion::Marked`](topolab_structures::Deletion::Marked)). For a collapse, whose erased
//! side edges are CGAL's choice, the ids of the edge, its triangles and their sides are read
//! before and those around the kept vertex after, and the difference is buried. The garbage
//! collection gives the ids again in list order, which is id order, so the survivors keep
//! their order (the changing workloads end the same way).
//!
//! | operation | CGAL's calls | cost |
//! |---|---|---|
//! | add vertex | `add_vertex`, one id | O(1) |
//! | add face | halfedge search and border test per side (checks, O(k) each), `Euler::add_face` | O(k) |
//! | delete face | fan check per corner, `remove_face` with the erased ids buried | O(k) |
//! | delete vertex | fan check per neighbour, that per face, `remove_vertex` | O(k) |
//! | flip edge | halfedge search, `Euler::flip_edge` | O(k) |
//! | split edge | `Euler::split_edge`, `Euler::split_face` twice, ids for the new elements | O(1) |
//! | split face | `Euler::add_center_vertex`, ids for the new elements | O(k) |
//! | collapse edge | the lab's link condition and tetrahedron test (O(k²), as for `Surface_mesh`), `does_satisfy_link_condition`, `Euler::collapse_edge`, the erased ids buried | O(k²) |
//! | split vertex | `Euler::split_vertex` (O(k)), `Euler::split_face` twice | O(k) |
//! | weld vertices | as for `Surface_mesh`, the ids of the one or two edges and the vertex `stitch_borders` removes buried first | O(k) |
//! | garbage collection | ids and tables again in list order | O(n) |

use super::{Cgal, PolyhedronClass, SurfaceMeshClass};
#[cfg(doc)]
use super::{Polyhedron, SurfaceMesh};
use crate::foreign::edit::{edit_api, impl_mesh_edit, EditApi, ForeignEdit};
use topolab_structures::Result;

edit_api!(SURFACE_MESH: super::ffi::RawMesh = [
    topolab_cgal_sm_edit_add_vertex,
    topolab_cgal_sm_edit_set_position,
    topolab_cgal_sm_edit_add_face,
    topolab_cgal_sm_edit_delete_face,
    topolab_cgal_sm_edit_delete_vertex,
    topolab_cgal_sm_edit_flip,
    topolab_cgal_sm_edit_split_edge,
    topolab_cgal_sm_edit_split_face,
    topolab_cgal_sm_edit_collapse,
    topolab_cgal_sm_edit_split_vertex,
    topolab_cgal_sm_edit_weld,
    topolab_cgal_sm_edit_is_deleted,
    topolab_cgal_sm_edit_garbage_collection,
    topolab_cgal_sm_edit_reserve,
]);

edit_api!(POLYHEDRON: super::ffi::RawMesh = [
    topolab_cgal_ph_edit_add_vertex,
    topolab_cgal_ph_edit_set_position,
    topolab_cgal_ph_edit_add_face,
    topolab_cgal_ph_edit_delete_face,
    topolab_cgal_ph_edit_delete_vertex,
    topolab_cgal_ph_edit_flip,
    topolab_cgal_ph_edit_split_edge,
    topolab_cgal_ph_edit_split_face,
    topolab_cgal_ph_edit_collapse,
    topolab_cgal_ph_edit_split_vertex,
    topolab_cgal_ph_edit_weld,
    topolab_cgal_ph_edit_is_deleted,
    topolab_cgal_ph_edit_garbage_collection,
    topolab_cgal_ph_edit_reserve,
]);

/// What CGAL's two classes share as [`ForeignEdit`]s: how they read their counts again (the
/// API is each class's).
macro_rules! cgal_edit {
    ($class:ty, $api:ident, $max:expr) => {
        impl ForeignEdit for Cgal<$class> {
            const API: EditApi<super::ffi::RawMesh> = $api;
            const MAX_ELEMENTS: u64 = $max;

            fn refresh_counts(&mut self) -> Result<()> {
                Cgal::refresh_counts(self)
            }
        }

        impl_mesh_edit!(Cgal<$class>);
    };
}

// `Surface_mesh`'s indices are `uint32_t`, the largest one its null index.
cgal_edit!(SurfaceMeshClass, SURFACE_MESH, u32::MAX as u64 - 1);
// The Polyhedron's ids are the shim's tables' (`size_t` in the items), kept to `u32`, the
// largest one its tombstones' id.
cgal_edit!(PolyhedronClass, POLYHEDRON, u32::MAX as u64 - 1);
