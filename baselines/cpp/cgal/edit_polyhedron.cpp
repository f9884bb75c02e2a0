// CGAL::Polyhedron_3 changed through its own Euler operations (the HalfedgeDS methods
// Polyhedron_3 exposes: create_center_vertex, flip_edge, and CGAL::Euler::collapse_edge,
// which runs on a Polyhedron_3 through join_face and join_vertex): the changing workloads of
// the Surface_mesh benchmark, whole, in C++, as edit_surface_mesh.cpp runs them on a
// Surface_mesh; and topolab's MeshEdit (src/cgal/edit.rs) through CGAL's Euler operations
// (CGAL/boost/graph/Euler_operations.h, which Polyhedron_3 models as a MutableFaceGraph).
//
// A Polyhedron_3 appends new vertices, halfedge pairs and facets to its lists, so the old
// elements are the first ones of each list; an erased element leaves its list at once (there
// is no garbage to collect). The workloads give the lab's ids (Polyhedron_items_with_id_3,
// polyhedron.h) again in list order at the end (renumber, O(n)): the counterpart of
// collect_garbage.
//
// The new vertex of a collapse goes: its edge is collapsed from the halfedge leaving it
// (collapse_edge removes the source of the edge's halfedge, and a Polyhedron edge made from a
// halfedge keeps it), so every old vertex stays, as in the other structures' runs.
//
// MeshEdit keeps the lab's ids stable with the id tables of polyhedron.h (handles by id, ids
// by handle in the items' id fields): an edit that creates numbers what CGAL appended to the
// lists after it (O(1) per new element: the lists' old ends are remembered); an edit that
// erases reads the ids of what CGAL will erase before it does and puts a tombstone into those
// slots, so ids and counts stay until the garbage collection (renumber, in list order, which
// is id order: the survivors keep their order). Which elements a collapse erases is CGAL's
// choice (one edge of each triangle, which one depending on the border): the ids of the edge,
// its triangles and their sides are read before, those around the kept vertex after, and the
// difference is buried, O(k).
//
// The operations and their checks are those of edit_surface_mesh.cpp (the half-edge family's
// rules, before any write, so a refused edit changes nothing and no CGAL precondition is
// violated), with two differences: a Polyhedron_3 vertex's halfedge is any halfedge into it
// (its border test circulates), so nothing restores border halfedges after an edit; and the
// deletions run CGAL's remove_face keeping isolated vertices here too, on the BGL functions.
// The vertex weld is edit_rules.h's template, the same as Surface_mesh's (stitch_borders),
// with the ids of the edges and the vertex it removes buried first.
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/internal/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <iterator>
#include <stdexcept>
#include <vector>

#include "edit.h"
#include "edit_rules.h"
#include "mesh.h"
#include "polyhedron.h"

