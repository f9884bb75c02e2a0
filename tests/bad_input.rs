//! The bad-input corpus (`tests/bad-input/`, written by its `generate.py`): every reader and
//! every structure answers with the exact typed error, and `topolab check` reports each
//! problem with the right exit code.

use std::path::{Path, PathBuf};
use std::process::Command;
use topolab_structures::{io, registry};

/// Per file: the kind of the first error of the strict pipeline (read, then the edge and
/// vertex-fan analysis every manifold structure runs; "ok" when all pass), and the finding
/// what `topolab check` must say.
const CORPUS: &[(&str, &str, Check)] = &[
    // OBJ
    ("empty.obj", "ok", Finds("empty-mesh")),
    ("obj-comments-only.obj", "ok", Finds("empty-mesh")),
    ("obj-bad-token.obj", "syntax", Unreadable),
    // "face 1 2 3": an unknown statement, skipped with a warning (as tobj and OpenMesh skip
    // it), which leaves three vertices and no face.
    (
        "obj-unknown-statement.obj",
        "ok",
        Warns(
            "skipped unknown OBJ statement \"face\" at line 4",
            "unused-vertex",
        ),
    ),
    ("obj-short-vertex.obj", "syntax", Unreadable),
    ("obj-truncated.obj", "truncated", Unreadable),
    (
        "obj-index-out-of-range.obj",
        "index-out-of-range",
        Finds("missing-vertex"),
    ),
    (
        "obj-negative-out-of-range.obj",
        "index-out-of-range",
        Finds("missing-vertex"),
    ),
    (
        "obj-index-zero.obj",
        "index-out-of-range",
        Finds("edge-without-end-point"),
    ),
    (
        "obj-index-overflows-u32.obj",
        "index-out-of-range",
        Finds("missing-vertex"),
    ),
    (
        "obj-index-overflows-i64.obj",
        "index-out-of-range",
        Finds("missing-vertex"),
    ),
    (
        "obj-nan.obj",
        "non-finite-coordinate",
        Finds("non-finite-coordinate"),
    ),
    (
        "obj-inf.obj",
        "non-finite-coordinate",
        Finds("non-finite-coordinate"),
    ),
    (
        "obj-one-vertex-face.obj",
        "too-few-corners",
        Finds("too-few-vertices"),
    ),
    (
        "obj-two-vertex-face.obj",
        "too-few-corners",
        Finds("too-few-vertices"),
    ),
    (
        "obj-repeated-vertex.obj",
        "repeated-vertex",
        Finds("repeated-vertex"),
    ),
    (
        "non-manifold-edge.obj",
        "non-manifold-edge",
        Finds("non-manifold-edge"),
    ),
    (
        "non-manifold-vertex.obj",
        "non-manifold-vertex",
        Finds("non-manifold-vertex"),
    ),
    (
        "inconsistent-orientation.obj",
        "inconsistent-orientation",
        Finds("inconsistent-orientation"),
    ),
    (
        "mobius.obj",
        "inconsistent-orientation",
        Finds("non-orientable"),
    ),
    (
        "duplicate-face.obj",
        "inconsistent-orientation",
        Finds("duplicate-face"),
    ),
    (
        "geometric-duplicate-face.obj",
        "ok",
        Finds("geometric-duplicate-face"),
    ),
    (
        "duplicate-vertices.obj",
        "non-manifold-vertex",
        Finds("duplicate-vertices"),
    ),
    ("unused-vertex.obj", "ok", Finds("unused-vertex")),
    ("point-cloud.obj", "ok", Finds("unused-vertex")),
    ("degenerate-face.obj", "ok", Finds("degenerate-face")),
    ("non-planar-face.obj", "ok", Finds("non-planar-face")),
    ("non-convex-face.obj", "ok", Finds("non-convex-face")),
    ("non-simple-face.obj", "ok", Finds("non-simple-face")),
    // Issue 52's hostile cases, small.
    ("obj-far-coordinates.obj", "ok", Clean),
    ("obj-ulps-apart.obj", "ok", Finds("duplicate-vertices")),
    (
        "obj-underflows-a-float.obj",
        "ok",
        Finds("duplicate-vertices"),
    ),
    (
        "obj-many-fans.obj",
        "non-manifold-vertex",
        Finds("non-manifold-vertex"),
    ),
    (
        "obj-unknown-kinds.obj",
        "ok",
        Warns(
            "skipped 12 times unknown OBJ statements of kinds beyond the first 8, first at line 13",
            "",
        ),
    ),
    (
        "obj-index-one-based.obj",
        "index-out-of-range",
        Finds("missing-vertex"),
    ),
    (
        "obj-holds-off.obj",
        "ok",
        Warns(
            "skipped unknown OBJ statement \"OFF\" at line 1",
            "empty-mesh",
        ),
    ),
    (
        "obj-zeros.obj",
        "ok",
        Warns("skipped unknown OBJ statement \"\\0\\0", "empty-mesh"),
    ),
    // OFF
    ("empty.off", "truncated", Unreadable),
    ("off-no-elements.off", "ok", Finds("empty-mesh")),
    ("off-no-header.off", "syntax", Unreadable),
    ("off-bad-count.off", "syntax", Unreadable),
    (
        "off-huge-vertex-count.off",
        "implausible-header",
        Unreadable,
    ),
    ("off-huge-face-count.off", "implausible-header", Unreadable),
    ("off-truncated.off", "truncated", Unreadable),
    ("off-truncated-in-face.off", "truncated", Unreadable),
    (
        "off-negative-index.off",
        "index-out-of-range",
        Finds("missing-vertex"),
    ),
    (
        "off-index-overflows-u32.off",
        "index-out-of-range",
        Finds("missing-vertex"),
    ),
    (
        "off-nan.off",
        "non-finite-coordinate",
        Finds("non-finite-coordinate"),
    ),
    ("off-nul-bytes.off", "syntax", Unreadable),
    (
        "off-two-vertex-face.off",
        "too-few-corners",
        Finds("too-few-vertices"),
    ),
    // PLY
    ("empty.ply", "truncated", Unreadable),
    ("ply-no-elements.ply", "ok", Finds("empty-mesh")),
    ("ply-no-end-header.ply", "truncated", Unreadable),
    ("ply-bad-format.ply", "syntax", Unreadable),
    ("ply-missing-z.ply", "syntax", Unreadable),
    ("ply-ascii-bad-token.ply", "syntax", Unreadable),
    (
        "ply-ascii-nan.ply",
        "non-finite-coordinate",
        Finds("non-finite-coordinate"),
    ),
    ("ply-ascii-truncated.ply", "truncated", Unreadable),
    (
        "ply-ascii-huge-header.ply",
        "implausible-header",
        Unreadable,
    ),
    (
        "ply-binary-huge-header.ply",
        "implausible-header",
        Unreadable,
    ),
    ("ply-binary-too-short.ply", "truncated", Unreadable),
    (
        "ply-binary-big-endian-too-short.ply",
        "truncated",
        Unreadable,
    ),
    // Four bytes after the last element: skipped with a warning (OpenMesh reads such files);
    // the mesh itself is clean.
    (
        "ply-binary-too-long.ply",
        "ok",
        Warns(
            "skipped 4 bytes after the last element the header announces at byte",
            "",
        ),
    ),
    (
        "ply-binary-negative-index.ply",
        "index-out-of-range",
        Finds("missing-vertex"),
    ),
    (
        "ply-binary-index-overflows-u32.ply",
        "index-out-of-range",
        Finds("missing-vertex"),
    ),
    ("ply-binary-negative-list-count.ply", "syntax", Unreadable),
    ("ply-count-u64-max.ply", "implausible-header", Unreadable),
    (
        "ply-binary-faces-without-corners.ply",
        "too-few-corners",
        Finds("too-few-vertices"),
    ),
    (
        "ply-binary-one-vertex-face.ply",
        "too-few-corners",
        Finds("too-few-vertices"),
    ),
    // STL
    ("stl-binary-count-too-large.stl", "truncated", Unreadable),
    ("stl-binary-bytes-after-count.stl", "syntax", Unreadable),
    ("stl-ascii-truncated.stl", "truncated", Unreadable),
    ("stl-ascii-four-vertices.stl", "syntax", Unreadable),
    // Its second facet has two corners at one position: welded, it repeats a vertex.
    (
        "stl-degenerate-facet.stl",
        "repeated-vertex",
        Finds("too-few-vertices"),
    ),
];

