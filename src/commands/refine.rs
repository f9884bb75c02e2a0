//! `topolab refine`: subdivides a triangle mesh level by level (midpoint or Loop) and writes
//! the result, optionally renumbered (`--order`), to make the large inputs of the benchmarks
//! from real or generated meshes, in files other tools (the C++ baseline) can read too.

use crate::input::{load_mesh, Failure};
use std::fmt::Write as _;
use std::path::Path;
use std::time::Instant;
use topolab_structures::ordering::{reorder, Ordering};
use topolab_structures::refine::{subdivide_levels, Scheme};
use topolab_structures::Format;

/// Refines `spec` (a file or built-in mesh) `levels` times with `scheme` (a name), renumbers
/// it in `order` (an ordering name) and writes it to `out` (.obj or .off). Progress per level
/// goes to stderr as it happens.
pub fn refine(
    spec: &str,
    levels: usize,
    scheme: &str,
    order: &str,
    out: &Path,
) -> Result<String, Failure> {
    let scheme = Scheme::from_name(scheme).ok_or_else(|| {
        let names: Vec<&str> = Scheme::ALL.iter().map(|s| s.name()).collect();
        Failure::usage(format!(
            "unknown scheme {scheme:?}; known: {}",
            names.join(", ")
        ))
    })?;
    let ordering = Ordering::from_name(order).ok_or_else(|| {
        let names: Vec<String> = Ordering::ALL.iter().map(|o| o.name()).collect();
        Failure::usage(format!(
            "unknown order {order:?}; known: {}, random:SEED",
            names.join(", ")
        ))
    })?;
    // Refuse an unwritable output format before the (long) refinement, not after.
    match topolab_structures::io::format_of(out) {
        Ok(Format::Obj | Format::Off) => {}
        Ok(format) => {
            return Err(Failure::usage(format!(
                "cannot write {format} ({}); use .obj or .off",
                out.display()
            )))
        }
        Err(e) => return Err(Failure::usage(format!("cannot write: {e}"))),
    }
    let soup = load_mesh(spec)?;
    // Each level makes four triangles of one: refuse at once a result whose corners u32 ids
    // cannot number, instead of refining until memory or the ids run out.
    let corners = 4u128
        .checked_pow(u32::try_from(levels).unwrap_or(u32::MAX))
        .and_then(|growth| growth.checked_mul(3 * soup.num_faces() as u128));
    if corners.is_none_or(|c| c > u32::MAX as u128) {
        return Err(Failure::usage(format!(
            "--levels {levels}: {spec} has {} faces, and {levels} levels would make more triangles than u32 ids number",
            soup.num_faces()
        )));
    }
    let started = Instant::now();
    eprintln!(
        "refine: level 0: {} vertices, {} faces",
        soup.num_vertices(),
        soup.num_faces()
    );
    let fine = subdivide_levels(soup, scheme, levels, |level, s| {
        eprintln!(
            "refine: level {level}: {} vertices, {} faces ({:.1} s)",
            s.num_vertices(),
            s.num_faces(),
            started.elapsed().as_secs_f64()
        );
    })
    .map_err(|e| Failure {
        message: format!("cannot refine {spec}: {e}"),
        code: 1,
    })?;
    let fine = if ordering == Ordering::Input {
        fine
    } else {
        let ordered = reorder(&fine, ordering).soup;
        // Free the refined copy before writing: at 16M triangles it is 450 MB.
        drop(fine);
        eprintln!(
            "refine: renumbered in {} order ({:.1} s)",
            ordering.name(),
            started.elapsed().as_secs_f64()
        );
        ordered
    };
    topolab_structures::io::write(out, &fine).map_err(|e| Failure {
        message: format!("cannot write {}: {e}", out.display()),
        code: 2,
    })?;
    let mut text = String::new();
    let _ = writeln!(
        text,
        "{spec}: {levels} levels of {} subdivision, {} order: {} vertices, {} faces, written to {} ({:.1} s)",
        scheme.name(),
        ordering.name(),
        fine.num_vertices(),
        fine.num_faces(),
        out.display(),
        started.elapsed().as_secs_f64()
    );
    Ok(text)
}
