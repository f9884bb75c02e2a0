/* The changing workloads and topolab's MeshEdit over CGAL's own Euler operations: C API for
 * Rust FFI, implemented in edit_surface_mesh.cpp and edit_polyhedron.cpp (one translation unit
 * per structure, like the builders), wrapped by src/cgal/changing.rs and src/cgal/edit.rs.
 * Same discipline as shim.h: every function is noexcept, catches every C++ exception and
 * returns a status; the mesh must be of the structure the function names. */
#ifndef TOPOLAB_CGAL_EDIT_H
#define TOPOLAB_CGAL_EDIT_H

#include "shim.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Runs a changing workload of the Surface_mesh benchmark (Sieger & Botsch) in place, as
 * CGAL's Surface_mesh/benchmark runs it: 0 = one step of sqrt3 subdivision, 1 = the collapse
 * test (garbage collected at the end). */
int topolab_cgal_sm_changing(topolab_cgal_mesh *mesh, int workload) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_polyhedron_changing(topolab_cgal_mesh *mesh, int workload) TOPOLAB_CGAL_NOEXCEPT;

/* The editing operations of topolab's MeshEdit on a Surface_mesh (topolab_cgal_sm_edit_*) and
 * on a Polyhedron_3 (topolab_cgal_ph_edit_*, the same signatures; see the end of this file),
 * one per CGAL Euler operation (src/cgal/edit.rs). Besides shim.h's statuses an edit may
 * return TOPOLAB_CGAL_EDIT_REFUSED with *refusal set to one of the refusal codes below
 * (topolab's Refusal, in its order): every check runs before CGAL is called, so a refused
 * edit changes nothing and no CGAL precondition is ever violated. The first edit switches
 * Surface_mesh's recycling of removed slots off (set_recycle_garbage(false)): new elements
 * are appended and removed ones keep their slots, marked, until
 * topolab_cgal_sm_edit_garbage_collection. */
#define TOPOLAB_CGAL_EDIT_REFUSED 5

#define TOPOLAB_CGAL_REFUSAL_NO_SUCH_ELEMENT 0
#define TOPOLAB_CGAL_REFUSAL_BAD_FACE 1
#define TOPOLAB_CGAL_REFUSAL_NON_MANIFOLD_EDGE 2
#define TOPOLAB_CGAL_REFUSAL_NON_MANIFOLD_VERTEX 3
#define TOPOLAB_CGAL_REFUSAL_NOT_TRIANGLES 4
#define TOPOLAB_CGAL_REFUSAL_BOUNDARY_EDGE 5
#define TOPOLAB_CGAL_REFUSAL_EDGE_EXISTS 6
#define TOPOLAB_CGAL_REFUSAL_NOT_NEIGHBOURS 7
#define TOPOLAB_CGAL_REFUSAL_LINK_CONDITION 8
#define TOPOLAB_CGAL_REFUSAL_NOT_IMPLEMENTED 9
#define TOPOLAB_CGAL_REFUSAL_SAME_VERTEX 10
#define TOPOLAB_CGAL_REFUSAL_TETRAHEDRON_TEST 11

/* add_vertex(p) (p = 3 doubles); *out = the new vertex (appended). */
int topolab_cgal_sm_edit_add_vertex(topolab_cgal_mesh *mesh, const double *p,
                                    uint32_t *out) TOPOLAB_CGAL_NOEXCEPT;
/* point(v) = p. */
int topolab_cgal_sm_edit_set_position(topolab_cgal_mesh *mesh, uint32_t v, const double *p,
                                      int *refusal) TOPOLAB_CGAL_NOEXCEPT;
/* Euler::add_face(vertices[0..n]); *out = the new face. */
int topolab_cgal_sm_edit_add_face(topolab_cgal_mesh *mesh, const uint32_t *vertices, uint32_t n,
                                  int *refusal, uint32_t *out) TOPOLAB_CGAL_NOEXCEPT;
/* Euler::remove_face, keeping the vertices it isolates (see edit_surface_mesh.cpp). */
int topolab_cgal_sm_edit_delete_face(topolab_cgal_mesh *mesh, uint32_t f,
                                     int *refusal) TOPOLAB_CGAL_NOEXCEPT;
/* The faces around v removed as above, then v. */
int topolab_cgal_sm_edit_delete_vertex(topolab_cgal_mesh *mesh, uint32_t v,
                                       int *refusal) TOPOLAB_CGAL_NOEXCEPT;
/* Euler::flip_edge. */
int topolab_cgal_sm_edit_flip(topolab_cgal_mesh *mesh, uint32_t e,
                              int *refusal) TOPOLAB_CGAL_NOEXCEPT;
/* Euler::split_edge, then Euler::split_face on each side (the 2-to-4 split); *out = the new
 * vertex. */
