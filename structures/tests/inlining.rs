//! The inlining half of the fairness rule (see "Fairness" in the docs of
//! [`MeshTopology`](topolab_structures::MeshTopology)): every query method of every registered
//! structure's `MeshTopology` impl carries `#[inline]`, checked in the sources.
//!
//! The structures come from the registry ([`topolab_structures::for_each_structure!`]); each
//! one's impl is looked up in its family's folder under `src/families/`, directly
//! (`impl MeshTopology for Name`), through a type alias (`type Name = Generic<..>` and
//! `impl<..> MeshTopology for Generic<..>`) or through a macro (`macro_name!(Name, ..)` whose
//! body holds `impl .. MeshTopology for $ty`). A query method the impl leaves to the trait's
//! default must carry `#[inline]` in the trait. The query methods are the trait's methods
//! minus [`NOT_QUERIES`].

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// The trait's methods that are not queries: what a structure is, how it is built, checked,
/// measured and explained (its access model among it), the enumeration of edge ids (run once,
/// outside any timing) and the baselines' native loops.
const NOT_QUERIES: &[&str] = &[
    "capabilities",
    "cost",
    "from_soup",
    "from_soup_owned",
    "for_each_edge",
    "validate",
    "heap_bytes",
    "access",
    "explain",
    "native",
    "separate_construction",
    "input_checks",
];

/// `(module, type path)` of every registered structure, as the registry writes them.
macro_rules! registered {
    ($($module:ident => $ty:ty $([$($capability:ident),*])?),* $(,)?) => {
        &[$((stringify!($module), stringify!($ty))),*]
    };
}
const REGISTERED: &[(&str, &str)] = topolab_structures::for_each_structure!(registered);

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// A source file with its comments and the contents of its string and character literals
/// blanked out (same length, newlines kept), so braces and `fn` can be found in code only.
struct Source {
    path: PathBuf,
    code: String,
}

fn blank(c: char) -> char {
    if c == '\n' {
        '\n'
    } else {
        ' '
    }
}

/// Blanks comments and literal contents (see [`Source`]); ASCII quotes stay.
fn code_only(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out: Vec<char> = Vec::with_capacity(chars.len());
    let ident = |c: char| c.is_alphanumeric() || c == '_';
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        if c == '/' && next == Some('/') {
            while i < chars.len() && chars[i] != '\n' {
                out.push(' ');
                i += 1;
            }
        } else if c == '/' && next == Some('*') {
            let mut depth = 0;
            loop {
                if chars[i] == '/' && chars.get(i + 1) == Some(&'*') {
                    depth += 1;
                    out.extend([' ', ' ']);
                    i += 2;
                } else if chars[i] == '*' && chars.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    out.extend([' ', ' ']);
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    out.push(blank(chars[i]));
                    i += 1;
                }
            }
        } else if c == 'r'
            && matches!(next, Some('"' | '#'))
            && !out.last().is_some_and(|&p| ident(p))
        {
            // A raw string r"..." or r#"..."#.
            let hashes = chars[i + 1..].iter().take_while(|&&c| c == '#').count();
            if chars.get(i + 1 + hashes) != Some(&'"') {
                out.push(c);
                i += 1;
                continue;
            }
            out.push('r');
            out.extend(std::iter::repeat_n('#', hashes));
            out.push('"');
            i += 2 + hashes;
            while !(chars[i] == '"' && chars[i + 1..].iter().take(hashes).all(|&c| c == '#')) {
                out.push(blank(chars[i]));
                i += 1;
            }
            out.push('"');
            out.extend(std::iter::repeat_n('#', hashes));
            i += 1 + hashes;
        } else if c == '"' {
            out.push('"');
            i += 1;
            while chars[i] != '"' {
                let n = if chars[i] == '\\' { 2 } else { 1 };
                for k in 0..n {
                    out.push(blank(chars[i + k]));
                }
                i += n;
            }
            out.push('"');
            i += 1;
        } else if c == '\'' && (next == Some('\\') || chars.get(i + 2) == Some(&'\'')) {
            // A character literal ('x' or '\n'); a lifetime ('a) has no closing quote.
            out.push('\'');
            i += 1;
            while chars[i] != '\'' {
                let n = if chars[i] == '\\' { 2 } else { 1 };
                out.extend(std::iter::repeat_n(' ', n));
                i += n;
            }
            out.push('\'');
            i += 1;
        } else {
            out.push(c);
            i += 1;
        }
    }
    out.into_iter().collect()
}

fn read_tree(dir: &Path, out: &mut Vec<Source>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            read_tree(&path, out);
        } else if path.extension().is_some_and(|x| x == "rs") {
            let text = std::fs::read_to_string(&path).expect("a readable source file");
            out.push(Source {
                code: code_only(&text),
                path,
            });
        }
    }
}

