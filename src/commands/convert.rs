//! `topolab convert IN OUT [--to FORMAT] [--level N] [--ascii]`: a mesh from any format the lab
//! reads (OBJ, OFF, PLY, STL, or a built-in mesh) to one it writes (OBJ, OFF, PLY, binary STL),
//! the format taken from OUT's extension unless `--to` names it (PLY binary little-endian,
//! ASCII with `--ascii`); or, with `--to che` (or a `.che` OUT), the containers of the CHE of
//! level N (default 2) as a memory-mappable file (docs/che-format.md). Vertex i and face j stay
//! vertex i and face j (STL, which stores triangles only, receives a face of more than three
//! corners as a fan of triangles; reading STL welds corners at exactly the same position).
//! What the lab's readers would not read back as the mesh (an empty mesh; in STL, coordinates
//! beyond `float` or corners `float` cannot tell apart) is refused with exit code 1, and
//! nothing is written; so is an output that is the input.

use crate::input::{invalid_mesh_hint, load_mesh, load_mesh_consumed, refuse_empty, Failure};
use crate::output::{check_file, check_not_input, write_mesh_as};
use std::path::Path;
use std::time::Instant;
use topolab_structures::che::file as che_file;
use topolab_structures::io::PlyEncoding;
use topolab_structures::{Error, Format};

/// The formats `--to` names, by their extension.
const NAMES: [(&str, Format); 4] = [
    ("obj", Format::Obj),
    ("off", Format::Off),
    ("stl", Format::Stl),
    ("ply", Format::Ply),
];

/// What `convert` writes: a mesh format, or the CHE's containers.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum Target {
    /// A mesh file the lab writes.
    Mesh(Format),
    /// A `.che` file (docs/che-format.md).
    Che,
}

/// The `--to` name and extension of a `.che` file.
const CHE: &str = "che";

/// The CHE level `--level` defaults to: the first with the vertex star in O(deg v).
const DEFAULT_LEVEL: u8 = 2;

/// What to write: `to` (a format name), else `out`'s extension.
fn target(out: &Path, to: Option<&str>) -> Result<Target, Failure> {
    if let Some(name) = to {
        if name.eq_ignore_ascii_case(CHE) {
            return Ok(Target::Che);
        }
        return NAMES
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name))
            .map(|&(_, f)| Target::Mesh(f))
            .ok_or_else(|| {
                Failure::usage(format!(
                    "--to {}: not a format; the lab writes obj, off, ply, stl and che",
                    topolab_structures::io::echo::quoted(name.as_bytes())
                ))
            });
    }
    if crate::input::has_che_extension(out) {
        return Ok(Target::Che);
    }
    topolab_structures::io::format_of(out)
        .map(Target::Mesh)
        .map_err(|e| Failure::usage(format!("cannot write: {e}; or name one with --to")))
}

/// Converts `spec` to `out` (in `to`, a format name, or by `out`'s extension); `level` is the
/// CHE level of a `.che` output; `ascii` asks for ASCII PLY (binary by default).
pub fn convert(
    spec: &str,
    out: &Path,
    to: Option<&str>,
    level: Option<u8>,
    ascii: bool,
) -> Result<String, Failure> {
    let target = target(out, to)?;
    if ascii && target != Target::Mesh(Format::Ply) {
        return Err(Failure::usage(
            "--ascii: only a PLY output has an ASCII encoding the lab writes".into(),
        ));
    }
    let format = match target {
        Target::Che => return convert_to_che(spec, out, level.unwrap_or(DEFAULT_LEVEL)),
        Target::Mesh(format) => format,
    };
    if let Some(level) = level {
        return Err(Failure::usage(format!(
            "--level {level}: a CHE level applies to a .che output (--to che) only"
        )));
    }
    check_not_input(spec, out)?;
    check_file(out)?;
    let started = Instant::now();
    let soup = load_mesh(spec, |_| 0)?;
    refuse_empty(spec, &soup)?;
    let encoding = if ascii {
        PlyEncoding::Ascii
    } else {
        PlyEncoding::Binary
    };
    write_mesh_as(out, &soup, format, encoding)?;
    Ok(format!(
        "{spec}: {} vertices, {} faces, written to {} as {format} ({:.2} s)\n",
        soup.num_vertices(),
        soup.num_faces(),
        out.display(),
        started.elapsed().as_secs_f64()
    ))
}

/// Builds the CHE of `level` from `spec` and writes its containers to `out` atomically
/// ([`che_file::write_mesh_owned`]: the mesh's arrays become the CHE's, never held twice). Polygons and non-manifold meshes are refused as the level
/// refuses them (exit code 1).
fn convert_to_che(spec: &str, out: &Path, level: u8) -> Result<String, Failure> {
    if level > 3 {
        return Err(Failure::usage(format!(
            "--level {level}: the CHE levels are 0, 1, 2 and 3"
        )));
    }
    check_not_input(spec, out)?;
    check_file(out)?;
    let started = Instant::now();
    // The memory of the work: the level built from the mesh it consumes (the file is
    // streamed).
    let soup = load_mesh_consumed(spec, |sample| {
        drop(che_file::OwnedLevel::build(sample, level));
        0
    })?;
    refuse_empty(spec, &soup)?;
    let (vertices, faces) = (soup.num_vertices(), soup.num_faces());
    che_file::write_mesh_owned(soup, level, out).map_err(|e| match e {
        Error::Io { source, .. } => {
            Failure::usage(format!("cannot write {}: {source}", out.display()))
        }
        e => Failure {
            message: format!(
                "cannot write {spec} as a level-{level} CHE: {e}{}",
                invalid_mesh_hint(spec, &e)
            ),
            code: 1,
        },
    })?;
    let bytes = std::fs::metadata(out).map_or(0, |m| m.len());
    Ok(format!(
        "{spec}: {vertices} vertices, {faces} faces, written to {} as a level-{level} CHE ({bytes} bytes; `topolab info {}` maps it) ({:.2} s)\n",
        out.display(),
        out.display(),
        started.elapsed().as_secs_f64()
    ))
}
