// OpenMesh's Decimater with ModQuadric, for the report's decimation section: the whole
// decimation runs in C++, timed here in the thread's CPU time around initialize() and
// decimate_to_faces() (what topolab's decimate() does: quadrics, heap, collapses; building
// the mesh and compacting it afterwards are outside the clock on both sides). The Decimater
// and its module are OpenMesh's header templates, compiled here; what they call of the
// library (is_collapse_ok, find_halfedge, valence, collapse) is OpenMesh's compiled code,
// built from the same source tree at -O3 -DNDEBUG (build.rs).
//
// The same C API discipline as shim.cpp: every exception is caught (none reaches Rust), a
// status from shim.h is returned, results go to out-parameters sized by the caller.

#include "mesh.h"

#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <ctime>

namespace {

using topolab_om::guard;
using topolab_om::Tri;
using VH = topolab_om::VH;
using Decimater = OpenMesh::Decimater::DecimaterT<Tri>;
using Quadric = OpenMesh::Decimater::ModQuadricT<Tri>;

// The calling thread's CPU time in seconds, as the report times the lab's decimater (its
// Stopwatch): time slices other processes take on the loaded machine do not count.
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

// The timed region: the Decimater's initialize() and decimate_to_faces(), in a call of its
// own so that `valgrind --tool=callgrind --toggle-collect='*timed_decimation*'` counts it
// alone (examples/openmesh_profile.rs); one call per decimation, nothing else changes.
[[gnu::noinline]] double timed_decimation(Decimater &decimater, uint32_t target) {
  const double started = thread_seconds();
  decimater.initialize();
  decimater.decimate_to_faces(0, target);
  return thread_seconds() - started;
}

}  // namespace

extern "C" int topolab_om_decimate(const double *xyz, uint32_t vertices,
                                   const uint32_t *triangles, uint32_t faces, uint32_t target,
                                   double *out_xyz, uint32_t *out_vertices,
                                   uint32_t *out_triangles, uint32_t *out_faces,
                                   double *seconds) noexcept {
  // guard() (mesh.h) also silences omerr once: add_face's refusals are returned as a status,
  // not printed.
  return guard([&] {
    Tri m;
    m.reserve(vertices, size_t(faces) * 3 / 2 + 3, faces);
    for (uint32_t v = 0; v < vertices; ++v)
      m.add_vertex(Tri::Point(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]));
    for (uint32_t f = 0; f < faces; ++f) {
      const VH a{int(triangles[3 * f])}, b{int(triangles[3 * f + 1])}, c{int(triangles[3 * f + 2])};
      if (!m.add_face(a, b, c).is_valid()) return TOPOLAB_OM_REFUSED;
    }
    // The Decimater requests the vertex, edge and face status it deletes with (its
    // constructor); is_collapse_ok tags the one-ring in the vertex status bits.
    Decimater decimater(m);
    Quadric::Handle quadric;
    decimater.add(quadric);
    *seconds = timed_decimation(decimater, target);
    m.garbage_collection();
    uint32_t nv = 0, nf = 0;
    for (auto v : m.vertices()) {
      const Tri::Point &p = m.point(v);
      out_xyz[3 * nv] = p[0];
      out_xyz[3 * nv + 1] = p[1];
      out_xyz[3 * nv + 2] = p[2];
      ++nv;
    }
    for (auto f : m.faces()) {
      uint32_t k = 0;
      for (auto v : m.fv_range(f)) {
        if (k < 3) out_triangles[3 * nf + k] = uint32_t(v.idx());
        ++k;
      }
      ++nf;
    }
    *out_vertices = nv;
    *out_faces = nf;
    return TOPOLAB_OM_OK;
  });
}
