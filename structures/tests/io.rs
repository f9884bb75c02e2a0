//! The readers: round trips through the writers, every syntax feature of each format, and the
//! typed errors (with their location) on bad files.

use glam::DVec3;
use proptest::prelude::*;
use topolab_structures::io::{self, read_bytes, read_bytes_raw};
use topolab_structures::meshes::{self, RandomMeshParams};
use topolab_structures::{Error, Format, Location, PolygonSoup};

mod support;
use support::{ascii_ply, ascii_stl, binary_ply};

fn round_trip(soup: &PolygonSoup) {
    let mut obj = Vec::new();
    io::write_obj(&mut obj, soup).unwrap();
    assert_eq!(&read_bytes(&obj, Format::Obj).unwrap(), soup, "OBJ");
    let mut off = Vec::new();
    io::write_off(&mut off, soup).unwrap();
    assert_eq!(&read_bytes(&off, Format::Off).unwrap(), soup, "OFF");
}

#[test]
fn canonical_meshes_survive_a_round_trip_through_obj_and_off() {
    for m in meshes::canonical() {
        round_trip(&m.soup);
    }
}

proptest! {
    #[test]
    fn random_meshes_survive_a_round_trip(seed in any::<u64>()) {
        round_trip(&meshes::random_mesh(seed, RandomMeshParams::default()));
    }
}

/// The quad and the triangle of the canonical mixed-polygons mesh, without the pentagon.
fn square_with_triangle() -> PolygonSoup {
    let mixed = meshes::mixed_polygons();
    PolygonSoup::from_polygons(
        mixed.positions[..5].to_vec(),
        &[mixed.face(0), mixed.face(1)],
    )
}

#[test]
fn obj_reads_every_corner_form_and_skips_what_a_soup_does_not_store() {
    let text = "# a comment\nmtllib a.mtl\no thing\ng group\ns off\nusemtl red\n\
        v 0 0 0 1\nv 1 0 0 1 0.5 0.5 0.5\nvt 0 0\nvn 0 0 1\nv 1 1 0\n\
        f 1/1/1 2//1 3/1\nv 0 1 0\r\nv 0.5 1.7 0 # apex\n\
        f -2 3 5\r\nl 1 2\np 1\n";
    let soup = read_bytes(text.as_bytes(), Format::Obj).unwrap();
    let mut expected = square_with_triangle();
    expected = PolygonSoup::from_polygons(expected.positions.clone(), &[[0u32, 1, 2], [3, 2, 4]]);
    assert_eq!(soup, expected);
}

#[test]
fn an_obj_point_cloud_reads_as_a_soup_without_faces() {
    let soup = read_bytes(b"v 1 2 3\nv 4 5 6\n", Format::Obj).unwrap();
    assert_eq!((soup.num_vertices(), soup.num_faces()), (2, 0));
    assert_eq!(soup.positions[1], DVec3::new(4.0, 5.0, 6.0));
}

#[test]
fn off_reads_variants_comments_and_face_colours() {
    let expected = square_with_triangle();
    let plain = "OFF\n# comment\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n\n0 1 0\n0.5 1.7 0\n\
        4 0 1 2 3\n3 3 2 4\n";
    let coloured = "COFF 5 2 7\n0 0 0 255 0 0 255\n1 0 0 1 1 1 1\n1 1 0 0 0 0 0\n0 1 0 1 1 1 1\n\
        0.5 1.7 0 0 0 0 0\n4 0 1 2 3 255 0 0\n3 3 2 4 0.1 0.2 0.3 # trailing colour\n";
    let normals = "NOFF\n5 2 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n1 1 0 0 0 1\n0 1 0 0 0 1\n\
        0.5 1.7 0 0 0 1\n4 0 1 2 3\n3 3 2 4";
    for text in [plain, coloured, normals] {
        assert_eq!(read_bytes(text.as_bytes(), Format::Off).unwrap(), expected);
    }
}

