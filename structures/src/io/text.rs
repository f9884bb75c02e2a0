//! What the text readers share: lines with their numbers and byte offsets, whitespace tokens,
//! comment stripping, number parsing, and the errors that point at a line.

use super::echo::quoted;
use crate::core::error::{Error, Format, Location};
use glam::DVec3;

/// One line of a text file.
#[derive(Copy, Clone, Debug)]
pub(super) struct Line<'a> {
    /// 1-based line number.
    pub number: usize,
    /// The line without its terminator (`\n` or `\r\n`).
    pub content: &'a [u8],
    /// Byte offset just after the line's terminator: where the rest of the file starts.
    pub end: usize,
    /// `false` for a last line with no `\n`: the file may have been cut inside it.
    pub terminated: bool,
}

/// The lines of `bytes`, numbered from `first_number`.
pub(super) fn lines(bytes: &[u8], first_number: usize) -> impl Iterator<Item = Line<'_>> + '_ {
    let mut start = 0;
    let mut number = first_number;
    std::iter::from_fn(move || {
        if start >= bytes.len() {
            return None;
        }
        let (content_end, end, terminated) = match bytes[start..].iter().position(|&b| b == b'\n') {
            Some(i) => (start + i, start + i + 1, true),
            None => (bytes.len(), bytes.len(), false),
        };
        let mut content = &bytes[start..content_end];
        if let [rest @ .., b'\r'] = content {
            content = rest;
        }
        let line = Line {
            number,
            content,
            end,
            terminated,
        };
        start = end;
        number += 1;
        Some(line)
    })
}

/// `content` up to its first `#` (every text format here uses `#` for comments).
pub(super) fn strip_comment(content: &[u8]) -> &[u8] {
    match content.iter().position(|&b| b == b'#') {
        Some(i) => &content[..i],
        None => content,
    }
}

/// The whitespace-separated tokens of `content`.
pub(super) fn tokens(content: &[u8]) -> impl Iterator<Item = &[u8]> + '_ {
    content
        .split(|b| b.is_ascii_whitespace())
        .filter(|t| !t.is_empty())
}

/// A decimal floating-point number (also `nan`, `inf`, which the soup check then refuses).
pub(super) fn parse_f64(token: &[u8]) -> Option<f64> {
    std::str::from_utf8(token).ok()?.parse().ok()
}

/// A decimal integer with optional sign, saturated at the `i64` range (so that an index far
/// beyond `u32` is reported as out of range, not as a syntax error). `None` if not an integer.
pub(super) fn parse_int(token: &[u8]) -> Option<i64> {
    let (negative, digits) = match token {
        [b'-', rest @ ..] => (true, rest),
        [b'+', rest @ ..] => (false, rest),
        _ => (false, token),
    };
    if digits.is_empty() || !digits.iter().all(u8::is_ascii_digit) {
        return None;
    }
    let magnitude = digits.iter().fold(0i64, |acc, &d| {
        acc.saturating_mul(10).saturating_add((d - b'0') as i64)
    });
    Some(if negative { -magnitude } else { magnitude })
}

/// A non-negative count (header counts, face sizes), saturated at `u64::MAX` (so that
/// `18446744073709551615` is reported as written, not as the `i64` range's end).
pub(super) fn parse_count(token: &[u8]) -> Option<u64> {
    let digits = token.strip_prefix(b"+").unwrap_or(token);
    if digits.is_empty() || !digits.iter().all(u8::is_ascii_digit) {
        return None;
    }
    Some(digits.iter().fold(0u64, |acc, &d| {
        acc.saturating_mul(10).saturating_add(u64::from(d - b'0'))
    }))
}

/// An [`Error::Syntax`] at a line.
pub(super) fn syntax(format: Format, line: usize, message: impl Into<String>) -> Error {
    Error::Syntax {
        format,
        location: Location::Line(line),
        message: message.into(),
    }
}

/// An [`Error::Truncated`] at a line.
pub(super) fn truncated(format: Format, line: usize, message: impl Into<String>) -> Error {
    Error::Truncated {
        format,
        location: Location::Line(line),
        message: message.into(),
    }
}

/// A short line: [`Error::Truncated`] when it is an unterminated last line (the file was
/// cut inside it), otherwise [`Error::Syntax`].
pub(super) fn short_line(format: Format, line: &Line<'_>, message: impl Into<String>) -> Error {
    if line.terminated {
        syntax(format, line.number, message)
    } else {
        truncated(format, line.number, message)
    }
}

/// Refuses a header that announces more elements than the remaining bytes could hold, before
/// anything is allocated: each element needs at least `min_bytes` of the `remaining` ones
/// (text readers add one byte: the last element may lack its final separator). Returns the
/// bytes left for the next element kind.
pub(super) fn plausible(
    format: Format,
    what: &'static str,
    announced: u64,
    min_bytes: u64,
    remaining: u64,
) -> Result<u64, Error> {
    let possible = remaining / min_bytes.max(1);
    if announced > possible {
        return Err(Error::ImplausibleHeader {
            format,
            what,
            announced,
            possible,
        });
    }
    Ok(remaining.saturating_sub(announced * min_bytes))
}

/// Parses `word` with `parse`, or an [`Error::Syntax`] saying it is not `what`.
pub(super) fn parse_or_syntax<T>(
    format: Format,
    line: usize,
    word: &[u8],
    parse: fn(&[u8]) -> Option<T>,
    what: &str,
) -> Result<T, Error> {
    parse(word).ok_or_else(|| syntax(format, line, format!("not {what}: {}", quoted(word))))
}

/// The next three words as a position (what follows them is the caller's business).
pub(super) fn position<'a>(
    format: Format,
    line: &Line<'_>,
    words: &mut impl Iterator<Item = &'a [u8]>,
) -> Result<DVec3, Error> {
    let mut xyz = [0.0; 3];
    for (axis, value) in xyz.iter_mut().enumerate() {
        let word = words.next().ok_or_else(|| {
            short_line(format, line, format!("vertex has {axis} of 3 coordinates"))
        })?;
        *value = parse_or_syntax(format, line.number, word, parse_f64, "a number")?;
    }
    Ok(DVec3::from_array(xyz))
}
