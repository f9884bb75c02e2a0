/* A C API over Qhull's reentrant library (libqhull_r, Debian's libqhull-dev) for topolab (Rust
 * FFI): the 3D convex hull of a point set, run the way SciPy's scipy.spatial.ConvexHull runs
 * it, for the report's hull section. Built by the top-level build.rs (the `has_qhull` shim).
 *
 * The options are SciPy's for ConvexHull in 3D (scipy/spatial/_qhull.pyx: mode "i", no option
 * of its own below 5 dimensions, "Qt" always required), so the command is TOPOLAB_QHULL_COMMAND.
 * Qhull merges coplanar facets by default ('C-0'), so the hull's vertices are its extreme
 * points; 'Qt' triangulates the merged facets without adding vertices.
 *
 * State: libqhull_r keeps all of its state in the qhT the caller passes ("All global variables
 * for qhull are in qhT", libqhull_r.h; "Do not run separate threads on the same instance of
 * qhT"). Every call below makes its own qhT and frees it before returning, so threads may call
 * in parallel; the shim has no state of its own either.
 */
#ifndef TOPOLAB_QHULL_SHIM_H
#define TOPOLAB_QHULL_SHIM_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Qhull's command line: "i" (SciPy's mode option for ConvexHull, an output format: the vertices
 * of each facet; with no output file Qhull prints nothing) and "Qt" (triangulated output). */
#define TOPOLAB_QHULL_COMMAND "qhull i Qt"

/* Statuses. The shim is C: nothing unwinds out of it. Qhull reports an error by longjmp to a
 * setjmp in qh_new_qhull (or in the shim, around the calls after it), which become statuses:
 * 1 to 9 are Qhull's own exit codes (qh_ERRinput ... qh_ERRdebug of libqhull_r.h), passed
 * through; the ones below are the shim's. On failure the counts, `*seconds` and `*volume` are
 * left untouched (`vertices` may hold some ids) and `message` says what Qhull said. */
#define TOPOLAB_QHULL_OK 0
/* A null pointer, or more coordinates (3n) than Qhull's `int` counts. */
#define TOPOLAB_QHULL_BAD_ARGUMENT 100
/* malloc failed in the shim (Qhull's own allocation failures are its qh_ERRmem, 4). */
#define TOPOLAB_QHULL_OUT_OF_MEMORY 101
/* qh_memfreeshort found memory Qhull did not free (SciPy raises an error for it too). */
#define TOPOLAB_QHULL_LEAK 102
/* A hull vertex whose point is not one of the input points. */
#define TOPOLAB_QHULL_BAD_VERTEX 103

/* The convex hull of the n points `xyz` (x, y, z each) by qh_new_qhull with
 * TOPOLAB_QHULL_COMMAND, once.
 *
 * `*seconds`: the steady clock around qh_new_qhull (which builds, merges and triangulates the
 * hull) and the walk that collects the hull's vertex ids, the way the lab's hull algorithms are
 * timed around building their output. Outside it: copying the points (Qhull takes a mutable
 * array), qh_zero, the volume (qh_getarea, as SciPy computes it) and freeing the hull.
 * `vertices` (room for n): the input indices of the hull's vertices, each once, in Qhull's facet
 * order (the vertices of SciPy's simplices); `*vertex_count` of them. `*facet_count`: the
 * triangles (SciPy's simplices). `*volume`: Qhull's volume of the hull.
 * `message` (room for `message_capacity` bytes, NUL-terminated, may be null if the capacity is
 * 0): on failure, what Qhull wrote to its error file (truncated), else empty. */
int topolab_qhull_convex_hull(const double *xyz, uint32_t n, double *seconds,
                              uint32_t *vertices, uint32_t *vertex_count,
                              uint32_t *facet_count, double *volume, char *message,
                              size_t message_capacity);

/* Qhull's version string (qh_version of the linked library, e.g. "2020.2.r 2020/08/31"). */
const char *topolab_qhull_version(void);

#ifdef __cplusplus
}
#endif

#endif
