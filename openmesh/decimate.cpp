// OpenMesh's Decimater with ModQuadric, for the report's decimation section: the whole
// decimation runs in C++, timed here in the thread's CPU time around initialize() and
// decimate_to_faces() (what topolab's decimate() does: quadrics, heap, collapses; building
// the mesh and compacting it afterwards are outside the clock on both sides).
//
// Why the mesh type below overrides two of OpenMesh's functions. Debian's libopenmesh 9.0 is
// compiled without NDEBUG (Debian builds CMake projects with build type "None"; OpenMesh's
// documented build is Release), so every property access inside the compiled library runs
// PropertyContainer.hh's `assert(internal_type_name() == get_type_name<T>())`: two
// std::string built, compared and freed, and an out-of-line is_valid_handle() per handle
// step. The Decimater itself is a header template, compiled here at -O3 -DNDEBUG, but its
// legality test calls two functions of the compiled library, TriConnectivity::is_collapse_ok
// and PolyConnectivity::find_halfedge. Callgrind on a 16k torus (to 10%): 2.79 G
// instructions, 87 % of them in the library's is_collapse_ok (309 689 calls, 7 873
// instructions each, 21 string allocations each), the same 190 k instructions per removed
// face at 4k and 16k (linear, not quadratic). DecimaterT<Mesh> calls them on its Mesh type,
// so the type below hides both with the same tests written out here, compiled as a release
// build of OpenMesh would compile them: 0.39 G instructions for the same run, and the same
// result mesh bit for bit (the test in src/native_decimate.rs decimates with both and
// compares). The rest of the library (collapse(), add_face(), garbage_collection()) still
// runs as Debian ships it: collapse() is about 12 % of the decimation's instructions.
//
// The same C API discipline as shim.cpp: every exception is caught (none reaches Rust), a
// status from shim.h is returned, results go to out-parameters sized by the caller.

#include "shim.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <ctime>
#include <ios>
#include <new>
#include <vector>

namespace {

struct Traits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
// The mesh as Debian's library compiles it (used by the test that compares the two).
using Shipped = OpenMesh::TriMesh_ArrayKernelT<Traits>;

// The mesh the report decimates: OpenMesh's, with the Decimater's two calls into the
// compiled library (see the top of the file) compiled here instead. Each keeps OpenMesh 9.0's
// documented contract and order of tests, so the Decimater's choices do not change.
struct Tri : Shipped {
  using Shipped::find_halfedge;

  // TriConnectivity::is_collapse_ok: may the half-edge v0 -> v1 collapse? Refused when the
  // edge or an end is deleted, when a triangle beside it has its two other edges on the
  // boundary, when vl and vr (the apexes of the two triangles) coincide or are both missing,
  // when the one-rings of v0 and v1 share a vertex other than vl and vr (the link condition;
  // tagged with the status bit, as the library does), and when an interior edge joins two
  // boundary vertices.
  bool is_collapse_ok(HalfedgeHandle v0v1) {
    if (status(edge_handle(v0v1)).deleted()) return false;
    const HalfedgeHandle v1v0 = opposite_halfedge_handle(v0v1);
    const VertexHandle v0 = to_vertex_handle(v1v0), v1 = to_vertex_handle(v0v1);
    if (status(v0).deleted() || status(v1).deleted()) return false;
    // The apex of the triangle left of `h` into `apex`; false when its two other edges are
    // both on the boundary.
    const auto side_ok = [this](HalfedgeHandle h, VertexHandle &apex) {
      if (is_boundary(h)) return true;
      const HalfedgeHandle h1 = next_halfedge_handle(h), h2 = next_halfedge_handle(h1);
      apex = to_vertex_handle(h1);
      return !(is_boundary(opposite_halfedge_handle(h1)) &&
               is_boundary(opposite_halfedge_handle(h2)));
    };
    VertexHandle vl, vr;
    if (!side_ok(v0v1, vl) || !side_ok(v1v0, vr) || vl == vr) return false;
    for (const VertexHandle w : vv_range(v0)) status(w).set_tagged(false);
    for (const VertexHandle w : vv_range(v1)) status(w).set_tagged(true);
    for (const VertexHandle w : vv_range(v0))
      if (status(w).tagged() && w != vl && w != vr) return false;
    return !(is_boundary(v0) && is_boundary(v1) && !is_boundary(v0v1) && !is_boundary(v1v0));
  }

