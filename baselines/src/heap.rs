//! The C++ side of the lab's heap counting (`cpp/heap/heap.h`): the counter of the global
//! `operator new` and `delete` that `cpp/heap/heap.cpp` replaces whenever a C++ baseline is
//! linked, as the [`ForeignHeap`] of `topolab-alloc`'s counting allocator, so that one switch
//! counts Rust's and C++'s blocks by one rule.

use topolab_alloc::ForeignHeap;

/// The C++ heap's counter, when a C++ baseline is linked (else nothing allocates through
/// C++'s `operator new` that the lab could count): give it to
/// [`topolab_alloc::CountingAllocator::with_foreign`].
pub const CPP_HEAP: Option<ForeignHeap> = if cfg!(has_cpp_heap) {
    Some(ForeignHeap {
        read: cpp::read,
        write: cpp::write,
    })
} else {
    None
};

/// The declarations of `cpp/heap/heap.h`, when it is linked.
#[cfg(has_cpp_heap)]
mod cpp {
    #[cfg(test)]
    use std::ffi::c_void;
    use topolab_alloc::HeapCounts;

    extern "C" {
        fn topolab_heap_read(out: *mut HeapCounts);
        fn topolab_heap_write(counts: *const HeapCounts);
        #[cfg(test)]
        fn topolab_heap_test_vector(length: usize, data: *mut *const c_void) -> *mut c_void;
        #[cfg(test)]
        fn topolab_heap_test_free(vector: *mut c_void);
    }

    /// This thread's C++ counts.
    pub(super) fn read() -> HeapCounts {
        let mut out = HeapCounts::default();
        // SAFETY: `out` is a valid, writable `topolab_heap_counts` (same layout, `repr(C)`);
        // the function only writes it.
        unsafe { topolab_heap_read(&mut out) };
        out
    }

    /// Replaces this thread's C++ counts.
    pub(super) fn write(counts: HeapCounts) {
        // SAFETY: `counts` is a valid `topolab_heap_counts`; the function only reads it.
        unsafe { topolab_heap_write(&counts) }
    }

    /// A C++ `std::vector<uint32_t>` of `length` zeros, made by `operator new` in C++: the
    /// vector and the address of its elements (two blocks). Freed by [`free_test_vector`].
    #[cfg(test)]
    pub(super) fn test_vector(length: usize) -> (*mut c_void, *const c_void) {
        let mut data = std::ptr::null();
        // SAFETY: `data` is a valid out-pointer; the function catches every exception.
        let vector = unsafe { topolab_heap_test_vector(length, &mut data) };
        assert!(!vector.is_null(), "out of memory");
        (vector, data)
    }

    /// Deletes a vector of [`test_vector`].
    #[cfg(test)]
    pub(super) fn free_test_vector(vector: *mut c_void) {
        // SAFETY: `vector` came from `topolab_heap_test_vector` and is freed once, here.
        unsafe { topolab_heap_test_free(vector) }
    }
}

/// Without a C++ baseline: [`CPP_HEAP`] is `None`; these only keep its initialiser compiling.
#[cfg(not(has_cpp_heap))]
mod cpp {
    use topolab_alloc::HeapCounts;

    pub(super) fn read() -> HeapCounts {
        HeapCounts::default()
    }

    pub(super) fn write(_: HeapCounts) {}
}

#[cfg(all(test, has_cpp_heap))]
mod tests {
    use super::*;
    use topolab_alloc::{CountingAllocator, HeapCounts};

    /// This test binary's allocator, counting both sides as the lab's does.
    #[global_allocator]
    static ALLOCATOR: CountingAllocator = CountingAllocator::with_foreign(CPP_HEAP);

    /// The bytes the live C++ block at `p` counts for, by the rule of both sides, read
    /// independently of the counters: at least what was asked.
    fn bytes_of<T>(p: *const T, requested: usize) -> usize {
        // SAFETY: `p` is a live block of C++'s `operator new`, which is glibc's `malloc` here.
        let bytes = unsafe { topolab_alloc::block_bytes(p.cast_mut().cast(), requested) };
        assert!(bytes >= requested, "{bytes} < {requested}");
        bytes
    }

    /// The C++ side: a `std::vector<uint32_t>` made by the C++ `operator new` is counted by the
    /// same rule, block by block, and only on the thread that counts.
    #[test]
    fn a_cpp_vector_counts_for_its_blocks_on_the_counting_thread_only() {
        let a = &ALLOCATOR;
        a.start();
        let (vector, data) = cpp::test_vector(1000);
        // The vector (three pointers) and its 1000 elements of 4 bytes.
        let blocks = bytes_of(vector, 24) + bytes_of(data, 4000);
        assert_eq!(cpp::read().current, blocks);
        assert_eq!(a.current(), blocks, "nothing in Rust meanwhile");
        // Another thread, not counting, makes and frees a C++ vector of 4 MB: neither its own
        // counts nor this thread's move.
        let other = std::thread::spawn(|| {
            let (vector, _) = cpp::test_vector(1 << 20);
            cpp::free_test_vector(vector);
            cpp::read()
        })
        .join()
        .unwrap();
        assert_eq!(other, HeapCounts::default());
        assert_eq!(cpp::read().current, blocks);
        cpp::free_test_vector(vector);
        assert_eq!(
            cpp::read(),
            HeapCounts {
                on: 1,
                current: 0,
                peak: blocks
            }
        );
        // Stopped: C++ allocations are not counted.
        a.stop();
        let (vector, _) = cpp::test_vector(1000);
        cpp::free_test_vector(vector);
        assert_eq!(
            cpp::read(),
            HeapCounts {
                on: 0,
                current: 0,
                peak: blocks
            }
        );
    }
}
