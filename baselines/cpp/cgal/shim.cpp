// The C API of shim.h over the structures of surface_mesh.cpp and polyhedron.cpp: each call
// runs inside the exception wall (mesh.h, guard) and forwards to the mesh. The only CGAL
// header here is the one of the set-up (its failure behaviour).

#include "mesh.h"

#include <CGAL/assertions.h>  // set_error_behaviour (defined there in header-only CGAL)
#include <CGAL/version.h>     // CGAL_VERSION_STR, for the report

using topolab_cgal::guard;

// A function-local static is initialised exactly once, thread-safely (C++11), by whichever
// thread calls first; CGAL's behaviour variable is then only read. If the initialiser threw,
// the exception would reach the caller's guard and the next call would try again.
void topolab_cgal::setup_once() {
  static const bool done = [] {
    CGAL::set_error_behaviour(CGAL::THROW_EXCEPTION);
    return true;
  }();
  (void)done;
}

namespace {
bool known_op(int op) { return op >= 0 && op < topolab_cgal::OP_COUNT; }
bool known_workload(int w) { return w >= 0 && w < topolab_cgal::WORKLOAD_COUNT; }
}  // namespace

extern "C" {

const char *topolab_cgal_version() noexcept { return CGAL_VERSION_STR; }

int topolab_cgal_build(int structure, const double *xyz, uint32_t vertices,
                       const uint32_t *indices, const uint32_t *offsets, uint32_t faces,
                       uint32_t edges_hint, topolab_cgal_mesh **out,
                       uint32_t *failed_face) noexcept {
  return guard([&] {
    if (structure != TOPOLAB_CGAL_SURFACE_MESH && structure != TOPOLAB_CGAL_POLYHEDRON)
      return TOPOLAB_CGAL_UNKNOWN_CODE;
    const topolab_cgal::Input input{xyz, vertices, indices, offsets, faces, edges_hint};
    std::unique_ptr<topolab_cgal::Mesh> mesh =
        structure == TOPOLAB_CGAL_SURFACE_MESH
            ? topolab_cgal::build_surface_mesh(input, failed_face)
            : topolab_cgal::build_polyhedron(input, failed_face);
    if (!mesh) return TOPOLAB_CGAL_REFUSED;
    *out = mesh.release();
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_finish(topolab_cgal_mesh *mesh) noexcept {
  return guard([&] {
    mesh->renumber();
    return TOPOLAB_CGAL_OK;
  });
}

void topolab_cgal_free(topolab_cgal_mesh *mesh) noexcept { delete mesh; }

int topolab_cgal_heap_bytes(const topolab_cgal_mesh *mesh, uint64_t *out) noexcept {
  return guard([&] {
    *out = mesh->declared_bytes();
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_summary(const topolab_cgal_mesh *mesh, uint32_t *out) noexcept {
  return guard([&] {
    mesh->summary(out);
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_position(const topolab_cgal_mesh *mesh, uint32_t v, double *out) noexcept {
  return guard([&] {
    mesh->position(v, out);
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_edge_vertices(const topolab_cgal_mesh *mesh, uint32_t e, uint32_t *out) noexcept {
  return guard([&] {
    mesh->edge_vertices(e, out);
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_is_boundary_vertex(const topolab_cgal_mesh *mesh, uint32_t v, int *out) noexcept {
  return guard([&] {
    *out = mesh->is_boundary_vertex(v) ? 1 : 0;
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_is_boundary_edge(const topolab_cgal_mesh *mesh, uint32_t e, int *out) noexcept {
  return guard([&] {
    *out = mesh->is_boundary_edge(e) ? 1 : 0;
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_query(const topolab_cgal_mesh *mesh, int op, uint32_t id, topolab_cgal_emit emit,
                       void *context) noexcept {
  return guard([&] {
    if (!known_op(op)) return TOPOLAB_CGAL_UNKNOWN_CODE;
    mesh->query(op, id, emit, context);
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_edge_neighbour(const topolab_cgal_mesh *mesh, uint32_t e, uint32_t f,
                                int successor, int64_t *out) noexcept {
  return guard([&] {
    *out = mesh->edge_neighbour(e, f, successor != 0);
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_boundary_curves(const topolab_cgal_mesh *mesh, topolab_cgal_emit emit,
                                 topolab_cgal_end_curve end_curve, void *context) noexcept {
  return guard([&] {
    mesh->boundary_curves(emit, end_curve, context);
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_halfedge(const topolab_cgal_mesh *mesh, uint32_t h, uint32_t *out) noexcept {
  return guard([&] {
    mesh->halfedge_record(h, out);
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_vertex_halfedge(const topolab_cgal_mesh *mesh, uint32_t v, uint32_t *out) noexcept {
  return guard([&] {
    *out = mesh->vertex_halfedge(v);
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_face_halfedge(const topolab_cgal_mesh *mesh, uint32_t f, uint32_t *out) noexcept {
  return guard([&] {
    *out = mesh->face_halfedge(f);
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_validate(const topolab_cgal_mesh *mesh, int *problem, uint32_t *element) noexcept {
  return guard([&] {
    *problem = mesh->validate(element);
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_sweep(const topolab_cgal_mesh *mesh, int op, uint64_t *out) noexcept {
  return guard([&] {
    if (!known_op(op)) return TOPOLAB_CGAL_UNKNOWN_CODE;
    *out = mesh->sweep(op);
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_prepare_sample(const topolab_cgal_mesh *mesh, int op, const uint32_t *ids,
                                size_t count, topolab_cgal_sample **out) noexcept {
  return guard([&] {
    if (!known_op(op)) return TOPOLAB_CGAL_UNKNOWN_CODE;
    std::unique_ptr<topolab_cgal_sample> sample = mesh->prepare_sample(op, ids, count);
    if (!sample) return TOPOLAB_CGAL_UNKNOWN_CODE;
    *out = sample.release();
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_sampled(const topolab_cgal_sample *sample, uint64_t *out) noexcept {
  return guard([&] {
    *out = sample->run();
    return TOPOLAB_CGAL_OK;
  });
}

void topolab_cgal_free_sample(topolab_cgal_sample *sample) noexcept { delete sample; }

int topolab_cgal_prepare_workload(topolab_cgal_mesh *mesh, int workload) noexcept {
  return guard([&] {
    if (!known_workload(workload)) return TOPOLAB_CGAL_UNKNOWN_CODE;
    mesh->prepare_workload(workload);
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_workload(topolab_cgal_mesh *mesh, int workload, double *out) noexcept {
  return guard([&] {
    if (!known_workload(workload)) return TOPOLAB_CGAL_UNKNOWN_CODE;
    *out = mesh->workload(workload);
    return TOPOLAB_CGAL_OK;
  });
}

}  // extern "C"
