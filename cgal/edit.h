/* The changing workloads (and, for Surface_mesh, topolab's MeshEdit) over CGAL's own Euler
 * operations: C API for Rust FFI, implemented in edit_surface_mesh.cpp and edit_polyhedron.cpp
 * (one translation unit per structure, like the builders), wrapped by src/cgal/changing.rs and
 * src/cgal/edit.rs. Same discipline as shim.h: every function is noexcept, catches every C++
 * exception and returns a status; the mesh must be of the structure the function names. */
#ifndef TOPOLAB_CGAL_EDIT_H
#define TOPOLAB_CGAL_EDIT_H

#include "shim.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Runs a changing workload of the Surface_mesh benchmark (Sieger & Botsch) in place, as
 * CGAL's Surface_mesh/benchmark runs it: 0 = one step of sqrt3 subdivision, 1 = the collapse
 * test (garbage collected at the end). */
int topolab_cgal_sm_changing(topolab_cgal_mesh *mesh, int workload) TOPOLAB_CGAL_NOEXCEPT;
int topolab_cgal_polyhedron_changing(topolab_cgal_mesh *mesh, int workload) TOPOLAB_CGAL_NOEXCEPT;

#ifdef __cplusplus
}
#endif

#endif
