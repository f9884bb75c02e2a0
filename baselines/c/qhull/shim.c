/* The C API of shim.h over Qhull's reentrant library. C, not C++: Qhull leaves an error by
 * longjmp, which would skip C++ destructors; here every resource is released by hand after the
 * setjmp that catches it. */
#define _POSIX_C_SOURCE 200809L

#include "shim.h"

#include <libqhull_r/qhull_ra.h>

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now_seconds(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* The input indices of the hull's vertices, each once, into `vertices` (room for `n`), and the
 * facets, counted: the vertices of every facet in qh's facet list, as SciPy's ConvexHull takes
 * them (np.unique of its simplices). TOPOLAB_QHULL_BAD_VERTEX if a vertex is no input point. */
static int collect(qhT *qh, uint32_t n, uint32_t *vertices, uint32_t *vertex_count,
                   uint32_t *facet_count) {
  facetT *facet;
  vertexT *vertex, **vertexp;
  uint32_t count = 0, facets = 0;
  qh->vertex_visit++;
  FORALLfacets {
    facets++;
    FOREACHvertex_(facet->vertices) {
      if (vertex->visitid == qh->vertex_visit) continue;
      vertex->visitid = qh->vertex_visit;
      int id = qh_pointid(qh, vertex->point);
      if (id < 0 || (uint32_t)id >= n || count == n) return TOPOLAB_QHULL_BAD_VERTEX;
      vertices[count++] = (uint32_t)id;
    }
  }
  *vertex_count = count;
  *facet_count = facets;
  return TOPOLAB_QHULL_OK;
}

/* The hull's volume by qh_getarea, as SciPy's ConvexHull.volume; an error in it comes back as
 * Qhull's exit code through the setjmp here (qh_new_qhull's own setjmp has returned). */
static int hull_volume(qhT *qh, double *volume) {
  int code = setjmp(qh->errexit);
  if (code == 0) {
    qh->NOerrexit = False;
    qh->hasAreaVolume = False;
    qh_getarea(qh, qh->facet_list);
    *volume = qh->totvol;
  }
  qh->NOerrexit = True;
  return code;
}

/* Copies what Qhull wrote to its error file into `message`, truncated, NUL-terminated. */
static void copy_message(const char *log, size_t size, char *message, size_t capacity) {
  if (capacity == 0) return;
  size_t n = size < capacity - 1 ? size : capacity - 1;
  if (log != NULL && n > 0) memcpy(message, log, n);
  message[n] = '\0';
}

int topolab_qhull_convex_hull(const double *xyz, uint32_t n, double *seconds,
                              uint32_t *vertices, uint32_t *vertex_count,
                              uint32_t *facet_count, double *volume, char *message,
                              size_t message_capacity) {
  if (message_capacity > 0 && message == NULL) return TOPOLAB_QHULL_BAD_ARGUMENT;
  copy_message(NULL, 0, message, message_capacity);
  if ((xyz == NULL && n > 0) || seconds == NULL || (vertices == NULL && n > 0) ||
      vertex_count == NULL || facet_count == NULL || volume == NULL || n > INT_MAX / 3)
    return TOPOLAB_QHULL_BAD_ARGUMENT;
  /* Qhull's points are not const (options such as 'QbB' scale them in place; ours leave them
   * as they are), so Qhull gets a copy, made outside the clock. */
  size_t bytes = (size_t)n * 3 * sizeof(coordT);
  coordT *points = malloc(bytes > 0 ? bytes : 1);
  qhT *qh = malloc(sizeof(qhT));
  char *log = NULL;
  size_t log_size = 0;
  FILE *errfile = open_memstream(&log, &log_size);
  int status = TOPOLAB_QHULL_OK;
  if (points == NULL || qh == NULL || errfile == NULL) {
    status = TOPOLAB_QHULL_OUT_OF_MEMORY;
  } else {
    if (bytes > 0) memcpy(points, xyz, bytes);
    char command[] = TOPOLAB_QHULL_COMMAND;
    uint32_t count = 0, facets = 0;
    double hull_volume_value = 0.0;
    qh_zero(qh, errfile);
    double start = now_seconds();
    status = qh_new_qhull(qh, 3, (int)n, points, False, command, NULL, errfile);
    if (status == TOPOLAB_QHULL_OK) status = collect(qh, n, vertices, &count, &facets);
    double took = now_seconds() - start;
    if (status == TOPOLAB_QHULL_OK) status = hull_volume(qh, &hull_volume_value);
    int curlong = 0, totlong = 0;
    qh_freeqhull(qh, !qh_ALL);
    qh_memfreeshort(qh, &curlong, &totlong);
    if (status == TOPOLAB_QHULL_OK && (curlong != 0 || totlong != 0)) {
      fprintf(errfile, "qhull did not free %d bytes (%d pieces)\n", totlong, curlong);
      status = TOPOLAB_QHULL_LEAK;
    }
    if (status == TOPOLAB_QHULL_OK) {
      *seconds = took;
      *vertex_count = count;
      *facet_count = facets;
      *volume = hull_volume_value;
    }
  }
  if (errfile != NULL) fclose(errfile);
  if (status != TOPOLAB_QHULL_OK) copy_message(log, log_size, message, message_capacity);
  free(log);
  free(qh);
  free(points);
  return status;
}

const char *topolab_qhull_version(void) { return qh_version; }
