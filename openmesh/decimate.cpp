// OpenMesh's Decimater with ModQuadric, for the report's decimation section: the whole
// decimation runs in C++, timed here in the thread's CPU time around initialize() and
// decimate_to_faces() (what topolab's decimate() does: quadrics, heap, collapses; building
// the mesh and compacting it afterwards are outside the clock on both sides).
//
// Why the mesh type below overrides OpenMesh's functions. Debian's libopenmesh 9.0 is
// compiled without NDEBUG (Debian builds CMake projects with build type "None"; OpenMesh's
// documented build is Release), so every property access inside the compiled library runs
// PropertyContainer.hh's `assert(internal_type_name() == get_type_name<T>())`: two
// std::string built, compared and freed, and an out-of-line is_valid_handle() per handle
// step. The Decimater itself is a header template, compiled here at -O3 -DNDEBUG, but it
// calls four functions of the compiled library: its legality test
// TriConnectivity::is_collapse_ok, PolyConnectivity::find_halfedge and
// PolyConnectivity::valence (BaseDecimaterT::is_collapse_legal), and
// PolyConnectivity::collapse (with collapse_edge, collapse_loop, adjust_outgoing_halfedge).
// DecimaterT<Mesh> calls them on its Mesh type, so the type below hides all four with
// OpenMesh 9.0's algorithm written out (collapse and find_halfedge are mesh.h's Compiled<>,
// which the shim's other kernels use too), compiled as a release build of OpenMesh would
// compile them, with the same result mesh bit for bit (the test in src/native_decimate.rs
// decimates with both and compares).
//
// Callgrind on a 16k torus (16 432 faces to 1 643), the instructions inside
// timed_decimation (`examples/openmesh_profile.rs decimate|decimate-shipped 16384`):
//
// | mesh type | instructions | in libOpenMeshCore |
// |---|---|---|
// | Debian's library as shipped | 2 710.8 M | 89 % is_collapse_ok (307 500 calls, 7 878 each) |
// | is_collapse_ok, find_halfedge compiled here | 321.0 M | collapse(): 47.2 M (7 395 calls), valence 0.02 M |
// | all four compiled here (below) | 276.6 M | none |
//
// The library's collapse() was 14.7 % of the run (its is_valid_handle calls and status
// strings, malloc and free); compiled here, its one part left out of line (collapse_loop) is
// 5.7 M, the rest inlined into the Decimater's loop. What remains is the Decimater's own
// design: a legality test for every outgoing half-edge of every vertex it heaps again.
// add_face() and garbage_collection(), outside the clock, are mesh.h's too.
//
// The same C API discipline as shim.cpp: every exception is caught (none reaches Rust), a
// status from shim.h is returned, results go to out-parameters sized by the caller.

#include "mesh.h"

#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <ctime>
#include <vector>

namespace {

using topolab_om::guard;
using HH = topolab_om::HH;
using VH = topolab_om::VH;
// The mesh as Debian's library compiles it (used by the test that compares the two): every
// call of the Decimater into the library is the library's own.
using Shipped = topolab_om::ShippedTri;

// The mesh the report decimates: OpenMesh's, with every call of the Decimater into the
// compiled library (see the top of the file) compiled here instead. mesh.h's Compiled<> gives
// collapse() (PolyConnectivity::collapse, collapse_edge, collapse_loop,
// adjust_outgoing_halfedge), find_halfedge, and the add_face and garbage_collection that run
// outside the clock; the two below are the Decimater's own. Each keeps OpenMesh 9.0's
// documented contract and order of tests, so the Decimater's choices do not change.
struct Tri : topolab_om::Compiled<Shipped> {
  using Compiled::valence;

  // TriConnectivity::is_collapse_ok: may the half-edge v0 -> v1 collapse? Refused when the
  // edge or an end is deleted, when a triangle beside it has its two other edges on the
  // boundary, when vl and vr (the apexes of the two triangles) coincide or are both missing,
  // when the one-rings of v0 and v1 share a vertex other than vl and vr (the link condition;
  // tagged with the status bit, as the library does), and when an interior edge joins two
  // boundary vertices.
  bool is_collapse_ok(HH v0v1) {
    if (status(edge_handle(v0v1)).deleted()) return false;
    const HH v1v0 = opposite_halfedge_handle(v0v1);
    const VH v0 = to_vertex_handle(v1v0), v1 = to_vertex_handle(v0v1);
    if (status(v0).deleted() || status(v1).deleted()) return false;
    // The apex of the triangle left of `h` into `apex`; false when its two other edges are
    // both on the boundary.
    const auto side_ok = [this](HH h, VH &apex) {
      if (is_boundary(h)) return true;
      const HH h1 = next_halfedge_handle(h), h2 = next_halfedge_handle(h1);
      apex = to_vertex_handle(h1);
      return !(is_boundary(opposite_halfedge_handle(h1)) &&
               is_boundary(opposite_halfedge_handle(h2)));
    };
    VH vl, vr;
    if (!side_ok(v0v1, vl) || !side_ok(v1v0, vr) || vl == vr) return false;
    for (const VH w : vv_range(v0)) status(w).set_tagged(false);
    for (const VH w : vv_range(v1)) status(w).set_tagged(true);
    for (const VH w : vv_range(v0))
      if (status(w).tagged() && w != vl && w != vr) return false;
    return !(is_boundary(v0) && is_boundary(v1) && !is_boundary(v0v1) && !is_boundary(v1v0));
  }

  // PolyConnectivity::valence(vertex): the vertices around it, counted by the same
  // circulator. The Decimater asks it only of the apexes of an edge whose apexes are joined
  // (BaseDecimaterT::is_collapse_legal: two valence-3 apexes refuse the collapse).
  unsigned valence(VH vh) const {
    unsigned count = 0;
    for (auto it = cvv_iter(vh); it.is_valid(); ++it) ++count;
    return count;
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

// The decimation on mesh type M (Tri or Shipped); the arguments are topolab_om_decimate's.
template <class M>
int decimate(const double *xyz, uint32_t vertices, const uint32_t *triangles, uint32_t faces,
             uint32_t target, double *out_xyz, uint32_t *out_vertices, uint32_t *out_triangles,
             uint32_t *out_faces, double *seconds) noexcept {
  // guard() (mesh.h) also silences omerr once: add_face's refusals are returned as a status,
  // not printed.
  return guard([&] {
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

// The same on the mesh type as Debian ships it (the library's own is_collapse_ok,
// find_halfedge, valence, collapse, add_face and garbage_collection): for the test that both
// give the same mesh, and for measuring what the library's build costs.
extern "C" int topolab_om_decimate_shipped(const double *xyz, uint32_t vertices,
                                           const uint32_t *triangles, uint32_t faces,
                                           uint32_t target, double *out_xyz,
                                           uint32_t *out_vertices, uint32_t *out_triangles,
                                           uint32_t *out_faces, double *seconds) noexcept {
  return decimate<Shipped>(xyz, vertices, triangles, faces, target, out_xyz, out_vertices,
                           out_triangles, out_faces, seconds);
}
