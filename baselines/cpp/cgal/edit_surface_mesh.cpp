// CGAL::Surface_mesh changed through CGAL's Euler operations (CGAL/boost/graph/
// Euler_operations.h): the changing workloads of the Surface_mesh benchmark, whole, in C++.
//
// The workloads follow CGAL's own Surface_mesh/benchmark (surface_mesh_performance.h,
// subdivision_test and collapse_test), which runs the protocol of Sieger & Botsch:
// - sqrt3: reserve; new positions of the old interior vertices into a property; every old
//   face split at its centroid with Euler::add_center_vertex; the new positions set; every
//   old edge that is not a border flipped with Euler::flip_edge (unchecked, as the benchmark
//   does: after the splits every old interior edge can be flipped);
// - collapse test: reserve; every face split at the origin with add_center_vertex; every new
//   vertex collapsed with Euler::collapse_edge; collect_garbage (commented out in CGAL's
//   benchmark, done here as the protocol and OpenMesh's run do, so the meshes compare).
//   CGAL's benchmark collapses the edge of the new vertex's halfedge, which points *to* the
//   new vertex, so the old neighbour goes and its point is copied onto the new vertex: the
//   same mesh with other labels. Here the halfedge *from* the new vertex is collapsed
//   (collapse_edge removes the source of the edge's halfedge, and a Surface_mesh edge made
//   from a halfedge keeps it), so the new vertex goes and every old vertex keeps its index,
//   as in pmp-library's and OpenMesh's runs: the results compare by their face lists.

//
// The editing operations of MeshEdit (src/cgal/edit.rs) are CGAL's Euler operations too, each
// after checks that refuse, before any write, what the lab refuses (the half-edge family's
// rules, structures/src/families/half_edge/edit/euler.rs) and what CGAL's preconditions
// exclude (does_satisfy_link_condition, triangles for flip_edge and collapse_edge):
// - add face: Euler::add_face; delete face: Euler::remove_face with one change, below;
//   delete vertex: its faces so, then remove_vertex;
// - flip: Euler::flip_edge; face split: Euler::add_center_vertex;
// - edge split (the 2-to-4 split of pmp and OpenMesh): Euler::split_edge puts the vertex into
//   the edge (its triangles become quads), then Euler::split_face cuts each quad in two;
// - collapse: Euler::collapse_edge of the edge made from the halfedge from -> to (it removes
//   the halfedge's source);
// - vertex split (OpenMesh's vertex_split): Euler::split_vertex moves the fan to the new
//   vertex and joins it to the old one by an edge (the two faces beside it gain a corner),
//   then Euler::split_face cuts the triangle with `left` and the one with `right` off them.
// Euler::remove_face removes a vertex it leaves without edges; MeshEdit keeps such a vertex,
// unused (as a file's unused vertices are kept), so delete face runs CGAL's remove_face with
// that one line changed (the vertex's halfedge is cleared instead), and afterwards points each
// corner left on the border at a border halfedge, which the boundary query reads (found by the
// smoothing step of the editing suite, whose boundary test asks it after deletions).
//
// - vertex weld: Polygon_mesh_processing::stitch_borders on the pairs of border halfedges
//   where the two boundaries meet, or remove_vertex where one vertex has no faces (the
//   template of edit_rules.h, shared with edit_polyhedron.cpp).
//
// Garbage collection keeps the survivors' order, as MeshEdit promises; collect_garbage fills
// each hole with the last live element (two indices walking towards each other), so the
// compaction builds the mesh again from the live elements in order (add_vertex, add_face):
// O(n), like the half-edge family's own. The collapse test above calls collect_garbage itself,
// as the benchmark's protocol does (only new vertices, the last ones, are removed there).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/internal/helpers.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <vector>

#include "edit.h"
#include "edit_rules.h"
#include "mesh.h"

