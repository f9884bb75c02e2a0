//! The memory estimates of `crate::limits` against the memory the commands really take: each
//! command runs in this process (whose global allocator counts bytes), once refused with no
//! memory available (the refusal states the estimate) and once for real (its peak measured).
//! An estimate must cover the peak, and not exceed it by more than [`SLACK`] times: a command
//! that grew its memory without its estimate following fails here.
//!
//! One test function: the allocator's counters and the environment are the process's.

use std::path::PathBuf;
use topolab::commands::{compare, explain, hull, info, refine, repair};
use topolab::input::Failure;
use topolab::limits::peak_of;

/// How far above the measured peak an estimate may be: it scales a small sample's peak,
/// fixed costs included, and counts what may be alive at once, among it the copy a growing
/// text's `realloc` may make, which the counting allocator does not see (it counts a
/// `realloc` as the old size replaced by the new: an `explain` of 100k faces came out at
/// 2.57 times the counted peak).
const SLACK: f64 = 3.0;

/// The estimate in a refusal "... needs about 12.3 MB of memory ...", in bytes.
fn estimate(refusal: &str) -> f64 {
    let after = refusal
        .split("needs about ")
        .nth(1)
        .unwrap_or_else(|| panic!("not a memory refusal: {refusal}"));
    let mut words = after.split_whitespace();
    let value: f64 = words.next().unwrap().parse().unwrap();
    let unit = match words.next().unwrap() {
        "bytes" => 1.0,
        "kB" => 1e3,
        "MB" => 1e6,
        "GB" => 1e9,
        other => panic!("unit {other}"),
    };
    value * unit
}

/// Runs `command` refused (no memory available) for its estimate, then for real for its peak;
/// checks the one against the other.
fn compare<T>(what: &str, command: impl Fn() -> Result<T, Failure>) {
    std::env::set_var("TOPOLAB_AVAILABLE_MEMORY", "0");
    let refusal = match command() {
        Ok(_) => panic!("{what}: not refused with no memory available"),
        Err(f) => f.message,
    };
    let estimated = estimate(&refusal);
    std::env::remove_var("TOPOLAB_AVAILABLE_MEMORY");
    let (ran, peak) = peak_of(&command);
    if let Err(f) = ran {
        panic!("{what}: {}", f.message);
    }
    let peak = peak as f64;
    println!(
        "{what}: estimate {:.1} MB, peak {:.1} MB ({:.2}x)",
        estimated / 1e6,
        peak / 1e6,
        estimated / peak
    );
    // The estimate is printed to 0.1 of its unit.
    assert!(
        estimated + 0.05e6 >= peak,
        "{what}: estimate {estimated} below the peak {peak}"
    );
    assert!(
        estimated <= SLACK * peak,
        "{what}: estimate {estimated} more than {SLACK} times the peak {peak}"
    );
}

#[test]
fn estimates_cover_the_peak_of_each_command_without_excess() {
    let dir = std::env::temp_dir().join(format!("topolab-estimates-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mesh = "torus:200000";
    for structure in [
        "index-half-edge",
        "pointer-half-edge",
        "che-l3",
        "winged-edge",
    ] {
        compare(&format!("info {mesh} --structure {structure}"), || {
            info::info(mesh, structure, false)
        });
    }
    compare("info quad-grid:200000", || {
        info::info("quad-grid:200000", "index-half-edge", false)
    });
    compare("explain index-half-edge --mesh grid:100000", || {
        explain::run("index-half-edge", Some("grid:100000"), None, None)
    });
    compare("explain che --mesh torus:100000", || {
        explain::run("che", Some("torus:100000"), None, None)
    });
    // A file: the estimate of reading it, then of the work on what it holds.
    let file = dir.join("torus.obj");
    topolab_structures::io::write(&file, &topolab_structures::meshes::from_spec(mesh).unwrap())
        .unwrap();
    let file_name = file.to_str().unwrap().to_string();
    compare("info FILE", || {
        info::info(&file_name, "index-half-edge", false)
    });
    let out: PathBuf = dir.join("out.off");
    // An input smaller than the sample mesh passes unmeasured: the refusal is the levels'.
    for order in ["input", "hilbert"] {
        compare(
            &format!("refine torus:3000 --levels 3 --order {order}"),
            || refine::refine("torus:3000", 3, "midpoint", order, &out),
        );
    }
    let args = repair::RepairArgs {
        file: mesh.into(),
        out: dir.join("repaired.obj"),
        skip: Vec::new(),
    };
    compare("repair torus:200000", || repair::repair_file(&args));
    // Two results.json of 40k cells each: read, compared, drawn.
    let runs = [dir.join("old.json"), dir.join("new.json")];
    for run in &runs {
        std::fs::write(run, topolab_harness::compare::sample_results(40_000)).unwrap();
    }
    let args = compare::CompareArgs {
        old: runs[0].clone(),
        new: runs[1].clone(),
        out: dir.join("compare"),
    };
    compare("compare OLD NEW (40k cells)", || compare::compare(&args));
    for (shape, algo, n) in [
        ("ball", "randomized", 200_000),
        ("sphere", "randomized", 50_000),
        ("cube", "incremental", 5_000),
    ] {
        let args = hull::HullArgs {
            file: None,
            random: Some(n),
            shape: shape.into(),
            algo: algo.into(),
            out: Some(dir.join("hull.obj")),
            seed: 1,
        };
        compare(
            &format!("hull --random {n} --shape {shape} --algo {algo}"),
            || hull::hull(&args),
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
