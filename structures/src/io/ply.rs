//! Stanford PLY, ASCII and binary (little and big endian).
//!
//! The `vertex` element gives the positions (its `x`, `y`, `z` properties, of any scalar type);
//! the `face` element gives the faces (its list property `vertex_indices` or `vertex_index`,
//! of any count and index type). Every other property and element is skipped by its type.

use super::echo::quoted;
use super::text::{
    lines, parse_count, parse_f64, parse_int, parse_or_syntax, plausible, syntax, tokens, truncated,
};
use super::{RawSoup, Skipped, SoupBuilder};
use crate::core::error::{Error, Format, Location, Result};
use glam::DVec3;
use std::fs::File;
use std::io::{Read, Seek, SeekFrom};
use std::path::Path;

const PLY: Format = Format::Ply;

/// A scalar type of the PLY header, with both of its names.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn from_name(name: &[u8]) -> Option<Self> {
        Some(match name {
            b"char" | b"int8" => Scalar::I8,
            b"uchar" | b"uint8" => Scalar::U8,
            b"short" | b"int16" => Scalar::I16,
            b"ushort" | b"uint16" => Scalar::U16,
            b"int" | b"int32" => Scalar::I32,
            b"uint" | b"uint32" => Scalar::U32,
            b"float" | b"float32" => Scalar::F32,
            b"double" | b"float64" => Scalar::F64,
            _ => return None,
        })
    }

    /// Bytes in the binary encodings.
    fn size(self) -> u64 {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }
}

/// A property of an element.
#[derive(Copy, Clone, Debug)]
enum Property {
    /// One value.
    Scalar(Scalar),
    /// A count, then that many items.
    List { count: Scalar, item: Scalar },
}

/// What the reader does with an element's property.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum Role {
    /// Coordinate `axis` of a vertex.
    Coordinate(usize),
    /// The corners of a face.
    Corners,
    /// Nothing: read past it.
    Skip,
}

