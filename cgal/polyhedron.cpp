// CGAL::Polyhedron_3 for the shim: the classical pointer-based halfedge structure (its default
// HalfedgeDS_list: every vertex, halfedge pair and facet its own list node), built with
// Polyhedron_incremental_builder_3 and queried through kernels.h.
//
// The incremental builder rather than Polygon_mesh_processing::polygon_soup_to_polygon_mesh:
// the builder is Polyhedron_3's own construction interface, keeps the input order, and reports
// a face it cannot add (its error flag) -- polygon_soup_to_polygon_mesh ignores a refused face
// outside debug builds (its check is an assertion), so it would build a wrong mesh silently.
//
// Ids: CGAL::Polyhedron_items_with_id_3 stores one id per vertex, halfedge and facet (the way
// CGAL gives a Polyhedron indices); vertex i is the builder's i-th vertex, facet j its j-th
// facet, and the halfedges of edge e get ids 2e and 2e + 1. Tables from id to handle are the
// way in from an id (the lab's pointer half-edge keeps the same tables).

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_incremental_builder_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include "kernels.h"

namespace topolab_cgal {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Polyhedron = CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3>;
using HDS = Polyhedron::HalfedgeDS;
using VH = Polyhedron::Vertex_handle;
using HH = Polyhedron::Halfedge_handle;
using FH = Polyhedron::Facet_handle;

struct PolyhedronAdapter {
  using Graph = Polyhedron;
  using Point = topolab_cgal::Point;
  Polyhedron mesh;
  std::vector<VH> vertices;
  std::vector<FH> facets;
  std::vector<HH> edges;  // edge e's halfedge 2e

  const Graph &graph() const { return mesh; }
  uint32_t vid(VH v) const { return uint32_t(v->id()); }
  uint32_t fid(FH f) const { return uint32_t(f->id()); }
  uint32_t hid(HH h) const { return uint32_t(h->id()); }
  VH vertex(uint32_t i) const { return vertices[i]; }
  FH face(uint32_t i) const { return facets[i]; }
  HH halfedge_at(uint32_t h) const { return h & 1 ? edges[h / 2]->opposite() : edges[h / 2]; }
  uint32_t num_vertices() const { return uint32_t(vertices.size()); }
  uint32_t num_edges() const { return uint32_t(edges.size()); }
  uint32_t num_faces() const { return uint32_t(facets.size()); }
  const Point &point(VH v) const { return v->point(); }
  // A vertex's halfedge need not be a border one in a Polyhedron_3, so this circulates
  // (CGAL::is_border(v, g): the first border halfedge around v), O(k).
  bool is_boundary_vertex(VH v) const {
    return v->halfedge() != HH() && bool(CGAL::is_border(v, mesh));
  }
  // Level 0 of Polyhedron_3 is its halfedge data structure's level 3: links, vertex and face
  // cycles (level 1 would also ask for a normalized border, which the builder does not keep).
  // It calls a vertex without a halfedge corrupted, but the lab keeps unused input vertices
  // (ids are the input's): with such vertices only the link checks of kernels.h run.
  bool cgal_is_valid() const {
    for (VH v : vertices)
      if (v->halfedge() == HH()) return true;
    return mesh.is_valid(/*verbose=*/false, /*level=*/0);
  }
  // The ids and tables from the lists' order (after building, and after a change).
  void renumber();
};

void PolyhedronAdapter::renumber() {
  vertices.clear();
  facets.clear();
  edges.clear();
  vertices.reserve(mesh.size_of_vertices());
  for (auto v = mesh.vertices_begin(); v != mesh.vertices_end(); ++v) {
    v->id() = vertices.size();
    vertices.push_back(v);
  }
  facets.reserve(mesh.size_of_facets());
  for (auto f = mesh.facets_begin(); f != mesh.facets_end(); ++f) {
    f->id() = facets.size();
    facets.push_back(f);
  }
  // Edge_iterator visits one halfedge of each pair.
  edges.reserve(mesh.size_of_halfedges() / 2);
  for (auto e = mesh.edges_begin(); e != mesh.edges_end(); ++e) {
    e->id() = 2 * edges.size();
    e->opposite()->id() = 2 * edges.size() + 1;
    edges.push_back(e);
  }
}

// The incremental builder, run by Polyhedron_3::delegate on the halfedge data structure.
class Builder : public CGAL::Modifier_base<HDS> {
 public:
  Builder(const Input &in, uint32_t *failed_face) : in_(in), failed_face_(failed_face) {}
  bool refused() const { return refused_; }

  void operator()(HDS &hds) override {
    CGAL::Polyhedron_incremental_builder_3<HDS> b(hds, /*verbose=*/false);
    b.begin_surface(in_.vertices, in_.faces, 2 * size_t(in_.edges_hint));
    for (uint32_t i = 0; i < in_.vertices; ++i)
      b.add_vertex(Point(in_.xyz[3 * i], in_.xyz[3 * i + 1], in_.xyz[3 * i + 2]));
    for (uint32_t j = 0; j < in_.faces; ++j) {
      b.add_facet(in_.indices + in_.offsets[j], in_.indices + in_.offsets[j + 1]);
      if (b.error()) {
        *failed_face_ = j;
        refused_ = true;
        b.rollback();
        break;
      }
    }
    b.end_surface();
  }

 private:
  const Input &in_;
  uint32_t *failed_face_;
  bool refused_ = false;
};

}  // namespace

std::unique_ptr<Mesh> build_polyhedron(const Input &in, uint32_t *failed_face) {
  auto built = std::make_unique<CgalMesh<PolyhedronAdapter>>();
  PolyhedronAdapter &a = built->adapter();
  Builder builder(in, failed_face);
  a.mesh.delegate(builder);
  if (builder.refused()) return nullptr;
  a.renumber();
  return built;
}

}  // namespace topolab_cgal
