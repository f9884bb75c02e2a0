// CGAL::Surface_mesh changed through CGAL's Euler operations (CGAL/boost/graph/
// Euler_operations.h): the changing workloads of the Surface_mesh benchmark, whole, in C++.
//
// The workloads follow CGAL's own Surface_mesh/benchmark (surface_mesh_performance.h,
// subdivision_test and collapse_test), which runs the protocol of Sieger & Botsch:
// - sqrt3: reserve; new positions of the old interior vertices into a property; every old
//   face split at its centroid with Euler::add_center_vertex; the new positions set; every
//   old edge that is not a border flipped with Euler::flip_edge (unchecked, as the benchmark
//   does: after the splits every old interior edge can be flipped);
// - collapse test: reserve; every face split at the origin with add_center_vertex; every new
//   vertex collapsed with Euler::collapse_edge; collect_garbage (commented out in CGAL's
//   benchmark, done here as the protocol and OpenMesh's run do, so the meshes compare).
//   CGAL's benchmark collapses the edge of the new vertex's halfedge, which points *to* the
//   new vertex, so the old neighbour goes and its point is copied onto the new vertex: the
//   same mesh with other labels. Here the halfedge *from* the new vertex is collapsed
//   (collapse_edge removes the source of the edge's halfedge, and a Surface_mesh edge made
//   from a halfedge keeps it), so the new vertex goes and every old vertex keeps its index,
//   as in pmp-library's and OpenMesh's runs: the results compare by their face lists.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <cmath>

#include "edit.h"
#include "mesh.h"

namespace topolab_cgal {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using VI = SurfaceMesh::Vertex_index;
using HI = SurfaceMesh::Halfedge_index;
using EI = SurfaceMesh::Edge_index;
using FI = SurfaceMesh::Face_index;

// The Surface_mesh behind a mesh of the shim (built by surface_mesh.cpp).
SurfaceMesh &surface_mesh(topolab_cgal_mesh *mesh) {
  return *static_cast<SurfaceMesh *>(mesh->native());
}

void sqrt3(SurfaceMesh &m) {
  const size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), nf = m.number_of_faces();
  m.reserve(nv + nf, ne + 3 * nf, 3 * nf);
  auto new_pos = m.add_property_map<VI, Point>("v:topolab_sqrt3").first;
  for (size_t i = 0; i < nv; ++i) {
    const VI v(i);
    if (m.is_border(v)) continue;
    const double n = m.degree(v);
    const double alpha = (4.0 - 2.0 * std::cos(2.0 * CGAL_PI / n)) / 9.0;
    Vector p(0, 0, 0);
    for (VI w : m.vertices_around_target(m.halfedge(v))) p = p + (m.point(w) - CGAL::ORIGIN);
    new_pos[v] = CGAL::ORIGIN + ((1.0 - alpha) * (m.point(v) - CGAL::ORIGIN) + alpha / n * p);
  }
  for (size_t i = 0; i < nf; ++i) {
    const FI f(i);
    Vector p(0, 0, 0);
    double c = 0;
    for (VI w : m.vertices_around_face(m.halfedge(f))) {
      p = p + (m.point(w) - CGAL::ORIGIN);
      c += 1;
    }
    const VI v = m.target(CGAL::Euler::add_center_vertex(m.halfedge(f), m));
    m.point(v) = CGAL::ORIGIN + p / c;
  }
  for (size_t i = 0; i < nv; ++i)
    if (!m.is_border(VI(i))) m.point(VI(i)) = new_pos[VI(i)];
  m.remove_property_map(new_pos);
  for (size_t i = 0; i < ne; ++i)
    if (!m.is_border(EI(i))) CGAL::Euler::flip_edge(m.halfedge(EI(i)), m);
}

void collapse_test(SurfaceMesh &m) {
  const size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), nf = m.number_of_faces();
  m.reserve(nv + nf, ne + 3 * nf, 3 * nf);
  for (size_t i = 0; i < nf; ++i) {
    const VI v = m.target(CGAL::Euler::add_center_vertex(m.halfedge(FI(i)), m));
    m.point(v) = Point(0, 0, 0);
  }
  const size_t end = m.number_of_vertices();
  for (size_t i = nv; i < end; ++i) {
    const HI from_new = m.opposite(m.halfedge(VI(i)));
    CGAL::Euler::collapse_edge(m.edge(from_new), m);
  }
  m.collect_garbage();
}

}  // namespace
}  // namespace topolab_cgal

extern "C" {

int topolab_cgal_sm_changing(topolab_cgal_mesh *mesh, int workload) noexcept {
  using namespace topolab_cgal;
  if (workload != 0 && workload != 1) return TOPOLAB_CGAL_UNKNOWN_CODE;
  const int done = guard([&] {
    SurfaceMesh &m = surface_mesh(mesh);
    if (workload == 0)
      sqrt3(m);
    else
      collapse_test(m);
    return TOPOLAB_CGAL_OK;
  });
  // Also after a failure part-way: the ids must name what the mesh now holds.
  const int renumbered = guard([&] {
    mesh->renumber();
    return TOPOLAB_CGAL_OK;
  });
  return done != TOPOLAB_CGAL_OK ? done : renumbered;
}

}  // extern "C"
