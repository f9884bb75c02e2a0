//! The memory meter: what the harness asks of the process's allocator (heap in use, peak, page
//! faults) and of its clock (the measuring thread's CPU time), implemented by the report
//! binary's counting allocator. The harness never counts inside a timed region: it reads the
//! meter before and after.

/// Reads the process's heap use (the report binary's counting allocator, which counts the C++
/// baselines' blocks by the same rule as Rust's) and page faults.
pub trait MemoryMeter {
    /// Bytes allocated now.
    fn current(&self) -> usize;
    /// Highest `current()` since the last reset.
    fn peak(&self) -> usize;
    /// Starts a new peak at `current()`.
    fn reset_peak(&self);
    /// Starts (`true`) or stops counting allocations. The report's allocator counts only while
    /// asked, so the timed builds pay nothing for the memory measurement. The default does
    /// nothing (a meter that always counts).
    fn counting(&self, on: bool) {
        let _ = on;
    }
    /// Minor page faults of the measuring thread so far; `None` (the default) when unknown.
    fn minor_faults(&self) -> Option<u64> {
        None
    }
    /// Returns the memory the allocator holds free to the kernel, so that the next build
    /// touches fresh pages (a cold build). The default does nothing.
    fn release_free_memory(&self) {}
    /// The measuring thread's CPU time so far, user and system, ns: when known, builds are
    /// timed by it, so that the other processes of a shared machine do not count. `None` (the
    /// default): builds are timed by the wall clock.
    fn thread_cpu_ns(&self) -> Option<u64> {
        None
    }
}

/// A meter that counts nothing and times by the wall clock: for tests and probes that run
/// kernels without the report's counting allocator.
pub struct Uncounted;

impl MemoryMeter for Uncounted {
    fn current(&self) -> usize {
        0
    }
    fn peak(&self) -> usize {
        0
    }
    fn reset_peak(&self) {}
}