namespace topolab_cgal {
namespace {

using namespace edit_rules;
using edit_rules::BOUNDARY_EDGE;

using polyhedron::Adapter;
using polyhedron::DEAD;
using polyhedron::FH;
using polyhedron::HH;
using polyhedron::Point;
using polyhedron::Polyhedron;
using polyhedron::VH;
using Vector = polyhedron::Kernel::Vector_3;

// The Polyhedron_3 behind a mesh of the shim with its id tables (built by polyhedron.cpp).
Adapter &adapter(topolab_cgal_mesh *mesh) { return *static_cast<Adapter *>(mesh->native()); }
Polyhedron &polyhedron_of(topolab_cgal_mesh *mesh) { return adapter(mesh).mesh; }

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


// --- MeshEdit ----------------------------------------------------------------------------

const HH NO_HALFEDGE = HH();

bool live(const Adapter &a, uint32_t v) { return v < a.num_vertices() && !a.is_dead_vertex(v); }
bool live_edge(const Adapter &a, uint32_t e) { return e < a.num_edges() && !a.is_dead_edge(e); }
bool live_face(const Adapter &a, uint32_t f) { return f < a.num_faces() && !a.is_dead_facet(f); }

uint32_t eid(HH h) { return uint32_t(h->id() / 2); }
bool isolated(VH v) { return v->halfedge() == NO_HALFEDGE; }
// The halfedge from a to b, or none: around a, whose halfedge points into it.
HH find(VH a, VH b) {
  if (isolated(a)) return NO_HALFEDGE;
  const HH start = a->halfedge();
  HH h = start;
  do {
    if (h->opposite()->vertex() == b) return h->opposite();
    h = h->next()->opposite();
  } while (h != start);
  return NO_HALFEDGE;
}
bool triangle(HH h) { return h->next()->next()->next() == h; }
// The next halfedge leaving the same vertex.
HH rotate(HH h) { return h->opposite()->next(); }
// Has v a border halfedge around it (CGAL::is_border circulates)?
bool boundary_vertex(const Polyhedron &m, VH v) {
  return !isolated(v) && bool(CGAL::is_border(v, m));
}
HH some_outgoing(VH v) { return v->halfedge()->opposite(); }

// The fans vertex w keeps when the faces `removed` go: runs of remaining faces around it.
size_t fans_without(VH w, const std::vector<FH> &removed) {
  if (isolated(w)) return 0;
  const HH start = some_outgoing(w);
  auto present = [&](HH h) {
    const FH f = h->facet();
    return f != FH() && std::find(removed.begin(), removed.end(), f) == removed.end();
  };
  size_t runs = 0;
  bool all = true;
  HH h = start;
  do {
    const bool here = present(h), before = present(rotate(h));
    all = all && here;
    runs += (before && !here) ? 1 : 0;
    h = rotate(h);
  } while (h != start);
  return all ? 1 : runs;
}

// CGAL::Euler::remove_face (CGAL 5.5, boost/graph/Euler_operations.h) with one change, as in
// edit_surface_mesh.cpp: a vertex left without edges stays, unused (CGAL removes it). Each
// edge and the face are buried before CGAL erases them.
void remove_face_keeping_vertices(HH h, Adapter &a) {
  Polyhedron &g = a.mesh;
  auto erase_edge = [&](HH x) {
    a.bury_edge(eid(x));
    remove_edge(edge(x, g), g);
  };
  const FH f = h->facet();
  const HH end = h;
  do {
    CGAL::internal::set_border(h, g);
    const HH nh = next(h, g);
    const bool h_border = is_border(opposite(h, g), g);
    const bool nh_bborder = is_border(opposite(nh, g), g);
    if (h_border && nh_bborder && next(opposite(nh, g), g) == opposite(h, g)) {
      set_halfedge(target(h, g), NO_HALFEDGE, g);  // CGAL: remove_vertex(target(h, g), g)
      if (h != end) erase_edge(h);
    } else {
      if (nh_bborder) {
        CGAL::internal::set_vertex_halfedge(opposite(next(opposite(nh, g), g), g), g);
        CGAL::internal::remove_tip(h, g);
      }
      if (h_border) {
        CGAL::internal::set_vertex_halfedge(opposite(next(h, g), g), g);
        CGAL::internal::remove_tip(prev(opposite(h, g), g), g);
        if (h != end) erase_edge(h);
      }
    }
    h = nh;
  } while (h != end);
  a.bury_facet(uint32_t(f->id()));
  remove_face(f, g);
  if (is_border(opposite(h, g), g)) erase_edge(h);
}

int add_face(Adapter &a, const uint32_t *vs, uint32_t n, uint32_t *out) {
  if (n < 3) return BAD_FACE;
  for (uint32_t i = 1; i < n; ++i)
    if (std::find(vs, vs + i, vs[i]) != vs + i) return BAD_FACE;
  for (uint32_t i = 0; i < n; ++i)
    if (!live(a, vs[i])) return NO_SUCH_ELEMENT;
  std::vector<HH> hs(n);
  for (uint32_t i = 0; i < n; ++i) {
    const VH x = a.vertex(vs[i]), y = a.vertex(vs[(i + 1) % n]);
    if (!isolated(x) && !boundary_vertex(a.mesh, x)) return NON_MANIFOLD_VERTEX;
    hs[i] = find(x, y);
    if (hs[i] != NO_HALFEDGE && !hs[i]->is_border()) return NON_MANIFOLD_EDGE;
  }
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t ii = (i + 1) % n;
    // As in edit_surface_mesh.cpp: two old sides meeting at a vertex must be consecutive on
    // its one border gap; two new sides at a used vertex would give it a second fan.
    const bool old_i = hs[i] != NO_HALFEDGE, old_ii = hs[ii] != NO_HALFEDGE;
    if (old_i && old_ii && hs[i]->next() != hs[ii]) return NON_MANIFOLD_VERTEX;
    if (!old_i && !old_ii && !isolated(a.vertex(vs[ii]))) return NON_MANIFOLD_VERTEX;
  }
  std::vector<VH> corners;
  for (uint32_t i = 0; i < n; ++i) corners.push_back(a.vertex(vs[i]));
  const auto before = a.ends();
  const FH f = CGAL::Euler::add_face(corners, a.mesh);
  if (f == FH()) throw std::runtime_error("add_face refused a checked face");
  a.number_new(before);
  *out = uint32_t(f->id());
  return OK_EDIT;
}

int delete_face(Adapter &a, uint32_t fi) {
  if (!live_face(a, fi)) return NO_SUCH_ELEMENT;
  const HH start = a.face(fi)->halfedge();
  // A border vertex keeps one fan only if the face is at an end of it.
  HH h = start;
  do {
    const VH v = h->opposite()->vertex();
    if (boundary_vertex(a.mesh, v) && !h->prev()->opposite()->is_border() &&
        !h->opposite()->is_border())
      return NON_MANIFOLD_VERTEX;
    h = h->next();
  } while (h != start);
  remove_face_keeping_vertices(start, a);
  return OK_EDIT;
}

int delete_vertex(Adapter &a, uint32_t vi) {
  if (!live(a, vi)) return NO_SUCH_ELEMENT;
  const VH v = a.vertex(vi);
  std::vector<FH> faces;
  std::vector<VH> corners;
  if (!isolated(v)) {
    const HH start = v->halfedge();
    HH h = start;
    do {
      if (!h->is_border()) {
        faces.push_back(h->facet());
        HH c = h;
        do {
          if (c->vertex() != v) corners.push_back(c->vertex());
          c = c->next();
        } while (c != h);
      }
      h = h->next()->opposite();
    } while (h != start);
  }
  for (VH w : corners)
    if (fans_without(w, faces) > 1) return NON_MANIFOLD_VERTEX;
  for (FH f : faces) remove_face_keeping_vertices(f->halfedge(), a);
  if (!isolated(v)) throw std::logic_error("a vertex kept an edge without faces");
  a.bury_vertex(vi);
  remove_vertex(v, a.mesh);
  return OK_EDIT;
}

int flip(Adapter &a, uint32_t ei) {
  if (!live_edge(a, ei)) return NO_SUCH_ELEMENT;
  const HH a0 = a.halfedge_at(2 * ei), b0 = a0->opposite();
  if (a0->is_border() || b0->is_border()) return BOUNDARY_EDGE;
  if (!triangle(a0) || !triangle(b0)) return NOT_TRIANGLES;
  const VH x = a0->next()->vertex(), y = b0->next()->vertex();
  if (x == y || find(x, y) != NO_HALFEDGE) return EDGE_EXISTS;
  CGAL::Euler::flip_edge(a0, a.mesh);
  return OK_EDIT;
}

int split_edge(Adapter &a, uint32_t ei, const Point &p, uint32_t *out) {
  if (!live_edge(a, ei)) return NO_SUCH_ELEMENT;
  Polyhedron &m = a.mesh;
  const HH h0 = a.halfedge_at(2 * ei), o0 = h0->opposite();
  if ((!h0->is_border() && !triangle(h0)) || (!o0->is_border() && !triangle(o0)))
    return NOT_TRIANGLES;
  if (!h0->is_border() && !o0->is_border() && h0->next()->vertex() == o0->next()->vertex())
    return EDGE_EXISTS;
  const auto before = a.ends();
  // a -> b becomes a -> v (hnew), v -> b (h0); each triangle beside it a quad, cut at v.
  const HH hnew = CGAL::Euler::split_edge(h0, m);
  const VH v = hnew->vertex();
  v->point() = p;
  if (!h0->is_border()) CGAL::Euler::split_face(hnew, h0->next(), m);
  const HH back = h0->opposite(), back_new = hnew->opposite();  // b -> v, v -> a
  if (!back->is_border()) CGAL::Euler::split_face(back, back_new->next(), m);
  a.number_new(before);
  *out = uint32_t(v->id());
  return OK_EDIT;
}

int split_face(Adapter &a, uint32_t fi, const Point &p, uint32_t *out) {
  if (!live_face(a, fi)) return NO_SUCH_ELEMENT;
  const auto before = a.ends();
  const VH v = CGAL::Euler::add_center_vertex(a.face(fi)->halfedge(), a.mesh)->vertex();
  v->point() = p;
  a.number_new(before);
  *out = uint32_t(v->id());
  return OK_EDIT;
}

// pmp's (and the half-edge family's) is_collapse_ok for the halfedge h from v0 to v1, with
// OpenMesh's tetrahedron test, as in edit_surface_mesh.cpp: the refusal code, OK_EDIT when the
// collapse may be done.
int lab_collapse_refusal(const Polyhedron &m, HH h) {
  const HH o = h->opposite();
  const VH v0 = o->vertex(), v1 = h->vertex();
  VH vl, vr;  // none
  if (!h->is_border()) {
    const HH h1 = h->next(), h2 = h1->next();
    vl = h1->vertex();
    if (h1->opposite()->is_border() && h2->opposite()->is_border()) return LINK_CONDITION;
  }
  if (!o->is_border()) {
    const HH o1 = o->next(), o2 = o1->next();
    vr = o1->vertex();
    if (o1->opposite()->is_border() && o2->opposite()->is_border()) return LINK_CONDITION;
  }
  if (vl == vr) return LINK_CONDITION;
  if (vl != VH() && vr != VH() && find(vl, vr) != NO_HALFEDGE && vl->vertex_degree() == 3 &&
      vr->vertex_degree() == 3)
    return TETRAHEDRON_TEST;
  if (boundary_vertex(m, v0) && boundary_vertex(m, v1) && !h->is_border() && !o->is_border())
    return LINK_CONDITION;
  const HH start = v0->halfedge();
  HH g = start;
  do {
    const VH w = g->opposite()->vertex();
    if (w != v1 && w != vl && w != vr && find(w, v1) != NO_HALFEDGE) return LINK_CONDITION;
    g = g->next()->opposite();
  } while (g != start);
  return OK_EDIT;
}

int collapse(Adapter &a, uint32_t from, uint32_t to) {
  if (!live(a, from) || !live(a, to)) return NO_SUCH_ELEMENT;
  Polyhedron &m = a.mesh;
  const HH h = find(a.vertex(from), a.vertex(to));
  if (h == NO_HALFEDGE) return NOT_NEIGHBOURS;
  HH g = h;
  do {
    if (!g->is_border() && !triangle(g)) return NOT_TRIANGLES;
    g = rotate(g);
  } while (g != h);
  const int refused = lab_collapse_refusal(m, h);
  if (refused != OK_EDIT) return refused;
  const auto e = edge(h, m);  // made from h: its halfedge is h, whose source goes
  if (!CGAL::Euler::does_satisfy_link_condition(e, m)) return LINK_CONDITION;
  // What CGAL may erase: the edge, its triangles and their other sides (see the file's
  // notes), at most 5 edges and 2 faces, in fixed arrays (no allocation per collapse).
  std::array<uint32_t, 5> edges{eid(h), DEAD, DEAD, DEAD, DEAD};
  std::array<uint32_t, 2> faces{DEAD, DEAD};
  size_t sides = 0;
  for (HH side : {h, h->opposite()}) {
    if (side->is_border()) continue;
    faces[sides] = uint32_t(side->facet()->id());
    edges[1 + 2 * sides] = eid(side->next());
    edges[2 + 2 * sides] = eid(side->prev());
    ++sides;
  }
  const VH kept = CGAL::Euler::collapse_edge(e, m);
  // What is left of those is around the kept vertex: struck off the lists, the rest buried.
  if (!isolated(kept)) {
    const HH start = kept->halfedge();
    HH x = start;
    do {
      std::replace(edges.begin(), edges.end(), eid(x), DEAD);
      if (!x->is_border())
        std::replace(faces.begin(), faces.end(), uint32_t(x->facet()->id()), DEAD);
      x = x->next()->opposite();
    } while (x != start);
  }
  for (uint32_t x : edges)
    if (x != DEAD) a.bury_edge(x);
  for (uint32_t f : faces)
    if (f != DEAD) a.bury_facet(f);
  if (uint32_t(kept->id()) != to) {
    // Not what CGAL documents (target(halfedge(e)) is kept): the ids would lie, so they are
    // given again, and the call fails.
    a.renumber();
    throw std::logic_error("collapse_edge kept the source");
  }
  a.bury_vertex(from);
  return OK_EDIT;
}

int split_vertex(Adapter &a, uint32_t v1i, const Point &p, uint32_t vli, uint32_t vri,
                 uint32_t *out) {
  if (!live(a, v1i) || !live(a, vli) || !live(a, vri)) return NO_SUCH_ELEMENT;
  if (vli == vri || vli == v1i || vri == v1i) return NOT_NEIGHBOURS;
  Polyhedron &m = a.mesh;
  const VH v1 = a.vertex(v1i), vl = a.vertex(vli), vr = a.vertex(vri);
  const HH ha = find(v1, vr), hb = find(v1, vl);
  if (ha == NO_HALFEDGE || hb == NO_HALFEDGE) return NOT_NEIGHBOURS;
  // As in edit_surface_mesh.cpp: the halfedges after `ha` up to `hb` move to the new vertex,
  // and their faces must be faces.
  HH g = rotate(ha);
  while (true) {
    if (g->is_border()) return NOT_IMPLEMENTED;
    if (g == hb) break;
    g = rotate(g);
  }
  const auto before = a.ends();
  const HH hnew = CGAL::Euler::split_vertex(ha->opposite(), hb->opposite(), m);
  const VH v0 = hnew->opposite()->vertex();
  v0->point() = p;
  const HH back = hnew->opposite();  // v1 -> v0
  const HH to_vl = hnew->prev()->prev(), to_vr = back->prev()->prev();
  if (to_vl->vertex() != vl || to_vr->vertex() != vr)
    throw std::logic_error("split_vertex regrouped another fan");
  auto close = [&](HH h, HH to, std::initializer_list<VH> corners) {
    if (!h->is_border()) {
      CGAL::Euler::split_face(h, to, m);
    } else if (CGAL::Euler::add_face(std::vector<VH>(corners), m) == FH()) {
      throw std::logic_error("add_face refused a triangle of the split");
    }
  };
  close(hnew, to_vl, {v0, v1, vl});
  close(back, to_vr, {v1, v0, vr});
  a.number_new(before);
  *out = uint32_t(v0->id());
  return OK_EDIT;
}

// The weld's id table (edit_rules.h): the adapter's, whose slots of what CGAL erases are
// buried first; a vertex's halfedge is any halfedge into it, so nothing is restored.
struct WeldIds {
  Adapter &a;
  bool live(uint32_t v) const { return topolab_cgal::live(a, v); }
  VH vertex(uint32_t v) const { return a.vertex(v); }
  uint32_t id(VH v) const { return uint32_t(v->id()); }
  void bury_vertex(uint32_t v) { a.bury_vertex(v); }
  void bury_edge(HH h) { a.bury_edge(eid(h)); }
  void touched(VH) {}
};

int weld(Adapter &a, uint32_t v, uint32_t w) {
  WeldIds ids{a};
  return weld_vertices(a.mesh, ids, v, w);
}

// Runs an edit: OK, or EDIT_REFUSED with *refusal set. After a failure part-way the ids are
// given again in list order, so that no table keeps the handle of an erased element.
template <class F> int edit(topolab_cgal_mesh *mesh, int *refusal, F &&body) {
  const int done = guard([&] {
    const int r = body(adapter(mesh));
    if (r == OK_EDIT) return TOPOLAB_CGAL_OK;
    *refusal = r;
    return TOPOLAB_CGAL_EDIT_REFUSED;
  });
  if (done != TOPOLAB_CGAL_OK && done != TOPOLAB_CGAL_EDIT_REFUSED) guard([&] {
      mesh->renumber();
      return TOPOLAB_CGAL_OK;
    });
  return done;
}

Point point(const double *p) { return point_of<Point>(p); }

}  // namespace
}  // namespace topolab_cgal

