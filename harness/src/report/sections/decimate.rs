//! "Decimation by quadric error, and reconstruction" (see [`crate::studies::decimate`]): on the closed
//! tori of the run up to [`MAX_FACES`], each mesh decimated to 10% of its faces by the lab's
//! decimater on the index and the pointer half-edge (the two structures whose eager collapses
//! are compared with OpenMesh's Decimater; the decimation suite enrols every editable one),
//! where asked for, with each [`Strategy`] (eager: OpenMesh's
//! Decimater step for step; lazy: the lab's), the reconstruction by vertex splits timed and
//! checked, and by OpenMesh's and CGAL's decimaters natively, every result's error measured
//! the same way.
//!
//! On the run's largest torus (torus-1M in a full report: the Targets table's mesh) the
//! index half-edge's eager decimation and OpenMesh's Decimater (one algorithm on two
//! structures) take turns, three rounds from fresh builds, so the Targets row's ratio is the
//! median of per-round ratios with its spread; above [`MAX_FACES`] only that pair runs there.
//!
//! Ties: the eager rows and the pair break them by storage, as OpenMesh does
//! ([`Ties::Storage`], which the half-edges share with OpenMesh), the lazy rows by ids as
//! `topolab decimate` does (the function `ties`).
//!
//! Cost: OpenMesh's Decimater and the library functions it calls (its legality test,
//! `collapse`) are OpenMesh's own, compiled from its source at `-O3 -DNDEBUG` by `build.rs`.
//! The eager strategy runs as many legality tests as OpenMesh's Decimater (one for every
//! outgoing half-edge of every vertex it heaps again); the lazy one tests a candidate when it
//! leaves the heap. CGAL stays below [`MAX_FACES`] (its `edge_collapse` builds an
//! `Edge_profile`, with vectors allocated each time, for every cost it computes, and gathers
//! each collapse's edges in a `std::set`: about a third of its instructions in callgrind are
//! `malloc`, `free` and the tree, none of it a setting of ours).

use crate::measuring::phases::Phase;
use crate::measuring::timing::median;
use crate::measuring::timing::meter::MemoryMeter;
use crate::measuring::timing::turns::{take_turns, Answer, Run, Stopwatch};
use crate::report::run::{Case, ReportError, Run as SectionRun};
use crate::report::section::{Needs, Page, Section};
use crate::studies::decimate::{distance, result_checksum, DecimateRow};
use glam::DVec3;
use std::fmt::Write;
use topolab_baselines::native_decimate::NativeDecimater;
use topolab_structures::algorithms::changing::to_soup;
use topolab_structures::algorithms::decimate::{
    decimate_with_ties, reconstruct, same_mesh, Strategy, Ties,
};
use topolab_structures::core::topology::first_three_corners;
use topolab_structures::{
    FaceId, IndexHalfEdge, MeshEdit, MeshTopology, PointerHalfEdge, PolygonSoup,
};

/// Tori larger than this (faces) are not decimated in a full report.
pub const MAX_FACES: usize = 65_536;
/// With `--quick`.
const MAX_FACES_QUICK: usize = 16_384;

/// The lab's structures the report decimates (every editable one decimates; these two are
/// the ones whose eager collapses are compared with OpenMesh's Decimater).
const EDITABLE: [&str; 2] = ["index-half-edge", "pointer-half-edge"];

/// The decimaters of the Targets row, which take turns on the run's largest torus: the index
/// half-edge with the eager strategy (OpenMesh's algorithm, [`PAIR_STRATEGY`]) and OpenMesh.
const PAIR: [&str; 2] = ["index-half-edge", topolab_registry::OPENMESH];

/// The strategy of the Targets row's lab decimater: the one that runs OpenMesh's algorithm.
const PAIR_STRATEGY: Strategy = Strategy::Eager;

/// The tie rule of the report's lab decimations ([`Ties`]): the eager strategy keeps
/// OpenMesh's order ([`Ties::Storage`]), so that on the half-edges, which store what OpenMesh
/// stores, it makes OpenMesh's collapses on the symmetric tori too and the pair gives one mesh;
/// the lazy one, the lab's own, breaks ties by ids as `topolab decimate` does.
const fn ties(strategy: Strategy) -> Ties {
    match strategy {
        Strategy::Eager => Ties::Storage,
        Strategy::Lazy => Ties::Ids,
    }
}

/// Timed rounds of the pair's turns (at least 2: one run gives the result, the last one the
/// reconstruction).
const TURNS: usize = 3;

