//! The house's rules, checked on the tree as it stands (docs/architecture.md): no Rust file
//! over 900 lines, no arrow back up between the rooms of a crate, and every path a document
//! cites exists.

use std::fs;
use std::path::{Path, PathBuf};

/// The longest a Rust source file may be: one that grows past it has more than one job.
const MAX_LINES: usize = 900;

/// The folders that are not the project's own sources: build output, fetched sources and
/// data, generated reports (all git-ignored).
const NOT_OURS: [&str; 8] = [
    "target",
    ".git",
    ".venv",
    "third_party/openmesh",
    "bench-data/cache",
    "reports/latest",
    "reports/scale-latest",
    "node_modules",
];

/// What a run writes or fetches: a document may name these before they exist.
const WRITTEN_BY_A_RUN: [&str; 7] = [
    "reports/latest",
    "reports/scale-latest",
    "reports/compare",
    "target",
    "bench-data/cache",
    ".venv",
    "third_party/openmesh",
];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Every file of the project's own, as paths relative to the root with `/` between parts.
fn files() -> Vec<String> {
    fn walk(root: &Path, dir: &Path, out: &mut Vec<String>) {
        for entry in fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            let rel = path
                .strip_prefix(root)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            let fetched = rel.starts_with("third_party/") && path.is_dir();
            if NOT_OURS
                .iter()
                .any(|n| rel == *n || rel.ends_with(&format!("/{n}")))
                || rel.starts_with("target")
                || fetched
            {
                continue;
            }
            if path.is_dir() {
                walk(root, &path, out);
            } else {
                out.push(rel);
            }
        }
    }
    let mut out = Vec::new();
    walk(&root(), &root(), &mut out);
    out.sort();
    out
}

#[test]
fn no_rust_file_is_longer_than_the_house_allows() {
    let all = files();
    let rust: Vec<&String> = all.iter().filter(|f| f.ends_with(".rs")).collect();
    assert!(rust.len() > 100, "the walk found {} Rust files", rust.len());
    let long: Vec<String> = rust
        .iter()
        .filter_map(|f| {
            let lines = fs::read_to_string(root().join(f)).unwrap().lines().count();
            (lines > MAX_LINES).then(|| format!("{f}: {lines} lines"))
        })
        .collect();
    assert!(
        long.is_empty(),
        "over {MAX_LINES} lines (split the file by concern): {long:#?}"
    );
}

/// The paths a Markdown text cites: link targets (relative to its folder, without their
/// `#anchor`) and code spans that look like a path of the project (a `/` or a source file's
/// extension, no spaces, no wildcard or placeholder).
fn cited(text: &str) -> (Vec<String>, Vec<String>) {
    let mut links = Vec::new();
    let mut spans = Vec::new();
    for (i, _) in text.match_indices("](") {
        let rest = &text[i + 2..];
        let target = &rest[..rest.find(')').unwrap_or(rest.len())];
        let target = target.split('#').next().unwrap().trim();
        let external = target.contains("://") || target.starts_with("mailto:");
        if !target.is_empty() && !external && !target.contains(' ') {
            links.push(target.to_string());
        }
    }
    let extensions = [".rs", ".md", ".toml", ".py", ".sh", ".cpp", ".h", ".hpp"];
    for (n, span) in text.split('`').enumerate() {
        // The odd pieces are inside code spans (a fence's backticks pair up alike).
        let path_like = span.contains('/') || extensions.iter().any(|e| span.ends_with(e));
        let placeholder = span.split('/').any(|part| {
            part.chars().any(|c| c.is_ascii_uppercase())
                && part.chars().all(|c| c.is_ascii_uppercase() || c == '_')
        });
        let not_a_path = span.is_empty()
            || span.contains(|c: char| c.is_whitespace() || "*<>{}$:=,;()|&'\"".contains(c))
            || span.starts_with('-')
            || span.starts_with('.')
                && !span.starts_with("./")
                && !span.starts_with(".ci")
                && !span.starts_with(".cargo")
            || span.starts_with('/');
        // Slashes between words that name nothing of the tree (`v/vt/vn`, an OBJ corner).
        let first = span.split('/').next().unwrap_or("");
        let last = span.trim_end_matches('/').rsplit('/').next().unwrap_or("");
        let words = span.contains('/')
            && !last.contains('.')
            && !first.contains('.')
            && !root().join(first).exists();
        if n % 2 == 1 && path_like && !placeholder && !not_a_path && !words {
            spans.push(span.trim_end_matches('/').to_string());
        }
    }
    (links, spans)
}

