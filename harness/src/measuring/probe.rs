//! The machine's physical limits, measured in the same run as the kernels: sequential read
//! bandwidth and the latency of a dependent random access (a pointer chase, and the same chase
//! with each kind of chain step's arithmetic, [`Step`]), over the memory (the arrays of
//! `--probe-mb`) and over working sets that fit each cache level. The workers ([`Reader`],
//! [`Chase`], [`Terms`]) also take turns with the sweeps of the Targets table, so a limit
//! there follows the machine from round to round.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::time::Instant;
use topolab_structures::Step;

/// What the probe measured.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Probe {
    /// Sequential read bandwidth, bytes per second (best of the runs).
    pub read_bytes_per_s: f64,
    /// Size of the array read, bytes.
    pub read_array_bytes: usize,
    /// Nanoseconds per hop of a dependent random walk over `chase_array_bytes`.
    pub chase_ns_per_hop: f64,
    /// Size of the chased array, bytes.
    pub chase_array_bytes: usize,
    /// Bandwidth and load latency by working-set size, smallest first: half of each data
    /// cache the machine reports (L1, L2, L3), then the memory (the arrays above).
    pub levels: Vec<Level>,
    /// Nanoseconds per checksum term ([`crate::measuring::checksum::mix`] and the sum) of answers read
    /// from L1: the work a sweep does per answer whatever the structure (best of 3).
    pub checksum_ns: f64,
}

/// One level of the memory hierarchy, as the probe measured it.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Level {
    /// `L1`, `L2`, `L3` or `memory`.
    pub name: String,
    /// The working set measured, bytes.
    pub bytes: usize,
    /// Sequential read bandwidth over it, bytes per second.
    pub read_bytes_per_s: f64,
    /// Latency of one dependent load (a hop of a random cycle through it), ns.
    pub load_ns: f64,
    /// Latency of one chain step of each kind of [`Step::ALL`] (the same cycle, each hop's
    /// address computed by the step's work): [`Level::step_ns`].
    pub step_ns: Vec<(Step, f64)>,
}

impl Level {
    /// A level of `bytes` read at `gb` GB/s whose loads take `load_ns`, a twin step 1.25 times
    /// as long and a CHE corner step twice: the machines of the tests.
    #[cfg(test)]
    pub(crate) fn for_tests(name: &str, bytes: usize, gb: f64, load_ns: f64) -> Self {
        Self {
            name: name.into(),
            bytes,
            read_bytes_per_s: gb * 1e9,
            load_ns,
            step_ns: vec![
                (Step::Load, load_ns),
                (Step::Twin, 1.25 * load_ns),
                (Step::Corner, 2.0 * load_ns),
            ],
        }
    }

    /// The latency of one chain step doing `step`'s work, ns (a plain load's for a kind not
    /// measured).
    pub fn step_ns(&self, step: Step) -> f64 {
        self.step_ns
            .iter()
            .find(|(s, _)| *s == step)
            .map_or(self.load_ns, |&(_, ns)| ns)
    }
}

impl Probe {
    /// The level called `name` (`L1`, `L2`, `L3`, `memory`), if the probe measured it.
    pub fn level(&self, name: &str) -> Option<&Level> {
        self.levels.iter().find(|l| l.name == name)
    }

    /// The level that holds a working set of `bytes`: the smallest one at least that large,
    /// the largest one (memory) beyond. `None` only for a probe without levels.
    pub fn level_for(&self, bytes: f64) -> Option<&Level> {
        self.levels
            .iter()
            .find(|l| l.bytes as f64 >= bytes)
            .or(self.levels.last())
    }
}

/// Measures bandwidth over `read_mb` MiB (best of 3) and latency over `chase_mb` MiB, and
/// both over half of each data cache of [`crate::measuring::machine::data_caches`] (for a cache level
/// at least as large as the memory arrays, the memory level alone speaks for it).
pub fn measure(read_mb: usize, chase_mb: usize) -> Probe {
    let read_array_bytes = read_mb << 20;
    let chase_array_bytes = chase_mb << 20;
    let read_bytes_per_s = read_bandwidth(read_array_bytes);
    let memory_steps = chase_latencies(chase_array_bytes);
    let chase_ns_per_hop = memory_steps[0].1;
    let mut levels: Vec<Level> = crate::measuring::machine::data_caches()
        .into_iter()
        .map(|(level, size)| (format!("L{level}"), size / 2))
        .filter(|&(_, bytes)| bytes < read_array_bytes.min(chase_array_bytes))
        .map(|(name, bytes)| {
            let step_ns = chase_latencies(bytes);
            Level {
                name,
                bytes,
                read_bytes_per_s: read_bandwidth(bytes),
                load_ns: step_ns[0].1,
                step_ns,
            }
        })
        .collect();
    levels.push(Level {
        name: "memory".into(),
        bytes: read_array_bytes.max(chase_array_bytes),
        read_bytes_per_s,
        load_ns: chase_ns_per_hop,
        step_ns: memory_steps,
    });
    Probe {
        read_bytes_per_s,
        read_array_bytes,
        chase_ns_per_hop,
        chase_array_bytes,
        levels,
        checksum_ns: checksum_term_ns(),
    }
}

