//! `topolab scale`: each structure climbs the ladder of tori in processes of its own until the
//! memory would not hold the next size, which it shows refused with its estimate; every
//! kernel's result agrees across structures; the `.che` part sweeps a file whose answers are
//! the in-memory CHE's. The memory is made small with `TOPOLAB_AVAILABLE_MEMORY` so the
//! refusal comes at a small size (and the probe with the hidden `--probe-mb 1`).

mod common;

use common::run::{scratch, text};
use serde_json::Value;
use std::process::Command;

/// Runs `topolab scale` with `available` bytes of memory; returns its results.json.
fn scale(dir: &std::path::Path, available: u64, args: &[&str]) -> Value {
    let out = Command::new(env!("CARGO_BIN_EXE_topolab"))
        .env("TOPOLAB_AVAILABLE_MEMORY", available.to_string())
        .args(["scale", "--probe-mb", "1", "--out"])
        .arg(dir)
        .args(args)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", text(&out.stderr));
    let json = std::fs::read_to_string(dir.join("results.json")).unwrap();
    let html = std::fs::read_to_string(dir.join("index.html")).unwrap();
    assert!(html.contains("Which structure fits my mesh"));
    serde_json::from_str(&json).unwrap()
}

fn cells<'a>(r: &'a Value, structure: &str) -> Vec<&'a Value> {
    r["scale"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| c["structure"] == structure)
        .collect()
}

#[test]
fn each_structure_climbs_until_the_memory_refuses_and_every_result_agrees() {
    let dir = scratch("scale-climb");
    let available = 50_000_000;
    let structures = ["vertex-list", "index-half-edge", "che-l2"];
    let r = scale(
        &dir,
        available,
        &[
            "--structures",
            &structures.join(","),
            "--max-triangles",
            "1000000",
            "--mapped-triangles",
            "0",
        ],
    );
    assert_eq!(r["format"], "topolab-scale/1");
    assert_eq!(r["notes"].as_array().unwrap().len(), 0, "{}", r["notes"]);
    let mut refused = 0;
    for s in structures {
        let cells = cells(&r, s);
        let (last, measured) = cells.split_last().unwrap();
        // Measured from the smallest size up, then refused: never run past the memory.
        assert!(measured.len() >= 4, "{s}: {cells:?}");
        for c in measured {
            assert_eq!(c["outcome"], "measured", "{s}: {c}");
            let faces = c["faces"].as_u64().unwrap();
            let asked = c["triangles"].as_u64().unwrap();
            assert!(
                faces.abs_diff(asked) * 50 < asked,
                "{s}: {faces} for {asked}"
            );
            assert!(c["peak_bytes"].as_u64().unwrap() >= c["start_bytes"].as_u64().unwrap());
            assert!(c["resident_bytes"].as_u64().unwrap() > 0, "{s}: {c}");
            assert!(c["construction_ns_per_face"].as_f64().unwrap() > 0.0);
        }
        match last["outcome"].as_str().unwrap() {
            "refused" => {
                refused += 1;
                assert_eq!(last["available_bytes"], available);
                assert!(last["estimate_bytes"].as_u64().unwrap() > available);
            }
            "measured" => assert_eq!(last["triangles"], 1_000_000, "{s}"),
            other => panic!("{s}: {other}: {last}"),
        }
    }
    assert!(refused > 0, "nothing refused at 1M triangles in 50 MB");
    // The scanning vertex list has no R00 sweep and no smoothing; the local ones have both,
    // and every result at a size is the same.
    for c in cells(&r, "vertex-list") {
        if c["outcome"] == "measured" {
            assert!(c["r00_sweep"].is_null() && c["smoothing"].is_null());
        }
    }
    for size in [1_000u64, 16_000, 64_000] {
        let at: Vec<&Value> = r["scale"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["triangles"] == size && c["outcome"] == "measured")
            .collect();
        assert_eq!(at.len(), 3, "{size}");
        let sampled: Vec<&Value> = at.iter().map(|c| &c["r00_sampled"]["check"]).collect();
        assert!(sampled.windows(2).all(|w| w[0] == w[1]), "{sampled:?}");
        let swept: Vec<&Value> = at
            .iter()
            .filter(|c| !c["r00_sweep"].is_null())
            .map(|c| &c["r00_sweep"]["check"])
            .collect();
        assert_eq!(swept.len(), 2);
        assert_eq!(swept[0], swept[1]);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_che_file_answers_as_the_in_memory_che_and_opens_in_milliseconds() {
    let dir = scratch("scale-mapped");
    let r = scale(
        &dir,
        u64::MAX / 2,
        &[
            "--structures",
            "che-l2",
            "--max-triangles",
            "16000",
            "--mapped-triangles",
            "16000",
            "--scratch",
            dir.to_str().unwrap(),
        ],
    );
    let runs = r["mapped"].as_array().unwrap();
    assert_eq!(runs.len(), 1, "{}", r["notes"]);
    let run = &runs[0];
    let in_memory = &run["in_memory_check"];
    assert!(!in_memory.is_null());
    assert_eq!(&run["first_sweep"]["check"], in_memory);
    assert_eq!(&run["later_sweeps"]["check"], in_memory);
    // Two more fills of the page cache, each swept to the same answer.
    let refills = run["refills"].as_array().unwrap();
    assert_eq!(refills.len(), 2);
    assert!(
        refills.iter().all(|t| &t["check"] == in_memory),
        "{refills:?}"
    );
    assert_eq!(run["open_ms"].as_array().unwrap().len(), 3);
    assert!(run["file_bytes"].as_u64().unwrap() > 16_000 * 40);
    // A file this small is not swept beyond memory, and the run says why.
    let notes = r["notes"].to_string();
    assert!(notes.contains("not swept beyond memory"), "{notes}");
    // The scratch file is gone.
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .filter(|n| n.to_string_lossy().ends_with(".che"))
        .collect();
    assert!(left.is_empty(), "{left:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn past_the_ids_limit_the_run_is_refused_in_one_line_before_any_work() {
    let dir = scratch("scale-ids");
    let out = common::run::topolab(&[
        "scale",
        "--max-triangles",
        "1500000000",
        "--out",
        dir.join("out").to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = text(&out.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("1.43 billion triangles"), "{err}");
    assert!(!dir.join("out").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}