#[test]
fn ply_reads_ascii_and_both_binary_byte_orders_with_any_scalar_types() {
    let soup = meshes::quad_cube();
    assert_eq!(
        read_bytes(ascii_ply(&soup).as_bytes(), Format::Ply).unwrap(),
        soup
    );
    for big_endian in [false, true] {
        assert_eq!(
            read_bytes(&binary_ply(&soup, big_endian), Format::Ply).unwrap(),
            soup,
            "big endian: {big_endian}"
        );
    }
}

#[test]
fn ply_ascii_keeps_double_precision() {
    let soup = meshes::open_tetrahedron();
    assert_eq!(
        read_bytes(ascii_ply(&soup).as_bytes(), Format::Ply).unwrap(),
        soup
    );
}

/// What loses nothing of the mesh is skipped and listed: OBJ statements the lab does not know
/// (per keyword, with a count and the first line), bytes after a binary PLY's last element.
#[test]
fn unknown_obj_statements_and_trailing_ply_bytes_are_skipped_and_listed() {
    let obj = "v 0 0 0\nvc 1 0 0\nv 1 0 0\nvc 0 1 0\nv 0 1 0\nfoo\nvc 0 0 1\nf 1 2 3\n";
    let raw = read_bytes_raw(obj.as_bytes(), Format::Obj).unwrap();
    assert_eq!(raw.soup.num_faces(), 1);
    let shown: Vec<String> = raw.skipped.iter().map(|s| s.to_string()).collect();
    assert_eq!(
        shown,
        [
            "skipped 3 times unknown OBJ statement \"vc\", first at line 2",
            "skipped unknown OBJ statement \"foo\" at line 6",
        ]
    );
    let soup = meshes::quad_cube();
    for trailing in [&b"\n"[..], b"\r\n", b"\0\0\0"] {
        let mut ply = binary_ply(&soup, false);
        let end = ply.len();
        ply.extend_from_slice(trailing);
        let raw = read_bytes_raw(&ply, Format::Ply).unwrap();
        assert_eq!(raw.soup, soup);
        assert_eq!(raw.skipped.len(), 1);
        assert_eq!(raw.skipped[0].first, Location::Byte(end as u64));
        assert!(raw.skipped[0]
            .what
            .starts_with(&format!("{} byte", trailing.len())));
    }
    // What would change the mesh stays an error: a short body, a malformed number.
    let ply = binary_ply(&soup, false);
    assert!(matches!(
        error(&ply[..ply.len() - 1], Format::Ply),
        Error::Truncated { .. }
    ));
    assert!(matches!(
        error(b"v 0 0 0\nvc 1 0 0\nv 1 x 0\n", Format::Obj),
        Error::Syntax { .. }
    ));
}

/// STL, both encodings, told apart by content: the triangles come back as written, face j of
/// the file is face j, and corners at exactly the same position are one vertex (numbered in
/// order of first appearance), counted in `welded_corners`.
#[test]
fn stl_reads_ascii_and_binary_welding_corners_by_exact_position() {
    for soup in [
        meshes::open_tetrahedron(),
        meshes::torus(5, 4),
        meshes::grid(3, 2, true),
    ] {
        let mut binary = Vec::new();
        io::write_stl(&mut binary, &soup).unwrap();
        for (bytes, encoding) in [(binary, "binary"), (ascii_stl(&soup).into_bytes(), "ascii")] {
            let raw = read_bytes_raw(&bytes, Format::Stl).unwrap();
            let read = raw.soup.clone();
            assert_eq!(read.num_faces(), soup.num_faces(), "{encoding}");
            assert_eq!(
                read.num_vertices(),
                soup.num_vertices(),
                "{encoding}: welded"
            );
            assert_eq!(
                raw.welded_corners,
                soup.num_corners() - soup.num_vertices(),
                "{encoding}"
            );
            // The same faces, on the same positions (f32 in binary).
            for (a, b) in read.faces().zip(soup.faces()) {
                for (&x, &y) in a.iter().zip(b) {
                    let (p, q) = (read.positions[x as usize], soup.positions[y as usize]);
                    assert!((p - q).abs().max_element() < 1e-6, "{encoding}: {p} vs {q}");
                }
            }
        }
    }
    // A binary header may start with "solid": the length decides.
    let mut binary = Vec::new();
    io::write_stl(&mut binary, &meshes::open_tetrahedron()).unwrap();
    binary[..5].copy_from_slice(b"solid");
    assert_eq!(read_bytes(&binary, Format::Stl).unwrap().num_faces(), 3);
    // Polygons are written as fans of triangles.
    let mut cube = Vec::new();
    io::write_stl(&mut cube, &meshes::quad_cube()).unwrap();
    assert_eq!(read_bytes(&cube, Format::Stl).unwrap().num_faces(), 12);
}

