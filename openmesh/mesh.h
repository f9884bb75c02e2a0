// What the translation units of the OpenMesh shim share (shim.cpp: building, queries and
// workloads; edit.cpp: the editing operations): the mesh types, the opaque mesh of shim.h,
// the process-wide set-up and the exception wall.

#ifndef TOPOLAB_OPENMESH_MESH_H
#define TOPOLAB_OPENMESH_MESH_H

#include "shim.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <ios>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace topolab_om {

// Double-precision points and normals, so positions round-trip exactly (the lab's are f64).
struct Traits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using VH = OpenMesh::VertexHandle;
using HH = OpenMesh::HalfedgeHandle;
using EH = OpenMesh::EdgeHandle;
using FH = OpenMesh::FaceHandle;
// The mesh types as Debian's library compiles their operations (for the test that the ones
// below give the same meshes, and for measuring what the library's build costs).
using ShippedTri = OpenMesh::TriMesh_ArrayKernelT<Traits>;
using ShippedPoly = OpenMesh::PolyMesh_ArrayKernelT<Traits>;

// Why the lab's mesh types override some of OpenMesh's functions.
//
// Debian's libopenmesh 9.0 is compiled without NDEBUG (its CMake build type "None"; OpenMesh's
// documented build is Release), so every handle step inside the compiled library runs
// ArrayKernel.hh's `assert(is_valid_handle(h))` through an out-of-line call, and every status
// access PropertyContainer.hh's `assert(internal_type_name() == get_type_name<T>())` (two
// std::string built, compared and freed). OpenMesh's header templates are compiled here at
// -O3 -DNDEBUG; the functions below are the ones of the compiled library that the timed
// kernels call, written out again with OpenMesh 9.0's algorithm (its order of tests, links and
// writes, so the meshes come out identical: the test in src/openmesh.rs builds and edits with
// both and compares every link), compiled as a release build of OpenMesh would compile them.
// Callgrind on a 65 520-triangle torus (`examples/openmesh_profile.rs`, the instructions
// inside the shim's call), before and after:
//
// | kernel | Debian's library | compiled here | what is overridden |
// |---|---|---|---|
// | construction (add_vertex + add_face) | 158.8 M | 66.7 M | add_face, find_halfedge, adjust_outgoing_halfedge |
// | sqrt3 subdivision | 396.0 M | 126.4 M | split (face), flip, is_flip_ok |
// | collapse test | 894.8 M | 213.4 M | split (face), collapse, garbage_collection |
// | decimation to 10 %, 16 432-triangle torus (decimate.cpp) | 2 710.8 M | 276.6 M | collapse, find_halfedge; decimate.cpp's is_collapse_ok, valence |
//
// Before, is_valid_handle alone (out of line, the assertions' call) was 30 %, 37 % and 26 %
// of the first three, and the collapse test's status lookups (their string compares) another
// 20 %. decimate.cpp's Decimater runs on Compiled<ShippedTri> with TriConnectivity's
// is_collapse_ok and PolyConnectivity::valence added there (its note gives the numbers);
// nothing of the compiled library runs inside its timed call. Not overridden: add_face's
// triangulation of polygons in a TriMesh, the vertex split, delete_face/delete_vertex, and
// is_collapse_ok for the editing operations (edit.cpp).
template <class Shipped> struct Compiled : Shipped {
  using typename Shipped::Point;
  using Shipped::add_face;
  using Shipped::find_halfedge;
  using Shipped::split;

  // PolyConnectivity::add_face: refuses (an invalid handle) a face at a vertex that is not on
  // the boundary or along an edge that already has a face on that side; else relinks the
  // boundary patches that the new face joins, creates the missing edges and the face, links
  // the half-edges through a cache written last, and re-points the outgoing half-edge of
  // vertices whose fans merged. OpenMesh also prints its refusals to omerr(), which the shim
  // silences (setup_once); they are not written here.
  OpenMesh::SmartFaceHandle add_face(const VH *vhs, size_t n) {
    const auto refused = OpenMesh::make_smart(FH(), this);
    if (add_face_edges_.size() < n) {
      add_face_edges_.resize(n);
      next_cache_.resize(6 * n);
    }
    size_t cached = 0;
    for (size_t i = 0, ii = 1; i < n; ++i, ++ii, ii %= n) {
      if (!this->is_boundary(vhs[i])) return refused;
      add_face_edges_[i].halfedge = find_halfedge(vhs[i], vhs[ii]);
      add_face_edges_[i].is_new = !add_face_edges_[i].halfedge.is_valid();
      add_face_edges_[i].needs_adjust = false;
      if (!add_face_edges_[i].is_new && !this->is_boundary(add_face_edges_[i].halfedge)) return refused;
    }
    // Two old edges in a row that are not consecutive on the boundary: move the patch between
    // them into a free gap of the vertex.
    for (size_t i = 0, ii = 1; i < n; ++i, ++ii, ii %= n) {
      if (add_face_edges_[i].is_new || add_face_edges_[ii].is_new) continue;
      const HH inner_prev = add_face_edges_[i].halfedge, inner_next = add_face_edges_[ii].halfedge;
      if (this->next_halfedge_handle(inner_prev) == inner_next) continue;
      HH boundary_prev = this->opposite_halfedge_handle(inner_next);
      do
        boundary_prev =
            this->opposite_halfedge_handle(this->next_halfedge_handle(boundary_prev));
      while (!this->is_boundary(boundary_prev));
      const HH boundary_next = this->next_halfedge_handle(boundary_prev);
      if (boundary_prev == inner_prev) return refused;  // no free gap: re-linking failed
      const HH patch_start = this->next_halfedge_handle(inner_prev);
      const HH patch_end = this->prev_halfedge_handle(inner_next);
      next_cache_[cached++] = {boundary_prev, patch_start};
      next_cache_[cached++] = {patch_end, boundary_next};
      next_cache_[cached++] = {inner_prev, inner_next};
    }
    for (size_t i = 0, ii = 1; i < n; ++i, ++ii, ii %= n)
      if (add_face_edges_[i].is_new) add_face_edges_[i].halfedge = this->new_edge(vhs[i], vhs[ii]);
    const FH fh = this->new_face();
    this->set_halfedge_handle(fh, add_face_edges_[n - 1].halfedge);
    for (size_t i = 0, ii = 1; i < n; ++i, ++ii, ii %= n) {
      const VH vh = vhs[ii];
      const HH inner_prev = add_face_edges_[i].halfedge, inner_next = add_face_edges_[ii].halfedge;
      const int id = (add_face_edges_[i].is_new ? 1 : 0) | (add_face_edges_[ii].is_new ? 2 : 0);
      if (id != 0) {
        const HH outer_prev = this->opposite_halfedge_handle(inner_next);
        const HH outer_next = this->opposite_halfedge_handle(inner_prev);
        if (id == 1) {  // the side before vh is new, the one after it old
          const HH boundary_prev = this->prev_halfedge_handle(inner_next);
          next_cache_[cached++] = {boundary_prev, outer_next};
          this->set_halfedge_handle(vh, outer_next);
        } else if (id == 2) {  // the side after vh is new, the one before it old
          const HH boundary_next = this->next_halfedge_handle(inner_prev);
          next_cache_[cached++] = {outer_prev, boundary_next};
          this->set_halfedge_handle(vh, boundary_next);
        } else if (!this->halfedge_handle(vh).is_valid()) {  // both new, vh isolated
          this->set_halfedge_handle(vh, outer_next);
          next_cache_[cached++] = {outer_prev, outer_next};
        } else {  // both new, vh already used: the face goes into its boundary gap
          const HH boundary_next = this->halfedge_handle(vh);
          const HH boundary_prev = this->prev_halfedge_handle(boundary_next);
          next_cache_[cached++] = {boundary_prev, outer_next};
          next_cache_[cached++] = {outer_prev, boundary_next};
        }
        next_cache_[cached++] = {inner_prev, inner_next};
      } else {
        add_face_edges_[ii].needs_adjust = (this->halfedge_handle(vh) == inner_next);
      }
      this->set_face_handle(add_face_edges_[i].halfedge, fh);
    }
    for (size_t i = 0; i < cached; ++i)
      this->set_next_halfedge_handle(next_cache_[i].first, next_cache_[i].second);
    for (size_t i = 0; i < n; ++i)
      if (add_face_edges_[i].needs_adjust) adjust_outgoing_halfedge(vhs[i]);
    return OpenMesh::make_smart(fh, this);
  }

  OpenMesh::SmartFaceHandle add_face(VH a, VH b, VH c) {
    const VH vhs[3] = {a, b, c};
    return add_face(vhs, 3);
  }

  // A polygon; in a TriMesh one of more than three corners goes to the library's
  // triangulating add_face (the lab's TriMesh input has triangles only).
  OpenMesh::SmartFaceHandle add_face(const std::vector<VH> &vhs) {
    if (std::is_base_of<OpenMesh::TriConnectivity, Shipped>::value && vhs.size() != 3)
      return Shipped::add_face(vhs);
    return add_face(vhs.data(), vhs.size());
  }

  // PolyConnectivity::find_halfedge: the half-edge from `from` to `to`, or an invalid one,
  // found by the same circulator (the same order).
  OpenMesh::SmartHalfedgeHandle find_halfedge(VH from, VH to) const {
    for (auto it = this->cvoh_iter(from); it.is_valid(); ++it)
      if (this->to_vertex_handle(*it) == to) return *it;
    return OpenMesh::make_smart(HH(), this);
  }

  // PolyConnectivity::adjust_outgoing_halfedge: the first boundary half-edge leaving `vh`
  // becomes its outgoing one.
  void adjust_outgoing_halfedge(VH vh) {
    for (auto it = this->cvoh_iter(vh); it.is_valid(); ++it)
      if (this->is_boundary(*it)) {
        this->set_halfedge_handle(vh, *it);
        break;
      }
  }

  // PolyConnectivity::split(fh, vh): the 1-to-n face split, a fan of new faces around vh;
  // the last of them keeps fh.
  void split(FH fh, VH vh) {
    const HH hend = this->halfedge_handle(fh);
    HH hh = this->next_halfedge_handle(hend);
    HH hold = this->new_edge(this->to_vertex_handle(hend), vh);
    this->set_next_halfedge_handle(hend, hold);
    this->set_face_handle(hold, fh);
    hold = this->opposite_halfedge_handle(hold);
    while (hh != hend) {
      const HH hnext = this->next_halfedge_handle(hh);
      const FH fnew = this->new_face();
      this->set_halfedge_handle(fnew, hh);
      const HH hnew = this->new_edge(this->to_vertex_handle(hh), vh);
      this->set_next_halfedge_handle(hnew, hold);
      this->set_next_halfedge_handle(hold, hh);
      this->set_next_halfedge_handle(hh, hnew);
      this->set_face_handle(hnew, fnew);
      this->set_face_handle(hold, fnew);
      this->set_face_handle(hh, fnew);
      hold = this->opposite_halfedge_handle(hnew);
      hh = hnext;
    }
    this->set_next_halfedge_handle(hold, hend);
    this->set_next_halfedge_handle(this->next_halfedge_handle(hend), hold);
    this->set_face_handle(hold, fh);
    this->set_halfedge_handle(vh, hold);
  }

  // PolyMeshT/TriMeshT::split(fh, point): a new vertex at the point, then the face split.
  OpenMesh::SmartVertexHandle split(FH fh, const Point &p) {
    const auto vh = this->add_vertex(p);
    split(fh, VH(vh));
    return vh;
  }

  // PolyConnectivity::collapse: the from-vertex of `hh` goes into its to-vertex; a face left
  // with two sides on either side is removed (collapse_loop). The trust is OpenMesh's: the
  // caller checks is_collapse_ok first.
  void collapse(HH hh) {
    const HH h1 = this->next_halfedge_handle(hh);
    const HH o1 = this->next_halfedge_handle(this->opposite_halfedge_handle(hh));
    collapse_edge(hh);
    if (this->next_halfedge_handle(this->next_halfedge_handle(h1)) == h1)
      collapse_loop(this->next_halfedge_handle(h1));
    if (this->next_halfedge_handle(this->next_halfedge_handle(o1)) == o1) collapse_loop(o1);
  }

  // ArrayKernel::garbage_collection(v, e, f): its own template from the header
  // (ArrayKernelT_impl.hh), with no handles to update, as the library's non-template
  // overload calls it.
  void garbage_collection(bool v = true, bool e = true, bool f = true) {
    std::vector<VH *> vertices;
    std::vector<HH *> halfedges;
    std::vector<FH *> faces;
    Shipped::garbage_collection(vertices, halfedges, faces, v, e, f);
  }

 private:
  // PolyConnectivity::collapse_edge: every half-edge into the removed vertex `vo` now ends at
  // `vh`; the edge's two half-edges leave their loops; faces and `vh` get a half-edge still
  // in them; the edge and `vo` are marked deleted.
  void collapse_edge(HH h) {
    const HH hn = this->next_halfedge_handle(h), hp = this->prev_halfedge_handle(h);
    const HH o = this->opposite_halfedge_handle(h);
    const HH on = this->next_halfedge_handle(o), op = this->prev_halfedge_handle(o);
    const FH fh = this->face_handle(h), fo = this->face_handle(o);
    const VH vh = this->to_vertex_handle(h), vo = this->to_vertex_handle(o);
    for (auto it = this->vih_iter(vo); it.is_valid(); ++it) this->set_vertex_handle(*it, vh);
    this->set_next_halfedge_handle(hp, hn);
    this->set_next_halfedge_handle(op, on);
    if (fh.is_valid()) this->set_halfedge_handle(fh, hn);
    if (fo.is_valid()) this->set_halfedge_handle(fo, on);
    if (this->halfedge_handle(vh) == o) this->set_halfedge_handle(vh, hn);
    adjust_outgoing_halfedge(vh);
    this->set_isolated(vo);
    this->status(this->edge_handle(h)).set_deleted(true);
    this->status(vo).set_deleted(true);
    if (this->has_halfedge_status()) {
      this->status(h).set_deleted(true);
      this->status(o).set_deleted(true);
    }
  }

  // PolyConnectivity::collapse_loop: a face of two sides (h0, h1) goes; h1 takes the place of
  // h0's opposite in the neighbouring loop, and h0's edge and the face are marked deleted.
  void collapse_loop(HH h0) {
    const HH h1 = this->next_halfedge_handle(h0);
    const HH o0 = this->opposite_halfedge_handle(h0), o1 = this->opposite_halfedge_handle(h1);
    const VH v0 = this->to_vertex_handle(h0), v1 = this->to_vertex_handle(h1);
    const FH fh = this->face_handle(h0), fo = this->face_handle(o0);
    this->set_next_halfedge_handle(h1, this->next_halfedge_handle(o0));
    this->set_next_halfedge_handle(this->prev_halfedge_handle(o0), h1);
    this->set_face_handle(h1, fo);
    this->set_halfedge_handle(v0, h1);
    adjust_outgoing_halfedge(v0);
    this->set_halfedge_handle(v1, o1);
    adjust_outgoing_halfedge(v1);
    if (fo.is_valid() && this->halfedge_handle(fo) == o0) this->set_halfedge_handle(fo, h1);
    if (fh.is_valid()) {
      this->set_halfedge_handle(fh, HH());
      this->status(fh).set_deleted(true);
    }
    this->status(this->edge_handle(h0)).set_deleted(true);
    if (this->has_halfedge_status()) {
      this->status(h0).set_deleted(true);
      this->status(o0).set_deleted(true);
    }
  }

  // add_face's working storage, as PolyConnectivity keeps it (its own is private).
  struct EdgeInfo {
    HH halfedge;
    bool is_new = false;
    bool needs_adjust = false;
  };
  std::vector<EdgeInfo> add_face_edges_;
  std::vector<std::pair<HH, HH>> next_cache_;
};

