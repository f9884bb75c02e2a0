// OpenMesh's own file readers (IO::read_mesh), for the differential test of the lab's readers
// on the test files OpenMesh ships with its unit tests (baselines/tests/openmesh_files.rs).
// Nothing here is timed.

#include "mesh.h"

// OpenMesh's readers register themselves from static objects in its library; linked
// statically, as build.rs links it, those objects are dropped unless the application asks
// for them, as MeshIO.hh's documentation says: with OM_STATIC_BUILD it includes
// IOInstances.hh, which references each reader. Here, in the one unit that reads files.
#define OM_STATIC_BUILD
#include <OpenMesh/Core/IO/MeshIO.hh>

#include <mutex>
#include <vector>

using namespace topolab_om;

int topolab_om_read_file(const char *path, topolab_om_read_vertex vertex,
                         topolab_om_read_face face, void *context) noexcept {
  return guard([&] {
    // OpenMesh's readers are process-wide singletons that keep per-read state (the OBJ
    // reader's folder and materials): one read at a time, from any thread.
    static std::mutex one_read;
    const std::lock_guard<std::mutex> lock(one_read);
    // Its readers log what they skip on omlog: silenced once, as omerr is (mesh.h).
    static const bool quiet = [] {
      omlog().disable();
      omout().disable();
      return true;
    }();
    (void)quiet;
    Poly mesh;
    // Custom properties read as OpenMesh properties, as its own tests read the files that
    // have them (without it its PLY reader stops at a face element with extra lists).
    OpenMesh::IO::Options options;
    options += OpenMesh::IO::Options::Custom;
    if (!OpenMesh::IO::read_mesh(mesh, path, options)) return TOPOLAB_OM_READ_FAILED;
    for (const auto v : mesh.vertices()) {
      const auto p = mesh.point(v);
      vertex(context, p[0], p[1], p[2]);
    }
    std::vector<uint32_t> corners;
    for (const auto f : mesh.faces()) {
      corners.clear();
      for (const auto v : mesh.fv_range(f)) corners.push_back(uint32_t(v.idx()));
      face(context, corners.data(), corners.size());
    }
    return TOPOLAB_OM_OK;
  });
}