namespace topolab_cgal {
namespace {

using namespace edit_rules;
using edit_rules::BOUNDARY_EDGE;

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using VI = SurfaceMesh::Vertex_index;
using HI = SurfaceMesh::Halfedge_index;
using EI = SurfaceMesh::Edge_index;
using FI = SurfaceMesh::Face_index;

// The Surface_mesh behind a mesh of the shim (built by surface_mesh.cpp).
SurfaceMesh &surface_mesh(topolab_cgal_mesh *mesh) {
  return *static_cast<SurfaceMesh *>(mesh->native());
}

void sqrt3(SurfaceMesh &m) {
  const size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), nf = m.number_of_faces();
  m.reserve(nv + nf, ne + 3 * nf, 3 * nf);
  auto new_pos = m.add_property_map<VI, Point>("v:topolab_sqrt3").first;
  for (size_t i = 0; i < nv; ++i) {
    const VI v(i);
    if (m.is_border(v)) continue;
    const double n = m.degree(v);
    const double alpha = (4.0 - 2.0 * std::cos(2.0 * CGAL_PI / n)) / 9.0;
    Vector p(0, 0, 0);
    for (VI w : m.vertices_around_target(m.halfedge(v))) p = p + (m.point(w) - CGAL::ORIGIN);
    new_pos[v] = CGAL::ORIGIN + ((1.0 - alpha) * (m.point(v) - CGAL::ORIGIN) + alpha / n * p);
  }
  for (size_t i = 0; i < nf; ++i) {
    const FI f(i);
    Vector p(0, 0, 0);
    double c = 0;
    for (VI w : m.vertices_around_face(m.halfedge(f))) {
      p = p + (m.point(w) - CGAL::ORIGIN);
      c += 1;
    }
    const VI v = m.target(CGAL::Euler::add_center_vertex(m.halfedge(f), m));
    m.point(v) = CGAL::ORIGIN + p / c;
  }
  for (size_t i = 0; i < nv; ++i)
    if (!m.is_border(VI(i))) m.point(VI(i)) = new_pos[VI(i)];
  m.remove_property_map(new_pos);
  for (size_t i = 0; i < ne; ++i)
    if (!m.is_border(EI(i))) CGAL::Euler::flip_edge(m.halfedge(EI(i)), m);
}

void collapse_test(SurfaceMesh &m) {
  const size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), nf = m.number_of_faces();
  m.reserve(nv + nf, ne + 3 * nf, 3 * nf);
  for (size_t i = 0; i < nf; ++i) {
    const VI v = m.target(CGAL::Euler::add_center_vertex(m.halfedge(FI(i)), m));
    m.point(v) = Point(0, 0, 0);
  }
  const size_t end = m.number_of_vertices();
  for (size_t i = nv; i < end; ++i) {
    const HI from_new = m.opposite(m.halfedge(VI(i)));
    CGAL::Euler::collapse_edge(m.edge(from_new), m);
  }
  m.collect_garbage();
}


// --- MeshEdit ----------------------------------------------------------------------------

const HI NO_HALFEDGE = SurfaceMesh::null_halfedge();

bool live(const SurfaceMesh &m, uint32_t v) { return v < m.num_vertices() && !m.is_removed(VI(v)); }
bool live_edge(const SurfaceMesh &m, uint32_t e) { return e < m.num_edges() && !m.is_removed(EI(e)); }
bool live_face(const SurfaceMesh &m, uint32_t f) { return f < m.num_faces() && !m.is_removed(FI(f)); }

// The halfedge from a to b, or the null halfedge.
HI find(const SurfaceMesh &m, VI a, VI b) {
  if (m.is_isolated(a)) return NO_HALFEDGE;
  return m.halfedge(a, b);
}
bool triangle(const SurfaceMesh &m, HI h) { return m.next(m.next(m.next(h))) == h; }
// The next halfedge leaving the same vertex.
HI rotate(const SurfaceMesh &m, HI h) { return m.next(m.opposite(h)); }
// Has v a border halfedge around it (every incident halfedge looked at)?
bool boundary_vertex(const SurfaceMesh &m, VI v) {
  return !m.is_isolated(v) && m.is_border(v, /*check_all_incident_halfedges=*/true);
}
// The halfedges leaving v, from one of them.
HI some_outgoing(const SurfaceMesh &m, VI v) { return m.opposite(m.halfedge(v)); }

