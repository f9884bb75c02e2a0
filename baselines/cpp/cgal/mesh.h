// What the translation units of the CGAL shim share, without any CGAL header (so that
// shim.cpp, the C API, compiles in a moment): the mesh interface each structure implements,
// the harness's checksum functions and the exception wall.

#ifndef TOPOLAB_CGAL_MESH_H
#define TOPOLAB_CGAL_MESH_H

#include "shim.h"
#include "../common/operators.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>

namespace topolab_cgal {

// The operator and workload codes, the checksum mix and the dispatch, as OpenMesh's shim has
// them (../common/operators.h).
using namespace topolab_shim;

constexpr uint64_t edge_key(uint32_t a, uint32_t b) {
  return a < b ? (uint64_t(a) << 32) | b : (uint64_t(b) << 32) | a;
}

// The face list of topolab_cgal_build.
struct Input {
  const double *xyz;
  uint32_t vertices;
  const uint32_t *indices;
  const uint32_t *offsets;
  uint32_t faces;
  uint32_t edges_hint;
};

}  // namespace topolab_cgal

// A sampled kernel prepared for one operator of one mesh, behind the C API's opaque pointer
// (the type of shim.h): its queries as the structure's own descriptors, so that run() reads no
// id table. It refers to its mesh, which must outlive it unchanged.
struct topolab_cgal_sample {
  virtual ~topolab_cgal_sample() = default;
  // The checksum of the prepared queries (harness/src/checksum.rs). May throw.
  virtual uint64_t run() const = 0;
};

// One built structure, behind the C API's opaque pointer (the type of shim.h). Ids are checked
// by the Rust wrapper; every method may throw (the C API's guard catches it).
struct topolab_cgal_mesh {
  virtual ~topolab_cgal_mesh() = default;
  // {vertices, edges, faces}.
  virtual void summary(uint32_t *out) const = 0;
  virtual void position(uint32_t v, double *out) const = 0;
  virtual void edge_vertices(uint32_t e, uint32_t *out) const = 0;
  virtual bool is_boundary_vertex(uint32_t v) const = 0;
  virtual bool is_boundary_edge(uint32_t e) const = 0;
  virtual void query(int op, uint32_t id, topolab_cgal_emit emit, void *context) const = 0;
  virtual int64_t edge_neighbour(uint32_t e, uint32_t f, bool successor) const = 0;
  virtual void boundary_curves(topolab_cgal_emit emit, topolab_cgal_end_curve end_curve,
                               void *context) const = 0;
  virtual void halfedge_record(uint32_t h, uint32_t *out) const = 0;
  virtual uint32_t vertex_halfedge(uint32_t v) const = 0;
  virtual uint32_t face_halfedge(uint32_t f) const = 0;
  // 0 when valid, else the problem code of topolab_cgal_validate with *element set.
  virtual int validate(uint32_t *element) const = 0;
  virtual uint64_t sweep(int op) const = 0;
  // The sampled kernel of `op` over `count` queries (the ids of topolab_cgal_prepare_sample,
  // checked by the Rust wrapper); null for an operator without one (boundary-curves).
  virtual std::unique_ptr<topolab_cgal_sample> prepare_sample(int op, const uint32_t *ids,
                                                              size_t count) const = 0;
  virtual void prepare_workload(int workload) = 0;
  virtual double workload(int workload) = 0;

  // For the translation units that change it (edit_surface_mesh.cpp, edit_polyhedron.cpp):
  // the Surface_mesh itself, or the Polyhedron_3 with its id tables (polyhedron::Adapter of
  // polyhedron.h: an edit keeps the tables).
  virtual void *native() = 0;
  // Called after building (topolab_cgal_finish, outside the timed build) and after those
  // changed it wholesale (the changing workloads, the garbage collection): the Polyhedron's
  // id tables are built in list order (its erased elements leave the lists at once); a
  // Surface_mesh's indices are its own.
  virtual void renumber() = 0;
  // Bytes its records take by their numbers, with the lab's tables (topolab_cgal_heap_bytes).
  virtual uint64_t declared_bytes() const = 0;
};

namespace topolab_cgal {

using Mesh = ::topolab_cgal_mesh;

// The builders, one per translation unit: the mesh, or null with *failed_face set when CGAL
// refused a face.
std::unique_ptr<Mesh> build_surface_mesh(const Input &input, uint32_t *failed_face);
std::unique_ptr<Mesh> build_polyhedron(const Input &input, uint32_t *failed_face);

// The shim's one process-wide action, done once whichever thread gets here first (shim.cpp):
// CGAL's failure behaviour pinned to THROW_EXCEPTION, so that every failure CGAL reports
// (CGAL_error, which NDEBUG keeps) reaches the guard below as an exception, never abort() or
// exit(), whatever the process chose before. Nothing else is process-wide: with verbose off
// (the Polyhedron builder's default) CGAL writes nothing, and the hull kernel's rounding-mode
// changes are per thread.
void setup_once();

// Runs `body` with every exception caught: the C API's wall (no exception may cross
// `extern "C"` into Rust, which would abort). Returns TOPOLAB_CGAL_OK or the failure.
template <class F> int guard(F &&body) noexcept {
  try {
    setup_once();
    return body();
  } catch (const std::bad_alloc &) {
    return TOPOLAB_CGAL_OUT_OF_MEMORY;
  } catch (...) {
    return TOPOLAB_CGAL_EXCEPTION;
  }
}

}  // namespace topolab_cgal

#endif
