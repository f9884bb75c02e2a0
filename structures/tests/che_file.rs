//! The `.che` file and the CHE over its mapped containers: the conformance suite on the mapped
//! levels, the owned and mapped levels answering alike, and every malformed file refused with
//! a typed error (a fuzz-like proptest of truncations and byte flips included).

use proptest::prelude::*;
use std::path::{Path, PathBuf};
use topolab_structures::che::file::{
    checksum, write_mesh, CheFileProblem, Container, Containers, Header, HEADER_BYTES,
};
use topolab_structures::che::{CheFile, MappedChe, MappedCheL1, MappedCheL2, MappedCheL3};
use topolab_structures::meshes;
use topolab_structures::{
    BoundaryCurves, CheL2, EdgeId, Error, FaceId, MeshTopology, PolygonSoup, VertexId,
};

// The conformance suite, one line per mapped level: `from_soup` writes the owned level to a
// temporary `.che` file, maps and verifies it.
topolab_structures::conformance!(che_l1_mapped, MappedCheL1);
topolab_structures::conformance!(che_l2_mapped, MappedCheL2);
topolab_structures::conformance!(che_l3_mapped, MappedCheL3);

/// A scratch file `name` of this test process.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("topolab-che-file-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// The `.che` bytes of `soup` at level 2.
fn level2_bytes(soup: &PolygonSoup) -> Vec<u8> {
    let owned = CheL2::from_soup(soup).unwrap();
    Containers::level2(&owned).to_bytes().unwrap()
}

/// Writes `bytes` to scratch file `name` and opens it as a level-2 mapped CHE.
fn open_bytes(name: &str, bytes: &[u8]) -> (PathBuf, Result<MappedCheL2, Error>) {
    let path = scratch(name);
    std::fs::write(&path, bytes).unwrap();
    let opened = MappedCheL2::open(&path);
    (path, opened)
}

/// The problem of a `.che` error, failing the test on any other error.
fn problem(e: Error) -> CheFileProblem {
    match e {
        Error::CheFile { problem, .. } => problem,
        other => panic!("expected a .che problem, got {other}"),
    }
}

/// Sets the header's checksum to the bytes' own, so that a test reaches the checks after it.
fn reseal(bytes: &mut [u8]) {
    let sum = checksum(bytes);
    bytes[56..64].copy_from_slice(&sum.to_le_bytes());
}

/// Every relation's answers for every element, in the order given.
fn answers<M: MeshTopology>(m: &M) -> Vec<Vec<u64>> {
    let mut out = Vec::new();
    for v in (0..m.num_vertices()).map(VertexId::new) {
        let mut a = Vec::new();
        m.vertex_vertices(v, |w| a.push(u64::from(w.0)));
        m.vertex_edges(v, |e| a.push(u64::from(e.0)));
        m.vertex_faces(v, |f| a.push(u64::from(f.0)));
        a.push(m.is_boundary_vertex(v) as u64);
        out.push(a);
    }
    let mut edges = Vec::new();
    m.for_each_edge(|e| edges.push(e));
    out.push(edges.iter().map(|e| u64::from(e.0)).collect());
    for &e in &edges {
        let mut a: Vec<u64> = m.edge_vertices(e).iter().map(|v| u64::from(v.0)).collect();
        m.edge_edges(e, |x| a.push(u64::from(x.0)));
        m.edge_faces(e, |f| a.push(u64::from(f.0)));
        a.push(m.is_boundary_edge(e) as u64);
        out.push(a);
    }
    for f in (0..m.num_faces()).map(FaceId::new) {
        let mut a = Vec::new();
        m.face_vertices(f, |v| a.push(u64::from(v.0)));
        m.face_edges(f, |e| a.push(u64::from(e.0)));
        m.face_faces(f, |g| a.push(u64::from(g.0)));
        let mut sides = Vec::new();
        m.face_edges(f, |e| sides.push(e));
        for e in sides {
            let next = m
                .edge_successor(e, f)
                .map_or(u64::MAX, |x: EdgeId| u64::from(x.0));
            let prev = m
                .edge_predecessor(e, f)
                .map_or(u64::MAX, |x| u64::from(x.0));
            a.extend([next, prev]);
        }
        out.push(a);
    }
    let mut curves = BoundaryCurves::default();
    m.boundary_curves(&mut curves);
    for i in 0..curves.len() {
        out.push(curves.curve(i).iter().map(|e| u64::from(e.0)).collect());
    }
    out
}

