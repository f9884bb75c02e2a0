use super::*;
use serde_json::{json, Value};

/// A measured cell: `median` with its fastest and slowest run.
fn cell(structure: &str, operator: &str, mesh: &str, (min, median, max): (f64, f64, f64)) -> Value {
    json!({
        "structure": structure, "operator": operator, "kernel": "sweep", "mesh": mesh,
        "family": "torus", "triangles": 1000, "status": "measured",
        "ns_per_item": median, "min_ns_per_item": min, "max_ns_per_item": max,
        "items": 500, "reps": 5, "checksum": "1", "bytes": null, "peak_bytes": null,
        "declared_bytes": null, "estimate_ns_per_item": null, "native": false, "note": null
    })
}

fn run(commit: &str, cells: Vec<Value>) -> Value {
    json!({
        "format_version": FORMAT_VERSION,
        "machine": {"cpu": "AMD EPYC", "cores": 2, "commit": commit, "date": "2026-12-01 10:00 UTC", "os": "Linux"},
        "probe": {},
        "settings": {"quick": true, "command": "topolab report --quick"},
        "meshes": [{"name": "torus-1k", "family": "torus"}],
        "measurements": cells,
    })
}

fn read_value(v: &Value) -> Result<Run, ReadError> {
    read(v.to_string().as_bytes())
}

#[test]
fn what_is_not_a_results_json_is_refused_with_the_reason() {
    for (bytes, why) in [
        (&b"OFF\n3 1 0\n"[..], "it is not JSON"),
        (b"{\"machine\": {}", "it is not JSON"),
        (b"\xff\xfe", "it is not JSON"),
        (b"[1, 2, 3]", "not an object with the fields of one"),
        (
            b"{\"machine\": {}, \"settings\": {}}",
            "no measurements field",
        ),
        (b"{}", "no machine, no settings, no measurements field"),
    ] {
        match read(bytes) {
            Err(e @ ReadError::NotResults(_)) => {
                let text = e.to_string();
                assert!(text.starts_with("not a topolab results.json"), "{text}");
                assert!(text.contains(why), "{text}");
            }
            other => panic!("{:?}: {other:?}", String::from_utf8_lossy(bytes)),
        }
    }
    let mut v = run(
        "abc",
        vec![cell("che-l0", "r00", "torus-1k", (1.0, 2.0, 3.0))],
    );
    v["measurements"][0]["operator"] = "r03".into();
    let e = read_value(&v).unwrap_err();
    assert!(e.to_string().contains("unknown operator \"r03\""), "{e}");
}

#[test]
fn format_versions_past_this_one_are_refused_and_files_without_one_read() {
    let mut v = run(
        "abc",
        vec![cell("che-l0", "r00", "torus-1k", (1.0, 2.0, 3.0))],
    );
    assert_eq!(
        read_value(&v).unwrap().format_version,
        FORMAT_VERSION as u64
    );
    v["format_version"] = (FORMAT_VERSION + 1).into();
    // Even when the rest would not read: the version is what a reader needs to hear.
    v["measurements"] = json!("renamed");
    let e = read_value(&v).unwrap_err();
    assert_eq!(
        e,
        ReadError::Version {
            found: FORMAT_VERSION as u64 + 1
        }
    );
    assert!(e.to_string().contains("format version 2"), "{e}");
    v["format_version"] = "one".into();
    assert!(matches!(read_value(&v), Err(ReadError::NotResults(_))));
    let mut old = run(
        "abc",
        vec![cell("che-l0", "r00", "torus-1k", (1.0, 2.0, 3.0))],
    );
    old.as_object_mut().unwrap().remove("format_version");
    let r = read_value(&old).unwrap();
    assert_eq!((r.format_version, r.measurements.len()), (0, 1));
    assert_eq!(r.machine.commit, "abc");
}

#[test]
fn the_committed_reference_report_reads() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../reports/reference/results.json"
    );
    let Ok(bytes) = std::fs::read(path) else {
        return;
    };
    let r = read(&bytes).unwrap();
    assert!(r.measurements.len() > 1000);
    assert!(!r.machine.commit.is_empty());
}

#[test]
fn changes_outside_both_spreads_are_flagged_and_sorted_by_size() {
    let old = run(
        "old1234",
        vec![
            cell("che-l2", "r00", "torus-1k", (9.0, 10.0, 11.0)),
            cell("index-half-edge", "r00", "torus-1k", (4.0, 5.0, 6.0)),
            cell("openmesh", "r00", "torus-1k", (19.0, 20.0, 40.0)),
            cell("winged-edge", "r00", "torus-1k", (1.0, 2.0, 3.0)),
            cell("explicit", "r00", "torus-1k", (1.0, 2.0, 3.0)),
        ],
    );
    let mut skipped = cell("explicit", "r00", "torus-1k", (1.0, 2.0, 3.0));
    skipped["status"] = "skipped".into();
    let new = run(
        "new5678",
        vec![
            // Twice as slow, outside both spreads: flagged.
            cell("che-l2", "r00", "torus-1k", (19.0, 20.0, 21.0)),
            // Twice as fast, outside both: flagged.
            cell("index-half-edge", "r00", "torus-1k", (2.4, 2.5, 2.6)),
            // 1.5x slower, but the old run's slowest was 40: not flagged.
            cell("openmesh", "r00", "torus-1k", (29.0, 30.0, 31.0)),
            cell("pointer-half-edge", "r00", "torus-1k", (1.0, 2.0, 3.0)),
            skipped,
        ],
    );
    let c = compare(read_value(&old).unwrap(), read_value(&new).unwrap());
    let order: Vec<(&str, bool)> = c
        .cells
        .iter()
        .map(|x| (x.structure.as_str(), x.flagged))
        .collect();
    // |ln 2| = |ln 0.5|: ties in name order.
    assert_eq!(
        order,
        [
            ("che-l2", true),
            ("index-half-edge", true),
            ("openmesh", false)
        ]
    );
    assert_eq!(c.cells[0].ratio, 2.0);
    assert_eq!(c.cells[1].ratio, 0.5);
    assert_eq!((c.only_old, c.only_new, c.not_measured), (1, 1, 1));
    assert_eq!(c.flagged(), 2);
    let text = text(&c, "a/results.json", "b/results.json");
    assert!(
        text.contains("old: a/results.json: commit old1234"),
        "{text}"
    );
    assert!(
        text.contains("new: b/results.json: commit new5678"),
        "{text}"
    );
    assert!(
        text.contains("3 cells measured in both, 2 flagged"),
        "{text}"
    );
    let page = html(&c, "a/results.json", "b/results.json");
    assert!(page.contains("commit new5678") && page.contains("2.00× slower, flagged"));
    assert!(
        !page.contains("http") && !page.contains("<script"),
        "self-contained"
    );
}

