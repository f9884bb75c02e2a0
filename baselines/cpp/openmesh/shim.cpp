// The C API of shim.h over OpenMesh. Every loop here uses OpenMesh the way its documentation
// recommends (ranges over elements, circulator ranges, handles; no property lookups in loops),
// so that a sweep measures OpenMesh, not the FFI.

#include "mesh.h"
#include "../common/operators.h"

#include <cmath>
#include <ios>
#include <memory>
#include <new>
#include <type_traits>
#include <vector>

namespace {

// The mesh types, the set-up and the guard (mesh.h).
using namespace topolab_om;

// The operator and workload codes, the checksum mix and the dispatch, as CGAL's shim has them
// (../common/operators.h).
using namespace topolab_shim;

constexpr uint64_t edge_key(uint32_t a, uint32_t b) {
  return a < b ? (uint64_t(a) << 32) | b : (uint64_t(b) << 32) | a;
}

// What the mesh's containers hold by their lengths: the array kernel's records (a vertex's
// outgoing halfedge; an edge's two halfedges, each to-vertex, next, prev and face; a face's
// halfedge), the traits' data item of every element (an empty struct of one byte with
// OpenMesh's default traits, stored all the same), and the elements of every property whose
// element size OpenMesh knows (the positions, and what a workload or an edit requested:
// normals, status). The data items are the only properties whose size it does not know.
template <class M> uint64_t declared_bytes(const M &m) {
  uint64_t bytes = m.n_vertices() * (sizeof(OpenMesh::ArrayItems::Vertex) +
                                     sizeof(typename M::VertexData)) +
                   m.n_halfedges() * sizeof(typename M::HalfedgeData) +
                   m.n_edges() * (sizeof(OpenMesh::ArrayItems::Edge) +
                                  sizeof(typename M::EdgeData)) +
                   m.n_faces() * (sizeof(OpenMesh::ArrayItems::Face) +
                                  sizeof(typename M::FaceData));
  const auto add = [&](auto begin, auto end) {
    for (auto p = begin; p != end; ++p)
      if (*p != nullptr && (*p)->element_size() != OpenMesh::BaseProperty::UnknownSize)
        bytes += (*p)->n_elements() * (*p)->element_size();
  };
  add(m.vprops_begin(), m.vprops_end());
  add(m.hprops_begin(), m.hprops_end());
  add(m.eprops_begin(), m.eprops_end());
  add(m.fprops_begin(), m.fprops_end());
  return bytes;
}

// How an answer enters a checksum: vertices and faces by index, edges by their end vertices.
template <class M> uint64_t key(const M &, VH v) { return uint32_t(v.idx()); }
template <class M> uint64_t key(const M &, FH f) { return uint32_t(f.idx()); }
template <class M> uint64_t key(const M &m, EH e) {
  const HH h = m.halfedge_handle(e, 0);
  return edge_key(m.to_vertex_handle(h).idx(), m.from_vertex_handle(h).idx());
}
template <class M> uint64_t key(const M &m, HH h) { return key(m, m.edge_handle(h)); }

// The lab's boundary vertex: incident to a boundary edge. OpenMesh's is_boundary(vh) is also
// true for an isolated vertex, and its outgoing halfedge is a boundary one when one exists.
template <class M> bool is_boundary_vertex(const M &m, VH v) {
  const HH h = m.halfedge_handle(v);
  return h.is_valid() && m.is_boundary(h);
}

// The halfedge of edge e in face f, or an invalid handle when e does not bound f: where the
// successor and predecessor of e in f start.
template <class M> HH side_in(const M &m, EH e, FH f) {
  for (int side = 0; side < 2; ++side) {
    const HH h = m.halfedge_handle(e, side);
    if (m.face_handle(h) == f) return h;
  }
  return HH();
}

// Relation `Op` of element `id`: one emit per answer (a handle).
template <int Op, class M, class Emit> inline void relation(const M &m, int id, Emit &&emit) {
  if constexpr (Op == R00) {
    for (VH w : m.vv_range(VH(id))) emit(w);
  } else if constexpr (Op == R01) {
    for (EH e : m.ve_range(VH(id))) emit(e);
  } else if constexpr (Op == R02) {
    for (FH f : m.vf_range(VH(id))) emit(f);
  } else if constexpr (Op == R11) {
    for (int side = 0; side < 2; ++side) {
      const HH h = m.halfedge_handle(EH(id), side);
      if (m.is_boundary(h)) continue;
      for (HH x = m.next_halfedge_handle(h); x != h; x = m.next_halfedge_handle(x))
        emit(m.edge_handle(x));
    }
  } else if constexpr (Op == R12) {
    for (int side = 0; side < 2; ++side) {
      const FH f = m.face_handle(m.halfedge_handle(EH(id), side));
      if (f.is_valid()) emit(f);
    }
  } else if constexpr (Op == R20) {
    for (VH v : m.fv_ccw_range(FH(id))) emit(v);
  } else if constexpr (Op == R21) {
    for (EH e : m.fe_ccw_range(FH(id))) emit(e);
  } else if constexpr (Op == R22) {
    for (FH g : m.ff_ccw_range(FH(id))) emit(g);
  }
}

// The checksum term of one query element (harness/src/checksum.rs, per-operator table).
template <int Op, class M> inline uint64_t term(const M &m, int id) {
  uint64_t sum = 0;
  if constexpr (Op == R00 || Op == R01 || Op == R02 || Op == R20 || Op == R21 || Op == R22) {
    const uint64_t q = uint32_t(id);
    relation<Op>(m, id, [&](auto h) { sum += mix(q, key(m, h)); });
  } else if constexpr (Op == R11 || Op == R12) {
    const uint64_t q = key(m, EH(id));
    relation<Op>(m, id, [&](auto h) { sum += mix(q, key(m, h)); });
  } else if constexpr (Op == R10) {
    const uint64_t k = key(m, EH(id));
    sum = mix(k >> 32, k & 0xFFFFFFFFULL);
  } else if constexpr (Op == BOUNDARY_VERTEX) {
    if (is_boundary_vertex(m, VH(id))) sum = mix(uint32_t(id), 1);
  } else if constexpr (Op == BOUNDARY_EDGE) {
    if (m.is_boundary(EH(id))) sum = mix(key(m, EH(id)), 1);
  } else if constexpr (Op == EDGE_SUCCESSOR || Op == EDGE_PREDECESSOR) {
    for (HH h : m.fh_ccw_range(FH(id))) {
      const HH other =
          Op == EDGE_SUCCESSOR ? m.next_halfedge_handle(h) : m.prev_halfedge_handle(h);
      sum += mix(key(m, h), key(m, other));
    }
  }
  return sum;
}

// The checksum term of one (edge, face) query of edge-successor or edge-predecessor, as the
// harness's generic kernel sums it: nothing when e does not bound f.
template <int Op, class M> inline uint64_t neighbour_term(const M &m, EH e, FH f) {
  const HH h = side_in(m, e, f);
  if (!h.is_valid()) return 0;
  const HH other = Op == EDGE_SUCCESSOR ? m.next_halfedge_handle(h) : m.prev_halfedge_handle(h);
  return mix(key(m, h), key(m, other));
}

// Calls on_loop(start halfedge, length) once per boundary loop, stepping from a boundary
// halfedge to the next with step(h).
template <class M, class Step, class OnLoop>
void boundary_loops(const M &m, Step &&step, OnLoop &&on_loop) {
  std::vector<bool> seen(m.n_halfedges(), false);
  for (HH start : m.halfedges()) {
    if (seen[start.idx()] || !m.is_boundary(start)) continue;
    uint32_t length = 0;
    HH h = start;
    do {
      seen[h.idx()] = true;
      ++length;
      h = step(h);
    } while (h != start);
    on_loop(start, length);
  }
}

// The boundary halfedge after boundary halfedge h by the lab's definition of a boundary curve
// (per fan): from h's opposite, turn around h's target through the faces of that fan (prev,
// then opposite) until the opposite is a boundary halfedge. At a vertex of one fan this is
// next_halfedge(h); at a vertex of several fans OpenMesh's own next may lead into another fan.
template <class M> HH next_in_fan(const M &m, HH h) {
  HH x = m.opposite_halfedge_handle(h);
  for (;;) {
    const HH q = m.opposite_halfedge_handle(m.prev_halfedge_handle(x));
    if (m.is_boundary(q)) return q;
    x = q;
  }
}

// The timed kernel walks OpenMesh's own boundary links (next_halfedge), as its users do: on
// the report's meshes every vertex is one fan, where they are the curves of next_in_fan.
template <class M> uint64_t boundary_curves_checksum(const M &m) {
  uint64_t sum = 0;
  const auto next = [&](HH h) { return m.next_halfedge_handle(h); };
  boundary_loops(m, next, [&](HH start, uint32_t length) {
    HH h = start;
    do {
      sum += mix(length, key(m, h));
      h = next(h);
    } while (h != start);
  });
  return sum;
}

// The elements a sweep of Op runs over.
template <int Op, class M> auto query_elements(const M &m) {
  if constexpr (Op == R00 || Op == R01 || Op == R02 || Op == BOUNDARY_VERTEX) {
    return m.vertices();
  } else if constexpr (Op == R10 || Op == R11 || Op == R12 || Op == BOUNDARY_EDGE) {
    return m.edges();
  } else {
    return m.faces();
  }
}

template <int Op, class M> uint64_t sweep(const M &m) {
  if constexpr (Op == BOUNDARY_CURVES) {
    return boundary_curves_checksum(m);
  } else {
    uint64_t sum = 0;
    for (auto element : query_elements<Op>(m)) sum += term<Op>(m, element.idx());
    return sum;
  }
}

// The sampled queries: `count` ids (OpenMesh's handles are these indices), or `count` (edge,
// face) pairs for successor and predecessor. Boundary curves have none (the caller refuses).
template <int Op, class M> uint64_t sampled(const M &m, const uint32_t *ids, size_t count) {
  uint64_t sum = 0;
  if constexpr (Op == EDGE_SUCCESSOR || Op == EDGE_PREDECESSOR) {
    for (size_t i = 0; i < count; ++i)
      sum += neighbour_term<Op>(m, EH(int(ids[2 * i])), FH(int(ids[2 * i + 1])));
  } else if constexpr (Op != BOUNDARY_CURVES) {
    for (size_t i = 0; i < count; ++i) sum += term<Op>(m, int(ids[i]));
  }
  return sum;
}


// Surface_mesh benchmark: count vertex-face incidences from both sides. Returns the count, or
// NaN when the two sides disagree (the benchmark's assertion).
template <class M> double circulators(const M &m) {
  int64_t counter = 0;
  for (VH v : m.vertices())
    for (FH f : m.vf_range(v)) {
      (void)f;
      ++counter;
    }
  const int64_t counted = counter;
  for (FH f : m.faces())
    for (VH v : m.fv_ccw_range(f)) {
      (void)v;
      --counter;
    }
  return counter == 0 ? double(counted) : std::nan("");
}

// The mean of all positions; returns the sum of its coordinates.
template <class M> double barycenter(const M &m) {
  typename M::Point center(0.0, 0.0, 0.0);
  for (VH v : m.vertices()) center += m.point(v);
  if (m.n_vertices() > 0) center /= double(m.n_vertices());
  return center[0] + center[1] + center[2];
}

// Face normals, then vertex normals (normalised sum of unit face normals); returns the sum of
// the vertex normals' coordinates. Normals must have been requested (prepare_workload).
template <class M> double normals(M &m) {
  m.update_face_normals();
  m.update_vertex_normals();
  double sum = 0.0;
  for (VH v : m.vertices()) {
    const auto &n = m.normal(v);
    sum += n[0] + n[1] + n[2];
  }
  return sum;
}

// One step of uniform Laplacian smoothing of interior vertices into a buffer reused across
// calls (as the Rust kernel writes into a caller-owned buffer); the mesh is left unchanged so
// that repeated timed runs compute the same step. Returns the sum of all new coordinates.
template <class M> double smoothing(const M &m) {
  static thread_local std::vector<typename M::Point> next;
  next.resize(m.n_vertices());
  for (VH v : m.vertices()) {
    next[v.idx()] = m.point(v);
    if (m.is_boundary(v)) continue;
    typename M::Point sum(0.0, 0.0, 0.0);
    unsigned valence = 0;
    for (VH w : m.vv_range(v)) {
      sum += m.point(w);
      ++valence;
    }
    if (valence > 0) next[v.idx()] = sum / double(valence);
  }
  double total = 0.0;
  for (const auto &p : next) total += p[0] + p[1] + p[2];
  return total;
}

template <class M>
bool fill(M &m, const double *xyz, uint32_t vertices, const uint32_t *indices,
          const uint32_t *offsets, uint32_t faces, uint32_t edges_hint, uint32_t *failed_face) {
  m.reserve(vertices, edges_hint, faces);
  for (uint32_t i = 0; i < vertices; ++i)
    m.add_vertex(typename M::Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]));
  std::vector<VH> corners;
  for (uint32_t j = 0; j < faces; ++j) {
    FH f;
    const uint32_t *begin = indices + offsets[j], *end = indices + offsets[j + 1];
    if (std::is_base_of<OpenMesh::TriConnectivity, M>::value) {
      f = m.add_face(VH(begin[0]), VH(begin[1]), VH(begin[2]));
    } else {
      corners.clear();
      for (const uint32_t *c = begin; c != end; ++c) corners.push_back(VH(*c));
      f = m.add_face(corners);
    }
    if (!f.is_valid()) {
      *failed_face = j;
      return false;
    }
  }
  return true;
}

