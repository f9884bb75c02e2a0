//! # topolab-alloc
//!
//! The process's allocator, and what the report's construction timing asks the system. The
//! crate declares no `#[global_allocator]`: a binary (the `topolab` crate's lib, an example or
//! a test that measures) declares one of [`CountingAllocator`] itself.
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
//! baselines' allocations are counted by the same rule and the same switch: the baselines
//! crate's `heap.cpp`, linked whenever a baseline is, replaces C++'s global `operator new` and
//! `delete` (every variant) by `malloc` and `free` that count into a thread-local counter of
//! their own, which an allocator made by [`CountingAllocator::with_foreign`] reads and writes
//! through the [`ForeignHeap`] it is given (a C API that cannot fail). Every count of
//! [`CountingAllocator`] is then the sum of the two sides. Usable sizes rather than requested ones, because only they can be
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

#![deny(missing_docs)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// The lab's global allocator: [`System`], counting this thread's bytes between
/// [`CountingAllocator::start`] and [`CountingAllocator::stop`], together with a foreign
/// heap's (the C++ baselines', see the module docs) when made with
/// [`CountingAllocator::with_foreign`].
#[derive(Debug, Default)]
pub struct CountingAllocator {
    /// The other side's counter, if any.
    foreign: Option<ForeignHeap>,
}

/// The counter of a heap the allocator does not see (C++'s `operator new`, counting into a
/// thread-local counter of its own by the same rule): how to read and write this thread's
/// counts. Both functions must be callable at any time, from any thread, and never allocate.
#[derive(Copy, Clone, Debug)]
pub struct ForeignHeap {
    /// This thread's counts.
    pub read: fn() -> HeapCounts,
    /// Replaces this thread's counts.
    pub write: fn(HeapCounts),
}

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

/// One side's counts of this thread, Rust's or a foreign heap's: the layout of
/// `topolab_heap_counts` of the baselines' `heap.h`, whose meaning both sides share.
#[repr(C)]
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct HeapCounts {
    /// 1 while the thread counts, else 0.
    pub on: i32,
    /// Bytes of the blocks counted and not freed since.
    pub current: usize,
    /// The highest `current` since the counts were last written.
    pub peak: usize,
}

impl HeapCounts {
    /// Counting, from zero.
    const STARTED: Self = Self {
        on: 1,
        current: 0,
        peak: 0,
    };
}

impl CountingAllocator {
    /// Counts Rust's allocations only.
    pub const fn new() -> Self {
        Self { foreign: None }
    }

    /// Counts Rust's allocations and, when given, those of `foreign`, by one switch.
    pub const fn with_foreign(foreign: Option<ForeignHeap>) -> Self {
        Self { foreign }
    }

    /// This thread's counts: Rust's, then the foreign heap's (all zero without one). Rust's
    /// read as all zero while the thread exits.
    fn sides(&self) -> [HeapCounts; 2] {
        let rust = COUNTER
            .try_with(|c| HeapCounts {
                on: c.on.get() as i32,
                current: c.current.get(),
                peak: c.peak.get(),
            })
            .unwrap_or_default();
        [rust, self.foreign.map(|f| (f.read)()).unwrap_or_default()]
    }

    /// Replaces this thread's counts, Rust's and the foreign heap's.
    fn set_sides(&self, [rust, foreign]: [HeapCounts; 2]) {
        let _ = COUNTER.try_with(|c| {
            c.on.set(rust.on != 0);
            c.current.set(rust.current);
            c.peak.set(rust.peak);
        });
        if let Some(f) = self.foreign {
            (f.write)(foreign);
        }
    }
}

/// Whether this thread counts (Rust's side; both are switched together).
#[inline(always)]
fn counting() -> bool {
    COUNTER.try_with(|c| c.on.get()).unwrap_or(false)
}

