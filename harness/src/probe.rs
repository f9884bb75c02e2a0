//! The machine's physical limits, measured in the same run as the kernels: sequential read
//! bandwidth and the latency of a dependent random access (a pointer chase).

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::time::Instant;

/// What the probe measured.
#[derive(Copy, Clone, Debug, serde::Serialize)]
pub struct Probe {
    /// Sequential read bandwidth, bytes per second (best of the runs).
    pub read_bytes_per_s: f64,
    /// Size of the array read, bytes.
    pub read_array_bytes: usize,
    /// Nanoseconds per hop of a dependent random walk over `chase_array_bytes`.
    pub chase_ns_per_hop: f64,
    /// Size of the chased array, bytes.
    pub chase_array_bytes: usize,
}

/// Measures bandwidth over `read_mb` MiB (best of 3) and latency over `chase_mb` MiB.
pub fn measure(read_mb: usize, chase_mb: usize) -> Probe {
    let words = read_mb * (1 << 20) / 8;
    let data: Vec<u64> = (0..words as u64).collect();
    let mut best = f64::INFINITY;
    for _ in 0..3 {
        let t = Instant::now();
        // Four independent sums so the adds are not the bottleneck.
        let mut s = [0u64; 4];
        for c in data.chunks_exact(4) {
            s[0] = s[0].wrapping_add(c[0]);
            s[1] = s[1].wrapping_add(c[1]);
            s[2] = s[2].wrapping_add(c[2]);
            s[3] = s[3].wrapping_add(c[3]);
        }
        std::hint::black_box(s);
        best = best.min(t.elapsed().as_secs_f64());
    }
    drop(data);
    let n = chase_mb * (1 << 20) / 4;
    // Sattolo's algorithm: one cycle through every slot.
    let mut next: Vec<u32> = (0..n as u32).collect();
    let mut rng = ChaCha8Rng::seed_from_u64(42);
    for i in (1..n).rev() {
        let j = rng.random_range(0..i);
        next.swap(i, j);
    }
    let hops = 2_000_000usize.min(n * 4);
    let t = Instant::now();
    let mut at = 0u32;
    for _ in 0..hops {
        at = next[at as usize];
    }
    std::hint::black_box(at);
    let chase = t.elapsed().as_nanos() as f64 / hops as f64;
    Probe {
        read_bytes_per_s: (words * 8) as f64 / best,
        read_array_bytes: words * 8,
        chase_ns_per_hop: chase,
        chase_array_bytes: n * 4,
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_small_probe_gives_positive_numbers() {
        let p = super::measure(8, 8);
        assert!(p.read_bytes_per_s > 1e8, "{p:?}");
        assert!(p.chase_ns_per_hop > 0.0);
    }
}
