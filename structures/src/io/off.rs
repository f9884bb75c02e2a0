//! Object File Format: a header line `OFF` (or `COFF`, `NOFF`, `STOFF`, ... whose extra
//! per-vertex values are ignored), the counts `vertices faces [edges]` on the same line or the
//! next, then one vertex per line (`x y z ...`) and one face per line (`k i1 .. ik`, trailing
//! colour values allowed), 0-based. `#` starts a comment; blank lines are skipped.

use super::echo::quoted;
use super::text::{
    lines, parse_count, parse_int, parse_or_syntax, plausible, position, short_line, strip_comment,
    syntax, tokens, truncated, Line,
};
use super::{RawSoup, SoupBuilder};
use crate::core::error::{Error, Format, Result};

const OFF: Format = Format::Off;
/// The shortest vertex line, `0 0 0\n`.
const MIN_VERTEX_BYTES: u64 = 6;
/// The shortest face line, `0\n` (a face without corners is readable; the soup check refuses
/// it), so the bound never refuses a file that would read.
const MIN_FACE_BYTES: u64 = 2;

pub(super) fn read(bytes: &[u8]) -> Result<RawSoup> {
    // Only lines with content matter; comments and blank lines are skipped everywhere.
    let mut content = lines(bytes, 1).filter(|l| tokens(strip_comment(l.content)).next().is_some());
    let header = content
        .next()
        .ok_or_else(|| truncated(OFF, 1, "empty file: expected the OFF header"))?;
    let mut words = tokens(strip_comment(header.content));
    let keyword = words.next().unwrap_or_default();
    check_keyword(keyword, header.number)?;
    // The counts follow the keyword on its line, or fill the next line.
    let mut counts: Vec<&[u8]> = words.collect();
    let mut counts_line = header;
    if counts.is_empty() {
        counts_line = content
            .next()
            .ok_or_else(|| truncated(OFF, header.number + 1, "expected the element counts"))?;
        counts = tokens(strip_comment(counts_line.content)).collect();
    }
    if counts.len() < 2 {
        return Err(short_line(
            OFF,
            &counts_line,
            "expected `vertices faces [edges]`",
        ));
    }
    let count = |word| parse_or_syntax(OFF, counts_line.number, word, parse_count, "a count");
    let (num_vertices, num_faces) = (count(counts[0])?, count(counts[1])?);
    let remaining = (bytes.len() - counts_line.end) as u64 + 1;
    let remaining = plausible(OFF, "vertices", num_vertices, MIN_VERTEX_BYTES, remaining)?;
    let slack = plausible(OFF, "faces", num_faces, MIN_FACE_BYTES, remaining)?;
    // Each corner takes at least two bytes (` 7`) beyond its face's shortest line.
    let corners = num_faces.saturating_mul(3).min(slack / 2);
    let mut out =
        SoupBuilder::with_capacity(num_vertices as usize, num_faces as usize, corners as usize);
    let mut last_line = counts_line.number;
    let mut next_line = |what: &str, read: u64, total: u64| {
        content
            .next()
            .inspect(|l| last_line = l.number)
            .ok_or_else(|| {
                truncated(
                    OFF,
                    last_line + 1,
                    format!("expected {total} {what}, found {read}"),
                )
            })
    };
    for v in 0..num_vertices {
        let line = next_line("vertices", v, num_vertices)?;
        let p = position(OFF, &line, &mut tokens(strip_comment(line.content)))?;
        out.raw.soup.push_vertex(p);
    }
    for f in 0..num_faces {
        let line = next_line("faces", f, num_faces)?;
        face(&line, &mut out)?;
    }
    // Anything after the faces (an edge list, say) is not part of the soup.
    Ok(out.finish())
}

/// Accepts `OFF` with the optional prefixes of the format (`ST`, `C`, `N`, in that order);
/// refuses the `4OFF`, `nOFF` and binary variants.
fn check_keyword(keyword: &[u8], line: usize) -> Result<()> {
    let Some(prefix) = keyword.strip_suffix(b"OFF") else {
        return Err(syntax(
            OFF,
            line,
            format!("expected the OFF header, found {}", quoted(keyword)),
        ));
    };
    let prefix = prefix.strip_prefix(b"ST").unwrap_or(prefix);
    let prefix = prefix.strip_prefix(b"C").unwrap_or(prefix);
    let prefix = prefix.strip_prefix(b"N").unwrap_or(prefix);
    if !prefix.is_empty() {
        return Err(Error::Unsupported(format!(
            "OFF line {line}: the {} variant is not supported",
            quoted(keyword)
        )));
    }
    Ok(())
}

/// `k i1 .. ik`, trailing colour values ignored.
fn face(line: &Line<'_>, out: &mut SoupBuilder) -> Result<()> {
    let mut words = tokens(strip_comment(line.content));
    let size_word = words.next().unwrap_or_default();
    let size = parse_or_syntax(OFF, line.number, size_word, parse_count, "a face size")?;
    for k in 0..size {
        let word = words
            .next()
            .ok_or_else(|| short_line(OFF, line, format!("face has {k} of its {size} corners")))?;
        let index = parse_or_syntax(OFF, line.number, word, parse_int, "a vertex index")?;
        out.corner(index);
    }
    out.end_face();
    Ok(())
}
