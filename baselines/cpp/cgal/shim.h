/* A C API over CGAL for topolab (Rust FFI): two mesh structures and one convex hull. Built by
 * the top-level build.rs, one translation unit per CGAL piece (surface_mesh.cpp,
 * polyhedron.cpp, hull.cpp) plus this API's shim.cpp, which includes no CGAL header.
 *
 * Structures (the `structure` argument of topolab_cgal_build):
 *   0 CGAL::Surface_mesh  -- index-based halfedges (the Surface_mesh of Sieger & Botsch)
 *   1 CGAL::Polyhedron_3  -- pointer-based halfedges in linked lists (HalfedgeDS_list)
 * Both answer every query through CGAL's BGL circulators (halfedges_around_target,
 * faces_around_target, vertices_around_face, ...), which CGAL's own algorithms use on both.
 *
 * Handles are plain indices: vertex i of the input is vertex i, face j is face j (both
 * structures keep insertion order), edge e is the structure's edge e (halfedges 2e, 2e + 1).
 *
 * Operator codes (topolab's Operator catalogue order, see structures/src/core/topology.rs):
 *   0 r00  1 r01  2 r02  3 r10  4 r11  5 r12  6 r20  7 r21  8 r22
 *   9 boundary-vertex  10 boundary-edge  11 boundary-curves  12 edge-successor  13 edge-predecessor
 * Workload codes (Sieger & Botsch's Surface_mesh benchmark):
 *   0 circulators  1 barycenter  2 normals  3 smoothing
 */
#ifndef TOPOLAB_CGAL_SHIM_H
#define TOPOLAB_CGAL_SHIM_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Every function below catches every C++ exception (none reaches Rust) and returns a status:
 * TOPOLAB_CGAL_OK, or one of the failures below; results go to out-parameters, which are left
 * untouched on failure. Functions never check indices: the Rust wrapper (src/cgal.rs) checks
 * them before calling. */
#define TOPOLAB_CGAL_OK 0
/* CGAL refused a face (add_face returned null_face, or the Polyhedron builder's error flag
 * went up): *failed_face names it. */
#define TOPOLAB_CGAL_REFUSED 1
/* std::bad_alloc. */
#define TOPOLAB_CGAL_OUT_OF_MEMORY 2
/* Any other exception (CGAL's, Boost's, or the standard library's). */
#define TOPOLAB_CGAL_EXCEPTION 3
/* A structure, operator or workload code the shim does not know. */
#define TOPOLAB_CGAL_UNKNOWN_CODE 4

#define TOPOLAB_CGAL_SURFACE_MESH 0
#define TOPOLAB_CGAL_POLYHEDRON 1

#ifdef __cplusplus
#define TOPOLAB_CGAL_NOEXCEPT noexcept
#else
#define TOPOLAB_CGAL_NOEXCEPT
#endif

/* A CGAL mesh with double-precision points, owned by the caller. */
typedef struct topolab_cgal_mesh topolab_cgal_mesh;
/* A sampled kernel prepared for one operator of one mesh, owned by the caller. */
typedef struct topolab_cgal_sample topolab_cgal_sample;

/* Receives one answer (an index) of a query. Must not unwind (Rust catches its panics). */
typedef void (*topolab_cgal_emit)(void *context, uint32_t index);
/* Called when a boundary curve is complete. */
typedef void (*topolab_cgal_end_curve)(void *context);

/* The version of the CGAL headers compiled in, e.g. "5.5.1" (a static string). */
const char *topolab_cgal_version(void) TOPOLAB_CGAL_NOEXCEPT;

/* Builds `structure` from a face list into *out, the way CGAL's documentation builds one, and does
 * nothing else (callers time it): Surface_mesh by reserve + add_vertex + add_face; Polyhedron_3
 * by Polyhedron_incremental_builder_3 (begin_surface with the counts, add_vertex, add_facet).
 * `xyz` holds 3 doubles per vertex, face j is indices[offsets[j]..offsets[j+1]]; `vertices`,
 * `edges_hint` and `faces` go to the reservation. TOPOLAB_CGAL_REFUSED with *failed_face = j
 * when face j is refused. The mesh answers queries after topolab_cgal_finish. */
