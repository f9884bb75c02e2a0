//! Taking turns: two or more contenders run A, B, A, B, … round after round, so that a change
//! of load on a shared machine hits every side of a round alike; every run's answer must agree
//! with the first ([`take_turns`]). Each run is timed by a [`Stopwatch`], in the measuring
//! thread's CPU time when the meter knows it; the per-round values make a [`Spread`].

use crate::measuring::checksum::MeshChecksum;
use crate::measuring::timing::interval::Interval;
use crate::measuring::timing::median;
use crate::measuring::timing::meter::MemoryMeter;
use std::time::Instant;

/// What one run answered, to compare with the other runs.
#[derive(Copy, Clone, Debug, PartialEq)]
pub enum Answer {
    /// A sweep's checksum: equal, bit for bit.
    Sum(u64),
    /// A workload's float checksum: equal within a relative 1e-6 (each structure sums in its
    /// own order).
    Value(f64),
    /// A built mesh's vertices, edges and faces.
    Counts([usize; 3]),
    /// A changed mesh.
    Mesh(MeshChecksum),
    /// The probe's read, which answers nothing about the mesh: compared with nothing.
    Probe,
}

impl Answer {
    /// Whether two runs gave the same answer.
    pub fn agrees(&self, other: &Answer) -> bool {
        match (self, other) {
            (Answer::Value(a), Answer::Value(b)) => {
                (a - b).abs() <= 1e-6 * a.abs().max(b.abs()).max(1.0)
            }
            (Answer::Probe, _) | (_, Answer::Probe) => true,
            _ => self == other,
        }
    }
}

/// One timed run.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Run {
    /// Nanoseconds per item.
    pub ns: f64,
    /// What it answered.
    pub answer: Answer,
}

/// Runs `names.len()` contenders in turns: `warm_up` untimed rounds, then `rounds` timed ones,
/// each contender once per round in the order of `names` (`run(i)` runs contender `i` once).
/// Returns the ns of every timed run, by contender then round. Fails when a run fails or
/// answers differently from the first run (of any round, warm-up included), naming both.
pub fn take_turns(
    warm_up: usize,
    rounds: usize,
    names: &[&str],
    mut run: impl FnMut(usize) -> Result<Run, String>,
) -> Result<Vec<Vec<f64>>, String> {
    let mut ns = vec![Vec::with_capacity(rounds); names.len()];
    let mut first: Option<(&str, Answer)> = None;
    for round in 0..warm_up + rounds {
        for (i, &name) in names.iter().enumerate() {
            let got = run(i).map_err(|e| format!("{name}, round {}: {e}", round + 1))?;
            match first {
                None => first = Some((name, got.answer)),
                Some((who, answer)) if !answer.agrees(&got.answer) => {
                    return Err(format!(
                        "checksum mismatch in round {}: {name} answered {:?}, {who} answered {answer:?}",
                        round + 1,
                        got.answer
                    ))
                }
                Some(_) => {}
            }
            if round >= warm_up {
                ns[i].push(got.ns);
            }
        }
    }
    Ok(ns)
}

/// The median of per-round values, their spread and the interval of the median.
#[derive(Copy, Clone, Debug, PartialEq, serde::Serialize)]
pub struct Spread {
    /// The median.
    pub median: f64,
    /// The smallest.
    pub min: f64,
    /// The largest.
    pub max: f64,
    /// How many values.
    pub rounds: usize,
    /// The order-statistics interval of the median ([`Interval::of_median`]).
    pub low: f64,
    /// Its high end.
    pub high: f64,
    /// The probability that it holds the median.
    pub coverage: f64,
}

impl Spread {
    /// The spread of `values`; `None` when there is none or one is not a positive finite
    /// number (a run that took no time, or a limit of zero, makes no ratio).
    pub fn of(values: impl IntoIterator<Item = f64>) -> Option<Spread> {
        let mut v: Vec<f64> = values.into_iter().collect();
        if v.is_empty() || v.iter().any(|x| !x.is_finite() || *x <= 0.0) {
            return None;
        }
        v.sort_by(f64::total_cmp);
        let ci = Interval::of_median(&v)?;
        Some(Spread {
            median: median(&v),
            min: v[0],
            max: v[v.len() - 1],
            rounds: v.len(),
            low: ci.low,
            high: ci.high,
            coverage: ci.coverage,
        })
    }