#[test]
fn bad_stl_files_are_typed_errors_with_their_place() {
    let mut binary = Vec::new();
    io::write_stl(&mut binary, &meshes::open_tetrahedron()).unwrap();
    assert!(matches!(
        error(&binary[..binary.len() - 1], Format::Stl),
        Error::Truncated { .. }
    ));
    let mut long = binary.clone();
    long.extend_from_slice(b"xx");
    assert!(matches!(error(&long, Format::Stl), Error::Syntax { .. }));
    let ascii = ascii_stl(&meshes::open_tetrahedron());
    for (text, line) in [
        (ascii.replacen("      vertex ", "      vertex x", 1), 4),
        (ascii.replacen("endfacet", "vertex 1 1 1\nendfacet", 1), 8),
        (ascii.clone() + "garbage\n", 24),
    ] {
        match error(text.as_bytes(), Format::Stl) {
            Error::Syntax { location, .. } => assert_eq!(location, Location::Line(line), "{text}"),
            other => panic!("{text}: expected a syntax error, got {other}"),
        }
    }
    let cut = &ascii[..ascii.find("endfacet").unwrap()];
    assert!(matches!(
        error(cut.as_bytes(), Format::Stl),
        Error::Truncated { .. }
    ));
    assert!(matches!(
        error(b"hello", Format::Stl),
        Error::Truncated { .. }
    ));
}

fn error(bytes: &[u8], format: Format) -> Error {
    read_bytes(bytes, format).expect_err("the file is bad")
}

#[test]
fn syntax_errors_name_their_line() {
    for (text, format, line) in [
        ("v 0 0 0\nv 1 x 0\n", Format::Obj, 2),
        ("v 0 0 0\n\nv 1 2\n", Format::Obj, 3),
        ("v 0 0 0\nf 1 a 1\n", Format::Obj, 2),
        ("OFF\n1 0 0\n0 zero 0\n", Format::Off, 3),
        ("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n3 0 1 2\n", Format::Off, 6),
        ("ply\nformat ascii 1.0\nelement vertex 1\nproperty weird x\nend_header\n", Format::Ply, 4),
        ("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 what\n", Format::Ply, 8),
        ("PLY\n", Format::Ply, 1),
    ] {
        match error(text.as_bytes(), format) {
            Error::Syntax { location, .. } => assert_eq!(location, Location::Line(line), "{text:?}"),
            other => panic!("{text:?}: expected a syntax error, got {other}"),
        }
    }
}

#[test]
fn cut_files_are_truncated_not_syntax_errors() {
    let soup = meshes::quad_cube();
    let mut off = Vec::new();
    io::write_off(&mut off, &soup).unwrap();
    let ascii = ascii_ply(&soup).into_bytes();
    let binary = binary_ply(&soup, false);
    for (bytes, format) in [
        (&off[..off.len() - 3], Format::Off),
        (&off[..off.len() - 12], Format::Off),
        (&ascii[..ascii.len() - 4], Format::Ply),
        (&binary[..binary.len() - 5], Format::Ply),
        (&b""[..], Format::Off),
        (&b"ply\nformat ascii 1.0\n"[..], Format::Ply),
    ] {
        let e = error(bytes, format);
        assert_eq!(e.kind(), "truncated", "{e}");
    }
    match error(&binary[..binary.len() - 5], Format::Ply) {
        Error::Truncated { location, .. } => {
            assert!(matches!(location, Location::Byte(b) if b > 0 && b < binary.len() as u64))
        }
        other => panic!("{other}"),
    }
}