#[test]
fn every_path_a_document_cites_exists() {
    let all = files();
    let docs: Vec<&String> = all.iter().filter(|f| f.ends_with(".md")).collect();
    assert!(
        docs.iter().any(|d| d.as_str() == "docs/architecture.md"),
        "{docs:?}"
    );
    // A path cited in a code span may be written from the root, from the document's folder,
    // or as the tail of a path that exists (`core/rewrite.rs` inside a text on `structures`).
    let exists = |from: &Path, p: &str| {
        let p = p.trim_start_matches("./");
        WRITTEN_BY_A_RUN
            .iter()
            .any(|w| p == *w || p.starts_with(&format!("{w}/")))
            || root().join(p).exists()
            || root().join(from).join(p).exists()
            || all
                .iter()
                .any(|f| f == p || f.ends_with(&format!("/{p}")) || f.contains(&format!("/{p}/")))
    };
    let mut missing = Vec::new();
    let mut checked = 0;
    for doc in &docs {
        let text = fs::read_to_string(root().join(doc)).unwrap();
        let from = Path::new(doc.as_str()).parent().unwrap();
        let (links, spans) = cited(&text);
        for link in links {
            checked += 1;
            if !root().join(from).join(&link).exists() {
                missing.push(format!("{doc}: link to {link}"));
            }
        }
        for span in spans {
            checked += 1;
            if !exists(from, &span) {
                missing.push(format!("{doc}: `{span}`"));
            }
        }
    }
    assert!(checked > 100, "only {checked} citations found");
    assert!(missing.is_empty(), "cited but not there: {missing:#?}");
}

#[test]
fn the_citation_reader_finds_paths_and_leaves_the_rest() {
    let (links, spans) = cited(
        "See [the docs](docs/cli.md#usage), [web](https://x.org/a.md), `harness/src/lib.rs`, \
         `core/rewrite.rs`, `cargo test --workspace`, `DIR/index.html`, `x::y`, `registry.rs`, \
         `v/vt/vn`, `docs/`.",
    );
    assert_eq!(links, ["docs/cli.md"]);
    assert_eq!(
        spans,
        [
            "harness/src/lib.rs",
            "core/rewrite.rs",
            "registry.rs",
            "docs"
        ]
    );
}

/// The rooms of each crate (a top-level module of its `src/`, a folder or a file), in the order
/// they stand: a room may use only the rooms before it. A new room takes its place here.
const ROOMS: [(&str, &[&str]); 5] = [
    (
        "structures/src",
        &[
            "core",
            "io",
            "families",
            "algorithms",
            "meshes",
            "registry",
            "testing",
        ],
    ),
    (
        "harness/src",
        &[
            "format",
            "measuring",
            "teaching",
            "studies",
            "results",
            "targets",
            "page",
            "report",
            "scale",
            "compare",
        ],
    ),
    (
        "peers/src",
        &[
            "versions",
            "compose",
            "baby_shark_corner_table",
            "lox_directed_edge",
            "lox_half_edge",
            "tri_mesh",
            "edit",
            "crates",
            "registry",
        ],
    ),
    (
        "baselines/src",
        &[
            "foreign",
            "heap",
            "openmesh",
            "cgal",
            "qhull",
            "hulls",
            "compiled",
            "native_decimate",
        ],
    ),
    (
        "src",
        &[
            "failure", "output", "limits", "input", "commands", "cli", "extend",
        ],
    ),
];