/// Times the lab's decimation with `strategy` on `M`: `runs` (at least 2) fresh builds, each
/// decimated (timed); the first run's result compacted and measured, the last one's
/// reconstructed (timed) and compared with the original.
fn ours<M: MeshEdit>(
    soup: &PolygonSoup,
    target: usize,
    runs: usize,
    strategy: Strategy,
    meter: &dyn MemoryMeter,
) -> topolab_structures::Result<(f64, PolygonSoup, f64, bool)> {
    let mut times = Vec::with_capacity(runs);
    let mut result = None;
    let (mut rebuilt_seconds, mut exact) = (0.0, false);
    for run in 0..runs.max(2) {
        let mut m = M::from_soup(soup)?;
        let watch = Stopwatch::start(meter);
        let d = decimate_with_ties(&mut m, target, strategy, ties(strategy))?;
        times.push(watch.ns() * 1e-9);
        if run == 0 {
            m.garbage_collection();
            result = Some(to_soup(&m));
        } else {
            let watch = Stopwatch::start(meter);
            let r = reconstruct(&mut m, &d.collapses)?;
            rebuilt_seconds = watch.ns() * 1e-9;
            exact = same_mesh(soup, &m, &r).is_ok();
        }
    }
    times.sort_by(f64::total_cmp);
    Ok((
        median(&times),
        result.unwrap_or_default(),
        rebuilt_seconds,
        exact,
    ))
}

/// Decimates every torus of `cases` (name, family, soup) up to the size cap with each
/// decimater among `names`.
fn measure(
    cases: &[Case],
    names: &[String],
    quick: bool,
    meter: &dyn MemoryMeter,
    notes: &mut Vec<String>,
) -> Result<Vec<DecimateRow>, ReportError> {
    let cap = if quick { MAX_FACES_QUICK } else { MAX_FACES };
    let asked = |s: &str| names.iter().any(|n| n == s);
    let natives: Vec<NativeDecimater> = NativeDecimater::ALL
        .into_iter()
        .filter(|d| asked(d.name()))
        .collect();
    for d in &natives {
        if !d.available() {
            notes.push(format!(
                "The decimation section has no {}: its decimater is not in this build (CGAL's needs Eigen: libeigen3-dev).",
                d.name()
            ));
        }
    }
    let mut rows = Vec::new();
    let mut skipped = Vec::new();
    let largest = cases
        .iter()
        .filter(|c| c.1 == "torus")
        .map(|c| c.2.num_faces())
        .max();
    let pair_ran = PAIR.iter().all(|s| asked(s))
        && natives.iter().any(|d| d.name() == PAIR[1] && d.available());
    for (mesh, family, soup) in cases {
        if family != "torus" {
            continue;
        }
        let faces = soup.num_faces();
        let in_turns = pair_ran && Some(faces) == largest;
        if faces > cap && !in_turns {
            skipped.push(mesh.clone());
            continue;
        }
        let target = faces / 10;
        let failed = |s: &str, e: topolab_structures::Error| {
            ReportError::Measurement(format!("decimating {mesh} failed on {s}: {e}"))
        };
        if in_turns {
            rows.extend(pair_in_turns(mesh, soup, target, meter)?);
            if faces > cap {
                notes.push(format!(
                    "The decimation section ran {mesh} (above {cap} faces) for the Targets row only: {} and {} in turns; the other decimaters stop at {cap} faces.",
                    PAIR[0], PAIR[1]
                ));
                continue;
            }
        }
        let others = |s: &str, strategy: Option<Strategy>| {
            let paired = s == PAIR[1] || (s == PAIR[0] && strategy == Some(PAIR_STRATEGY));
            !(in_turns && paired)
        };
        let editable = EDITABLE.into_iter().filter(|s| asked(s));
        let lab = editable.flat_map(|s| Strategy::ALL.map(|strategy| (s, strategy)));
        for (s, strategy) in lab.filter(|&(s, strategy)| others(s, Some(strategy))) {
            eprintln!("topolab report: decimate {mesh}: {s} ({strategy})");
            let runs = if faces <= 16_384 { 3 } else { 2 };
            let (seconds, result, rebuilt, exact) = match s {
                "pointer-half-edge" => ours::<PointerHalfEdge>(soup, target, runs, strategy, meter),
                _ => ours::<IndexHalfEdge>(soup, target, runs, strategy, meter),
            }
            .map_err(|e| failed(s, e))?;
            if !exact {
                return Err(not_undone(mesh, s));
            }
            rows.push(DecimateRow {
                mesh: mesh.clone(),
                faces,
                target,
                structure: s.to_string(),
                strategy: Some(strategy),
                seconds,
                runs: runs.max(2),
                turns: Vec::new(),
                faces_after: result.num_faces(),
                error: distance(soup, &result),
                reconstruction: Some((rebuilt, exact)),
            });
        }
        for d in natives
            .iter()
            .filter(|d| d.available() && others(d.name(), None))
        {
            eprintln!("topolab report: decimate {mesh}: {}", d.name());
            let got = d.decimate(soup, target).map_err(|e| failed(d.name(), e))?;
            rows.push(DecimateRow {
                mesh: mesh.clone(),
                faces,
                target,
                structure: d.name().to_string(),
                strategy: None,
                seconds: got.seconds,
                runs: 1,
                turns: Vec::new(),
                faces_after: got.result.num_faces(),
                error: distance(soup, &got.result),
                reconstruction: None,
            });
        }
    }
    if let Some(note) = per_removed_face(&rows) {
        notes.push(note);
    }
    if !skipped.is_empty() && !rows.is_empty() {
        notes.push(format!(
            "The decimation section skipped {} (above {cap} faces: CGAL's edge_collapse takes 50–75 µs per removed face on the loaded 2-core machine).",
            skipped.join(", ")
        ));
    }
    Ok(rows)
}

