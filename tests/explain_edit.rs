//! `topolab explain NAME --op flip|split|collapse --edge E`: the records an edit writes, and
//! a refused edit's exit code and reason.

use std::process::{Command, Output};
use topolab::commands::explain_edit::{run, ExplainOp, EDITABLE};

fn topolab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_topolab"))
        .args(args)
        .output()
        .expect("the binary runs")
}

/// The records marked added (`+ key: ...`) in `text`.
fn added(text: &str) -> Vec<&str> {
    text.lines()
        .filter_map(|l| l.strip_prefix("+ "))
        .filter_map(|l| l.split(": ").next())
        .collect()
}

#[test]
fn a_split_names_the_records_it_adds_and_rewrites() {
    // The open tetrahedron has 4 vertices, 3 triangles and 6 edges: a split adds vertex 4
    // and, splitting an interior edge, two triangles.
    let half_edge = run("index-half-edge", None, ExplainOp::Split, 1).expect("edge 1 splits");
    let new = added(&half_edge);
    assert!(
        new.contains(&"v4") && new.contains(&"f3") && new.contains(&"f4"),
        "{half_edge}"
    );
    assert_eq!(
        new.iter().filter(|k| k.starts_with('h')).count(),
        6,
        "{half_edge}"
    );
    assert!(
        half_edge.contains(".next: "),
        "next links change: {half_edge}"
    );

    let che = run("che", None, ExplainOp::Split, 1).expect("edge 1 splits at every level");
    for level in 0..4 {
        assert!(
            che.contains(&format!("che-l{level}: split-edge of edge 1")),
            "{che}"
        );
    }
    let new = added(&che);
    // Two new triangles: half-edges 9..=14 of V[] at every level, of O[] from level 1 on.
    let count = |prefix: &str| new.iter().filter(|k| k.starts_with(prefix)).count();
    assert_eq!(count("V["), 4 * 6, "{che}");
    assert_eq!(count("O["), 3 * 6, "{che}");
    assert_eq!(
        count("VH["),
        2,
        "the new vertex's VH at levels 2 and 3: {che}"
    );
    assert!(che.contains("G[]: 4 vertices -> 5 vertices"), "{che}");
}

#[test]
fn a_collapse_marks_its_vertex_deleted_on_a_torus() {
    for name in EDITABLE {
        let text = run(name, Some("torus:50"), ExplainOp::Collapse, 0)
            .unwrap_or_else(|f| panic!("{name}: {}", f.message));
        assert!(
            text.lines()
                .any(|l| l.starts_with("+ v") && l.contains(".deleted: yes")),
            "{name}: {text}"
        );
    }
}

#[test]
fn a_refused_flip_exits_with_the_reason_and_no_panic() {
    // Every interior edge of the open tetrahedron joins the apex; its flip would create a
    // boundary edge that exists already.
    for name in ["index-half-edge", "che-l2", "che"] {
        let out = topolab(&["explain", name, "--op", "flip", "--edge", "1"]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{name}: {stderr}");
        assert!(stderr.contains("refuses flip-edge"), "{name}: {stderr}");
        assert!(
            stderr.contains("the edge it would create exists already"),
            "{stderr}"
        );
        assert!(!stderr.contains("panicked"), "{stderr}");
        assert!(
            out.stdout.is_empty(),
            "{name}: nothing printed before the refusal"
        );
    }
    // A boundary edge (edge 0, v0 - v1) cannot be flipped at all.
    let out = topolab(&["explain", "che-l1", "--op", "flip", "--edge", "0"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("boundary edge"));
}

#[test]
fn bad_requests_are_usage_errors() {
    for args in [
        vec!["explain", "che-l1", "--op", "flip"],
        vec!["explain", "che-l1", "--op", "twist", "--edge", "1"],
        vec!["explain", "che-l1", "--op", "flip", "--edge", "6"],
        vec!["explain", "edge-list", "--op", "flip", "--edge", "1"],
        vec![
            "explain", "che-l1", "--op", "flip", "--edge", "1", "--trace", "r00",
        ],
    ] {
        let out = topolab(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}
