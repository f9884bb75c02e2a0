//! `topolab refine FILE --max-edge L [--region xmin,ymin,zmin,xmax,ymax,zmax] [--structure
//! NAME] --out FILE`: adaptive refinement by longest-edge bisection
//! ([`topolab_structures::algorithms::adaptive`]) on any editable structure of the registry
//! (the index half-edge by default), and the result written.
//!
//! Refused before any work, nothing written (exit 2): a `--max-edge` that is not a finite
//! length > 0, a `--region` that is not six finite numbers with each minimum at most its
//! maximum, an unknown `--structure`, an unwritable output, and a request whose fewest faces
//! ([`fewest_faces`], a lower bound) pass what `u32` ids number, or whose predicted faces
//! ([`predicted_faces`], an estimate from the area) need more than the available memory holds
//! (`--allow-memory` runs it anyway). The prediction and its memory are stated on stderr before
//! the work, and the faces made so far shown against it while it runs (a bar, on a terminal).
//! Refused (exit 1): a structure that cannot refine locally (the regular grid and the height
//! field, whose vertices are implicit in (i, j): a split would break the grid; explicit
//! storage, which moves vertices only and does not offer the split), polygons, input the structure cannot store. The
//! final face count is known only once the refinement ends (the medians a split makes may be
//! split too), so the refinement runs under a budget of faces, the lower of the `u32` limit and
//! what the available memory holds at the structure's bytes per face (measured on
//! [`limits::sample_mesh`]); a refinement that would pass it stops, nothing written (exit 2).

use crate::input::{load_mesh, refuse_empty, Failure};
use crate::limits;
use crate::output::{check_mesh_out, write_mesh};
use crate::registry::{self, EditVisitor};
use indicatif::{ProgressBar, ProgressStyle};
use std::path::Path;
use std::time::Instant;
use topolab_structures::algorithms::adaptive::{
    fewest_faces, predicted_faces, refine_adaptive_with_progress, Region, Request,
};
use topolab_structures::algorithms::changing::to_soup;
use topolab_structures::glam::DVec3;
use topolab_structures::summary::plural;
use topolab_structures::{EditOp, Error, MeshEdit, PolygonSoup};

/// The structure `--structure` defaults to.
pub const DEFAULT_STRUCTURE: &str = "index-half-edge";

/// The most faces a refined mesh may have: its corners (3 per face) and the index half-edge's
/// half-edge ids (about 3 per face, and the edge ids twice that) must stay below `u32::MAX`.
const MAX_FACES_U32: u64 = (u32::MAX as u64 - 1) / 6;

/// The box of `--region xmin,ymin,zmin,xmax,ymax,zmax`.
fn parse_region(text: &str) -> Result<Region, Failure> {
    let numbers: Vec<f64> = text
        .split(',')
        .map(|n| n.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|e| {
            Failure::usage(format!(
                "--region {text}: {e}; expected six numbers xmin,ymin,zmin,xmax,ymax,zmax"
            ))
        })?;
    let [x0, y0, z0, x1, y1, z1] = numbers[..] else {
        return Err(Failure::usage(format!(
            "--region {text}: {} numbers; expected six, xmin,ymin,zmin,xmax,ymax,zmax",
            numbers.len()
        )));
    };
    Region::new(DVec3::new(x0, y0, z0), DVec3::new(x1, y1, z1))
        .map_err(|e| Failure::usage(format!("--region {text}: {e}")))
}

/// Why the structure `name` refuses to refine, when it is a structure of the registry that is
/// not editable.
fn not_editable(name: &str) -> Option<String> {
    if !registry::NAMES.contains(&name) {
        return None;
    }
    let why = match name {
        "regular-grid" | "height-field" => {
            topolab_structures::families::regular_grid::NO_LOCAL_REFINEMENT
        }
        _ => "it has no editing operations (it implements no MeshEdit)",
    };
    Some(format!("{name} cannot refine adaptively: {why}"))
}

/// Runs `topolab refine --max-edge`: `max_edge` the longest edge left, `region` the box as
/// given on the command line, `structure` the editable structure that refines.
pub fn adaptive(
    spec: &str,
    max_edge: f64,
    region: Option<&str>,
    structure: &str,
    out: &Path,
) -> Result<String, Failure> {
    let region = region.map(parse_region).transpose()?;
    let request = Request::new(max_edge, region)
        .map_err(|e| Failure::usage(format!("--max-edge {max_edge}: {e}")))?;
    // Longest-edge bisection splits edges: a structure that implements `MeshEdit` without
    // offering the split (explicit storage moves vertices only) cannot run it.
    let splitting = || -> Vec<&str> {
        registry::NAMES
            .iter()
            .copied()
            .filter(|n| registry::offers(n, EditOp::SplitEdge) == Some(true))
            .collect()
    };
    match registry::offers(structure, EditOp::SplitEdge) {
        Some(true) => {}
        Some(false) => {
            return Err(Failure {
                message: format!(
                    "{structure} cannot refine adaptively: it does not offer split-edge (not offered: a missing feature, not a refusal of an element); the structures that offer it are {}",
                    splitting().join(", ")
                ),
                code: 1,
            })
        }
        None => {
            if let Some(why) = not_editable(structure) {
                return Err(Failure {
                    message: why,
                    code: 1,
                });
            }
            return Err(Failure::usage(format!(
                "--structure {structure}: no such structure; the editable ones are {}",
                splitting().join(", ")
            )));
        }
    }
    check_mesh_out(out, spec)?;
    registry::visit_editable(structure, Adaptive { spec, request, out })
        .expect("checked above: an editable structure")
}

