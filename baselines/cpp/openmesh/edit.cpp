// The C API of edit.h: topolab's MeshEdit through OpenMesh's own operations (add_vertex,
// add_face, delete_face, delete_vertex, TriConnectivity's flip, 2-to-4 split and
// vertex_split, PolyConnectivity's face split and collapse), and the vertex weld, which
// OpenMesh lacks, written with its low-level connectivity setters as its own operators are.
//
// Each operation first checks everything that could make it refuse, with OpenMesh's handles
// and circulators, and only then calls OpenMesh, so that a refused edit writes nothing and
// OpenMesh is never called outside its preconditions (flip only asserts is_flip_ok, and the
// assertion is compiled out of OpenMesh's release build, which build.rs makes; collapse and
// vertex_split trust their caller). The checks are the lab's rules (the ones the half-edge
// family enforces, structures/src/families/half_edge/edit/euler.rs) plus OpenMesh's own
// predicates where it has one (is_flip_ok, is_collapse_ok), called as well: where the two
// ever disagreed, the edit would be refused, never forced.
//
// What OpenMesh allows and the lab refuses, because the result would not be an oriented
// manifold with one fan per vertex: OpenMesh's add_face links a face that touches a used
// vertex with two new edges as a second fan of that vertex; delete_face and delete_vertex
// leave a vertex with two fans; its is_collapse_ok passes the collapse of an edge of a closed
// tetrahedron's kind (vl and vr neighbours of valence 3), which leaves two triangles on the
// same three vertices: refused with TETRAHEDRON_TEST, the test OpenMesh's own Decimater adds
// (BaseDecimaterT::is_collapse_legal), not the link condition.
//
// A PolyMesh (polygon input) has no flip, no 2-to-4 edge split and no vertex split (they are
// TriConnectivity's): those edits are refused there with NOT_IMPLEMENTED after the other
// checks.

#include "edit.h"

#include "mesh.h"

#include <algorithm>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace {

using namespace topolab_om;

// The refusal codes of edit.h; OK_EDIT when the edit is allowed (or done).
enum Refusal {
  OK_EDIT = -1,
  NO_SUCH_ELEMENT = TOPOLAB_OM_REFUSAL_NO_SUCH_ELEMENT,
  BAD_FACE = TOPOLAB_OM_REFUSAL_BAD_FACE,
  NON_MANIFOLD_EDGE = TOPOLAB_OM_REFUSAL_NON_MANIFOLD_EDGE,
  NON_MANIFOLD_VERTEX = TOPOLAB_OM_REFUSAL_NON_MANIFOLD_VERTEX,
  NOT_TRIANGLES = TOPOLAB_OM_REFUSAL_NOT_TRIANGLES,
  BOUNDARY_EDGE = TOPOLAB_OM_REFUSAL_BOUNDARY_EDGE,
  EDGE_EXISTS = TOPOLAB_OM_REFUSAL_EDGE_EXISTS,
  NOT_NEIGHBOURS = TOPOLAB_OM_REFUSAL_NOT_NEIGHBOURS,
  LINK_CONDITION = TOPOLAB_OM_REFUSAL_LINK_CONDITION,
  NOT_IMPLEMENTED = TOPOLAB_OM_REFUSAL_NOT_IMPLEMENTED,
  SAME_VERTEX = TOPOLAB_OM_REFUSAL_SAME_VERTEX,
  TETRAHEDRON_TEST = TOPOLAB_OM_REFUSAL_TETRAHEDRON_TEST,
};

template <class M> constexpr bool is_tri() { return std::is_same<M, Tri>::value; }

template <class M> bool live(const M &m, uint32_t v) {
  return v < m.n_vertices() && !m.status(VH(int(v))).deleted();
}
template <class M> bool live_edge(const M &m, uint32_t e) {
  return e < m.n_edges() && !m.status(EH(int(e))).deleted();
}
template <class M> bool live_face(const M &m, uint32_t f) {
  return f < m.n_faces() && !m.status(FH(int(f))).deleted();
}

