//! The machine's physical limits, measured in the same run as the kernels: sequential read
//! bandwidth and the latency of a dependent random access (a pointer chase), over the memory
//! (the arrays of `--probe-mb`) and over working sets that fit each cache level.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::time::Instant;

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
    /// Nanoseconds per checksum term ([`crate::checksum::mix`] and the sum) of answers read
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
}

impl Probe {
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
/// both over half of each data cache of [`crate::machine::data_caches`] (for a cache level
/// at least as large as the memory arrays, the memory level alone speaks for it).
pub fn measure(read_mb: usize, chase_mb: usize) -> Probe {
    let read_array_bytes = read_mb << 20;
    let chase_array_bytes = chase_mb << 20;
    let read_bytes_per_s = read_bandwidth(read_array_bytes);
    let chase_ns_per_hop = load_latency(chase_array_bytes);
    let mut levels: Vec<Level> = crate::machine::data_caches()
        .into_iter()
        .map(|(level, size)| (format!("L{level}"), size / 2))
        .filter(|&(_, bytes)| bytes < read_array_bytes.min(chase_array_bytes))
        .map(|(name, bytes)| Level {
            name,
            bytes,
            read_bytes_per_s: read_bandwidth(bytes),
            load_ns: load_latency(bytes),
        })
        .collect();
    levels.push(Level {
        name: "memory".into(),
        bytes: read_array_bytes.max(chase_array_bytes),
        read_bytes_per_s,
        load_ns: chase_ns_per_hop,
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

/// The smallest of `runs` results of `run`: on a shared machine the fastest run is the one the
/// other processes disturbed least, so every probe is many short runs.
fn fastest(runs: usize, mut run: impl FnMut() -> f64) -> f64 {
    (0..runs).map(|_| run()).fold(f64::INFINITY, f64::min)
}

/// Nanoseconds per checksum term over 4096 answers in L1, fastest of 31 runs of 64k terms.
fn checksum_term_ns() -> f64 {
    let answers: Vec<u32> = (0..4096u32).map(|i| i.wrapping_mul(0x9E37_79B9)).collect();
    let passes = 16;
    fastest(31, || {
        let t = Instant::now();
        let mut sum = 0u64;
        for _ in 0..passes {
            for (i, &w) in std::hint::black_box(&answers).iter().enumerate() {
                sum = sum.wrapping_add(crate::checksum::mix(i as u64, w as u64));
            }
        }
        std::hint::black_box(sum);
        t.elapsed().as_nanos() as f64 / (passes * answers.len()) as f64
    })
}

/// Bytes per second of a sequential read of `bytes` (rounded down to 32 bytes): the fastest of
/// three reads of a memory-sized array, or of fifteen runs of at least 4 MiB of reads of a
/// cache-sized one (read many times over).
fn read_bandwidth(bytes: usize) -> f64 {
    let words = (bytes / 8).max(4);
    let data: Vec<u64> = (0..words as u64).collect();
    let passes = ((4usize << 20) / (words * 8)).max(1);
    let runs = if bytes >= 64 << 20 { 3 } else { 15 };
    let best = fastest(runs, || {
        let t = Instant::now();
        // Four independent sums so the adds are not the bottleneck.
        let mut s = [0u64; 4];
        for _ in 0..passes {
            for c in std::hint::black_box(&data).chunks_exact(4) {
                s[0] = s[0].wrapping_add(c[0]);
                s[1] = s[1].wrapping_add(c[1]);
                s[2] = s[2].wrapping_add(c[2]);
                s[3] = s[3].wrapping_add(c[3]);
            }
        }
        std::hint::black_box(s);
        t.elapsed().as_secs_f64()
    });
    (passes * words * 8) as f64 / best
}

/// Nanoseconds per hop of a random cycle through `bytes` of `u32` indices, fastest of nine runs
/// of 64k to 128k hops: each load's address is the value of the one before, so nothing
/// overlaps.
fn load_latency(bytes: usize) -> f64 {
    let n = (bytes / 4).max(2);
    // Sattolo's algorithm: one cycle through every slot.
    let mut next: Vec<u32> = (0..n as u32).collect();
    let mut rng = ChaCha8Rng::seed_from_u64(42);
    for i in (1..n).rev() {
        let j = rng.random_range(0..i);
        next.swap(i, j);
    }
    // Round the cycle untimed, so the timed hops find the working set where it lives.
    let mut at = 0u32;
    for _ in 0..n.min(1 << 20) {
        at = next[at as usize];
    }
    let hops = (2 * n).clamp(1 << 16, 1 << 17);
    let best = fastest(9, || {
        let t = Instant::now();
        for _ in 0..hops {
            at = next[at as usize];
        }
        t.elapsed().as_nanos() as f64 / hops as f64
    });
    std::hint::black_box(at);
    best
}

#[cfg(test)]
mod tests {
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
        // A working set goes to the smallest level that holds it, the memory beyond.
        assert_eq!(p.level_for(1.0), p.levels.first());
        assert_eq!(p.level_for(1e15), Some(last));
        assert_eq!(p.level_for((8 << 20) as f64), Some(last));
    }
}