int topolab_cgal_build(int structure, const double *xyz, uint32_t vertices,
                       const uint32_t *indices, const uint32_t *offsets, uint32_t faces,
                       uint32_t edges_hint, topolab_cgal_mesh **out,
                       uint32_t *failed_face) TOPOLAB_CGAL_NOEXCEPT;
/* What the lab adds to a mesh of topolab_cgal_build for its queries, outside the timed build:
 * the Polyhedron_3's ids and tables from id to handle (nothing for a Surface_mesh, whose
 * indices are the ids). */
int topolab_cgal_finish(topolab_cgal_mesh *mesh) TOPOLAB_CGAL_NOEXCEPT;
/* Frees a mesh from topolab_cgal_build. NULL is allowed. */
void topolab_cgal_free(topolab_cgal_mesh *mesh) TOPOLAB_CGAL_NOEXCEPT;

/* Bytes the mesh's records take by their numbers (and the Polyhedron_3's id tables by their
 * capacities); see src/cgal.rs. The blocks it really takes are counted by heap/heap.h's
 * counter. */
int topolab_cgal_heap_bytes(const topolab_cgal_mesh *mesh, uint64_t *out) TOPOLAB_CGAL_NOEXCEPT;
/* out = {vertices, edges, faces}. */
int topolab_cgal_summary(const topolab_cgal_mesh *mesh, uint32_t *out) TOPOLAB_CGAL_NOEXCEPT;

/* The coordinates of vertex v into out[0..3]. */
int topolab_cgal_position(const topolab_cgal_mesh *mesh, uint32_t v,
                          double *out) TOPOLAB_CGAL_NOEXCEPT;
/* The two end vertices of edge e into out[0..2]. */
int topolab_cgal_edge_vertices(const topolab_cgal_mesh *mesh, uint32_t e,
                               uint32_t *out) TOPOLAB_CGAL_NOEXCEPT;
/* *out = 1 when vertex v (or edge e) is on the boundary, else 0. */
int topolab_cgal_is_boundary_vertex(const topolab_cgal_mesh *mesh, uint32_t v,
                                    int *out) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_is_boundary_edge(const topolab_cgal_mesh *mesh, uint32_t e,
                                  int *out) TOPOLAB_CGAL_NOEXCEPT;
/* Relation `op` (r00 r01 r02 r11 r12 r20 r21 r22) of element `id`, one emit per answer;
 * other operator codes emit nothing. */
int topolab_cgal_query(const topolab_cgal_mesh *mesh, int op, uint32_t id, topolab_cgal_emit emit,
                       void *context) TOPOLAB_CGAL_NOEXCEPT;
/* *out = the edge after (successor != 0) or before edge e in face f; -1 if e does not bound f. */
int topolab_cgal_edge_neighbour(const topolab_cgal_mesh *mesh, uint32_t e, uint32_t f,
                                int successor, int64_t *out) TOPOLAB_CGAL_NOEXCEPT;
/* Every boundary curve: its edges, then end_curve. */
int topolab_cgal_boundary_curves(const topolab_cgal_mesh *mesh, topolab_cgal_emit emit,
                                 topolab_cgal_end_curve end_curve,
                                 void *context) TOPOLAB_CGAL_NOEXCEPT;
/* The halfedge records as CGAL stores them, for teaching: out = {target vertex, next, prev,
 * face} (UINT32_MAX for no face). Halfedge h's opposite is h ^ 1, its edge h / 2. */
int topolab_cgal_halfedge(const topolab_cgal_mesh *mesh, uint32_t h,
                          uint32_t *out) TOPOLAB_CGAL_NOEXCEPT;
/* *out = the halfedge CGAL keeps for vertex v (one pointing to v), or for face f
 * (UINT32_MAX if none). */
int topolab_cgal_vertex_halfedge(const topolab_cgal_mesh *mesh, uint32_t v,
                                 uint32_t *out) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_face_halfedge(const topolab_cgal_mesh *mesh, uint32_t f,
                               uint32_t *out) TOPOLAB_CGAL_NOEXCEPT;