extern "C" {

int topolab_cgal_polyhedron_changing(topolab_cgal_mesh *mesh, int workload) noexcept {
  using namespace topolab_cgal;
  if (workload != 0 && workload != 1) return TOPOLAB_CGAL_UNKNOWN_CODE;
  const int done = guard([&] {
    Polyhedron &m = polyhedron_of(mesh);
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


int topolab_cgal_ph_edit_add_vertex(topolab_cgal_mesh *mesh, const double *p,
                                    uint32_t *out) noexcept {
  using namespace topolab_cgal;
  int unused = 0;
  return edit(mesh, &unused, [&](Adapter &a) {
    const auto before = a.ends();
    const VH v = add_vertex(a.mesh);
    v->point() = point(p);
    a.number_new(before);
    *out = uint32_t(v->id());
    return int(OK_EDIT);
  });
}

int topolab_cgal_ph_edit_set_position(topolab_cgal_mesh *mesh, uint32_t v, const double *p,
                                      int *refusal) noexcept {
  using namespace topolab_cgal;
  return edit(mesh, refusal, [&](Adapter &a) {
    if (!live(a, v)) return int(NO_SUCH_ELEMENT);
    a.vertex(v)->point() = point(p);
    return int(OK_EDIT);
  });
}

TOPOLAB_CGAL_EDIT_CALLS(ph, Adapter)

int topolab_cgal_ph_edit_is_deleted(const topolab_cgal_mesh *mesh, int kind, uint32_t id,
                                    int *out) noexcept {
  using namespace topolab_cgal;
  return guard([&] {
    if (kind < 0 || kind > 2) return TOPOLAB_CGAL_UNKNOWN_CODE;
    const Adapter &a = adapter(const_cast<topolab_cgal_mesh *>(mesh));
    switch (kind) {
      case 0: *out = id < a.num_vertices() && a.is_dead_vertex(id) ? 1 : 0; break;
      case 1: *out = id < a.num_edges() && a.is_dead_edge(id) ? 1 : 0; break;
      default: *out = id < a.num_faces() && a.is_dead_facet(id) ? 1 : 0; break;
    }
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_ph_edit_garbage_collection(topolab_cgal_mesh *mesh) noexcept {
  using namespace topolab_cgal;
  return guard([&] {
    mesh->renumber();
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_ph_edit_reserve(topolab_cgal_mesh *mesh, uint32_t vertices, uint32_t edges,
                                 uint32_t faces) noexcept {
  using namespace topolab_cgal;
  return guard([&] {
    Adapter &a = adapter(mesh);
    const size_t nv = a.vertices.size() + vertices, ne = a.edges.size() + edges,
                 nf = a.facets.size() + faces;
    a.mesh.reserve(nv, 2 * ne, nf);
    a.vertices.reserve(nv);
    a.edges.reserve(ne);
    a.facets.reserve(nf);
    return TOPOLAB_CGAL_OK;
  });
}

}  // extern "C"