// The next halfedge leaving the same vertex.
template <class M> HH rotate(const M &m, HH h) {
  return m.next_halfedge_handle(m.opposite_halfedge_handle(h));
}
template <class M> bool triangle(const M &m, HH h) {
  return m.next_halfedge_handle(m.next_halfedge_handle(m.next_halfedge_handle(h))) == h;
}
// Is a halfedge leaving v a boundary one? (OpenMesh keeps one as a boundary vertex's outgoing
// halfedge, but only where its own operations adjust it; the rotation does not rely on that.)
template <class M> bool boundary_vertex(const M &m, VH v) {
  for (HH h : m.voh_range(v))
    if (m.is_boundary(h)) return true;
  return false;
}
template <class M> size_t valence(const M &m, VH v) {
  size_t n = 0;
  for (VH w : m.vv_range(v)) {
    (void)w;
    ++n;
  }
  return n;
}

// The fans vertex w keeps when the faces `removed` go: runs of remaining faces around it.
template <class M> size_t fans_without(const M &m, VH w, const std::vector<FH> &removed) {
  const HH start = m.halfedge_handle(w);
  if (!start.is_valid()) return 0;
  auto present = [&](HH h) {
    const FH f = m.face_handle(h);
    return f.is_valid() && std::find(removed.begin(), removed.end(), f) == removed.end();
  };
  size_t runs = 0;
  bool all = true;
  HH h = start;
  do {
    const bool here = present(h), before = present(rotate(m, h));
    all = all && here;
    runs += (before && !here) ? 1 : 0;
    h = rotate(m, h);
  } while (h != start);
  return all ? 1 : runs;
}

template <class M> int add_face(M &m, const uint32_t *vs, uint32_t n, uint32_t *out) {
  if (n < 3) return BAD_FACE;
  for (uint32_t i = 1; i < n; ++i)
    if (std::find(vs, vs + i, vs[i]) != vs + i) return BAD_FACE;
  for (uint32_t i = 0; i < n; ++i)
    if (!live(m, vs[i])) return NO_SUCH_ELEMENT;
  // A TriMesh's add_face would triangulate a polygon into several faces.
  if (is_tri<M>() && n != 3) return NOT_TRIANGLES;
  std::vector<HH> hs(n);
  for (uint32_t i = 0; i < n; ++i) {
    const VH a(int(vs[i])), b(int(vs[(i + 1) % n]));
    const HH out_a = m.halfedge_handle(a);
    if (out_a.is_valid() && !m.is_boundary(out_a)) return NON_MANIFOLD_VERTEX;
    hs[i] = m.find_halfedge(a, b);
    if (hs[i].is_valid() && !m.is_boundary(hs[i])) return NON_MANIFOLD_EDGE;
  }
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t ii = (i + 1) % n;
    const VH v(int(vs[ii]));
    // Two old sides meeting at v must be consecutive on v's one boundary gap (OpenMesh would
    // relink the fans); two new sides at a used vertex would give it a second fan.
    const bool old_i = hs[i].is_valid(), old_ii = hs[ii].is_valid();
    if (old_i && old_ii && m.next_halfedge_handle(hs[i]) != hs[ii]) return NON_MANIFOLD_VERTEX;
    if (!old_i && !old_ii && m.halfedge_handle(v).is_valid()) return NON_MANIFOLD_VERTEX;
  }
  std::vector<VH> corners;
  for (uint32_t i = 0; i < n; ++i) corners.push_back(VH(int(vs[i])));
  const FH f = m.add_face(corners);
  if (!f.is_valid()) return NON_MANIFOLD_VERTEX;  // not reached: checked above
  *out = uint32_t(f.idx());
  return OK_EDIT;
}

template <class M> int delete_face(M &m, uint32_t fi) {
  if (!live_face(m, fi)) return NO_SUCH_ELEMENT;
  const FH f{int(fi)};
  // A boundary vertex keeps one fan only if the face is at an end of it.
  for (HH h : m.fh_range(f)) {
    const VH v = m.from_vertex_handle(h);
    if (boundary_vertex(m, v) &&
        !m.is_boundary(m.opposite_halfedge_handle(m.prev_halfedge_handle(h))) &&
        !m.is_boundary(m.opposite_halfedge_handle(h)))
      return NON_MANIFOLD_VERTEX;
  }
  m.delete_face(f, /*_delete_isolated_vertices=*/false);
  return OK_EDIT;
}