/* Checks the halfedge invariants and CGAL's own is_valid(): *problem = 0 when they hold, else
 * 1 (a halfedge), 2 (a vertex), 3 (a face) with the offending element's index in *element, or
 * 4 when CGAL's is_valid() fails. */
int topolab_cgal_validate(const topolab_cgal_mesh *mesh, int *problem,
                          uint32_t *element) TOPOLAB_CGAL_NOEXCEPT;

/* *out = the checksum of operator `op` over all elements (harness/src/checksum.rs), computed in
 * one C++ loop with CGAL's circulators. */
int topolab_cgal_sweep(const topolab_cgal_mesh *mesh, int op, uint64_t *out) TOPOLAB_CGAL_NOEXCEPT;
/* Prepares the sampled kernel of operator `op` over `count` queries into *out (owned by the
 * caller, freed by topolab_cgal_free_sample): ids[0..count], vertex, edge or face ids by the
 * operator's input, or for edge-successor/predecessor `count` (edge, face) pairs ids[2i],
 * ids[2i + 1]. The queries are translated to the structure's own descriptors here (a
 * Polyhedron's handles from its id tables), so that a timed topolab_cgal_sampled translates
 * nothing. The sample refers to `mesh`, which must outlive it unchanged.
 * TOPOLAB_CGAL_UNKNOWN_CODE for boundary-curves, which has no queries to sample. */
int topolab_cgal_prepare_sample(const topolab_cgal_mesh *mesh, int op, const uint32_t *ids,
                                size_t count, topolab_cgal_sample **out) TOPOLAB_CGAL_NOEXCEPT;
/* *out = the checksum of the prepared queries, answered as the harness's generic kernel answers
 * them (a successor or predecessor of an edge that does not bound the face counts nothing). */
int topolab_cgal_sampled(const topolab_cgal_sample *sample, uint64_t *out) TOPOLAB_CGAL_NOEXCEPT;
/* Frees a sample from topolab_cgal_prepare_sample. NULL is allowed. */
void topolab_cgal_free_sample(topolab_cgal_sample *sample) TOPOLAB_CGAL_NOEXCEPT;
/* Allocates what workload `workload` needs (the normal arrays for normals), so that a timed
 * run of topolab_cgal_workload computes only. */
int topolab_cgal_prepare_workload(topolab_cgal_mesh *mesh, int workload) TOPOLAB_CGAL_NOEXCEPT;
/* *out = the result of a Surface_mesh benchmark workload; see src/cgal.rs. */
int topolab_cgal_workload(topolab_cgal_mesh *mesh, int workload,
                          double *out) TOPOLAB_CGAL_NOEXCEPT;

/* CGAL::convex_hull_3 (its quickhull; Exact_predicates_inexact_constructions_kernel) of the
 * n points xyz[0..3n] into a Surface_mesh, run `repeat` times (at least once): *seconds = the
 * best time of the convex_hull_3 call alone; out = {hull vertices, hull faces, 1 if every face
 * is a triangle and the hull is closed, else 0}; *volume = the enclosed volume (signed
 * tetrahedra from the origin, as the lab computes it). The caller checks the input first
 * (finite coordinates, four points not in one plane): the hull of degenerate input is not a
 * solid. */
int topolab_cgal_convex_hull(const double *xyz, uint32_t n, uint32_t repeat, double *seconds,
                             uint32_t *out, double *volume) TOPOLAB_CGAL_NOEXCEPT;

/* cgal/decimate.cpp (built when Eigen is found): builds a Surface_mesh of `faces` triangles,
 * simplifies it with edge_collapse and the Garland-Heckbert plane policies down to the edges
 * of `target` faces, *seconds the time of edge_collapse(), and writes the compacted result:
 * out_xyz (room for 3 * vertices doubles), out_triangles (room for 3 * faces), their counts.
 * TOPOLAB_CGAL_REFUSED when add_face refuses a triangle. */
int topolab_cgal_decimate(const double *xyz, uint32_t vertices, const uint32_t *triangles,
                          uint32_t faces, uint32_t target, double *out_xyz,
                          uint32_t *out_vertices, uint32_t *out_triangles, uint32_t *out_faces,
                          double *seconds) TOPOLAB_CGAL_NOEXCEPT;

#ifdef __cplusplus
}
#endif

#endif
