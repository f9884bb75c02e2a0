//! Reading and writing meshes: OBJ, OFF, PLY and STL (ASCII and binary) in; OBJ, OFF, PLY
//! (binary or ASCII) and binary STL out. A mesh is written only when the lab's readers will
//! read the file back as that mesh ([`writable`]).
//!
//! Readers return a [`PolygonSoup`] in file order (vertex i of the file is vertex i of the
//! soup), already checked with [`PolygonSoup::check`]. Bad files give a typed [`Error`] with
//! the line or byte offset, never a panic; a header announcing more elements than the file can
//! hold is refused before anything is allocated.
//!
//! [`read_raw`] and [`read_bytes_raw`] stop short of that check and return a [`RawSoup`]: the
//! file as written, so that `topolab check` can report every problem instead of the first.
//!
//! Tolerant where tolerance loses nothing of the mesh, as other readers are (OpenMesh's, tobj):
//! OBJ statements the lab does not know (`vc`, vendor extensions) and bytes after a binary
//! PLY's last element (a trailing newline, padding) are skipped and listed in
//! [`RawSoup::skipped`] ([`read_with_notes`] returns them, for a warning line); anything that
//! would change the mesh (a short body, an index out of range, a malformed number) stays an
//! error with its line or byte.

use crate::core::error::{Error, Format, Location, Numbering, Result};
use crate::core::soup::PolygonSoup;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// The format of a path, from its extension.
pub fn format_of(path: &Path) -> Result<Format> {
    match path
        .extension()
        .and_then(|e| e.to_str())
        .map(|e| e.to_ascii_lowercase())
    {
        Some(e) if e == "obj" => Ok(Format::Obj),
        Some(e) if e == "off" => Ok(Format::Off),
        Some(e) if e == "ply" => Ok(Format::Ply),
        Some(e) if e == "stl" => Ok(Format::Stl),
        _ => Err(Error::UnknownFormat {
            path: path.to_path_buf(),
        }),
    }
}

pub mod echo;
mod obj;
mod off;
mod ply;
mod ply_write;
mod stl;
mod text;
mod writable;

pub use ply_write::{write_ply, PlyEncoding};
pub use writable::writable;

pub use obj::LISTED_UNKNOWN_KINDS;

/// Reads a mesh file, choosing the reader by extension, and checks it
/// ([`RawSoup::into_checked`]).
pub fn read(path: &Path) -> Result<PolygonSoup> {
    read_raw(path)?.into_checked()
}

/// What a reader tells beside the mesh, for the user: what it skipped because it does not
/// change the mesh (see the module docs), and how many STL corners it welded.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Notes {
    /// [`RawSoup::skipped`].
    pub skipped: Vec<Skipped>,
    /// [`RawSoup::welded_corners`].
    pub welded_corners: usize,
}

/// [`read`], with the reader's [`Notes`].
pub fn read_with_notes(path: &Path) -> Result<(PolygonSoup, Notes)> {
    let mut raw = read_raw(path)?;
    let notes = Notes {
        skipped: std::mem::take(&mut raw.skipped),
        welded_corners: raw.welded_corners,
    };
    Ok((raw.into_checked()?, notes))
}

/// Reads a mesh from memory and checks it ([`RawSoup::into_checked`]).
pub fn read_bytes(bytes: &[u8], format: Format) -> Result<PolygonSoup> {
    read_bytes_raw(bytes, format)?.into_checked()
}

/// Reads a mesh file as written, without [`PolygonSoup::check`]: for tools that report every
/// problem of a file (`topolab check`) instead of stopping at the first.
pub fn read_raw(path: &Path) -> Result<RawSoup> {
    let format = format_of(path)?;
    if format == Format::Ply {
        return ply::read_path(path);
    }
    let bytes = std::fs::read(path).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })?;
    read_bytes_raw(&bytes, format)
}

