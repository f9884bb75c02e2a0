//! `topolab explain NAME --op OP --structures A,B`: an edit's reads and writes, counted in the
//! counting build, side by side and on tori of growing size.

mod common;

use common::run::topolab;
use topolab_structures::EditOp;
// The structures that offer the topological edits these tests refuse or count: explicit
// storage (`[moves]`) offers none of them.
use topolab_structures::registry::editable_names;

/// The lesson of counted edits: a flip on the vertex list searches the faces, so its reads
/// grow with the mesh, where the index half-edge and the CHE level 2 reach the edge through
/// their relations; every structure is counted side by side, and the growth table says so.
#[test]
fn counted_edits_side_by_side_grow_with_the_mesh_only_where_the_structure_searches() {
    let out = topolab(&[
        "explain",
        "vertex-list",
        "--op",
        "flip",
        "--edge",
        "1",
        "--mesh",
        "torus:2000",
        "--structures",
        "index-half-edge,che-l1",
    ]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // The growth table's rows: name, then "reads / writes" for each torus.
    let growth = |name: &str| -> Vec<u64> {
        let table = text
            .split("tori of growing size")
            .nth(1)
            .expect("a growth table");
        let row = table
            .lines()
            .find(|l| l.split_whitespace().next() == Some(name))
            .unwrap_or_else(|| panic!("no growth row for {name}: {text}"));
        row.split_whitespace()
            .skip(1)
            .collect::<Vec<_>>()
            .chunks(3)
            .map(|c| c[0].parse().expect("reads"))
            .collect()
    };
    let (list, half_edge, che) = (
        growth("vertex-list"),
        growth("index-half-edge"),
        growth("che-l1"),
    );
    assert_eq!(list.len(), 3, "{text}");
    // Each torus has 16 times the faces of the last: a scan's reads grow about so much.
    assert!(
        list[1] > 8 * list[0] && list[2] > 8 * list[1],
        "{list:?}\n{text}"
    );
    assert!(
        half_edge.iter().all(|&r| r > 0 && r == half_edge[0]),
        "{half_edge:?}\n{text}"
    );
    // Level 1 finds its far corners' edge by a scan of V[] (its flip is O(n)): it grows too.
    assert!(che[2] > 8 * che[1], "{che:?}\n{text}");
    // The side-by-side table counts the three on the mesh given.
    let counted = text.split("counted (").nth(1).expect("a counted table");
    for name in ["vertex-list", "index-half-edge", "che-l1"] {
        assert!(
            counted.lines().any(|l| l.trim_start().starts_with(name)),
            "{name}: {text}"
        );
    }
}

/// Every editable structure's edit reads through counted accessors: a structure whose edit
/// code read its containers only directly would count nothing.
#[test]
fn every_editable_structure_counts_the_reads_and_writes_of_a_split() {
    let torus = topolab_structures::meshes::torus(8, 6);
    for name in editable_names() {
        let counted = topolab_harness::teaching::edits::counted::count(
            name,
            &torus,
            EditOp::SplitEdge,
            &topolab_harness::teaching::edits::Subject::Edge(3),
        )
        .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(counted.refused.is_none(), "{name}: {counted:?}");
        assert!(
            counted.reads > 0 && counted.writes > 0,
            "{name}: {counted:?}"
        );
    }
}

#[test]
fn structures_without_trace_or_op_is_a_usage_error() {
    let out = topolab(&["explain", "vertex-list", "--structures", "che-l2"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--trace OP or --op OP"));
}