// The changing workloads as the Surface_mesh benchmark's protocol runs them (pmp-library's
// benchmarks/SurfaceMeshPerformance.h, with OpenMesh's names for the same calls): 0, sqrt3
// subdivision; 1, the collapse test. The status attributes must have been requested.
template <class M> void changing(M &m, int workload) {
  const size_t nv = m.n_vertices(), ne = m.n_edges(), nf = m.n_faces();
  m.reserve(nv + nf, ne + 3 * nf, 3 * nf);
  if (workload == 0) {
    // New positions of the old interior vertices (sqrt3's smoothing rule).
    std::vector<typename M::Point> moved(nv);
    for (size_t i = 0; i < nv; ++i) {
      const VH v{int(i)};
      moved[i] = m.point(v);
      if (m.is_boundary(v)) continue;
      typename M::Point p(0.0, 0.0, 0.0);
      double n = 0.0;
      for (VH w : m.vv_range(v)) {
        p += m.point(w);
        n += 1.0;
      }
      if (n == 0.0) continue;
      const double alpha = (4.0 - 2.0 * std::cos(2.0 * M_PI / n)) / 9.0;
      moved[i] = (1.0 - alpha) * m.point(v) + alpha / n * p;
    }
    for (size_t i = 0; i < nf; ++i) {
      const FH f{int(i)};
      typename M::Point c(0.0, 0.0, 0.0);
      double k = 0.0;
      for (VH v : m.fv_range(f)) {
        c += m.point(v);
        k += 1.0;
      }
      m.split(f, c / k);
    }
    for (size_t i = 0; i < nv; ++i)
      if (!m.is_boundary(VH(int(i)))) m.set_point(VH(int(i)), moved[i]);
    for (size_t i = 0; i < ne; ++i) {
      const EH e{int(i)};
      if (m.is_flip_ok(e)) m.flip(e);
    }
  } else {
    for (size_t i = 0; i < nf; ++i) m.split(FH(int(i)), typename M::Point(0.0, 0.0, 0.0));
    const size_t end = m.n_vertices();
    for (size_t i = nv; i < end; ++i) m.collapse(m.halfedge_handle(VH(int(i))));
    m.garbage_collection();
  }
}

}  // namespace