/// The refinement on one structure.
struct Adaptive<'a> {
    spec: &'a str,
    request: Request,
    out: &'a Path,
}

/// The bytes per face of `M` and of its soup: one build of [`limits::sample_mesh`] and its soup,
/// measured, per face, times 3 for the growth of the arrays a refinement appends to (a vector
/// that doubles holds up to twice its elements, and three times during the copy).
fn bytes_per_face<M: MeshEdit>() -> u64 {
    let sample = limits::sample_mesh();
    let (_, peak) = limits::peak_of(|| {
        if let Ok(m) = M::from_soup(&sample) {
            drop(to_soup(&m));
        }
    });
    3 * (peak + sample.heap_bytes() as u64).div_ceil(sample.num_faces() as u64)
}

/// The bar of a refinement from `faces` faces towards `predicted`, on stderr (drawn on a
/// terminal only, as `topolab report`'s).
fn progress_bar(faces: usize, predicted: u128) -> ProgressBar {
    let bar = ProgressBar::new(u64::try_from(predicted).unwrap_or(u64::MAX));
    if let Ok(style) = ProgressStyle::with_template(
        "{elapsed_precise} [{bar:30}] {human_pos}/{human_len} faces (predicted), eta {eta}",
    ) {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_position(faces as u64);
    bar
}

impl EditVisitor for Adaptive<'_> {
    type Output = Result<String, Failure>;

    fn visit<M: MeshEdit + 'static>(self) -> Self::Output {
        let Adaptive { spec, request, out } = self;
        let refused = |e: Error| Failure {
            message: format!("cannot refine {spec} on {}: {e}", M::NAME),
            code: 1,
        };
        let soup: PolygonSoup = load_mesh(spec, |s| {
            drop(M::from_soup(s));
            0
        })?;
        refuse_empty(spec, &soup)?;
        if let Some((face, corners)) = soup.first_non_triangle() {
            return Err(Failure {
                message: format!(
                    "cannot refine {spec}: longest-edge bisection splits triangles, but face {face} has {corners} corners"
                ),
                code: 1,
            });
        }
        let mut m = M::from_soup(&soup).map_err(refused)?;
        drop(soup);
        let what = format!("--max-edge {} of {spec}", request.max_edge());
        let fewest = fewest_faces(&m, &request).map_err(refused)?;
        limits::within_u32(
            &what,
            &[
                ("faces", fewest),
                ("corners", fewest.saturating_mul(3)),
                ("half-edges (twice)", fewest.saturating_mul(6)),
            ],
        )?;
        let per_face = bytes_per_face::<M>();
        let predicted = predicted_faces(&m, &request).map_err(refused)?;
        let bytes = u64::try_from(predicted.saturating_mul(per_face.into())).unwrap_or(u64::MAX);
        let estimate = format!(
            "about {predicted} faces predicted (at least {fewest}), about {} of memory at {} per face",
            limits::human(bytes),
            limits::human(per_face)
        );
        eprintln!("topolab refine: {what} on {}: {estimate}", M::NAME);
        limits::admit(
            &format!("{what} (about {predicted} faces predicted)"),
            bytes,
        )?;
        let by_memory = limits::affordable(per_face);
        let budget = by_memory.map_or(MAX_FACES_U32, |n| n.min(MAX_FACES_U32));
        let started = Instant::now();
        let bar = progress_bar(m.num_faces(), predicted);
        let progress = |faces: usize| {
            let faces = faces as u64;
            if faces > bar.length().unwrap_or(0) {
                bar.set_length(faces);
            }
            bar.set_position(faces);
        };
        let report = refine_adaptive_with_progress(&mut m, &request, budget as usize, progress);
        bar.finish_and_clear();
        let report = report.map_err(|e| match e {
            Error::BudgetExceeded { limit, .. } => Failure::usage(format!(
                "{what} would make more than {limit} faces, {}; nothing written",
                if by_memory.is_some_and(|n| n < MAX_FACES_U32) {
                    format!(
                        "more than the available memory holds at about {} per face; --allow-memory runs it anyway",
                        limits::human(per_face)
                    )
                } else {
                    "more than u32 ids number (3 corners and 6 half-edge ids per face); no option allows it".to_string()
                }
            )),
            e => refused(e),
        })?;
        let seconds = started.elapsed().as_secs_f64();
        let fine = to_soup(&m);
        drop(m);
        write_mesh(out, &fine)?;
        let inside = match request.region() {
            Some(r) => {
                let (a, b) = (r.min(), r.max());
                format!(
                    " with both ends in ({}, {}, {}) .. ({}, {}, {})",
                    a.x, a.y, a.z, b.x, b.y, b.z
                )
            }
            None => String::new(),
        };
        Ok(format!(
            "{spec}: adaptive refinement (longest-edge bisection) on {} of the edges longer than {}{inside}: {} edges split in {} round{}, {} faces before, {} after, {} vertices, written to {} (refinement {:.3} s)\n",
            M::NAME,
            request.max_edge(),
            report.edges_split,
            report.rounds,
            plural(report.rounds),
            report.faces_before,
            report.faces_after,
            fine.num_vertices(),
            out.display(),
            seconds
        ))
    }
}
