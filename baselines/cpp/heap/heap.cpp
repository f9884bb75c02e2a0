// C++'s replaceable global allocation functions ([new.delete]: operator new and delete, new[]
// and delete[], with their sized, aligned and nothrow variants), for every C++ baseline linked
// into the lab. Each takes its block from glibc's malloc (posix_memalign when over-aligned) and
// gives it back with free, as libstdc++'s own do, and counts the block's bytes as
// malloc_usable_size reports them into the calling thread's counter while that thread counts:
// the rule src/alloc.rs applies to Rust's allocations, so a baseline's heap and a Rust
// structure's are counted alike. Sizes passed to a sized delete are not used: the unsized
// forms, which libstdc++ still calls, do not have them, and a block's usable size is exact for
// both.
//
// One translation unit, in a static library of its own (build.rs): a program defines these
// functions once, and the OpenMesh and CGAL shims are separate libraries. Its definitions
// replace libstdc++'s for the whole process, shared libraries included (OpenMesh's
// libOpenMeshCore allocates through them too).

#include "heap.h"

#include <malloc.h>

#include <cstdint>
#include <cstdlib>
#include <new>
#include <vector>

namespace {

// One thread's counter. Constant-initialised and trivially destructible, so reading it needs
// no guard; the initial-exec model makes that read one load at a fixed offset from the thread
// pointer (this unit is linked into the executable, never loaded later by dlopen), so an
// allocation on a thread that does not count pays that load and nothing else.
struct Counter {
  bool on;
  size_t current;
  size_t peak;
};
__attribute__((tls_model("initial-exec"))) thread_local Counter counter = {false, 0, 0};

// Counts the new block `p` (not null), if this thread counts.
inline void count_block(void *p) noexcept {
  Counter &c = counter;
  if (!c.on) return;
  c.current += malloc_usable_size(p);
  if (c.current > c.peak) c.peak = c.current;
}

// Frees `p` (possibly null), subtracting its bytes first if this thread counts.
inline void free_block(void *p) noexcept {
  Counter &c = counter;
  if (c.on && p != nullptr) {
    const size_t bytes = malloc_usable_size(p);
    c.current = c.current > bytes ? c.current - bytes : 0;
  }
  std::free(p);
}

// [new.delete.single]: a block of at least `size` bytes (one for zero), calling the new-handler
// while there is one and malloc fails; std::bad_alloc when there is none.
void *allocate(std::size_t size) {
  if (size == 0) size = 1;
  for (;;) {
    if (void *p = std::malloc(size)) {
      count_block(p);
      return p;
    }
    const std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
  }
}

// The same, aligned to `alignment` (a power of two, as std::align_val_t guarantees).
void *allocate_aligned(std::size_t size, std::align_val_t alignment) {
  std::size_t align = static_cast<std::size_t>(alignment);
  // posix_memalign takes multiples of sizeof(void *) only.
  if (align < sizeof(void *)) align = sizeof(void *);
  if (size == 0) size = 1;
  for (;;) {
    void *p = nullptr;
    if (posix_memalign(&p, align, size) == 0) {
      count_block(p);
      return p;
    }
    const std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
  }
}

// The nothrow forms: null where the throwing form throws std::bad_alloc.
void *allocate_nothrow(std::size_t size) noexcept {
  try {
    return allocate(size);
  } catch (const std::bad_alloc &) {
    return nullptr;
  }
}
void *allocate_aligned_nothrow(std::size_t size, std::align_val_t alignment) noexcept {
  try {
    return allocate_aligned(size, alignment);
  } catch (const std::bad_alloc &) {
    return nullptr;
  }
}

}  // namespace

void *operator new(std::size_t size) { return allocate(size); }
void *operator new[](std::size_t size) { return allocate(size); }
void *operator new(std::size_t size, const std::nothrow_t &) noexcept {
  return allocate_nothrow(size);
}
void *operator new[](std::size_t size, const std::nothrow_t &) noexcept {
  return allocate_nothrow(size);
}
void *operator new(std::size_t size, std::align_val_t alignment) {
  return allocate_aligned(size, alignment);
}
void *operator new[](std::size_t size, std::align_val_t alignment) {
  return allocate_aligned(size, alignment);
}
void *operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t &) noexcept {
  return allocate_aligned_nothrow(size, alignment);
}
void *operator new[](std::size_t size, std::align_val_t alignment,
                     const std::nothrow_t &) noexcept {
  return allocate_aligned_nothrow(size, alignment);
}

void operator delete(void *p) noexcept { free_block(p); }
void operator delete[](void *p) noexcept { free_block(p); }
void operator delete(void *p, const std::nothrow_t &) noexcept { free_block(p); }
void operator delete[](void *p, const std::nothrow_t &) noexcept { free_block(p); }
void operator delete(void *p, std::size_t) noexcept { free_block(p); }
void operator delete[](void *p, std::size_t) noexcept { free_block(p); }
void operator delete(void *p, std::align_val_t) noexcept { free_block(p); }
void operator delete[](void *p, std::align_val_t) noexcept { free_block(p); }
void operator delete(void *p, std::align_val_t, const std::nothrow_t &) noexcept {
  free_block(p);
}
void operator delete[](void *p, std::align_val_t, const std::nothrow_t &) noexcept {
  free_block(p);
}
void operator delete(void *p, std::size_t, std::align_val_t) noexcept { free_block(p); }
void operator delete[](void *p, std::size_t, std::align_val_t) noexcept { free_block(p); }

extern "C" {

void topolab_heap_read(topolab_heap_counts *out) noexcept {
  const Counter &c = counter;
  out->on = c.on ? 1 : 0;
  out->current = c.current;
  out->peak = c.peak;
}

void topolab_heap_write(const topolab_heap_counts *counts) noexcept {
  counter = Counter{counts->on != 0, counts->current, counts->peak};
}

void *topolab_heap_test_vector(size_t length, const void **data) noexcept {
  try {
    auto *vector = new std::vector<uint32_t>(length);
    *data = vector->data();
    return vector;
  } catch (...) {
    return nullptr;
  }
}

void topolab_heap_test_free(void *vector) noexcept {
  delete static_cast<std::vector<uint32_t> *>(vector);
}

}  // extern "C"
