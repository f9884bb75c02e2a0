//! `topolab repair` as the binary: on small hand-made meshes with one problem each, and on the
//! real meshes the report refused as read (when `make data` fetched them), `topolab check`
//! finds none of the problems repair fixed in its output; what cannot be fixed (a
//! non-orientable component) or was skipped remains, with exit code 1.

mod common;

use common::run::{scratch, text, topolab};
use glam::DVec3;
use std::path::{Path, PathBuf};
use std::process::Output;
use topolab_harness::report::repair::measurable;
use topolab_structures::{meshes, PolygonSoup};

/// The findings repair removes, by their names in `topolab check --json`.
const FIXED: [&str; 5] = [
    "duplicate-face",
    "non-manifold-edge",
    "non-manifold-vertex",
    "inconsistent-orientation",
    "unused-vertex",
];

/// The finding kinds `topolab check` reports on `file`, each once.
fn findings(file: &Path) -> Vec<String> {
    let out = topolab(&["check", file.to_str().unwrap(), "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("check --json");
    let mut kinds: Vec<String> = v["findings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["kind"].as_str().unwrap().to_string())
        .collect();
    kinds.dedup();
    kinds
}

/// Repairs `input` into `dir/NAME.repaired.obj` with `extra` arguments; returns the output
/// file and the run.
fn repair(dir: &Path, input: &Path, extra: &[&str]) -> (PathBuf, Output) {
    let stem = input.file_stem().unwrap().to_str().unwrap();
    let out = dir.join(format!("{stem}.repaired.obj"));
    let mut args = vec![
        "repair",
        input.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend(extra);
    (out.clone(), topolab(&args))
}

fn write(dir: &Path, name: &str, soup: &PolygonSoup) -> PathBuf {
    let path = dir.join(name);
    topolab_structures::io::write(&path, soup).unwrap();
    path
}

/// One mesh per problem repair fixes.
fn broken() -> Vec<(&'static str, &'static str, PolygonSoup)> {
    let sphere = meshes::sphere(5, 7);
    let faces: Vec<Vec<u32>> = sphere
        .faces()
        .enumerate()
        .map(|(j, f)| {
            let mut f = f.to_vec();
            if j % 3 == 0 {
                f.reverse();
            }
            f
        })
        .collect();
    let shuffled = PolygonSoup::from_polygons(sphere.positions.clone(), &faces);
    let mut duplicated = meshes::closed_tetrahedron();
    let again: Vec<u32> = duplicated.face(2).iter().rev().copied().collect();
    duplicated.push_face(&again);
    let mut fin = meshes::closed_tetrahedron();
    let (a, b) = (fin.face(0)[0], fin.face(0)[1]);
    let tip = fin.push_vertex(DVec3::new(3.0, 3.0, 3.0)).0;
    fin.push_face(&[b, a, tip]);
    let mut unused = meshes::open_tetrahedron();
    unused.push_vertex(DVec3::splat(7.0));
    vec![
        ("shuffled.off", "inconsistent-orientation", shuffled),
        ("duplicated.off", "duplicate-face", duplicated),
        ("fin.obj", "non-manifold-edge", fin),
        ("bowtie.off", "non-manifold-vertex", meshes::bowtie()),
        ("unused.obj", "unused-vertex", unused),
    ]
}

#[test]
fn each_problem_is_gone_from_the_output() {
    let dir = scratch("repair-each");
    for (name, problem, soup) in broken() {
        let input = write(&dir, name, &soup);
        assert!(findings(&input).iter().any(|k| k == problem), "{name}");
        let (out, run) = repair(&dir, &input, &[]);
        assert_eq!(run.status.code(), Some(0), "{name}: {}", text(&run.stderr));
        let left: Vec<String> = findings(&out)
            .into_iter()
            .filter(|k| FIXED.contains(&k.as_str()))
            .collect();
        assert!(
            left.is_empty(),
            "{name}: {left:?} left\n{}",
            text(&run.stdout)
        );
        // Every structure of the lab that needs an oriented manifold stores it.
        let info = topolab(&["info", out.to_str().unwrap()]);
        assert_eq!(
            info.status.code(),
            Some(0),
            "{name}: {}",
            text(&info.stderr)
        );
        let said = text(&run.stdout);
        assert!(!said.contains("nothing to repair"), "{name}: {said}");
        assert!(
            said.contains("check of the output: no duplicate face"),
            "{said}"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn split_vertices_are_expected_duplicates_and_repair_says_so() {
    let dir = scratch("repair-split");
    let input = write(&dir, "bowtie.off", &meshes::bowtie());
    let (out, run) = repair(&dir, &input, &[]);
    let said = text(&run.stdout);
    assert!(said.contains("split 1 non-manifold vertices"), "{said}");
    assert!(said.contains("expected: the 1 new vertices"), "{said}");
    assert_eq!(findings(&out), ["duplicate-vertices"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn what_remains_is_said_and_exits_1() {
    let dir = scratch("repair-remains");
    // A Möbius strip of four quads: 0-1 across, the last quad joins the first pair twisted.
    let strip = "OFF\n8 4 0\n3 0 0\n3 0 1\n0 3 0\n0 3 1\n-3 0 0\n-3 0 1\n0 -3 0\n0 -3 1\n\
                 4 0 1 3 2\n4 2 3 5 4\n4 4 5 7 6\n4 6 7 0 1\n";
    let input = dir.join("mobius.off");
    std::fs::write(&input, strip).unwrap();
    let (out, run) = repair(&dir, &input, &[]);
    assert_eq!(run.status.code(), Some(1), "{}", text(&run.stderr));
    assert!(out.exists(), "the output is written all the same");
    assert!(text(&run.stdout).contains("non-orientable (1)"));
    let stderr = text(&run.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    // The strip's inconsistent edge and its non-orientability.
    assert!(
        stderr.starts_with("topolab: ") && stderr.contains("2 problems remain"),
        "{stderr}"
    );
    assert!(findings(&out).contains(&"non-orientable".to_string()));

    // A skipped step leaves its problem.
    let (name, problem, soup) = broken().remove(0);
    let input = write(&dir, name, &soup);
    let (out, run) = repair(&dir, &input, &["--skip", "orient,unused-vertices"]);
    assert_eq!(run.status.code(), Some(1));
    assert!(findings(&out).iter().any(|k| k == problem));
    let run = topolab(&[
        "repair",
        input.to_str().unwrap(),
        "--out",
        "x.obj",
        "--skip",
        "nope",
    ]);
    assert_eq!(run.status.code(), Some(2));
    assert!(text(&run.stderr).contains("known: duplicate-faces, split-edges"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The three real meshes the report refused as read, each for one problem.
const REFUSED: [(&str, &str); 3] = [
    ("blobby-shuffled.off", "inconsistent-orientation"),
    ("meshfix-stanford-bunny.ply", "non-manifold-edge"),
    ("meshlab-face000.ply", "non-manifold-vertex"),
];

fn cached(file: &str) -> Option<PathBuf> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("bench-data/cache")
        .join(file);
    if !path.exists() {
        eprintln!("SKIPPED for {file}: bench-data/cache/ does not have it (run `make data`)");
    }
    path.exists().then_some(path)
}

#[test]
fn the_real_meshes_the_report_refused_come_out_clean() {
    let dir = scratch("repair-real");
    for (file, problem) in REFUSED {
        let Some(input) = cached(file) else { continue };
        assert!(findings(&input).iter().any(|k| k == problem), "{file}");
        let (out, run) = repair(&dir, &input, &[]);
        assert_eq!(run.status.code(), Some(0), "{file}: {}", text(&run.stderr));
        let left: Vec<String> = findings(&out)
            .into_iter()
            .filter(|k| FIXED.contains(&k.as_str()))
            .collect();
        assert!(left.is_empty(), "{file}: {left:?}");
        let info = topolab(&["info", out.to_str().unwrap()]);
        assert_eq!(
            info.status.code(),
            Some(0),
            "{file}: {}",
            text(&info.stderr)
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_report_measures_the_refused_real_meshes_repaired() {
    for (file, _) in REFUSED {
        let Some(input) = cached(file) else { continue };
        let soup = topolab_structures::io::read(&input).unwrap();
        assert!(
            soup.connectivity()
                .and_then(|c| c.check_vertex_fans(&soup))
                .is_err(),
            "{file} is refused as read"
        );
        let mut notes = Vec::new();
        let (fixed, log) = measurable(file, soup, &mut notes);
        assert!(log.is_some_and(|l| !l.is_empty()), "{file}");
        fixed
            .connectivity()
            .and_then(|c| c.check_vertex_fans(&fixed))
            .unwrap();
        assert!(notes[0].contains("measured repaired"), "{notes:?}");
    }
}
