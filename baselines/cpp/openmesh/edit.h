/* The editing operations of topolab's MeshEdit over OpenMesh's own Euler operations (C API for
 * Rust FFI; implemented in edit.cpp, wrapped by src/openmesh/edit.rs). Same discipline as
 * shim.h: every function is noexcept, catches every C++ exception and returns a status.
 *
 * Besides shim.h's statuses an edit may return TOPOLAB_OM_EDIT_REFUSED with *refusal set to
 * one of the TOPOLAB_OM_REFUSAL_ codes (topolab's Refusal, in its order): the edit was checked
 * against OpenMesh's preconditions (is_flip_ok, is_collapse_ok, add_face's manifold rules)
 * and the lab's own, before any write, so a refused edit changes nothing and OpenMesh is never
 * called outside its preconditions (which its release build does not check). Ids out of range
 * are refused (NO_SUCH_ELEMENT) here too.
 *
 * The first edit requests OpenMesh's status attributes (its deletion marks) once. Deleted
 * elements keep their slots until topolab_om_edit_garbage_collection. */
#ifndef TOPOLAB_OPENMESH_EDIT_H
#define TOPOLAB_OPENMESH_EDIT_H

#include "shim.h"

#ifdef __cplusplus
extern "C" {
#endif

#define TOPOLAB_OM_EDIT_REFUSED 5

#define TOPOLAB_OM_REFUSAL_NO_SUCH_ELEMENT 0
#define TOPOLAB_OM_REFUSAL_BAD_FACE 1
#define TOPOLAB_OM_REFUSAL_NON_MANIFOLD_EDGE 2
#define TOPOLAB_OM_REFUSAL_NON_MANIFOLD_VERTEX 3
#define TOPOLAB_OM_REFUSAL_NOT_TRIANGLES 4
#define TOPOLAB_OM_REFUSAL_BOUNDARY_EDGE 5
#define TOPOLAB_OM_REFUSAL_EDGE_EXISTS 6
#define TOPOLAB_OM_REFUSAL_NOT_NEIGHBOURS 7
#define TOPOLAB_OM_REFUSAL_LINK_CONDITION 8
#define TOPOLAB_OM_REFUSAL_NOT_IMPLEMENTED 9
#define TOPOLAB_OM_REFUSAL_SAME_VERTEX 10
#define TOPOLAB_OM_REFUSAL_TETRAHEDRON_TEST 11

/* add_vertex(p) (p = 3 doubles); *out = the new vertex (appended). */
int topolab_om_edit_add_vertex(topolab_om_mesh *mesh, const double *p,
                               uint32_t *out) TOPOLAB_OM_NOEXCEPT;
/* set_point(v, p). */
int topolab_om_edit_set_position(topolab_om_mesh *mesh, uint32_t v, const double *p,
                                 int *refusal) TOPOLAB_OM_NOEXCEPT;
/* add_face(vertices[0..n]); *out = the new face. */
int topolab_om_edit_add_face(topolab_om_mesh *mesh, const uint32_t *vertices, uint32_t n,
                             int *refusal, uint32_t *out) TOPOLAB_OM_NOEXCEPT;
/* delete_face(f, false): the face's edges that border nothing else go, its vertices stay. */
int topolab_om_edit_delete_face(topolab_om_mesh *mesh, uint32_t f,
                                int *refusal) TOPOLAB_OM_NOEXCEPT;
/* delete_vertex(v, false): v and its faces. */
int topolab_om_edit_delete_vertex(topolab_om_mesh *mesh, uint32_t v,
                                  int *refusal) TOPOLAB_OM_NOEXCEPT;
/* flip(e) after is_flip_ok(e) (a TriMesh). */
int topolab_om_edit_flip(topolab_om_mesh *mesh, uint32_t e, int *refusal) TOPOLAB_OM_NOEXCEPT;
/* split(e, add_vertex(p)), the 2-to-4 split (a TriMesh); *out = the new vertex. */
int topolab_om_edit_split_edge(topolab_om_mesh *mesh, uint32_t e, const double *p, int *refusal,
                               uint32_t *out) TOPOLAB_OM_NOEXCEPT;
/* split(f, add_vertex(p)), the 1-to-n fan; *out = the new vertex. */
int topolab_om_edit_split_face(topolab_om_mesh *mesh, uint32_t f, const double *p, int *refusal,
                               uint32_t *out) TOPOLAB_OM_NOEXCEPT;
/* collapse(halfedge from -> to) after is_collapse_ok: `from` goes, `to` stays. */
int topolab_om_edit_collapse(topolab_om_mesh *mesh, uint32_t from, uint32_t to,
                             int *refusal) TOPOLAB_OM_NOEXCEPT;
/* vertex_split(add_vertex(p), v, left, right) (a TriMesh); *out = the new vertex. */
int topolab_om_edit_split_vertex(topolab_om_mesh *mesh, uint32_t v, const double *p,
                                 uint32_t left, uint32_t right, int *refusal,
                                 uint32_t *out) TOPOLAB_OM_NOEXCEPT;
/* Vertex b merged into vertex a (MeshEdit::weld_vertices): OpenMesh has none, so the
 * half-edges' weld with its low-level connectivity setters (see edit.cpp). */
int topolab_om_edit_weld(topolab_om_mesh *mesh, uint32_t a, uint32_t b,
                         int *refusal) TOPOLAB_OM_NOEXCEPT;
/* *out = 1 when vertex (kind 0), edge (kind 1) or face (kind 2) `id` is marked deleted. */
int topolab_om_edit_is_deleted(const topolab_om_mesh *mesh, int kind, uint32_t id,
                               int *out) TOPOLAB_OM_NOEXCEPT;
/* Removes the deleted elements keeping the survivors' order (see edit.cpp for why this is
 * not OpenMesh's garbage_collection). */
int topolab_om_edit_garbage_collection(topolab_om_mesh *mesh) TOPOLAB_OM_NOEXCEPT;
/* reserve() room for that many more vertices, edges and faces. */
int topolab_om_edit_reserve(topolab_om_mesh *mesh, uint32_t vertices, uint32_t edges,
                            uint32_t faces) TOPOLAB_OM_NOEXCEPT;

#ifdef __cplusplus
}
#endif

#endif