/// Each answer list sorted: the same sets, whatever the walk's order.
fn as_sets(mut a: Vec<Vec<u64>>) -> Vec<Vec<u64>> {
    a.iter_mut().for_each(|x| x.sort_unstable());
    a
}

/// The owned level `L` and its mapped file, opened and then verified, answer alike: the same
/// answers in the same order once verified (the same walk), the same sets before.
fn round_trip<Owned: MeshTopology, const L: u8>(name: &str, soup: &PolygonSoup)
where
    MappedChe<L>: MeshTopology,
{
    let owned = Owned::from_soup(soup).unwrap();
    let path = scratch(&format!("{name}-l{L}.che"));
    write_mesh(soup, L, &path).unwrap();
    let mut mapped = MappedChe::<L>::open(&path).unwrap();
    assert!(!mapped.is_verified());
    let expected = answers(&owned);
    assert_eq!(
        as_sets(answers(&mapped)),
        as_sets(expected.clone()),
        "{name} at level {L}, not verified"
    );
    mapped.verify().unwrap();
    assert_eq!(answers(&mapped), expected, "{name} at level {L}, verified");
    mapped.validate().unwrap();
    let header = mapped.file().header();
    assert_eq!(header.vertices, soup.num_vertices() as u64);
    assert_eq!(header.triangles, soup.num_faces() as u64);
    assert_eq!(header.edges, owned.num_edges() as u64);
    drop(mapped);
    std::fs::remove_file(&path).unwrap();
}

#[test]
fn owned_and_mapped_levels_answer_alike_on_the_canonical_meshes_and_a_torus() {
    let mut cases: Vec<(String, PolygonSoup)> = meshes::canonical()
        .into_iter()
        .filter(|m| CheL2::from_soup(&m.soup).is_ok())
        .map(|m| (m.name.to_string(), m.soup))
        .collect();
    assert!(cases.len() >= 3, "the canonical meshes a CHE stores");
    cases.push(("torus".into(), meshes::torus(24, 16)));
    for (name, soup) in &cases {
        round_trip::<topolab_structures::CheL1, 1>(name, soup);
        round_trip::<CheL2, 2>(name, soup);
        round_trip::<topolab_structures::CheL3, 3>(name, soup);
    }
}

#[test]
fn a_level_0_file_is_checked_and_described_but_not_mapped_as_a_structure() {
    let soup = meshes::torus(8, 6);
    let path = scratch("level0.che");
    write_mesh(&soup, 0, &path).unwrap();
    let file = CheFile::open(&path).unwrap();
    assert_eq!(file.level(), 0);
    assert_eq!(file.header().edges, 3 * soup.num_faces() as u64 / 2);
    file.check().unwrap();
    assert!(matches!(
        MappedChe::<0>::from_file(file),
        Err(Error::Unsupported(_))
    ));
    let wrong = MappedCheL2::open(&path).unwrap_err();
    assert_eq!(
        problem(wrong),
        CheFileProblem::WrongLevel {
            expected: 2,
            found: 0
        }
    );
}

#[test]
fn writing_refuses_what_the_level_refuses() {
    let path = scratch("refused.che");
    let quads = meshes::grid(3, 3, false);
    let e = write_mesh(&quads, 2, &path).unwrap_err();
    assert_eq!(e.kind(), "not-triangles");
    let e = write_mesh(&meshes::torus(4, 4), 9, &path).unwrap_err();
    assert_eq!(e.kind(), "invalid-parameter");
    assert!(!path.exists(), "a refused write leaves no file");
}

/// Whether a refusal is the one a case expects.
type Expected = fn(&CheFileProblem) -> bool;

