/* A C API over OpenMesh for topolab (Rust FFI). Built by the top-level build.rs.
 *
 * Handles are plain indices: vertex i of the input is vertex i here, face j is face j (OpenMesh
 * keeps insertion order), an edge is OpenMesh's edge index.
 *
 * Operator codes (topolab's Operator catalogue order, see structures/src/core/topology.rs):
 *   0 r00  1 r01  2 r02  3 r10  4 r11  5 r12  6 r20  7 r21  8 r22
 *   9 boundary-vertex  10 boundary-edge  11 boundary-curves  12 edge-successor  13 edge-predecessor
 * Workload codes (Sieger & Botsch's Surface_mesh benchmark):
 *   0 circulators  1 barycenter  2 normals  3 smoothing
 */
#ifndef TOPOLAB_OPENMESH_SHIM_H
#define TOPOLAB_OPENMESH_SHIM_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Every function below catches every C++ exception (none reaches Rust) and returns a status:
 * TOPOLAB_OM_OK, or one of the failures below; results go to out-parameters, which are left
 * untouched on failure. Functions never check indices: the Rust wrapper (src/openmesh.rs)
 * checks them before calling. */
#define TOPOLAB_OM_OK 0
/* add_face refused a face (complex edge / complex vertex): *failed_face names it. */
#define TOPOLAB_OM_REFUSED 1
/* std::bad_alloc. */
#define TOPOLAB_OM_OUT_OF_MEMORY 2
/* Any other exception (OpenMesh's, or the standard library's). */
#define TOPOLAB_OM_EXCEPTION 3
/* An operator or workload code the shim does not know. */
#define TOPOLAB_OM_UNKNOWN_CODE 4
/* OpenMesh's read_mesh returned false (topolab_om_read_file). */
#define TOPOLAB_OM_READ_FAILED 5

#ifdef __cplusplus
#define TOPOLAB_OM_NOEXCEPT noexcept
#else
#define TOPOLAB_OM_NOEXCEPT
#endif

/* An OpenMesh TriMesh or PolyMesh with double-precision points, owned by the caller. */
typedef struct topolab_om_mesh topolab_om_mesh;

/* Receives one answer (an index) of a query. Must not unwind (Rust catches its panics). */
typedef void (*topolab_om_emit)(void *context, uint32_t index);
/* Called when a boundary curve is complete. */
typedef void (*topolab_om_end_curve)(void *context);

/* Builds a mesh from a face list with reserve + add_vertex + add_face into *out, and does nothing
 * else (callers time it): `xyz` holds 3 doubles per vertex, face j is
 * indices[offsets[j]..offsets[j+1]]. `triangles` != 0 chooses TriMesh. `vertices`,
 * `edges_hint` and `faces` are passed to reserve(). TOPOLAB_OM_REFUSED with *failed_face = j
 * when add_face refuses face j. The first call of the process (from any thread) also does the
 * shim's one-time, process-wide set-up: OpenMesh's error stream is connected and disabled. */
int topolab_om_build(const double *xyz, uint32_t vertices, const uint32_t *indices,
                     const uint32_t *offsets, uint32_t faces, int triangles, uint32_t edges_hint,
                     topolab_om_mesh **out, uint32_t *failed_face) TOPOLAB_OM_NOEXCEPT;
/* Frees a mesh from topolab_om_build. NULL is allowed. */
void topolab_om_free(topolab_om_mesh *mesh) TOPOLAB_OM_NOEXCEPT;

/* Receive the vertices, then the faces, of a file OpenMesh read. Must not unwind. */
typedef void (*topolab_om_read_vertex)(void *context, double x, double y, double z);
typedef void (*topolab_om_read_face)(void *context, const uint32_t *corners, size_t count);
/* Reads `path` (NUL-terminated) with OpenMesh's IO::read_mesh into a PolyMesh with default
 * options and reports every vertex, then every face (its vertices from fv_range), in OpenMesh's
 * order. TOPOLAB_OM_READ_FAILED when read_mesh returns false. One read at a time (a mutex):
 * OpenMesh's readers keep per-read state. Silences OpenMesh's omlog and omout on first use. */
int topolab_om_read_file(const char *path, topolab_om_read_vertex vertex,
                         topolab_om_read_face face, void *context) TOPOLAB_OM_NOEXCEPT;

/* Bytes the mesh's containers hold by their lengths: the array kernel's vertex, edge and face
 * records and every property's elements (OpenMesh's BaseProperty::size_of). The blocks it
 * really takes are counted by heap/heap.h's counter. */
int topolab_om_heap_bytes(const topolab_om_mesh *mesh, uint64_t *out) TOPOLAB_OM_NOEXCEPT;
/* out = {1 for a TriMesh else 0, vertices, edges, faces}. */
int topolab_om_summary(const topolab_om_mesh *mesh, uint32_t *out) TOPOLAB_OM_NOEXCEPT;

/* The coordinates of vertex v into out[0..3]. */
int topolab_om_position(const topolab_om_mesh *mesh, uint32_t v, double *out) TOPOLAB_OM_NOEXCEPT;
/* The two end vertices of edge e into out[0..2]. */
int topolab_om_edge_vertices(const topolab_om_mesh *mesh, uint32_t e,
                             uint32_t *out) TOPOLAB_OM_NOEXCEPT;
