//! A differential suite of the lab's readers against OpenMesh's own (`IO::read_mesh`), on every
//! OBJ, OFF, PLY and STL test file OpenMesh ships with its unit tests (in the pinned source the
//! baselines compile, `third_party/openmesh/src/Unittests/TestFiles`). Per file: both read it
//! and agree on the vertices (in order, positions within float precision) and the faces (in
//! order, each up to where its cycle starts), or the difference is one stated in `DIFFERENT`
//! with its reason, and the test checks that it still differs (so the table stays true).

mod common;

#[cfg(has_openmesh)]
mod with_openmesh {
    use std::path::{Path, PathBuf};
    use topolab_baselines::openmesh::read::read_file;
    use topolab_structures::io;
    use topolab_structures::testing::oracle::canonical_face;
    use topolab_structures::PolygonSoup;

    /// Files the lab and OpenMesh read differently on purpose, with the reason.
    const DIFFERENT: &[(&str, &str)] = &[(
        "cube-minimal-degenerated.obj",
        "faces that repeat a vertex (`f 2 6 8 8 2`, `f 2 2 2`, `f 2 8 2`): OpenMesh's reader \
         drops the repeated corners and the faces left with fewer than three (12 faces); the \
         lab's raw reader keeps the file as written (14 faces), so that `topolab check` names \
         each such face, and its checked reader refuses the file with the first one",
    )];

    fn test_files() -> Vec<PathBuf> {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../third_party/openmesh/src/Unittests/TestFiles");
        let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
            .unwrap_or_else(|e| {
                panic!(
                    "{}: {e} (run `python3 third_party/fetch.py`)",
                    dir.display()
                )
            })
            .map(|e| e.unwrap().path())
            .filter(|p| {
                let ext = p.extension().and_then(|e| e.to_str()).unwrap_or("");
                ["obj", "off", "ply", "stl"].contains(&ext.to_ascii_lowercase().as_str())
            })
            .collect();
        files.sort();
        files
    }

    /// Where the two readings differ, or `None`.
    fn difference(lab: &PolygonSoup, om: &PolygonSoup) -> Option<String> {
        if lab.num_vertices() != om.num_vertices() || lab.num_faces() != om.num_faces() {
            return Some(format!(
                "the lab reads {} vertices and {} faces, OpenMesh {} and {}",
                lab.num_vertices(),
                lab.num_faces(),
                om.num_vertices(),
                om.num_faces()
            ));
        }
        for (i, (p, q)) in lab.positions.iter().zip(&om.positions).enumerate() {
            // OpenMesh's readers parse single precision for some formats.
            if (*p - *q).abs().max_element() > 1e-5 * (1.0 + p.abs().max_element()) {
                return Some(format!("vertex {i}: the lab reads {p}, OpenMesh {q}"));
            }
        }
        for (j, (f, g)) in lab.faces().zip(om.faces()).enumerate() {
            if canonical_face(f) != canonical_face(g) {
                return Some(format!("face {j}: the lab reads {f:?}, OpenMesh {g:?}"));
            }
        }
        None
    }

    /// The two readings of `path`: `Ok(faces compared)`, or how they differ.
    fn compare(path: &Path) -> Result<usize, String> {
        match (io::read_raw(path), read_file(path)) {
            (Ok(raw), Ok(om)) => match difference(&raw.soup, &om) {
                Some(d) => Err(d),
                None => Ok(raw.soup.num_faces()),
            },
            (Err(e), Ok(_)) => Err(format!("the lab refuses it ({e}), OpenMesh reads it")),
            (Ok(_), Err(e)) => Err(format!("OpenMesh refuses it ({e}), the lab reads it")),
            (Err(_), Err(_)) => Ok(0),
        }
    }

    #[test]
    fn every_openmesh_test_file_reads_as_openmesh_reads_it_or_differs_on_purpose() {
        let files = test_files();
        assert!(files.len() >= 20, "{} test files", files.len());
        let mut compared = 0;
        let mut unexpected = Vec::new();
        for path in &files {
            let file = path.file_name().unwrap().to_str().unwrap();
            let outcome = compare(path);
            match (DIFFERENT.iter().find(|d| d.0 == file), outcome) {
                (Some((_, why)), Ok(_)) => unexpected.push(format!(
                    "{file} is listed as differing ({why}) but both read it alike"
                )),
                (Some(_), Err(_)) => {}
                (None, Ok(faces)) => compared += faces,
                (None, Err(d)) => unexpected.push(format!("{file}: {d}")),
            }
        }
        assert!(unexpected.is_empty(), "{}", unexpected.join("\n"));
        assert!(compared >= 100, "{compared} faces compared");
    }
}

#[cfg(not(has_openmesh))]
#[test]
fn skipped_openmesh_not_compiled_in() {
    common::report_skip(
        "OpenMesh's readers on its test files",
        topolab_baselines::OPENMESH_MISSING,
    );
}
