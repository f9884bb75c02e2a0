// CGAL::Polyhedron_3 as the shim holds it, shared by the unit that builds and queries it
// (polyhedron.cpp) and the unit that changes it (edit_polyhedron.cpp): the polyhedron, the
// lab's ids (Polyhedron_items_with_id_3's id fields: ids by handle) and tables of handles by
// id beside it (the way in from an id; the lab's pointer half-edge keeps the same tables).
//
// A Polyhedron_3 appends new vertices, halfedge pairs and facets to its lists and erases an
// element from its list at once, so stable ids are these tables': a new element gets the next
// id, and an erased element's slot holds the handle of a tombstone until renumber() (the
// garbage collection) gives the ids again in list order. The tombstones are one vertex, one
// halfedge pair and one facet in a halfedge data structure of their own, linked to each other
// (each halfedge its own next and prev), so that a query about a deleted id reads a harmless
// record instead of freed memory, and no query pays for a liveness test.

#ifndef TOPOLAB_CGAL_POLYHEDRON_H
#define TOPOLAB_CGAL_POLYHEDRON_H

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include <cstdint>
#include <iterator>
#include <vector>

namespace topolab_cgal {
namespace polyhedron {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Polyhedron = CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3>;
using HDS = Polyhedron::HalfedgeDS;
using VH = Polyhedron::Vertex_handle;
using HH = Polyhedron::Halfedge_handle;
using FH = Polyhedron::Facet_handle;

// The id of every tombstone element (never a live id: the Rust side keeps counts below it).
constexpr uint32_t DEAD = UINT32_MAX;

struct Adapter {
  using Graph = Polyhedron;
  using Point = polyhedron::Point;
  Polyhedron mesh;
  std::vector<VH> vertices;  // by id; a deleted id's slot holds dead_vertex
  std::vector<FH> facets;    // by id; a deleted id's slot holds dead_facet
  std::vector<HH> edges;     // edge e's halfedge 2e; a deleted edge's slot holds dead_halfedge

  Adapter() {
    dead_vertex = graveyard.vertices_push_back(HDS::Vertex());
    dead_halfedge = graveyard.edges_push_back(HDS::Halfedge(), HDS::Halfedge());
    dead_facet = graveyard.faces_push_back(HDS::Face());
    const HH o = dead_halfedge->opposite();
    for (HH h : {dead_halfedge, o}) {
      h->HDS::Halfedge::Base::set_next(h);
      h->HDS::Halfedge::Base::set_prev(h);
      h->HDS::Halfedge::Base::set_vertex(dead_vertex);
      h->id() = DEAD;
    }
    dead_halfedge->HDS::Halfedge::Base::set_face(dead_facet);
    o->HDS::Halfedge::Base::set_face(FH());
    dead_vertex->HDS::Vertex::Base::set_halfedge(dead_halfedge);
    dead_facet->HDS::Face::Base::set_halfedge(dead_halfedge);
    dead_vertex->id() = DEAD;
    dead_facet->id() = DEAD;
  }
  Adapter(const Adapter &) = delete;
  Adapter &operator=(const Adapter &) = delete;

  const Graph &graph() const { return mesh; }
  void *native() { return this; }
  uint32_t vid(VH v) const { return uint32_t(v->id()); }
  uint32_t fid(FH f) const { return uint32_t(f->id()); }
  uint32_t hid(HH h) const { return uint32_t(h->id()); }
  VH vertex(uint32_t i) const { return vertices[i]; }
  FH face(uint32_t i) const { return facets[i]; }
  HH halfedge_at(uint32_t h) const { return h & 1 ? edges[h / 2]->opposite() : edges[h / 2]; }
  // Slots, deleted ones included (ids stay until renumber()).
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
    for (auto v = mesh.vertices_begin(); v != mesh.vertices_end(); ++v)
      if (v->halfedge() == HH()) return true;
    return mesh.is_valid(/*verbose=*/false, /*level=*/0);
  }

  // The list nodes by their numbers (CGAL's items with their list links and ids; halfedges
  // come in pairs, one block each), and the tables by their capacities.
  uint64_t declared_bytes() const {
    return mesh.size_of_vertices() * sizeof(HDS::Vertex) +
           mesh.size_of_halfedges() * sizeof(HDS::Halfedge) +
           mesh.size_of_facets() * sizeof(HDS::Face) + vertices.capacity() * sizeof(VH) +
           facets.capacity() * sizeof(FH) + edges.capacity() * sizeof(HH);
  }

  bool is_dead_vertex(uint32_t i) const { return vertices[i] == dead_vertex; }
  bool is_dead_edge(uint32_t e) const { return edges[e] == dead_halfedge; }
  bool is_dead_facet(uint32_t i) const { return facets[i] == dead_facet; }
  // An erased element's slot (its id read before CGAL erased it).
  void bury_vertex(uint32_t i) { vertices[i] = dead_vertex; }
  void bury_edge(uint32_t e) { edges[e] = dead_halfedge; }
  void bury_facet(uint32_t i) { facets[i] = dead_facet; }

  // The ids and tables from the lists' order (after building, and as the garbage
  // collection): the survivors keep their order, since new elements are appended to the lists
  // and given the next ids (number_new).
  void renumber() {
    vertices.clear();
    facets.clear();
    edges.clear();
    vertices.reserve(mesh.size_of_vertices());
    facets.reserve(mesh.size_of_facets());
    edges.reserve(mesh.size_of_halfedges() / 2);
    number_from(mesh.vertices_begin(), mesh.halfedges_begin(), mesh.facets_begin());
  }

  // Where the lists end now, to number what an edit appends after them (number_new).
  struct Ends {
    Polyhedron::Vertex_iterator v;
    Polyhedron::Halfedge_iterator h;
    Polyhedron::Facet_iterator f;
  };
  Ends ends() {
    auto last = [](auto begin, auto end) { return begin == end ? end : std::prev(end); };
    return {last(mesh.vertices_begin(), mesh.vertices_end()),
            last(mesh.halfedges_begin(), mesh.halfedges_end()),
            last(mesh.facets_begin(), mesh.facets_end())};
  }
  // Gives the next ids to the elements appended after `before` (an edit that erased nothing).
  void number_new(const Ends &before) {
    auto after = [](auto last, auto begin, auto end) {
      return last == end ? begin : std::next(last);
    };
    number_from(after(before.v, mesh.vertices_begin(), mesh.vertices_end()),
                after(before.h, mesh.halfedges_begin(), mesh.halfedges_end()),
                after(before.f, mesh.facets_begin(), mesh.facets_end()));
  }

  HDS graveyard;  // the tombstones' own lists
  VH dead_vertex;
  HH dead_halfedge;
  FH dead_facet;

 private:
  // Numbers the list elements from these on with the next ids. Halfedges come in pairs,
  // consecutive in the list (HalfedgeDS_list::edges_push_back), as Edge_iterator steps.
  void number_from(Polyhedron::Vertex_iterator v, Polyhedron::Halfedge_iterator h,
                   Polyhedron::Facet_iterator f) {
    for (; v != mesh.vertices_end(); ++v) {
      v->id() = vertices.size();
      vertices.push_back(v);
    }
    for (; f != mesh.facets_end(); ++f) {
      f->id() = facets.size();
      facets.push_back(f);
    }
    while (h != mesh.halfedges_end()) {
      h->id() = 2 * edges.size();
      h->opposite()->id() = 2 * edges.size() + 1;
      edges.push_back(h);
      ++h;
      ++h;
    }
  }
};

}  // namespace polyhedron
}  // namespace topolab_cgal

#endif
