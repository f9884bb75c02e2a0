// CGAL's Surface_mesh_simplification::edge_collapse with the Garland–Heckbert plane policies
// (GarlandHeckbert_plane_policies: per-face plane quadrics, cost the quadric error, the new
// vertex placed at the quadric's minimiser) on a Surface_mesh, for the report's decimation
// section. CGAL 5.5's stop predicates count edges: the target is a face count turned into
// edges (a closed triangle mesh has 3F/2 edges), and the caller gets the faces it kept.
// Timed here in the thread's CPU time around edge_collapse() alone (the policies' quadrics
// are computed inside it); building and compacting the mesh are outside the clock, as for the
// other decimaters. Nothing here slows it: Eigen solves the 4x4 quadrics (invert_matrix_4),
// the points are the Surface_mesh's own property map and its indices are its own. Its cost
// is the package's design: every cost or placement computed builds an Edge_profile (vectors of
// the link's vertices and triangles, allocated each time), and every collapse gathers the
// edges to update in a std::set. Callgrind, 16k torus to 10%: 516 M instructions, 12 % of
// them in free and 7 % in malloc, 8 % inverting the 4x4 matrices.
//
// The same C API discipline as shim.cpp: every exception is caught (none reaches Rust), a
// status from shim.h is returned, results go to out-parameters sized by the caller.

// Eigen's 4x4 matrices copied inside CGAL's quadric storage trip GCC's -Wmaybe-uninitialized
// (a false positive in the library's headers, as OpenMesh's Property.hh does for shim.cpp).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <ctime>
#include <new>

#include "shim.h"

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
namespace SMS = CGAL::Surface_mesh_simplification;

// The calling thread's CPU time in seconds, as the report times the lab's decimater (its
// Stopwatch): time slices other processes take on the loaded machine do not count.
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

template <class F> int guard(F &&body) noexcept {
  try {
    return body();
  } catch (const std::bad_alloc &) {
    return TOPOLAB_CGAL_OUT_OF_MEMORY;
  } catch (...) {
    return TOPOLAB_CGAL_EXCEPTION;
  }
}

}  // namespace

extern "C" int topolab_cgal_decimate(const double *xyz, uint32_t vertices,
                                     const uint32_t *triangles, uint32_t faces, uint32_t target,
                                     double *out_xyz, uint32_t *out_vertices,
                                     uint32_t *out_triangles, uint32_t *out_faces,
                                     double *seconds) noexcept {
  return guard([&] {
    SurfaceMesh m;
    m.reserve(vertices, size_t(faces) * 3 / 2 + 3, faces);
    for (uint32_t v = 0; v < vertices; ++v)
      m.add_vertex(Point(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]));
    for (uint32_t f = 0; f < faces; ++f) {
      using VI = SurfaceMesh::Vertex_index;
      if (m.add_face(VI(triangles[3 * f]), VI(triangles[3 * f + 1]), VI(triangles[3 * f + 2])) ==
          SurfaceMesh::null_face())
        return TOPOLAB_CGAL_REFUSED;
    }
    const size_t edges = size_t(target) * 3 / 2;
    SMS::Count_stop_predicate<SurfaceMesh> stop(edges);
    SMS::GarlandHeckbert_plane_policies<SurfaceMesh, Kernel> policies(m);
    const double started = thread_seconds();
    SMS::edge_collapse(m, stop,
                       CGAL::parameters::get_cost(policies.get_cost())
                           .get_placement(policies.get_placement()));
    *seconds = thread_seconds() - started;
    m.collect_garbage();
    uint32_t nv = 0, nf = 0;
    for (auto v : m.vertices()) {
      const Point &p = m.point(v);
      out_xyz[3 * nv] = p.x();
      out_xyz[3 * nv + 1] = p.y();
      out_xyz[3 * nv + 2] = p.z();
      ++nv;
    }
    for (auto f : m.faces()) {
      uint32_t k = 0;
      for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) {
        if (k < 3) out_triangles[3 * nf + k] = uint32_t(v);
        ++k;
      }
      ++nf;
    }
    *out_vertices = nv;
    *out_faces = nf;
    return TOPOLAB_CGAL_OK;
  });
}