/* *out = 1 when vertex v (or edge e) is on the boundary, else 0. */
int topolab_om_is_boundary_vertex(const topolab_om_mesh *mesh, uint32_t v,
                                  int *out) TOPOLAB_OM_NOEXCEPT;
int topolab_om_is_boundary_edge(const topolab_om_mesh *mesh, uint32_t e,
                                int *out) TOPOLAB_OM_NOEXCEPT;
/* Relation `op` (r00 r01 r02 r11 r12 r20 r21 r22) of element `id`, one emit per answer;
 * other operator codes emit nothing. */
int topolab_om_query(const topolab_om_mesh *mesh, int op, uint32_t id, topolab_om_emit emit,
                     void *context) TOPOLAB_OM_NOEXCEPT;
/* *out = the edge after (successor != 0) or before edge e in face f; -1 if e does not bound f. */
int topolab_om_edge_neighbour(const topolab_om_mesh *mesh, uint32_t e, uint32_t f, int successor,
                              int64_t *out) TOPOLAB_OM_NOEXCEPT;
/* Every boundary curve: its edges, then end_curve. */
int topolab_om_boundary_curves(const topolab_om_mesh *mesh, topolab_om_emit emit,
                               topolab_om_end_curve end_curve, void *context) TOPOLAB_OM_NOEXCEPT;
/* The halfedge records as OpenMesh stores them, for teaching: out = {to vertex, next, prev,
 * face} (UINT32_MAX for no face). Halfedge h's opposite is h ^ 1, its edge h / 2. */
int topolab_om_halfedge(const topolab_om_mesh *mesh, uint32_t h, uint32_t *out) TOPOLAB_OM_NOEXCEPT;
/* *out = the outgoing halfedge of vertex v, or the halfedge of face f (UINT32_MAX if none). */
int topolab_om_vertex_halfedge(const topolab_om_mesh *mesh, uint32_t v,
                               uint32_t *out) TOPOLAB_OM_NOEXCEPT;
int topolab_om_face_halfedge(const topolab_om_mesh *mesh, uint32_t f,
                             uint32_t *out) TOPOLAB_OM_NOEXCEPT;
/* Checks the halfedge invariants: *problem = 0 when they hold, else 1 (a halfedge), 2 (a
 * vertex) or 3 (a face) with the offending element's index in *element. */
int topolab_om_validate(const topolab_om_mesh *mesh, int *problem,
                        uint32_t *element) TOPOLAB_OM_NOEXCEPT;

/* *out = the checksum of operator `op` over all elements (harness/src/checksum.rs), computed in
 * one C++ loop with OpenMesh's circulators. */
int topolab_om_sweep(const topolab_om_mesh *mesh, int op, uint64_t *out) TOPOLAB_OM_NOEXCEPT;
/* *out = the same checksum over `count` sampled queries only, answered as the harness's generic
 * kernel answers them: ids[0..count], vertex, edge or face ids by the operator's input (OpenMesh's
 * handles are these indices); for edge-successor/predecessor, `count` (edge, face) pairs
 * ids[2i], ids[2i + 1], each asking about that edge in that face (nothing when it does not bound
 * it). TOPOLAB_OM_UNKNOWN_CODE for boundary-curves, which has no queries to sample. */
int topolab_om_sampled(const topolab_om_mesh *mesh, int op, const uint32_t *ids, size_t count,
                       uint64_t *out) TOPOLAB_OM_NOEXCEPT;
/* Requests what workload `workload` needs (face and vertex normals for normals). */
int topolab_om_prepare_workload(topolab_om_mesh *mesh, int workload) TOPOLAB_OM_NOEXCEPT;
/* *out = the result of a Surface_mesh benchmark workload; see src/openmesh.rs. */
int topolab_om_workload(topolab_om_mesh *mesh, int workload, double *out) TOPOLAB_OM_NOEXCEPT;

/* Requests the status attributes the changing workloads delete with (a TriMesh only;
 * TOPOLAB_OM_UNKNOWN_CODE for a PolyMesh). Outside what a caller times. */
int topolab_om_prepare_changing(topolab_om_mesh *mesh) TOPOLAB_OM_NOEXCEPT;
/* Runs a changing workload of the Surface_mesh benchmark (Sieger & Botsch) in place, as its
 * protocol does: 0 = one step of sqrt3 subdivision, 1 = the collapse test. A TriMesh only. */
int topolab_om_changing(topolab_om_mesh *mesh, int workload) TOPOLAB_OM_NOEXCEPT;
/* openmesh/decimate.cpp: builds a TriMesh of `faces` triangles, decimates it with
 * DecimaterT + ModQuadricT to `target` faces (decimate_to_faces), *seconds the time of
 * initialize() and decimate_to_faces(), and writes the compacted result: out_xyz (room for
 * 3 * vertices doubles), out_triangles (room for 3 * faces), their counts. TOPOLAB_OM_REFUSED
 * when add_face refuses a triangle. */
int topolab_om_decimate(const double *xyz, uint32_t vertices, const uint32_t *triangles,
                        uint32_t faces, uint32_t target, double *out_xyz,
                        uint32_t *out_vertices, uint32_t *out_triangles, uint32_t *out_faces,
                        double *seconds) TOPOLAB_OM_NOEXCEPT;

#ifdef __cplusplus
}
#endif

#endif