/// The failure of a reconstruction that did not give `mesh` back on `structure`.
fn not_undone(mesh: &str, structure: &str) -> ReportError {
    ReportError::Measurement(format!("the reconstruction of {mesh} on {structure} did not give the original back\nThe report stops: a decimation that cannot be undone is a bug."))
}

/// The Targets row's pair on `soup`: the index half-edge with [`PAIR_STRATEGY`] and OpenMesh's
/// Decimater, each from a fresh build, in turns for [`TURNS`] rounds (the build not timed).
/// Both must give the same mesh in every round ([`result_checksum`], outside the clock); the
/// first round's results are measured, and the index half-edge's last run is reconstructed
/// and compared with the original.
fn pair_in_turns(
    mesh: &str,
    soup: &PolygonSoup,
    target: usize,
    meter: &dyn MemoryMeter,
) -> Result<Vec<DecimateRow>, ReportError> {
    eprintln!(
        "topolab report: decimate {mesh}: {} ({PAIR_STRATEGY}) and {} taking turns",
        PAIR[0], PAIR[1]
    );
    let mut results: [Option<PolygonSoup>; 2] = [None, None];
    let mut runs = [0usize; 2];
    let mut rebuilt = None;
    let seconds = take_turns(0, TURNS, &PAIR, |i| {
        runs[i] += 1;
        let (seconds, checksum) = if i == 0 {
            let mut m =
                <IndexHalfEdge as MeshTopology>::from_soup(soup).map_err(|e| e.to_string())?;
            let watch = Stopwatch::start(meter);
            let d = decimate_with_ties(&mut m, target, PAIR_STRATEGY, ties(PAIR_STRATEGY))
                .map_err(|e| e.to_string())?;
            let seconds = watch.ns() * 1e-9;
            let checksum = result_checksum(live_triangles(&m));
            if runs[i] == 1 {
                m.garbage_collection();
                results[i] = Some(to_soup(&m));
            } else if runs[i] == TURNS {
                let watch = Stopwatch::start(meter);
                let r = reconstruct(&mut m, &d.collapses).map_err(|e| e.to_string())?;
                let s = watch.ns() * 1e-9;
                rebuilt = Some((s, same_mesh(soup, &m, &r).is_ok()));
            }
            (seconds, checksum)
        } else {
            let got = NativeDecimater::OpenMesh
                .decimate(soup, target)
                .map_err(|e| e.to_string())?;
            let r = &got.result;
            let checksum = result_checksum(
                r.faces()
                    .map(|f| [f[0], f[1], f[2]].map(|v| r.positions[v as usize])),
            );
            if runs[i] == 1 {
                results[i] = Some(got.result);
            }
            (got.seconds, checksum)
        };
        Ok(Run {
            ns: seconds * 1e9,
            // One algorithm on two structures: the same result mesh, triangle for triangle.
            answer: Answer::Sum(checksum),
        })
    })
    .map_err(|e| {
        ReportError::Measurement(format!(
            "decimating {mesh} in turns: {e}\nThe report stops."
        ))
    })?;
    if rebuilt.is_some_and(|(_, exact)| !exact) {
        return Err(not_undone(mesh, PAIR[0]));
    }
    let faces = soup.num_faces();
    Ok(PAIR
        .iter()
        .zip(seconds)
        .zip(results)
        .enumerate()
        .map(|(i, ((name, ns), result))| {
            let turns: Vec<f64> = ns.iter().map(|ns| ns * 1e-9).collect();
            let mut sorted = turns.clone();
            sorted.sort_by(f64::total_cmp);
            let result = result.unwrap_or_default();
            DecimateRow {
                mesh: mesh.to_string(),
                faces,
                target,
                structure: name.to_string(),
                strategy: (i == 0).then_some(PAIR_STRATEGY),
                seconds: median(&sorted),
                runs: turns.len(),
                turns,
                faces_after: result.num_faces(),
                error: distance(soup, &result),
                reconstruction: if i == 0 { rebuilt } else { None },
            }
        })
        .collect())
}