#[derive(Clone, Debug)]
struct Element {
    count: u64,
    /// Each property with its role.
    properties: Vec<(Property, Role)>,
    /// `true` for the `vertex` element: each instance adds a vertex.
    is_vertex: bool,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum Encoding {
    Ascii,
    LittleEndian,
    BigEndian,
}

struct Header {
    encoding: Encoding,
    elements: Vec<Element>,
    /// Byte offset of the body.
    body: usize,
    /// Line number of the body's first line (for ASCII errors).
    body_line: usize,
}

pub(super) fn read(bytes: &[u8]) -> Result<RawSoup> {
    let header = read_header(bytes)?;
    let file_bytes = bytes.len() as u64;
    match header.encoding {
        Encoding::Ascii => read_elements(
            &header,
            file_bytes,
            &mut AsciiValues {
                bytes: &bytes[header.body..],
                pos: 0,
                line: header.body_line,
            },
        ),
        encoding => read_elements(
            &header,
            file_bytes,
            &mut BinaryValues::new(FileBytes::Memory(bytes), &header, file_bytes, encoding),
        ),
    }
}

/// The bytes of a binary body read from the file at a time.
const WINDOW: usize = 64 * 1024;

/// Reads the PLY file at `path`: an ASCII one whole, as [`read`] does, a binary one's header
/// whole and its body [`WINDOW`] bytes at a time, so that reading it holds the soup and not
/// the file besides (4.9 MB of faces without corners make 19.5 MB of offsets, not 24.4 MB).
pub(super) fn read_path(path: &Path) -> Result<RawSoup> {
    let io = |source| Error::Io {
        path: path.to_path_buf(),
        source,
    };
    let mut file = File::open(path).map_err(io)?;
    let file_bytes = file.metadata().map_err(io)?.len();
    // The header: read until it parses with a byte after its last line (a line cut at the
    // end of what was read may go on), or until the file ends; what was read doubles.
    let mut head = Vec::new();
    let header = loop {
        let before = head.len();
        let more = before.max(WINDOW) as u64;
        Read::by_ref(&mut file)
            .take(more)
            .read_to_end(&mut head)
            .map_err(io)?;
        let whole = head.len() == before || head.len() as u64 >= file_bytes;
        match read_header(&head) {
            Ok(header) if header.body < head.len() || whole => break header,
            Err(e) if whole => return Err(e),
            _ => {}
        }
    };
    let encoding = header.encoding;
    if encoding == Encoding::Ascii {
        file.read_to_end(&mut head).map_err(io)?;
        return read(&head);
    }
    drop(head);
    let body = FileBytes::File {
        file,
        path,
        window: Vec::with_capacity(WINDOW),
    };
    read_elements(
        &header,
        file_bytes,
        &mut BinaryValues::new(body, &header, file_bytes, encoding),
    )
}

/// The elements of a file of `file_bytes` bytes whose header is `header`, from `values`.
fn read_elements(header: &Header, file_bytes: u64, values: &mut impl Values) -> Result<RawSoup> {
    // Refuse counts the body cannot hold before allocating anything.
    let body_bytes = file_bytes.saturating_sub(header.body as u64);
    let [num_vertices, num_faces, corners] = announced(header, body_bytes)?;
    let corners = num_faces.saturating_mul(3).min(corners);
    let mut out =
        SoupBuilder::with_capacity(num_vertices as usize, num_faces as usize, corners as usize);
    let skipped = read_body(values, &header.elements, &mut out)?;
    out.raw.skipped.extend(skipped);
    Ok(out.finish())
}

/// The vertices and faces the header announces, refused ([`Error::ImplausibleHeader`]) when
/// the body's `body_bytes` cannot hold them, and the most corners those bytes can hold: the
/// bytes no element needs for its shortest instance, over a corner's fewest bytes.
fn announced(header: &Header, body_bytes: u64) -> Result<[u64; 3]> {
    let mut remaining = body_bytes + (header.encoding == Encoding::Ascii) as u64;
    let (mut num_vertices, mut num_faces, mut corner_bytes) = (0, 0, 1);
    for e in &header.elements {
        let corners = e.properties.iter().find_map(|p| match p {
            (Property::List { item, .. }, Role::Corners) => Some(*item),
            _ => None,
        });
        let what = if e.is_vertex {
            num_vertices = e.count;
            "vertices"
        } else if let Some(item) = corners {
            num_faces = e.count;
            corner_bytes = match header.encoding {
                Encoding::Ascii => 2,
                _ => item.size(),
            };
            "faces"
        } else {
            "elements"
        };
        remaining = plausible(PLY, what, e.count, min_bytes(e, header.encoding), remaining)?;
    }
    Ok([num_vertices, num_faces, remaining / corner_bytes])
}

/// The most heap bytes the soup of a PLY file of `file_bytes` bytes whose start is `head`
/// takes: the vertices and faces its header announces and the most corners the rest can hold
/// ([`super::read_peak_bound`]); and whether the reader holds the file whole besides (ASCII)
/// or only its header and a window of the body (binary, [`read_path`]). `None` when `head`
/// holds no whole, plausible header.
pub(super) fn soup_bound(head: &[u8], file_bytes: u64) -> Option<(u64, bool)> {
    let header = read_header(head).ok()?;
    let body = file_bytes.checked_sub(header.body as u64)?;
    let [v, f, c] = announced(&header, body).ok()?;
    // Corners reserved three a face may grow, by doubling, to twice the most the bytes hold.
    let soup = 24 * v + 4 * (f + 1) + 8 * c;
    Some((soup, header.encoding == Encoding::Ascii))
}

/// The fewest bytes one instance of `e` takes: in binary, its scalars and list counts (lists
/// may be empty); in ASCII, one digit and one separator per scalar or list count.
fn min_bytes(e: &Element, encoding: Encoding) -> u64 {
    e.properties
        .iter()
        .map(|(p, _)| match (encoding, p) {
            (Encoding::Ascii, _) => 2,
            (_, Property::Scalar(t)) | (_, Property::List { count: t, .. }) => t.size(),
        })
        .sum()
}

fn read_header(bytes: &[u8]) -> Result<Header> {
    let mut lines = lines(bytes, 1);
    match lines.next() {
        Some(l) if l.content == b"ply" => {}
        Some(_) => return Err(syntax(PLY, 1, "expected the magic line `ply`")),
        None => {
            return Err(truncated(
                PLY,
                1,
                "empty file: expected the magic line `ply`",
            ))
        }
    }
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    let mut last = 1;
    for line in lines {
        last = line.number;
        let n = line.number;
        let words: Vec<&[u8]> = tokens(line.content).collect();
        match words.as_slice() {
            [] | [b"comment", ..] | [b"obj_info", ..] => {}
            [b"format", kind, _version] => {
                encoding = Some(match *kind {
                    b"ascii" => Encoding::Ascii,
                    b"binary_little_endian" => Encoding::LittleEndian,
                    b"binary_big_endian" => Encoding::BigEndian,
                    _ => return Err(syntax(PLY, n, "unknown format")),
                })
            }
            [b"element", name, count] => {
                let count = parse_count(count)
                    .ok_or_else(|| syntax(PLY, n, "element count is not a count"))?;
                let is_vertex = *name == b"vertex";
                if is_vertex && elements.iter().any(|e| e.is_vertex) {
                    return Err(syntax(PLY, n, "a second vertex element"));
                }
                elements.push(Element {
                    count,
                    properties: Vec::new(),
                    is_vertex,
                });
            }
            [b"property", ..] => {
                let element = elements
                    .last_mut()
                    .ok_or_else(|| syntax(PLY, n, "property before any element"))?;
                let scalar = |name: &[u8]| {
                    Scalar::from_name(name)
                        .ok_or_else(|| syntax(PLY, n, format!("unknown type {}", quoted(name))))
                };
                let (property, name) = match words.as_slice() {
                    [_, b"list", count, item, name] => (
                        Property::List {
                            count: scalar(count)?,
                            item: scalar(item)?,
                        },
                        *name,
                    ),
                    [_, ty, name] => (Property::Scalar(scalar(ty)?), *name),
                    _ => return Err(syntax(PLY, n, "malformed property line")),
                };
                let role = match (&property, name) {
                    (Property::Scalar(_), b"x") if element.is_vertex => Role::Coordinate(0),
                    (Property::Scalar(_), b"y") if element.is_vertex => Role::Coordinate(1),
                    (Property::Scalar(_), b"z") if element.is_vertex => Role::Coordinate(2),
                    (Property::List { .. }, b"vertex_indices" | b"vertex_index")
                        if !element.is_vertex =>
                    {
                        Role::Corners
                    }
                    _ => Role::Skip,
                };
                if role != Role::Skip && element.properties.iter().any(|p| p.1 == role) {
                    return Err(syntax(PLY, n, "a property given twice"));
                }
                element.properties.push((property, role));
            }
            [b"end_header"] => {
                let encoding =
                    encoding.ok_or_else(|| syntax(PLY, n, "no format line before end_header"))?;
                if let Some(v) = elements.iter().find(|e| e.is_vertex) {
                    for axis in 0..3 {
                        if !v.properties.iter().any(|p| p.1 == Role::Coordinate(axis)) {
                            return Err(syntax(PLY, n, "the vertex element lacks x, y or z"));
                        }
                    }
                }
                return Ok(Header {
                    encoding,
                    elements,
                    body: line.end,
                    body_line: n + 1,
                });
            }
            _ => {
                return Err(syntax(
                    PLY,
                    n,
                    format!("unexpected header line {}", quoted(line.content)),
                ))
            }
        }
    }
    Err(truncated(PLY, last, "the header has no end_header line"))
}

/// The values of a PLY body, in order, whatever the encoding.
trait Values {
    /// The next value, of type `ty`, as a float.
    fn float(&mut self, ty: Scalar) -> Result<f64>;
    /// The next value, of type `ty`, as an integer (saturated to `i64` in ASCII).
    fn int(&mut self, ty: Scalar) -> Result<i64>;
    /// Reads past `n` values of type `ty`.
    fn skip(&mut self, ty: Scalar, n: u64) -> Result<()>;
    /// Where the next value starts.
    fn location(&self) -> Location;
    /// Fails when anything but whitespace is left (ASCII: the header's counts or types do not
    /// describe the body); in a binary body the bytes left (a trailing newline, padding) do
    /// not change the mesh and are returned as skipped.
    fn finish(&mut self) -> Result<Option<Skipped>>;
}

fn read_body(
    values: &mut impl Values,
    elements: &[Element],
    out: &mut SoupBuilder,
) -> Result<Option<Skipped>> {
    for e in elements {
        if e.properties.is_empty() {
            // Nothing to read, however many (a header may announce billions of them).
            continue;
        }
        for _ in 0..e.count {
            let mut xyz = [0.0; 3];
            for (property, role) in &e.properties {
                match (*property, *role) {
                    (Property::Scalar(ty), Role::Coordinate(axis)) => {
                        xyz[axis] = values.float(ty)?
                    }
                    (Property::Scalar(ty), _) => values.skip(ty, 1)?,
                    (Property::List { count, item }, role) => {
                        let location = values.location();
                        let n = u64::try_from(values.int(count)?).map_err(|_| Error::Syntax {
                            format: PLY,
                            location,
                            message: "negative list count".into(),
                        })?;
                        if role == Role::Corners {
                            for _ in 0..n {
                                let index = values.int(item)?;
                                out.corner(index);
                            }
                            out.end_face();
                        } else {
                            values.skip(item, n)?;
                        }
                    }
                }
            }
            if e.is_vertex {
                out.raw.soup.push_vertex(DVec3::from_array(xyz));
            }
        }
    }
    values.finish()
}

/// ASCII body: whitespace-separated numbers.
struct AsciiValues<'a> {
    bytes: &'a [u8],
    pos: usize,
    /// Line of `pos`.
    line: usize,
}

