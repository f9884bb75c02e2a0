// What the two MeshEdit units of the CGAL shim share (edit_surface_mesh.cpp,
// edit_polyhedron.cpp): the refusal codes of edit.h as an enum their checks return, and the
// point of a C array. A unit takes them with `using namespace edit_rules;` and
// `using edit_rules::BOUNDARY_EDGE;` (mesh.h has an operator of that name) in its unnamed
// namespace.

#ifndef TOPOLAB_CGAL_EDIT_RULES_H
#define TOPOLAB_CGAL_EDIT_RULES_H

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
};

// The point of 3 doubles (x, y, z).
template <class Point> Point point_of(const double *p) { return Point(p[0], p[1], p[2]); }

}  // namespace edit_rules
}  // namespace topolab_cgal

#endif
