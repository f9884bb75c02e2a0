//! `.che` files (docs/che-format.md) through the CLI and the harness's checksums: `convert --to
//! che` writes a file that `info` describes from its header and `check` verifies, the mapped
//! CHE gives every operator's sweep checksum of the owned CHE it was written from, and bad
//! files are refused with a one-line message and the documented exit code.

mod common;

use common::run::{scratch, text, topolab};
use std::path::Path;
use topolab_structures::che::file::write_mesh;
use topolab_structures::che::MappedChe;
use topolab_structures::meshes;
use topolab_structures::{CheL1, CheL2, CheL3, MeshTopology, Operator, PolygonSoup};

/// Every operator's sweep checksum of `owned` and of its level written to `path` and mapped,
/// both before and after the mapped file's verification.
fn same_checksums<Owned: MeshTopology, const L: u8>(name: &str, soup: &PolygonSoup, path: &Path)
where
    MappedChe<L>: MeshTopology,
{
    let owned = Owned::from_soup(soup).unwrap();
    write_mesh(soup, L, path).unwrap();
    let mut mapped = MappedChe::<L>::open(path).unwrap();
    for verified in [false, true] {
        if verified {
            mapped.verify().unwrap();
        }
        for op in Operator::ALL {
            assert_eq!(
                common::checksum(&mapped, op),
                common::checksum(&owned, op),
                "{name}, level {L}, {op:?}, verified {verified}"
            );
        }
    }
}