/// The live triangles of `m` (not garbage-collected), by their corners' positions.
fn live_triangles<M: MeshEdit>(m: &M) -> impl Iterator<Item = [DVec3; 3]> + '_ {
    let live = (0..m.num_faces()).map(FaceId::new);
    live.filter(|&f| !m.is_deleted_face(f))
        .map(|f| first_three_corners(m, f).0.map(|v| m.position(v)))
}

/// The section's note on what its times mean: each decimater's thread CPU time per removed
/// face on the largest torus it ran, and why the baselines cost what they cost.
fn per_removed_face(rows: &[DecimateRow]) -> Option<String> {
    let mut names: Vec<String> = Vec::new();
    for r in rows {
        if !names.contains(&r.decimater()) {
            names.push(r.decimater());
        }
    }
    let times: Vec<String> = names
        .iter()
        .filter_map(|s| {
            let r = rows
                .iter()
                .filter(|r| &r.decimater() == s)
                .max_by_key(|r| r.faces)?;
            let removed = r.faces.saturating_sub(r.faces_after).max(1);
            Some(format!(
                "{s} {:.1} µs on {}",
                r.seconds * 1e6 / removed as f64,
                r.mesh
            ))
        })
        .collect();
    if times.is_empty() {
        return None;
    }
    Some(format!(
        "Decimation, the thread's CPU time per removed face on the largest torus each decimater ran: {}. OpenMesh's Decimater runs as OpenMesh ships it, compiled from its source in release (see Machine); its design tests the legality of every outgoing half-edge of every vertex it heaps again, which the lab's eager strategy does too, through each structure's own test (the lazy strategy tests a candidate when it leaves the heap). CGAL's edge_collapse builds an Edge_profile, with vectors allocated each time, for every cost and placement it computes, and gathers each collapse's edges in a std::set: about a third of its instructions are malloc, free and the tree, none of it a setting of the report's.",
        times.join(", ")
    ))
}

