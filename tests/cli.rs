//! `topolab info` on mesh files of each format, run as a user would: the binary, a file, JSON.

use std::path::{Path, PathBuf};
use std::process::Command;

/// A fresh directory for this test's files.
fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("topolab-cli-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs `topolab args...`; returns the exit code and stdout.
fn topolab(args: &[&str]) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_topolab"))
        .args(args)
        .output()
        .expect("the binary runs");
    (
        out.status.code().expect("exited normally"),
        String::from_utf8(out.stdout).expect("UTF-8 output"),
    )
}

fn info_json(path: &Path, structure: &str) -> serde_json::Value {
    let (code, stdout) = topolab(&[
        "info",
        path.to_str().unwrap(),
        "--structure",
        structure,
        "--json",
    ]);
    assert_eq!(code, 0, "{}: {stdout}", path.display());
    serde_json::from_str(&stdout).expect("JSON")
}

/// The open tetrahedron of the CHE chapter (apex 3) in each format.
const OBJ: &str = "# open tetrahedron\no tet\nv 0 0 0\nv 1 0 0\nv 0.5 0.8 0\nv 0.5 0.3 0.8\n\
    vn 0 0 1\nf 1//1 2//1 4//1\nf 2 3 4\nf -2 -4 -1\n";
const OFF: &str = "OFF\n4 3 6\n0 0 0\n1 0 0\n0.5 0.8 0\n0.5 0.3 0.8\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";
const PLY: &str = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n\
    property float z\nelement face 3\nproperty list uchar int vertex_indices\nend_header\n\
    0 0 0\n1 0 0\n0.5 0.8 0\n0.5 0.3 0.8\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";