/// Bytes of the live block at `p` by the counting rule: `malloc_usable_size` with glibc; the
/// `requested` size elsewhere, where the rule has no function to read it.
///
/// # Safety
///
/// `p` is a live block of glibc's `malloc` family (Rust's [`System`], or C++'s `operator new`
/// as the baselines replace it).
#[inline]
pub unsafe fn block_bytes(p: *mut u8, requested: usize) -> usize {
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
        self.set_sides([HeapCounts::STARTED; 2]);
    }

    /// Stops counting this thread's allocations (the counts stay readable).
    pub fn stop(&self) {
        self.set_sides(self.sides().map(|c| HeapCounts { on: 0, ..c }));
    }

    /// Bytes this thread allocated and did not free since [`CountingAllocator::start`], Rust's
    /// and C++'s.
    pub fn current(&self) -> usize {
        self.sides().iter().map(|c| c.current).sum()
    }

    /// The highest [`CountingAllocator::current`] since the start or the last reset: the sum of
    /// each side's highest (see the module docs).
    pub fn peak(&self) -> usize {
        self.sides().iter().map(|c| c.peak).sum()
    }

    /// Starts a new peak at the current count.
    pub fn reset_peak(&self) {
        self.set_sides(self.sides().map(|c| HeapCounts {
            peak: c.current,
            ..c
        }));
    }

    /// Runs `work` and returns the peak of the bytes it allocated on this thread, Rust's and
    /// C++'s, beyond what was allocated when it started. Nests: inside a counting region
    /// (another `measure`, or [`CountingAllocator::start`]) the outer region's counts and peak
    /// go on, `work`'s allocations included, as if nothing had been measured inside.
    pub fn measure<T>(&self, work: impl FnOnce() -> T) -> (T, usize) {
        let outer = self.sides();
        self.set_sides(outer.map(|c| HeapCounts {
            on: 1,
            peak: c.current,
            ..c
        }));
        let out = work();
        let inner = self.sides();
        let peak = (0..2)
            .map(|i| inner[i].peak.saturating_sub(outer[i].current))
            .sum();
        self.set_sides([0, 1].map(|i| {
            let (before, after) = (outer[i], inner[i]);
            if before.on != 0 {
                HeapCounts {
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

/// Drops the pages of `file` from the page cache (`posix_fadvise(POSIX_FADV_DONTNEED)` after
/// writing back its dirty pages): the next read of the file, or of a mapping of it, comes from
/// the disk. The scale run's cold sweeps of a `.che` file need it. An error where the system
/// refuses (and on systems without `posix_fadvise`, where nothing is dropped).
pub fn drop_file_cache(file: &std::fs::File) -> std::io::Result<()> {
    file.sync_all()?;
    #[cfg(target_os = "linux")]
    {
        use std::os::fd::AsRawFd;
        // SAFETY: the descriptor is open for the call's duration (borrowed from `file`);
        // `posix_fadvise` only advises the kernel about the file's cached pages.
        let code =
            unsafe { libc::posix_fadvise(file.as_raw_fd(), 0, 0, libc::POSIX_FADV_DONTNEED) };
        if code != 0 {
            return Err(std::io::Error::from_raw_os_error(code));
        }
        Ok(())
    }
    #[cfg(not(target_os = "linux"))]
    {
        Err(std::io::Error::new(
            std::io::ErrorKind::Unsupported,
            "dropping a file's cached pages needs Linux's posix_fadvise",
        ))
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The tests' allocator: they read what it counted.
    #[global_allocator]
    static ALLOCATOR: CountingAllocator = CountingAllocator::new();

    /// The bytes a block counts for, by the rule (`block_bytes`), read independently of the
    /// counter: at least what was asked.
    fn bytes_of<T>(p: *const T, requested: usize) -> usize {
        // SAFETY: `p` is a live block of the test's allocator, `System`.
        let bytes = unsafe { block_bytes(p.cast_mut().cast(), requested) };
        assert!(bytes >= requested, "{bytes} < {requested}");
        bytes
    }

    #[test]
    fn counts_only_between_start_and_stop_on_this_thread() {
        let a = CountingAllocator::new();
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
        let a = CountingAllocator::new();
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

    #[test]
    fn a_measure_inside_another_leaves_the_outer_counts_whole() {
        let a = CountingAllocator::new();
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
