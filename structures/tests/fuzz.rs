//! Property-based fuzzing: random bytes and random mutations of valid files, through every
//! reader, the checker, the writers and the construction of every registered structure.
//! Nothing may panic; every refusal is a typed error whose message is short (a token echoed
//! at most 60 characters); every mesh the writers accept reads back with the same counts.
//!
//! CI runs a thousand cases per property (a few seconds). A longer run:
//! `TOPOLAB_FUZZ_CASES=200000 cargo test --release -p topolab-structures --test fuzz`.

use proptest::prelude::*;
use proptest::test_runner::Config;
use std::collections::HashSet;
use std::sync::atomic::{AtomicUsize, Ordering};
use topolab_structures::che::file as che_file;
use topolab_structures::che::CheFile;
use topolab_structures::checks::{check, Options};
use topolab_structures::io::{self, read_bytes_raw, PlyEncoding};
use topolab_structures::{meshes, registry, Format, PolygonSoup};

mod support;

/// Cases per property: `TOPOLAB_FUZZ_CASES`, or a CI-sized default.
fn config() -> Config {
    let cases = std::env::var("TOPOLAB_FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1000);
    Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    }
}

const FORMATS: [Format; 4] = [Format::Obj, Format::Off, Format::Ply, Format::Stl];

/// Everything downstream of the readers on `bytes` read as `format`: the raw reader, the
/// checker on what it read, the checked reader, and every structure on what passes.
fn exercise(bytes: &[u8], format: Format) -> Result<(), TestCaseError> {
    let raw = match read_bytes_raw(bytes, format) {
        Ok(raw) => raw,
        Err(e) => {
            // The checked reader fails the same way on an unreadable file.
            let checked = io::read_bytes(bytes, format).expect_err("unreadable raw");
            prop_assert_eq!(checked.kind(), e.kind());
            // However long a token of the file, the message stays one short line.
            let message = e.to_string();
            prop_assert!(message.len() <= 300, "{} bytes: {}", message.len(), message);
            return Ok(());
        }
    };
    for s in &raw.skipped {
        prop_assert!(s.to_string().len() <= 300, "{}", s);
    }
    let report = check(&raw, &Options::default());
    prop_assert_eq!(report.summary.vertices, raw.soup.num_vertices());
    let Ok(soup) = raw.into_checked() else {
        return Ok(());
    };
    round_trip(&soup)?;
    for (name, outcome) in registry::build_each(&soup) {
        // A structure may refuse input it cannot store, but what it built must validate.
        if let Err(e) = outcome {
            prop_assert_ne!(
                e.kind(),
                "invariant",
                "{} broke on its own build: {}",
                name,
                e
            );
        }
    }
    Ok(())
}

/// Every format and encoding the lab writes.
const WRITTEN: [(Format, PlyEncoding); 5] = [
    (Format::Obj, PlyEncoding::Binary),
    (Format::Off, PlyEncoding::Binary),
    (Format::Ply, PlyEncoding::Binary),
    (Format::Ply, PlyEncoding::Ascii),
    (Format::Stl, PlyEncoding::Binary),
];

/// `soup` in `format`, as the lab writes it.
fn written(soup: &PolygonSoup, format: Format, ply: PlyEncoding) -> Vec<u8> {
    let mut bytes = Vec::new();
    match format {
        Format::Obj => io::write_obj(&mut bytes, soup),
        Format::Off => io::write_off(&mut bytes, soup),
        Format::Ply => io::write_ply(&mut bytes, soup, ply),
        Format::Stl => io::write_stl(&mut bytes, soup),
    }
    .expect("writing to memory");
    bytes
}

