//! Local refinement in the changing section: adaptive refinement by longest-edge bisection
//! ([`topolab_structures::algorithms::adaptive`], what `topolab refine --max-edge` runs) timed
//! on every editable structure on the run's tori, and beside it what a structure that cannot
//! refine locally would need.
//!
//! The lecture on polygon-mesh data structures asks that refinement be possible "lokal und
//! adaptiv" and says that the structures with implicit topology allow no adaptive refinement.
//! Each torus is refined in one quarter of its bounding box (x and y at least the box
//! centre's) until no edge there is longer than half the mean length of the faces' sides.
//! The refinement does not depend on the structure (its order and its new vertices are fixed
//! by the geometry), so every structure must give the same mesh: an untimed run on the index
//! half-edge gives the reference, and a structure that differs stops the report.
//!
//! The regular grid and the height field cannot take part ([`NO_LOCAL_REFINEMENT`]); their row
//! gives the refusal and what refining everywhere costs instead: the levels of uniform midpoint
//! refinement that bring the torus's longest edge to the same length, and the faces they make.
//!
//! The C++ baselines are not timed here: their shims have no native adaptive refinement, and
//! one FFI call per split would time the calls, not the structure (the lab times whole loops
//! inside C++). The Rust crates run where they offer the edge split (tri-mesh).

use super::{lacks, too_long};
use crate::measuring::timing::meter::MemoryMeter;
use crate::page::skips::Skip;
use crate::report::run::{Case, ReportError};
use crate::studies::changing::{
    declared_operations, in_rounds, mesh_checksum, runner, LocalRefinement, LocalRefinementCase,
    LocalRefinementRow, Runner,
};
use std::fmt::Write;
use topolab_registry::{self as registry, EditVisitor};
use topolab_structures::algorithms::adaptive::{refine_adaptive, Region, Request};
use topolab_structures::families::regular_grid::NO_LOCAL_REFINEMENT;
use topolab_structures::glam::DVec3;
use topolab_structures::summary::plural;
use topolab_structures::{EditOp, IndexHalfEdge, MeshEdit, MeshTopology, Operator, PolygonSoup};

/// What the skip notes call this work.
const WHAT: &str = "local refinement";

/// Tori larger than this (faces) are left out of the default report, for its time budget: on
/// the 1M torus the refinement splits about a million edges per run, and the four structures
/// that ran it there took about 55 s with their builds and the reference (alone they would
/// take less; it was timed beside three compilations). `--full` runs up to [`FULL_MAX_FACES`].
const MAX_FACES: usize = 300_000;

/// Tori larger than this (faces) are left out with `--full` too.
const FULL_MAX_FACES: usize = 1_100_000;

/// The request the section makes of `soup` (see the module docs) and the longest side of its
/// faces; `None` for a mesh without faces or coordinates (no torus of the run).
fn request_of(soup: &PolygonSoup) -> Option<(Request, f64)> {
    let (mut min, mut max) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    for &p in &soup.positions {
        min = min.min(p);
        max = max.max(p);
    }
    let (mut sum, mut sides, mut longest) = (0.0, 0usize, 0.0f64);
    for f in 0..soup.num_faces() {
        let face = soup.face(f);
        for (i, &a) in face.iter().enumerate() {
            let b = face[(i + 1) % face.len()];
            let length = soup.positions[a as usize].distance(soup.positions[b as usize]);
            sum += length;
            sides += 1;
            longest = longest.max(length);
        }
    }
    if sides == 0 {
        return None;
    }
    let centre = 0.5 * (min + max);
    let region = Region::new(DVec3::new(centre.x, centre.y, min.z), max).ok()?;
    let request = Request::new(0.5 * sum / sides as f64, Some(region)).ok()?;
    Some((request, longest))
}

/// The levels of uniform midpoint refinement (each halves every edge) that bring `longest`
/// to `max_edge` or below.
fn uniform_levels(longest: f64, max_edge: f64) -> u32 {
    let mut levels = 0;
    let mut length = longest;
    while length > max_edge && levels < 64 {
        length *= 0.5;
        levels += 1;
    }
    levels
}

