//! The process's allocator, and what the report's construction timing asks the system.
//!
//! [`CountingAllocator`] is glibc's `malloc` (Rust's [`System`]) that counts the bytes of one
//! thread only while that thread asked it to ([`CountingAllocator::start`]): the report measures
//! a structure's heap in one build of its own, and times the other builds with nothing counted.
//! The counters are plain thread-local cells, so a build that is not counted pays one
//! thread-local load per allocation and nothing else; the counting allocator the lab used
//! before added two atomic read-modify-writes to every allocation, and copied on every
//! `realloc` and zeroed every `calloc` itself, which slowed the Rust structures' timed
//! construction (most of all the pointer half-edge's one allocation per record).
//!
//! **One rule for Rust and C++.** A block counts for the bytes `malloc_usable_size` reports for
//! it: the request rounded up to glibc's chunk size (steps of 16 bytes, at least 24 on 64-bit
//! Linux; whole pages for a block glibc maps by itself, which the report does not let it do,
//! [`keep_freed_memory`]), without the 8-byte size field glibc keeps in front of each block.
//! The C++
//! baselines' allocations are counted by the same rule and the same switch: `heap/heap.cpp`,
//! linked whenever a baseline is, replaces C++'s global `operator new` and `delete` (every
//! variant) by `malloc` and `free` that count into a thread-local counter of their own, read
//! and written here through a C API that cannot fail. Every count of [`CountingAllocator`] is
//! the sum of the two sides. Usable sizes rather than requested ones, because only they can be
//! had exactly on both sides: C++'s unsized `delete` does not say how many bytes it frees
//! (libstdc++ calls the sized one for most of its containers, not all), so requested sizes
//! would need each block's size kept somewhere, a header that changes every block or a table
//! that is a structure of its own; and the rounding they include is what a structure of many
//! small blocks (the pointer half-edge, `Polyhedron_3`) really pays. What is not counted:
//! memory a C or C++ library takes from `malloc` itself instead of `operator new` (GMP's
//! numbers in CGAL's hull), and the transient copy a `realloc` may make. A peak is the sum of
//! the two sides' peaks: exact when only one side allocates in the measured region (every
//! construction: a baseline's build allocates in C++ alone, the lab's structures in Rust
//! alone), an upper bound when both do.
//!
//! The glibc functions below make construction timings comparable between runs:
//! [`keep_freed_memory`] stops glibc from returning memory to the kernel (and from serving large
//! blocks by `mmap`), so a build that follows another reuses its pages instead of faulting in
//! fresh ones, whatever ran before; [`release_free_memory`] returns it on purpose, so the next
//! build starts cold; [`minor_faults`] counts the page faults in between. Builds are timed in
//! the thread's CPU time ([`thread_cpu_ns`]: user and system, so page faults count), which the
//! other processes of a shared machine do not stretch as they stretch the wall-clock time.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// The lab's global allocator: [`System`], counting this thread's bytes between
/// [`CountingAllocator::start`] and [`CountingAllocator::stop`], together with the C++
/// baselines' (see the module docs).
#[derive(Debug, Default)]
pub struct CountingAllocator;

/// Rust's counter of one thread. A `const` thread-local without a destructor is a plain TLS
/// slot: the allocator may read it at any time, also while the thread exits.
struct Counter {
    on: Cell<bool>,
    current: Cell<usize>,
    peak: Cell<usize>,
}

thread_local! {
    static COUNTER: Counter = const {
        Counter {
            on: Cell::new(false),
            current: Cell::new(0),
            peak: Cell::new(0),
        }
    };
}

/// One side's counts of this thread, Rust's or C++'s: the `topolab_heap_counts` of
/// `heap/heap.h`, whose meaning both sides share.
#[repr(C)]
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
struct Counts {
    /// 1 while the thread counts, else 0.
    on: i32,
    /// Bytes of the blocks counted and not freed since.
    current: usize,
    /// The highest `current` since the counts were last written.
    peak: usize,
}

impl Counts {
    /// Counting, from zero.
    const STARTED: Self = Self {
        on: 1,
        current: 0,
        peak: 0,
    };
}