/// An upper bound on the heap bytes reading a file of `file_bytes` bytes allocates at its
/// peak, given its first bytes `head` (64 KiB are enough for any header the lab writes or
/// meets): the file's bytes, which the readers hold whole but for a binary PLY's body (read a
/// window at a time: its header and the window instead), and the soup, 24 bytes a vertex, 4
/// a corner and 4 a face. How large the soup can be follows from the fewest bytes each element
/// takes in the file, and from what is reserved before the elements are read:
///
/// - OBJ: its `v` and `f` lines are counted first, so vertices (at least 8 bytes, `v 0 0 0`
///   and a newline, for 24) and faces (2, `f` and a newline, for 4) are reserved exactly;
///   corners (2 bytes, ` 1`, for 4) are reserved three a face and may double: the soup at
///   most 4 times the file;
/// - OFF: the counts of its header; a vertex at least 6 bytes (`0 0 0` and a newline): at
///   most 4 times;
/// - PLY: the counts its header announces, the corners bounded by the bytes left (a binary
///   vertex of three one-byte coordinates takes 3 bytes for 24: up to 8 times the file, which
///   only such files reach);
/// - STL: a triangle at least 50 bytes (binary; ASCII takes more) for 16 bytes of corners and
///   offset, up to three new vertices of 24 bytes (their array doubling as it grows) and the
///   welding table's slots (4 bytes each, at most half full): at most 4 times.
///
/// So reading takes at most 5 times the file's size; a binary PLY at most 4, 8 for one of
/// one-byte coordinates. What a command does with the mesh comes on top (measured on a sample and
/// scaled by elements: `topolab`'s limits).
pub fn read_peak_bound(format: Format, head: &[u8], file_bytes: u64) -> u64 {
    let (soup, whole) = match format {
        Format::Obj | Format::Off | Format::Stl => (file_bytes.saturating_mul(4), true),
        Format::Ply => match ply::soup_bound(head, file_bytes) {
            Some((soup, whole)) => (soup.min(file_bytes.saturating_mul(8)), whole),
            None => (file_bytes.saturating_mul(8), true),
        },
    };
    // A binary PLY's body is read a window at a time: its header, read by doubling, is in
    // `head` (twice it, at most, and the window).
    let held = if whole {
        file_bytes
    } else {
        (2 * head.len() as u64 + 64 * 1024).min(file_bytes)
    };
    held.saturating_add(soup).saturating_add(4096)
}

/// Reads a mesh from memory as written, without [`PolygonSoup::check`]. Fails only on what
/// makes the file unreadable (syntax, truncation, an implausible header).
pub fn read_bytes_raw(bytes: &[u8], format: Format) -> Result<RawSoup> {
    match format {
        Format::Obj => obj::read(bytes),
        Format::Off => off::read(bytes),
        Format::Ply => ply::read(bytes),
        Format::Stl => stl::read(bytes),
    }
}

/// The corner value stored in a [`RawSoup`] for an index that no `u32` can hold (negative, or
/// beyond `u32::MAX`). It is never a valid vertex: [`PolygonSoup::check`] refuses soups with
/// `u32::MAX` or more vertices.
pub const UNREPRESENTABLE: u32 = u32::MAX;

/// An index of the file that does not fit a `u32` vertex id.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct UnrepresentableIndex {
    /// The face (0-based, file order).
    pub face: usize,
    /// The corner within the face.
    pub corner: usize,
    /// The index as written, converted to 0-based (saturated at the `i64` range).
    pub index: i64,
}

/// A mesh as the file wrote it: vertex i of the file is vertex i, face j is face j, nothing
/// checked. Corners whose index does not fit a `u32` hold [`UNREPRESENTABLE`] and are listed in
/// `unrepresentable` with the index as written.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RawSoup {
    /// The positions and faces as read.
    pub soup: PolygonSoup,
    /// Every index that did not fit a `u32`, in file order.
    pub unrepresentable: Vec<UnrepresentableIndex>,
    /// What the reader skipped because it does not change the mesh, in file order.
    pub skipped: Vec<Skipped>,
    /// Corners that named a vertex already read at the same position: STL stores positions
    /// per corner, and its reader welds equal ones (0 for the other formats).
    pub welded_corners: usize,
    /// How the file numbers its vertices and faces (OBJ from 1), for messages in its own
    /// numbering; the soup's ids are the lab's, from 0, whatever the file.
    pub numbering: Numbering,
}