impl<'a> AsciiValues<'a> {
    fn token(&mut self) -> Result<&'a [u8]> {
        while let Some(&b) = self.bytes.get(self.pos) {
            if !b.is_ascii_whitespace() {
                break;
            }
            self.line += (b == b'\n') as usize;
            self.pos += 1;
        }
        let start = self.pos;
        while self
            .bytes
            .get(self.pos)
            .is_some_and(|b| !b.is_ascii_whitespace())
        {
            self.pos += 1;
        }
        if start == self.pos {
            return Err(truncated(PLY, self.line, "expected more values"));
        }
        Ok(&self.bytes[start..self.pos])
    }

    fn parsed<T>(&mut self, parse: fn(&[u8]) -> Option<T>, what: &str) -> Result<T> {
        let word = self.token()?;
        parse_or_syntax(PLY, self.line, word, parse, what)
    }
}

impl Values for AsciiValues<'_> {
    fn float(&mut self, _: Scalar) -> Result<f64> {
        self.parsed(parse_f64, "a number")
    }
    fn int(&mut self, _: Scalar) -> Result<i64> {
        self.parsed(parse_int, "an integer")
    }
    fn skip(&mut self, _: Scalar, n: u64) -> Result<()> {
        for _ in 0..n {
            self.token()?;
        }
        Ok(())
    }
    fn location(&self) -> Location {
        Location::Line(self.line)
    }
    fn finish(&mut self) -> Result<Option<Skipped>> {
        match self.token() {
            Ok(word) => Err(syntax(
                PLY,
                self.line,
                format!(
                    "{} after the last element the header announces",
                    quoted(word)
                ),
            )),
            Err(_) => Ok(None),
        }
    }
}