/// Every format the lab writes either refuses `soup` before writing ([`io::writable`]: the
/// file would not read back) or writes a file its reader reads back with the same counts:
/// the same soup for OBJ, OFF and PLY, which write coordinates exactly; for STL, a triangle
/// per fan triangle and a vertex per distinct float position of the used vertices (STL welds).
/// And so does every CHE level ([`che_round_trip`], whose count of levels written it returns).
fn round_trip(soup: &PolygonSoup) -> Result<usize, TestCaseError> {
    for (format, ply) in WRITTEN {
        if let Err(e) = io::writable(soup, format) {
            prop_assert_eq!(e.kind(), "not-writable", "{}", e);
            let empty = soup.num_vertices() == 0 && soup.num_faces() == 0;
            prop_assert!(
                format == Format::Stl || empty,
                "only STL refuses a checked soup that is not empty: {}",
                e
            );
            continue;
        }
        let bytes = written(soup, format, ply);
        let back = io::read_bytes(&bytes, format);
        prop_assert!(
            back.is_ok(),
            "{format} ({ply:?}) does not read back: {:?}",
            back.err()
        );
        let back = back.unwrap();
        if format != Format::Stl {
            prop_assert_eq!(&back, soup, "{} ({:?})", format, ply);
            continue;
        }
        let triangles: usize = soup.faces().map(|f| f.len() - 2).sum();
        let places: HashSet<[u32; 3]> = soup
            .indices()
            .iter()
            .map(|&v| {
                let p = soup.positions[v as usize];
                p.to_array().map(|x| ((x as f32) + 0.0).to_bits())
            })
            .collect();
        prop_assert_eq!(
            (back.num_faces(), back.num_vertices()),
            (triangles, places.len())
        );
    }
    che_round_trip(soup)
}

/// Every CHE level either refuses `soup` (as its construction refuses it: a typed error, and
/// no file) or writes a `.che` file that opens, passes `check` and holds the soup's vertices
/// and triangles as they were: what `convert --to che` writes (the same bytes, through
/// `che_file::write_mesh_owned`) reads back. The empty soup is left out: `convert` refuses it
/// before writing. Returns the levels written.
fn che_round_trip(soup: &PolygonSoup) -> Result<usize, TestCaseError> {
    if soup.num_vertices() == 0 && soup.num_faces() == 0 {
        return Ok(0);
    }
    // Properties run on several threads of one process: a file each.
    static FILES: AtomicUsize = AtomicUsize::new(0);
    let path = std::env::temp_dir().join(format!(
        "topolab-fuzz-{}-{}.che",
        std::process::id(),
        FILES.fetch_add(1, Ordering::Relaxed)
    ));
    let mut written = 0;
    for level in 0..=3u8 {
        if let Err(e) = che_file::write_mesh(soup, level, &path) {
            prop_assert_ne!(e.kind(), "io", "level {}: {}", level, e);
            prop_assert!(!path.exists(), "level {} refused, yet wrote a file", level);
            continue;
        }
        let file = CheFile::open(&path);
        prop_assert!(file.is_ok(), "level {}: {:?}", level, file.err());
        let file = file.unwrap();
        let checked = file.check();
        prop_assert!(checked.is_ok(), "level {}: {:?}", level, checked.err());
        prop_assert_eq!(file.geometry(), &soup.positions[..], "level {}", level);
        prop_assert_eq!(file.start_vertices(), soup.indices(), "level {}", level);
        drop(file);
        std::fs::remove_file(&path).unwrap();
        written += 1;
    }
    Ok(written)
}

/// Valid files of every format and encoding to mutate: as the lab writes them and as other
/// tools do, of polygons, quads and triangles, and triangles that STL cannot hold (a
/// coordinate beyond float's range, corners float cannot tell apart).
fn seeds() -> Vec<(Vec<u8>, Format)> {
    let mut out = Vec::new();
    let mut huge = meshes::bowtie();
    huge.positions[1].x = 1e308;
    let mut tiny = meshes::bowtie();
    for p in &mut tiny.positions {
        *p *= 1e-50;
    }
    for soup in [
        meshes::mixed_polygons(),
        meshes::quad_cube(),
        meshes::bowtie(),
        // A closed triangle mesh: every CHE level writes it (`che_round_trip`).
        meshes::torus(4, 3),
        huge,
        tiny,
    ] {
        for ply in [PlyEncoding::Binary, PlyEncoding::Ascii] {
            out.push((written(&soup, Format::Ply, ply), Format::Ply));
        }
        let mut obj = Vec::new();
        io::write_obj(&mut obj, &soup).unwrap();
        let mut off = Vec::new();
        io::write_off(&mut off, &soup).unwrap();
        out.push((obj, Format::Obj));
        out.push((off, Format::Off));
        // The other tools' encodings store floats: only for the soups a float holds.
        let floats = io::writable(&soup, Format::Stl).is_ok();
        if floats {
            out.push((support::ascii_ply(&soup).into_bytes(), Format::Ply));
            out.push((support::binary_ply(&soup, false), Format::Ply));
            out.push((support::binary_ply(&soup, true), Format::Ply));
        }
        if soup.is_triangle_mesh() && floats {
            let mut stl = Vec::new();
            io::write_stl(&mut stl, &soup).unwrap();
            out.push((stl, Format::Stl));
            out.push((support::ascii_stl(&soup).into_bytes(), Format::Stl));
        }
    }
    out
}

