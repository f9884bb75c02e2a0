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

use super::text::{lines, parse_int, parse_or_syntax, position, strip_comment, tokens};
use super::{RawSoup, Skipped, SoupBuilder};
use crate::core::error::{Format, Location, Result};

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
    let mut out = SoupBuilder::with_capacity(0, 0);
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
            other => {
                let what = format!("unknown OBJ statement {:?}", String::from_utf8_lossy(other));
                match out.raw.skipped.iter_mut().find(|s| s.what == what) {
                    Some(seen) => seen.count += 1,
                    None => out.raw.skipped.push(Skipped {
                        what,
                        count: 1,
                        first: Location::Line(line.number),
                    }),
                }
            }
        }
    }
    Ok(out.finish())
}