// Surface_mesh's border test reads one halfedge (is_border(v, false)), which the lab's
// boundary query uses: "if algorithms operating on a surface mesh maintain that the halfedge
// associated to a border vertex is a border halfedge" (Surface_mesh's reference, "Borders").
// Euler::split_vertex (and split_edge, built on it) does not maintain it (its calls to do so
// are commented out in CGAL 5.5), so each edit restores it around what it touched.
void restore_border_halfedges(SurfaceMesh &m, std::initializer_list<VI> touched) {
  for (VI v : touched)
    if (v != VI() && !m.is_isolated(v)) m.set_vertex_halfedge_to_border_halfedge(v);
}

// The fans vertex w keeps when the faces `removed` go: runs of remaining faces around it.
size_t fans_without(const SurfaceMesh &m, VI w, const std::vector<FI> &removed) {
  if (m.is_isolated(w)) return 0;
  const HI start = some_outgoing(m, w);
  auto present = [&](HI h) {
    const FI f = m.face(h);
    return f != SurfaceMesh::null_face() &&
           std::find(removed.begin(), removed.end(), f) == removed.end();
  };
  size_t runs = 0;
  bool all = true;
  HI h = start;
  do {
    const bool here = present(h), before = present(rotate(m, h));
    all = all && here;
    runs += (before && !here) ? 1 : 0;
    h = rotate(m, h);
  } while (h != start);
  return all ? 1 : runs;
}

// CGAL::Euler::remove_face (CGAL 5.5, boost/graph/Euler_operations.h) with one change: a
// vertex left without edges keeps its slot, unused (CGAL removes it).
void remove_face_keeping_vertices(HI h, SurfaceMesh &g) {
  const FI f = g.face(h);
  const HI end = h;
  do {
    CGAL::internal::set_border(h, g);
    const HI nh = g.next(h);
    const bool h_border = g.is_border(g.opposite(h));
    const bool nh_bborder = g.is_border(g.opposite(nh));
    if (h_border && nh_bborder && g.next(g.opposite(nh)) == g.opposite(h)) {
      g.set_halfedge(g.target(h), NO_HALFEDGE);  // CGAL: remove_vertex(target(h, g), g)
      if (h != end) g.remove_edge(g.edge(h));
    } else {
      if (nh_bborder) {
        CGAL::internal::set_vertex_halfedge(g.opposite(g.next(g.opposite(nh))), g);
        CGAL::internal::remove_tip(h, g);
      }
      if (h_border) {
        CGAL::internal::set_vertex_halfedge(g.opposite(g.next(h)), g);
        CGAL::internal::remove_tip(g.prev(g.opposite(h)), g);
        if (h != end) g.remove_edge(g.edge(h));
      }
    }
    h = nh;
  } while (h != end);
  g.remove_face(f);
  if (g.is_border(g.opposite(h))) g.remove_edge(g.edge(h));
}

int add_face(SurfaceMesh &m, const uint32_t *vs, uint32_t n, uint32_t *out) {
  if (n < 3) return BAD_FACE;
  for (uint32_t i = 1; i < n; ++i)
    if (std::find(vs, vs + i, vs[i]) != vs + i) return BAD_FACE;
  for (uint32_t i = 0; i < n; ++i)
    if (!live(m, vs[i])) return NO_SUCH_ELEMENT;
  std::vector<HI> hs(n);
  for (uint32_t i = 0; i < n; ++i) {
    const VI a(vs[i]), b(vs[(i + 1) % n]);
    if (!m.is_isolated(a) && !boundary_vertex(m, a)) return NON_MANIFOLD_VERTEX;
    hs[i] = find(m, a, b);
    if (hs[i] != NO_HALFEDGE && !m.is_border(hs[i])) return NON_MANIFOLD_EDGE;
  }
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t ii = (i + 1) % n;
    const VI v(vs[ii]);
    // Two old sides meeting at v must be consecutive on v's one border gap; two new sides at
    // a used vertex would give it a second fan.
    const bool old_i = hs[i] != NO_HALFEDGE, old_ii = hs[ii] != NO_HALFEDGE;
    if (old_i && old_ii && m.next(hs[i]) != hs[ii]) return NON_MANIFOLD_VERTEX;
    if (!old_i && !old_ii && !m.is_isolated(v)) return NON_MANIFOLD_VERTEX;
  }
  std::vector<VI> corners;
  for (uint32_t i = 0; i < n; ++i) corners.push_back(VI(vs[i]));
  const FI f = CGAL::Euler::add_face(corners, m);
  if (f == SurfaceMesh::null_face()) throw std::runtime_error("add_face refused a checked face");
  *out = uint32_t(f);
  return OK_EDIT;
}

