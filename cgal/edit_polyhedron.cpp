// CGAL::Polyhedron_3 changed through its own Euler operations (the HalfedgeDS methods
// Polyhedron_3 exposes: create_center_vertex, flip_edge, and CGAL::Euler::collapse_edge,
// which runs on a Polyhedron_3 through join_face and join_vertex): the changing workloads of
// the Surface_mesh benchmark, whole, in C++, as edit_surface_mesh.cpp runs them on a
// Surface_mesh.
//
// A Polyhedron_3 appends new vertices, halfedge pairs and facets to its lists, so the old
// elements are the first ones of each list; an erased element leaves its list at once (there
// is no garbage to collect). The lab's ids (Polyhedron_items_with_id_3, polyhedron.cpp) are
// given again in list order at the end (renumber, O(n)): the counterpart of collect_garbage.
//
// The new vertex of a collapse goes: its edge is collapsed from the halfedge leaving it
// (collapse_edge removes the source of the edge's halfedge, and a Polyhedron edge made from a
// halfedge keeps it), so every old vertex stays, as in the other structures' runs.

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <iterator>
#include <vector>

#include "edit.h"
#include "mesh.h"

namespace topolab_cgal {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Polyhedron = CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3>;
using VH = Polyhedron::Vertex_handle;
using HH = Polyhedron::Halfedge_handle;
using FH = Polyhedron::Facet_handle;

// The Polyhedron_3 behind a mesh of the shim (built by polyhedron.cpp).
Polyhedron &polyhedron(topolab_cgal_mesh *mesh) {
  return *static_cast<Polyhedron *>(mesh->native());
}

// Splits facet f at a new vertex at p (create_center_vertex); the new vertex is appended.
void split_at(Polyhedron &m, FH f, const Point &p) {
  const HH h = m.create_center_vertex(f->halfedge());
  h->vertex()->point() = p;
}

void sqrt3(Polyhedron &m) {
  const size_t nv = m.size_of_vertices(), nf = m.size_of_facets();
  const size_t ne = m.size_of_halfedges() / 2;
  m.reserve(nv + nf, 2 * (ne + 3 * nf), 3 * nf);
  std::vector<Point> moved(nv);
  auto v = m.vertices_begin();
  for (size_t i = 0; i < nv; ++i, ++v) {
    moved[i] = v->point();
    if (CGAL::is_border(v, m)) continue;
    const double n = double(v->vertex_degree());
    const double alpha = (4.0 - 2.0 * std::cos(2.0 * CGAL_PI / n)) / 9.0;
    Vector p(0, 0, 0);
    auto c = v->vertex_begin();
    const auto end = c;
    do {
      p = p + (c->opposite()->vertex()->point() - CGAL::ORIGIN);
    } while (++c != end);
    moved[i] = CGAL::ORIGIN + ((1.0 - alpha) * (v->point() - CGAL::ORIGIN) + alpha / n * p);
  }
  auto f = m.facets_begin();
  for (size_t i = 0; i < nf; ++i) {
    const FH here = f++;
    Vector p(0, 0, 0);
    double k = 0;
    auto c = here->facet_begin();
    const auto end = c;
    do {
      p = p + (c->vertex()->point() - CGAL::ORIGIN);
      k += 1;
    } while (++c != end);
    split_at(m, here, CGAL::ORIGIN + p / k);
  }
  v = m.vertices_begin();
  for (size_t i = 0; i < nv; ++i, ++v) v->point() = moved[i];
  auto e = m.edges_begin();
  for (size_t i = 0; i < ne; ++i) {
    const HH h = e++;
    if (!h->is_border_edge()) m.flip_edge(h);
  }
}

void collapse_test(Polyhedron &m) {
  const size_t nv = m.size_of_vertices(), nf = m.size_of_facets();
  const size_t ne = m.size_of_halfedges() / 2;
  m.reserve(nv + nf, 2 * (ne + 3 * nf), 3 * nf);
  auto f = m.facets_begin();
  for (size_t i = 0; i < nf; ++i) split_at(m, f++, Point(0, 0, 0));
  auto v = std::next(m.vertices_begin(), nv);
  while (v != m.vertices_end()) {
    // The collapse erases v itself (and nothing else on a closed mesh): step past it first.
    const VH here = v++;
    CGAL::Euler::collapse_edge(edge(here->halfedge()->opposite(), m), m);
  }
}

}  // namespace
}  // namespace topolab_cgal

extern "C" {

int topolab_cgal_polyhedron_changing(topolab_cgal_mesh *mesh, int workload) noexcept {
  using namespace topolab_cgal;
  if (workload != 0 && workload != 1) return TOPOLAB_CGAL_UNKNOWN_CODE;
  const int done = guard([&] {
    Polyhedron &m = polyhedron(mesh);
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
