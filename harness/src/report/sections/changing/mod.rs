//! "Changing meshes": the changing workloads (√3 subdivision and the collapse test of the
//! Surface_mesh benchmark; see [`crate::studies::changing`]): every editable structure among
//! those asked for (the registry's capability, [`registry::visit_editable`]), and OpenMesh and
//! CGAL's two structures natively ([`registry::NATIVE_CHANGING`]: the whole workload in C++),
//! on the closed tori of the run; and local refinement (the `local_refinement` module: adaptive
//! refinement in one region of each torus, with the regular grid's refusal beside it).
//!
//! A structure whose edits scan the mesh (the vertex list's and the edge list's O(n) and
//! O(k·n), declared by `MeshEdit::edit_cost`) would run each workload in quadratic time: it is
//! skipped, with a note giving the estimate, where that estimate exceeds [`MAX_SECONDS`]; so is
//! √3 on a structure whose edge ids do not survive the splits (`MeshEdit::STABLE_EDGE_IDS`),
//! and a workload on a structure that lacks one of its operations (`MeshEdit::supports`: the
//! Rust crates' adapters offer only their crate's).
//! A structure whose workload edits cost O(n) each runs only on tori of at most
//! [`LINEAR_EDIT_MAX_FACES`] faces: the estimate assumes 1 ns per element read, and the CHE
//! levels' O(n) edits (an `EH` rebuild, a relabelling) cost far more per element.

mod local_refinement;

use crate::measuring::phases::Phase;
use crate::measuring::timing::meter::MemoryMeter;
use crate::page::skips::{self, Skip};
use crate::report::run::{Case, ReportError, Run};
use crate::report::section::{Needs, Page, Section};
use crate::studies::changing::{
    cross_check, declared, declared_operations, in_rounds, mesh_checksum, runner, ChangingRow,
    LocalRefinement, Runner,
};
use std::fmt::Write;
#[cfg(has_openmesh)]
use topolab_baselines::openmesh::OpenMesh;
use topolab_registry::{self as registry, EditVisitor};
use topolab_structures::algorithms::changing::Changing;
use topolab_structures::summary::plural;
#[cfg(any(has_openmesh, has_cgal))]
use topolab_structures::MeshTopology;
use topolab_structures::{Cost, EditOp, MeshEdit, Operator, PolygonSoup};

// OpenMesh is built through MeshTopology::from_soup.
#[cfg(has_openmesh)]
const _: fn(&PolygonSoup) -> topolab_structures::Result<OpenMesh> =
    <OpenMesh as MeshTopology>::from_soup;

/// A structure's workload is skipped where its declared costs predict more than this
/// (a tenth of it in a quick run).
pub const MAX_SECONDS: f64 = 20.0;

/// The time the estimate assumes per element a scan reads (a streaming read of a few bytes,
/// optimistic, so that nothing is skipped that would have fitted).
const SECONDS_PER_ELEMENT: f64 = 1e-9;

/// The elements one operation of cost `c` reads on a mesh of `n` elements (valence k ≈ 6).
fn elements(c: Cost, n: f64) -> f64 {
    match c {
        Cost::Constant | Cost::Log | Cost::Local | Cost::Boundary => 6.0,
        Cost::LocalSquared => 36.0,
        Cost::Linear => n,
        Cost::LocalTimesLinear => 6.0 * n,
        Cost::Quadratic => n * n,
    }
}

/// Tori larger than this (faces) are left out for a structure whose workload edits are
/// declared O(n) or costlier: the CHE levels' edits rebuild `EH` or relabel curves (see their
/// editing module), and on the 4k torus a run already takes seconds, some 2000x the index
/// half-edge's.
pub const LINEAR_EDIT_MAX_FACES: usize = 1_500;

/// Why `M` does not run `w` on a mesh of `faces` faces, if it does not: the reason (the same
/// words on every mesh, so that the notes group them) and what differs by mesh.
fn skip<M: MeshEdit>(w: Changing, faces: usize, quick: bool) -> Option<(String, Option<String>)> {
    if let Some(why) = lacks::<M>(w.operations()) {
        return Some(why);
    }
    if w == Changing::Sqrt3 && !M::STABLE_EDGE_IDS {
        return Some((
            "its edge ids change when faces are split, and √3 flips the old edges by id".into(),
            None,
        ));
    }
    too_long::<M>(w.operations(), &[], faces, quick)
}

