// OpenMesh's Decimater with ModQuadric, for the report's decimation section: the whole
// decimation runs in C++, timed here around initialize() and decimate_to_faces() (what
// topolab's decimate() does: quadrics, heap, collapses; building the mesh and compacting it
// afterwards are outside the clock on both sides).
//
// The same C API discipline as shim.cpp: every exception is caught (none reaches Rust), a
// status from shim.h is returned, results go to out-parameters sized by the caller.

#include "shim.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <chrono>
#include <ios>
#include <new>
#include <vector>

namespace {

struct Traits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using Tri = OpenMesh::TriMesh_ArrayKernelT<Traits>;

template <class F> int guard(F &&body) noexcept {
  try {
    return body();
  } catch (const std::bad_alloc &) {
    return TOPOLAB_OM_OUT_OF_MEMORY;
  } catch (...) {
    return TOPOLAB_OM_EXCEPTION;
  }
}

}  // namespace

extern "C" int topolab_om_decimate(const double *xyz, uint32_t vertices,
                                   const uint32_t *triangles, uint32_t faces, uint32_t target,
                                   double *out_xyz, uint32_t *out_vertices,
                                   uint32_t *out_triangles, uint32_t *out_faces,
                                   double *seconds) noexcept {
  return guard([&] {
    // add_face's refusals are returned as a status, not printed (shim.cpp silences omerr
    // the same way; doing it again is harmless).
    static const bool silenced = [] {
      omerr().disable();
      omerr().setstate(std::ios::badbit | std::ios::failbit);
      return true;
    }();
    (void)silenced;
    Tri m;
    m.reserve(vertices, size_t(faces) * 3 / 2 + 3, faces);
    for (uint32_t v = 0; v < vertices; ++v)
      m.add_vertex(Tri::Point(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]));
    for (uint32_t f = 0; f < faces; ++f) {
      const Tri::VertexHandle a{int(triangles[3 * f])}, b{int(triangles[3 * f + 1])},
          c{int(triangles[3 * f + 2])};
      if (!m.add_face(a, b, c).is_valid()) return TOPOLAB_OM_REFUSED;
    }
    // The decimater deletes with status flags; with the half-edge flags too, is_collapse_ok
    // tags the one-ring in them instead of in a temporary property it adds and removes (by
    // name) on every call.
    m.request_vertex_status();
    m.request_halfedge_status();
    m.request_edge_status();
    m.request_face_status();
    using Decimater = OpenMesh::Decimater::DecimaterT<Tri>;
    using Quadric = OpenMesh::Decimater::ModQuadricT<Tri>;
    Decimater decimater(m);
    Quadric::Handle quadric;
    decimater.add(quadric);
    const auto started = std::chrono::steady_clock::now();
    decimater.initialize();
    decimater.decimate_to_faces(0, target);
    const auto stopped = std::chrono::steady_clock::now();
    *seconds = std::chrono::duration<double>(stopped - started).count();
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