#[test]
fn a_mesh_repaired_in_one_run_only_is_not_compared() {
    let cells = vec![cell("che-l2", "r00", "blobby", (9.0, 10.0, 11.0))];
    let old = run("a", cells.clone());
    let mut new = run("b", cells);
    new["meshes"] = json!([{"name": "blobby", "family": "real", "repaired": {"flipped_faces": 3}}]);
    let c = compare(read_value(&old).unwrap(), read_value(&new).unwrap());
    assert_eq!((c.cells.len(), c.repaired_in_one), (0, 1));
    let c = compare(read_value(&new).unwrap(), read_value(&new).unwrap());
    assert_eq!((c.cells.len(), c.repaired_in_one, c.flagged()), (1, 0, 0));
}

#[test]
fn the_sample_reads() {
    assert_eq!(
        read(sample_results(3).as_bytes())
            .unwrap()
            .measurements
            .len(),
        3
    );
}

#[test]
fn with_intervals_only_a_separation_is_flagged_and_the_changes_are_counted() {
    let with_ci = |s: &str, median: f64, ci: [f64; 2]| {
        let mut c = cell(s, "r00", "torus-1k", (ci[0] * 0.9, median, ci[1] * 1.1));
        c["ns_per_item_ci"] = json!(ci);
        c
    };
    let same = ["lox-half-edge", "winged-edge", "edge-list"];
    let mut old_cells = vec![
        with_ci("che-l2", 10.0, [9.5, 10.5]),
        with_ci("che-l3", 10.0, [9.5, 10.5]),
        with_ci("openmesh", 20.0, [19.0, 21.0]),
    ];
    let mut new_cells = vec![
        // 12% slower, but the intervals overlap at 10.5: not flagged.
        with_ci("che-l2", 11.2, [10.5, 12.0]),
        // 12% slower and the intervals apart: flagged.
        with_ci("che-l3", 11.2, [10.6, 12.0]),
        // 30% faster, apart: flagged.
        with_ci("openmesh", 14.0, [13.0, 15.0]),
    ];
    // Three cells that did not move: the run-wide shift is 1.
    for s in same {
        old_cells.push(with_ci(s, 5.0, [4.9, 5.1]));
        new_cells.push(with_ci(s, 5.0, [4.9, 5.1]));
    }
    let c = compare(
        read_value(&run("old", old_cells.clone())).unwrap(),
        read_value(&run("new", new_cells)).unwrap(),
    );
    let flagged: Vec<(&str, bool)> = c
        .cells
        .iter()
        .take(3)
        .map(|x| (x.structure.as_str(), x.flagged))
        .collect();
    assert_eq!(
        flagged,
        [("openmesh", true), ("che-l2", false), ("che-l3", true)]
    );
    assert_eq!((c.shift, c.flagged(), c.moved()), (1.0, 2, 2));
    assert_eq!(
        (c.differ_by_more_than(0.10), c.differ_by_more_than(0.25)),
        (3, 1)
    );
    let text = text(&c, "a", "b");
    assert!(
        text.contains("6 cells measured in both, 2 flagged (33.3%")
            && text.contains("3 (50.0%) differ by more than 10%, 1 (16.7%) by more than 25%"),
        "{text}"
    );
    // The whole run 20% slower, every interval apart as measured: a shift, not a change of any
    // one cell.
    let slower: Vec<Value> = old_cells
        .iter()
        .map(|m| {
            let mut m = m.clone();
            for f in ["ns_per_item", "min_ns_per_item", "max_ns_per_item"] {
                m[f] = json!(m[f].as_f64().unwrap() * 1.2);
            }
            let ci: Vec<f64> = m["ns_per_item_ci"]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap() * 1.2)
                .collect();
            m["ns_per_item_ci"] = json!(ci);
            m
        })
        .collect();
    let c = compare(
        read_value(&run("old", old_cells)).unwrap(),
        read_value(&run("new", slower)).unwrap(),
    );
    assert!((c.shift - 1.2).abs() < 1e-12);
    assert_eq!((c.flagged(), c.moved()), (0, 6));
    assert!(text_of(&c).contains("Run-wide shift: the new run's cells are 20.0% slower"));
}

fn text_of(c: &Comparison) -> String {
    text(c, "a", "b")
}
