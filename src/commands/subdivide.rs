//! `topolab subdivide`: subdivides a mesh level by level and writes it. `sqrt3` runs through
//! the editing operations ([`topolab_structures::MeshEdit`]) on the index half-edge, one step
//! of the Surface_mesh benchmark's √3 subdivision per level
//! ([`topolab_structures::algorithms::changing::sqrt3_step`]: every face split at its
//! centroid, every old interior edge flipped, old interior vertices smoothed; three faces per
//! face and level); `midpoint` and `loop` are `topolab refine`'s schemes (four faces per face
//! and level).
//!
//! Refused before any work, nothing written: an unknown scheme or an unwritable output (exit
//! 2), a result past `u32` ids or the available memory (exit 2), polygons for `sqrt3` and
//! `loop` (triangle schemes) and input the half-edge cannot store, non-manifold or
//! inconsistently oriented (exit 1). The output is written atomically
//! ([`crate::output::write_mesh`]).

use crate::input::{built_in_size, load_mesh, Failure};
use crate::limits;
use crate::output::{check_mesh_out, write_mesh};
use std::path::Path;
use std::time::Instant;
use topolab_structures::algorithms::changing::{sqrt3_step, to_soup};
use topolab_structures::summary::plural;
use topolab_structures::{IndexHalfEdge, MeshTopology, PolygonSoup};

/// The schemes of `topolab subdivide`.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Scheme {
    /// √3 subdivision through the editing operations.
    Sqrt3,
    /// Midpoint subdivision (`topolab refine`).
    Midpoint,
    /// Loop subdivision (`topolab refine`).
    Loop,
}

impl Scheme {
    /// Every scheme.
    pub const ALL: [Scheme; 3] = [Scheme::Sqrt3, Scheme::Midpoint, Scheme::Loop];

    /// The name on the command line.
    pub const fn name(self) -> &'static str {
        match self {
            Scheme::Sqrt3 => "sqrt3",
            Scheme::Midpoint => "midpoint",
            Scheme::Loop => "loop",
        }
    }
}

/// The faces and corners of `levels` √3 levels of `faces` triangles, saturated.
fn sqrt3_counts(faces: u64, levels: usize) -> u128 {
    3u128
        .saturating_pow(u32::try_from(levels).unwrap_or(u32::MAX))
        .saturating_mul(faces.into())
}

/// Refuses a √3 result past `u32` ids (corners, and the half-edge ids of the index
/// half-edge, which stay below 2^31: about 3 per face) or past the available memory: the
/// half-edge built, one level run and the soup written, measured on one level of
/// [`limits::sample_mesh`] and scaled by the result's faces.
fn admit_sqrt3(what: &str, faces: u128) -> Result<(), Failure> {
    limits::within_u32(
        what,
        &[
            ("faces", faces),
            ("corners", faces.saturating_mul(3)),
            ("half-edges (twice)", faces.saturating_mul(6)),
        ],
    )?;
    let sample = limits::sample_mesh();
    if faces <= 3 * sample.num_faces() as u128 {
        return Ok(());
    }
    let (fine_faces, peak) = limits::peak_of(|| {
        IndexHalfEdge::from_soup(&sample).map_or(0, |mut m| {
            let _ = sqrt3_step(&mut m);
            to_soup(&m).num_faces() as u64
        })
    });
    let need = limits::scale(peak + sample.heap_bytes() as u64, fine_faces, faces as u64);
    limits::admit(what, need)
}

/// Subdivides `spec` (a file or built-in mesh) `levels` times with `scheme` (a name) and
/// writes it to `out` (.obj, .off or .stl).
pub fn subdivide(spec: &str, scheme: &str, levels: usize, out: &Path) -> Result<String, Failure> {
    let scheme = Scheme::ALL
        .into_iter()
        .find(|s| s.name() == scheme)
        .ok_or_else(|| {
            let names: Vec<&str> = Scheme::ALL.iter().map(|s| s.name()).collect();
            Failure::usage(format!(
                "unknown scheme {}; known: {}",
                topolab_structures::io::echo::quoted(scheme.as_bytes()),
                names.join(", ")
            ))
        })?;
    if scheme != Scheme::Sqrt3 {
        return super::refine::refine(spec, levels, scheme.name(), "input", out);
    }
    check_mesh_out(out, spec)?;
    let what = |faces: u64| format!("--levels {levels} of √3 of {spec} ({faces} faces)");
    if let Some(size) = built_in_size(spec) {
        admit_sqrt3(&what(size.faces), sqrt3_counts(size.faces, levels))?;
    }
    let soup = load_mesh(spec, |_| 0)?;
    if let Some((face, corners)) = soup.first_non_triangle() {
        return Err(Failure {
            message: format!(
                "cannot subdivide {spec} with sqrt3: it is a triangle scheme, but face {face} has {corners} corners"
            ),
            code: 1,
        });
    }
    let faces = soup.num_faces() as u64;
    admit_sqrt3(&what(faces), sqrt3_counts(faces, levels))?;
    let started = Instant::now();
    let mut mesh = IndexHalfEdge::from_soup(&soup).map_err(|e| Failure {
        message: format!("cannot subdivide {spec}: {e}"),
        code: 1,
    })?;
    drop(soup);
    for level in 1..=levels {
        sqrt3_step(&mut mesh).map_err(|e| Failure {
            message: format!("cannot subdivide {spec}: level {level}: {e}"),
            code: 1,
        })?;
        eprintln!(
            "subdivide: level {level}: {} vertices, {} faces ({:.1} s)",
            mesh.num_vertices(),
            mesh.num_faces(),
            started.elapsed().as_secs_f64()
        );
    }
    let fine: PolygonSoup = to_soup(&mesh);
    drop(mesh);
    write_mesh(out, &fine)?;
    Ok(format!(
        "{spec}: {levels} level{} of sqrt3 subdivision: {} vertices, {} faces, written to {} ({:.1} s)\n",
        plural(levels),
        fine.num_vertices(),
        fine.num_faces(),
        out.display(),
        started.elapsed().as_secs_f64()
    ))
}