/// What `topolab check` says about a file.
#[derive(Copy, Clone, Debug)]
enum Check {
    /// It cannot read it: exit code 2.
    Unreadable,
    /// At least this finding: exit code 1.
    Finds(&'static str),
    /// It reads the file with this warning on stderr, then finds this (exit code 1), or
    /// nothing when it is empty (exit code 0).
    Warns(&'static str, &'static str),
    /// It finds nothing: exit code 0.
    Clean,
}
use Check::{Clean, Finds, Unreadable, Warns};

/// Refusals that depend on what a structure can store, not on the file being broken.
const CAPABILITY_REFUSALS: &[&str] = &[
    "not-triangles",
    "coincident-vertices",
    "not-a-grid",
    "non-manifold-vertex",
    "star-too-large",
];

fn corpus(file: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/bad-input")
        .join(file)
}

/// The kind of the first error of the strict pipeline, or "ok".
fn strict_kind(path: &Path) -> &'static str {
    let soup = match io::read(path) {
        Ok(soup) => soup,
        Err(e) => return e.kind(),
    };
    match soup.connectivity().and_then(|c| c.check_vertex_fans(&soup)) {
        Ok(()) => "ok",
        Err(e) => e.kind(),
    }
}

#[test]
fn the_corpus_is_complete_and_every_file_is_in_the_table() {
    let mut on_disk: Vec<String> = std::fs::read_dir(corpus(""))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n != "generate.py")
        .collect();
    on_disk.sort();
    let mut listed: Vec<String> = CORPUS.iter().map(|c| c.0.to_string()).collect();
    listed.sort();
    assert_eq!(on_disk, listed);
    assert!(CORPUS.len() >= 30);
}

