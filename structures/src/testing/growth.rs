//! Complexity tests without absolute times: the work on an input and on one 4 times larger,
//! each the fastest of a few runs, and the ratio of the two held between linear growth (4×, a
//! little more for hashing and allocation) and quadratic (16×). The inputs are small (each run
//! well under a second), so a test holds a bound on growth, never a speed.
//!
//! Each run is timed by the CPU time of the thread running it, not by the clock on the wall:
//! on a shared machine, other processes delay the thread (a growth test once failed under
//! heavy load), but the CPU time it spends is its own work. The work measured runs on that
//! thread.

use std::sync::Mutex;
use std::time::Duration;

/// The most the time may grow when the input grows 4×: linear is 4, quadratic 16; the rest
/// is the margin a shared machine needs.
pub const MAX_RATIO: f64 = 8.0;

/// The least the smaller time counts as: below it, a machine's noise is of the time's size.
pub const NOISE_FLOOR: Duration = Duration::from_millis(5);

/// One measurement at a time in a test binary: its tests run on parallel threads, and a
/// measurement taken while another test's ran would time both.
static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

/// The times of `small` and `large`, each the fastest of `runs` runs, the runs taken in turns
/// (small, large, small, ...) so that a load that comes and goes weighs on both alike.
pub fn fastest_in_turns(runs: usize, small: &dyn Fn(), large: &dyn Fn()) -> (Duration, Duration) {
    // A test that failed while holding the lock poisoned it; the lock itself is still good.
    let _alone = ONE_AT_A_TIME
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    let time = |work: &dyn Fn()| {
        let started = thread_cpu_time();
        work();
        thread_cpu_time().saturating_sub(started)
    };
    let (mut a, mut b) = (Duration::MAX, Duration::MAX);
    for _ in 0..runs {
        a = a.min(time(small));
        b = b.min(time(large));
    }
    (a, b)
}

/// The CPU time the calling thread has spent, `CLOCK_THREAD_CPUTIME_ID` (nanoseconds).
#[allow(unsafe_code)]
fn thread_cpu_time() -> Duration {
    let mut now = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `now` is a valid timespec to write; the clock exists on every POSIX system the
    // lab builds on, and its failure (-1) would leave `now` at zero, which the assert refuses.
    let failed = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut now) };
    assert_eq!(failed, 0, "no thread CPU clock");
    Duration::new(now.tv_sec as u64, now.tv_nsec as u32)
}

/// How much `large` took over `small`, the smaller counted as at least [`NOISE_FLOOR`].
pub fn ratio(small: Duration, large: Duration) -> f64 {
    large.as_secs_f64() / small.max(NOISE_FLOOR).as_secs_f64()
}

/// `work(n)` and `work(4n)` ([`fastest_in_turns`], five runs each): the larger takes at most
/// [`MAX_RATIO`] times the smaller's time. Panics, naming `name` and both times, otherwise.
pub fn grows_linearly(name: &str, n: usize, work: impl Fn(usize)) {
    let (small, large) = fastest_in_turns(5, &|| work(n), &|| work(4 * n));
    let ratio = ratio(small, large);
    println!(
        "{name}: {small:?} at {n}, {large:?} at {}: {ratio:.1}x",
        4 * n
    );
    assert!(
        ratio <= MAX_RATIO,
        "{name}: {small:?} at {n}, {large:?} at {} ({ratio:.1}x, more than {MAX_RATIO})",
        4 * n
    );
}
