// CGAL::convex_hull_3 for the report's hull section: CGAL's quickhull with the
// Exact_predicates_inexact_constructions_kernel (exact orientation tests on the input doubles,
// as the lab's hulls use Shewchuk's orient3d) into a Surface_mesh.

#include "mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <vector>

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using HullMesh = CGAL::Surface_mesh<Point>;
}  // namespace

extern "C" int topolab_cgal_convex_hull(const double *xyz, uint32_t n, uint32_t repeat,
                                        double *seconds, uint32_t *out,
                                        double *volume) noexcept {
  return topolab_cgal::guard([&] {
    std::vector<Point> points;
    points.reserve(n);
    for (uint32_t i = 0; i < n; ++i) points.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    double best = std::numeric_limits<double>::infinity();
    HullMesh hull;
    for (uint32_t run = 0; run < std::max(repeat, 1u); ++run) {
      hull.clear();
      const auto start = std::chrono::steady_clock::now();
      CGAL::convex_hull_3(points.begin(), points.end(), hull);
      const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
      best = std::min(best, took.count());
    }
    double sum = 0.0;
    for (auto f : hull.faces()) {
      double p[3][3];
      int corner = 0;
      for (auto v : vertices_around_face(hull.halfedge(f), hull)) {
        if (corner < 3)
          for (int k = 0; k < 3; ++k) p[corner][k] = hull.point(v)[k];
        ++corner;
      }
      if (corner != 3) continue;
      // a · (b × c), as the lab's Hull::volume sums it.
      sum += p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) +
             p[0][1] * (p[1][2] * p[2][0] - p[1][0] * p[2][2]) +
             p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
    }
    *seconds = best;
    out[0] = uint32_t(hull.number_of_vertices());
    out[1] = uint32_t(hull.number_of_faces());
    out[2] = CGAL::is_closed(hull) && CGAL::is_triangle_mesh(hull) ? 1 : 0;
    *volume = sum / 6.0;
    return TOPOLAB_CGAL_OK;
  });
}