/// The same small measurement repeated before every mesh of a report, so the page can show how
/// the machine itself moved over the run (its frequency, its neighbours, its memory): a
/// sequential read and a dependent chase through [`DRIFT_BYTES`] (beyond the caches of most
/// machines) and the checksum arithmetic in L1, each the median of [`DRIFT_RUNS`] runs. Nothing
/// of a structure is in it, so its changes are the machine's.
pub struct Drift {
    reader: Reader,
    cycle: Cycle,
    terms: Terms,
}

/// The working set of the drift probe's read and chase.
pub const DRIFT_BYTES: usize = 64 << 20;

/// Runs of each of the drift probe's measurements.
pub const DRIFT_RUNS: usize = 5;

/// One reading of the drift probe.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct DriftPoint {
    /// The mesh measured after it.
    pub mesh: String,
    /// Seconds since the run started.
    pub at_s: f64,
    /// Sequential read of [`DRIFT_BYTES`], bytes per second.
    pub read_bytes_per_s: f64,
    /// Dependent load through [`DRIFT_BYTES`], ns per hop.
    pub load_ns: f64,
    /// Checksum arithmetic in L1, ns per term.
    pub term_ns: f64,
}

impl Drift {
    /// The probe's arrays, made once.
    pub fn new() -> Self {
        Self {
            reader: Reader::reading(DRIFT_BYTES, DRIFT_BYTES),
            cycle: Cycle::new(DRIFT_BYTES),
            terms: Terms::new(),
        }
    }

    /// One reading before `mesh`, `at_s` seconds into the run.
    pub fn read(&self, mesh: &str, at_s: f64) -> DriftPoint {
        let median_ns = |work: &mut dyn FnMut() -> usize| {
            let mut v: Vec<f64> = (0..DRIFT_RUNS)
                .map(|_| {
                    let t = Instant::now();
                    let units = work();
                    t.elapsed().as_nanos() as f64 / units.max(1) as f64
                })
                .collect();
            v.sort_by(f64::total_cmp);
            crate::measuring::timing::median(&v)
        };
        let mut chase = Chase::through(&self.cycle, Step::Load).hopping(1 << 16);
        DriftPoint {
            mesh: mesh.into(),
            at_s,
            read_bytes_per_s: 1e9 / median_ns(&mut || self.reader.run()),
            load_ns: median_ns(&mut || chase.run()),
            term_ns: median_ns(&mut || self.terms.run()),
        }
    }
}

impl Default for Drift {
    fn default() -> Self {
        Self::new()
    }
}

/// The smallest of `runs` results of `run`: on a shared machine the fastest run is the one the
/// other processes disturbed least, so every probe is many short runs.
fn fastest(runs: usize, mut run: impl FnMut() -> f64) -> f64 {
    (0..runs).map(|_| run()).fold(f64::INFINITY, f64::min)
}

/// Nanoseconds per unit of the fastest of `runs` runs of `work`, which returns the units it did.
fn fastest_ns(runs: usize, mut work: impl FnMut() -> usize) -> f64 {
    fastest(runs, || {
        let t = Instant::now();
        let units = work();
        t.elapsed().as_nanos() as f64 / units.max(1) as f64
    })
}

/// Nanoseconds per checksum term over 4096 answers in L1, fastest of 31 runs of 64k terms.
fn checksum_term_ns() -> f64 {
    let terms = Terms::new();
    fastest_ns(31, || terms.run())
}

/// Bytes per second of a sequential read of `bytes` (rounded down to 32 bytes): the fastest of
/// three reads of a memory-sized array, or of fifteen runs of at least 4 MiB of reads of a
/// cache-sized one (read many times over).
fn read_bandwidth(bytes: usize) -> f64 {
    let reader = Reader::new(bytes);
    let runs = if bytes >= 64 << 20 { 3 } else { 15 };
    1e9 / fastest_ns(runs, || reader.run())
}