/// One edit of a file: positions are taken modulo its length.
#[derive(Clone, Debug)]
enum Mutation {
    /// XOR a byte.
    Flip(usize, u8),
    /// Insert a byte.
    Insert(usize, u8),
    /// Insert a token that readers must handle with care.
    Token(usize, &'static str),
    /// Remove up to `n` bytes.
    Delete(usize, usize),
    /// Repeat up to `n` bytes.
    Duplicate(usize, usize),
    /// Cut the file.
    Truncate(usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    const TOKENS: &[&str] = &[
        "-1",
        "0",
        "4294967295",
        "4294967296",
        "99999999999999999999",
        "nan",
        "inf",
        "1e999",
        "\n",
        " ",
        "#",
        "/",
        "f",
        "v",
        "end_header\n",
        "255",
        "1000000000000",
        "18446744073709551615",
        "1e308",
        "1e-50",
        "-0",
        "\0",
    ];
    prop_oneof![
        (any::<usize>(), 1..=255u8).prop_map(|(p, b)| Mutation::Flip(p, b)),
        (any::<usize>(), any::<u8>()).prop_map(|(p, b)| Mutation::Insert(p, b)),
        (any::<usize>(), prop::sample::select(TOKENS)).prop_map(|(p, t)| Mutation::Token(p, t)),
        (any::<usize>(), 1..16usize).prop_map(|(p, n)| Mutation::Delete(p, n)),
        (any::<usize>(), 1..64usize).prop_map(|(p, n)| Mutation::Duplicate(p, n)),
        any::<usize>().prop_map(Mutation::Truncate),
    ]
}

fn apply(bytes: &mut Vec<u8>, m: &Mutation) {
    let at = |p: usize, len: usize| if len == 0 { 0 } else { p % (len + 1) };
    let len = bytes.len();
    match *m {
        Mutation::Flip(p, b) if len > 0 => bytes[p % len] ^= b,
        Mutation::Flip(..) => {}
        Mutation::Insert(p, b) => bytes.insert(at(p, len), b),
        Mutation::Token(p, t) => {
            let i = at(p, len);
            bytes.splice(i..i, t.bytes());
        }
        Mutation::Delete(p, n) => {
            let i = at(p, len);
            bytes.drain(i..(i + n).min(len));
        }
        Mutation::Duplicate(p, n) => {
            let i = at(p, len);
            let piece = bytes[i..(i + n).min(len)].to_vec();
            bytes.splice(i..i, piece);
        }
        Mutation::Truncate(p) => bytes.truncate(at(p, len)),
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn random_bytes_never_panic_any_reader(bytes in prop::collection::vec(any::<u8>(), 0..600)) {
        for format in FORMATS {
            exercise(&bytes, format)?;
        }
    }

    #[test]
    fn random_text_never_panics_any_reader(
        text in "(ply|format ascii 1.0|element (vertex|face) [0-9]{1,3}|property (float|uchar|int|list uchar int) [a-z_]{1,14}|end_header|OFF|v|f|[0-9 ./-]{0,12}|nan|\n){0,40}"
    ) {
        for format in FORMATS {
            exercise(text.as_bytes(), format)?;
        }
    }

    #[test]
    fn mutated_valid_files_never_panic(
        seed in any::<prop::sample::Index>(),
        edits in prop::collection::vec(mutation(), 1..6),
    ) {
        let mut seeds = seeds();
        let (mut bytes, format) = seeds.swap_remove(seed.index(seeds.len()));
        for m in &edits {
            apply(&mut bytes, m);
        }
        exercise(&bytes, format)?;
    }
}

#[test]
fn the_seeds_are_valid_files_that_read_back_as_written() {
    let mut che_levels_written = 0;
    for (bytes, format) in seeds() {
        let soup = io::read_bytes(&bytes, format).unwrap();
        che_levels_written += round_trip(&soup).unwrap();
    }
    // Some seeds are written at every CHE level: the CHE part of the property is not vacuous.
    assert!(che_levels_written >= 4, "{che_levels_written}");
    // STL refuses the seeds it cannot hold: the property above is not vacuous.
    let refused = seeds()
        .iter()
        .filter(|(bytes, format)| {
            let soup = io::read_bytes(bytes, *format).unwrap();
            io::writable(&soup, Format::Stl).is_err()
        })
        .count();
    assert!(refused >= 4, "{refused}");
}