/// Why `M` cannot run a workload doing `operations`: it lacks one of them (a Rust crate's
/// adapter offers only its crate's operations), so every run would be refused.
pub(crate) fn lacks<M: MeshEdit>(operations: &[(EditOp, f64)]) -> Option<(String, Option<String>)> {
    operations
        .iter()
        .find(|&&(op, _)| !M::supports(op))
        .map(|&(op, _)| {
            (
                format!("it does not offer {op}, which the workload needs"),
                None,
            )
        })
}

/// Why `M` should not run a workload doing `operations` (each with how many per face of the
/// input) on a mesh of `faces` faces: the costs it declares for them (and for `queries`, each
/// with how many per face, that the workload asks beside its edits) predict more than
/// [`MAX_SECONDS`] (a tenth in a quick run), or they are O(n) per step and the mesh is above
/// [`LINEAR_EDIT_MAX_FACES`].
pub(crate) fn too_long<M: MeshEdit>(
    operations: &[(EditOp, f64)],
    queries: &[(Operator, f64)],
    faces: usize,
    quick: bool,
) -> Option<(String, Option<String>)> {
    let max = if quick {
        MAX_SECONDS / 10.0
    } else {
        MAX_SECONDS
    };
    let costs: Vec<(Cost, f64)> = operations
        .iter()
        .map(|&(op, per_face)| (M::edit_cost(op), per_face))
        .chain(queries.iter().map(|&(q, per_face)| (M::cost(q), per_face)))
        .collect();
    let declared = declared_operations::<M>(operations, queries);
    // The mesh grows to about three times its faces (corners, edges): n ≈ 3 faces.
    let n = 3.0 * faces as f64;
    let seconds: f64 = costs
        .iter()
        .map(|&(c, per_face)| per_face * faces as f64 * elements(c, n) * SECONDS_PER_ELEMENT)
        .sum();
    if seconds > max {
        return Some((
            format!(
                "its declared costs ({declared}) predict above {max} s at ≥ 1 ns per element read"
            ),
            Some(format!("about {} s", format_seconds(seconds))),
        ));
    }
    let linear = costs
        .iter()
        .any(|&(c, per_face)| per_face > 0.0 && elements(c, n) >= n);
    (linear && faces > LINEAR_EDIT_MAX_FACES).then(|| {
        (
            format!("its declared costs ({declared}) are O(n) per step: run up to {LINEAR_EDIT_MAX_FACES} faces"),
            None,
        )
    })
}

fn format_seconds(s: f64) -> String {
    if s >= 1e4 {
        format!("{s:.1e}")
    } else {
        format!("{s:.0}")
    }
}

/// One workload timed on one editable structure, or why not.
struct Timed<'a> {
    soup: &'a PolygonSoup,
    workload: Changing,
    quick: bool,
}

enum Outcome<'a> {
    Ran(Runner<'a>, String),
    Skipped((String, Option<String>)),
}

impl<'a> EditVisitor for Timed<'a> {
    type Output = Outcome<'a>;
    fn visit<M: MeshEdit>(self) -> Outcome<'a> {
        let (soup, w) = (self.soup, self.workload);
        match skip::<M>(w, soup.num_faces(), self.quick) {
            Some(why) => Outcome::Skipped(why),
            None => Outcome::Ran(
                runner(move || M::from_soup(soup), move |m| w.run(m), mesh_checksum),
                declared::<M>(w),
            ),
        }
    }
}

/// Above this many faces a torus is not changed.
const MAX_FACES: usize = 4_000_000;

/// The runner of a C++ baseline's own loop of `w` (the whole workload in C++), for the
/// structures of [`registry::NATIVE_CHANGING`] this build has.
fn native<'a>(name: &str, soup: &'a PolygonSoup, w: Changing) -> Result<Runner<'a>, String> {
    match name {
        #[cfg(has_cgal)]
        registry::CGAL_SURFACE_MESH => Ok(runner(
            move || {
                <topolab_baselines::cgal::Cgal<topolab_baselines::cgal::SurfaceMeshClass> as MeshTopology>::from_soup(soup)
            },
            move |m| m.native_changing(w),
            mesh_checksum,
        )),
        #[cfg(has_cgal)]
        registry::CGAL_POLYHEDRON => Ok(runner(
            move || {
                <topolab_baselines::cgal::Cgal<topolab_baselines::cgal::PolyhedronClass> as MeshTopology>::from_soup(soup)
            },
            move |m| m.native_changing(w),
            mesh_checksum,
        )),
        #[cfg(has_openmesh)]
        registry::OPENMESH => Ok(runner(
            move || {
                let mut m = <OpenMesh as MeshTopology>::from_soup(soup)?;
                m.prepare_changing()?;
                Ok(m)
            },
            move |m| m.native_changing(w),
            mesh_checksum,
        )),
        _ => {
            // Without the C++ baselines no arm above is compiled, and these go unread.
            let _ = (soup, w);
            Err(format!(
                "{name} has no native changing workloads in this build"
            ))
        }
    }
}

