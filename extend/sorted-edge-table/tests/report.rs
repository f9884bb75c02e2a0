//! The lab's report, run through this crate's binary (`src/bin/report.rs`), measures the sorted
//! edge table beside the lab's structures and the C++ baselines compiled into the lab.

use std::process::Command;
use topolab_structures::Operator;

#[test]
fn the_report_has_the_sorted_edge_table_beside_the_labs_structures() {
    let out = std::env::temp_dir().join(format!("sorted-edge-table-report-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let mut structures = vec![
        "vertex-list",
        "index-half-edge",
        "che-l2",
        "sorted-edge-table",
    ];
    if topolab::HAS_OPENMESH {
        structures.push(topolab::registry::OPENMESH);
    }
    let status = Command::new(env!("CARGO_BIN_EXE_report"))
        .args(["--quick", "--sizes", "200,800", "--probe-mb", "4"])
        .args([
            "--meshes",
            "torus,grid",
            "--structures",
            &structures.join(","),
        ])
        .arg("--out")
        .arg(&out)
        .status()
        .expect("run the report binary");
    assert!(status.success(), "the report failed: {status}");

    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    let listed: Vec<&str> = json["structures"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["name"].as_str().unwrap())
        .collect();
    assert_eq!(listed, structures);
    let ms = json["measurements"].as_array().unwrap();
    let ours = |m: &&serde_json::Value| m["structure"] == "sorted-edge-table";
    for op in Operator::ALL {
        assert!(
            ms.iter()
                .filter(ours)
                .any(|m| m["operator"] == op.name() && m["status"] == "measured"),
            "no measurement of {} on the sorted edge table",
            op.name()
        );
    }
    // Its answers to the queries are those of the index half-edge, checksum for checksum (the
    // report itself stops on a mismatch; the workloads' floating-point sums may differ in the
    // last bits, as the report allows, so they are left out here).
    let mut compared = 0;
    let queries = |m: &&serde_json::Value| m["kernel"] == "sweep" || m["kernel"] == "sampled";
    for m in ms.iter().filter(ours).filter(queries) {
        let twin = ms.iter().find(|o| {
            o["structure"] == "index-half-edge"
                && ["mesh", "operator", "kernel"]
                    .iter()
                    .all(|k| o[*k] == m[*k])
        });
        if let Some(twin) = twin.filter(|t| t["checksum"].is_string()) {
            assert_eq!(twin["checksum"], m["checksum"], "{m}");
            compared += 1;
        }
    }
    assert!(compared > 20, "only {compared} checksums compared");

    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    for s in &structures {
        assert!(
            html.contains(&format!("<th>{s}</th>")),
            "{s} missing from the page's tables"
        );
    }
    assert!(html.contains("sorted edge table: every edge in both directions"));
    let _ = std::fs::remove_dir_all(&out);
}