#[test]
fn malformed_headers_and_lengths_are_typed_errors_on_open() {
    let good = level2_bytes(&meshes::torus(6, 4));
    let cases: Vec<(&str, Vec<u8>, Expected)> = vec![
        ("empty", Vec::new(), |p| {
            matches!(p, CheFileProblem::Short { bytes: 0 })
        }),
        ("short", good[..40].to_vec(), |p| {
            matches!(p, CheFileProblem::Short { bytes: 40 })
        }),
        ("truncated", good[..good.len() - 64].to_vec(), |p| {
            matches!(p, CheFileProblem::LengthMismatch { .. })
        }),
        ("longer", [good.clone(), vec![0; 64]].concat(), |p| {
            matches!(p, CheFileProblem::LengthMismatch { .. })
        }),
        (
            "magic",
            {
                let mut b = good.clone();
                b[0] = b'O';
                b
            },
            |p| matches!(p, CheFileProblem::WrongMagic),
        ),
        (
            "big-endian",
            {
                let mut b = good.clone();
                b[8..12].reverse();
                b
            },
            |p| matches!(p, CheFileProblem::BigEndian),
        ),
        (
            "version",
            {
                let mut b = good.clone();
                b[12] = 7;
                b
            },
            |p| matches!(p, CheFileProblem::UnknownVersion { found: 7 }),
        ),
        (
            "level",
            {
                let mut b = good.clone();
                b[16] = 9;
                b
            },
            |p| matches!(p, CheFileProblem::UnknownLevel { found: 9 }),
        ),
        (
            "counts",
            {
                let mut b = good.clone();
                b[32..40].copy_from_slice(&u64::MAX.to_le_bytes());
                b
            },
            |p| matches!(p, CheFileProblem::ImpossibleCounts { .. }),
        ),
    ];
    for (name, bytes, expected) in cases {
        let (_, opened) = open_bytes(&format!("{name}.che"), &bytes);
        let p = problem(opened.unwrap_err());
        assert!(expected(&p), "{name}: {p}");
    }
}

#[test]
fn check_refuses_a_checksum_mismatch_and_ids_out_of_range() {
    let soup = meshes::torus(6, 4);
    let good = level2_bytes(&soup);
    let header = Header::parse(&good).unwrap();
    let layout = topolab_structures::che::file::Layout::of(header).unwrap();
    let o_at = layout.section(Container::O).unwrap().offset as usize;
    // A flipped bit of O[0]: opens (O(1)), refused by the checksum.
    let mut flipped = good.clone();
    flipped[o_at] ^= 1;
    let (_, opened) = open_bytes("flipped.che", &flipped);
    let mut m = opened.unwrap();
    assert!(matches!(
        problem(m.verify().unwrap_err()),
        CheFileProblem::ChecksumMismatch { .. }
    ));
    assert!(!m.is_verified());
    // O[0] past the half-edges, the checksum made right: refused by the range check.
    let mut far = good.clone();
    far[o_at..o_at + 4].copy_from_slice(&i32::MAX.to_le_bytes());
    reseal(&mut far);
    let (_, opened) = open_bytes("far.che", &far);
    let p = problem(opened.unwrap().verify().unwrap_err());
    assert!(
        matches!(
            p,
            CheFileProblem::IdOutOfRange {
                container: Container::O,
                index: 0,
                value: 2147483647,
                ..
            }
        ),
        "{p}"
    );
    // O[0] and O[1] swapped: every id in range, the opposites broken.
    let mut swapped = good.clone();
    let (a, b) = (o_at, o_at + 4);
    let first: [u8; 4] = swapped[a..a + 4].try_into().unwrap();
    swapped.copy_within(b..b + 4, a);
    swapped[b..b + 4].copy_from_slice(&first);
    reseal(&mut swapped);
    let (_, opened) = open_bytes("swapped.che", &swapped);
    let e = opened.unwrap().verify().unwrap_err();
    assert_eq!(e.kind(), "invariant", "{e}");
    // The header's edges contradicted at level 1 (no EH to lay it out).
    let owned = topolab_structures::CheL1::from_soup(&soup).unwrap();
    let mut wrong_edges = Containers::level1(&owned);
    wrong_edges.edges -= 1;
    let bytes = wrong_edges.to_bytes().unwrap();
    let path = scratch("edges.che");
    std::fs::write(&path, bytes).unwrap();
    let p = problem(CheFile::open(&path).unwrap().check().unwrap_err());
    assert!(
        matches!(p, CheFileProblem::CountMismatch { what: "edges", .. }),
        "{p}"
    );
}