int topolab_cgal_sm_edit_split_edge(topolab_cgal_mesh *mesh, uint32_t e, const double *p,
                                    int *refusal, uint32_t *out) TOPOLAB_CGAL_NOEXCEPT;
/* Euler::add_center_vertex; *out = the new vertex. */
int topolab_cgal_sm_edit_split_face(topolab_cgal_mesh *mesh, uint32_t f, const double *p,
                                    int *refusal, uint32_t *out) TOPOLAB_CGAL_NOEXCEPT;
/* Euler::collapse_edge of the halfedge from -> to, after does_satisfy_link_condition. */
int topolab_cgal_sm_edit_collapse(topolab_cgal_mesh *mesh, uint32_t from, uint32_t to,
                                  int *refusal) TOPOLAB_CGAL_NOEXCEPT;
/* Euler::split_vertex, then Euler::split_face on each side; *out = the new vertex. */
int topolab_cgal_sm_edit_split_vertex(topolab_cgal_mesh *mesh, uint32_t v, const double *p,
                                      uint32_t left, uint32_t right, int *refusal,
                                      uint32_t *out) TOPOLAB_CGAL_NOEXCEPT;
/* Vertex b merged into vertex a (MeshEdit::weld_vertices): PMP::stitch_borders on the one or
 * two pairs of border halfedges where their boundaries meet, or remove_vertex where one has no
 * faces (edit_rules.h). */
int topolab_cgal_sm_edit_weld(topolab_cgal_mesh *mesh, uint32_t a, uint32_t b,
                              int *refusal) TOPOLAB_CGAL_NOEXCEPT;
/* *out = 1 when vertex (kind 0), edge (kind 1) or face (kind 2) `id` is marked removed. */
int topolab_cgal_sm_edit_is_deleted(const topolab_cgal_mesh *mesh, int kind, uint32_t id,
                                    int *out) TOPOLAB_CGAL_NOEXCEPT;
/* Removes the removed elements keeping the survivors' order (see edit_surface_mesh.cpp for
 * why this is not collect_garbage). */
int topolab_cgal_sm_edit_garbage_collection(topolab_cgal_mesh *mesh) TOPOLAB_CGAL_NOEXCEPT;
/* reserve() room for that many more vertices, edges and faces. */
int topolab_cgal_sm_edit_reserve(topolab_cgal_mesh *mesh, uint32_t vertices, uint32_t edges,
                                 uint32_t faces) TOPOLAB_CGAL_NOEXCEPT;

/* The same operations on a Polyhedron_3, with the same arguments and results. A Polyhedron_3
 * erases at once: the lab's ids stay stable through id tables kept beside it, an erased
 * element's slot holding a tombstone until topolab_cgal_ph_edit_garbage_collection gives the
 * ids again in list order (polyhedron.h, edit_polyhedron.cpp). */
int topolab_cgal_ph_edit_add_vertex(topolab_cgal_mesh *mesh, const double *p,
                                    uint32_t *out) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_ph_edit_set_position(topolab_cgal_mesh *mesh, uint32_t v, const double *p,
                                      int *refusal) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_ph_edit_add_face(topolab_cgal_mesh *mesh, const uint32_t *vertices, uint32_t n,
                                  int *refusal, uint32_t *out) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_ph_edit_delete_face(topolab_cgal_mesh *mesh, uint32_t f,
                                     int *refusal) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_ph_edit_delete_vertex(topolab_cgal_mesh *mesh, uint32_t v,
                                       int *refusal) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_ph_edit_flip(topolab_cgal_mesh *mesh, uint32_t e,
                              int *refusal) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_ph_edit_split_edge(topolab_cgal_mesh *mesh, uint32_t e, const double *p,
                                    int *refusal, uint32_t *out) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_ph_edit_split_face(topolab_cgal_mesh *mesh, uint32_t f, const double *p,
                                    int *refusal, uint32_t *out) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_ph_edit_collapse(topolab_cgal_mesh *mesh, uint32_t from, uint32_t to,
                                  int *refusal) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_ph_edit_split_vertex(topolab_cgal_mesh *mesh, uint32_t v, const double *p,
                                      uint32_t left, uint32_t right, int *refusal,
                                      uint32_t *out) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_ph_edit_weld(topolab_cgal_mesh *mesh, uint32_t a, uint32_t b,
                              int *refusal) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_ph_edit_is_deleted(const topolab_cgal_mesh *mesh, int kind, uint32_t id,
                                    int *out) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_ph_edit_garbage_collection(topolab_cgal_mesh *mesh) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_ph_edit_reserve(topolab_cgal_mesh *mesh, uint32_t vertices, uint32_t edges,
                                 uint32_t faces) TOPOLAB_CGAL_NOEXCEPT;

#ifdef __cplusplus
}
#endif

#endif