template <class M> int delete_vertex(M &m, uint32_t vi) {
  if (!live(m, vi)) return NO_SUCH_ELEMENT;
  const VH v{int(vi)};
  std::vector<FH> faces;
  std::vector<VH> corners;
  for (FH f : m.vf_range(v)) {
    faces.push_back(f);
    for (VH w : m.fv_range(f))
      if (w != v) corners.push_back(w);
  }
  for (VH w : corners)
    if (fans_without(m, w, faces) > 1) return NON_MANIFOLD_VERTEX;
  m.delete_vertex(v, /*_delete_isolated_vertices=*/false);
  return OK_EDIT;
}

template <class M> int flip(M &m, uint32_t ei) {
  if (!live_edge(m, ei)) return NO_SUCH_ELEMENT;
  const EH e{int(ei)};
  const HH a0 = m.halfedge_handle(e, 0), b0 = m.halfedge_handle(e, 1);
  if (m.is_boundary(a0) || m.is_boundary(b0)) return BOUNDARY_EDGE;
  if (!triangle(m, a0) || !triangle(m, b0)) return NOT_TRIANGLES;
  const VH x = m.to_vertex_handle(m.next_halfedge_handle(a0));
  const VH y = m.to_vertex_handle(m.next_halfedge_handle(b0));
  if (x == y || m.find_halfedge(x, y).is_valid()) return EDGE_EXISTS;
  if constexpr (is_tri<M>()) {
    if (!m.is_flip_ok(e)) return EDGE_EXISTS;
    m.flip(e);
    return OK_EDIT;
  } else {
    return NOT_IMPLEMENTED;
  }
}

template <class M> int split_edge(M &m, uint32_t ei, const double *p, uint32_t *out) {
  if (!live_edge(m, ei)) return NO_SUCH_ELEMENT;
  const EH e{int(ei)};
  const HH h0 = m.halfedge_handle(e, 0), o0 = m.halfedge_handle(e, 1);
  if ((!m.is_boundary(h0) && !triangle(m, h0)) || (!m.is_boundary(o0) && !triangle(m, o0)))
    return NOT_TRIANGLES;
  // Two triangles (a, b, c) and (b, a, c) would both give an edge from the new vertex to c.
  if (!m.is_boundary(h0) && !m.is_boundary(o0) &&
      m.to_vertex_handle(m.next_halfedge_handle(h0)) ==
          m.to_vertex_handle(m.next_halfedge_handle(o0)))
    return EDGE_EXISTS;
  if constexpr (is_tri<M>()) {
    const VH v = m.add_vertex(typename M::Point(p[0], p[1], p[2]));
    m.split(e, v);
    *out = uint32_t(v.idx());
    return OK_EDIT;
  } else {
    (void)p;
    (void)out;
    return NOT_IMPLEMENTED;
  }
}

template <class M> int split_face(M &m, uint32_t fi, const double *p, uint32_t *out) {
  if (!live_face(m, fi)) return NO_SUCH_ELEMENT;
  const VH v = m.add_vertex(typename M::Point(p[0], p[1], p[2]));
  m.split(FH(int(fi)), v);
  *out = uint32_t(v.idx());
  return OK_EDIT;
}

// pmp's (and the half-edge family's) is_collapse_ok for the halfedge h from v0 to v1, both
// sides triangles (the tests of OpenMesh's is_collapse_ok: LINK_CONDITION), with the
// tetrahedron test OpenMesh's Decimater adds in is_collapse_legal (TETRAHEDRON_TEST) after the
// vl == vr rule, as the half-edge family orders them; OK_EDIT when the collapse may be done.
template <class M> int lab_collapse_refusal(const M &m, HH h) {
  const HH o = m.opposite_halfedge_handle(h);
  const VH v0 = m.from_vertex_handle(h), v1 = m.to_vertex_handle(h);
  VH vl, vr;
  if (!m.is_boundary(h)) {
    const HH h1 = m.next_halfedge_handle(h), h2 = m.next_halfedge_handle(h1);
    vl = m.to_vertex_handle(h1);
    if (m.is_boundary(m.opposite_halfedge_handle(h1)) &&
        m.is_boundary(m.opposite_halfedge_handle(h2)))
      return LINK_CONDITION;
  }
  if (!m.is_boundary(o)) {
    const HH o1 = m.next_halfedge_handle(o), o2 = m.next_halfedge_handle(o1);
    vr = m.to_vertex_handle(o1);
    if (m.is_boundary(m.opposite_halfedge_handle(o1)) &&
        m.is_boundary(m.opposite_halfedge_handle(o2)))
      return LINK_CONDITION;
  }
  if (vl == vr) return LINK_CONDITION;
  if (vl.is_valid() && vr.is_valid() && m.find_halfedge(vl, vr).is_valid() &&
      valence(m, vl) == 3 && valence(m, vr) == 3)
    return TETRAHEDRON_TEST;
  if (boundary_vertex(m, v0) && boundary_vertex(m, v1) && !m.is_boundary(h) &&
      !m.is_boundary(o))
    return LINK_CONDITION;
  for (VH w : m.vv_range(v0))
    if (w != v1 && w != vl && w != vr && m.find_halfedge(w, v1).is_valid())
      return LINK_CONDITION;
  return OK_EDIT;
}

