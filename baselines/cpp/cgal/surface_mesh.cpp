// CGAL::Surface_mesh for the shim: built as its documentation builds one (reserve, add_vertex,
// add_face), queried through kernels.h. Its own indices are the lab's ids: vertex i is the
// i-th add_vertex, face j the j-th add_face, edge e has halfedges 2e and 2e + 1.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include "kernels.h"

namespace topolab_cgal {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using VI = SurfaceMesh::Vertex_index;
using HI = SurfaceMesh::Halfedge_index;
using FI = SurfaceMesh::Face_index;

struct SurfaceMeshAdapter {
  using Graph = SurfaceMesh;
  using Point = topolab_cgal::Point;
  SurfaceMesh mesh;

  const Graph &graph() const { return mesh; }
  void *native() { return &mesh; }
  uint32_t vid(VI v) const { return uint32_t(v); }
  uint32_t fid(FI f) const { return uint32_t(f); }
  uint32_t hid(HI h) const { return uint32_t(h); }
  VI vertex(uint32_t i) const { return VI(i); }
  FI face(uint32_t i) const { return FI(i); }
  HI halfedge_at(uint32_t h) const { return HI(h); }
  // Slots, removed ones included: an edit's removed elements keep their ids until the garbage
  // is collected (edit_surface_mesh.cpp); the same as number_of_vertices() and so on until an
  // edit removes one.
  uint32_t num_vertices() const { return uint32_t(mesh.num_vertices()); }
  uint32_t num_edges() const { return uint32_t(mesh.num_edges()); }
  uint32_t num_faces() const { return uint32_t(mesh.num_faces()); }
  const Point &point(VI v) const { return mesh.point(v); }
  // Surface_mesh keeps a border halfedge as the halfedge of a border vertex ("If v is a border
  // vertex this will be a border halfedge"), so is_border(v, false) looks at that one halfedge
  // only, O(1); it also calls an isolated vertex a border one, which the lab does not.
  bool is_boundary_vertex(VI v) const {
    return !mesh.is_isolated(v) && mesh.is_border(v, /*check_all_incident_halfedges=*/false);
  }
  bool cgal_is_valid() const { return mesh.is_valid(/*verbose=*/false); }
  // Surface_mesh's indices are the ids, changed or not.
  void renumber() {}
  // Its property arrays by their lengths, laid out as its connectivity is: per vertex a point
  // and a halfedge, per halfedge its face, target vertex, next and prev, per face a halfedge,
  // and a removed flag of one bit (a vector<bool>) per vertex, edge and face.
  uint64_t declared_bytes() const {
    const uint64_t v = mesh.num_vertices(), h = mesh.num_halfedges(), e = mesh.num_edges(),
                   f = mesh.num_faces();
    const auto bits = [](uint64_t n) { return (n + 7) / 8; };
    return v * (sizeof(Point) + sizeof(HI)) + h * (sizeof(FI) + sizeof(VI) + 2 * sizeof(HI)) +
           f * sizeof(HI) + bits(v) + bits(e) + bits(f);
  }
};

}  // namespace

std::unique_ptr<Mesh> build_surface_mesh(const Input &in, uint32_t *failed_face) {
  auto built = std::make_unique<CgalMesh<SurfaceMeshAdapter>>();
  SurfaceMesh &m = built->adapter().mesh;
  m.reserve(in.vertices, in.edges_hint, in.faces);
  for (uint32_t i = 0; i < in.vertices; ++i)
    m.add_vertex(Point(in.xyz[3 * i], in.xyz[3 * i + 1], in.xyz[3 * i + 2]));
  std::vector<VI> corners;
  for (uint32_t j = 0; j < in.faces; ++j) {
    const uint32_t *begin = in.indices + in.offsets[j], *end = in.indices + in.offsets[j + 1];
    FI f;
    if (end - begin == 3) {
      f = m.add_face(VI(begin[0]), VI(begin[1]), VI(begin[2]));
    } else {
      corners.clear();
      for (const uint32_t *c = begin; c != end; ++c) corners.push_back(VI(*c));
      f = m.add_face(corners);
    }
    if (f == SurfaceMesh::null_face()) {
      *failed_face = j;
      return nullptr;
    }
  }
  return built;
}

}  // namespace topolab_cgal
