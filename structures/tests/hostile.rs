//! The hostile inputs of issue 52, each grown 4×: reading and checking them takes time that
//! grows about 4× (linear; at most 8× is asserted), where each of them once grew 16× (quadratic) and ran past
//! 20 s on files of a few MB.
//!
//! Time is measured inside the test, as the ratio of two sizes that take well under a second,
//! each the fastest of a few runs taken in turns ([`grows_linearly`]); the ratio must stay
//! below [`MAX_RATIO`](topolab_structures::testing::growth::MAX_RATIO), between linear growth
//! (4×, a little more for hashing and allocation) and quadratic (16×), so that a loaded
//! machine does not make it fail and a quadratic step does. Where the work can be counted
//! (the duplicate-vertex search's lookups and comparisons) the unit tests count it instead.

use glam::DVec3;
use topolab_structures::checks::{check, Options};
use topolab_structures::io::{self, read_bytes_raw};
use topolab_structures::summary::summarize;
use topolab_structures::testing::growth::grows_linearly;
use topolab_structures::{CheL2, Format, MeshTopology, PolygonSoup};

/// An OBJ file of `n` vertices at `position(i)`, each three in a triangle.
fn obj(n: usize, position: impl Fn(usize) -> DVec3) -> Vec<u8> {
    let mut out = String::new();
    for i in 0..n {
        let p = position(i);
        out += &format!("v {:?} {:?} {:?}\n", p.x, p.y, p.z);
    }
    for i in (0..n.saturating_sub(2)).step_by(3) {
        out += &format!("f {} {} {}\n", i + 1, i + 2, i + 3);
    }
    out.into_bytes()
}

/// Reads `bytes` as `format` and runs every check, as `topolab check` does.
fn read_and_check(bytes: &[u8], format: Format) {
    let raw = read_bytes_raw(bytes, format).expect("readable");
    let report = check(&raw, &Options::default());
    assert!(report.findings.len() <= 18 * Options::default().kept_per_kind);
}

#[test]
fn distinct_vertices_with_coordinates_of_1e10_and_more() {
    // Their cell index of old saturated: every vertex in one cell.
    grows_linearly("check, coordinates of 1e10", 20_000, |n| {
        let bytes = obj(n, |i| DVec3::new(1e10 + 1024.0 * i as f64, 2e10, 3e10));
        read_and_check(&bytes, Format::Obj);
    });
}

#[test]
fn distinct_vertices_a_few_ulps_apart() {
    // All within the tolerance of each other: every vertex compared with every other of old.
    grows_linearly("check, vertices ulps apart", 20_000, |n| {
        let bytes = obj(n, |i| {
            DVec3::new(f64::from_bits(1.0f64.to_bits() + 2 * i as u64), 1.0, 1.0)
        });
        read_and_check(&bytes, Format::Obj);
    });
}

#[test]
fn distinct_vertices_closer_than_a_float_can_tell() {
    // 1e-50 apart: within the tolerance, and welded to one point when written as STL floats.
    grows_linearly("check, vertices 1e-50 apart", 20_000, |n| {
        let bytes = obj(n, |i| {
            DVec3::new(i as f64 * 1e-50, (i % 7) as f64 * 1e-50, 0.0)
        });
        read_and_check(&bytes, Format::Obj);
    });
}

#[test]
fn unknown_obj_statements_of_distinct_kinds() {
    // Each kind was looked up in a list of the kinds met so far, and printed on a line.
    grows_linearly("read, distinct unknown OBJ statements", 100_000, |n| {
        let mut text = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        for i in 0..n {
            text += &format!("unknown{i} 1 2\n");
        }
        let raw = read_bytes_raw(text.as_bytes(), Format::Obj).unwrap();
        assert_eq!(raw.skipped.len(), io::LISTED_UNKNOWN_KINDS + 1);
        assert_eq!(raw.skipped.iter().map(|s| s.count).sum::<usize>(), n);
    });
}

/// A binary PLY of `faces` faces without corners.
fn faces_without_corners(faces: usize) -> Vec<u8> {
    let mut bytes = format!(
        "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\n\
         property float y\nproperty float z\nelement face {faces}\n\
         property list uchar int vertex_indices\nend_header\n"
    )
    .into_bytes();
    bytes.resize(bytes.len() + faces, 0);
    bytes
}

#[test]
fn a_binary_ply_of_faces_without_corners() {
    // Every face a finding of its own, each stored with its message: 1.24 GB for 4.9 MB.
    grows_linearly("check, PLY faces without corners", 400_000, |n| {
        read_and_check(&faces_without_corners(n), Format::Ply);
    });
}

#[test]
fn many_separate_triangles_through_che_level_2() {
    // Each boundary half-edge of old was looked up in the curves written so far.
    grows_linearly(
        "info --structure che-l2, separate triangles",
        100_000,
        |n| {
            let positions: Vec<DVec3> = (0..3 * n)
                .map(|i| DVec3::new(i as f64, (i % 3) as f64, 0.0))
                .collect();
            let faces: Vec<[u32; 3]> = (0..n as u32)
                .map(|t| [3 * t, 3 * t + 1, 3 * t + 2])
                .collect();
            let soup = PolygonSoup::from_polygons(positions, &faces);
            let summary = summarize(&CheL2::from_soup(&soup).unwrap());
            assert_eq!(summary.boundary_curves, Some(n));
        },
    );
}

#[test]
fn a_vertex_of_many_faces_through_info() {
    // The components' flood fill of old read the faces of every vertex of every face.
    grows_linearly("info, a disk of triangles around one vertex", 20_000, |n| {
        let mut positions = vec![DVec3::ZERO];
        for i in 0..n {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            positions.push(DVec3::new(a.cos(), a.sin(), 0.0));
        }
        let faces: Vec<[u32; 3]> = (0..n as u32)
            .map(|i| [0, i + 1, (i + 1) % n as u32 + 1])
            .collect();
        let soup = PolygonSoup::from_polygons(positions, &faces);
        let summary = summarize(&topolab_structures::IndexHalfEdge::from_soup(&soup).unwrap());
        assert_eq!((summary.components, summary.genus), (1, Some(0)));
    });
}

#[test]
fn a_long_token_is_echoed_short() {
    // A file of NUL bytes read as OFF: its one token was echoed whole, 2 bytes a byte.
    for format in [Format::Off, Format::Ply, Format::Stl] {
        for bytes in [vec![0u8; 1 << 20], vec![b'x'; 1 << 20]] {
            let e = read_bytes_raw(&bytes, format).unwrap_err().to_string();
            assert!(e.len() < 300, "{format}: {} bytes: {}", e.len(), &e[..300]);
        }
    }
    let e = read_bytes_raw(&vec![0u8; 1 << 20], Format::Off)
        .unwrap_err()
        .to_string();
    assert!(e.ends_with("(1048576 bytes)"), "{e}");
}

#[test]
fn a_count_of_u64_max_is_reported_as_written() {
    let ply = "ply\nformat ascii 1.0\nelement vertex 18446744073709551615\nproperty float x\n\
               property float y\nproperty float z\nend_header\n0 0 0\n";
    let e = read_bytes_raw(ply.as_bytes(), Format::Ply).unwrap_err();
    assert!(
        e.to_string()
            .contains("announces 18446744073709551615 vertices"),
        "{e}"
    );
    let off = "OFF\n18446744073709551615 0 0\n";
    let e = read_bytes_raw(off.as_bytes(), Format::Off).unwrap_err();
    assert!(e.to_string().contains("18446744073709551615"), "{e}");
}