#[test]
fn headers_announcing_more_than_the_file_holds_are_refused_before_allocating() {
    let off = b"OFF\n1000000000000 1 0\n0 0 0\n";
    let ply = b"ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n\
        property float x\nproperty float y\nproperty float z\nend_header\n";
    let faces = b"OFF\n3 1000000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    for (bytes, format, what) in [
        (&off[..], Format::Off, "vertices"),
        (&ply[..], Format::Ply, "vertices"),
        (&faces[..], Format::Off, "faces"),
    ] {
        match error(bytes, format) {
            Error::ImplausibleHeader {
                what: w, announced, ..
            } => assert_eq!((w, announced), (what, 1_000_000_000_000)),
            other => panic!("expected an implausible header, got {other}"),
        }
    }
}

#[test]
fn indices_out_of_range_negative_or_beyond_u32_are_index_errors_with_the_written_index() {
    // OBJ numbers from 1, and so do its errors (a relative index resolved first).
    for (text, format, index) in [
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", Format::Obj, 4),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", Format::Obj, 0),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", Format::Obj, 0),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967297\n",
            Format::Obj,
            4294967297,
        ),
        (
            "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n",
            Format::Off,
            -1,
        ),
        (
            "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 4294967295\n",
            Format::Off,
            4294967295,
        ),
        (
            "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 99999999999999999999999\n",
            Format::Off,
            i64::MAX,
        ),
    ] {
        let first = match format {
            Format::Obj => 1,
            _ => 0,
        };
        match error(text.as_bytes(), format) {
            e @ Error::IndexOutOfRange {
                face,
                index: i,
                vertices,
                ..
            } => {
                assert_eq!((face, i, vertices), (first, index, 3), "{text:?}");
                assert_eq!(e.to_string().contains("numbered from 1"), first == 1, "{e}");
            }
            other => panic!("{text:?}: {other}"),
        }
    }
}

#[test]
fn the_soup_check_runs_on_what_was_read() {
    for (text, kind) in [
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 nan\nf 1 2 3\n",
            "non-finite-coordinate",
        ),
        ("v 0 0 0\nv 1 0 0\nv 0 1 inf\n", "non-finite-coordinate"),
        ("v 0 0 0\nv 1 0 0\nf 1 2\n", "too-few-corners"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 1\n", "repeated-vertex"),
    ] {
        assert_eq!(error(text.as_bytes(), Format::Obj).kind(), kind, "{text:?}");
    }
}

#[test]
fn the_raw_reader_keeps_what_the_check_refuses() {
    let raw = read_bytes_raw(b"v 0 0 0\nv 1 0 0\nf 1 2 -9\nf 1 2 7\n", Format::Obj).unwrap();
    assert_eq!(raw.soup.num_faces(), 2);
    assert_eq!(raw.soup.face(0), &[0, 1, io::UNREPRESENTABLE]);
    assert_eq!(raw.soup.face(1), &[0, 1, 6]);
    assert_eq!(raw.unrepresentable.len(), 1);
    assert_eq!(
        (raw.unrepresentable[0].face, raw.unrepresentable[0].index),
        (0, -7)
    );
}