#[test]
fn every_corpus_file_gives_its_exact_error_kind() {
    for &(file, expected, _) in CORPUS {
        assert_eq!(strict_kind(&corpus(file)), expected, "{file}");
    }
}

#[test]
fn every_structure_builds_or_refuses_corpus_files_with_a_typed_error() {
    for &(file, expected, _) in CORPUS {
        let Ok(soup) = io::read(&corpus(file)) else {
            continue;
        };
        for (name, outcome) in registry::build_each(&soup) {
            if let Err(e) = outcome {
                assert!(
                    e.kind() == expected || CAPABILITY_REFUSALS.contains(&e.kind()),
                    "{name} refused {file} with {} ({e}); the file's problem is {expected}",
                    e.kind()
                );
            }
        }
    }
}

#[test]
fn check_reports_each_problem_with_its_exit_code() {
    for &(file, _, expected) in CORPUS {
        let out = Command::new(env!("CARGO_BIN_EXE_topolab"))
            .args(["check", "--json"])
            .arg(corpus(file))
            .output()
            .unwrap();
        let code = out.status.code().unwrap();
        let expected = match expected {
            Warns(warning, finds) => {
                let stderr = String::from_utf8_lossy(&out.stderr);
                assert!(stderr.contains(warning), "{file}: {stderr}");
                if finds.is_empty() {
                    assert_eq!(code, 0, "{file}: {stderr}");
                    continue;
                }
                Finds(finds)
            }
            other => other,
        };
        match expected {
            Warns(..) => unreachable!("handled above"),
            Unreadable => assert_eq!(code, 2, "{file}"),
            Clean => assert_eq!(code, 0, "{file}: {}", String::from_utf8_lossy(&out.stderr)),
            Finds(kind) => {
                assert_eq!(code, 1, "{file}");
                let report: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
                let kinds: Vec<&str> = report["findings"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|f| f["kind"].as_str().unwrap())
                    .collect();
                assert!(kinds.contains(&kind), "{file}: {kinds:?}");
                assert_eq!(report["clean"], false);
            }
        }
    }
}

/// The messages of issue 52's corpus files: a long token echoed short with its length, an
/// OBJ index as the file numbers it, a count of u64::MAX as written.
#[test]
fn messages_are_short_and_in_the_files_numbering() {
    for (file, expected) in [
        ("off-nul-bytes.off", "…\" (4096 bytes)"),
        (
            "obj-index-one-based.obj",
            "face 1 refers to vertex 2, but there are 1 vertices (numbered from 1",
        ),
        (
            "ply-count-u64-max.ply",
            "announces 18446744073709551615 vertices",
        ),
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_topolab"))
            .arg("info")
            .arg(corpus(file))
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(expected), "{file}: {stderr}");
        assert!(stderr.len() < 300, "{file}: {stderr}");
    }
}

#[test]
fn an_empty_mesh_is_named_by_check_and_info_in_every_format() {
    for file in [
        "empty.obj",
        "obj-comments-only.obj",
        "off-no-elements.off",
        "ply-no-elements.ply",
    ] {
        let path = corpus(file);
        let check = Command::new(env!("CARGO_BIN_EXE_topolab"))
            .arg("check")
            .arg(&path)
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&check.stdout);
        assert_eq!(check.status.code(), Some(1), "{file}: {text}");
        assert!(text.contains("empty-mesh (1):"), "{file}: {text}");
        assert!(!text.contains("no problems found"), "{file}: {text}");
        for args in [
            &["info"][..],
            &["info", "--json"],
            &["explain", "vertex-list", "--mesh"],
        ] {
            let info = Command::new(env!("CARGO_BIN_EXE_topolab"))
                .args(args)
                .arg(&path)
                .output()
                .unwrap();
            let stderr = String::from_utf8_lossy(&info.stderr);
            assert_eq!(info.status.code(), Some(1), "{file} {args:?}: {stderr}");
            assert!(
                stderr.contains("is an empty mesh: it has no vertices and no faces"),
                "{file} {args:?}: {stderr}"
            );
            assert!(info.stdout.is_empty(), "{file} {args:?}");
        }
    }
}