/// The C++ side (`heap/heap.h`), when a baseline is linked.
#[cfg(has_cpp_heap)]
mod cpp {
    use super::Counts;
    #[cfg(test)]
    use std::ffi::c_void;

    extern "C" {
        fn topolab_heap_read(out: *mut Counts);
        fn topolab_heap_write(counts: *const Counts);
        #[cfg(test)]
        fn topolab_heap_test_vector(length: usize, data: *mut *const c_void) -> *mut c_void;
        #[cfg(test)]
        fn topolab_heap_test_free(vector: *mut c_void);
    }

    /// This thread's C++ counts.
    pub(super) fn read() -> Counts {
        let mut out = Counts::default();
        // SAFETY: `out` is a valid, writable `topolab_heap_counts` (same layout, `repr(C)`);
        // the function only writes it.
        unsafe { topolab_heap_read(&mut out) };
        out
    }

    /// Replaces this thread's C++ counts.
    pub(super) fn write(counts: Counts) {
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

/// Without a C++ baseline nothing allocates through C++'s `operator new` that the lab could
/// count: the C++ side reads as nothing counted.
#[cfg(not(has_cpp_heap))]
mod cpp {
    use super::Counts;

    pub(super) fn read() -> Counts {
        Counts::default()
    }

    pub(super) fn write(_: Counts) {}
}

/// This thread's counts: Rust's, then C++'s. Rust's read as all zero while the thread exits.
fn sides() -> [Counts; 2] {
    let rust = COUNTER
        .try_with(|c| Counts {
            on: c.on.get() as i32,
            current: c.current.get(),
            peak: c.peak.get(),
        })
        .unwrap_or_default();
    [rust, cpp::read()]
}

/// Replaces this thread's counts, Rust's and C++'s.
fn set_sides([rust, cpp]: [Counts; 2]) {
    let _ = COUNTER.try_with(|c| {
        c.on.set(rust.on != 0);
        c.current.set(rust.current);
        c.peak.set(rust.peak);
    });
    cpp::write(cpp);
}

/// Whether this thread counts (Rust's side; both are switched together).
#[inline(always)]
fn counting() -> bool {
    COUNTER.try_with(|c| c.on.get()).unwrap_or(false)
}

/// Bytes of the live block at `p` by the counting rule: `malloc_usable_size` with glibc; the
/// `requested` size elsewhere, where the rule has no function to read it.
#[inline]
fn block_bytes(p: *mut u8, requested: usize) -> usize {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    {
        let _ = requested;
        // SAFETY: `p` is a live block of `System`, which is glibc's malloc family.
        unsafe { libc::malloc_usable_size(p.cast()) }
    }
    #[cfg(not(all(target_os = "linux", target_env = "gnu")))]
    {
        let _ = p;
        requested
    }
}

/// Counts `grown` bytes allocated and `shrunk` bytes freed, if this thread is counting. Bytes
/// freed that were allocated before counting started are not subtracted below zero.
#[inline(always)]
fn count(grown: usize, shrunk: usize) {
    let _ = COUNTER.try_with(|c| {
        if c.on.get() {
            let now = c.current.get().saturating_sub(shrunk) + grown;
            c.current.set(now);
            if now > c.peak.get() {
                c.peak.set(now);
            }
        }
    });
}

// SAFETY: every call is forwarded to `System` with the caller's arguments unchanged; the
// counting touches only this thread's cells, reads a block's size before it is freed, and
// never allocates.
unsafe impl GlobalAlloc for CountingAllocator {
    #[inline]
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller upholds `GlobalAlloc::alloc`'s contract, which `System` has too.
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() && counting() {
            count(block_bytes(p, layout.size()), 0);
        }
        p
    }

    #[inline]
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: as `alloc`. `System` calls `calloc`, which skips zeroing pages the kernel
        // hands out zeroed.
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() && counting() {
            count(block_bytes(p, layout.size()), 0);
        }
        p
    }