/// Something of a file a reader skipped because it does not change the mesh (see the module
/// docs): a warning for the user, not an error.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Skipped {
    /// What was skipped, e.g. `unknown OBJ statement "vc"`.
    pub what: String,
    /// How many times.
    pub count: usize,
    /// Where the first one is.
    pub first: Location,
}

impl std::fmt::Display for Skipped {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.count {
            1 => write!(f, "skipped {} at {}", self.what, self.first),
            n => write!(
                f,
                "skipped {n} times {}, first at {}",
                self.what, self.first
            ),
        }
    }
}

impl RawSoup {
    /// The soup, once [`PolygonSoup::check`] accepts it; an unrepresentable index is reported
    /// first, as [`Error::IndexOutOfRange`] with the index as written. The ids of the error are
    /// in the file's numbering ([`RawSoup::numbering`]).
    pub fn into_checked(self) -> Result<PolygonSoup> {
        let numbering = self.numbering;
        if let Some(bad) = self.unrepresentable.first() {
            return Err(Error::IndexOutOfRange {
                face: bad.face,
                index: bad.index,
                vertices: self.soup.num_vertices(),
                numbering: Numbering::FromZero,
            }
            .numbered(numbering));
        }
        self.soup.check().map_err(|e| e.numbered(numbering))?;
        Ok(self.soup)
    }
}

/// Collects faces corner by corner for the readers, turning file indices (already 0-based)
/// into `u32` corners and recording the ones that do not fit.
struct SoupBuilder {
    raw: RawSoup,
    /// Corners of the face being read.
    face: Vec<u32>,
}

impl SoupBuilder {
    /// Room for `vertices`, `faces` and `corners`: what the header announces, which the
    /// readers bound by what the file's bytes can hold before they ask.
    fn with_capacity(vertices: usize, faces: usize, corners: usize) -> Self {
        Self {
            raw: RawSoup {
                soup: PolygonSoup::with_capacity(vertices, faces, corners),
                ..RawSoup::default()
            },
            face: Vec::new(),
        }
    }

    /// Adds a corner of the current face: `index` is 0-based, as written.
    fn corner(&mut self, index: i64) {
        let stored = u32::try_from(index)
            .ok()
            .filter(|&v| v != UNREPRESENTABLE)
            .unwrap_or_else(|| {
                self.raw.unrepresentable.push(UnrepresentableIndex {
                    face: self.raw.soup.num_faces(),
                    corner: self.face.len(),
                    index,
                });
                UNREPRESENTABLE
            });
        self.face.push(stored);
    }

    /// Ends the current face.
    fn end_face(&mut self) {
        self.raw.soup.push_face(&self.face);
        self.face.clear();
    }

    fn finish(self) -> RawSoup {
        self.raw
    }
}

/// Writes `soup` as OBJ (1-based `v` and `f` lines).
pub fn write_obj(w: &mut impl Write, soup: &PolygonSoup) -> std::io::Result<()> {
    for p in &soup.positions {
        writeln!(w, "v {} {} {}", p.x, p.y, p.z)?;
    }
    for f in soup.faces() {
        write!(w, "f")?;
        for &v in f {
            write!(w, " {}", v + 1)?;
        }
        writeln!(w)?;
    }
    Ok(())
}

/// Writes `soup` as OFF.
pub fn write_off(w: &mut impl Write, soup: &PolygonSoup) -> std::io::Result<()> {
    writeln!(w, "OFF\n{} {} 0", soup.num_vertices(), soup.num_faces())?;
    write_counted_lists(w, soup)
}

/// The body OFF and ASCII PLY share: one position a line, then each face as its corner count
/// and its vertex ids.
pub(crate) fn write_counted_lists(w: &mut impl Write, soup: &PolygonSoup) -> std::io::Result<()> {
    for p in &soup.positions {
        writeln!(w, "{} {} {}", p.x, p.y, p.z)?;
    }
    for f in soup.faces() {
        write!(w, "{}", f.len())?;
        for &v in f {
            write!(w, " {v}")?;
        }
        writeln!(w)?;
    }
    Ok(())
}

