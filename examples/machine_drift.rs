//! How the machine itself moves while nothing of the lab runs: the report's drift probe
//! (`topolab_harness::measuring::probe::Drift`: a sequential read and a dependent chase through 64 MiB,
//! the checksum arithmetic in L1) read again and again, one line a reading, with the spread
//! of each over the readings at the end.
//!
//! ```sh
//! cargo run --release --example machine_drift              # 60 readings, 2 s apart
//! cargo run --release --example machine_drift -- 180 1     # READINGS, SECONDS apart
//! ```

use std::time::{Duration, Instant};
use topolab_harness::measuring::probe::Drift;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let readings: usize = args.first().map_or(60, |a| a.parse().expect("READINGS"));
    let apart: f64 = args.get(1).map_or(2.0, |a| a.parse().expect("SECONDS"));
    let drift = Drift::new();
    let start = Instant::now();
    let mut all = Vec::new();
    println!(
        "{:>8} {:>12} {:>10} {:>10}",
        "s", "read GB/s", "load ns", "term ns"
    );
    for _ in 0..readings {
        let d = drift.read("idle", start.elapsed().as_secs_f64());
        println!(
            "{:>8.1} {:>12.2} {:>10.1} {:>10.3}",
            d.at_s,
            d.read_bytes_per_s / 1e9,
            d.load_ns,
            d.term_ns
        );
        all.push(d);
        std::thread::sleep(Duration::from_secs_f64(apart));
    }
    let spread = |name: &str, v: Vec<f64>| {
        let (lo, hi) = v
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
        println!(
            "{name}: {lo:.3} to {hi:.3} ({:.0}% apart)",
            100.0 * (hi / lo - 1.0)
        );
    };
    spread(
        "read GB/s",
        all.iter().map(|d| d.read_bytes_per_s / 1e9).collect(),
    );
    spread("load ns", all.iter().map(|d| d.load_ns).collect());
    spread("term ns", all.iter().map(|d| d.term_ns).collect());
}
