//! `topolab refine`: subdivides a triangle mesh level by level (midpoint or Loop) and writes
//! the result, optionally renumbered (`--order`), to make the large inputs of the benchmarks
//! from real or generated meshes, in files other tools (the C++ baseline) can read too; with
//! `--max-edge` instead of `--levels`, refines adaptively
//! ([`super::refine_adaptive`]: the edges longer than L, inside a box if given).

use crate::input::{built_in_size, load_mesh, Failure};
use crate::limits;
use crate::output::{check_mesh_out, write_mesh};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;
use topolab_structures::ordering::{reorder, Ordering};
use topolab_structures::refine::{subdivide, subdivide_levels, Scheme};
use topolab_structures::summary::plural;
use topolab_structures::PolygonSoup;

/// Options of `topolab refine`: uniform (`--levels`) or adaptive (`--max-edge`), one of them.
#[derive(clap::Args, Debug, Clone)]
#[command(group = clap::ArgGroup::new("mode").required(true).args(["levels", "max_edge"]))]
pub struct RefineArgs {
    /// A triangle mesh file (.obj, .off, .ply, .stl) or a built-in mesh (see `topolab info --help`).
    pub mesh: String,
    /// Uniform refinement: the number of levels (each: 4 triangles per triangle).
    #[arg(long)]
    pub levels: Option<usize>,
    /// Adaptive refinement: split every edge longer than this, longest first, until none is
    /// left (longest-edge bisection through the editing operations; the mesh stays conforming).
    #[arg(long, allow_hyphen_values = true)]
    pub max_edge: Option<f64>,
    /// Adaptive refinement only in this box: `xmin,ymin,zmin,xmax,ymax,zmax` (the edges with
    /// both ends inside it).
    #[arg(long, conflicts_with = "levels", allow_hyphen_values = true)]
    pub region: Option<String>,
    /// The editable structure that refines adaptively (see `topolab list`).
    #[arg(long, conflicts_with = "levels", default_value = super::refine_adaptive::DEFAULT_STRUCTURE)]
    pub structure: String,
    /// Uniform refinement: where new vertices go, `midpoint` (same shape) or `loop` (smooth).
    #[arg(long, default_value = "midpoint", conflicts_with = "max_edge")]
    pub scheme: String,
    /// The output file (.obj, .off or .stl).
    #[arg(long)]
    pub out: PathBuf,
    /// Uniform refinement: renumber the result: `input` (as refined: new vertices appended),
    /// `random`, `random:SEED`, `morton`, `hilbert` or `bfs` (see
    /// `topolab_structures::ordering`).
    #[arg(long, default_value = "input", conflicts_with = "max_edge")]
    pub order: String,
}

/// Runs `topolab refine`: [`refine`] with `--levels`, [`super::refine_adaptive::adaptive`] with
/// `--max-edge`. Both or neither is a usage error (exit 2), as clap already says on the command
/// line.
pub fn run(args: &RefineArgs) -> Result<String, Failure> {
    match (args.levels, args.max_edge) {
        (Some(levels), None) => refine(&args.mesh, levels, &args.scheme, &args.order, &args.out),
        (None, Some(max_edge)) => super::refine_adaptive::adaptive(
            &args.mesh,
            max_edge,
            args.region.as_deref(),
            &args.structure,
            &args.out,
        ),
        (Some(_), Some(_)) => Err(Failure::usage(
            "--levels refines uniformly, --max-edge adaptively: give one of them, not both"
                .to_string(),
        )),
        (None, None) => Err(Failure::usage(
            "give --levels N (uniform refinement) or --max-edge L (adaptive refinement)"
                .to_string(),
        )),
    }
}

/// Refuses `levels` levels of a mesh of `input_faces` faces when the result's ids would pass
/// `u32`; returns the request's description and the result's faces.
fn levels_within_u32(
    spec: &str,
    input_faces: u64,
    levels: usize,
) -> Result<(String, u128), Failure> {
    // Each level makes four triangles of one: 3 F 4^L corners, saturated far past u32.
    let growth = 4u128.saturating_pow(u32::try_from(levels).unwrap_or(u32::MAX));
    let faces = growth.saturating_mul(input_faces.into());
    let what = format!("--levels {levels} of {spec} ({input_faces} faces)");
    limits::within_u32(
        &what,
        &[("faces", faces), ("corners", faces.saturating_mul(3))],
    )?;
    Ok((what, faces))
}

/// Refuses `levels` levels of `soup` when the result's ids would pass `u32` or its last level
/// would not fit in memory: that level's input, edge analysis and output, and the renumbered
/// copy, measured on one level of [`limits::sample_mesh`] and scaled by the result's corners.
/// The estimate is stated on stderr before it is checked: the faces the last level has and,
/// past the sample's size, the memory it needs.
fn admit_levels(
    spec: &str,
    soup: &PolygonSoup,
    levels: usize,
    scheme: Scheme,
    ordering: Ordering,
) -> Result<(), Failure> {
    let (what, faces) = levels_within_u32(spec, soup.num_faces() as u64, levels)?;
    let sample = limits::sample_mesh();
    if levels == 0 || faces <= 4 * sample.num_faces() as u128 {
        eprintln!("refine: {what}: {faces} faces when done");
        return Ok(());
    }
    let (fine_corners, peak) = limits::peak_of(|| {
        let fine = subdivide(&sample, scheme).map_or(0, |fine| {
            let corners = fine.num_corners();
            if ordering != Ordering::Input {
                reorder(&fine, ordering);
            }
            corners
        });
        fine as u64
    });
    let need = limits::scale(
        peak + sample.heap_bytes() as u64,
        fine_corners,
        3 * faces as u64,
    );
    eprintln!(
        "refine: {what}: {faces} faces when done, about {} of memory",
        limits::human(need)
    );
    limits::admit(&what, need)
}

/// Refines `spec` (a file or built-in mesh) `levels` times with `scheme` (a name), renumbers
/// it in `order` (an ordering name) and writes it to `out` (.obj, .off or .stl). Progress per level
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
            "unknown scheme {}; known: {}",
            topolab_structures::io::echo::quoted(scheme.as_bytes()),
            names.join(", ")
        ))
    })?;
    let ordering = Ordering::from_name(order).ok_or_else(|| {
        let names: Vec<String> = Ordering::ALL.iter().map(|o| o.name()).collect();
        Failure::usage(format!(
            "unknown order {}; known: {}, random:SEED",
            topolab_structures::io::echo::quoted(order.as_bytes()),
            names.join(", ")
        ))
    })?;
    // Refuse an unwritable output before the (long) refinement, not after.
    check_mesh_out(out, spec)?;
    // A built-in mesh's size is known before it is generated: too many levels of a large one
    // are refused without generating it.
    if let Some(size) = built_in_size(spec) {
        levels_within_u32(spec, size.faces, levels)?;
    }
    let soup = load_mesh(spec, |_| 0)?;
    admit_levels(spec, &soup, levels, scheme, ordering)?;
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
    write_mesh(out, &fine)?;
    let mut text = String::new();
    let _ = writeln!(
        text,
        "{spec}: {levels} level{} of {} subdivision, {} order: {} vertices, {} faces, written to {} ({:.1} s)",
        plural(levels),
        scheme.name(),
        ordering.name(),
        fine.num_vertices(),
        fine.num_faces(),
        out.display(),
        started.elapsed().as_secs_f64()
    );
    Ok(text)
}