/// The refinement timed on one editable structure, or why not.
struct Timed<'a> {
    soup: &'a PolygonSoup,
    request: &'a Request,
    /// Edge splits per face of the input, from the reference run (for the estimate).
    splits_per_face: f64,
    quick: bool,
}

/// One structure's runner and declared costs, or the skip's reason.
type Outcome<'a> = Result<(Runner<'a>, String), (String, Option<String>)>;

impl<'a> EditVisitor for Timed<'a> {
    type Output = Outcome<'a>;
    fn visit<M: MeshEdit>(self) -> Outcome<'a> {
        let operations = [(EditOp::SplitEdge, self.splits_per_face)];
        // Each split first finds its edge from the two vertices.
        let queries = [(Operator::R01, self.splits_per_face)];
        if let Some(why) = lacks::<M>(&operations)
            .or_else(|| too_long::<M>(&operations, &queries, self.soup.num_faces(), self.quick))
        {
            return Err(why);
        }
        let (soup, request) = (self.soup, self.request);
        Ok((
            runner(
                move || M::from_soup(soup),
                move |m| refine_adaptive(m, request, usize::MAX).map(|_| ()),
                mesh_checksum,
            ),
            declared_operations::<M>(&operations, &queries),
        ))
    }
}

/// Refines every torus of `cases` (up to [`MAX_FACES`]) on each editable structure of
/// `editing` but the C++ baselines, `runs(faces)` times each; a structure whose mesh differs
/// from the reference is an error. Skips go to `skips`.
pub(super) fn measure(
    cases: &[Case],
    editing: &[&str],
    (quick, full): (bool, bool),
    runs: impl Fn(usize) -> usize,
    meter: &dyn MemoryMeter,
    skips: &mut Vec<Skip>,
    notes: &mut Vec<String>,
) -> Result<LocalRefinement, ReportError> {
    let (mut done, mut rows) = (Vec::new(), Vec::new());
    let max_faces = if full { FULL_MAX_FACES } else { MAX_FACES };
    for (mesh, family, soup) in cases {
        if family != "torus" || editing.is_empty() {
            continue;
        }
        if soup.num_faces() > max_faces {
            notes.push(format!(
                "{WHAT} skipped {mesh}: above {max_faces} faces{}",
                if full {
                    ""
                } else {
                    ", to keep the default report within its time budget (`--full` runs it)"
                }
            ));
            continue;
        }
        let Some((request, longest)) = request_of(soup) else {
            continue;
        };
        // The reference: the index half-edge, untimed.
        let mut reference = IndexHalfEdge::from_soup(soup)
            .map_err(|e| ReportError::Measurement(format!("{WHAT} on {mesh}: {e}")))?;
        let report = refine_adaptive(&mut reference, &request, usize::MAX)
            .map_err(|e| ReportError::Measurement(format!("{WHAT} on {mesh}: {e}")))?;
        let expected = mesh_checksum(&reference);
        drop(reference);
        let levels = uniform_levels(longest, request.max_edge());
        let region = request.region().expect("the request has a region");
        done.push(LocalRefinementCase {
            mesh: mesh.clone(),
            faces: soup.num_faces(),
            max_edge: request.max_edge(),
            region: [region.min().to_array(), region.max().to_array()],
            splits: report.edges_split,
            faces_after: report.faces_after,
            uniform_levels: levels,
            uniform_faces: (soup.num_faces() as u64).saturating_mul(4u64.saturating_pow(levels)),
        });
        let runs = runs(soup.num_faces());
        let mut runners: Vec<(&str, Runner)> = Vec::new();
        let mut declared_by = Vec::new();
        for &s in editing {
            if registry::NATIVE_CHANGING.contains(&s) {
                skips.push(Skip {
                    what: WHAT.into(),
                    structure: s.into(),
                    mesh: mesh.clone(),
                    reason: "its C++ shim has no native adaptive refinement, and one FFI call per split would time the calls".into(),
                    detail: None,
                });
                continue;
            }
            let timed = Timed {
                soup,
                request: &request,
                splits_per_face: report.edges_split as f64 / soup.num_faces().max(1) as f64,
                quick,
            };
            match registry::visit_editable(s, timed) {
                Some(Ok((run, declared))) => {
                    runners.push((s, run));
                    declared_by.push(declared);
                }
                Some(Err((reason, detail))) => skips.push(Skip {
                    what: WHAT.into(),
                    structure: s.into(),
                    mesh: mesh.clone(),
                    reason,
                    detail,
                }),
                None => {}
            }
        }
        eprintln!(
            "topolab report: {WHAT} on {mesh}: {} structures, {runs} round{}",
            runners.len(),
            plural(runs)
        );
        let rounds = in_rounds(&mut runners, runs, 2026, meter)
            .map_err(|e| ReportError::Measurement(format!("{WHAT} on {mesh} failed on {e}")))?;
        let per_split = 1e9 / report.edges_split.max(1) as f64;
        for (((s, _), r), declared) in runners.iter().zip(&rounds).zip(declared_by) {
            if r.result != expected {
                return Err(ReportError::Measurement(format!(
                    "{WHAT} on {mesh}: {s} made {:?}, the index half-edge {expected:?}\nThe report stops: two structures refined a mesh differently.",
                    r.result
                )));
            }
            let seconds = r.median();
            rows.push(LocalRefinementRow {
                mesh: mesh.clone(),
                structure: s.to_string(),
                seconds,
                runs: r.seconds.len(),
                ns_per_split: seconds * per_split,
                ns_per_split_ci: r
                    .interval()
                    .map(|i| [i.low * per_split, i.high * per_split]),
                result: r.result,
                declared,
            });
        }
    }
    Ok(LocalRefinement { cases: done, rows })
}