/// The bytes of a binary PLY file: all of them in memory, or the file, read a window at a
/// time.
enum FileBytes<'a> {
    Memory(&'a [u8]),
    File {
        file: File,
        path: &'a Path,
        /// The bytes from [`BinaryValues::start`] on.
        window: Vec<u8>,
    },
}

/// Binary body: fixed-size values in one byte order; `pos` counts from the start of the file.
struct BinaryValues<'a> {
    bytes: FileBytes<'a>,
    /// Where the bytes in memory start in the file (0 for a file in memory).
    start: u64,
    pos: u64,
    /// The file's length.
    len: u64,
    big_endian: bool,
}

impl<'a> BinaryValues<'a> {
    fn new(bytes: FileBytes<'a>, header: &Header, len: u64, encoding: Encoding) -> Self {
        let start = match bytes {
            FileBytes::Memory(_) => 0,
            // Nothing in memory yet: the first value read fills the window.
            FileBytes::File { .. } => len,
        };
        Self {
            bytes,
            start,
            pos: header.body as u64,
            len,
            big_endian: encoding == Encoding::BigEndian,
        }
    }

    /// The bytes in memory, from [`Self::start`] on.
    fn in_memory(&self) -> &[u8] {
        match &self.bytes {
            FileBytes::Memory(bytes) => bytes,
            FileBytes::File { window, .. } => window,
        }
    }