template <class M> int collapse(M &m, uint32_t from, uint32_t to) {
  if (!live(m, from) || !live(m, to)) return NO_SUCH_ELEMENT;
  const HH h = m.find_halfedge(VH(int(from)), VH(int(to)));
  if (!h.is_valid()) return NOT_NEIGHBOURS;
  // Every face around `from` must be a triangle: a larger face holding both ends would
  // repeat a vertex.
  HH g = h;
  do {
    if (!m.is_boundary(g) && !triangle(m, g)) return NOT_TRIANGLES;
    g = rotate(m, g);
  } while (g != h);
  const int refused = lab_collapse_refusal(m, h);
  if (refused != OK_EDIT) return refused;
  // OpenMesh's own test too (it tags the one-rings: status bits, not the topology).
  if (!m.is_collapse_ok(h)) return LINK_CONDITION;
  m.collapse(h);
  return OK_EDIT;
}

template <class M>
int split_vertex(M &m, uint32_t v1i, const double *p, uint32_t vli, uint32_t vri,
                 uint32_t *out) {
  if (!live(m, v1i) || !live(m, vli) || !live(m, vri)) return NO_SUCH_ELEMENT;
  if (vli == vri || vli == v1i || vri == v1i) return NOT_NEIGHBOURS;
  const VH v1{int(v1i)}, vl{int(vli)}, vr{int(vri)};
  const HH a = m.find_halfedge(v1, vr), b = m.find_halfedge(v1, vl);
  if (!a.is_valid() || !b.is_valid()) return NOT_NEIGHBOURS;
  // The halfedges after `a` up to `b` move to the new vertex; their faces must be faces (a
  // boundary inside the moved fan is the inverse of a boundary collapse, which the lab's
  // split_vertex does not take).
  HH g = rotate(m, a);
  while (true) {
    if (m.is_boundary(g)) return NOT_IMPLEMENTED;
    if (g == b) break;
    g = rotate(m, g);
  }
  if constexpr (is_tri<M>()) {
    const VH v0 = m.add_vertex(typename M::Point(p[0], p[1], p[2]));
    m.vertex_split(v0, v1, vl, vr);
    *out = uint32_t(v0.idx());
    return OK_EDIT;
  } else {
    (void)p;
    (void)out;
    return NOT_IMPLEMENTED;
  }
}

// The halfedge into v on the boundary, invalid if v is interior: by rotation, as the half-edges'
// incoming_boundary (OpenMesh's own adjust_outgoing_halfedge is not relied on).
template <class M> HH boundary_into(const M &m, VH v) {
  const HH start = m.halfedge_handle(v);
  HH h = start;
  do {
    const HH in = m.opposite_halfedge_handle(h);
    if (m.is_boundary(in)) return in;
    h = rotate(m, h);
  } while (h != start);
  return HH();
}

// The boundary halfedge `keep` takes the place of opposite(drop) in its face, and the edge of
// `drop` (a boundary halfedge running against `keep`) is marked deleted, with both halfedges,
// as delete_edge marks them.
template <class M> void merge_boundary_edges(M &m, HH keep, HH drop) {
  const HH inner = m.opposite_halfedge_handle(drop);
  const HH before = m.prev_halfedge_handle(inner), after = m.next_halfedge_handle(inner);
  const FH f = m.face_handle(inner);
  m.set_face_handle(keep, f);
  m.set_next_halfedge_handle(before, keep);
  m.set_next_halfedge_handle(keep, after);
  if (m.halfedge_handle(f) == inner) m.set_halfedge_handle(f, keep);
  m.status(m.edge_handle(drop)).set_deleted(true);
  m.status(drop).set_deleted(true);
  m.status(inner).set_deleted(true);
}