#[test]
fn the_mapped_che_gives_the_owned_checksums_on_the_canonical_meshes_and_a_torus() {
    let dir = scratch("che-checksums");
    let mut cases: Vec<(String, PolygonSoup)> = meshes::canonical()
        .into_iter()
        .filter(|m| CheL2::from_soup(&m.soup).is_ok())
        .map(|m| (m.name.to_string(), m.soup))
        .collect();
    cases.push(("torus".into(), meshes::torus(30, 20)));
    for (name, soup) in &cases {
        let path = dir.join(format!("{name}.che"));
        same_checksums::<CheL1, 1>(name, soup, &path);
        same_checksums::<CheL2, 2>(name, soup, &path);
        same_checksums::<CheL3, 3>(name, soup, &path);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn convert_info_and_check_a_che_file() {
    let dir = scratch("che-cli");
    let out = dir.join("grid.che");
    let o = topolab(&["convert", "grid:50", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    assert!(
        text(&o.stdout).contains("level-2 CHE"),
        "{}",
        text(&o.stdout)
    );
    // A 5 × 5 grid of squares, two triangles each: 6 · 6 = 36 vertices, 30 + 30 sides and 25
    // diagonals = 85 edges, 50 triangles; a disc, χ = 1.
    let o = topolab(&["info", out.to_str().unwrap(), "--json"]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["level"], 2);
    assert_eq!(v["vertices"], 36);
    assert_eq!(v["edges"], 85);
    assert_eq!(v["faces"], 50);
    assert_eq!(v["euler_characteristic"], 1);
    assert_eq!(v["memory_mapped"], true);
    assert_eq!(
        v["bytes"].as_u64().unwrap(),
        std::fs::metadata(&out).unwrap().len()
    );
    let o = topolab(&["info", out.to_str().unwrap()]);
    assert!(text(&o.stdout).contains("opened in"), "{}", text(&o.stdout));
    let o = topolab(&["check", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(text(&o.stdout).contains("no problems found"));
    // Detected by its magic under another name.
    let renamed = dir.join("grid.bin");
    std::fs::copy(&out, &renamed).unwrap();
    let o = topolab(&["check", renamed.to_str().unwrap(), "--json"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["clean"], true);
    // One flipped byte in the containers: opens, and check finds it (exit code 1).
    let mut bytes = std::fs::read(&out).unwrap();
    let last = bytes.len() - 200;
    bytes[last] ^= 0x40;
    let flipped = dir.join("flipped.che");
    std::fs::write(&flipped, &bytes).unwrap();
    // `info` verifies before it answers: it refuses the file, naming the problem.
    let o = topolab(&["info", flipped.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        text(&o.stderr).contains("checksum mismatch"),
        "{}",
        text(&o.stderr)
    );
    let o = topolab(&["check", flipped.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        text(&o.stderr).contains("checksum mismatch"),
        "{}",
        text(&o.stderr)
    );
    // Every level converts and checks clean.
    for level in ["0", "1", "3"] {
        let path = dir.join(format!("torus-{level}.che"));
        let o = topolab(&[
            "convert",
            "torus:500",
            "--to",
            "che",
            "--level",
            level,
            path.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", text(&o.stderr));
        let o = topolab(&["check", path.to_str().unwrap()]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "level {level}: {}",
            text(&o.stderr)
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `info` on a `.che` file answers every field `info` gives for the mesh it was converted
/// from, with the same values, at every level; and says so when `--structure` names another.
#[test]
fn info_on_a_che_file_answers_as_info_on_its_mesh() {
    let dir = scratch("che-info");
    // A torus with two holes, and separate pieces: genus, curves and components all count.
    for mesh in ["surface:1:2:400", "holes:3:300", "torus:200"] {
        let o = topolab(&["info", mesh, "--json"]);
        assert!(o.status.success(), "{}", text(&o.stderr));
        let expected: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        for level in ["0", "1", "2", "3"] {
            let file = dir.join(format!("l{level}.che"));
            let o = topolab(&["convert", mesh, file.to_str().unwrap(), "--level", level]);
            assert!(o.status.success(), "{}", text(&o.stderr));
            let o = topolab(&["info", file.to_str().unwrap(), "--json"]);
            assert!(o.status.success(), "{}", text(&o.stderr));
            let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
            for field in [
                "vertices",
                "unused_vertices",
                "edges",
                "faces",
                "boundary_edges",
                "boundary_curves",
                "components",
                "euler_characteristic",
                "genus",
                "non_manifold_vertices",
                "triangles_only",
            ] {
                assert!(!v[field].is_null(), "{mesh} level {level}: no {field}");
                assert_eq!(v[field], expected[field], "{mesh} level {level}: {field}");
            }
            assert_eq!(v["structure"], format!("che-l{level}"));
            assert_eq!(v["verified"], true);
        }
    }
    // `--structure` is the file's level whatever it says, and a note says so.
    let file = dir.join("l2.che");
    let o = topolab(&["info", file.to_str().unwrap(), "--structure", "openmesh"]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    assert!(
        text(&o.stderr).contains("--structure openmesh ignored"),
        "{}",
        text(&o.stderr)
    );
    let o = topolab(&["info", file.to_str().unwrap(), "--structure", "che-l2"]);
    assert!(o.stderr.is_empty(), "{}", text(&o.stderr));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A level-0 file whose triangles are all (0, 0, 0), or one repeated, fails `check` as a
/// level-1 file of the same triangles does (issue 52: it passed, "no problems found").
#[test]
fn check_refuses_corrupt_triangles_at_level_0_as_at_level_1() {
    let dir = scratch("che-level-0");
    for level in ["0", "1"] {
        let file = dir.join(format!("l{level}.che"));
        let o = topolab(&[
            "convert",
            "torus:100",
            file.to_str().unwrap(),
            "--level",
            level,
        ]);
        assert!(o.status.success(), "{}", text(&o.stderr));
        let good = std::fs::read(&file).unwrap();
        let header = topolab_structures::che::file::Header::parse(&good).unwrap();
        let layout = topolab_structures::che::file::Layout::of(header).unwrap();
        let v = layout
            .section(topolab_structures::che::file::Container::V)
            .unwrap();
        let (start, end) = (v.offset as usize, (v.offset + 4 * v.len) as usize);
        let mut zeros = good.clone();
        zeros[start..end].fill(0);
        let mut repeated = good.clone();
        repeated.copy_within(start..start + 12, start + 12);
        for (name, mut bytes) in [("zeros", zeros), ("repeated", repeated)] {
            let sum = topolab_structures::che::file::checksum(&bytes);
            bytes[56..64].copy_from_slice(&sum.to_le_bytes());
            let bad = dir.join(format!("{name}-l{level}.che"));
            std::fs::write(&bad, &bytes).unwrap();
            let o = topolab(&["check", bad.to_str().unwrap()]);
            assert_eq!(
                o.status.code(),
                Some(1),
                "level {level}, {name}: {}",
                text(&o.stdout)
            );
            assert!(!text(&o.stdout).contains("no problems found"));
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_che_requests_are_refused_in_one_line_with_nothing_written() {
    let dir = scratch("che-refusals");
    let out = dir.join("x.che");
    let cases: [(&[&str], i32, &str); 4] = [
        (
            &["convert", "quad-grid:20", "--to", "che"],
            1,
            "triangles only",
        ),
        (
            &["convert", "torus", "--to", "che", "--level", "9"],
            2,
            "--level 9",
        ),
        (
            &["convert", "torus", "--to", "obj", "--level", "1"],
            2,
            "--level 1",
        ),
        (&["convert", "torus", "--ascii"], 2, "--ascii"),
    ];
    for (args, code, says) in cases {
        let mut args = args.to_vec();
        args.push(out.to_str().unwrap());
        let o = topolab(&args);
        let stderr = text(&o.stderr);
        assert_eq!(o.status.code(), Some(code), "{args:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(stderr.contains(says), "{args:?}: {stderr}");
        assert!(!out.exists(), "{args:?} wrote a file");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn explain_reads_a_che_file_through_the_mapping_as_the_owned_level_explains_its_mesh() {
    let dir = scratch("che-explain");
    for level in ["1", "2", "3"] {
        let file = dir.join(format!("grid-l{level}.che"));
        let o = topolab(&[
            "convert",
            "grid:50",
            file.to_str().unwrap(),
            "--level",
            level,
        ]);
        assert!(o.status.success(), "{}", text(&o.stderr));
        let name = format!("che-l{level}");
        let mapped = topolab(&["explain", &name, "--mesh", file.to_str().unwrap()]);
        assert!(mapped.status.success(), "{}", text(&mapped.stderr));
        let owned = topolab(&["explain", &name, "--mesh", "grid:50"]);
        assert!(owned.status.success(), "{}", text(&owned.stderr));
        let mapped = text(&mapped.stdout);
        assert!(mapped.contains("verified"), "{mapped}");
        let records = &mapped[mapped.find("G[] geometry").unwrap()..];
        assert!(records.len() > 200, "{mapped}");
        assert!(text(&owned.stdout).contains(records), "{mapped}");
        // The level is the file's: another level's name is refused, naming the right one.
        let other = if level == "1" { "che-l2" } else { "che-l1" };
        let o = topolab(&["explain", other, "--mesh", file.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2));
        assert!(
            text(&o.stderr).contains(&format!("explain {name} --mesh")),
            "{}",
            text(&o.stderr)
        );
    }
    // A trace reads meshes, and says so.
    let file = dir.join("grid-l2.che");
    let o = topolab(&[
        "explain",
        "che-l2",
        "--mesh",
        file.to_str().unwrap(),
        "--trace",
        "r00",
        "--vertex",
        "0",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(text(&o.stderr).lines().count(), 1);
    std::fs::remove_dir_all(&dir).unwrap();
}