int delete_face(SurfaceMesh &m, uint32_t fi) {
  if (!live_face(m, fi)) return NO_SUCH_ELEMENT;
  const FI f(fi);
  // A border vertex keeps one fan only if the face is at an end of it.
  for (HI h : m.halfedges_around_face(m.halfedge(f))) {
    const VI v = m.source(h);
    if (boundary_vertex(m, v) && !m.is_border(m.opposite(m.prev(h))) &&
        !m.is_border(m.opposite(h)))
      return NON_MANIFOLD_VERTEX;
  }
  std::vector<VI> corners;
  for (VI w : m.vertices_around_face(m.halfedge(f))) corners.push_back(w);
  remove_face_keeping_vertices(m.halfedge(f), m);
  // Its corners are border vertices now: remove_face re-points only the tips it removes.
  for (VI w : corners)
    if (!m.is_isolated(w)) m.set_vertex_halfedge_to_border_halfedge(w);
  return OK_EDIT;
}

int delete_vertex(SurfaceMesh &m, uint32_t vi) {
  if (!live(m, vi)) return NO_SUCH_ELEMENT;
  const VI v(vi);
  std::vector<FI> faces;
  std::vector<VI> corners;
  if (!m.is_isolated(v)) {
    for (FI f : m.faces_around_target(m.halfedge(v))) {
      if (f == SurfaceMesh::null_face()) continue;
      faces.push_back(f);
      for (VI w : m.vertices_around_face(m.halfedge(f)))
        if (w != v) corners.push_back(w);
    }
  }
  for (VI w : corners)
    if (fans_without(m, w, faces) > 1) return NON_MANIFOLD_VERTEX;
  for (FI f : faces) remove_face_keeping_vertices(m.halfedge(f), m);
  // Its neighbours are border vertices now (see delete_face).
  for (VI w : corners)
    if (!m.is_isolated(w)) m.set_vertex_halfedge_to_border_halfedge(w);
  m.set_halfedge(v, NO_HALFEDGE);
  m.remove_vertex(v);
  return OK_EDIT;
}

int flip(SurfaceMesh &m, uint32_t ei) {
  if (!live_edge(m, ei)) return NO_SUCH_ELEMENT;
  const HI a0 = m.halfedge(EI(ei)), b0 = m.opposite(a0);
  if (m.is_border(a0) || m.is_border(b0)) return BOUNDARY_EDGE;
  if (!triangle(m, a0) || !triangle(m, b0)) return NOT_TRIANGLES;
  const VI x = m.target(m.next(a0)), y = m.target(m.next(b0));
  if (x == y || find(m, x, y) != NO_HALFEDGE) return EDGE_EXISTS;
  const VI u = m.source(a0), w = m.target(a0);
  CGAL::Euler::flip_edge(a0, m);
  restore_border_halfedges(m, {u, w, x, y});
  return OK_EDIT;
}

