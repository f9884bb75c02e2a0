// CGAL::Polyhedron_3 for the shim: the classical pointer-based halfedge structure (its default
// HalfedgeDS_list: every vertex, halfedge pair and facet its own list node), built with
// Polyhedron_incremental_builder_3 and queried through kernels.h.
//
// The incremental builder rather than Polygon_mesh_processing::polygon_soup_to_polygon_mesh:
// the builder is Polyhedron_3's own construction interface, keeps the input order, and reports
// a face it cannot add (its error flag) -- polygon_soup_to_polygon_mesh ignores a refused face
// outside debug builds (its check is an assertion), so it would build a wrong mesh silently.
//
// Ids: CGAL::Polyhedron_items_with_id_3 stores one id per vertex, halfedge and facet (the way
// CGAL gives a Polyhedron indices); vertex i is the builder's i-th vertex, facet j its j-th
// facet, and the halfedges of edge e get ids 2e and 2e + 1. Tables from id to handle are the
// way in from an id (the lab's pointer half-edge keeps the same tables). polyhedron.h holds
// them, and the tombstones that stand for elements an edit erased (edit_polyhedron.cpp).

#include <CGAL/Polyhedron_incremental_builder_3.h>

#include "kernels.h"
#include "polyhedron.h"

namespace topolab_cgal {
namespace {

using polyhedron::HDS;
using polyhedron::Point;
using PolyhedronAdapter = polyhedron::Adapter;

// The incremental builder, run by Polyhedron_3::delegate on the halfedge data structure.
class Builder : public CGAL::Modifier_base<HDS> {
 public:
  Builder(const Input &in, uint32_t *failed_face) : in_(in), failed_face_(failed_face) {}
  bool refused() const { return refused_; }

  void operator()(HDS &hds) override {
    CGAL::Polyhedron_incremental_builder_3<HDS> b(hds, /*verbose=*/false);
    b.begin_surface(in_.vertices, in_.faces, 2 * size_t(in_.edges_hint));
    for (uint32_t i = 0; i < in_.vertices; ++i)
      b.add_vertex(Point(in_.xyz[3 * i], in_.xyz[3 * i + 1], in_.xyz[3 * i + 2]));
    for (uint32_t j = 0; j < in_.faces; ++j) {
      b.add_facet(in_.indices + in_.offsets[j], in_.indices + in_.offsets[j + 1]);
      if (b.error()) {
        *failed_face_ = j;
        refused_ = true;
        b.rollback();
        break;
      }
    }
    b.end_surface();
  }

 private:
  const Input &in_;
  uint32_t *failed_face_;
  bool refused_ = false;
};

}  // namespace

std::unique_ptr<Mesh> build_polyhedron(const Input &in, uint32_t *failed_face) {
  auto built = std::make_unique<CgalMesh<PolyhedronAdapter>>();
  PolyhedronAdapter &a = built->adapter();
  Builder builder(in, failed_face);
  a.mesh.delegate(builder);
  if (builder.refused()) return nullptr;
  // The ids and tables are the lab's, not the builder's: made by topolab_cgal_finish, after
  // the timed build.
  return built;
}

}  // namespace topolab_cgal
