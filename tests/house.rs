//! The house's rules, checked on the tree as it stands (docs/architecture.md): no Rust file
//! over 900 lines, and every path a document cites exists.

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