    #[inline]
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // The block's size is read while it is still allocated.
        let freed = counting().then(|| block_bytes(ptr, layout.size()));
        // SAFETY: the caller passes a block of this allocator, which is `System`'s.
        unsafe { System.dealloc(ptr, layout) };
        if let Some(bytes) = freed {
            count(0, bytes);
        }
    }

    #[inline]
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let old = counting().then(|| block_bytes(ptr, layout.size()));
        // SAFETY: as `dealloc`; `System` calls `realloc`, which grows in place when it can.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if let (false, Some(old)) = (p.is_null(), old) {
            // The transient copy a `realloc` may make is not counted in the peak.
            count(block_bytes(p, new_size), old);
        }
        p
    }
}

impl CountingAllocator {
    /// Starts counting this thread's allocations, Rust's and C++'s, from zero bytes.
    pub fn start(&self) {
        set_sides([Counts::STARTED; 2]);
    }

    /// Stops counting this thread's allocations (the counts stay readable).
    pub fn stop(&self) {
        set_sides(sides().map(|c| Counts { on: 0, ..c }));
    }

    /// Bytes this thread allocated and did not free since [`CountingAllocator::start`], Rust's
    /// and C++'s.
    pub fn current(&self) -> usize {
        sides().iter().map(|c| c.current).sum()
    }

    /// The highest [`CountingAllocator::current`] since the start or the last reset: the sum of
    /// each side's highest (see the module docs).
    pub fn peak(&self) -> usize {
        sides().iter().map(|c| c.peak).sum()
    }

    /// Starts a new peak at the current count.
    pub fn reset_peak(&self) {
        set_sides(sides().map(|c| Counts {
            peak: c.current,
            ..c
        }));
    }

    /// Runs `work` and returns the peak of the bytes it allocated on this thread, Rust's and
    /// C++'s, beyond what was allocated when it started. Nests: inside a counting region
    /// (another `measure`, or [`CountingAllocator::start`]) the outer region's counts and peak
    /// go on, `work`'s allocations included, as if nothing had been measured inside.
    pub fn measure<T>(&self, work: impl FnOnce() -> T) -> (T, usize) {
        let outer = sides();
        set_sides(outer.map(|c| Counts {
            on: 1,
            peak: c.current,
            ..c
        }));
        let out = work();
        let inner = sides();
        let peak = (0..2)
            .map(|i| inner[i].peak.saturating_sub(outer[i].current))
            .sum();
        set_sides([0, 1].map(|i| {
            let (before, after) = (outer[i], inner[i]);
            if before.on != 0 {
                Counts {
                    peak: before.peak.max(after.peak),
                    ..after
                }
            } else {
                // Outside a counting region nothing is counted: leave the counts as they were.
                before
            }
        }));
        (out, peak)
    }
}

/// glibc only: makes freed memory stay with the process, for every allocation of the process
/// (C++ baselines included, which use the same `malloc`). Without it, glibc serves large blocks
/// (above a threshold that moves with the sizes freed before) by `mmap` and unmaps them when
/// freed, and trims the heap's top, so whether a build of a large mesh faults in fresh pages
/// depended on what the run had built before it. Returns whether glibc accepted the settings.
pub fn keep_freed_memory() -> bool {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    {
        // SAFETY: `mallopt` only changes glibc's allocation policy; both parameters are valid.
        unsafe {
            libc::mallopt(libc::M_MMAP_MAX, 0) == 1
                && libc::mallopt(libc::M_TRIM_THRESHOLD, libc::c_int::MAX) == 1
        }
    }
    #[cfg(not(all(target_os = "linux", target_env = "gnu")))]
    {
        false
    }
}

/// glibc only: returns the memory the allocator holds free to the kernel (`malloc_trim(0)`), so
/// the next build touches fresh pages: a cold build.
pub fn release_free_memory() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: `malloc_trim` only releases free memory; no block in use moves.
    unsafe {
        libc::malloc_trim(0);
    }
}

/// The minor page faults of this thread so far (`getrusage`), `None` where unavailable.
pub fn minor_faults() -> Option<u64> {
    #[cfg(target_os = "linux")]
    {
        /// `RUSAGE_THREAD` of `<sys/resource.h>` (Linux), which the `libc` crate does not
        /// export for glibc.
        const RUSAGE_THREAD: libc::c_int = 1;
        let mut usage = std::mem::MaybeUninit::<libc::rusage>::zeroed();
        // SAFETY: `usage` is a valid, writable `rusage`; `getrusage` fills it or fails.
        let ok = unsafe { libc::getrusage(RUSAGE_THREAD, usage.as_mut_ptr()) } == 0;
        // SAFETY: zero-initialised, and filled by `getrusage` when it succeeded.
        ok.then(|| unsafe { usage.assume_init() }.ru_minflt as u64)
    }
    #[cfg(not(target_os = "linux"))]
    {
        None
    }
}