    /// The per-round ratios `a[i] / b[i]` of two contenders' runs in the same rounds; `None`
    /// when their rounds do not match or a ratio cannot be made ([`Spread::of`]).
    pub fn of_ratios(a: &[f64], b: &[f64]) -> Option<Spread> {
        if a.len() != b.len() {
            return None;
        }
        Spread::of(a.iter().zip(b).map(|(x, y)| x / y))
    }
}

/// Times one run in the measuring thread's CPU time when the meter knows it
/// ([`MemoryMeter::thread_cpu_ns`]), else by the wall clock. On a machine with more runnable
/// processes than cores, a run of a few milliseconds is preempted for whole time slices, which
/// the wall clock counts and the thread's CPU time does not: the rounds of a target then
/// differ by what the structures did, not by when the scheduler took the core away.
pub struct Stopwatch<'a> {
    meter: &'a dyn MemoryMeter,
    cpu: Option<u64>,
    wall: Instant,
}

impl<'a> Stopwatch<'a> {
    /// Starts timing.
    pub fn start(meter: &'a dyn MemoryMeter) -> Self {
        Self {
            meter,
            cpu: meter.thread_cpu_ns(),
            wall: Instant::now(),
        }
    }

    /// Nanoseconds since the start.
    pub fn ns(&self) -> f64 {
        match (self.cpu, self.meter.thread_cpu_ns()) {
            (Some(a), Some(b)) => b.saturating_sub(a) as f64,
            _ => self.wall.elapsed().as_nanos() as f64,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sum(ns: f64, s: u64) -> Result<Run, String> {
        Ok(Run {
            ns,
            answer: Answer::Sum(s),
        })
    }

    #[test]
    fn the_median_of_the_round_ratios_and_their_spread() {
        // Round 2 is disturbed: both sides slow, their ratio stays.
        let a = [10.0, 40.0, 12.0, 11.0, 30.0];
        let b = [5.0, 20.0, 4.0, 5.5, 10.0];
        let s = Spread::of_ratios(&a, &b).unwrap();
        assert_eq!(
            (s.median, s.min, s.max, s.rounds, s.low, s.high),
            (2.0, 2.0, 3.0, 5, 2.0, 3.0)
        );
        assert!((s.coverage - 0.9375).abs() < 1e-12);
        let even = Spread::of([1.0, 4.0, 2.0, 3.0]).unwrap();
        assert_eq!((even.median, even.min, even.max), (2.5, 1.0, 4.0));
        // Rounds that do not match, nothing, or a zero time make no ratio.
        assert_eq!(Spread::of_ratios(&a, &b[..4]), None);
        assert_eq!(Spread::of([]), None);
        assert_eq!(Spread::of_ratios(&[1.0], &[0.0]), None);
    }

    #[test]
    fn turns_alternate_and_a_different_checksum_fails_loudly() {
        let mut order = Vec::new();
        let ns = take_turns(1, 3, &["a", "b"], |i| {
            order.push(i);
            sum(10.0 * (order.len()) as f64, 7)
        })
        .unwrap();
        assert_eq!(order, [0, 1, 0, 1, 0, 1, 0, 1]);
        // The warm-up round is not kept.
        assert_eq!(ns, vec![vec![30.0, 50.0, 70.0], vec![40.0, 60.0, 80.0]]);
        // b answers differently in its third run.
        let mut runs = 0;
        let err = take_turns(0, 3, &["a", "b"], |i| {
            runs += 1;
            sum(1.0, if i == 1 && runs == 6 { 8 } else { 7 })
        })
        .unwrap_err();
        assert!(
            err.contains("checksum mismatch in round 3") && err.contains("b answered Sum(8)"),
            "{err}"
        );
        // A failed run names its contender and round.
        let err = take_turns(0, 2, &["a", "b"], |i| {
            if i == 0 {
                sum(1.0, 7)
            } else {
                Err("native kernel failed".into())
            }
        })
        .unwrap_err();
        assert_eq!(err, "b, round 1: native kernel failed");
        // Floats agree within a relative 1e-6, not beyond.
        assert!(Answer::Value(1e6).agrees(&Answer::Value(1e6 + 0.5)));
        assert!(!Answer::Value(1e6).agrees(&Answer::Value(1e6 + 2.0)));
    }
}
