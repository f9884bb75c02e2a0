//! The process's allocator, and what the report's construction timing asks the system.
//!
//! [`CountingAllocator`] is glibc's `malloc` (Rust's [`System`]) that counts the bytes of one
//! thread only while that thread asked it to ([`CountingAllocator::start`]): the report measures
//! a structure's heap in one build of its own, and times the other builds with nothing counted,
//! as OpenMesh's C++ allocations never are. The counters are plain thread-local cells, so a build
//! that is not counted pays one thread-local load per allocation and nothing else; the counting
//! allocator the lab used before added two atomic read-modify-writes to every allocation, and
//! copied on every `realloc` and zeroed every `calloc` itself, which slowed the Rust structures'
//! timed construction (most of all the pointer half-edge's one allocation per record).
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
/// [`CountingAllocator::start`] and [`CountingAllocator::stop`].
#[derive(Debug, Default)]
pub struct CountingAllocator;

/// One thread's counters. A `const` thread-local without a destructor is a plain TLS slot: the
/// allocator may read it at any time, also while the thread exits.
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
// counting touches only this thread's cells and never allocates.
unsafe impl GlobalAlloc for CountingAllocator {
    #[inline]
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller upholds `GlobalAlloc::alloc`'s contract, which `System` has too.
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            count(layout.size(), 0);
        }
        p
    }

    #[inline]
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: as `alloc`. `System` calls `calloc`, which skips zeroing pages the kernel
        // hands out zeroed.
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            count(layout.size(), 0);
        }
        p
    }

    #[inline]
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: the caller passes a block of this allocator, which is `System`'s.
        unsafe { System.dealloc(ptr, layout) };
        count(0, layout.size());
    }

    #[inline]
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: as `dealloc`; `System` calls `realloc`, which grows in place when it can.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            // The transient copy a `realloc` may make is not counted in the peak.
            count(new_size, layout.size());
        }
        p
    }
}

impl CountingAllocator {
    /// Starts counting this thread's allocations, from zero bytes.
    pub fn start(&self) {
        let _ = COUNTER.try_with(|c| {
            c.current.set(0);
            c.peak.set(0);
            c.on.set(true);
        });
    }

    /// Stops counting this thread's allocations (the counts stay readable).
    pub fn stop(&self) {
        let _ = COUNTER.try_with(|c| c.on.set(false));
    }

    /// Bytes this thread allocated and did not free since [`CountingAllocator::start`].
    pub fn current(&self) -> usize {
        COUNTER.try_with(|c| c.current.get()).unwrap_or(0)
    }

    /// The highest [`CountingAllocator::current`] since the start or the last reset.
    pub fn peak(&self) -> usize {
        COUNTER.try_with(|c| c.peak.get()).unwrap_or(0)
    }

    /// Starts a new peak at the current count.
    pub fn reset_peak(&self) {
        let _ = COUNTER.try_with(|c| c.peak.set(c.current.get()));
    }

    /// Runs `work` and returns the peak of the bytes it allocated on this thread beyond what
    /// was allocated when it started. Nests: inside a counting region (another `measure`, or
    /// [`CountingAllocator::start`]) the outer region's counts and peak go on, `work`'s
    /// allocations included, as if nothing had been measured inside.
    pub fn measure<T>(&self, work: impl FnOnce() -> T) -> (T, usize) {
        let outer = COUNTER.try_with(|c| (c.on.get(), c.current.get(), c.peak.get()));
        let Ok((was_on, before, outer_peak)) = outer else {
            return (work(), 0);
        };
        let _ = COUNTER.try_with(|c| {
            c.peak.set(before);
            c.on.set(true);
        });
        let out = work();
        let peak = COUNTER.try_with(|c| c.peak.get()).unwrap_or(before);
        let _ = COUNTER.try_with(|c| {
            c.on.set(was_on);
            if was_on {
                c.peak.set(outer_peak.max(peak));
            } else {
                // Outside a counting region nothing is counted: leave the counts as they were.
                c.current.set(before);
                c.peak.set(outer_peak);
            }
        });
        (out, peak.saturating_sub(before))
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
/// hull benchmark: counting starts and stops with [`CountingAllocator::start`] and
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

    #[test]
    fn counts_only_between_start_and_stop_on_this_thread() {
        let a = CountingAllocator;
        a.start();
        let v: Vec<u8> = Vec::with_capacity(1 << 20);
        assert_eq!(a.current(), 1 << 20);
        let mut w: Vec<u64> = Vec::with_capacity(16);
        w.extend(0..1000u64);
        assert_eq!(a.current(), (1 << 20) + w.capacity() * 8);
        drop(v);
        assert_eq!(a.current(), w.capacity() * 8);
        assert!(a.peak() >= (1 << 20) + 8000, "{}", a.peak());
        // Another thread's 4 MiB are not this thread's (spawning it allocates a few bytes
        // here: its handle).
        let held = w.capacity() * 8;
        std::thread::spawn(|| Vec::<u8>::with_capacity(1 << 22).capacity())
            .join()
            .unwrap();
        assert!(a.current() < held + 1024, "{} > {held}", a.current());
        let held = a.current();
        a.stop();
        let x: Vec<u8> = Vec::with_capacity(1 << 20);
        drop(w);
        assert_eq!(a.current(), held, "nothing counted after stop");
        drop(x);
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
