//! Command-line values that used to panic, abort or give a wrong answer: each is now a usage
//! error (exit code 2) that names the option, before any work is done.

use std::path::Path;
use std::process::Command;

/// Runs `topolab args...`; returns the exit code (`None`: killed by a signal) and stderr.
fn topolab(args: &[&str]) -> (Option<i32>, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_topolab"))
        .args(args)
        .output()
        .expect("the binary runs");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn corpus(file: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/bad-input")
        .join(file)
        .display()
        .to_string()
}

#[test]
fn report_sizes_the_generators_cannot_build_are_usage_errors() {
    // Past u32 ids (it panicked in `from_spec(..).expect(..)` after the memory probe), and 0.
    for size in ["5000000000", "1073741825", "0"] {
        let (code, stderr) = topolab(&[
            "report",
            "--sizes",
            size,
            "--structures",
            "index-half-edge",
            "--meshes",
            "torus",
            "--out",
            "/nonexistent/never-written",
        ]);
        assert_eq!(code, Some(2), "--sizes {size}: {stderr}");
        assert!(
            stderr.contains(&format!("--sizes {size}")) && !stderr.contains("panicked"),
            "--sizes {size}: {stderr}"
        );
    }
}

#[test]
fn report_probe_sizes_past_what_can_be_allocated_are_usage_errors() {
    // MiB times 2^20 overflowed (a panic in debug builds, a huge allocation in release).
    for mb in ["0", "4097", "18446744073709551615"] {
        let (code, stderr) = topolab(&["report", "--probe-mb", mb, "--out", "/nonexistent/x"]);
        assert_eq!(code, Some(2), "--probe-mb {mb}: {stderr}");
        assert!(stderr.contains("--probe-mb"), "{stderr}");
    }
}

#[test]
fn hull_random_counts_past_u32_are_usage_errors() {
    // It panicked (capacity overflow) or aborted (allocation failure) generating the points.
    for n in ["4294967296", "18446744073709551615"] {
        let (code, stderr) = topolab(&["hull", "--random", n]);
        assert_eq!(code, Some(2), "--random {n}: {stderr}");
        assert!(stderr.contains(&format!("--random {n}")), "{stderr}");
    }
}

#[test]
fn check_tolerances_must_be_finite_and_not_negative() {
    // A NaN planarity tolerance made every comparison false: a non-planar face came out clean.
    let file = corpus("non-planar-face.obj");
    for (option, value) in [
        ("--planarity-tolerance", "nan"),
        ("--planarity-tolerance", "-1"),
        ("--tolerance", "nan"),
        ("--tolerance", "inf"),
        ("--tolerance", "-0.5"),
    ] {
        let (code, stderr) = topolab(&["check", &format!("{option}={value}"), &file]);
        assert_eq!(code, Some(2), "{option} {value}: {stderr}");
        assert!(stderr.contains(option), "{option} {value}: {stderr}");
    }
    let (code, _) = topolab(&["check", "--planarity-tolerance=0.5", &file]);
    assert_eq!(
        code,
        Some(0),
        "a loose planarity tolerance accepts the face"
    );
}

#[test]
fn explain_trace_refuses_what_it_cannot_trace_with_a_clear_error() {
    // (arguments after `explain`, exit code, what stderr names)
    let cases: &[(&[&str], i32, &str)] = &[
        (
            &["vertex-list", "--trace", "r10"],
            2,
            "--trace r10 needs --edge N",
        ),
        (
            &["edge-list", "--trace", "r10", "--edge", "6"],
            2,
            "--edge 6: the mesh has 6 edges",
        ),
        (
            &["che-l2", "--trace", "r00", "--vertex", "4"],
            2,
            "--vertex 4: the mesh has 4 vertices",
        ),
        (
            &["winged-edge", "--trace", "r20", "--face", "3"],
            2,
            "--face 3: the mesh has 3 faces",
        ),
        (
            &[
                "index-half-edge",
                "--trace",
                "edge-successor",
                "--edge",
                "1",
            ],
            2,
            "needs --face N",
        ),
        (
            &["index-half-edge", "--trace", "r99", "--vertex", "0"],
            2,
            "no such operator",
        ),
        (
            &["openmesh", "--trace", "r00", "--vertex", "0"],
            2,
            "C++ baselines",
        ),
        (
            &["no-such", "--trace", "r00", "--vertex", "0"],
            2,
            "no structure",
        ),
        (
            &[
                "vertex-list",
                "--trace",
                "r00",
                "--vertex",
                "0",
                "--structures",
                "x",
            ],
            2,
            "no structure \"x\"",
        ),
        // A structure that refuses the mesh: exit 1, as `explain` without `--trace`.
        (
            &[
                "che-l1",
                "--trace",
                "r00",
                "--vertex",
                "0",
                "--mesh",
                "quad-cube",
            ],
            1,
            "cannot store",
        ),
    ];
    for (args, want, names) in cases {
        let mut all = vec!["explain"];
        all.extend_from_slice(args);
        let (code, stderr) = topolab(&all);
        assert_eq!(code, Some(*want), "{all:?}: {stderr}");
        assert!(stderr.contains(names), "{all:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{all:?}: {stderr}");
    }
}

#[test]
fn explain_trace_answers_every_operator_on_every_structure_on_a_given_mesh() {
    // The default mesh is covered by the harness's tests; here a file-free built-in mesh
    // with boundary and interior, through the binary.
    let out = Command::new(env!("CARGO_BIN_EXE_topolab"))
        .args(["explain", "vertex-list", "--mesh", "annulus", "--trace", "edge-predecessor", "--edge", "2", "--face", "0"])
        .args(["--structures", "explicit,edge-list,winged-edge,pointer-half-edge,index-half-edge,che-l0,che-l1,che-l2,che-l3"])
        .output()
        .expect("the binary runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(text.matches("container reads").count(), 10, "{text}");
    let answers: Vec<&str> = text
        .lines()
        .filter(|l| l.trim_start().starts_with("answer:"))
        .collect();
    assert!(
        answers.windows(2).all(|w| w[0] == w[1]),
        "every structure gives the same predecessor: {answers:?}"
    );
}