// A TriMesh with TriConnectivity's flip and its test compiled here too.
struct Tri : Compiled<ShippedTri> {
  // TriConnectivity::is_flip_ok: not on the boundary, the two apexes differ and are not
  // already joined (searched around the first apex by its vertex circulator).
  bool is_flip_ok(EH eh) const {
    if (this->is_boundary(eh)) return false;
    const HH hh = halfedge_handle(eh, 0), oh = halfedge_handle(eh, 1);
    const VH ah = to_vertex_handle(next_halfedge_handle(hh));
    const VH bh = to_vertex_handle(next_halfedge_handle(oh));
    if (ah == bh) return false;
    for (auto it = cvv_iter(ah); it.is_valid(); ++it)
      if (*it == bh) return false;
    return true;
  }

  // TriConnectivity::flip: the edge between two triangles turns to join their apexes.
  void flip(EH eh) {
    const HH a0 = halfedge_handle(eh, 0), b0 = halfedge_handle(eh, 1);
    const HH a1 = next_halfedge_handle(a0), a2 = next_halfedge_handle(a1);
    const HH b1 = next_halfedge_handle(b0), b2 = next_halfedge_handle(b1);
    const VH va0 = to_vertex_handle(a0), va1 = to_vertex_handle(a1);
    const VH vb0 = to_vertex_handle(b0), vb1 = to_vertex_handle(b1);
    const FH fa = face_handle(a0), fb = face_handle(b0);
    set_vertex_handle(a0, va1);
    set_vertex_handle(b0, vb1);
    set_next_halfedge_handle(a0, a2);
    set_next_halfedge_handle(a2, b1);
    set_next_halfedge_handle(b1, a0);
    set_next_halfedge_handle(b0, b2);
    set_next_halfedge_handle(b2, a1);
    set_next_halfedge_handle(a1, b0);
    set_face_handle(a1, fb);
    set_face_handle(b1, fa);
    set_halfedge_handle(fa, a0);
    set_halfedge_handle(fb, b0);
    if (halfedge_handle(va0) == b0) set_halfedge_handle(va0, a1);
    if (halfedge_handle(vb0) == a0) set_halfedge_handle(vb0, b1);
  }
};
struct Poly : Compiled<ShippedPoly> {};

