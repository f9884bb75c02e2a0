//! `topolab list`'s editing table: every editing operation a row (the lecture's operations
//! among them), explicit storage a column, `—` where a structure does not offer one.

use std::process::Command;
use topolab_structures::EditOp;

fn list() -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_topolab"))
        .arg("list")
        .output()
        .expect("run topolab");
    assert_eq!(out.status.code(), Some(0));
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// The editing table: its header's structure names and, per operation, its cells.
fn editing_table(text: &str) -> (Vec<String>, Vec<(String, Vec<String>)>) {
    let table = text
        .split("Editing operations (MeshEdit) and their cost\n")
        .nth(1)
        .expect("the editing table");
    let mut lines = table.lines();
    let header: Vec<String> = lines
        .next()
        .expect("a header")
        .split_whitespace()
        .skip(1)
        .map(str::to_string)
        .collect();
    let rows = lines
        .take_while(|l| !l.trim().is_empty())
        .map(|l| {
            let mut cells = l.split_whitespace().map(str::to_string);
            (cells.next().expect("a name"), cells.collect())
        })
        .collect();
    (header, rows)
}

#[test]
fn every_editing_operation_is_a_row_and_explicit_storage_a_column() {
    let (header, rows) = editing_table(&list());
    let names: Vec<&str> = rows.iter().map(|(n, _)| n.as_str()).collect();
    let all: Vec<&str> = EditOp::ALL.iter().map(|op| op.name()).collect();
    assert_eq!(names, all);
    let column = |s: &str| {
        header
            .iter()
            .position(|h| h == s)
            .unwrap_or_else(|| panic!("no {s} column in {header:?}"))
    };
    let cell = |s: &str, op: &str| {
        let row = &rows.iter().find(|(n, _)| n == op).expect("a row").1;
        assert_eq!(row.len(), header.len(), "{op}: {row:?}");
        row[column(s)].clone()
    };
    // The lecture's contrast: a vertex moved in explicit storage is found in every polygon.
    assert_eq!(cell("explicit", "set-position"), "O(n)");
    assert_eq!(cell("vertex-list", "set-position"), "O(1)");
    assert_eq!(cell("index-half-edge", "set-position"), "O(1)");
    assert_eq!(cell("explicit", "rotate-selection"), "O(n)");
    assert_eq!(cell("winged-edge", "rotate-selection"), "O(k)");
    // Explicit storage offers no topological edit; the CHE levels hold triangles only.
    assert_eq!(cell("explicit", "add-face"), "—");
    assert_eq!(cell("che-l3", "insert-edge"), "—");
    assert_eq!(cell("che-l3", "delete-edge"), "—");
    assert_eq!(cell("edge-list", "insert-edge"), "O(n)");
    assert_eq!(cell("index-half-edge", "delete-edge"), "O(k)");
    assert_eq!(cell("vertex-list", "smooth"), "O(n²)");
    assert_eq!(cell("index-half-edge", "smooth"), "O(n)");
}

/// `list --json`'s editing rows: per structure, its operations' costs and its schemes'.
fn editing_json() -> Vec<serde_json::Value> {
    let out = Command::new(env!("CARGO_BIN_EXE_topolab"))
        .args(["list", "--json"])
        .output()
        .expect("run topolab");
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    v["editing"].as_array().expect("editing rows").clone()
}

#[test]
fn refinement_and_thinning_have_rows_whose_cost_follows_the_operations_they_do() {
    let text = list();
    assert!(text.contains("Refinement and thinning"), "{text}");
    for row in editing_json() {
        let name = row["name"].as_str().unwrap();
        let cost = |op: &str| -> String {
            let costs = row["costs"].as_array().unwrap();
            let c = costs.iter().find(|c| c[0] == op).expect("an operation");
            c[1].as_str().unwrap().to_string()
        };
        let scheme = |s: &str| -> String {
            let schemes = row["schemes"].as_array().unwrap();
            let c = schemes.iter().find(|c| c[0] == s).expect("a scheme");
            c[1].as_str().unwrap().to_string()
        };
        let bisection = scheme("bisection (a split)");
        let decimation = scheme("decimation (a collapse)");
        // A structure that does not split (collapse) has no bisection (decimation) ...
        assert_eq!(cost("split-edge") == "—", bisection == "—", "{name}");
        assert_eq!(cost("collapse-edge") == "—", decimation == "—", "{name}");
        // ... one whose split scans has a scanning bisection, and a local one adds the heap.
        if cost("split-edge") == "O(n)" {
            assert_eq!(bisection, "O(n)", "{name}");
        }
        // A local bisection or decimation still pays for its heap: a logarithm shows.
        for step in [&bisection, &decimation] {
            let scans = ["—", "O(n)", "O(k·n)", "O(n²)", "O(∂n1)"];
            if !scans.contains(&step.as_str()) {
                assert!(step.contains("log n"), "{name}: {step}");
            }
        }
    }
}

#[test]
fn counted_reads_sit_beside_the_declared_costs_and_grow_as_they_say() {
    let out = Command::new(env!("CARGO_BIN_EXE_topolab"))
        .args(["list", "--counted", "--json"])
        .output()
        .expect("run topolab");
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let cells = v["counted"].as_array().expect("counted cells");
    let declared = |structure: &str, op: &str| -> String {
        let row = v["editing"]
            .as_array()
            .unwrap()
            .iter()
            .find(|r| r["name"] == structure)
            .expect("an editing row");
        let c = row["costs"].as_array().unwrap();
        let c = c.iter().find(|c| c[0] == op).expect("an operation");
        c[1].as_str().unwrap().to_string()
    };
    let mut checked = 0;
    for cell in cells {
        let (op, structure) = (
            cell["op"].as_str().unwrap(),
            cell["structure"].as_str().unwrap(),
        );
        let reads: Vec<u64> = cell["reads"]
            .as_array()
            .unwrap()
            .iter()
            .filter_map(|r| r[1]["Ok"].as_u64())
            .collect();
        if reads.len() != 2 {
            continue;
        }
        // 16 times the faces: a declared O(1) or O(k) reads the same on both tori, a declared
        // O(n) at least 8 times as much (or nothing at all, where it reads no container).
        // A count is at most what an edit reads (a scan straight over a container is not
        // counted): a declared scan that does not grow is marked so, never shown as local.
        let unseen = cell["scan_not_counted"].as_bool().unwrap();
        match declared(structure, op).as_str() {
            "O(1)" | "O(k)" | "O(k²)" => {
                assert_eq!(reads[0], reads[1], "{op} on {structure}");
                assert!(!unseen, "{op} on {structure}");
            }
            "O(n)" | "O(k·n)" | "O(n²)" => {
                let grows = reads[1] >= 2 * reads[0].max(1);
                assert_eq!(unseen, !grows, "{op} on {structure}: {reads:?}");
            }
            _ => continue,
        }
        checked += 1;
    }
    assert!(checked > 50, "{checked} cells checked");
}
