//! `topolab decimate`: writes a mesh `topolab check` finds clean with at most the faces asked
//! for; polygons, non-manifold input, targets below the topology's minimum and bad requests are
//! refused with nothing written.

use std::path::Path;
use std::process::{Command, Output};

fn topolab() -> Command {
    Command::new(env!("CARGO_BIN_EXE_topolab"))
}

fn decimate(mesh: &str, target: &[&str], out: &Path, extra: &[&str]) -> Output {
    topolab()
        .arg("decimate")
        .arg(mesh)
        .args(target)
        .arg("--out")
        .arg(out)
        .args(extra)
        .output()
        .unwrap()
}

fn faces_in_off(path: &Path) -> usize {
    let text = std::fs::read_to_string(path).unwrap();
    let counts = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .nth(1)
        .unwrap()
        .to_string();
    counts.split_whitespace().nth(1).unwrap().parse().unwrap()
}

#[test]
fn decimation_writes_a_clean_mesh_with_at_most_the_faces_asked_for() {
    let dir = std::env::temp_dir().join(format!("topolab-decimate-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let both = ["lazy", "eager"];
    let cases = [
        (
            "torus:2000",
            vec!["--ratio", "0.1"],
            "index-half-edge",
            &both[..],
        ),
        (
            "sphere:1000",
            vec!["--faces", "100"],
            "pointer-half-edge",
            &both[..],
        ),
        // Flat regions: only the lazy strategy's normal test keeps all their triangles' area,
        // which `check` asks of the file.
        (
            "genus:2:2000",
            vec!["--faces", "300"],
            "index-half-edge",
            &both[..1],
        ),
    ];
    let runs = cases
        .iter()
        .flat_map(|(mesh, target, structure, strategies)| {
            strategies
                .iter()
                .map(move |&s| (*mesh, target, *structure, s))
        });
    for (mesh, target, structure, strategy) in runs {
        let out = dir.join(format!("{structure}-{strategy}.off"));
        let run = decimate(
            mesh,
            target,
            &out,
            &["--structure", structure, "--strategy", strategy],
        );
        assert!(
            run.status.success(),
            "{mesh}: {}",
            String::from_utf8_lossy(&run.stderr)
        );
        // "{mesh}: B faces decimated to A by ..."
        let text = String::from_utf8_lossy(&run.stdout).to_string();
        let words: Vec<&str> = text.split_whitespace().collect();
        let before: usize = words[1].parse().unwrap();
        let after: usize = words[5].parse().unwrap();
        let most = match target[0] {
            "--ratio" => (0.1 * before as f64).round() as usize,
            _ => target[1].parse().unwrap(),
        };
        assert_eq!(faces_in_off(&out), after, "{mesh}: {text}");
        assert!(
            after <= most && after + 2 >= most,
            "{mesh}: {after} faces for a target of {most}"
        );
        let check = topolab().arg("check").arg(&out).output().unwrap();
        assert!(
            check.status.success(),
            "check on the decimated {mesh}: {}{}",
            String::from_utf8_lossy(&check.stdout),
            String::from_utf8_lossy(&check.stderr)
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_input_and_bad_requests_are_refused_and_nothing_is_written() {
    let dir = std::env::temp_dir().join(format!("topolab-decimate-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("out.off");
    // mesh, target, more arguments, exit code, what the message says.
    type Case<'a> = (&'a str, Vec<&'a str>, Vec<&'a str>, i32, &'a str);
    let cases: [Case; 9] = [
        ("quad-grid", vec!["--faces", "4"], vec![], 1, "corners"),
        ("bowtie", vec!["--faces", "1"], vec![], 1, "cannot decimate"),
        ("torus", vec!["--faces", "13"], vec![], 1, "at least 14"),
        (
            "closed-tetrahedron",
            vec!["--faces", "3"],
            vec![],
            1,
            "at least 4",
        ),
        ("torus", vec!["--ratio", "1.5"], vec![], 2, "(0, 1]"),
        // A structure without editing operations: the refusal says which structures decimate.
        (
            "torus",
            vec!["--faces", "20"],
            vec!["--structure", "explicit"],
            2,
            "it does not offer both the edge collapse a decimation makes and the vertex split that undoes it (not offered",
        ),
        (
            "torus",
            vec!["--faces", "20"],
            vec!["--structure", "nope"],
            2,
            "unknown structure",
        ),
        (
            "torus",
            vec!["--faces", "20"],
            vec!["--strategy", "greedy"],
            2,
            "the strategies are eager, lazy",
        ),
        (
            "torus",
            vec!["--faces", "10", "--ratio", "0.5"],
            vec![],
            2,
            "cannot be used",
        ),
    ];
    for (mesh, target, extra, code, says) in cases {
        let run = decimate(mesh, &target, &out, &extra);
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(code), "{mesh} {target:?}: {stderr}");
        assert!(stderr.contains(says), "{mesh} {target:?}: {stderr}");
        assert!(!out.exists(), "{mesh} {target:?} wrote a file");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