#[test]
fn info_reads_obj_off_and_ply_files_with_every_structure() {
    let dir = temp_dir("formats");
    for (name, text) in [("tet.obj", OBJ), ("tet.off", OFF), ("tet.ply", PLY)] {
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        for structure in ["vertex-list", "explicit"] {
            let v = info_json(&path, structure);
            let facts = [
                ("vertices", 4),
                ("edges", 6),
                ("faces", 3),
                ("boundary_edges", 3),
                ("boundary_curves", 1),
                ("euler_characteristic", 1),
            ];
            for (field, expected) in facts {
                assert_eq!(v[field], expected, "{name} {structure} {field}");
            }
            assert_eq!(v["structure"], structure, "{name}");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The soup of issue #38: five triangles on nine vertices, five vertices with two fans.
const TWO_FANS: &str = "v 0.489 0.908 0.338\nv 0.459 0.350 0.807\nv 0.333 0.137 0.488\n\
    v 0.805 0.072 0.618\nv 0.046 0.757 0.986\nv 0.349 0.004 0.378\nv 0.089 0.465 0.541\n\
    v 0.024 0.362 0.010\nv 0.110 0.924 0.916\nf 3 7 6\nf 4 7 9\nf 5 1 4\nf 2 5 6\nf 3 1 7\n";

/// Every structure of this build that stores the two-fan soup prints the same `info --json`
/// apart from its name (the others refuse it with exit code 1): four boundary curves, one per
/// fan's boundary, and a genus that is undefined, with the same reason for all.
#[test]
fn info_gives_one_answer_from_every_structure_that_stores_a_non_manifold_mesh() {
    let dir = temp_dir("two-fans");
    let path = dir.join("two-fans.obj");
    std::fs::write(&path, TWO_FANS).unwrap();
    let mut answers = Vec::new();
    for &structure in topolab::registry::NAMES {
        let (code, stdout) = topolab(&[
            "info",
            path.to_str().unwrap(),
            "--structure",
            structure,
            "--json",
        ]);
        if code == 1 {
            continue;
        }
        assert_eq!(code, 0, "{structure}: {stdout}");
        let mut v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
        v["structure"] = "".into();
        answers.push((structure, v));
    }
    let stored: Vec<&str> = answers.iter().map(|(s, _)| *s).collect();
    assert!(
        stored.contains(&"explicit") && stored.contains(&"edge-list"),
        "{stored:?}"
    );
    let (first, expected) = &answers[0];
    assert_eq!(expected["boundary_curves"], 4);
    assert_eq!(expected["genus"], serde_json::Value::Null);
    assert_eq!(
        expected["genus_undefined"],
        "5 vertices whose faces form several fans"
    );
    for (structure, v) in &answers {
        assert_eq!(v, expected, "{structure} and {first} differ");
    }
    let (_, text) = topolab(&["info", path.to_str().unwrap(), "--structure", "vertex-list"]);
    assert!(
        text.contains("genus:                undefined (5 vertices whose faces form several fans)"),
        "{text}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `topolab info FILE`'s exit code and stderr.
fn info_stderr(file: &Path) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_topolab"))
        .args(["info", file.to_str().unwrap()])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    (out.status.code().expect("exited normally"), stderr)
}

/// A file that reads but is not a mesh the structure can store: the message says why and
/// where to go next (`check` for every problem, `repair` for the manifold ones); a file with
/// statements the reader skips says so on stderr and is read.
#[test]
fn messages_point_to_check_and_repair_and_skipped_statements_are_warned() {
    let dir = temp_dir("hints");
    let bowtie = dir.join("bowtie.obj");
    std::fs::write(
        &bowtie,
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nf 1 2 3\nf 1 4 5\n",
    )
    .unwrap();
    let (code, stderr) = info_stderr(&bowtie);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("non-manifold"), "{stderr}");
    assert!(stderr.contains("`topolab check "), "{stderr}");
    assert!(stderr.contains("`topolab repair "), "{stderr}");
    let coloured = dir.join("coloured.obj");
    std::fs::write(
        &coloured,
        "v 0 0 0\nvc 1 0 0\nv 1 0 0\nvc 0 1 0\nv 0 1 0\nvc 0 0 1\nf 1 2 3\n",
    )
    .unwrap();
    let (code, stderr) = info_stderr(&coloured);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(
        stderr.trim(),
        format!(
            "topolab: warning: {}: skipped 3 times unknown OBJ statement \"vc\", first at line 2",
            coloured.display()
        )
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `convert` writes every format the lab writes and reads back what it wrote: a torus through
/// binary STL (corners welded back into its vertices, which `info` notes), then OBJ, then OFF
/// named by `--to`; PLY output and unknown formats are usage errors.
#[test]
fn convert_round_trips_through_stl_obj_and_off() {
    let dir = temp_dir("convert");
    let stl = dir.join("torus.stl");
    let (code, stdout) = topolab(&["convert", "torus:200", stl.to_str().unwrap()]);
    assert_eq!(code, 0, "{stdout}");
    assert!(stdout.contains("as STL"), "{stdout}");
    let original = info_json(Path::new("torus:200"), "index-half-edge");
    let out = Command::new(env!("CARGO_BIN_EXE_topolab"))
        .args(["info", stl.to_str().unwrap(), "--json"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("STL corners welded"), "{stderr}");
    let from_stl: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    for field in ["vertices", "edges", "faces", "genus", "boundary_curves"] {
        assert_eq!(from_stl[field], original[field], "{field}");
    }
    let obj = dir.join("torus.obj");
    let txt = dir.join("torus.txt");
    assert_eq!(
        topolab(&["convert", stl.to_str().unwrap(), obj.to_str().unwrap()]).0,
        0
    );
    let (code, stdout) = topolab(&[
        "convert",
        obj.to_str().unwrap(),
        txt.to_str().unwrap(),
        "--to",
        "off",
    ]);
    assert_eq!(code, 0, "{stdout}");
    assert!(std::fs::read_to_string(&txt).unwrap().starts_with("OFF"));
    // PLY, binary and ASCII, reads back as the mesh it was written from.
    for more in [&[][..], &["--ascii"]] {
        let ply = dir.join("torus.ply");
        let (code, stdout) =
            topolab(&[&["convert", "torus:200", ply.to_str().unwrap()][..], more].concat());
        assert_eq!(code, 0, "{stdout}");
        let back = topolab_structures::io::read(&ply).unwrap();
        assert_eq!(
            back,
            topolab_structures::meshes::from_spec("torus:200").unwrap()
        );
        std::fs::remove_file(&ply).unwrap();
    }
    // A point cloud written as STL would read back empty: refused, nothing written.
    let stl_cloud = dir.join("cloud.stl");
    std::fs::write(dir.join("cloud.obj"), "v 0 0 0\nv 1 0 0\n").unwrap();
    assert_eq!(
        topolab(&[
            "convert",
            dir.join("cloud.obj").to_str().unwrap(),
            stl_cloud.to_str().unwrap()
        ])
        .0,
        1
    );
    assert!(!stl_cloud.exists(), "a refused write leaves no file");
    assert_eq!(
        topolab(&["convert", "torus:200", txt.to_str().unwrap(), "--to", "dxf"]).0,
        2
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn info_exits_2_on_an_unreadable_file_and_1_on_a_non_manifold_mesh() {
    let dir = temp_dir("exit-codes");
    let unreadable = dir.join("bad.off");
    std::fs::write(&unreadable, "OFF\n3 1 0\n0 0 0\n1 oops 0\n").unwrap();
    // Three triangles on one edge (0, 1).
    let fin = dir.join("fin.obj");
    std::fs::write(
        &fin,
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n",
    )
    .unwrap();
    assert_eq!(topolab(&["info", unreadable.to_str().unwrap()]).0, 2);
    assert_eq!(topolab(&["info", fin.to_str().unwrap()]).0, 1);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn check_exits_0_on_a_clean_file_and_reports_its_topology() {
    let dir = temp_dir("check");
    let path = dir.join("tet.off");
    std::fs::write(&path, OFF).unwrap();
    let (code, stdout) = topolab(&["check", path.to_str().unwrap()]);
    assert_eq!(code, 0, "{stdout}");
    assert!(stdout.contains("no problems found"), "{stdout}");
    let (code, stdout) = topolab(&["check", path.to_str().unwrap(), "--json"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(v["clean"], true);
    let s = &v["summary"];
    assert_eq!(
        (s["edges"].as_u64(), s["boundary_curves"].as_u64()),
        (Some(6), Some(1))
    );
    assert_eq!(s["components"][0]["euler_characteristic"], 1);
    assert_eq!(s["components"][0]["genus"], 0);
    assert_eq!(
        topolab(&["check", dir.join("none.obj").to_str().unwrap()]).0,
        2
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_reader_that_stops_early_ends_the_output_without_a_panic() {
    use std::io::Read as _;
    use std::process::Stdio;
    // Megabytes of containers: far more than a pipe holds, so the writes after the reader
    // is gone fail with a broken pipe whenever the reader stops.
    let mut child = Command::new(env!("CARGO_BIN_EXE_topolab"))
        .args(["explain", "index-half-edge", "--mesh", "torus:20000"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 16];
    child.stdout.take().unwrap().read_exact(&mut first).unwrap();
    // The read end is dropped here, as `head -c 16` would exit.
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
}
