//! Writing PLY: binary little-endian (the default, what scanners and most tools exchange) or
//! ASCII, positions as `double` so that every coordinate reads back bit for bit, faces as a
//! list of `uint` indices with a `uchar` count (`uint` when a face has more than 255 corners).

use crate::core::soup::PolygonSoup;
use std::io::Write;

/// The encoding of a PLY file the lab writes.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub enum PlyEncoding {
    /// `binary_little_endian`.
    #[default]
    Binary,
    /// `ascii`: one element per line.
    Ascii,
}

/// Writes `soup` as PLY in `encoding`.
pub fn write_ply(
    w: &mut impl Write,
    soup: &PolygonSoup,
    encoding: PlyEncoding,
) -> std::io::Result<()> {
    let wide = soup.faces().any(|f| f.len() > u8::MAX as usize);
    let count_type = if wide { "uint" } else { "uchar" };
    let format = match encoding {
        PlyEncoding::Binary => "binary_little_endian",
        PlyEncoding::Ascii => "ascii",
    };
    write!(
        w,
        "ply\nformat {format} 1.0\ncomment written by topolab\nelement vertex {}\n\
         property double x\nproperty double y\nproperty double z\nelement face {}\n\
         property list {count_type} uint vertex_indices\nend_header\n",
        soup.num_vertices(),
        soup.num_faces()
    )?;
    match encoding {
        PlyEncoding::Ascii => super::write_counted_lists(w, soup)?,
        PlyEncoding::Binary => {
            for p in &soup.positions {
                for x in p.to_array() {
                    w.write_all(&x.to_le_bytes())?;
                }
            }
            for f in soup.faces() {
                if wide {
                    w.write_all(&(f.len() as u32).to_le_bytes())?;
                } else {
                    w.write_all(&[f.len() as u8])?;
                }
                for &v in f {
                    w.write_all(&v.to_le_bytes())?;
                }
            }
        }
    }
    Ok(())
}