/// Nanoseconds per hop of a chase through `bytes` for every kind of step, [`Step::ALL`]'s
/// order (the plain load first), each the fastest of nine runs of 64k to 128k hops.
fn chase_latencies(bytes: usize) -> Vec<(Step, f64)> {
    let cycle = Cycle::new(bytes);
    Step::ALL
        .into_iter()
        .map(|step| {
            let mut chase = Chase::through(&cycle, step);
            (step, fastest_ns(9, || chase.run()))
        })
        .collect()
}

/// The checksum's work per answer, as a sweep does it ([`crate::measuring::checksum::mix`] and the sum)
/// over 4096 answers in L1, 16 passes a run: the probe's `checksum_ns`, and the Targets' turn
/// that measures it again in every round.
pub struct Terms {
    answers: Vec<u32>,
    passes: usize,
}

impl Terms {
    /// The answers, 4096 of them, 16 passes a run.
    pub fn new() -> Self {
        Self::with_passes(16)
    }

    /// The same answers, `passes` passes a run (a longer run for a turn beside a sweep).
    pub fn with_passes(passes: usize) -> Self {
        Self {
            answers: (0..4096u32).map(|i| i.wrapping_mul(0x9E37_79B9)).collect(),
            passes: passes.max(1),
        }
    }

    /// One run: the terms it computed.
    pub fn run(&self) -> usize {
        let mut sum = 0u64;
        for _ in 0..self.passes {
            for (i, &w) in std::hint::black_box(&self.answers).iter().enumerate() {
                sum = sum.wrapping_add(crate::measuring::checksum::mix(i as u64, w as u64));
            }
        }
        std::hint::black_box(sum);
        self.passes * self.answers.len()
    }
}

impl Default for Terms {
    fn default() -> Self {
        Self::new()
    }
}

/// A sequential read of a working set: four independent sums over `u64` words (so the adds are
/// not the bottleneck), the set read over and over for at least 4 MiB. The probe's bandwidth,
/// and the Targets' turn that measures it again in every round.
pub struct Reader {
    data: Vec<u64>,
    passes: usize,
}

impl Reader {
    /// A reader of `bytes` (rounded down to 32, at least 32), at least 4 MiB a run.
    pub fn new(bytes: usize) -> Self {
        Self::reading(bytes, 4 << 20)
    }

    /// A reader of `bytes` that reads at least `per_run` bytes a run (a longer run for a turn
    /// beside a sweep).
    pub fn reading(bytes: usize, per_run: usize) -> Self {
        let words = (bytes / 8).max(4);
        Self {
            data: (0..words as u64).collect(),
            passes: (per_run / (words * 8)).max(1),
        }
    }

    /// One run: the bytes it read.
    pub fn run(&self) -> usize {
        let mut s = [0u64; 4];
        for _ in 0..self.passes {
            for c in std::hint::black_box(&self.data).chunks_exact(4) {
                s[0] = s[0].wrapping_add(c[0]);
                s[1] = s[1].wrapping_add(c[1]);
                s[2] = s[2].wrapping_add(c[2]);
                s[3] = s[3].wrapping_add(c[3]);
            }
        }
        std::hint::black_box(s);
        self.passes * self.data.len() * 8
    }
}

/// A dependent random walk through `bytes` of `u32` indices: one cycle through every slot
/// ([`Cycle`]), each load's address computed from the value of the one before by
/// `step`'s work ([`Step::address`], the structures' own arithmetic), so nothing overlaps. The
/// probe's load latency (a plain load) and the latency of a chain step of each kind, and the
/// Targets' turns that measure them again in every round.
pub struct Chase {
    /// `slots[step.address(c)]` is the slot after `c` on the cycle.
    slots: Vec<u32>,
    step: Step,
    at: u32,
    hops: usize,
}

/// A random cycle through the `u32` slots of a working set, in as many slots as every kind of
/// [`Step`] needs to be a bijection on them (a multiple of six): what a [`Chase`] walks.
pub struct Cycle {
    /// `next[c]` is the slot after `c`.
    next: Vec<u32>,
}

impl Cycle {
    /// A cycle through `bytes` (rounded down to 24 bytes, at least 24), by Sattolo's algorithm
    /// with a fixed seed.
    pub fn new(bytes: usize) -> Self {
        let n = (bytes / 4 / 6).max(1) * 6;
        let mut next: Vec<u32> = (0..n as u32).collect();
        let mut rng = ChaCha8Rng::seed_from_u64(42);
        for i in (1..n).rev() {
            let j = rng.random_range(0..i);
            next.swap(i, j);
        }
        Self { next }
    }

