//! `topolab subdivide`: √3 through the editing operations writes a mesh `topolab check` finds
//! clean; polygons and bad requests are refused with nothing written.

use std::process::Command;

fn topolab() -> Command {
    Command::new(env!("CARGO_BIN_EXE_topolab"))
}

#[test]
fn sqrt3_writes_three_faces_per_face_and_level_and_check_finds_it_clean() {
    let dir = std::env::temp_dir().join(format!("topolab-subdivide-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (mesh, levels, faces) in [("torus", "2", 24 * 9), ("grid", "1", 0)] {
        let out = dir.join(format!("{mesh}.off"));
        let run = topolab()
            .args([
                "subdivide",
                mesh,
                "--scheme",
                "sqrt3",
                "--levels",
                levels,
                "--out",
            ])
            .arg(&out)
            .output()
            .unwrap();
        assert!(
            run.status.success(),
            "{}",
            String::from_utf8_lossy(&run.stderr)
        );
        let text = String::from_utf8_lossy(&run.stdout);
        if faces > 0 {
            assert!(text.contains(&format!("{faces} faces")), "{text}");
        }
        let check = topolab().arg("check").arg(&out).output().unwrap();
        assert!(
            check.status.success(),
            "check on {mesh}: {}{}",
            String::from_utf8_lossy(&check.stdout),
            String::from_utf8_lossy(&check.stderr)
        );
    }
    // midpoint and loop are refine's schemes.
    let out = dir.join("loop.obj");
    let run = topolab()
        .args(["subdivide", "torus", "--scheme", "loop", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(String::from_utf8_lossy(&run.stdout).contains("96 faces"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn polygons_bad_schemes_and_non_manifold_input_are_refused_and_nothing_is_written() {
    let out = std::env::temp_dir().join(format!("never-{}.obj", std::process::id()));
    let _ = std::fs::remove_file(&out);
    // (mesh, scheme, exit code, words of the message)
    let cases = [
        ("quad-cube", "sqrt3", 1, "triangle scheme"),
        ("quad-cube", "loop", 1, "corners"),
        ("bowtie", "sqrt3", 1, "non-manifold"),
        ("torus", "butterfly", 2, "unknown scheme"),
    ];
    for (mesh, scheme, code, words) in cases {
        let run = topolab()
            .args(["subdivide", mesh, "--scheme", scheme, "--out"])
            .arg(&out)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(code), "{mesh} {scheme}: {err}");
        assert!(err.contains(words), "{mesh} {scheme}: {err}");
        assert!(!out.exists(), "{mesh} {scheme} wrote a file");
    }
}
