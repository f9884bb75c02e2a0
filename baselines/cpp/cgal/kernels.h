// Every query, sweep, sampled kernel and workload of the CGAL shim, written once over CGAL's
// BGL interface (the free functions next, prev, opposite, target, face and the circulator
// ranges of <CGAL/boost/graph/iterator.h>), which both CGAL::Surface_mesh and
// CGAL::Polyhedron_3 model and CGAL's own algorithms use on both. Each translation unit
// instantiates CgalMesh with its structure's Adapter (surface_mesh.cpp, polyhedron.cpp), so
// every loop is compiled for that structure alone: a sweep measures CGAL, not the FFI.
//
// An Adapter gives what BGL leaves to each structure: the graph, the lab's ids of elements
// (Surface_mesh's own indices; Polyhedron's ids stored in its items), elements by id, and the
// boundary-vertex test each structure's documentation gives.
//
//   struct Adapter {
//     using Graph = ...; using Point = ...;
//     const Graph &graph() const;
//     uint32_t vid(vertex_descriptor), fid(face_descriptor), hid(halfedge_descriptor);
//     vertex_descriptor vertex(uint32_t); face_descriptor face(uint32_t);
//     halfedge_descriptor halfedge_at(uint32_t h);            // edge e: halfedges 2e, 2e + 1
//     uint32_t num_vertices(), num_edges(), num_faces();
//     bool is_boundary_vertex(vertex_descriptor);             // incident to a boundary edge
//     const Point &point(vertex_descriptor);
//     bool cgal_is_valid();                                   // the structure's is_valid()
//     uint64_t declared_bytes();                              // its records, by their numbers
//   };

#ifndef TOPOLAB_CGAL_KERNELS_H
#define TOPOLAB_CGAL_KERNELS_H

#include "mesh.h"

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cmath>
#include <type_traits>
#include <utility>
#include <vector>

