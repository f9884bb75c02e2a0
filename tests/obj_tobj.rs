//! The lab's OBJ reader against an independent one, `tobj`: every OBJ file of the bad-input
//! corpus and of `bench-data/cache/` (when `make data` fetched it) is read by both, and the
//! positions and faces compared, so a bug in either reader shows as a disagreement.
//!
//! The lab keeps its own reader (the file's vertex order, unused vertices, line numbers in
//! errors, a typed error for what tobj silently accepts), so `tobj` is only this cross-check.
//! It is asked for the file as written: no triangulation, and separate position indices
//! (`single_index` would split a position per (position, texture, normal) triple, which the
//! lab does not keep). tobj then cuts the file into models at `o`, `g` and material changes,
//! and numbers each model's vertices in the order its faces first use them, dropping unused
//! ones; the comparison maps those per-model indices back to the file's through the lab's
//! faces, which are in file order.
//!
//! The lab compared is its raw reader (`topolab check`'s: it keeps out-of-range indices and
//! non-finite coordinates as findings), and where its strict reader accepts a file, the
//! strict soup must be the raw one.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use topolab_structures::io;
use topolab_structures::PolygonSoup;

/// Files the two readers treat differently on purpose, and why; each must still differ.
const DELIBERATE: &[(&str, &str)] = &[
    (
        "obj-index-out-of-range.obj",
        "the lab's raw reader keeps the index for `check` to report; tobj refuses the file",
    ),
    (
        "obj-negative-out-of-range.obj",
        "the lab's raw reader keeps the index for `check` to report; tobj refuses the file",
    ),
    (
        "obj-index-zero.obj",
        "the lab's raw reader keeps the index for `check` to report; tobj refuses the file",
    ),
    (
        "obj-index-overflows-u32.obj",
        "the lab's raw reader keeps the index for `check` to report; tobj refuses the file",
    ),
    (
        "obj-index-overflows-i64.obj",
        "the lab's raw reader keeps the index for `check` to report; tobj refuses the file",
    ),
    (
        "obj-index-one-based.obj",
        "the lab's raw reader keeps the index for `check` to report; tobj refuses the file",
    ),
];

/// The OBJ files of `dir`, sorted (none when it does not exist).
fn obj_files(dir: &Path) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|d| {
            d.filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "obj"))
                .collect()
        })
        .unwrap_or_default();
    files.sort();
    files
}

/// tobj's reading of the file as written.
fn tobj_read(path: &Path) -> Result<Vec<tobj::Model>, tobj::LoadError> {
    let options = tobj::LoadOptions {
        single_index: false,
        triangulate: false,
        ignore_points: false,
        ignore_lines: false,
    };
    tobj::load_obj(path, &options).map(|(models, _materials)| models)
}

fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

/// The first disagreement between the lab's soup and tobj's models, if any.
fn disagreement(soup: &PolygonSoup, models: &[tobj::Model]) -> Option<String> {
    let mut faces = soup.faces().enumerate();
    for model in models {
        let mesh = &model.mesh;
        let arities: Vec<usize> = if mesh.face_arities.is_empty() {
            vec![3; mesh.indices.len() / 3]
        } else {
            mesh.face_arities.iter().map(|&a| a as usize).collect()
        };
        // The model's vertex numbering: file vertex -> tobj index, by first use.
        let mut local: HashMap<u32, u32> = HashMap::new();
        let mut offset = 0;
        for arity in arities {
            let Some((j, face)) = faces.next() else {
                return Some(format!(
                    "tobj has more faces than the lab's {}",
                    soup.num_faces()
                ));
            };
            if face.len() != arity {
                return Some(format!(
                    "face {j}: the lab reads {} corners, tobj {arity} (model {:?})",
                    face.len(),
                    model.name
                ));
            }
            for (k, &v) in face.iter().enumerate() {
                let next = local.len() as u32;
                let expected = *local.entry(v).or_insert(next);
                let got = mesh.indices[offset + k];
                if got != expected {
                    return Some(format!(
                        "face {j} corner {k}: the lab reads vertex {v}, tobj another one (its index {got}, expected {expected})"
                    ));
                }
                let p = soup.positions[v as usize].to_array();
                let q = &mesh.positions[3 * got as usize..3 * got as usize + 3];
                if !(0..3).all(|i| same(p[i], q[i])) {
                    return Some(format!(
                        "vertex {v}: the lab reads {p:?}, tobj {q:?} (face {j} corner {k})"
                    ));
                }
            }
            offset += arity;
        }
        if mesh.positions.len() != 3 * local.len() || offset != mesh.indices.len() {
            return Some(format!(
                "model {:?}: tobj holds {} positions and {} indices, its faces use {} and {offset}",
                model.name,
                mesh.positions.len() / 3,
                mesh.indices.len(),
                local.len()
            ));
        }
    }
    faces
        .next()
        .map(|(j, _)| format!("the lab reads face {j} and more; tobj stops before"))
}