namespace {
bool known_op(int op) { return op >= 0 && op < OP_COUNT; }
}  // namespace

extern "C" {

int topolab_om_build(const double *xyz, uint32_t vertices, const uint32_t *indices,
                     const uint32_t *offsets, uint32_t faces, int triangles, uint32_t edges_hint,
                     topolab_om_mesh **out, uint32_t *failed_face) noexcept {
  return guard([&] {
    auto mesh = std::make_unique<topolab_om_mesh>();
    bool ok;
    if (triangles) {
      mesh->tri = std::make_unique<Tri>();
      ok = fill(*mesh->tri, xyz, vertices, indices, offsets, faces, edges_hint, failed_face);
    } else {
      mesh->poly = std::make_unique<Poly>();
      ok = fill(*mesh->poly, xyz, vertices, indices, offsets, faces, edges_hint, failed_face);
    }
    if (!ok) return TOPOLAB_OM_REFUSED;
    *out = mesh.release();
    return TOPOLAB_OM_OK;
  });
}

void topolab_om_free(topolab_om_mesh *mesh) noexcept { delete mesh; }

int topolab_om_heap_bytes(const topolab_om_mesh *mesh, uint64_t *out) noexcept {
  return guard([&] {
    *out = with_mesh(mesh, [](const auto &m) { return declared_bytes(m); });
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_summary(const topolab_om_mesh *mesh, uint32_t *out) noexcept {
  return guard([&] {
    out[0] = mesh->tri ? 1 : 0;
    with_mesh(mesh, [&](const auto &m) {
      out[1] = uint32_t(m.n_vertices());
      out[2] = uint32_t(m.n_edges());
      out[3] = uint32_t(m.n_faces());
      return 0;
    });
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_position(const topolab_om_mesh *mesh, uint32_t v, double *out) noexcept {
  return guard([&] {
    return with_mesh(mesh, [&](const auto &m) {
      const auto &p = m.point(VH(int(v)));
      out[0] = p[0];
      out[1] = p[1];
      out[2] = p[2];
      return TOPOLAB_OM_OK;
    });
  });
}

int topolab_om_edge_vertices(const topolab_om_mesh *mesh, uint32_t e, uint32_t *out) noexcept {
  return guard([&] {
    return with_mesh(mesh, [&](const auto &m) {
      const HH h = m.halfedge_handle(EH(int(e)), 0);
      out[0] = uint32_t(m.from_vertex_handle(h).idx());
      out[1] = uint32_t(m.to_vertex_handle(h).idx());
      return TOPOLAB_OM_OK;
    });
  });
}

int topolab_om_is_boundary_vertex(const topolab_om_mesh *mesh, uint32_t v, int *out) noexcept {
  return guard([&] {
    *out = with_mesh(mesh, [&](const auto &m) { return is_boundary_vertex(m, VH(int(v))) ? 1 : 0; });
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_is_boundary_edge(const topolab_om_mesh *mesh, uint32_t e, int *out) noexcept {
  return guard([&] {
    *out = with_mesh(mesh, [&](const auto &m) { return m.is_boundary(EH(int(e))) ? 1 : 0; });
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_query(const topolab_om_mesh *mesh, int op, uint32_t id, topolab_om_emit emit,
                     void *context) noexcept {
  return guard([&] {
    if (!known_op(op)) return TOPOLAB_OM_UNKNOWN_CODE;
    with_mesh(mesh, [&](const auto &m) {
      return dispatch(op, [&](auto code) -> uint64_t {
        relation<decltype(code)::value>(m, int(id),
                                        [&](auto h) { emit(context, uint32_t(h.idx())); });
        return 0;
      });
    });
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_edge_neighbour(const topolab_om_mesh *mesh, uint32_t e, uint32_t f, int successor,
                              int64_t *out) noexcept {
  return guard([&] {
    *out = with_mesh(mesh, [&](const auto &m) -> int64_t {
      const HH h = side_in(m, EH(int(e)), FH(int(f)));
      if (!h.is_valid()) return -1;
      const HH other = successor ? m.next_halfedge_handle(h) : m.prev_halfedge_handle(h);
      return m.edge_handle(other).idx();
    });
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_boundary_curves(const topolab_om_mesh *mesh, topolab_om_emit emit,
                               topolab_om_end_curve end_curve, void *context) noexcept {
  return guard([&] {
    with_mesh(mesh, [&](const auto &m) {
      // The lab's definition (per fan), which info and the conformance suite ask for.
      const auto next = [&](HH h) { return next_in_fan(m, h); };
      boundary_loops(m, next, [&](HH start, uint32_t) {
        HH h = start;
        do {
          emit(context, uint32_t(m.edge_handle(h).idx()));
          h = next(h);
        } while (h != start);
        end_curve(context);
      });
      return 0;
    });
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_halfedge(const topolab_om_mesh *mesh, uint32_t h, uint32_t *out) noexcept {
  return guard([&] {
    return with_mesh(mesh, [&](const auto &m) {
      const HH heh{int(h)};
      const FH f = m.face_handle(heh);
      out[0] = uint32_t(m.to_vertex_handle(heh).idx());
      out[1] = uint32_t(m.next_halfedge_handle(heh).idx());
      out[2] = uint32_t(m.prev_halfedge_handle(heh).idx());
      out[3] = f.is_valid() ? uint32_t(f.idx()) : UINT32_MAX;
      return TOPOLAB_OM_OK;
    });
  });
}

int topolab_om_vertex_halfedge(const topolab_om_mesh *mesh, uint32_t v, uint32_t *out) noexcept {
  return guard([&] {
    *out = with_mesh(mesh, [&](const auto &m) {
      const HH h = m.halfedge_handle(VH(int(v)));
      return h.is_valid() ? uint32_t(h.idx()) : UINT32_MAX;
    });
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_face_halfedge(const topolab_om_mesh *mesh, uint32_t f, uint32_t *out) noexcept {
  return guard([&] {
    *out = with_mesh(mesh, [&](const auto &m) { return uint32_t(m.halfedge_handle(FH(int(f))).idx()); });
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_validate(const topolab_om_mesh *mesh, int *problem, uint32_t *element) noexcept {
  return guard([&] {
    *problem = with_mesh(mesh, [&](const auto &m) {
      for (HH h : m.halfedges()) {
        const HH next = m.next_halfedge_handle(h);
        const bool linked = next.is_valid() && m.prev_halfedge_handle(next) == h &&
                            m.from_vertex_handle(next) == m.to_vertex_handle(h) &&
                            m.face_handle(next) == m.face_handle(h);
        if (!linked) {
          *element = uint32_t(h.idx());
          return 1;
        }
      }
      for (VH v : m.vertices()) {
        const HH h = m.halfedge_handle(v);
        if (h.is_valid() && m.from_vertex_handle(h) != v) {
          *element = uint32_t(v.idx());
          return 2;
        }
      }
      for (FH f : m.faces()) {
        if (m.face_handle(m.halfedge_handle(f)) != f) {
          *element = uint32_t(f.idx());
          return 3;
        }
      }
      return 0;
    });
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_sweep(const topolab_om_mesh *mesh, int op, uint64_t *out) noexcept {
  return guard([&] {
    if (!known_op(op)) return TOPOLAB_OM_UNKNOWN_CODE;
    *out = with_mesh(mesh, [&](const auto &m) {
      return dispatch(op, [&](auto code) { return sweep<decltype(code)::value>(m); });
    });
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_sampled(const topolab_om_mesh *mesh, int op, const uint32_t *ids, size_t count,
                       uint64_t *out) noexcept {
  return guard([&] {
    if (!known_op(op) || op == BOUNDARY_CURVES) return TOPOLAB_OM_UNKNOWN_CODE;
    *out = with_mesh(mesh, [&](const auto &m) {
      return dispatch(op, [&](auto code) { return sampled<decltype(code)::value>(m, ids, count); });
    });
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_prepare_workload(topolab_om_mesh *mesh, int workload) noexcept {
  return guard([&] {
    if (workload < CIRCULATORS || workload > SMOOTHING) return TOPOLAB_OM_UNKNOWN_CODE;
    if (workload != NORMALS || mesh->normals_requested) return TOPOLAB_OM_OK;
    with_mesh_mut(mesh, [](auto &m) {
      m.request_face_normals();
      m.request_vertex_normals();
      return 0;
    });
    mesh->normals_requested = true;
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_workload(topolab_om_mesh *mesh, int workload, double *out) noexcept {
  const int prepared = topolab_om_prepare_workload(mesh, workload);
  if (prepared != TOPOLAB_OM_OK) return prepared;
  return guard([&] {
    *out = with_mesh_mut(mesh, [&](auto &m) {
      switch (workload) {
        case CIRCULATORS: return circulators(m);
        case BARYCENTER: return barycenter(m);
        case NORMALS: return normals(m);
        default: return smoothing(m);
      }
    });
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_prepare_changing(topolab_om_mesh *mesh) noexcept {
  return guard([&] {
    if (!mesh->tri) return TOPOLAB_OM_UNKNOWN_CODE;
    mesh->tri->request_vertex_status();
    mesh->tri->request_edge_status();
    mesh->tri->request_face_status();
    return TOPOLAB_OM_OK;
  });
}

// The changing workloads (changing() above) on the mesh.
int topolab_om_changing(topolab_om_mesh *mesh, int workload) noexcept {
  const int prepared = topolab_om_prepare_changing(mesh);
  if (prepared != TOPOLAB_OM_OK) return prepared;
  if (workload != 0 && workload != 1) return TOPOLAB_OM_UNKNOWN_CODE;
  return guard([&] {
    changing(*mesh->tri, workload);
    return TOPOLAB_OM_OK;
  });
}

}  // extern "C"