    /// The next `N` bytes in little-endian order.
    fn take<const N: usize>(&mut self) -> Result<[u8; N]> {
        if self.len - self.pos < N as u64 {
            return Err(self.truncated(N as u64));
        }
        if self.pos < self.start || self.pos + N as u64 > self.start + self.in_memory().len() as u64
        {
            self.refill(N)?;
        }
        let at = (self.pos - self.start) as usize;
        let mut raw: [u8; N] = self.in_memory()[at..at + N].try_into().expect("N bytes");
        if self.big_endian {
            raw.reverse();
        }
        self.pos += N as u64;
        Ok(raw)
    }

    /// Reads the window from `pos` on, at least `n` bytes: only a file read a window at a
    /// time has any to read (a file in memory holds every byte up to `len`).
    fn refill(&mut self, n: usize) -> Result<()> {
        let pos = self.pos;
        let truncated = self.truncated(n as u64);
        let FileBytes::File { file, path, window } = &mut self.bytes else {
            return Err(truncated);
        };
        let io = |source| Error::Io {
            path: path.to_path_buf(),
            source,
        };
        file.seek(SeekFrom::Start(pos)).map_err(io)?;
        window.clear();
        Read::by_ref(file)
            .take(WINDOW as u64)
            .read_to_end(window)
            .map_err(io)?;
        self.start = pos;
        if window.len() < n {
            // The file got shorter than it was when its length was taken.
            return Err(truncated);
        }
        Ok(())
    }

    fn truncated(&self, needed: u64) -> Error {
        Error::Truncated {
            format: PLY,
            location: Location::Byte(self.pos),
            message: format!("{needed} more bytes expected, {} left", self.len - self.pos),
        }
    }

    /// The next value: integers exactly, floats as `f64`.
    fn value(&mut self, ty: Scalar) -> Result<Result<i64, f64>> {
        Ok(match ty {
            Scalar::I8 => Ok(i8::from_le_bytes(self.take()?) as i64),
            Scalar::U8 => Ok(u8::from_le_bytes(self.take()?) as i64),
            Scalar::I16 => Ok(i16::from_le_bytes(self.take()?) as i64),
            Scalar::U16 => Ok(u16::from_le_bytes(self.take()?) as i64),
            Scalar::I32 => Ok(i32::from_le_bytes(self.take()?) as i64),
            Scalar::U32 => Ok(u32::from_le_bytes(self.take()?) as i64),
            Scalar::F32 => Err(f32::from_le_bytes(self.take()?) as f64),
            Scalar::F64 => Err(f64::from_le_bytes(self.take()?)),
        })
    }
}

impl Values for BinaryValues<'_> {
    fn float(&mut self, ty: Scalar) -> Result<f64> {
        Ok(self.value(ty)?.map_or_else(|f| f, |i| i as f64))
    }
    fn int(&mut self, ty: Scalar) -> Result<i64> {
        let location = self.location();
        match self.value(ty)? {
            Ok(i) => Ok(i),
            // A float where an integer belongs: accepted only when it is one.
            Err(f) if f.is_finite() && f.fract() == 0.0 => Ok(f as i64),
            Err(f) => Err(Error::Syntax {
                format: PLY,
                location,
                message: format!("{f} is not an integer"),
            }),
        }
    }
    fn skip(&mut self, ty: Scalar, n: u64) -> Result<()> {
        let bytes = n.saturating_mul(ty.size());
        if bytes > self.len - self.pos {
            return Err(self.truncated(bytes));
        }
        self.pos += bytes;
        Ok(())
    }
    fn location(&self) -> Location {
        Location::Byte(self.pos)
    }
    fn finish(&mut self) -> Result<Option<Skipped>> {
        let left = self.len - self.pos;
        Ok((left > 0).then(|| Skipped {
            what: format!(
                "{left} byte{} after the last element the header announces",
                if left == 1 { "" } else { "s" }
            ),
            count: 1,
            first: self.location(),
        }))
    }
}