// MeshEdit::weld_vertices, b merged into a. OpenMesh has no weld (its remove_edge merges two
// faces, not two vertices), so this is the half-edges' algorithm (structures/src/families/
// half_edge/edit/euler/weld.rs) written with ArrayKernel's low-level connectivity setters
// (set_vertex_handle, set_next_halfedge_handle, set_face_handle, set_halfedge_handle), as
// OpenMesh's own collapse_edge and remove_edge are: every halfedge into b ends at a; where the
// boundaries meet along an edge (a's runs q -> a -> p, b's s -> b -> r, with s == p or r == q),
// each pair of boundary edges becomes one interior edge, a's boundary halfedge taking the place
// of b's inner one in its face, and b's edge marked deleted. Face ids stay (deleting b's faces
// and adding them again with a, through the documented API, would give them new ids).
//
// Every check runs before the first write, with the half-edges' reasons in their order, so the
// shared cases agree: a dead id (NO_SUCH_ELEMENT); one vertex twice (SAME_VERTEX); a face around b holding a
// (BAD_FACE); both used and one interior, or boundaries that meet at no edge
// (NON_MANIFOLD_VERTEX); a neighbour of both other than p and q (NON_MANIFOLD_EDGE).
template <class M> int weld(M &m, uint32_t ai, uint32_t bi) {
  if (!live(m, ai) || !live(m, bi)) return NO_SUCH_ELEMENT;
  if (ai == bi) return SAME_VERTEX;
  const VH a{int(ai)}, b{int(bi)};
  const HH ob = m.halfedge_handle(b);
  if (!ob.is_valid()) {
    m.delete_vertex(b, /*_delete_isolated_vertices=*/false);  // nothing refers to b
    return OK_EDIT;
  }
  // No face around b may hold a (an edge a-b always has a face).
  HH h = ob;
  do {
    if (!m.is_boundary(h))
      for (VH v : m.fv_range(m.face_handle(h)))
        if (v == a) return BAD_FACE;
    h = rotate(m, h);
  } while (h != ob);
  HH a_in, a_out, b_in, b_out;
  VH p, q;
  bool at_p = false, at_q = false;
  if (m.halfedge_handle(a).is_valid()) {
    a_in = boundary_into(m, a);
    b_in = boundary_into(m, b);
    if (!a_in.is_valid() || !b_in.is_valid()) return NON_MANIFOLD_VERTEX;
    a_out = m.next_halfedge_handle(a_in);
    b_out = m.next_halfedge_handle(b_in);
    p = m.to_vertex_handle(a_out);
    q = m.from_vertex_handle(a_in);
    // Boundary halfedges that would run the same way (b -> p beside a -> p) cannot meet: p
    // would have two boundary halfedges into it.
    at_p = m.from_vertex_handle(b_in) == p;
    at_q = m.to_vertex_handle(b_out) == q;
    if (!at_p && !at_q) return NON_MANIFOLD_VERTEX;
    // Any other neighbour of both would get two edges to a.
    std::vector<int> around_a;
    for (VH w : m.vv_range(a)) around_a.push_back(w.idx());
    std::sort(around_a.begin(), around_a.end());
    for (VH y : m.vv_range(b)) {
      if ((at_p && y == p) || (at_q && y == q)) continue;
      if (std::binary_search(around_a.begin(), around_a.end(), y.idx())) return NON_MANIFOLD_EDGE;
    }
  }
  // Every halfedge into b ends at a.
  h = ob;
  do {
    m.set_vertex_handle(m.opposite_halfedge_handle(h), a);
    h = rotate(m, h);
  } while (h != ob);
  HH out_a = ob;  // a was unused: it takes b's fan as it is
  if (at_p && !at_q) {
    // ... q -> a -> p -> b -> r ... becomes ... q -> a -> r ...; p is closed.
    merge_boundary_edges(m, a_out, b_in);
    m.set_next_halfedge_handle(a_in, b_out);
    m.set_halfedge_handle(p, m.opposite_halfedge_handle(a_out));
    out_a = b_out;
  } else if (at_q && !at_p) {
    // ... s -> b -> q -> a -> p ... becomes ... s -> a -> p ...; q is closed.
    merge_boundary_edges(m, a_in, b_out);
    m.set_next_halfedge_handle(b_in, a_out);
    m.set_halfedge_handle(q, a_in);
    out_a = a_out;
  } else if (at_p && at_q) {
    // The boundary loop a -> p -> b -> q -> a closes, and a with it.
    merge_boundary_edges(m, a_out, b_in);
    merge_boundary_edges(m, a_in, b_out);
    m.set_halfedge_handle(p, m.opposite_halfedge_handle(a_out));
    m.set_halfedge_handle(q, a_in);
    out_a = m.opposite_halfedge_handle(a_in);
  }
  m.set_halfedge_handle(a, out_a);
  m.set_isolated(b);
  m.status(b).set_deleted(true);
  return OK_EDIT;
}

