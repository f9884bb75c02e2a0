/* The C++ side of the lab's heap counting (heap.cpp), for src/alloc.rs. Built by the top-level
 * build.rs as a static library of its own, linked whenever a C++ baseline is.
 *
 * Every C++ allocation of the process goes through heap.cpp's global operator new and delete,
 * which count the bytes of each block (malloc_usable_size, the rule src/alloc.rs applies to
 * Rust's allocations) into the calling thread's counter, while that thread counts. Nothing
 * here can throw or fail. */
#ifndef TOPOLAB_HEAP_H
#define TOPOLAB_HEAP_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#define TOPOLAB_HEAP_NOEXCEPT noexcept
#else
#define TOPOLAB_HEAP_NOEXCEPT
#endif

/* One thread's counts: whether it counts (1) or not (0), the bytes of the blocks counted and not
 * freed since, and the highest that has been. A block counted and freed while the thread does
 * not count stays counted; a block freed while counting that was allocated before is not
 * subtracted below zero. */
typedef struct topolab_heap_counts {
  int on;
  size_t current;
  size_t peak;
} topolab_heap_counts;

/* The calling thread's counts into *out. */
void topolab_heap_read(topolab_heap_counts *out) TOPOLAB_HEAP_NOEXCEPT;
/* Replaces the calling thread's counts (to start, stop, or nest a measurement). */
void topolab_heap_write(const topolab_heap_counts *counts) TOPOLAB_HEAP_NOEXCEPT;

/* For the tests of src/alloc.rs: a new std::vector<uint32_t> of `length` zeros (two blocks: the
 * vector and its elements), its elements' address in *data; NULL when out of memory. */
void *topolab_heap_test_vector(size_t length, const void **data) TOPOLAB_HEAP_NOEXCEPT;
/* Deletes a vector of topolab_heap_test_vector. */
void topolab_heap_test_free(void *vector) TOPOLAB_HEAP_NOEXCEPT;

#ifdef __cplusplus
}
#endif

#endif