/// The index just after the brace that closes the one at `open`.
fn closing(code: &str, open: usize) -> usize {
    let mut depth = 0;
    for (i, c) in code[open..].char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return open + i + 1;
                }
            }
            _ => {}
        }
    }
    panic!("unbalanced braces")
}

/// Does `code[at..]` start the word `word` (not inside a longer identifier)?
fn word_at(code: &str, at: usize, word: &str) -> bool {
    let ident = |c: char| c.is_alphanumeric() || c == '_';
    code[at..].starts_with(word)
        && !code[..at].chars().next_back().is_some_and(ident)
        && !code[at + word.len()..].chars().next().is_some_and(ident)
}

/// One `fn` item directly inside a block: its name, the text of its attributes (everything
/// since the previous item), and whether it has a body.
struct Method {
    name: String,
    attributes: String,
    has_body: bool,
}

/// The `fn` items directly inside the block `code[open..end]` (`open` at its `{`).
fn methods(code: &str, open: usize, end: usize) -> Vec<Method> {
    let mut out = Vec::new();
    let mut item_start = open + 1;
    let mut i = open + 1;
    while i < end - 1 {
        let c = code[i..].chars().next().expect("in range");
        if c == '{' {
            i = closing(code, i);
            item_start = i;
            continue;
        }
        if c == ';' {
            item_start = i + 1;
        } else if word_at(code, i, "fn") {
            let rest = &code[i + 2..];
            let name: String = rest
                .trim_start()
                .chars()
                .take_while(|&c| c.is_alphanumeric() || c == '_')
                .collect();
            // The signature ends at the body's `{` or at the `;` of a declaration.
            let sig_end = rest.find(['{', ';']).expect("a signature ends");
            out.push(Method {
                name,
                attributes: code[item_start..i].to_string(),
                has_body: rest.as_bytes()[sig_end] == b'{',
            });
        }
        i += c.len_utf8();
    }
    out
}

/// A `MeshTopology` impl block: where it is, what it is for, and its methods.
struct Impl {
    file: PathBuf,
    /// The text after `MeshTopology for`, e.g. `HalfEdge<L>` or `$ty`.
    target: String,
    /// The `macro_rules!` it is written in, if any.
    in_macro: Option<String>,
    methods: Vec<Method>,
}

fn impls(sources: &[Source]) -> Vec<Impl> {
    let mut out = Vec::new();
    for s in sources {
        let code = &s.code;
        let mut from = 0;
        while let Some(k) = code[from..].find("MeshTopology for ") {
            let at = from + k;
            from = at + 1;
            let line_start = code[..at].rfind('\n').map_or(0, |n| n + 1);
            if !code[line_start..at].trim_start().starts_with("impl") {
                continue;
            }
            let open = at + code[at..].find('{').expect("an impl has a body");
            let target = code[at + "MeshTopology for ".len()..open]
                .trim()
                .to_string();
            let in_macro = code[..at]
                .rfind("macro_rules!")
                .filter(|&m| closing(code, m + code[m..].find('{').unwrap()) > at)
                .map(|m| {
                    code[m + "macro_rules!".len()..]
                        .trim_start()
                        .chars()
                        .take_while(|&c| c.is_alphanumeric() || c == '_')
                        .collect()
                });
            out.push(Impl {
                file: s.path.clone(),
                target,
                in_macro,
                methods: methods(code, open, closing(code, open)),
            });
        }
    }
    out
}

/// The name before the generic arguments: `HalfEdge` of `HalfEdge<L>`.
fn base(target: &str) -> &str {
    target.split('<').next().unwrap_or(target).trim()
}

/// The impl of the registered structure `name` among its family's `impls`.
fn impl_of<'a>(name: &str, family: &[Source], impls: &'a [Impl]) -> Option<&'a Impl> {
    if let Some(i) = impls.iter().find(|i| base(&i.target) == name) {
        return Some(i);
    }
    for s in family {
        // `type Name = Generic<...>;`
        let alias = format!("type {name} = ");
        if let Some(k) = s.code.find(&alias) {
            let generic = base(s.code[k + alias.len()..].split(';').next().unwrap_or(""));
            if let Some(i) = impls.iter().find(|i| base(&i.target) == generic) {
                return Some(i);
            }
        }
        // `macro_name!(Name, ...)` of a macro that writes the impl.
        for i in impls.iter().filter(|i| i.in_macro.is_some()) {
            let call = format!("{}!({name},", i.in_macro.as_deref().unwrap_or_default());
            if s.code.replace(char::is_whitespace, "").contains(&call) {
                return Some(i);
            }
        }
    }
    None
}