/// A binary PLY file is read a window of its body at a time (so that reading holds the soup,
/// not the file besides): file by file, what it reads, refuses or skips is what the reader of
/// the same bytes in memory does, on bodies of several windows, cut anywhere, with trailing
/// bytes, and with a header longer than the first read.
#[test]
fn a_binary_ply_read_from_its_file_a_window_at_a_time_reads_as_in_memory() {
    let dir = std::env::temp_dir().join(format!("topolab-io-ply-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("mesh.ply");
    // 60,000 faces of a torus: about 1.4 MB of body, some 22 windows of 64 KiB.
    let soup = meshes::torus(300, 100);
    let mut long_header = binary_ply(&soup, false);
    let comments = "comment a long header\n".repeat(8000);
    let at = long_header
        .windows(7)
        .position(|w| w == b"element")
        .unwrap();
    long_header.splice(at..at, comments.bytes());
    for big_endian in [false, true] {
        let whole = binary_ply(&soup, big_endian);
        let mut trailing = whole.clone();
        trailing.extend_from_slice(b"\n\0\0");
        let cuts = [
            whole.len() - 1,
            whole.len() - 5,
            whole.len() / 2,
            70_000,
            200,
        ];
        let files = [whole.clone(), trailing, long_header.clone()]
            .into_iter()
            .chain(cuts.iter().map(|&n| whole[..n].to_vec()));
        for bytes in files {
            std::fs::write(&path, &bytes).unwrap();
            let from_file = io::read_raw(&path);
            let in_memory = read_bytes_raw(&bytes, Format::Ply);
            match (&from_file, &in_memory) {
                (Ok(a), Ok(b)) => assert!(a == b, "{} bytes read differently", bytes.len()),
                (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string()),
                _ => panic!("{} bytes: read from one, refused by the other", bytes.len()),
            }
        }
    }
    // The long header's file holds the mesh (its float coordinates), as written.
    std::fs::write(&path, &long_header).unwrap();
    let read = io::read(&path).unwrap();
    assert_eq!(
        (read.num_vertices(), read.num_faces()),
        (soup.num_vertices(), soup.num_faces())
    );
    assert!(read.faces().eq(soup.faces()));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn files_are_read_by_extension() {
    let dir = std::env::temp_dir().join(format!("topolab-io-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let soup = meshes::mixed_polygons();
    for ext in ["obj", "off"] {
        let path = dir.join(format!("mesh.{ext}"));
        io::write(&path, &soup).unwrap();
        assert_eq!(io::read(&path).unwrap(), soup);
    }
    // STL: polygons as fans of triangles.
    let stl = dir.join("mesh.stl");
    io::write(&stl, &soup).unwrap();
    let triangles: usize = soup.faces().map(|f| f.len() - 2).sum();
    assert_eq!(io::read(&stl).unwrap().num_faces(), triangles);
    let missing = io::read(&dir.join("none.obj")).unwrap_err();
    assert_eq!(missing.kind(), "io");
    assert_eq!(
        io::read(&dir.join("mesh.dxf")).unwrap_err().kind(),
        "unknown-format"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_refused_write_leaves_no_file() {
    let path = std::env::temp_dir().join(format!("topolab-refused-{}.stl", std::process::id()));
    let mut far = topolab_structures::meshes::single_triangle();
    far.positions[1].x = 1e308;
    for soup in [topolab_structures::PolygonSoup::new(), far] {
        let err = topolab_structures::io::write(&path, &soup).unwrap_err();
        assert_eq!(err.kind(), "not-writable", "{err}");
        assert!(
            !path.exists(),
            "the refused write created {}",
            path.display()
        );
    }
}

#[test]
fn a_failed_write_leaves_the_old_file_and_no_temporary_file() {
    let dir = std::env::temp_dir().join(format!("topolab-atomic-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("mesh.obj");
    std::fs::write(&path, "the old file").unwrap();
    // A writer that fails half way: what it wrote must not reach `path`.
    let failed = io::write_atomically(&path, |w| {
        use std::io::Write;
        w.write_all(b"half a mesh")?;
        Err(std::io::Error::other("interrupted"))
    });
    assert!(failed.is_err());
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "the old file");
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, ["mesh.obj"], "no temporary file left");
    // A complete write replaces the file, and leaves only it in the folder.
    io::write(&path, &meshes::single_triangle()).unwrap();
    assert_eq!(io::read(&path).unwrap(), meshes::single_triangle());
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, ["mesh.obj"]);
    std::fs::remove_dir_all(&dir).unwrap();
}