// The shim's one process-wide action, done once whichever thread gets here first.
//
// OpenMesh 9's omerr() connects its stream to std::cerr on first use behind a plain static
// flag, inserting into an unlocked std::vector: two threads building their first mesh at the
// same time both connected and corrupted it (a SIGSEGV in 1 test run of 5). A function-local
// static is initialised exactly once, thread-safely (C++11), and an inline function's static
// is one object in the whole program; if the initialiser throws, the exception reaches the
// caller's guard and the next call tries again.
//
// Silencing omerr is process-wide too: add_face's refusals ("complex edge", "complex
// vertex") become typed errors on the Rust side instead of stderr lines. The lab is the only
// user of OpenMesh in its process. disable() alone still lets every `omerr() << ...` of
// OpenMesh format into the one shared std::ostream (its width, its buffer) from whichever
// thread refuses a face, which helgrind reports as races; with badbit set, each such write
// stops at the stream's sentry and writes nothing but the same state bits.
inline void setup_once() {
  static const bool done = [] {
    omerr().disable();
    omerr().setstate(std::ios::badbit | std::ios::failbit);
    return true;
  }();
  (void)done;
}

// Runs `body` with every exception caught: the C API's wall (no exception may cross
// `extern "C"` into Rust, which would abort). Returns TOPOLAB_OM_OK or the failure.
template <class F> int guard(F &&body) noexcept {
  try {
    setup_once();
    return body();
  } catch (const std::bad_alloc &) {
    return TOPOLAB_OM_OUT_OF_MEMORY;
  } catch (...) {
    return TOPOLAB_OM_EXCEPTION;
  }
}

}  // namespace topolab_om

struct topolab_om_mesh {
  std::unique_ptr<topolab_om::Tri> tri;    // set for triangle input
  std::unique_ptr<topolab_om::Poly> poly;  // set for polygon input
  bool normals_requested = false;
  // The status attributes (OpenMesh's deletion marks) requested by the first edit (edit.cpp).
  bool edit_status_requested = false;
};

namespace topolab_om {
template <class F> auto with_mesh(const topolab_om_mesh *mesh, F &&f) {
  return mesh->tri ? f(*mesh->tri) : f(*mesh->poly);
}
template <class F> auto with_mesh_mut(topolab_om_mesh *mesh, F &&f) {
  return mesh->tri ? f(*mesh->tri) : f(*mesh->poly);
}
}  // namespace topolab_om

#endif