namespace topolab_cgal {

template <class Adapter> class CgalMesh final : public Mesh {
  using Graph = typename Adapter::Graph;
  using Traits = boost::graph_traits<Graph>;
  using VD = typename Traits::vertex_descriptor;
  using HD = typename Traits::halfedge_descriptor;
  using FD = typename Traits::face_descriptor;
  using Kernel = typename CGAL::Kernel_traits<typename Adapter::Point>::Kernel;
  using Vector = typename Kernel::Vector_3;

 public:
  // The structure, filled in place by its builder (CGAL's meshes are not moved: a
  // Surface_mesh's property maps point into it).
  Adapter &adapter() { return a_; }

  void *native() override { return a_.native(); }
  void renumber() override { a_.renumber(); }
  uint64_t declared_bytes() const override { return a_.declared_bytes(); }

  void summary(uint32_t *out) const override {
    out[0] = a_.num_vertices();
    out[1] = a_.num_edges();
    out[2] = a_.num_faces();
  }

  void position(uint32_t v, double *out) const override {
    const auto &p = a_.point(a_.vertex(v));
    out[0] = p.x();
    out[1] = p.y();
    out[2] = p.z();
  }

  void edge_vertices(uint32_t e, uint32_t *out) const override {
    const HD h = a_.halfedge_at(2 * e);
    out[0] = a_.vid(source(h, g()));
    out[1] = a_.vid(target(h, g()));
  }

  bool is_boundary_vertex(uint32_t v) const override {
    return a_.is_boundary_vertex(a_.vertex(v));
  }

  bool is_boundary_edge(uint32_t e) const override {
    return CGAL::is_border_edge(a_.halfedge_at(2 * e), g());
  }

  void query(int op, uint32_t id, topolab_cgal_emit emit, void *context) const override {
    dispatch(op, [&](auto code) -> uint64_t {
      constexpr int Code = decltype(code)::value;
      relation<Code>(element<Code>(id), [&](uint32_t answer) { emit(context, answer); });
      return 0;
    });
  }

  int64_t edge_neighbour(uint32_t e, uint32_t f, bool successor) const override {
    const HD h = side_in(a_.halfedge_at(2 * e), a_.face(f));
    if (h == Traits::null_halfedge()) return -1;
    return eid(successor ? next(h, g()) : prev(h, g()));
  }

  void boundary_curves(topolab_cgal_emit emit, topolab_cgal_end_curve end_curve,
                       void *context) const override {
    // The lab's definition (per fan), which info and the conformance suite ask for.
    const auto step = [&](HD h) { return next_in_fan(h); };
    boundary_loops(step, [&](HD start, uint32_t) {
      HD h = start;
      do {
        emit(context, eid(h));
        h = step(h);
      } while (h != start);
      end_curve(context);
    });
  }

  void halfedge_record(uint32_t index, uint32_t *out) const override {
    const HD h = a_.halfedge_at(index);
    const FD f = face(h, g());
    out[0] = a_.vid(target(h, g()));
    out[1] = a_.hid(next(h, g()));
    out[2] = a_.hid(prev(h, g()));
    out[3] = f == Traits::null_face() ? UINT32_MAX : a_.fid(f);
  }

  uint32_t vertex_halfedge(uint32_t v) const override {
    const HD h = halfedge(a_.vertex(v), g());
    return h == Traits::null_halfedge() ? UINT32_MAX : a_.hid(h);
  }

  uint32_t face_halfedge(uint32_t f) const override {
    return a_.hid(halfedge(a_.face(f), g()));
  }

  int validate(uint32_t *element) const override {
    for (HD h : halfedges(g())) {
      const HD n = next(h, g());
      const bool linked = n != Traits::null_halfedge() && prev(n, g()) == h &&
                          source(n, g()) == target(h, g()) &&
                          face(n, g()) == face(h, g()) &&
                          opposite(opposite(h, g()), g()) == h;
      if (!linked) {
        *element = a_.hid(h);
        return 1;
      }
    }
    for (VD v : vertices(g())) {
      const HD h = halfedge(v, g());
      if (h != Traits::null_halfedge() && target(h, g()) != v) {
        *element = a_.vid(v);
        return 2;
      }
    }
    for (FD f : faces(g())) {
      if (face(halfedge(f, g()), g()) != f) {
        *element = a_.fid(f);
        return 3;
      }
    }
    return a_.cgal_is_valid() ? 0 : 4;
  }

  uint64_t sweep(int op) const override {
    return dispatch(op, [&](auto code) -> uint64_t {
      constexpr int Code = decltype(code)::value;
      if constexpr (Code == BOUNDARY_CURVES) {
        uint64_t sum = 0;
        // CGAL's own boundary links, as its users walk a hole: on the report's meshes every
        // vertex is one fan, where they are the curves of next_in_fan.
        const auto step = [&](HD h) { return next(h, g()); };
        boundary_loops(step, [&](HD start, uint32_t length) {
          HD h = start;
          do {
            sum += mix(length, key(h));
            h = step(h);
          } while (h != start);
        });
        return sum;
      } else {
        uint64_t sum = 0;
        for (auto element : elements<Code>()) sum += term<Code>(from_range<Code>(element));
        return sum;
      }
    });
  }

  std::unique_ptr<topolab_cgal_sample> prepare_sample(int op, const uint32_t *ids,
                                                      size_t count) const override {
    std::unique_ptr<topolab_cgal_sample> prepared;
    dispatch(op, [&](auto code) -> uint64_t {
      constexpr int Code = decltype(code)::value;
      if constexpr (Code != BOUNDARY_CURVES) {
        auto sample = std::make_unique<Sample<Code>>(*this);
        sample->queries.reserve(count);
        for (size_t i = 0; i < count; ++i) {
          if constexpr (Code == EDGE_SUCCESSOR || Code == EDGE_PREDECESSOR) {
            sample->queries.emplace_back(a_.halfedge_at(2 * ids[2 * i]), a_.face(ids[2 * i + 1]));
          } else {
            sample->queries.push_back(element<Code>(ids[i]));
          }
        }
        prepared = std::move(sample);
      }
      return 0;
    });
    return prepared;
  }

  void prepare_workload(int workload) override {
    if (workload == NORMALS) {
      face_normals_.resize(a_.num_faces());
      vertex_normals_.resize(a_.num_vertices());
    } else if (workload == SMOOTHING) {
      smoothed_.resize(a_.num_vertices());
    }
  }

  double workload(int workload) override {
    prepare_workload(workload);
    switch (workload) {
      case CIRCULATORS: return circulators();
      case BARYCENTER: return barycenter();
      case NORMALS: return normals();
      default: return smoothing();
    }
  }

 private:
  // The sampled queries of operator Op in the structure's descriptors: the element each asks
  // about (an edge by its halfedge 2e), or (edge, face) for successor and predecessor. run() is
  // compiled for Op alone, as a sweep is, and reads no id table.
  template <int Op> struct Sample final : topolab_cgal_sample {
    static constexpr bool kPairs = Op == EDGE_SUCCESSOR || Op == EDGE_PREDECESSOR;
    // The descriptor element<Op> gives for an id.
    using Element = decltype(std::declval<const CgalMesh &>().template element<Op>(0));
    using Query = std::conditional_t<kPairs, std::pair<HD, FD>, Element>;

    explicit Sample(const CgalMesh &mesh) : mesh(mesh) {}

    uint64_t run() const override {
      uint64_t sum = 0;
      for (const Query &q : queries) {
        if constexpr (kPairs) {
          sum += mesh.template neighbour_term<Op>(q.first, q.second);
        } else {
          sum += mesh.template term<Op>(q);
        }
      }
      return sum;
    }

    const CgalMesh &mesh;
    std::vector<Query> queries;
  };

  const Graph &g() const { return a_.graph(); }
  uint32_t eid(HD h) const { return a_.hid(h) / 2; }

  // How an answer enters a checksum: vertices and faces by index, edges by their end vertices.
  uint64_t key(HD h) const {
    return edge_key(a_.vid(source(h, g())), a_.vid(target(h, g())));
  }

  // The side of edge x (one of its halfedges) in face f, or null_halfedge when x does not
  // bound f: where the successor and predecessor of the edge in f start.
  HD side_in(HD x, FD f) const {
    for (HD h : {x, opposite(x, g())})
      if (face(h, g()) == f) return h;
    return Traits::null_halfedge();
  }

  // The checksum term of one (edge, face) query of edge-successor or edge-predecessor, as the
  // harness's generic kernel sums it: nothing when the edge does not bound the face.
  template <int Op> uint64_t neighbour_term(HD x, FD f) const {
    const HD h = side_in(x, f);
    if (h == Traits::null_halfedge()) return 0;
    return mix(key(h), key(Op == EDGE_SUCCESSOR ? next(h, g()) : prev(h, g())));
  }

  // The kind of element operator Op asks about, by id (edges by their halfedge 2e).
  template <int Op> auto element(uint32_t id) const {
    if constexpr (Op == R00 || Op == R01 || Op == R02 || Op == BOUNDARY_VERTEX) {
      return a_.vertex(id);
    } else if constexpr (Op == R10 || Op == R11 || Op == R12 || Op == BOUNDARY_EDGE) {
      return a_.halfedge_at(2 * id);
    } else {
      return a_.face(id);
    }
  }

  // The elements a sweep of Op runs over, in the structure's order, and the element of an
  // item of that range (an edge by one of its halfedges).
  template <int Op> auto elements() const {
    if constexpr (Op == R00 || Op == R01 || Op == R02 || Op == BOUNDARY_VERTEX) {
      return vertices(g());
    } else if constexpr (Op == R10 || Op == R11 || Op == R12 || Op == BOUNDARY_EDGE) {
      return edges(g());
    } else {
      return faces(g());
    }
  }
  template <int Op, class Item> auto from_range(Item item) const {
    if constexpr (Op == R10 || Op == R11 || Op == R12 || Op == BOUNDARY_EDGE) {
      return halfedge(item, g());
    } else {
      return item;
    }
  }

  // Relation Op of an element: one emit per answer, as the lab's id.
  template <int Op, class Element, class Emit> void relation(Element x, Emit &&emit) const {
    if constexpr (Op == R00 || Op == R01 || Op == R02) {
      const HD h = halfedge(x, g());
      if (h == Traits::null_halfedge()) return;  // an isolated vertex
      if constexpr (Op == R00) {
        for (VD w : vertices_around_target(h, g())) emit(a_.vid(w));
      } else if constexpr (Op == R01) {
        for (HD y : halfedges_around_target(h, g())) emit(eid(y));
      } else {
        for (FD f : faces_around_target(h, g()))
          if (f != Traits::null_face()) emit(a_.fid(f));
      }
    } else if constexpr (Op == R11) {
      for (HD side : {x, opposite(x, g())}) {
        if (CGAL::is_border(side, g())) continue;
        for (HD y = next(side, g()); y != side; y = next(y, g())) emit(eid(y));
      }
    } else if constexpr (Op == R12) {
      for (HD side : {x, opposite(x, g())}) {
        const FD f = face(side, g());
        if (f != Traits::null_face()) emit(a_.fid(f));
      }
    } else if constexpr (Op == R20) {
      for (VD v : vertices_around_face(halfedge(x, g()), g())) emit(a_.vid(v));
    } else if constexpr (Op == R21) {
      for (HD y : halfedges_around_face(halfedge(x, g()), g())) emit(eid(y));
    } else if constexpr (Op == R22) {
      for (FD f : faces_around_face(halfedge(x, g()), g()))
        if (f != Traits::null_face()) emit(a_.fid(f));
    }
  }

  // The checksum term of one query element (harness/src/checksum.rs, per-operator table).
  // Answers enter by key, so relations circulate here directly instead of through ids.
  template <int Op, class Element> uint64_t term(Element x) const {
    uint64_t sum = 0;
    if constexpr (Op == R00 || Op == R01 || Op == R02) {
      const uint64_t q = a_.vid(x);
      const HD h = halfedge(x, g());
      if (h == Traits::null_halfedge()) return 0;
      if constexpr (Op == R00) {
        for (VD w : vertices_around_target(h, g())) sum += mix(q, a_.vid(w));
      } else if constexpr (Op == R01) {
        for (HD y : halfedges_around_target(h, g())) sum += mix(q, key(y));
      } else {
        for (FD f : faces_around_target(h, g()))
          if (f != Traits::null_face()) sum += mix(q, a_.fid(f));
      }
    } else if constexpr (Op == R10) {
      const uint64_t k = key(x);
      sum = mix(k >> 32, k & 0xFFFFFFFFULL);
    } else if constexpr (Op == R11) {
      const uint64_t q = key(x);
      for (HD side : {x, opposite(x, g())}) {
        if (CGAL::is_border(side, g())) continue;
        for (HD y = next(side, g()); y != side; y = next(y, g())) sum += mix(q, key(y));
      }
    } else if constexpr (Op == R12) {
      const uint64_t q = key(x);
      for (HD side : {x, opposite(x, g())}) {
        const FD f = face(side, g());
        if (f != Traits::null_face()) sum += mix(q, a_.fid(f));
      }
    } else if constexpr (Op == R20) {
      const uint64_t q = a_.fid(x);
      for (VD v : vertices_around_face(halfedge(x, g()), g())) sum += mix(q, a_.vid(v));
    } else if constexpr (Op == R21) {
      const uint64_t q = a_.fid(x);
      for (HD y : halfedges_around_face(halfedge(x, g()), g())) sum += mix(q, key(y));
    } else if constexpr (Op == R22) {
      const uint64_t q = a_.fid(x);
      for (FD f : faces_around_face(halfedge(x, g()), g()))
        if (f != Traits::null_face()) sum += mix(q, a_.fid(f));
    } else if constexpr (Op == BOUNDARY_VERTEX) {
      if (a_.is_boundary_vertex(x)) sum = mix(a_.vid(x), 1);
    } else if constexpr (Op == BOUNDARY_EDGE) {
      if (CGAL::is_border_edge(x, g())) sum = mix(key(x), 1);
    } else if constexpr (Op == EDGE_SUCCESSOR || Op == EDGE_PREDECESSOR) {
      for (HD h : halfedges_around_face(halfedge(x, g()), g()))
        sum += mix(key(h), key(Op == EDGE_SUCCESSOR ? next(h, g()) : prev(h, g())));
    }
    return sum;
  }

  // Calls on_loop(start halfedge, length) once per boundary loop, stepping from a border
  // halfedge to the next with step(h).
  template <class Step, class OnLoop> void boundary_loops(Step &&step, OnLoop &&on_loop) const {
    std::vector<bool> seen(2 * size_t(a_.num_edges()), false);
    for (HD start : halfedges(g())) {
      if (seen[a_.hid(start)] || !CGAL::is_border(start, g())) continue;
      uint32_t length = 0;
      HD h = start;
      do {
        seen[a_.hid(h)] = true;
        ++length;
        h = step(h);
      } while (h != start);
      on_loop(start, length);
    }
  }

  // The border halfedge after border halfedge h by the lab's definition of a boundary curve
  // (per fan): from h's opposite, turn around h's target through the faces of that fan (prev,
  // then opposite) until the opposite is a border halfedge. At a vertex of one fan this is
  // next(h); at a vertex of several fans CGAL's own next may lead into another fan.
  HD next_in_fan(HD h) const {
    HD x = opposite(h, g());
    for (;;) {
      const HD q = opposite(prev(x, g()), g());
      if (CGAL::is_border(q, g())) return q;
      x = q;
    }
  }

  Vector vector_of(VD v) const { return a_.point(v) - CGAL::ORIGIN; }

  // glam's normalize_or_zero, as the lab's kernel normalises.
  static Vector normalize_or_zero(const Vector &n) {
    const double reciprocal = 1.0 / std::sqrt(n.squared_length());
    return std::isfinite(reciprocal) && reciprocal > 0.0 ? n * reciprocal : CGAL::NULL_VECTOR;
  }

  // Surface_mesh benchmark: count vertex-face incidences from both sides. Returns the count, or
  // NaN when the two sides disagree (the benchmark's assertion).
  double circulators() const {
    int64_t counter = 0;
    for (VD v : vertices(g())) {
      const HD h = halfedge(v, g());
      if (h == Traits::null_halfedge()) continue;
      for (FD f : faces_around_target(h, g()))
        if (f != Traits::null_face()) ++counter;
    }
    const int64_t counted = counter;
    for (FD f : faces(g()))
      for (VD v : vertices_around_face(halfedge(f, g()), g())) {
        (void)v;
        --counter;
      }
    return counter == 0 ? double(counted) : std::nan("");
  }

  // The mean of all positions; returns the sum of its coordinates.
  double barycenter() const {
    Vector center = CGAL::NULL_VECTOR;
    for (VD v : vertices(g())) center = center + vector_of(v);
    if (a_.num_vertices() > 0) center = center / double(a_.num_vertices());
    return center.x() + center.y() + center.z();
  }

  // Face normals (Newell's vector, normalised, as the lab computes them), then vertex normals
  // (normalised sum of the unit normals of their faces) into arrays indexed by the lab's ids;
  // returns the sum of the vertex normals' coordinates.
  double normals() {
    for (FD f : faces(g())) {
      Vector newell = CGAL::NULL_VECTOR;
      const HD start = halfedge(f, g());
      HD h = start;
      do {
        newell = newell + cross_product(vector_of(source(h, g())), vector_of(target(h, g())));
        h = next(h, g());
      } while (h != start);
      face_normals_[a_.fid(f)] = normalize_or_zero(newell);
    }
    double sum = 0.0;
    for (VD v : vertices(g())) {
      Vector n = CGAL::NULL_VECTOR;
      const HD h = halfedge(v, g());
      if (h != Traits::null_halfedge())
        for (FD f : faces_around_target(h, g()))
          if (f != Traits::null_face()) n = n + face_normals_[a_.fid(f)];
      n = normalize_or_zero(n);
      vertex_normals_[a_.vid(v)] = n;
      sum += n.x() + n.y() + n.z();
    }
    return sum;
  }

  // One step of uniform Laplacian smoothing of interior vertices into a buffer kept across
  // calls; the mesh is left unchanged so that repeated timed runs compute the same step.
  // Returns the sum of all new coordinates.
  double smoothing() {
    for (VD v : vertices(g())) {
      Vector p = vector_of(v);
      const HD h = halfedge(v, g());
      if (h != Traits::null_halfedge() && !a_.is_boundary_vertex(v)) {
        Vector sum = CGAL::NULL_VECTOR;
        unsigned valence = 0;
        for (VD w : vertices_around_target(h, g())) {
          sum = sum + vector_of(w);
          ++valence;
        }
        if (valence > 0) p = sum / double(valence);
      }
      smoothed_[a_.vid(v)] = p;
    }
    double total = 0.0;
    for (const Vector &p : smoothed_) total += p.x() + p.y() + p.z();
    return total;
  }

  Adapter a_;
  std::vector<Vector> face_normals_, vertex_normals_, smoothed_;
};

}  // namespace topolab_cgal

#endif