/// The report section.
fn render(h: &mut String, rows: &[DecimateRow]) {
    if rows.is_empty() {
        return;
    }
    h.push_str(concat!(
        "<h2>Decimation by quadric error, and reconstruction</h2><div class=read><b>How to read it.</b> Thinning for level of detail, as the lecture on polygon-mesh data structures asks, with reconstruction possible again. ",
        "Each mesh is decimated to 10% of its faces by Garland and Heckbert's quadric error. ",
        "The lab's decimater runs on the index and the pointer half-edge (of the editable structures, which its test suite all enrols, the two whose collapses are compared with OpenMesh's Decimater) with two strategies, both with OpenMesh's area-weighted plane quadrics, a heap of vertices keyed by their best half-edge collapse (the error rounded to <code>f32</code>), the removed vertex collapsed onto its neighbour (no optimal placement), the structure's collapse test (the link condition and OpenMesh's tetrahedron test), and boundary vertices kept. ",
        "<b>eager</b> rows run OpenMesh's <code>DecimaterT</code> with <code>ModQuadricT</code> step for step: every neighbour of a vertex tested for legality (<code>MeshEdit::check_collapse</code>, the structure's own test) before it is priced, only legal collapses heaped, one refused when it leaves the heap dropped, every neighbour of the removed vertex heaped again, no geometric test. ",
        "They and OpenMesh's Decimater run one algorithm, so their time ratio compares the structures: the Targets row is the index half-edge's eager decimation against OpenMesh. ",
        "That includes the ties, which the generated tori have all over (their <code>f32</code> errors take a handful of values): the eager rows break them as OpenMesh does, by storage (of equal errors the first in the rotation from the vertex's stored half-edge, equal keys leaving the heap in the order of OpenMesh's <code>HeapT</code>), which the two half-edges share with OpenMesh, so that they make its collapses exactly. Another structure starts its rotations elsewhere, so <code>topolab decimate</code> and the lazy rows break ties by vertex ids instead, and every editable structure then gives the same mesh (tested on all of them); without ties the two rules agree. ",
        "<b>lazy</b> rows run the lab's own variant: collapses priced without a legality test and tested when they leave the heap (a refused vertex heaped again with its next-best neighbour), and a collapse that would flip or flatten a face skipped (OpenMesh's <code>ModNormalFlippingT</code> at 90°, which OpenMesh's row does not run): another algorithm, with fewer legality tests, shown beside but not a structure comparison. ",
        "OpenMesh's own Decimater and CGAL's <code>edge_collapse</code> with the Garland–Heckbert plane policies on a <code>Surface_mesh</code> (edges keyed, the new vertex at the quadric's minimiser) run in C++. ",
        "Time: the decimation alone, median of fresh builds (the build not timed); on the run's largest torus the index half-edge (eager) and OpenMesh take turns, round by round, and must give the same mesh, triangle for triangle, in every round (the report stops otherwise); the Targets table gives the median of their per-round ratios. ",
        "The library functions OpenMesh's Decimater calls (its legality test <code>is_collapse_ok</code>, <code>find_halfedge</code>, <code>valence</code>, and <code>collapse</code>) are compiled with the report's shim, in release: Debian's library has its assertions compiled in, which cost 90% of the Decimater's instructions (callgrind, 16k torus: 2.71 G as shipped, 0.28 G so), with the same result mesh. ",
        "Error, computed by the lab on every result the same way: the distance from each vertex of the original to the decimated surface, its maximum (one-sided Hausdorff at the vertices) and mean, in % of the bounding-box diagonal. ",
        "Reconstruction: the recorded collapses replayed backwards by vertex splits, and the result compared with the original (positions bit for bit, the same oriented faces through the id mapping).</div>",
    ));
    h.push_str("<table><tr><th class=l>mesh</th><th>faces</th><th>target</th><th class=l>decimater</th><th>ms</th><th>× OpenMesh</th><th>faces after</th><th>max error %</th><th>mean error %</th><th>reconstruction ms</th><th>exact</th></tr>");
    for r in rows {
        let om = rows
            .iter()
            .find(|o| o.mesh == r.mesh && o.structure == "openmesh")
            .map(|o| format!("{:.2}", r.seconds / o.seconds))
            .unwrap_or_else(|| "–".into());
        let (rec, exact) = match r.reconstruction {
            Some((s, ok)) => (format!("{:.1}", s * 1e3), if ok { "yes" } else { "NO" }),
            None => ("–".into(), "–"),
        };
        let _ = write!(
            h,
            "<tr><td class=l>{}</td><td>{}</td><td>{}</td><td class=l>{}</td><td>{:.1}</td><td>{om}</td><td>{}</td><td>{:.4}</td><td>{:.4}</td><td>{rec}</td><td>{exact}</td></tr>",
            r.mesh,
            r.faces,
            r.target,
            r.decimater(),
            r.seconds * 1e3,
            r.faces_after,
            r.error.max * 100.0,
            r.error.mean * 100.0,
        );
    }
    h.push_str("</table>");
}

/// Decimation by quadric error against OpenMesh's and CGAL's decimaters, and the
/// reconstruction by vertex splits, on the generated tori.
pub struct Decimate;

impl Section for Decimate {
    fn name(&self) -> &'static str {
        "decimate"
    }

    fn needs(&self) -> Needs {
        Needs::GENERATED
    }

    fn phase(&self) -> Option<Phase> {
        Some(Phase::new("decimate", "decimation"))
    }

    fn measure(&self, run: &mut SectionRun) -> Result<(), ReportError> {
        let (req, r) = (run.request, &mut *run.results);
        r.decimate = measure(run.cases, &req.names, req.quick, run.meter, &mut r.notes)?;
        Ok(())
    }

    fn render(&self, h: &mut String, page: &Page) {
        render(h, &page.r.decimate);
    }
}
