//! `topolab convert IN OUT [--to FORMAT]`: a mesh from any format the lab reads (OBJ, OFF,
//! PLY, STL, or a built-in mesh) to one it writes (OBJ, OFF, binary STL), the format taken
//! from OUT's extension unless `--to` names it. Vertex i and face j stay vertex i and face j
//! (STL, which stores triangles only, receives a face of more than three corners as a fan of
//! triangles; reading STL welds corners at exactly the same position).

use crate::input::{load_mesh, Failure};
use crate::output::{check_file, check_writable, write_mesh_as};
use std::path::Path;
use std::time::Instant;
use topolab_structures::Format;

/// The formats `--to` names, by their extension.
const NAMES: [(&str, Format); 4] = [
    ("obj", Format::Obj),
    ("off", Format::Off),
    ("stl", Format::Stl),
    ("ply", Format::Ply),
];

/// Converts `spec` to `out` (in `to`, a format name, or by `out`'s extension).
pub fn convert(spec: &str, out: &Path, to: Option<&str>) -> Result<String, Failure> {
    let format = match to {
        Some(name) => NAMES
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name))
            .map(|&(_, f)| f)
            .ok_or_else(|| {
                Failure::usage(format!(
                    "--to {name:?}: not a format; the lab writes obj, off and stl"
                ))
            })?,
        None => topolab_structures::io::format_of(out)
            .map_err(|e| Failure::usage(format!("cannot write: {e}; or name one with --to")))?,
    };
    check_writable(format, out)?;
    check_file(out)?;
    let started = Instant::now();
    let soup = load_mesh(spec, |_| 0)?;
    write_mesh_as(out, &soup, format)?;
    Ok(format!(
        "{spec}: {} vertices, {} faces, written to {} as {format} ({:.2} s)\n",
        soup.num_vertices(),
        soup.num_faces(),
        out.display(),
        started.elapsed().as_secs_f64()
    ))
}