// The survivors in their order, as a new mesh of the same kind. OpenMesh's own
// garbage_collection fills each hole with the last live element (ArrayKernel: two indices
// walking towards each other, swapping), so it renumbers survivors; MeshEdit promises that
// vertex i stays before vertex j, so the compaction is a rebuild with add_vertex and add_face
// from the live elements in index order: O(n), like the half-edge family's own.
template <class M> std::unique_ptr<M> compacted(const M &m) {
  auto out = std::make_unique<M>();
  out->reserve(m.n_vertices(), m.n_edges(), m.n_faces());
  std::vector<int> map(m.n_vertices(), -1);
  for (VH v : m.vertices()) map[v.idx()] = out->add_vertex(m.point(v)).idx();
  std::vector<VH> corners;
  for (FH f : m.faces()) {
    corners.clear();
    const HH start = m.halfedge_handle(f);
    HH h = start;
    do {
      corners.push_back(VH(map[m.from_vertex_handle(h).idx()]));
      h = m.next_halfedge_handle(h);
    } while (h != start);
    if (!out->add_face(corners).is_valid()) throw std::runtime_error("add_face refused a live face");
  }
  return out;
}

// Requests the status attributes once per mesh (and again after a compaction).
void ensure_status(topolab_om_mesh *mesh) {
  if (mesh->edit_status_requested) return;
  with_mesh_mut(mesh, [](auto &m) {
    m.request_vertex_status();
    // Without halfedge status OpenMesh marks a deleted edge but not its halfedges, and every
    // halfedge range (validate's) would still visit them.
    m.request_halfedge_status();
    m.request_edge_status();
    m.request_face_status();
    return 0;
  });
  mesh->edit_status_requested = true;
}

// Runs an edit: OK, or EDIT_REFUSED with *refusal set.
template <class F> int edit(topolab_om_mesh *mesh, int *refusal, F &&body) {
  return guard([&] {
    ensure_status(mesh);
    const int r = with_mesh_mut(mesh, body);
    if (r == OK_EDIT) return TOPOLAB_OM_OK;
    *refusal = r;
    return TOPOLAB_OM_EDIT_REFUSED;
  });
}

}  // namespace

