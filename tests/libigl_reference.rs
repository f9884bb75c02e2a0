//! `python/libigl_reference.py` (libigl's own adjacency functions) gives the lab's
//! checksums. Skipped, with a message, when `.venv/bin/python` or libigl is missing
//! (`bash .ci/install-deps` makes them).

mod common;

use common::{checksum, close, uniform_vertex_normals_sum};
use std::path::{Path, PathBuf};
use std::process::Command;
use topolab_harness::results::Subject;
use topolab_structures::{meshes, MeshTopology, PolygonSoup, VertexList, Workload};

/// The venv's python, if it can import libigl.
fn python_with_libigl() -> Option<PathBuf> {
    let python = Path::new(env!("CARGO_MANIFEST_DIR")).join(".venv/bin/python");
    let imports = Command::new(&python)
        .args(["-c", "import igl, numpy"])
        .output()
        .ok()?;
    imports.status.success().then_some(python)
}

/// Runs the reference script on `soup` (written as OBJ) and returns its JSON report.
fn run_reference(python: &Path, name: &str, soup: &PolygonSoup) -> serde_json::Value {
    let dir = std::env::temp_dir().join(format!("topolab-libigl-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (mesh, json) = (
        dir.join(format!("{name}.obj")),
        dir.join(format!("{name}.json")),
    );
    topolab_structures::io::write(&mesh, soup).unwrap();
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("python/libigl_reference.py");
    let run = Command::new(python)
        .arg(&script)
        .arg(&mesh)
        .arg("--out")
        .arg(&json)
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{} failed on {name}: {}",
        script.display(),
        String::from_utf8_lossy(&run.stderr)
    );
    let report = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    std::fs::remove_dir_all(&dir).ok();
    report
}

#[test]
fn libigl_gives_the_checksums_of_the_lab() {
    let Some(python) = python_with_libigl() else {
        common::report_skip(
            "libigl reference",
            ".venv/bin/python with libigl is missing (run `bash .ci/install-deps`)",
        );
        return;
    };
    for (name, soup) in [
        ("torus", meshes::torus(9, 5)),
        ("grid", meshes::grid(5, 4, true)),
    ] {
        let lab = VertexList::from_soup(&soup).unwrap();
        let report = run_reference(&python, name, &soup);
        assert_eq!(report["triangles"], soup.num_faces());
        let results = report["results"].as_array().unwrap();
        let mut seen = Vec::new();
        for result in results {
            let operator = result["operator"].as_str().unwrap();
            assert!(result["seconds"].as_f64().unwrap() >= 0.0);
            seen.push(operator.to_string());
            let op = match Subject::from_name(operator) {
                Some(Subject::Query(op)) => op,
                Some(Subject::Workload(Workload::Normals)) => {
                    let value = result["value"].as_f64().unwrap();
                    let expected = uniform_vertex_normals_sum(&soup);
                    assert!(
                        close(value, expected),
                        "normals on {name}: {value} vs {expected}"
                    );
                    continue;
                }
                other => panic!("{operator}: not an operator libigl answers ({other:?})"),
            };
            assert_eq!(
                result["checksum"].as_str().unwrap(),
                checksum(&lab, op).to_string(),
                "{operator} ({}) on {name}",
                result["function"]
            );
        }
        assert_eq!(
            seen,
            ["r00", "r02", "r10", "r22", "boundary-curves", "normals"],
            "operators reported on {name}"
        );
    }
}
