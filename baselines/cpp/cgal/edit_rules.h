// What the two MeshEdit units of the CGAL shim share (edit_surface_mesh.cpp,
// edit_polyhedron.cpp): the refusal codes of edit.h as an enum their checks return, the point
// of a C array, and the vertex weld, one BGL template for both classes. A unit takes them with
// `using namespace edit_rules;` and `using edit_rules::BOUNDARY_EDGE;` (mesh.h has an operator
// of that name) in its unnamed namespace.

#ifndef TOPOLAB_CGAL_EDIT_RULES_H
#define TOPOLAB_CGAL_EDIT_RULES_H

#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "edit.h"

namespace topolab_cgal {
namespace edit_rules {

// The refusal codes of edit.h; OK_EDIT when the edit is allowed (or done).
enum Refusal {
  OK_EDIT = -1,
  NO_SUCH_ELEMENT = TOPOLAB_CGAL_REFUSAL_NO_SUCH_ELEMENT,
  BAD_FACE = TOPOLAB_CGAL_REFUSAL_BAD_FACE,
  NON_MANIFOLD_EDGE = TOPOLAB_CGAL_REFUSAL_NON_MANIFOLD_EDGE,
  NON_MANIFOLD_VERTEX = TOPOLAB_CGAL_REFUSAL_NON_MANIFOLD_VERTEX,
  NOT_TRIANGLES = TOPOLAB_CGAL_REFUSAL_NOT_TRIANGLES,
  BOUNDARY_EDGE = TOPOLAB_CGAL_REFUSAL_BOUNDARY_EDGE,
  EDGE_EXISTS = TOPOLAB_CGAL_REFUSAL_EDGE_EXISTS,
  NOT_NEIGHBOURS = TOPOLAB_CGAL_REFUSAL_NOT_NEIGHBOURS,
  LINK_CONDITION = TOPOLAB_CGAL_REFUSAL_LINK_CONDITION,
  NOT_IMPLEMENTED = TOPOLAB_CGAL_REFUSAL_NOT_IMPLEMENTED,
  SAME_VERTEX = TOPOLAB_CGAL_REFUSAL_SAME_VERTEX,
  TETRAHEDRON_TEST = TOPOLAB_CGAL_REFUSAL_TETRAHEDRON_TEST,
};

// The point of 3 doubles (x, y, z).
template <class Point> Point point_of(const double *p) { return Point(p[0], p[1], p[2]); }

// MeshEdit::weld_vertices (b merged into a) on any CGAL MutableFaceGraph, through what CGAL
// documents: where the boundaries of a and b meet along an edge (a's border runs q -> a -> p,
// b's s -> b -> r, and s == p or r == q), Polygon_mesh_processing::stitch_borders with those one
// or two pairs of border halfedges zips them ("for each pair p, p.second and its opposite will be
// removed"); where b has no faces it is removed (remove_vertex); where a has none, every halfedge
// into b is set to end at a (set_target, set_halfedge: the MutableHalfedgeGraph setters) and b
// is removed.
//
// Every check runs first, so a refused weld changes nothing, in the order and with the reasons
// of the lab's half-edges (structures/src/families/half_edge/edit/euler/weld.rs), so the shared
// cases agree: a dead id (NO_SUCH_ELEMENT); one vertex twice (SAME_VERTEX); a face around b holding a
// (BAD_FACE); both used and one of them interior, or two boundaries that meet at no edge
// (NON_MANIFOLD_VERTEX); a neighbour of both other than p and q, whose edge would be doubled
// (NON_MANIFOLD_EDGE; stitch_borders' own filter would skip such a pair and weld nothing).
//
// Which vertex stitch_borders keeps is its union-find's choice, not documented: with b's border
// halfedge first in each pair (so b's edges stay and a's go), CGAL 5.5 unites b into a and keeps
// a; the kept vertex is checked after, and a weld that kept b fails (logic_error) rather than let
// the ids lie.
//
// `Ids` is the unit's id table: live(id), vertex(id), id(vertex); bury_vertex(id) and
// bury_edge(halfedge), called before CGAL removes them (Polyhedron_3 erases at once, so its
// tables tombstone the slot; Surface_mesh only marks); touched(vertex) after the weld, for each
// vertex whose halfedge CGAL set (Surface_mesh keeps a border vertex's halfedge on the border).
//
// Cost: O(k) for the checks (the faces around b, the neighbours of both, sorted by id: O(k log
// k)) and the renaming of b's halfedges, plus stitch_borders on one or two pairs (its filter
// circulates around the vertices of the pairs: O(k)).
template <class Graph, class Ids> int weld_vertices(Graph &g, Ids &ids, uint32_t ai, uint32_t bi) {
  using GT = boost::graph_traits<Graph>;
  using HD = typename GT::halfedge_descriptor;
  using VD = typename GT::vertex_descriptor;
  if (!ids.live(ai) || !ids.live(bi)) return NO_SUCH_ELEMENT;
  if (ai == bi) return SAME_VERTEX;
  const VD a = ids.vertex(ai), b = ids.vertex(bi);
  const HD none = GT::null_halfedge();
  auto remove_b = [&] {
    ids.bury_vertex(bi);
    set_halfedge(b, none, g);
    remove_vertex(b, g);
  };
  if (halfedge(b, g) == none) {
    remove_b();  // nothing refers to b
    return OK_EDIT;
  }
  // No face around b may hold a (an edge a-b always has a face).
  for (HD h : CGAL::halfedges_around_target(b, g))
    if (!is_border(h, g))
      for (VD v : CGAL::vertices_around_face(h, g))
        if (v == a) return BAD_FACE;
  if (halfedge(a, g) == none) {
    // a takes b's fan as it is.
    const HD into_b = halfedge(b, g);
    for (HD h : CGAL::halfedges_around_target(into_b, g)) set_target(h, a, g);
    set_halfedge(a, into_b, g);
    remove_b();
    ids.touched(a);
    return OK_EDIT;
  }
  // Both used: both on the boundary, meeting at an edge (the border halfedge into each).
  auto border_into = [&](VD v) {
    for (HD h : CGAL::halfedges_around_target(v, g))
      if (is_border(h, g)) return h;
    return none;
  };
  const HD a_in = border_into(a), b_in = border_into(b);
  if (a_in == none || b_in == none) return NON_MANIFOLD_VERTEX;
  const HD a_out = next(a_in, g), b_out = next(b_in, g);
  const VD p = target(a_out, g), q = source(a_in, g);
  const VD r = target(b_out, g), s = source(b_in, g);
  // Border halfedges that would run the same way (r == p) cannot meet: p would have two border
  // halfedges into it. So the result is oriented whenever it is a manifold.
  const bool at_p = s == p, at_q = r == q;
  if (!at_p && !at_q) return NON_MANIFOLD_VERTEX;
  // Any other neighbour of both would get two edges to a.
  std::vector<uint32_t> around_a;
  for (HD h : CGAL::halfedges_around_target(a, g)) around_a.push_back(ids.id(source(h, g)));
  std::sort(around_a.begin(), around_a.end());
  for (HD h : CGAL::halfedges_around_target(b, g)) {
    const VD y = source(h, g);
    if ((at_p && y == p) || (at_q && y == q)) continue;
    if (std::binary_search(around_a.begin(), around_a.end(), ids.id(y))) return NON_MANIFOLD_EDGE;
  }
  std::vector<std::pair<HD, HD>> pairs;
  if (at_p) pairs.emplace_back(b_in, a_out);  // p -> b stays, a -> p goes
  if (at_q) pairs.emplace_back(b_out, a_in);  // b -> q stays, q -> a goes
  const HD into_kept = at_p ? b_in : opposite(b_out, g);  // kept: its target must end as a
  for (const auto &pair : pairs) ids.bury_edge(pair.second);
  ids.bury_vertex(bi);
  if (CGAL::Polygon_mesh_processing::stitch_borders(g, pairs) != pairs.size())
    throw std::logic_error("stitch_borders dropped a checked pair");
  if (target(into_kept, g) != a) throw std::logic_error("stitch_borders kept the welded vertex");
  ids.touched(a);
  if (at_p) ids.touched(p);
  if (at_q) ids.touched(q);
  return OK_EDIT;
}

}  // namespace edit_rules
}  // namespace topolab_cgal