/// The local refinement table: a row per structure and torus, then per torus the row of the
/// structures that cannot refine locally.
pub(crate) fn render(h: &mut String, local: &LocalRefinement) {
    let (cases, rows) = (&local.cases, &local.rows);
    if cases.is_empty() {
        return;
    }
    h.push_str("<h3>Local refinement: adaptive, in one region</h3><div class=read><b>How to read it.</b> The lecture on polygon-mesh data structures asks that refinement be possible locally and adaptively, and says that the structures whose topology is implicit do not allow it. Each torus is refined by longest-edge bisection (what <code>topolab refine --max-edge L --region BOX</code> runs, through each structure's edge split) in the quarter of its bounding box with x and y at least the centre's, until no edge there is longer than half the mean side of its faces. Splitting an edge splits its two triangles, so the mesh stays conforming with no closure step. The result does not depend on the structure, and every structure's is compared with the index half-edge's; a disagreement stops the report. Time per edge split, median of rounds, each structure once a round on a fresh build (the build not timed) in a random order, in the measuring thread's CPU time (hover it for the interval of the median); it includes finding the edge from its two vertices (the structure's edges-around-a-vertex query) and the heap of edges to split. The regular grid's row: it cannot refine one region, and refining everywhere to the same edge length makes far more faces. The C++ baselines are left out (see the notes).</div>");
    h.push_str("<table><tr><th class=l>mesh</th><th>faces</th><th class=l>structure</th><th>ms</th><th>ns per split</th><th>× index-half-edge</th><th>splits</th><th>result V / E / F</th><th class=l>declared costs</th></tr>");
    for c in cases {
        let base = rows
            .iter()
            .find(|r| r.mesh == c.mesh && r.structure == IndexHalfEdge::NAME)
            .map(|r| r.seconds);
        for r in rows.iter().filter(|r| r.mesh == c.mesh) {
            let ratio = base.map_or_else(|| "–".into(), |b| format!("{:.2}", r.seconds / b));
            let _ = write!(
                h,
                "<tr><td class=l>{}</td><td>{}</td><td class=l>{}</td><td>{:.1}</td><td title=\"{}\">{:.0}</td><td>{ratio}</td><td>{}</td><td>{} / {} / {}</td><td class=l>{}</td></tr>",
                c.mesh,
                c.faces,
                r.structure,
                r.seconds * 1e3,
                r.ns_per_split_ci
                    .map(|[lo, hi]| format!(
                        "interval {lo:.0} to {hi:.0} ns per split, median of {} round{}",
                        r.runs,
                        plural(r.runs)
                    ))
                    .unwrap_or_default(),
                r.ns_per_split,
                c.splits,
                r.result.vertices,
                r.result.edges,
                r.result.faces,
                r.declared
            );
        }
        let _ = write!(
            h,
            "<tr><td class=l>{}</td><td>{}</td><td class=l>regular-grid, height-field</td><td colspan=6 class=l>cannot: {NO_LOCAL_REFINEMENT}. Refined everywhere instead, {} level{} of uniform midpoint refinement bring the longest edge to {:.3e}: {} faces, against {} here ({:.1}×).</td></tr>",
            c.mesh,
            c.faces,
            c.uniform_levels,
            plural(c.uniform_levels),
            c.max_edge,
            c.uniform_faces,
            c.faces_after,
            c.uniform_faces as f64 / c.faces_after.max(1) as f64
        );
    }
    h.push_str("</table>");
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::meshes;

    #[test]
    fn every_structure_refines_the_torus_alike_and_the_grid_row_says_why_not() {
        let soup = meshes::torus(24, 8);
        let cases = vec![("torus-384".to_string(), "torus".to_string(), soup.clone())];
        let editing = ["index-half-edge", "winged-edge", "che-l1", "vertex-list"];
        let mut skips = Vec::new();
        let mut notes = Vec::new();
        let local = measure(
            &cases,
            &editing,
            (true, false),
            |_| 2,
            &crate::measuring::timing::meter::Uncounted,
            &mut skips,
            &mut notes,
        )
        .expect("the same meshes");
        assert!(notes.is_empty(), "{notes:?}");
        let (done, rows) = (&local.cases, &local.rows);
        assert_eq!(done.len(), 1);
        let c = &done[0];
        // Only the region's edges are split, so the faces grow, but fewer than everywhere.
        assert!(c.splits > 0 && c.faces_after > c.faces, "{c:?}");
        assert!(c.uniform_levels >= 1);
        assert!(c.uniform_faces > c.faces_after as u64, "{c:?}");
        assert_eq!(rows.len(), editing.len(), "{skips:?}");
        for r in rows {
            assert_eq!(r.result.faces, c.faces_after, "{}", r.structure);
        }
        let mut html = String::new();
        render(&mut html, &local);
        assert_eq!(html.matches("<tr>").count(), 1 + rows.len() + 1);
        assert!(html.contains("cannot: a regular grid cannot refine locally"));
    }

    #[test]
    fn the_region_is_a_quarter_and_the_length_half_the_mean_side() {
        // A unit square of two triangles: sides 1, 1, 1, 1 and the diagonal twice.
        let soup = PolygonSoup::from_polygons(
            vec![
                DVec3::ZERO,
                DVec3::new(1.0, 0.0, 0.0),
                DVec3::new(1.0, 1.0, 0.0),
                DVec3::new(0.0, 1.0, 0.0),
            ],
            &[[0, 1, 2], [0, 2, 3]],
        );
        let (request, longest) = request_of(&soup).expect("faces");
        let mean = (4.0 + 2.0 * 2f64.sqrt()) / 6.0;
        assert!((request.max_edge() - 0.5 * mean).abs() < 1e-12);
        assert_eq!(longest, 2f64.sqrt());
        let region = request.region().expect("a region");
        assert_eq!(region.min(), DVec3::new(0.5, 0.5, 0.0));
        assert_eq!(region.max(), DVec3::new(1.0, 1.0, 0.0));
        // √2 halved twice is 0.354 ≤ 0.569 < 0.707.
        assert_eq!(uniform_levels(longest, request.max_edge()), 2);
        assert!(request_of(&PolygonSoup::new()).is_none());
    }
}