    /// Its slots.
    pub fn len(&self) -> usize {
        self.next.len()
    }

    /// Whether it has none (never: at least six).
    pub fn is_empty(&self) -> bool {
        self.next.is_empty()
    }
}

impl Chase {
    /// The chase of `cycle` whose steps do `step`'s work, 64k to 128k hops a run, walked once
    /// round untimed (at most 2^20 hops) so the timed hops find it where it lives.
    pub fn through(cycle: &Cycle, step: Step) -> Self {
        let n = cycle.len();
        let mut slots = vec![0u32; n];
        for (c, &after) in cycle.next.iter().enumerate() {
            slots[step.address(c as u32) as usize] = after;
        }
        let mut chase = Self {
            slots,
            step,
            at: 0,
            hops: (2 * n).clamp(1 << 16, 1 << 17),
        };
        chase.walk(n.min(1 << 20));
        chase
    }

    /// The same chase, `hops` hops a run (a longer run for a turn beside a sweep).
    pub fn hopping(self, hops: usize) -> Self {
        Self {
            hops: hops.max(1),
            ..self
        }
    }

    /// One run: the hops it made.
    pub fn run(&mut self) -> usize {
        self.walk(self.hops);
        self.hops
    }

    /// `hops` steps from where the last run stopped.
    fn walk(&mut self, hops: usize) {
        // One loop per kind, so the step's work is all that differs between them.
        self.at = match self.step {
            Step::Load => hop(&self.slots, self.at, hops, |h| Step::Load.address(h)),
            Step::Twin => hop(&self.slots, self.at, hops, |h| Step::Twin.address(h)),
            Step::Corner => hop(&self.slots, self.at, hops, |h| Step::Corner.address(h)),
        };
    }
}

/// `hops` steps of `at ← slots[address(at)]`.
#[inline(always)]
fn hop(slots: &[u32], mut at: u32, hops: usize, address: impl Fn(u32) -> u32) -> u32 {
    for _ in 0..hops {
        at = slots[address(at) as usize];
    }
    std::hint::black_box(at)
}

#[cfg(test)]
mod tests {
    use topolab_structures::Step;

    #[test]
    fn a_small_probe_gives_positive_numbers_by_level() {
        let p = super::measure(8, 8);
        assert!(p.read_bytes_per_s > 1e8, "{p:?}");
        assert!(p.chase_ns_per_hop > 0.0);
        let last = p.levels.last().expect("the memory level");
        assert_eq!((last.name.as_str(), last.bytes), ("memory", 8 << 20));
        for w in p.levels.windows(2) {
            assert!(w[0].bytes < w[1].bytes, "{p:?}");
        }
        for l in &p.levels {
            assert!(l.read_bytes_per_s > 1e8 && l.load_ns > 0.0, "{l:?}");
        }
        assert!(p.checksum_ns > 0.0 && p.checksum_ns < 1e3, "{p:?}");
        // Every level times every kind of chain step, a plain load as its load latency.
        for l in &p.levels {
            let kinds: Vec<Step> = l.step_ns.iter().map(|s| s.0).collect();
            assert_eq!(kinds, Step::ALL, "{l:?}");
            assert!(l.step_ns.iter().all(|s| s.1 > 0.0 && s.1.is_finite()));
        }
        // A working set goes to the smallest level that holds it, the memory beyond.
        assert_eq!(p.level_for(1.0), p.levels.first());
        assert_eq!(p.level_for(1e15), Some(last));
        assert_eq!(p.level_for((8 << 20) as f64), Some(last));
    }

    /// Every kind of step walks one cycle through every slot, as a run walks it: the chase's
    /// loads are all dependent and its working set is the one asked for.
    #[test]
    fn each_chase_is_one_cycle_through_every_slot() {
        for bytes in [0, 24, 100, 6000] {
            let cycle = super::Cycle::new(bytes);
            let n = cycle.len();
            assert!(n >= 6 && n.is_multiple_of(6), "{n}");
            for step in Step::ALL {
                let mut chase = super::Chase::through(&cycle, step).hopping(1);
                // Where the untimed round left it.
                let start = chase.at;
                let mut seen = vec![false; n];
                for _ in 0..n {
                    assert!(
                        !seen[chase.at as usize],
                        "{step:?} revisits {} early",
                        chase.at
                    );
                    seen[chase.at as usize] = true;
                    assert_eq!(chase.run(), 1);
                }
                assert_eq!(
                    chase.at, start,
                    "{step:?}: back at the start after every slot"
                );
                assert!(seen.iter().all(|&s| s));
            }
        }
    }
}
