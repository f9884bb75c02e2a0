//! What a message may repeat of a file or a command line: a token of any length shortened to
//! [`MAX_ECHOED_CHARS`] characters and its byte count, and control characters escaped, so
//! that an error about a 1 MB token is one short line and a file name holding an escape
//! sequence does not reach the terminal raw.

use std::borrow::Cow;

/// The most characters of a token a message repeats (escapes counted as the characters they
/// print); a longer token is cut and its length in bytes given.
pub const MAX_ECHOED_CHARS: usize = 60;

/// `bytes` quoted for a message, as `{:?}` quotes a string (invalid UTF-8 as U+FFFD, control
/// characters escaped), cut after [`MAX_ECHOED_CHARS`] characters with the token's length in
/// bytes: `"abc"`, or `"\0\0\0…" (1048576 bytes)`.
pub fn quoted(bytes: &[u8]) -> String {
    // Only the start is decoded: a token of any length costs O(MAX_ECHOED_CHARS).
    let head = &bytes[..bytes.len().min(4 * MAX_ECHOED_CHARS + 4)];
    let text = String::from_utf8_lossy(head);
    let mut out = String::from("\"");
    let mut shown = 0;
    let mut cut = head.len() < bytes.len();
    for c in text.chars() {
        let escaped: String = c.escape_debug().collect();
        let width = escaped.chars().count();
        if shown + width > MAX_ECHOED_CHARS {
            cut = true;
            break;
        }
        out.push_str(&escaped);
        shown += width;
    }
    if cut {
        out.push_str(&format!("…\" ({} bytes)", bytes.len()));
    } else {
        out.push('"');
    }
    out
}

/// `text` with every control character but newline and tab escaped (`\u{1b}` for ESC, as Rust
/// writes it): what reaches a terminal cannot move its cursor, change its colours or retitle
/// its window, whatever a file name or a file holds.
pub fn escape_controls(text: &str) -> Cow<'_, str> {
    let is_bad = |c: char| c.is_control() && c != '\n' && c != '\t';
    if !text.chars().any(is_bad) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        if is_bad(c) {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    Cow::Owned(out)
}

/// A path for a message: its text ([`std::path::Path::display`]) with control characters
/// escaped ([`escape_controls`], newlines and tabs too: a file name is one line).
pub fn path(path: &std::path::Path) -> String {
    let mut out = String::new();
    for c in path.display().to_string().chars() {
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_tokens_are_quoted_as_debug_quotes_them() {
        for token in ["vc", "face", "", "a\tb", "é"] {
            assert_eq!(quoted(token.as_bytes()), format!("{token:?}"));
        }
    }

    #[test]
    fn long_tokens_are_cut_with_their_length() {
        let nul = vec![0u8; 1 << 20];
        let q = quoted(&nul);
        assert!(q.ends_with("…\" (1048576 bytes)"), "{q}");
        assert_eq!(q.matches("\\0").count(), MAX_ECHOED_CHARS / 2);
        let long = "x".repeat(61);
        assert_eq!(
            quoted(long.as_bytes()),
            format!("\"{}…\" (61 bytes)", "x".repeat(60))
        );
        let exact = "x".repeat(60);
        assert_eq!(quoted(exact.as_bytes()), format!("\"{exact}\""));
        // Invalid UTF-8 and a cut inside a multi-byte character.
        let mut bytes = vec![0xffu8; 10];
        bytes.extend("é".repeat(300).bytes());
        let q = quoted(&bytes);
        assert!(q.starts_with("\"\u{fffd}"), "{q}");
        assert!(q.ends_with("(610 bytes)"), "{q}");
    }

    #[test]
    fn control_characters_are_escaped_but_lines_kept() {
        assert_eq!(escape_controls("plain\nline\t"), "plain\nline\t");
        assert_eq!(escape_controls("a\u{1b}[31mb"), "a\\u{1b}[31mb");
        assert_eq!(escape_controls("bell\u{7}\r"), "bell\\u{7}\\r");
        assert_eq!(
            path(std::path::Path::new("x\u{1b}]0;t\u{7}\n.obj")),
            "x\\u{1b}]0;t\\u{7}\\n.obj"
        );
    }
}
