//! Wavefront OBJ: our own line parser, so that vertex i of the file is vertex i of the soup
//! (no re-indexing per group, unused vertices kept) and errors carry line numbers.
//!
//! Read: `v x y z` (extra `w` or colour values ignored) and `f` with corners `v`, `v/vt`,
//! `v//vn`, `v/vt/vn`, 1-based or negative (relative to the vertices read so far). Every
//! other statement of the OBJ specification (`vt`, `vn`, `o`, `g`, `s`, `usemtl`, `mtllib`,
//! `l`, `p`, free-form geometry, ...) and comments are skipped; so is a statement the
//! specification does not have (`vc` vertex colours, vendor extensions), as tobj and OpenMesh
//! skip it, but listed in [`RawSoup::skipped`] (per keyword: how often, and the first line), so
//! that a file that is not OBJ at all does not pass unnoticed. Line continuations (`\`) are
//! not supported.

use super::echo::quoted;
use super::text::{lines, parse_int, parse_or_syntax, position, strip_comment, tokens};
use super::{RawSoup, Skipped, SoupBuilder};
use crate::core::error::{Format, Location, Numbering, Result};

/// OBJ statements that carry nothing a polygon soup stores.
const SKIPPED: &[&[u8]] = &[
    b"vt",
    b"vn",
    b"vp",
    b"o",
    b"g",
    b"s",
    b"mg",
    b"usemtl",
    b"mtllib",
    b"l",
    b"p",
    b"cstype",
    b"deg",
    b"bmat",
    b"step",
    b"curv",
    b"curv2",
    b"surf",
    b"parm",
    b"trim",
    b"hole",
    b"scrv",
    b"sp",
    b"end",
    b"con",
    b"lod",
    b"usemap",
    b"maplib",
    b"bevel",
    b"c_interp",
    b"d_interp",
    b"shadow_obj",
    b"trace_obj",
    b"ctech",
    b"stech",
    b"call",
    b"csh",
];

pub(super) fn read(bytes: &[u8]) -> Result<RawSoup> {
    const OBJ: Format = Format::Obj;
    let [vertices, faces] = statements(bytes);
    let mut out = SoupBuilder::with_capacity(vertices, faces, faces.saturating_mul(3));
    out.raw.numbering = Numbering::FromOne;
    let mut unknown = Unknown::default();
    for line in lines(bytes, 1) {
        let mut words = tokens(strip_comment(line.content));
        let Some(keyword) = words.next() else {
            continue;
        };
        match keyword {
            b"v" => {
                let p = position(OBJ, &line, &mut words)?;
                out.raw.soup.push_vertex(p);
            }
            b"f" => {
                let vertices_so_far = out.raw.soup.num_vertices() as i64;
                for word in words {
                    // `v`, `v/vt`, `v//vn`, `v/vt/vn`: only the position index matters.
                    let position_index = word.split(|&b| b == b'/').next().unwrap_or(word);
                    let index = parse_or_syntax(
                        OBJ,
                        line.number,
                        position_index,
                        parse_int,
                        "a vertex index",
                    )?;
                    // 1-based; negative counts back from the last vertex read; 0 is no vertex.
                    out.corner(match index {
                        i if i > 0 => i - 1,
                        0 => -1,
                        i => vertices_so_far.saturating_add(i),
                    });
                }
                out.end_face();
            }
            other if SKIPPED.contains(&other) => {}
            other => unknown.note(other, line.number, &mut out.raw.skipped),
        }
    }
    unknown.finish(&mut out.raw.skipped);
    Ok(out.finish())
}

/// How many `v` and `f` statements `bytes` holds (lines whose first word is `v` or `f`): the
/// soup's arrays are reserved once, exactly, instead of growing to up to twice their size.
/// One pass over the bytes, a few operations a line.
fn statements(bytes: &[u8]) -> [usize; 2] {
    let mut counts = [0, 0];
    for line in bytes.split(|&b| b == b'\n') {
        let start = line.iter().position(|b| !b.is_ascii_whitespace());
        let Some(rest) = start.map(|i| &line[i..]) else {
            continue;
        };
        let second_is_space = rest.get(1).is_none_or(|b| b.is_ascii_whitespace());
        match rest[0] {
            b'v' if second_is_space => counts[0] += 1,
            b'f' if second_is_space => counts[1] += 1,
            _ => {}
        }
    }
    counts
}

/// The unknown statement kinds listed one by one in [`RawSoup::skipped`]; the statements of
/// further kinds are counted together in one more entry. A file cannot make the reader keep
/// (or the user read) a list as long as itself, and finding a kind among those listed costs
/// at most this many comparisons.
pub const LISTED_UNKNOWN_KINDS: usize = 8;

/// The unknown statements met so far: the first [`LISTED_UNKNOWN_KINDS`] kinds (their raw
/// keyword, to compare with the next ones) and the others counted.
#[derive(Default)]
struct Unknown {
    /// The keyword of each listed kind, in the order of `skipped`.
    keywords: Vec<Vec<u8>>,
    /// Statements of the kinds not listed: how many, and the first one's line.
    others: Option<(usize, usize)>,
}

impl Unknown {
    /// Counts the statement `keyword` at `line` in `skipped`.
    fn note(&mut self, keyword: &[u8], line: usize, skipped: &mut Vec<Skipped>) {
        if let Some(i) = self.keywords.iter().position(|k| k == keyword) {
            skipped[i].count += 1;
        } else if self.keywords.len() < LISTED_UNKNOWN_KINDS {
            self.keywords.push(keyword.to_vec());
            skipped.push(Skipped {
                what: format!("unknown OBJ statement {}", quoted(keyword)),
                count: 1,
                first: Location::Line(line),
            });
        } else {
            let (count, _) = self.others.get_or_insert((0, line));
            *count += 1;
        }
    }

    /// Adds the statements of the kinds not listed to `skipped`, as one entry.
    fn finish(self, skipped: &mut Vec<Skipped>) {
        if let Some((count, line)) = self.others {
            skipped.push(Skipped {
                what: format!(
                    "unknown OBJ statement{} of kinds beyond the first {LISTED_UNKNOWN_KINDS}",
                    if count == 1 { "" } else { "s" }
                ),
                count,
                first: Location::Line(line),
            });
        }
    }
}
