//! Reading and writing meshes: OBJ, OFF, PLY and STL (ASCII and binary) in; OBJ, OFF and
//! binary STL out.
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

use crate::core::error::{Error, Format, Location, Result};
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

pub mod che_file;
mod obj;
mod off;
mod ply;
mod stl;
mod text;

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
    let bytes = std::fs::read(path).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })?;
    read_bytes_raw(&bytes, format)
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
    /// first, as [`Error::IndexOutOfRange`] with the index as written.
    pub fn into_checked(self) -> Result<PolygonSoup> {
        if let Some(bad) = self.unrepresentable.first() {
            return Err(Error::IndexOutOfRange {
                face: bad.face,
                index: bad.index,
                vertices: self.soup.num_vertices(),
            });
        }
        self.soup.check()?;
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
    fn with_capacity(vertices: usize, faces: usize) -> Self {
        Self {
            raw: RawSoup {
                soup: PolygonSoup::with_capacity(vertices, faces, faces.saturating_mul(3)),
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

/// Writes `soup` to `path` as OBJ, OFF or binary STL (faces of more than three corners as
/// fans of triangles), by extension, through [`write_atomically`].
pub fn write(path: &Path, soup: &PolygonSoup) -> Result<()> {
    write_as(path, soup, format_of(path)?)
}

/// [`write()`] in `format`, whatever the extension of `path`.
pub fn write_as(path: &Path, soup: &PolygonSoup, format: Format) -> Result<()> {
    // Refuse before creating anything, so a refused write leaves no empty file behind.
    let write_as: fn(&mut BufWriter<File>, &PolygonSoup) -> std::io::Result<()> = match format {
        Format::Obj => |w, s| write_obj(w, s),
        Format::Off => |w, s| write_off(w, s),
        Format::Stl => |w, s| write_stl(w, s),
        Format::Ply => {
            return Err(Error::Unsupported(
                "writing PLY is not supported; use .obj, .off or .stl".into(),
            ))
        }
    };
    write_atomically(path, |w| write_as(w, soup)).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// The temporary file [`write_atomically`] fills before renaming it to `path`: a hidden name
/// with the process id, in the same folder (a rename replaces a file at once only within one
/// file system).
pub fn temporary_path(path: &Path) -> PathBuf {
    let name = path.file_name().unwrap_or_default().to_string_lossy();
    path.with_file_name(format!(".{name}.{}.tmp", std::process::id()))
}

/// Writes `path` by filling its [`temporary_path`] with `fill` and renaming it over `path` once
/// complete, so that `path` is never half-written: it is either what it was before or the
/// whole new file. When `fill` or the rename fails, the temporary file is removed. A process
/// killed while filling leaves the temporary file behind (never a partial `path`); the file
/// is not synced to disk, so this guards against failed and interrupted runs, not power cuts.
pub fn write_atomically(
    path: &Path,
    fill: impl FnOnce(&mut BufWriter<File>) -> std::io::Result<()>,
) -> std::io::Result<()> {
    let tmp = temporary_path(path);
    let written = File::create(&tmp).and_then(|file| {
        let mut w = BufWriter::new(file);
        fill(&mut w)?;
        w.flush()?;
        std::fs::rename(&tmp, path)
    });
    if written.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    written
}