/// Reads `path` with both; `Ok(faces compared)`, or the disagreement.
fn cross_check(path: &Path) -> Result<usize, String> {
    let name = path.display();
    match (io::read_raw(path), tobj_read(path)) {
        (Ok(raw), Ok(models)) => {
            if let Some(d) = disagreement(&raw.soup, &models) {
                return Err(format!("{name}: {d}"));
            }
            if let Ok(strict) = io::read(path) {
                assert_eq!(strict.positions, raw.soup.positions, "{name}");
                assert!(strict.faces().eq(raw.soup.faces()), "{name}");
            }
            Ok(raw.soup.num_faces())
        }
        // Broken for both (syntax, truncation): nothing to compare.
        (Err(_), Err(_)) => Ok(0),
        (Err(e), Ok(_)) => Err(format!("{name}: the lab refuses it ({e}), tobj reads it")),
        (Ok(_), Err(e)) => Err(format!("{name}: tobj refuses it ({e}), the lab reads it")),
    }
}

#[test]
fn every_corpus_obj_reads_the_same_with_tobj_or_differs_on_purpose() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad-input");
    let files = obj_files(&dir);
    assert!(files.len() >= 20, "{} OBJ files in the corpus", files.len());
    let mut compared = 0;
    for path in &files {
        let file = path.file_name().unwrap().to_str().unwrap();
        let outcome = cross_check(path);
        match DELIBERATE.iter().find(|d| d.0 == file) {
            Some((_, why)) => assert!(
                outcome.is_err(),
                "{file} was listed as differing on purpose ({why}), but both read it alike"
            ),
            None => compared += outcome.unwrap_or_else(|e| panic!("{e}")),
        }
    }
    // Not only files both refuse: the corpus's meshes were compared face by face.
    assert!(compared >= 20, "{compared} faces compared");
}

#[test]
fn a_file_with_every_statement_the_lab_reads_or_skips_reads_the_same_with_tobj() {
    // Objects, groups and materials (tobj: several models), texture and normal indices,
    // negative (relative) indices, a `w` of 1, a polygon, an unused vertex between used ones,
    // smoothing groups and comments. Not `l`/`p` (tobj makes faces of them), a `w` other than
    // 1 (tobj divides by it; the lab ignores it), nor colours on some vertices only (tobj
    // refuses them).
    let text = "# every statement\nmtllib absent.mtl\no first\nv 0 0 0\nv 1 0 0 1\n\
        v 1 1 0\nv 0 1 0\nv 9 9 9\nvt 0 0\nvt 1 0\nvn 0 0 1\n\
        g side\nusemtl a\nf 1/1/1 2/2/1 3/2/1 4/1/1\ns 1\nusemtl b\nf -5//1 -3//1 -2//1\n\
        o second\nv 0 0 -1e-3\nv 2.5e2 0 1\nf 1/1 2/2 -1/1\nf -2 -1 4 3\ng\nf 7 6 2 1 4\n";
    let path = std::env::temp_dir().join(format!("topolab-tobj-{}.obj", std::process::id()));
    std::fs::write(&path, text).unwrap();
    let models = tobj_read(&path).unwrap();
    assert!(models.len() >= 3, "{} models", models.len());
    assert_eq!(cross_check(&path), Ok(5));
    std::fs::remove_file(&path).unwrap();
}

#[test]
fn every_obj_of_bench_data_reads_the_same_with_tobj() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("bench-data/cache");
    let files = obj_files(&dir);
    if files.is_empty() {
        eprintln!(
            "SKIPPED every_obj_of_bench_data_reads_the_same_with_tobj: bench-data/cache/ has no OBJ file (run `make data`); the corpus test still ran"
        );
        return;
    }
    for path in &files {
        let faces = cross_check(path).unwrap_or_else(|e| panic!("{e}"));
        assert!(faces > 0, "{}: no faces compared", path.display());
        eprintln!("{}: {faces} faces agree", path.display());
    }
}

#[test]
fn the_comparison_catches_a_reader_that_drops_or_moves_something() {
    // The cross-check itself must fail on a wrong reading: a moved vertex, a face with a
    // corner swapped, a missing face.
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad-input/mobius.obj");
    let raw = io::read_raw(&path).unwrap().soup;
    let models = tobj_read(&path).unwrap();
    assert_eq!(disagreement(&raw, &models), None);
    let mut moved = raw.clone();
    moved.positions[3].x += 1e-12;
    assert!(disagreement(&moved, &models).is_some_and(|d| d.contains("vertex 3")));
    let faces: Vec<Vec<u32>> = raw.faces().map(|f| f.to_vec()).collect();
    let rebuild = |faces: &[Vec<u32>]| {
        let mut s = PolygonSoup::from_polygons(raw.positions.clone(), &[] as &[[u32; 3]]);
        for f in faces {
            s.push_face(f);
        }
        s
    };
    let mut swapped = faces.clone();
    swapped[2].swap(0, 1);
    assert!(disagreement(&rebuild(&swapped), &models).is_some_and(|d| d.contains("face 2")));
    assert!(disagreement(&rebuild(&faces[1..]), &models).is_some());
}