/// Runs both workloads on every torus of `cases` (name, family, soup) for each structure of
/// `names` that can edit, each [`changing_runs`](crate::report::clock::changing_runs) times; a disagreement
/// between structures is an error.
fn measure(
    cases: &[Case],
    names: &[String],
    (quick, full): (bool, bool),
    meter: &dyn MemoryMeter,
    notes: &mut Vec<String>,
) -> Result<(Vec<ChangingRow>, LocalRefinement), ReportError> {
    let mut rows = Vec::new();
    let mut skips = Vec::new();
    let editing: Vec<&str> = names
        .iter()
        .map(String::as_str)
        .filter(|s| registry::is_editable(s))
        .collect();
    for (mesh, family, soup) in cases {
        if family != "torus" || editing.is_empty() {
            continue;
        }
        if soup.num_faces() > MAX_FACES {
            notes.push(format!(
                "the changing workloads skipped {mesh}: above {MAX_FACES} faces"
            ));
            continue;
        }
        let runs = crate::report::clock::changing_runs(soup.num_faces(), quick, full);
        for w in Changing::ALL {
            // Every structure's runner, then the rounds of all of them, interleaved.
            let mut runners: Vec<(&str, Runner)> = Vec::new();
            let mut declared_by = Vec::new();
            for &s in &editing {
                // The baselines run natively even where they implement MeshEdit: the
                // protocol's whole loop in C++, not one FFI call per edit.
                let (run, declared) = if registry::NATIVE_CHANGING.contains(&s) {
                    let run = native(s, soup, w).map_err(|e| {
                        ReportError::Measurement(format!("{} on {mesh}: {e}", w.name()))
                    })?;
                    (run, String::new())
                } else {
                    let timed = Timed {
                        soup,
                        workload: w,
                        quick,
                    };
                    match registry::visit_editable(s, timed) {
                        Some(Outcome::Ran(run, declared)) => (run, declared),
                        Some(Outcome::Skipped((reason, detail))) => {
                            skips.push(Skip {
                                what: w.name().to_string(),
                                structure: s.to_string(),
                                mesh: mesh.clone(),
                                reason,
                                detail,
                            });
                            continue;
                        }
                        None => return Err(ReportError::Measurement(format!("{s} does not edit"))),
                    }
                };
                runners.push((s, run));
                declared_by.push(declared);
            }
            eprintln!(
                "topolab report: {} on {mesh}: {} structures, {runs} round{}",
                w.name(),
                runners.len(),
                plural(runs)
            );
            let rounds = in_rounds(&mut runners, runs, 2026, meter).map_err(|e| {
                ReportError::Measurement(format!("{} on {mesh} failed on {e}", w.name()))
            })?;
            for (((s, _), r), declared) in runners.iter().zip(&rounds).zip(declared_by) {
                rows.push(ChangingRow::of(w, (mesh, soup.num_faces()), s, r, declared));
            }
        }
        cross_check(&rows).map_err(|e| {
            ReportError::Measurement(format!(
                "{e}\nThe report stops: two structures changed a mesh differently."
            ))
        })?;
    }
    let runs = |faces| crate::report::clock::changing_runs(faces, quick, full);
    let local = local_refinement::measure(
        cases,
        &editing,
        (quick, full),
        runs,
        meter,
        &mut skips,
        notes,
    )?;
    notes.extend(skips::group(&skips));
    Ok((rows, local))
}

