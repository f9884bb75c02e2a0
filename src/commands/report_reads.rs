//! The report's counting run: reads per query of every operator on every structure of the
//! report at its sizes ([`topolab_harness::reads::count`]), in the counting build of the
//! structures, after the timed runs (nothing timed runs while it counts).

use std::time::Instant;
use topolab_harness::reads::count::{count_all, Budget, ReadsRow};

/// Counts the reads of `names` (the C++ baselines and structures outside the lab are left
/// out: their reads are not the lab's to count) on the generated meshes of `sizes`, and notes
/// how long it took.
pub fn count(names: &[String], sizes: &[usize], notes: &mut Vec<String>) -> Vec<ReadsRow> {
    eprintln!("topolab report: counting reads per query...");
    let start = Instant::now();
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    let rows = count_all(&names, sizes, Budget::default());
    let skipped = rows.iter().filter(|r| !r.skipped.is_empty()).count();
    notes.push(format!(
        "Reads per query were counted in {:.1} s ({} rows; {skipped} stop before the largest size, whose reads the declared cost puts above {:.0e} per cell).",
        start.elapsed().as_secs_f64(),
        rows.len(),
        Budget::default().reads_per_cell
    ));
    rows
}