/// `V[]` corrupted the ways issue 52 found a level-0 file passing the check: every triangle
/// (0, 0, 0), and one triangle repeating another. At every level the check refuses them, as
/// building the level from those triangles refuses them, and a level-0 file (no `O[]` to
/// contradict `V[]`) as a level-1 file.
#[test]
fn corrupt_triangles_fail_the_check_at_every_level() {
    let soup = meshes::torus(6, 4);
    let levels = [
        Containers::level0(&topolab_structures::CheL0::from_soup(&soup).unwrap()).to_bytes(),
        Containers::level1(&topolab_structures::CheL1::from_soup(&soup).unwrap()).to_bytes(),
        Containers::level2(&CheL2::from_soup(&soup).unwrap()).to_bytes(),
        Containers::level3(&topolab_structures::CheL3::from_soup(&soup).unwrap()).to_bytes(),
    ];
    for (level, good) in levels.into_iter().enumerate() {
        let good = good.unwrap();
        let header = Header::parse(&good).unwrap();
        let layout = topolab_structures::che::file::Layout::of(header).unwrap();
        let v = layout.section(Container::V).unwrap();
        let v_bytes = v.offset as usize..(v.offset + 4 * v.len) as usize;
        let path = scratch(&format!("corrupt-{level}.che"));
        std::fs::write(&path, &good).unwrap();
        CheFile::open(&path).unwrap().check().unwrap();
        // Every triangle (0, 0, 0).
        let mut zeros = good.clone();
        zeros[v_bytes.clone()].fill(0);
        // Triangle 1 a copy of triangle 0.
        let mut repeated = good.clone();
        let t0 = v_bytes.start..v_bytes.start + 12;
        repeated.copy_within(t0, v_bytes.start + 12);
        for (name, mut bytes, kinds) in [
            ("zeros", zeros, &["repeated-vertex"][..]),
            (
                "repeated",
                repeated,
                &[
                    "inconsistent-orientation",
                    "non-manifold-edge",
                    "repeated-vertex",
                ][..],
            ),
        ] {
            reseal(&mut bytes);
            std::fs::write(&path, &bytes).unwrap();
            let e = CheFile::open(&path).unwrap().check().unwrap_err();
            assert!(
                kinds.contains(&e.kind()),
                "level {level}, {name}: {} ({e})",
                e.kind()
            );
        }
    }
}

/// Opens `bytes` and, if it opens, checks it; anything that passes must be a valid mesh whose
/// every relation answers. Never a panic.
fn open_check_and_query(path: &Path, bytes: &[u8]) -> bool {
    std::fs::write(path, bytes).unwrap();
    let Ok(mut m) = MappedCheL2::open(path) else {
        return false;
    };
    if m.verify().is_err() {
        return false;
    }
    m.validate().expect("a verified file is a valid level 2");
    answers(&m);
    true
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// A valid file cut short or with bytes flipped is refused, or read as a valid mesh.
    #[test]
    fn truncated_or_flipped_files_are_refused_or_valid(
        cut in any::<prop::sample::Index>(),
        flips in prop::collection::vec((any::<prop::sample::Index>(), 1u8..=255), 0..4),
        truncate in any::<bool>(),
        seal in any::<bool>(),
    ) {
        let good = level2_bytes(&meshes::open_tetrahedron());
        let mut bytes = good.clone();
        for (at, mask) in &flips {
            let i = at.index(bytes.len());
            bytes[i] ^= mask;
        }
        if truncate {
            bytes.truncate(cut.index(bytes.len()));
        }
        if seal && bytes.len() >= HEADER_BYTES as usize {
            // Past the checksum: what the range and structure checks alone must catch.
            reseal(&mut bytes);
        }
        let path = scratch(&format!("fuzz-{}.che", std::thread::current().name().unwrap_or("t").replace("::", "-")));
        let read = open_check_and_query(&path, &bytes);
        if bytes == good {
            prop_assert!(read);
        }
        if !seal && bytes != good {
            prop_assert!(!read, "a change the checksum must see");
        }
    }
}