extern "C" {

int topolab_om_edit_add_vertex(topolab_om_mesh *mesh, const double *p, uint32_t *out) noexcept {
  int unused = 0;
  return edit(mesh, &unused, [&](auto &m) {
    using M = std::decay_t<decltype(m)>;
    *out = uint32_t(m.add_vertex(typename M::Point(p[0], p[1], p[2])).idx());
    return int(OK_EDIT);
  });
}

int topolab_om_edit_set_position(topolab_om_mesh *mesh, uint32_t v, const double *p,
                                 int *refusal) noexcept {
  return edit(mesh, refusal, [&](auto &m) {
    using M = std::decay_t<decltype(m)>;
    if (!live(m, v)) return int(NO_SUCH_ELEMENT);
    m.set_point(VH(int(v)), typename M::Point(p[0], p[1], p[2]));
    return int(OK_EDIT);
  });
}

int topolab_om_edit_add_face(topolab_om_mesh *mesh, const uint32_t *vertices, uint32_t n,
                             int *refusal, uint32_t *out) noexcept {
  return edit(mesh, refusal, [&](auto &m) { return add_face(m, vertices, n, out); });
}

int topolab_om_edit_delete_face(topolab_om_mesh *mesh, uint32_t f, int *refusal) noexcept {
  return edit(mesh, refusal, [&](auto &m) { return delete_face(m, f); });
}

int topolab_om_edit_delete_vertex(topolab_om_mesh *mesh, uint32_t v, int *refusal) noexcept {
  return edit(mesh, refusal, [&](auto &m) { return delete_vertex(m, v); });
}

int topolab_om_edit_flip(topolab_om_mesh *mesh, uint32_t e, int *refusal) noexcept {
  return edit(mesh, refusal, [&](auto &m) { return flip(m, e); });
}

int topolab_om_edit_split_edge(topolab_om_mesh *mesh, uint32_t e, const double *p, int *refusal,
                               uint32_t *out) noexcept {
  return edit(mesh, refusal, [&](auto &m) { return split_edge(m, e, p, out); });
}

int topolab_om_edit_split_face(topolab_om_mesh *mesh, uint32_t f, const double *p, int *refusal,
                               uint32_t *out) noexcept {
  return edit(mesh, refusal, [&](auto &m) { return split_face(m, f, p, out); });
}

int topolab_om_edit_collapse(topolab_om_mesh *mesh, uint32_t from, uint32_t to,
                             int *refusal) noexcept {
  return edit(mesh, refusal, [&](auto &m) { return collapse(m, from, to); });
}

int topolab_om_edit_split_vertex(topolab_om_mesh *mesh, uint32_t v, const double *p,
                                 uint32_t left, uint32_t right, int *refusal,
                                 uint32_t *out) noexcept {
  return edit(mesh, refusal, [&](auto &m) { return split_vertex(m, v, p, left, right, out); });
}

int topolab_om_edit_weld(topolab_om_mesh *mesh, uint32_t a, uint32_t b, int *refusal) noexcept {
  return edit(mesh, refusal, [&](auto &m) { return weld(m, a, b); });
}

int topolab_om_edit_is_deleted(const topolab_om_mesh *mesh, int kind, uint32_t id,
                               int *out) noexcept {
  return guard([&] {
    if (kind < 0 || kind > 2) return TOPOLAB_OM_UNKNOWN_CODE;
    *out = with_mesh(mesh, [&](const auto &m) {
      // Before the first edit nothing is marked (no status attributes yet).
      if (!mesh->edit_status_requested) return 0;
      switch (kind) {
        case 0: return id < m.n_vertices() && m.status(VH(int(id))).deleted() ? 1 : 0;
        case 1: return id < m.n_edges() && m.status(EH(int(id))).deleted() ? 1 : 0;
        default: return id < m.n_faces() && m.status(FH(int(id))).deleted() ? 1 : 0;
      }
    });
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_edit_garbage_collection(topolab_om_mesh *mesh) noexcept {
  return guard([&] {
    if (!mesh->edit_status_requested) return TOPOLAB_OM_OK;  // nothing was ever deleted
    const bool any_deleted = with_mesh(mesh, [](const auto &m) {
      for (auto v : m.all_vertices())
        if (m.status(v).deleted()) return true;
      for (auto e : m.all_edges())
        if (m.status(e).deleted()) return true;
      for (auto f : m.all_faces())
        if (m.status(f).deleted()) return true;
      return false;
    });
    if (!any_deleted) return TOPOLAB_OM_OK;
    if (mesh->tri)
      mesh->tri = compacted(*mesh->tri);
    else
      mesh->poly = compacted(*mesh->poly);
    // The new mesh has neither status attributes nor normals yet.
    mesh->edit_status_requested = false;
    mesh->normals_requested = false;
    return TOPOLAB_OM_OK;
  });
}

int topolab_om_edit_reserve(topolab_om_mesh *mesh, uint32_t vertices, uint32_t edges,
                            uint32_t faces) noexcept {
  return guard([&] {
    with_mesh_mut(mesh, [&](auto &m) {
      m.reserve(m.n_vertices() + vertices, m.n_edges() + edges, m.n_faces() + faces);
      return 0;
    });
    return TOPOLAB_OM_OK;
  });
}

}  // extern "C"