/// The CPU time this thread has used, user and system, in nanoseconds
/// (`CLOCK_THREAD_CPUTIME_ID`); `None` where unavailable.
pub fn thread_cpu_ns() -> Option<u64> {
    #[cfg(target_os = "linux")]
    {
        let mut t = libc::timespec {
            tv_sec: 0,
            tv_nsec: 0,
        };
        // SAFETY: `t` is a valid, writable `timespec`; the clock id is a constant of Linux.
        let ok = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) } == 0;
        ok.then(|| t.tv_sec as u64 * 1_000_000_000 + t.tv_nsec as u64)
    }
    #[cfg(not(target_os = "linux"))]
    {
        None
    }
}

/// Whose CPU time [`cpu_seconds`] reads.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Who {
    /// The process, all its threads (`RUSAGE_SELF`).
    Process,
    /// The subprocesses it has waited for (`RUSAGE_CHILDREN`).
    Children,
}

/// User plus system CPU time of `who` so far (`getrusage`), seconds; `None` where unavailable.
pub fn cpu_seconds(who: Who) -> Option<f64> {
    let id = match who {
        Who::Process => libc::RUSAGE_SELF,
        Who::Children => libc::RUSAGE_CHILDREN,
    };
    let mut usage = std::mem::MaybeUninit::<libc::rusage>::zeroed();
    // SAFETY: `usage` is a valid, writable `rusage`; `getrusage` fills it or fails.
    let ok = unsafe { libc::getrusage(id, usage.as_mut_ptr()) } == 0;
    // SAFETY: zero-initialised, and filled by `getrusage` when it succeeded.
    let u = ok.then(|| unsafe { usage.assume_init() })?;
    let s = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
    Some(s(u.ru_utime) + s(u.ru_stime))
}