/// The code of a source file the crate's build sees, without comments and without its test
/// module (`#[cfg(test)]` to the end: a room's tests may use the rooms above it, as an
/// integration test would).
fn production_code(text: &str) -> String {
    let text = &text[..text.find("#[cfg(test)]").unwrap_or(text.len())];
    text.lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The first names after every `crate::` of `code` (not `$crate::`, a macro's path for its
/// callers), with the names of a `crate::{a, b::c}` group.
fn crate_paths(code: &str) -> Vec<String> {
    let mut names = Vec::new();
    for (i, _) in code.match_indices("crate::") {
        let before = code[..i].chars().next_back();
        if before.is_some_and(|c| c == '$' || c == '_' || c.is_alphanumeric()) {
            continue;
        }
        let rest = &code[i + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let group = &group[..group.find('}').unwrap_or(group.len())];
            for item in group.split(',') {
                let name = item.trim().split("::").next().unwrap_or("").trim();
                if !name.is_empty() {
                    names.push(name.to_string());
                }
            }
        } else {
            let end = rest
                .find(|c: char| !(c == '_' || c.is_alphanumeric()))
                .unwrap_or(rest.len());
            let macro_call = rest[end..].starts_with('!');
            if end > 0 && !macro_call {
                names.push(rest[..end].to_string());
            }
        }
    }
    names
}

/// The room a source file belongs to: the first part of its path below the crate's `src/`
/// (`None` for the crate root, which declares the rooms).
fn room_of(relative: &str) -> Option<String> {
    let first = relative.split('/').next()?;
    let room = first.strip_suffix(".rs").unwrap_or(first);
    (!matches!(room, "lib" | "main")).then(|| room.to_string())
}

#[test]
fn no_room_uses_a_room_after_it() {
    let all = files();
    let mut back_up = Vec::new();
    let mut unplaced = Vec::new();
    let mut arrows = 0;
    for (src, order) in ROOMS {
        let place = |room: &str| order.iter().position(|r| *r == room);
        let mut rooms_seen = 0;
        for file in all.iter().filter(|f| f.ends_with(".rs")) {
            let Some(relative) = file.strip_prefix(&format!("{src}/")) else {
                continue;
            };
            let Some(room) = room_of(relative) else {
                continue;
            };
            rooms_seen += 1;
            let Some(here) = place(&room) else {
                unplaced.push(format!("{src}/{room}"));
                continue;
            };
            if relative.ends_with("/tests.rs") {
                continue;
            }
            let code = production_code(&fs::read_to_string(root().join(file)).unwrap());
            for name in crate_paths(&code) {
                match place(&name) {
                    Some(there) if there > here => {
                        back_up.push(format!("{file}: {room} uses {name}, which stands after it"))
                    }
                    Some(there) if there < here => arrows += 1,
                    // A name of the crate root that is no room: its re-exports, which hide
                    // which room a path reaches (and so a circle), in the structures' crate.
                    None if src == "structures/src" => back_up.push(format!(
                        "{file}: crate::{name} is a re-export of the crate root; name its module"
                    )),
                    _ => {}
                }
            }
        }
        assert!(rooms_seen > 3, "{src}: only {rooms_seen} files in rooms");
    }
    unplaced.sort();
    unplaced.dedup();
    assert!(
        unplaced.is_empty(),
        "rooms missing from ROOMS (give each its place): {unplaced:?}"
    );
    assert!(arrows > 100, "only {arrows} arrows between rooms found");
    assert!(back_up.is_empty(), "arrows back up: {back_up:#?}");
}

#[test]
fn the_path_reader_finds_rooms_and_leaves_macros_and_comments() {
    let code = production_code(
        "use crate::core::ids;\n// crate::testing\nuse crate::{io::obj, families};\n\
         $crate::Family; crate::for_each!(x); my_crate::x;\n#[cfg(test)]\nuse crate::meshes;",
    );
    assert_eq!(crate_paths(&code), ["core", "io", "families"]);
    assert_eq!(room_of("core/ids.rs").as_deref(), Some("core"));
    assert_eq!(room_of("format.rs").as_deref(), Some("format"));
    assert_eq!(room_of("lib.rs"), None);
}
