//! Levels of detail you can step through: `topolab decimate --levels` writes a folder,
//! `topolab reconstruct` rebuilds any level and the original from its coarse mesh and collapse
//! record alone. The original rebuilt must be byte for byte the folder's `original.obj`, and
//! that file must be the input itself (checked here with this file's own reading: every
//! vertex at its id with its position's bits, the same oriented faces); each level rebuilt must
//! be byte for byte its level file. Bad records and requests are refused with nothing written.

mod common;

use common::run::{scratch, text, topolab};
use std::path::Path;
use topolab_structures::{meshes, PolygonSoup};

/// Reads a mesh file with the lab's reader.
fn read(path: &Path) -> PolygonSoup {
    topolab_structures::io::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// `soup`'s faces, each rotated to start at its smallest vertex, sorted: the face set.
fn face_set(soup: &PolygonSoup) -> Vec<Vec<u32>> {
    let mut faces: Vec<Vec<u32>> = soup
        .faces()
        .map(|f| {
            let i = (0..f.len()).min_by_key(|&i| f[i]).unwrap();
            f[i..].iter().chain(&f[..i]).copied().collect()
        })
        .collect();
    faces.sort();
    faces
}

fn bits(soup: &PolygonSoup) -> Vec<[u64; 3]> {
    soup.positions
        .iter()
        .map(|p| p.to_array().map(f64::to_bits))
        .collect()
}

/// Runs `topolab` with `args`; its stdout, or a panic with its stderr.
fn ok(args: &[&str]) -> String {
    let run = topolab(args);
    assert!(
        run.status.success(),
        "topolab {args:?}: {}",
        text(&run.stderr)
    );
    text(&run.stdout)
}

/// Decimates `mesh` through `levels` into `dir`, checks `original.obj` against `input` (the
/// mesh as read independently), and rebuilds the original and every level with each of
/// `structures`: byte for byte the folder's files.
fn steps_back(mesh: &str, input: &PolygonSoup, levels: &str, dir: &Path, structures: &[&str]) {
    let lod = dir.join("lod");
    let lod_s = lod.to_str().unwrap();
    ok(&["decimate", mesh, "--levels", levels, "--out", lod_s]);
    let original = read(&lod.join("original.obj"));
    assert_eq!(bits(&original), bits(input), "{mesh}: positions by id");
    assert_eq!(face_set(&original), face_set(input), "{mesh}: faces");
    let count = levels.split(',').count();
    let level_files: Vec<_> = (1..=count)
        .map(|i| lod.join(format!("level-{i}.obj")))
        .collect();
    assert_eq!(
        std::fs::read(lod.join("coarse.obj")).unwrap(),
        std::fs::read(level_files.last().unwrap()).unwrap(),
        "{mesh}: the coarse mesh is the last level"
    );
    let mut before = input.num_faces();
    for structure in structures {
        let out = dir.join(format!("{structure}.obj"));
        let out_s = out.to_str().unwrap();
        ok(&[
            "reconstruct",
            lod_s,
            "--out",
            out_s,
            "--structure",
            structure,
        ]);
        assert_eq!(
            std::fs::read(&out).unwrap(),
            std::fs::read(lod.join("original.obj")).unwrap(),
            "{mesh} on {structure}: the original rebuilt"
        );
        for (i, file) in level_files.iter().enumerate() {
            let level = read(file);
            assert!(level.num_faces() <= before, "{mesh}: level {} grows", i + 1);
            before = level.num_faces();
            let faces = level.num_faces().to_string();
            ok(&[
                "reconstruct",
                lod_s,
                "--to",
                &faces,
                "--out",
                out_s,
                "--structure",
                structure,
            ]);
            assert_eq!(
                std::fs::read(&out).unwrap(),
                std::fs::read(file).unwrap(),
                "{mesh} on {structure}: level {} rebuilt",
                i + 1
            );
        }
        before = input.num_faces();
    }
}

#[test]
fn a_built_in_mesh_comes_back_byte_for_byte_from_its_coarse_mesh_and_record() {
    let dir = scratch("lod-built-in");
    // The built-in mesh as the lab generates it: what `convert` writes, read back.
    let input_file = dir.join("torus.off");
    ok(&["convert", "torus:3000", input_file.to_str().unwrap()]);
    let input = read(&input_file);
    steps_back(
        "torus:3000",
        &input,
        "60%,25%,5%",
        &dir,
        &["index-half-edge", "che-l2", "winged-edge"],
    );
    let coarse = read(&dir.join("lod/coarse.obj"));
    // 5% of 3000-odd faces, or at most two more (a collapse removes two).
    let target = (input.num_faces() as f64 * 0.05).round() as usize;
    assert!(
        coarse.num_faces() <= target && coarse.num_faces() + 2 > target,
        "{} faces for {target}",
        coarse.num_faces()
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_mesh_file_with_a_boundary_and_irregular_positions_comes_back_bit_for_bit() {
    let dir = scratch("lod-file");
    // Positions moved at random: full 17-digit decimals, which must come back bit for bit.
    let soup = meshes::perturb(&meshes::grid(14, 11, true), 0.03, 36);
    let file = dir.join("grid.obj");
    topolab_structures::io::write(&file, &soup).unwrap();
    assert_eq!(
        bits(&read(&file)),
        bits(&soup),
        "the OBJ writer round-trips"
    );
    steps_back(
        file.to_str().unwrap(),
        &soup,
        "50%",
        &dir,
        &["pointer-half-edge", "vertex-list"],
    );
    std::fs::remove_dir_all(&dir).unwrap();
    // A file with a vertex no face uses: it stays, at its id.
    let dir = scratch("lod-unused");
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad-input/unused-vertex.obj");
    steps_back(
        file.to_str().unwrap(),
        &read(&file),
        "50%",
        &dir,
        &["index-half-edge", "edge-list"],
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_coarse_mesh_holds_the_survivors_in_increasing_original_id() {
    let dir = scratch("lod-numbering");
    let lod = dir.join("lod");
    ok(&[
        "decimate",
        "sphere:400",
        "--levels",
        "30%",
        "--out",
        lod.to_str().unwrap(),
    ]);
    let original = read(&lod.join("original.obj"));
    let coarse = read(&lod.join("coarse.obj"));
    // Every coarse vertex is an original vertex, in increasing original id.
    let ids: Vec<usize> = bits(&coarse)
        .iter()
        .map(|p| bits(&original).iter().position(|q| q == p).unwrap())
        .collect();
    assert!(ids.windows(2).all(|w| w[0] < w[1]), "{ids:?}");
    // The record names the removed ones: the others are exactly those.
    let record = std::fs::read_to_string(lod.join("collapses.txt")).unwrap();
    let lines: Vec<&str> = record.lines().filter(|l| !l.starts_with('#')).collect();
    let n: usize = lines
        .iter()
        .find_map(|l| l.strip_prefix("collapses "))
        .unwrap()
        .parse()
        .unwrap();
    let start = lines
        .iter()
        .position(|l| l.starts_with("collapses "))
        .unwrap()
        + 1;
    let mut removed: Vec<usize> = lines[start..start + n]
        .iter()
        .map(|l| l.split(' ').next().unwrap().parse().unwrap())
        .collect();
    removed.sort();
    let survivors: Vec<usize> = (0..original.num_vertices())
        .filter(|v| removed.binary_search(v).is_err())
        .collect();
    assert_eq!(ids, survivors);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Runs `topolab args`, which must fail with `code` and one line saying `says`.
fn refused(args: &[&str], code: i32, says: &str) {
    let run = topolab(args);
    let stderr = text(&run.stderr);
    assert_eq!(run.status.code(), Some(code), "{args:?}: {stderr}");
    assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
    assert!(stderr.contains(says), "{args:?}: {stderr}");
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
}

#[test]
fn bad_levels_records_and_requests_are_refused_and_nothing_is_written() {
    let dir = scratch("lod-bad");
    let lod = dir.join("lod");
    let lod_s = lod.to_str().unwrap().to_string();
    ok(&[
        "decimate",
        "torus:600",
        "--levels",
        "50%,20%",
        "--out",
        &lod_s,
    ]);
    let record = std::fs::read_to_string(lod.join("collapses.txt")).unwrap();
    let coarse = std::fs::read_to_string(lod.join("coarse.obj")).unwrap();
    let out = dir.join("out.obj");
    let out_s = out.to_str().unwrap().to_string();
    let new = dir.join("new");
    let new_s = new.to_str().unwrap().to_string();

    for (levels, says) in [
        ("", "percentage"),
        ("0%", "more than 0%"),
        ("100%", "less than 100%"),
        ("150%", "less than 100%"),
        ("10%,50%", "decrease strictly"),
        ("ten%", "not a percentage"),
        ("0.5", "percentage of the faces"),
    ] {
        refused(
            &["decimate", "torus:600", "--levels", levels, "--out", &new_s],
            2,
            says,
        );
    }
    refused(
        &[
            "decimate",
            "torus:600",
            "--levels",
            "50%",
            "--faces",
            "10",
            "--out",
            &new_s,
        ],
        2,
        "cannot be used with",
    );
    // A structure outside the suite, a level below the topology's minimum (a torus keeps 14).
    refused(
        &[
            "decimate",
            "torus:600",
            "--levels",
            "50%",
            "--structure",
            "regular-grid",
            "--out",
            &new_s,
        ],
        2,
        "decimation suite enrols",
    );
    refused(
        &[
            "decimate",
            "torus:600",
            "--levels",
            "50%,1%",
            "--out",
            &new_s,
        ],
        1,
        "at least 14",
    );
    std::fs::write(&out, "").unwrap();
    refused(
        &["decimate", "torus:600", "--levels", "50%", "--out", &out_s],
        2,
        "not a folder",
    );
    std::fs::remove_file(&out).unwrap();
    assert!(!new.exists(), "a refused decimation created its folder");

    // Folders with one thing wrong each.
    let broken = |name: &str, record: Option<&str>, coarse: Option<&str>| {
        let d = dir.join(name);
        std::fs::create_dir_all(&d).unwrap();
        if let Some(r) = record {
            std::fs::write(d.join("collapses.txt"), r).unwrap();
        }
        if let Some(c) = coarse {
            std::fs::write(d.join("coarse.obj"), c).unwrap();
        }
        d.to_str().unwrap().to_string()
    };
    let lines: Vec<&str> = record.lines().collect();
    let first = lines.iter().position(|l| l.starts_with("# from")).unwrap() + 1;
    let with_line = |i: usize, line: &str| {
        let mut l = lines.clone();
        l[i] = line;
        l.join("\n") + "\n"
    };
    let last = lines.iter().position(|&l| l == "end").unwrap() - 1;
    let words: Vec<&str> = lines[last].split(' ').collect();
    let swapped = [&[words[0], words[1], words[3], words[2]][..], &words[4..]]
        .concat()
        .join(" ");
    let moved = [&words[..4], &["0.5"][..], &words[5..]].concat().join(" ");
    let vertices: usize = lines[2].split(' ').nth(1).unwrap().parse().unwrap();
    // The same counts, one vertex moved: only the fingerprint tells.
    let other_coarse: String = coarse
        .lines()
        .enumerate()
        .map(|(i, l)| if i == 0 { "v 9 9 9" } else { l })
        .collect::<Vec<_>>()
        .join("\n")
        + "\n";
    let fewer_faces: String = {
        let mut c: Vec<&str> = coarse.lines().collect();
        c.pop();
        c.join("\n") + "\n"
    };
    let cases: Vec<(String, i32, &str)> = vec![
        (
            dir.join("missing").to_str().unwrap().into(),
            2,
            "cannot read",
        ),
        (broken("no-record", None, Some(&coarse)), 2, "collapses.txt"),
        (broken("no-coarse", Some(&record), None), 2, "coarse.obj"),
        (
            broken(
                "truncated",
                Some(&record[..record.len() - 20]),
                Some(&coarse),
            ),
            2,
            "ends early",
        ),
        (
            broken(
                "version",
                Some(&record.replacen("topolab-collapses 1", "topolab-collapses 9", 1)),
                Some(&coarse),
            ),
            2,
            "version 9",
        ),
        (
            broken(
                "out-of-range",
                Some(&with_line(first, &format!("{vertices} 0 1 2 0 0 0 0"))),
                Some(&coarse),
            ),
            2,
            "original has",
        ),
        // The last collapse, undone first, with its wings swapped: the split is refused.
        (
            broken("swapped", Some(&with_line(last, &swapped)), Some(&coarse)),
            1,
            "does not match the coarse mesh",
        ),
        // Its vertex put back elsewhere: the original rebuilt is not the record's.
        (
            broken("moved", Some(&with_line(last, &moved)), Some(&coarse)),
            1,
            "does not match the original rebuilt",
        ),
        (
            broken("other-coarse", Some(&record), Some(&other_coarse)),
            1,
            "does not match",
        ),
        (
            broken("fewer-faces", Some(&record), Some(&fewer_faces)),
            1,
            "does not match",
        ),
    ];
    for (folder, code, says) in cases {
        refused(&["reconstruct", &folder, "--out", &out_s], code, says);
        assert!(!out.exists(), "{folder}: wrote {out_s}");
    }
    // --to outside the record's range, an output that cannot be written, a bad structure.
    let coarse_faces = coarse.lines().filter(|l| l.starts_with("f ")).count();
    for to in [(coarse_faces - 1).to_string(), "999999".to_string()] {
        refused(
            &["reconstruct", &lod_s, "--to", &to, "--out", &out_s],
            2,
            "ask for a count between them",
        );
    }
    refused(
        &["reconstruct", &lod_s, "--out", "/proc/nope.obj"],
        2,
        "cannot write",
    );
    refused(
        &[
            "reconstruct",
            &lod_s,
            "--out",
            &out_s,
            "--structure",
            "explicit",
        ],
        2,
        "it does not offer both the edge collapse",
    );
    assert!(!out.exists());
    std::fs::remove_dir_all(&dir).unwrap();
}
