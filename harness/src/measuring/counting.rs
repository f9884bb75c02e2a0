//! The lab's counting allocator (`topolab-alloc`) as the harness's [`MemoryMeter`].

use crate::measuring::measure::MemoryMeter;
use topolab_alloc::{minor_faults, release_free_memory, thread_cpu_ns, CountingAllocator};

/// The lab's allocator as the harness's memory meter, for the report's measurements and the
/// hull benchmark: it reads both counters, Rust's and, when it was made with one, the C++
/// baselines' (one rule for both, see `topolab_alloc`); counting starts and stops with [`CountingAllocator::start`] and
/// [`CountingAllocator::stop`], on the calling thread only.
impl MemoryMeter for CountingAllocator {
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
