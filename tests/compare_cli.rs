//! `topolab compare` and `topolab report --sections` as the binary: a focused report shows and
//! measures only its sections and writes a format version; two runs compare with exit code 0
//! whatever changed; what is not a topolab results.json, or is of a newer format, is refused in
//! one line with exit code 2; an unknown section lists the known.

mod common;

use common::run::{scratch, text, topolab};
use serde_json::{json, Value};
use std::path::Path;
use topolab_harness::results::FORMAT_VERSION;

fn json_of(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// A small report of `sections` into `dir`.
fn report(dir: &Path, sections: &str) -> Value {
    let run = topolab(&[
        "report",
        "--quick",
        "--sizes",
        "300,1200",
        "--meshes",
        "torus,grid",
        "--structures",
        "index-half-edge,che-l2",
        "--probe-mb",
        "4",
        "--sections",
        sections,
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(run.status.success(), "{}", text(&run.stderr));
    json_of(&dir.join("results.json"))
}

#[test]
fn a_focused_report_measures_and_shows_only_its_sections() {
    let dir = scratch("compare-sections");
    let v = report(&dir, "memory,construction");
    assert_eq!(v["format_version"], FORMAT_VERSION);
    assert_eq!(v["settings"]["sections"], json!(["memory", "construction"]));
    let ms = v["measurements"].as_array().unwrap();
    assert!(!ms.is_empty());
    // Construction and the 1-ring sweep only: what those sections are drawn from.
    for m in ms {
        let what = (
            m["operator"].as_str().unwrap(),
            m["kernel"].as_str().unwrap(),
        );
        assert!(
            what == ("construction", "construction") || what == ("r00", "sweep"),
            "{what:?}"
        );
    }
    assert!(v["hull"].as_array().unwrap().is_empty());
    assert!(v["libigl"].as_array().unwrap().is_empty());
    let page = std::fs::read_to_string(dir.join("index.html")).unwrap();
    assert!(page.contains("<h2>Construction time</h2>"));
    assert!(page.contains("<h2>Memory per triangle"));
    for absent in [
        "Table 4.1, measured",
        "<h2>Teaching",
        "<h2>Meshes</h2>",
        "<h2>3D convex hull",
    ] {
        assert!(!page.contains(absent), "{absent}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn an_unknown_section_is_a_usage_error_listing_the_known() {
    let run = topolab(&["report", "--sections", "table-4-1,nope", "--out", "/tmp/x"]);
    assert_eq!(run.status.code(), Some(2));
    let stderr = text(&run.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.contains("'nope'")
            && stderr.contains("known: chooser, table-4-1, plots")
            && stderr.contains("targets"),
        "{stderr}"
    );
}

#[test]
fn two_runs_compare_with_exit_0_and_their_machines_shown() {
    let dir = scratch("compare-runs");
    let (a, b) = (dir.join("a"), dir.join("b"));
    report(&a, "table-4-1");
    let mut v = report(&b, "table-4-1");
    // The new run of another commit, with one cell a hundred times slower than anything before.
    v["machine"]["commit"] = "feedbee".into();
    let cells = v["measurements"].as_array_mut().unwrap();
    let slow = cells
        .iter_mut()
        .find(|m| {
            m["structure"] == "che-l2"
                && m["operator"] == "r00"
                && m["kernel"] == "sweep"
                && m["status"] == "measured"
        })
        .unwrap();
    let max = slow["max_ns_per_item"].as_f64().unwrap();
    let slower = |ns: f64| max * 100.0 + ns;
    for field in ["ns_per_item", "min_ns_per_item", "max_ns_per_item"] {
        slow[field] = slower(slow[field].as_f64().unwrap()).into();
    }
    // Its interval and rounds move with it, as a slow cell's would: compare flags by intervals.
    for field in ["ns_per_item_ci", "round_ns_per_item"] {
        let moved: Vec<f64> = slow[field]
            .as_array()
            .unwrap()
            .iter()
            .map(|ns| slower(ns.as_f64().unwrap()))
            .collect();
        slow[field] = json!(moved);
    }
    let mesh = slow["mesh"].as_str().unwrap().to_string();
    std::fs::write(b.join("results.json"), v.to_string()).unwrap();
    let out = dir.join("page");
    let run = topolab(&[
        "compare",
        a.join("results.json").to_str().unwrap(),
        b.join("results.json").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", text(&run.stderr));
    let said = text(&run.stdout);
    let old_commit = json_of(&a.join("results.json"))["machine"]["commit"]
        .as_str()
        .unwrap()
        .to_string();
    assert!(said.contains(&format!("commit {old_commit}")), "{said}");
    assert!(said.contains("commit feedbee"), "{said}");
    // The largest change comes first, flagged.
    let first = said
        .lines()
        .skip_while(|line| !line.starts_with("new/old"))
        .nth(1)
        .unwrap();
    assert!(
        first.contains('*') && first.contains("che-l2") && first.contains(&mesh),
        "{said}"
    );
    let page = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(page.contains("commit feedbee") && page.contains("flagged"));
    assert!(!page.contains("<script") && !page.contains("src=\"http"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn what_is_not_a_results_json_of_a_known_format_is_refused_with_exit_2() {
    let dir = scratch("compare-refused");
    let good = dir.join("good.json");
    let results = json!({
        "format_version": FORMAT_VERSION,
        "machine": {"cpu": "x", "cores": 1, "commit": "abc", "date": "today"},
        "settings": {"command": "topolab report"},
        "meshes": [],
        "measurements": [],
    });
    std::fs::write(&good, results.to_string()).unwrap();
    let mesh = dir.join("mesh.off");
    std::fs::write(&mesh, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").unwrap();
    let other = dir.join("other.json");
    std::fs::write(&other, r#"{"name": "a package.json"}"#).unwrap();
    let newer = dir.join("newer.json");
    let mut v = results.clone();
    v["format_version"] = (FORMAT_VERSION + 1).into();
    std::fs::write(&newer, v.to_string()).unwrap();
    let out = dir.join("page");
    for (file, why) in [
        (&mesh, "not a topolab results.json"),
        (&other, "not a topolab results.json"),
        (&newer, "format version"),
        (&dir.join("missing.json"), "cannot read"),
    ] {
        for (old, new) in [(file, &good), (&good, file)] {
            let run = topolab(&[
                "compare",
                old.to_str().unwrap(),
                new.to_str().unwrap(),
                "--out",
                out.to_str().unwrap(),
            ]);
            let stderr = text(&run.stderr);
            assert_eq!(run.status.code(), Some(2), "{}: {stderr}", file.display());
            assert_eq!(stderr.lines().count(), 1, "{stderr}");
            assert!(
                stderr.contains(why) && stderr.contains(file.to_str().unwrap()),
                "{stderr}"
            );
        }
    }
    assert!(!out.exists(), "nothing written for a refused comparison");
    let run = topolab(&[
        "compare",
        good.to_str().unwrap(),
        good.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", text(&run.stderr));
    assert!(text(&run.stdout).contains("0 cells measured in both, 0 flagged"));
    std::fs::remove_dir_all(&dir).unwrap();
}