fn inlined(attributes: &str) -> bool {
    attributes.contains("#[inline")
}

/// The methods of `trait MeshTopology` (core/topology.rs) with those of its default bodies.
fn trait_methods() -> Vec<Method> {
    let mut sources = Vec::new();
    read_tree(&src().join("core"), &mut sources);
    let s = sources
        .iter()
        .find(|s| s.path.ends_with("topology.rs"))
        .expect("core/topology.rs");
    let at = s
        .code
        .find("pub trait MeshTopology")
        .expect("the trait is in core/topology.rs");
    let open = at + s.code[at..].find('{').unwrap();
    methods(&s.code, open, closing(&s.code, open))
}

/// The names of the query methods, and the trait's defaults that lack `#[inline]`.
fn queries() -> (Vec<String>, BTreeSet<String>) {
    let all = trait_methods();
    let names: BTreeSet<&str> = all.iter().map(|m| m.name.as_str()).collect();
    for exempt in NOT_QUERIES {
        assert!(
            names.contains(exempt),
            "NOT_QUERIES names `{exempt}`, which MeshTopology does not have"
        );
    }
    let queries: Vec<String> = all
        .iter()
        .filter(|m| !NOT_QUERIES.contains(&m.name.as_str()))
        .map(|m| m.name.clone())
        .collect();
    let slow_defaults = all
        .iter()
        .filter(|m| m.has_body && queries.contains(&m.name) && !inlined(&m.attributes))
        .map(|m| m.name.clone())
        .collect();
    (queries, slow_defaults)
}

/// What the rule finds wrong in the sources under `src`, one line per method.
fn violations() -> Vec<String> {
    let (queries, slow_defaults) = queries();
    assert!(
        queries.iter().any(|q| q == "vertex_vertices") && queries.len() >= 15,
        "the trait's query methods were not found: {queries:?}"
    );
    let mut found = Vec::new();
    for (module, path) in REGISTERED {
        let segments: Vec<&str> = path.split("::").map(str::trim).collect();
        let at = segments
            .iter()
            .position(|&s| s == "families")
            .unwrap_or_else(|| panic!("{module}: {path} is not under families/"));
        let name = segments[segments.len() - 1];
        let mut family = Vec::new();
        read_tree(&src().join("families").join(segments[at + 1]), &mut family);
        let impls = impls(&family);
        let Some(i) = impl_of(name, &family, &impls) else {
            found.push(format!(
                "{module}: no impl of MeshTopology for {name} found under families/{}",
                segments[at + 1]
            ));
            continue;
        };
        for q in &queries {
            let file = i.file.strip_prefix(src()).unwrap_or(&i.file).display();
            match i.methods.iter().find(|m| &m.name == q) {
                Some(m) if !inlined(&m.attributes) => found.push(format!(
                    "{module}: `fn {q}` of the MeshTopology impl in src/{file} lacks #[inline]"
                )),
                None if slow_defaults.contains(q) => found.push(format!(
                    "{module}: `fn {q}` is the trait's default, which lacks #[inline]"
                )),
                _ => {}
            }
        }
    }
    found
}

#[test]
fn every_query_method_of_every_structure_is_inline() {
    let found = violations();
    assert!(
        found.is_empty(),
        "the fairness rule (MeshTopology's docs) asks #[inline] on every query method:\n{}",
        found.join("\n")
    );
}

#[test]
fn every_registered_structure_has_its_impl_found() {
    // The lookup itself: a structure whose impl is not found is reported, not skipped.
    assert_eq!(REGISTERED.len(), topolab_structures::registry::NAMES.len());
    let found = violations();
    assert!(
        !found.iter().any(|f| f.contains("no impl")),
        "{}",
        found.join("\n")
    );
}

#[test]
fn the_source_reader_sees_code_only() {
    let code = code_only(
        "fn a() { let s = \"} fn b\"; let c = '}'; } // fn c {\n/* fn d { */ fn e<'x>(x: &'x u8) {}",
    );
    let open = code.find('{').unwrap();
    assert_eq!(closing(&code, open), code.find("; }").unwrap() + 3);
    assert!(!code.contains("fn b") && !code.contains("fn c") && !code.contains("fn d"));
    assert!(code.contains("fn e<'x>(x: &'x u8)"));
    let block = "impl T { #[inline]\n fn f(&self) {} fn g(&self) { {} }\n #[cold] fn h(); }";
    let ms = methods(block, 7, block.len());
    let names: Vec<(&str, bool, bool)> = ms
        .iter()
        .map(|m| (m.name.as_str(), inlined(&m.attributes), m.has_body))
        .collect();
    assert_eq!(
        names,
        [("f", true, true), ("g", false, true), ("h", false, false)]
    );
}