int split_edge(SurfaceMesh &m, uint32_t ei, const Point &p, uint32_t *out) {
  if (!live_edge(m, ei)) return NO_SUCH_ELEMENT;
  const HI h0 = m.halfedge(EI(ei)), o0 = m.opposite(h0);
  if ((!m.is_border(h0) && !triangle(m, h0)) || (!m.is_border(o0) && !triangle(m, o0)))
    return NOT_TRIANGLES;
  if (!m.is_border(h0) && !m.is_border(o0) && m.target(m.next(h0)) == m.target(m.next(o0)))
    return EDGE_EXISTS;
  // a -> b becomes a -> v (hnew), v -> b (h0); each triangle beside it a quad, cut at v.
  const HI hnew = CGAL::Euler::split_edge(h0, m);
  const VI v = m.target(hnew);
  m.point(v) = p;
  if (!m.is_border(h0)) CGAL::Euler::split_face(hnew, m.next(h0), m);
  const HI back = m.opposite(h0), back_new = m.opposite(hnew);  // b -> v, v -> a
  if (!m.is_border(back)) CGAL::Euler::split_face(back, m.next(back_new), m);
  restore_border_halfedges(m, {v, m.source(hnew), m.target(h0)});
  *out = uint32_t(v);
  return OK_EDIT;
}

int split_face(SurfaceMesh &m, uint32_t fi, const Point &p, uint32_t *out) {
  if (!live_face(m, fi)) return NO_SUCH_ELEMENT;
  const VI v = m.target(CGAL::Euler::add_center_vertex(m.halfedge(FI(fi)), m));
  m.point(v) = p;
  for (VI w : m.vertices_around_target(m.halfedge(v))) restore_border_halfedges(m, {w});
  *out = uint32_t(v);
  return OK_EDIT;
}

// pmp's (and the half-edge family's) is_collapse_ok for the halfedge h from v0 to v1
// (LINK_CONDITION), with the tetrahedron test of OpenMesh's Decimater (is_collapse_legal) after
// the vl == vr rule (TETRAHEDRON_TEST, not the link condition: vl and vr neighbours of valence
// 3): the refusal code, OK_EDIT when the collapse may be done.
int lab_collapse_refusal(const SurfaceMesh &m, HI h) {
  const HI o = m.opposite(h);
  const VI v0 = m.source(h), v1 = m.target(h);
  VI vl, vr;  // default: null vertex
  if (!m.is_border(h)) {
    const HI h1 = m.next(h), h2 = m.next(h1);
    vl = m.target(h1);
    if (m.is_border(m.opposite(h1)) && m.is_border(m.opposite(h2))) return LINK_CONDITION;
  }
  if (!m.is_border(o)) {
    const HI o1 = m.next(o), o2 = m.next(o1);
    vr = m.target(o1);
    if (m.is_border(m.opposite(o1)) && m.is_border(m.opposite(o2))) return LINK_CONDITION;
  }
  if (vl == vr) return LINK_CONDITION;
  const VI none;
  if (vl != none && vr != none && find(m, vl, vr) != NO_HALFEDGE && m.degree(vl) == 3 &&
      m.degree(vr) == 3)
    return TETRAHEDRON_TEST;
  if (boundary_vertex(m, v0) && boundary_vertex(m, v1) && !m.is_border(h) && !m.is_border(o))
    return LINK_CONDITION;
  for (VI w : m.vertices_around_target(m.halfedge(v0)))
    if (w != v1 && w != vl && w != vr && find(m, w, v1) != NO_HALFEDGE) return LINK_CONDITION;
  return OK_EDIT;
}

int collapse(SurfaceMesh &m, uint32_t from, uint32_t to) {
  if (!live(m, from) || !live(m, to)) return NO_SUCH_ELEMENT;
  const HI h = find(m, VI(from), VI(to));
  if (h == NO_HALFEDGE) return NOT_NEIGHBOURS;
  HI g = h;
  do {
    if (!m.is_border(g) && !triangle(m, g)) return NOT_TRIANGLES;
    g = rotate(m, g);
  } while (g != h);
  const int refused = lab_collapse_refusal(m, h);
  if (refused != OK_EDIT) return refused;
  const EI e = m.edge(h);  // made from h: its halfedge is h, whose source goes
  if (!CGAL::Euler::does_satisfy_link_condition(e, m)) return LINK_CONDITION;
  const VI kept = CGAL::Euler::collapse_edge(e, m);
  restore_border_halfedges(m, {kept});
  for (VI w : m.vertices_around_target(m.halfedge(kept))) restore_border_halfedges(m, {w});
  return OK_EDIT;
}