/// Writes `soup` as binary STL (little endian; a face of more than three corners as a fan of
/// triangles from its first corner; positions as `f32`, as the format stores them).
pub fn write_stl(w: &mut impl Write, soup: &PolygonSoup) -> std::io::Result<()> {
    stl::write_binary(w, soup)
}

/// Writes `soup` to `path` as OBJ, OFF, binary PLY or binary STL (faces of more than three
/// corners as fans of triangles), by extension, through [`write_atomically`].
pub fn write(path: &Path, soup: &PolygonSoup) -> Result<()> {
    write_as(path, soup, format_of(path)?)
}

/// [`write()`] in `format`, whatever the extension of `path` (PLY binary).
pub fn write_as(path: &Path, soup: &PolygonSoup, format: Format) -> Result<()> {
    write_encoded(path, soup, format, PlyEncoding::Binary)
}

/// [`write_as`] with PLY in `ply` (binary or ASCII). Refuses, before creating anything, a mesh
/// the file would not hold as it is ([`writable`]), so a refused write leaves nothing behind.
pub fn write_encoded(
    path: &Path,
    soup: &PolygonSoup,
    format: Format,
    ply: PlyEncoding,
) -> Result<()> {
    writable(soup, format)?;
    write_atomically(path, |w| match format {
        Format::Obj => write_obj(w, soup),
        Format::Off => write_off(w, soup),
        Format::Stl => write_stl(w, soup),
        Format::Ply => write_ply(w, soup, ply),
    })
    .map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// Creates the temporary file [`write_atomically`] fills before renaming it to `path`: a
/// hidden name with 64 random bits, in the same folder (a rename replaces a file at once only
/// within one file system), opened with create-new semantics (`O_CREAT | O_EXCL`): it fails
/// rather than open anything already there, a symbolic link included, so that nothing
/// planted at a name, predictable or not, is followed or truncated. A name taken is retried
/// with other random bits. Returns the file and its path.
pub fn create_temporary(path: &Path) -> std::io::Result<(File, PathBuf)> {
    use std::hash::{BuildHasher, Hasher};
    use std::sync::atomic::{AtomicU64, Ordering};
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    // The start of the target's name, so that a leftover file says whose it was, short enough
    // that the temporary name stays within the 255 bytes a file name may have.
    let name: String = path
        .file_name()
        .unwrap_or_default()
        .to_string_lossy()
        .chars()
        .take(64)
        .collect();
    let mut last = None;
    for _ in 0..16 {
        // The standard library's hasher keys are random per process (from the OS).
        let mut h = std::collections::hash_map::RandomState::new().build_hasher();
        h.write_u64(COUNTER.fetch_add(1, Ordering::Relaxed));
        h.write_u32(std::process::id());
        let tmp = path.with_file_name(format!(".{name}.{:016x}.tmp", h.finish()));
        match std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&tmp)
        {
            Ok(file) => return Ok((file, tmp)),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => last = Some(e),
            Err(e) => return Err(e),
        }
    }
    Err(last.unwrap_or_else(|| std::io::Error::other("no free temporary name")))
}

/// Writes `path` by filling a new temporary file next to it ([`create_temporary`]) with
/// `fill` and renaming it over `path` once complete, so that `path` is never half-written: it
/// is either what it was before or the whole new file. A symbolic link at `path` is replaced,
/// not followed. When `fill` or the rename fails, the temporary file is removed. A process
/// killed while filling leaves the temporary file behind (never a partial `path`); the file
/// is not synced to disk, so this guards against failed and interrupted runs, not power cuts.
pub fn write_atomically(
    path: &Path,
    fill: impl FnOnce(&mut BufWriter<File>) -> std::io::Result<()>,
) -> std::io::Result<()> {
    let (file, tmp) = create_temporary(path)?;
    let mut w = BufWriter::new(file);
    let written = fill(&mut w)
        .and_then(|()| w.flush())
        .and_then(|()| std::fs::rename(&tmp, path));
    if written.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    written
}