/// The report section.
pub(crate) fn render(h: &mut String, rows: &[ChangingRow]) {
    if rows.is_empty() {
        return;
    }
    h.push_str("<h2>Changing meshes: √3 subdivision and the collapse test (Sieger &amp; Botsch, IMR 2011)</h2><div class=read><b>How to read it.</b> The two workloads of the published Surface_mesh benchmark that change the mesh, run as its protocol runs them: <i>sqrt3</i> is one step of √3 subdivision (new positions of the old interior vertices, every old face split at its centroid, every old edge flipped where a flip is allowed); <i>collapse-test</i> splits every face at a new vertex, collapses every new vertex back and garbage-collects the deleted elements. The lab's structures run them through their editing operations (<code>MeshEdit</code>: checked flips and collapses, the link condition included); OpenMesh runs the protocol's loop in C++ (its collapse unchecked, as the protocol calls it), and so do CGAL's Surface_mesh and Polyhedron_3, through CGAL's Euler operations as CGAL's own Surface_mesh benchmark does. Each time is the median of rounds, in each of which every structure ran once on a fresh build (the build not timed), in a random order, in the measuring thread's CPU time, per face of the input; hover it for the interval of the median. Every resulting mesh is compared (counts and a hash of the face list) across structures; a disagreement stops the report. <i>Declared costs</i>: what each structure declares for the operations the workload does (all of them: <code>topolab explain NAME</code>); a structure whose declared costs predict more than 20 s (2 s in a quick run) (the vertex list's and the edge list's scans on large meshes) is skipped, with the estimate in the notes.</div>");
    h.push_str("<table><tr><th class=l>workload</th><th class=l>mesh</th><th>faces</th><th class=l>structure</th><th>ms</th><th>ns per face</th><th>× OpenMesh</th><th>result V / E / F</th><th class=l>declared costs</th></tr>");
    for r in rows {
        let om = rows
            .iter()
            .find(|o| o.workload == r.workload && o.mesh == r.mesh && o.structure == "openmesh")
            .map(|o| format!("{:.2}", r.seconds / o.seconds))
            .unwrap_or_else(|| "–".into());
        let _ = write!(
            h,
            "<tr><td class=l>{}</td><td class=l>{}</td><td>{}</td><td class=l>{}</td><td>{:.1}</td><td title=\"{}\">{:.1}</td><td>{om}</td><td>{} / {} / {}</td><td class=l>{}</td></tr>",
            r.workload.name(),
            r.mesh,
            r.faces,
            r.structure,
            r.seconds * 1e3,
            r.ns_per_face_ci
                .map(|[lo, hi]| format!(
                    "interval {lo:.1} to {hi:.1} ns per face, median of {} round{}",
                    r.runs,
                    plural(r.runs)
                ))
                .unwrap_or_default(),
            r.ns_per_face,
            r.result.vertices,
            r.result.edges,
            r.result.faces,
            if r.declared.is_empty() { "native" } else { &r.declared }
        );
    }
    h.push_str("</table>");
}

/// The changing workloads (√3 subdivision, the collapse test) on the editable structures and
/// OpenMesh, on the generated tori.
pub struct ChangingMeshes;

impl Section for ChangingMeshes {
    fn name(&self) -> &'static str {
        "changing"
    }

    fn needs(&self) -> Needs {
        Needs::GENERATED
    }

    fn phase(&self) -> Option<Phase> {
        Some(Phase::new("changing", "changing workloads"))
    }

    fn measure(&self, run: &mut Run) -> Result<(), ReportError> {
        let (req, r) = (run.request, &mut *run.results);
        (r.changing, r.local_refinement) = measure(
            run.cases,
            &req.names,
            (req.quick, req.full),
            run.meter,
            &mut r.notes,
        )?;
        // The Targets of the changing workloads read these rounds on the largest torus.
        if let Some((mesh, _, soup)) = run
            .cases
            .iter()
            .filter(|c| c.1 == "torus")
            .max_by_key(|c| c.2.num_faces())
        {
            r.targets.extend(crate::targets::swept::changing_turns(
                &r.changing,
                mesh,
                soup,
            ));
        }
        Ok(())
    }

    fn render(&self, h: &mut String, page: &Page) {
        render(h, &page.r.changing);
        local_refinement::render(h, &page.r.local_refinement);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::{EdgeList, IndexHalfEdge, VertexList, WingedEdge};

    #[test]
    fn scanning_structures_are_skipped_with_an_estimate_where_it_would_take_too_long() {
        for w in Changing::ALL {
            for faces in [1_000, 1_000_000] {
                assert_eq!(skip::<IndexHalfEdge>(w, faces, false), None);
                assert_eq!(skip::<WingedEdge>(w, faces, false), None);
            }
            assert_eq!(skip::<EdgeList>(w, 1_000, false), None, "{w:?}");
            let (why, estimate) = skip::<EdgeList>(w, 1_000_000, false).expect("quadratic at 1M");
            assert!(
                why.contains("predict above") && why.contains("O(n)"),
                "{why}"
            );
            assert!(estimate.is_some_and(|e| e.starts_with("about ")));
        }
        assert_eq!(skip::<VertexList>(Changing::Collapse, 1_000, false), None);
        assert!(skip::<VertexList>(Changing::Collapse, 1_000_000, false).is_some());
        // The report test's quick 64k torus: skipped, not minutes of scans.
        assert!(skip::<VertexList>(Changing::Collapse, 64_000, true).is_some());
        let (why, _) =
            skip::<VertexList>(Changing::Sqrt3, 1_000, false).expect("no stable edge ids");
        assert!(why.contains("edge ids"), "{why}");
    }
}