int split_vertex(SurfaceMesh &m, uint32_t v1i, const Point &p, uint32_t vli, uint32_t vri,
                 uint32_t *out) {
  if (!live(m, v1i) || !live(m, vli) || !live(m, vri)) return NO_SUCH_ELEMENT;
  if (vli == vri || vli == v1i || vri == v1i) return NOT_NEIGHBOURS;
  const VI v1(v1i), vl(vli), vr(vri);
  const HI a = find(m, v1, vr), b = find(m, v1, vl);
  if (a == NO_HALFEDGE || b == NO_HALFEDGE) return NOT_NEIGHBOURS;
  // The halfedges after `a` up to `b` move to the new vertex; their faces must be faces (a
  // border inside the moved fan is the inverse of a boundary collapse, which the lab's
  // split_vertex does not take).
  HI g = rotate(m, a);
  while (true) {
    if (m.is_border(g)) return NOT_IMPLEMENTED;
    if (g == b) break;
    g = rotate(m, g);
  }
  // split_vertex(h1, h2) moves the incoming halfedges after h1 up to h2 (rotating as
  // opposite(next(.)) does): h1 = vr -> v1, h2 = vl -> v1; it returns the new edge's halfedge
  // to v1, from the new vertex.
  const HI hnew = CGAL::Euler::split_vertex(m.opposite(a), m.opposite(b), m);
  const VI v0 = m.source(hnew);
  m.point(v0) = p;
  // hnew lies in the face of vl -> v1, now (.., vl, v0, v1, ..), and its opposite in the face
  // of vr -> v1, now (.., vr, v1, v0, ..): each cut closes one of the two new triangles. Where
  // that side was the border (v1-vl or v1-vr a boundary edge), the triangle is added there.
  const HI back = m.opposite(hnew);  // v1 -> v0
  const HI to_vl = m.prev(m.prev(hnew)), to_vr = m.prev(m.prev(back));
  if (m.target(to_vl) != vl || m.target(to_vr) != vr)
    throw std::logic_error("split_vertex regrouped another fan");
  auto close = [&](HI h, HI to, std::initializer_list<VI> triangle) {
    if (!m.is_border(h)) {
      CGAL::Euler::split_face(h, to, m);
    } else if (CGAL::Euler::add_face(std::vector<VI>(triangle), m) == SurfaceMesh::null_face()) {
      throw std::logic_error("add_face refused a triangle of the split");
    }
  };
  close(hnew, to_vl, {v0, v1, vl});
  close(back, to_vr, {v1, v0, vr});
  restore_border_halfedges(m, {v0, v1, vl, vr});
  *out = uint32_t(v0);
  return OK_EDIT;
}

// The weld's id table (edit_rules.h): Surface_mesh's indices, which only mark removal, so
// nothing is buried; a vertex whose halfedge CGAL set gets its border halfedge back.
struct WeldIds {
  SurfaceMesh &m;
  bool live(uint32_t v) const { return topolab_cgal::live(m, v); }
  VI vertex(uint32_t v) const { return VI(v); }
  uint32_t id(VI v) const { return uint32_t(v); }
  void bury_vertex(uint32_t) {}
  void bury_edge(HI) {}
  void touched(VI v) { restore_border_halfedges(m, {v}); }
};

int weld(SurfaceMesh &m, uint32_t a, uint32_t b) {
  WeldIds ids{m};
  return weld_vertices(m, ids, a, b);
}

// The survivors in their order (see the file's notes): positions and face lists read, the
// mesh cleared and built again with add_vertex and add_face.
void compact(SurfaceMesh &m) {
  std::vector<int64_t> map(m.num_vertices(), -1);
  std::vector<Point> points;
  int64_t next = 0;
  for (VI v : m.vertices()) {
    map[size_t(v)] = next++;
    points.push_back(m.point(v));
  }
  std::vector<uint32_t> corners, offsets{0};
  for (FI f : m.faces()) {
    for (VI v : m.vertices_around_face(m.halfedge(f))) corners.push_back(uint32_t(map[size_t(v)]));
    offsets.push_back(uint32_t(corners.size()));
  }
  const size_t edges = m.number_of_edges();
  m.clear();
  m.set_recycle_garbage(false);
  m.reserve(points.size(), edges, offsets.size() - 1);
  for (const Point &p : points) m.add_vertex(p);
  std::vector<VI> face;
  for (size_t j = 0; j + 1 < offsets.size(); ++j) {
    face.clear();
    for (uint32_t c = offsets[j]; c < offsets[j + 1]; ++c) face.push_back(VI(corners[c]));
    if (CGAL::Euler::add_face(face, m) == SurfaceMesh::null_face())
      throw std::runtime_error("add_face refused a live face");
  }
}