// The extern "C" calls of the edits whose work is one function of the unit's unnamed namespace
// (add_face, delete_face, ..., weld), written once for both units: PREFIX names the class
// (`ph`, `sm`), TARGET is what `edit` hands each call (the polyhedron's Adapter, the
// SurfaceMesh). The unit's `edit` guards every exception and turns the code into the refusal.
#define TOPOLAB_CGAL_EDIT_CALLS(PREFIX, TARGET)                                                 \
  int topolab_cgal_##PREFIX##_edit_add_face(topolab_cgal_mesh *mesh, const uint32_t *vertices, \
                                            uint32_t n, int *refusal, uint32_t *out) noexcept { \
    using namespace topolab_cgal;                                                              \
    return edit(mesh, refusal, [&](TARGET &t) { return add_face(t, vertices, n, out); });      \
  }                                                                                            \
  int topolab_cgal_##PREFIX##_edit_delete_face(topolab_cgal_mesh *mesh, uint32_t f,            \
                                               int *refusal) noexcept {                        \
    using namespace topolab_cgal;                                                              \
    return edit(mesh, refusal, [&](TARGET &t) { return delete_face(t, f); });                  \
  }                                                                                            \
  int topolab_cgal_##PREFIX##_edit_delete_vertex(topolab_cgal_mesh *mesh, uint32_t v,          \
                                                 int *refusal) noexcept {                      \
    using namespace topolab_cgal;                                                              \
    return edit(mesh, refusal, [&](TARGET &t) { return delete_vertex(t, v); });                \
  }                                                                                            \
  int topolab_cgal_##PREFIX##_edit_flip(topolab_cgal_mesh *mesh, uint32_t e,                   \
                                        int *refusal) noexcept {                               \
    using namespace topolab_cgal;                                                              \
    return edit(mesh, refusal, [&](TARGET &t) { return flip(t, e); });                         \
  }                                                                                            \
  int topolab_cgal_##PREFIX##_edit_split_edge(topolab_cgal_mesh *mesh, uint32_t e,             \
                                              const double *p, int *refusal,                   \
                                              uint32_t *out) noexcept {                        \
    using namespace topolab_cgal;                                                              \
    return edit(mesh, refusal, [&](TARGET &t) { return split_edge(t, e, point(p), out); });    \
  }                                                                                            \
  int topolab_cgal_##PREFIX##_edit_split_face(topolab_cgal_mesh *mesh, uint32_t f,             \
                                              const double *p, int *refusal,                   \
                                              uint32_t *out) noexcept {                        \
    using namespace topolab_cgal;                                                              \
    return edit(mesh, refusal, [&](TARGET &t) { return split_face(t, f, point(p), out); });    \
  }                                                                                            \
  int topolab_cgal_##PREFIX##_edit_collapse(topolab_cgal_mesh *mesh, uint32_t from,            \
                                            uint32_t to, int *refusal) noexcept {              \
    using namespace topolab_cgal;                                                              \
    return edit(mesh, refusal, [&](TARGET &t) { return collapse(t, from, to); });              \
  }                                                                                            \
  int topolab_cgal_##PREFIX##_edit_split_vertex(topolab_cgal_mesh *mesh, uint32_t v,           \
                                                const double *p, uint32_t left,                \
                                                uint32_t right, int *refusal,                  \
                                                uint32_t *out) noexcept {                      \
    using namespace topolab_cgal;                                                              \
    return edit(mesh, refusal,                                                                 \
                [&](TARGET &t) { return split_vertex(t, v, point(p), left, right, out); });    \
  }                                                                                            \
  int topolab_cgal_##PREFIX##_edit_weld(topolab_cgal_mesh *mesh, uint32_t a, uint32_t b,       \
                                        int *refusal) noexcept {                               \
    using namespace topolab_cgal;                                                              \
    return edit(mesh, refusal, [&](TARGET &t) { return weld(t, a, b); });                      \
  }

#endif