/// The lab's allocator as the harness's memory meter, for the report's measurements and the
/// hull benchmark: it reads both counters, Rust's and the C++ baselines' (one rule for both,
/// see the module docs); counting starts and stops with [`CountingAllocator::start`] and
/// [`CountingAllocator::stop`], on the calling thread only.
impl topolab_harness::measure::MemoryMeter for CountingAllocator {
    fn current(&self) -> usize {
        CountingAllocator::current(self)
    }
    fn peak(&self) -> usize {
        CountingAllocator::peak(self)
    }
    fn reset_peak(&self) {
        CountingAllocator::reset_peak(self)
    }
    fn counting(&self, on: bool) {
        if on {
            self.start()
        } else {
            self.stop()
        }
    }
    fn minor_faults(&self) -> Option<u64> {
        minor_faults()
    }
    fn release_free_memory(&self) {
        release_free_memory()
    }
    fn thread_cpu_ns(&self) -> Option<u64> {
        thread_cpu_ns()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bytes a block counts for, by the rule (`block_bytes`), read independently of the
    /// counter: at least what was asked.
    fn bytes_of<T>(p: *const T, requested: usize) -> usize {
        let bytes = block_bytes(p.cast_mut().cast(), requested);
        assert!(bytes >= requested, "{bytes} < {requested}");
        bytes
    }

    #[test]
    fn counts_only_between_start_and_stop_on_this_thread() {
        let a = CountingAllocator;
        a.start();
        let v: Vec<u8> = Vec::with_capacity(1 << 20);
        let v_bytes = bytes_of(v.as_ptr(), 1 << 20);
        assert_eq!(a.current(), v_bytes);
        let mut w: Vec<u64> = Vec::with_capacity(16);
        w.extend(0..1000u64);
        let w_bytes = bytes_of(w.as_ptr(), w.capacity() * 8);
        assert_eq!(a.current(), v_bytes + w_bytes);
        drop(v);
        assert_eq!(a.current(), w_bytes);
        assert!(a.peak() >= v_bytes + w_bytes, "{}", a.peak());
        // Another thread's 4 MiB are not this thread's (spawning it allocates a few bytes
        // here: its handle).
        std::thread::spawn(|| Vec::<u8>::with_capacity(1 << 22).capacity())
            .join()
            .unwrap();
        assert!(a.current() < w_bytes + 1024, "{} > {w_bytes}", a.current());
        let held = a.current();
        a.stop();
        let x: Vec<u8> = Vec::with_capacity(1 << 20);
        drop(w);
        assert_eq!(a.current(), held, "nothing counted after stop");
        drop(x);
    }

    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    #[test]
    fn a_block_counts_for_what_glibc_hands_out() {
        let a = CountingAllocator;
        // glibc's chunks grow by 16 bytes, and a block gives its user all of its chunk but the
        // 8-byte size field in front: 24 usable bytes for 1 to 24 asked, 40 for 25 to 40.
        for (asked, counted) in [
            (1usize, 24usize),
            (24, 24),
            (25, 40),
            (1000, 1000),
            (1001, 1016),
        ] {
            a.start();
            let v: Vec<u8> = Vec::with_capacity(asked);
            assert_eq!(a.current(), counted, "{asked} bytes asked");
            drop(v);
            assert_eq!(a.current(), 0, "{asked} bytes freed");
            a.stop();
        }
    }

    /// The C++ side: a `std::vector<uint32_t>` made by the C++ `operator new` is counted by the
    /// same rule, block by block, and only on the thread that counts.
    #[cfg(has_cpp_heap)]
    #[test]
    fn a_cpp_vector_counts_for_its_blocks_on_the_counting_thread_only() {
        let a = CountingAllocator;
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
        assert_eq!(other, Counts::default());
        assert_eq!(cpp::read().current, blocks);
        cpp::free_test_vector(vector);
        assert_eq!(
            cpp::read(),
            Counts {
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
            Counts {
                on: 0,
                current: 0,
                peak: blocks
            }
        );
    }

    #[test]
    fn a_measure_inside_another_leaves_the_outer_counts_whole() {
        let a = CountingAllocator;
        let (_, outer) = a.measure(|| {
            let kept: Vec<u8> = Vec::with_capacity(1 << 20);
            let (_, inner) = a.measure(|| Vec::<u8>::with_capacity(1 << 21).capacity());
            assert!(inner >= 1 << 21, "{inner}");
            kept.len()
        });
        // The outer peak saw the inner 2 MiB on top of its own 1 MiB.
        assert!(outer >= 3 << 20, "{outer}");
        // Outside any region, nothing stays counted.
        let before = a.current();
        let _v: Vec<u8> = Vec::with_capacity(1 << 20);
        assert_eq!(a.current(), before);
    }

    #[test]
    fn page_faults_grow_when_fresh_memory_is_touched() {
        let Some(before) = minor_faults() else {
            return;
        };
        // 64 MiB written: glibc maps a block that large afresh, so its pages fault in, 4 KiB
        // or (transparent huge pages) 2 MiB at a time.
        let v = vec![1u8; 64 << 20];
        std::hint::black_box(&v);
        let after = minor_faults().unwrap();
        assert!(after >= before + 16, "{before} -> {after}");
    }

    #[test]
    fn thread_cpu_time_counts_work_and_not_sleep() {
        let Some(start) = thread_cpu_ns() else {
            return;
        };
        std::thread::sleep(std::time::Duration::from_millis(50));
        let slept = thread_cpu_ns().unwrap() - start;
        let t = std::time::Instant::now();
        let mut x = 0u64;
        while t.elapsed() < std::time::Duration::from_millis(50) {
            x = std::hint::black_box(x.wrapping_add(1));
        }
        let worked = thread_cpu_ns().unwrap() - start - slept;
        // Sleeping takes (almost) no CPU time; spinning for 50 ms takes some (all of it on an
        // idle machine, less when other processes share the core).
        assert!(slept < 20_000_000, "{slept} ns of CPU while sleeping");
        assert!(worked > slept, "{worked} ns spinning, {slept} ns sleeping");
    }
}
