//! Timing: repeated runs with a warm-up, a time budget and medians ([`time`]); contenders
//! taking turns ([`turns`]); the memory meter and the measuring thread's clock ([`meter`]).

pub mod interval;
pub mod meter;
pub mod turns;

use std::time::{Duration, Instant};

/// Timing of repeated runs of one kernel.
#[derive(Copy, Clone, Debug, serde::Serialize)]
pub struct Timing {
    /// Median of the runs, in nanoseconds per run.
    pub median_ns: f64,
    /// Fastest run.
    pub min_ns: f64,
    /// Slowest run.
    pub max_ns: f64,
    /// How many runs were timed (after the warm-up).
    pub reps: usize,
}

/// How long to repeat.
#[derive(Copy, Clone, Debug)]
pub struct Budget {
    /// Stop repeating once this much time was spent (after `min_reps`).
    pub time: Duration,
    /// At least this many timed runs.
    pub min_reps: usize,
    /// At most this many timed runs.
    pub max_reps: usize,
}

/// Runs `f` once to warm up, then repeats it until the budget is spent; returns the timing and
/// the result of the runs. Fails if two runs give different results (a kernel must be
/// deterministic), naming both. A kernel whose warm-up alone exceeds the budget is timed once
/// more (one run of a slow kernel is dominated by its work, not by noise).
pub fn time<T: PartialEq + std::fmt::Debug>(
    budget: Budget,
    mut f: impl FnMut() -> T,
) -> Result<(Timing, T), String> {
    let warm = Instant::now();
    let first = f();
    let min_reps = if warm.elapsed() > budget.time {
        1
    } else {
        budget.min_reps
    };
    let start = Instant::now();
    let mut runs = Vec::with_capacity(min_reps);
    while runs.len() < min_reps || (runs.len() < budget.max_reps && start.elapsed() < budget.time) {
        let t = Instant::now();
        let r = std::hint::black_box(f());
        runs.push(t.elapsed().as_nanos() as f64);
        if r != first {
            return Err(format!(
                "run {} gave {r:?}, the first gave {first:?}",
                runs.len()
            ));
        }
    }
    Ok((Timing::of(runs), first))
}

impl Timing {
    /// The timing of `runs` (ns per run, at least one).
    pub fn of(mut runs: Vec<f64>) -> Timing {
        runs.sort_by(f64::total_cmp);
        Timing {
            median_ns: median(&runs),
            min_ns: runs.first().copied().unwrap_or(f64::NAN),
            max_ns: runs.last().copied().unwrap_or(f64::NAN),
            reps: runs.len(),
        }
    }
}

/// The median of sorted values (mean of the two middle ones for an even count).
pub fn median(sorted: &[f64]) -> f64 {
    let n = sorted.len();
    if n == 0 {
        f64::NAN
    } else if n % 2 == 1 {
        sorted[n / 2]
    } else {
        0.5 * (sorted[n / 2 - 1] + sorted[n / 2])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_of_odd_and_even() {
        assert_eq!(median(&[1.0, 2.0, 9.0]), 2.0);
        assert_eq!(median(&[1.0, 2.0, 4.0, 9.0]), 3.0);
    }

    #[test]
    fn repeats_at_least_min_reps_and_catches_nondeterminism() {
        let b = Budget {
            time: Duration::from_secs(5),
            min_reps: 5,
            max_reps: 10,
        };
        let (t, r) = time(b, || 7u64).unwrap();
        assert_eq!((t.reps, r), (10, 7));
        let slow = Budget {
            time: Duration::ZERO,
            ..b
        };
        assert_eq!(time(slow, || 7u64).unwrap().0.reps, 1);
        assert!(t.min_ns <= t.median_ns && t.median_ns <= t.max_ns);
        let mut n = 0;
        assert!(time(b, || {
            n += 1;
            n
        })
        .is_err());
    }
}
