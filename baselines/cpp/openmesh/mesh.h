// What the translation units of the OpenMesh shim share (shim.cpp: building, queries and
// workloads; decimate.cpp: the Decimater; edit.cpp: the editing operations): the mesh types,
// the opaque mesh of shim.h, the process-wide set-up and the exception wall.
//
// The mesh types are OpenMesh's own, and every operation the shim calls is the library's:
// build.rs compiles OpenMesh from its pinned source tree with its Release flags (-O3 -DNDEBUG),
// and these headers come from the same tree.

#ifndef TOPOLAB_OPENMESH_MESH_H
#define TOPOLAB_OPENMESH_MESH_H

#include "shim.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <ios>
#include <memory>
#include <new>

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
// A TriMesh for triangle input, a PolyMesh otherwise.
using Tri = OpenMesh::TriMesh_ArrayKernelT<Traits>;
using Poly = OpenMesh::PolyMesh_ArrayKernelT<Traits>;

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