// Runs an edit: OK, or EDIT_REFUSED with *refusal set. Recycling is switched off first.
template <class F> int edit(topolab_cgal_mesh *mesh, int *refusal, F &&body) {
  return guard([&] {
    SurfaceMesh &m = surface_mesh(mesh);
    m.set_recycle_garbage(false);
    const int r = body(m);
    if (r == OK_EDIT) return TOPOLAB_CGAL_OK;
    *refusal = r;
    return TOPOLAB_CGAL_EDIT_REFUSED;
  });
}

Point point(const double *p) { return point_of<Point>(p); }

}  // namespace
}  // namespace topolab_cgal

extern "C" {

int topolab_cgal_sm_changing(topolab_cgal_mesh *mesh, int workload) noexcept {
  using namespace topolab_cgal;
  if (workload != 0 && workload != 1) return TOPOLAB_CGAL_UNKNOWN_CODE;
  const int done = guard([&] {
    SurfaceMesh &m = surface_mesh(mesh);
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

int topolab_cgal_sm_edit_add_vertex(topolab_cgal_mesh *mesh, const double *p,
                                    uint32_t *out) noexcept {
  using namespace topolab_cgal;
  int unused = 0;
  return edit(mesh, &unused, [&](SurfaceMesh &m) {
    *out = uint32_t(m.add_vertex(point(p)));
    return int(OK_EDIT);
  });
}

int topolab_cgal_sm_edit_set_position(topolab_cgal_mesh *mesh, uint32_t v, const double *p,
                                      int *refusal) noexcept {
  using namespace topolab_cgal;
  return edit(mesh, refusal, [&](SurfaceMesh &m) {
    if (!live(m, v)) return int(NO_SUCH_ELEMENT);
    m.point(VI(v)) = point(p);
    return int(OK_EDIT);
  });
}

TOPOLAB_CGAL_EDIT_CALLS(sm, SurfaceMesh)

int topolab_cgal_sm_edit_is_deleted(const topolab_cgal_mesh *mesh, int kind, uint32_t id,
                                    int *out) noexcept {
  using namespace topolab_cgal;
  return guard([&] {
    if (kind < 0 || kind > 2) return TOPOLAB_CGAL_UNKNOWN_CODE;
    const SurfaceMesh &m = *static_cast<const SurfaceMesh *>(
        const_cast<topolab_cgal_mesh *>(mesh)->native());
    switch (kind) {
      case 0: *out = id < m.num_vertices() && m.is_removed(VI(id)) ? 1 : 0; break;
      case 1: *out = id < m.num_edges() && m.is_removed(EI(id)) ? 1 : 0; break;
      default: *out = id < m.num_faces() && m.is_removed(FI(id)) ? 1 : 0; break;
    }
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_sm_edit_garbage_collection(topolab_cgal_mesh *mesh) noexcept {
  using namespace topolab_cgal;
  return guard([&] {
    SurfaceMesh &m = surface_mesh(mesh);
    if (m.has_garbage()) compact(m);
    return TOPOLAB_CGAL_OK;
  });
}

int topolab_cgal_sm_edit_reserve(topolab_cgal_mesh *mesh, uint32_t vertices, uint32_t edges,
                                 uint32_t faces) noexcept {
  using namespace topolab_cgal;
  return guard([&] {
    SurfaceMesh &m = surface_mesh(mesh);
    m.reserve(m.num_vertices() + vertices, m.num_edges() + edges, m.num_faces() + faces);
    return TOPOLAB_CGAL_OK;
  });
}

}  // extern "C"
