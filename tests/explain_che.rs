//! `topolab explain che`: the containers of every CHE level and the vertex-star traces, for
//! the chapter's open tetrahedron (our numbering: triangle t = (t, t+1 mod 3, 3)).

use std::process::Command;
use topolab::commands::explain_che::explain_che;

/// The values of the (indented) container row `name` (e.g. "O[]") in each level's block.
fn rows(text: &str, name: &str) -> Vec<Vec<i64>> {
    text.lines()
        .filter(|l| l.starts_with("  "))
        .filter_map(|l| {
            let mut words = l.split_whitespace();
            (words.next() == Some(name)).then(|| words.map(|w| w.parse().unwrap()).collect())
        })
        .collect()
}

#[test]
fn every_container_of_every_level() {
    let text = explain_che(None, None, None).unwrap();
    for level in 0..4 {
        assert!(
            text.contains(&format!("== level {level} (che-l{level})")),
            "{text}"
        );
    }
    // V[] at all four levels, O[] at levels 1-3, VH[] and EH at 2-3, CH[] at 3.
    assert_eq!(rows(&text, "V[]"), vec![vec![0, 1, 3, 1, 2, 3, 2, 0, 3]; 4]);
    assert_eq!(
        rows(&text, "O[]"),
        vec![vec![-1, 5, 7, -1, 8, 1, -1, 2, 4]; 3]
    );
    assert_eq!(rows(&text, "VH[]"), vec![vec![0, 3, 6, 2]; 2]);
    assert_eq!(rows(&text, "EH[]"), vec![vec![0, 1, 2, 3, 4, 6]; 2]);
    assert_eq!(rows(&text, "CH[]"), vec![vec![0]]);
    // The index rows name each half-edge.
    assert!(
        text.contains("he      0   1   2   3   4   5   6   7   8"),
        "{text}"
    );
}

#[test]
fn annulus_has_two_curves_labelled_in_opposite() {
    let text = explain_che(Some("annulus"), None, None).unwrap();
    let ch = rows(&text, "CH[]");
    assert_eq!(ch.len(), 1);
    assert_eq!(ch[0].len(), 2);
    let o = rows(&text, "O[]");
    // Level 3's O[] (the last) labels curve 2 with -2; levels 1 and 2 use -1 only.
    assert!(o[2].contains(&-2));
    assert!(!o[1].contains(&-2));
}

/// The container reads a block prints: each `read X[i] = y` line, and each neighbour R00
/// reads from `V[]` (one per triangle of the star, one for a boundary vertex's closing edge).
fn printed_reads(block: &str) -> usize {
    block.matches("read ").count() + block.matches("R00 reads neighbour V[").count()
}

/// The count the block's last line states: `R00(vN) = [...] after N container reads`.
fn stated_reads(block: &str) -> usize {
    let line = block
        .lines()
        .find(|l| l.contains("container reads"))
        .unwrap();
    let words: Vec<&str> = line.split_whitespace().collect();
    words[words.len() - 3].parse().unwrap()
}

#[test]
fn star_trace_reads_per_level() {
    let text = explain_che(None, Some("r00"), Some(3)).unwrap();
    let blocks: Vec<&str> = text.split("== level ").skip(1).collect();
    assert_eq!(blocks.len(), 4);
    // Level 0 scans all of V[]; level 1 stops at the first half-edge leaving v3 (V[2] = 3).
    assert!(blocks[0].contains("read V[8] = 3"));
    assert!(blocks[1].contains("read V[2] = 3") && !blocks[1].contains("read V[3]"));
    // Levels 2 and 3 start at VH[3] = 2 and never read V[] to find the star.
    for block in &blocks[2..] {
        assert!(block.contains("read VH[3] = 2"), "{block}");
        assert!(!block.contains("read V["), "{block}");
        assert_eq!(block.matches("read O[").count(), 3, "{block}");
    }
    for block in &blocks {
        let ring = block.lines().find(|l| l.contains("R00(v3)")).unwrap();
        for w in ["0", "1", "2"] {
            assert!(ring.contains(w), "{ring}");
        }
    }
}

#[test]
fn star_trace_counts_every_read_it_prints_and_the_neighbours() {
    let soup = topolab_structures::meshes::open_tetrahedron();
    for v in 0..soup.num_vertices() as u32 {
        let text = explain_che(None, Some("r00"), Some(v)).unwrap();
        let blocks: Vec<&str> = text.split("== level ").skip(1).collect();
        for block in &blocks {
            assert_eq!(stated_reads(block), printed_reads(block), "v{v}:\n{block}");
        }
        // Levels 2 and 3 (Algorithm 7 from VH[v]): VH[v], then per triangle of the star one
        // O[] read and R00's neighbour read, and a boundary vertex's closing neighbour.
        let triangles = soup.faces().filter(|f| f.contains(&v)).count();
        let mut neighbours: Vec<u32> = soup
            .faces()
            .filter(|f| f.contains(&v))
            .flat_map(|f| f.iter().copied().filter(|&w| w != v))
            .collect();
        neighbours.sort_unstable();
        neighbours.dedup();
        let boundary = neighbours.len() > triangles;
        for block in &blocks[2..] {
            assert_eq!(
                stated_reads(block),
                1 + 2 * triangles + usize::from(boundary),
                "v{v}:\n{block}"
            );
        }
    }
}

#[test]
fn command_line() {
    let exe = env!("CARGO_BIN_EXE_topolab");
    let out = Command::new(exe)
        .args(["explain", "che", "--trace", "r00", "--vertex", "1"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("read VH[1] = 3"), "{text}");
    let bad = Command::new(exe)
        .args(["explain", "che", "--trace", "r11", "--vertex", "1"])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
    let missing = Command::new(exe)
        .args(["explain", "che", "--trace", "r00", "--vertex", "9"])
        .output()
        .unwrap();
    assert_eq!(missing.status.code(), Some(2));
    let quads = Command::new(exe)
        .args(["explain", "che", "--mesh", "quad-cube"])
        .output()
        .unwrap();
    assert_eq!(quads.status.code(), Some(1));
    let level = Command::new(exe)
        .args(["explain", "che-l2"])
        .output()
        .unwrap();
    assert!(String::from_utf8(level.stdout).unwrap().contains("VH[]"));
}