  // PolyConnectivity::find_halfedge: the half-edge from `from` to `to`, or an invalid one.
  OpenMesh::SmartHalfedgeHandle find_halfedge(VertexHandle from, VertexHandle to) const {
    for (const OpenMesh::SmartHalfedgeHandle h : voh_range(from))
      if (h.to() == to) return h;
    return OpenMesh::SmartHalfedgeHandle();
  }
};

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
template <class Decimater>
[[gnu::noinline]] double timed_decimation(Decimater &decimater, uint32_t target) {
  const double started = thread_seconds();
  decimater.initialize();
  decimater.decimate_to_faces(0, target);
  return thread_seconds() - started;
}

template <class F> int guard(F &&body) noexcept {
  try {
    return body();
  } catch (const std::bad_alloc &) {
    return TOPOLAB_OM_OUT_OF_MEMORY;
  } catch (...) {
    return TOPOLAB_OM_EXCEPTION;
  }
}

// The decimation on mesh type M (Tri or Shipped); the arguments are topolab_om_decimate's.
template <class M>
int decimate(const double *xyz, uint32_t vertices, const uint32_t *triangles, uint32_t faces,
             uint32_t target, double *out_xyz, uint32_t *out_vertices, uint32_t *out_triangles,
             uint32_t *out_faces, double *seconds) noexcept {
  return guard([&] {
    // add_face's refusals are returned as a status, not printed (shim.cpp silences omerr
    // the same way; doing it again is harmless).
    static const bool silenced = [] {
      omerr().disable();
      omerr().setstate(std::ios::badbit | std::ios::failbit);
      return true;
    }();
    (void)silenced;
    M m;
    m.reserve(vertices, size_t(faces) * 3 / 2 + 3, faces);
    for (uint32_t v = 0; v < vertices; ++v)
      m.add_vertex(typename M::Point(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]));
    for (uint32_t f = 0; f < faces; ++f) {
      const typename M::VertexHandle a{int(triangles[3 * f])}, b{int(triangles[3 * f + 1])},
          c{int(triangles[3 * f + 2])};
      if (!m.add_face(a, b, c).is_valid()) return TOPOLAB_OM_REFUSED;
    }
    // The Decimater requests the vertex, edge and face status it deletes with (its
    // constructor); is_collapse_ok tags the one-ring in the vertex status bits.
    using Decimater = OpenMesh::Decimater::DecimaterT<M>;
    using Quadric = OpenMesh::Decimater::ModQuadricT<M>;
    Decimater decimater(m);
    typename Quadric::Handle quadric;
    decimater.add(quadric);
    *seconds = timed_decimation(decimater, target);
    m.garbage_collection();
    uint32_t nv = 0, nf = 0;
    for (auto v : m.vertices()) {
      const typename M::Point &p = m.point(v);
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

}  // namespace

extern "C" int topolab_om_decimate(const double *xyz, uint32_t vertices,
                                   const uint32_t *triangles, uint32_t faces, uint32_t target,
                                   double *out_xyz, uint32_t *out_vertices,
                                   uint32_t *out_triangles, uint32_t *out_faces,
                                   double *seconds) noexcept {
  return decimate<Tri>(xyz, vertices, triangles, faces, target, out_xyz, out_vertices,
                       out_triangles, out_faces, seconds);
}

// The same with the library's own is_collapse_ok and find_halfedge, as Debian ships them: for
// the test that both give the same mesh, and for measuring what the library's build costs.
extern "C" int topolab_om_decimate_shipped(const double *xyz, uint32_t vertices,
                                           const uint32_t *triangles, uint32_t faces,
                                           uint32_t target, double *out_xyz,
                                           uint32_t *out_vertices, uint32_t *out_triangles,
                                           uint32_t *out_faces, double *seconds) noexcept {
  return decimate<Shipped>(xyz, vertices, triangles, faces, target, out_xyz, out_vertices,
                           out_triangles, out_faces, seconds);
}
