//! The decimation section of `topolab report` (see `topolab_harness::decimate`): on the closed
//! tori of the run up to [`MAX_FACES`], each mesh decimated to 10% of its faces by the lab's
//! decimater on the editable structures asked for (with the reconstruction by vertex splits
//! timed and checked), and by OpenMesh's and CGAL's decimaters natively, every result's error
//! measured the same way.
//!
//! Cost: OpenMesh's Decimater is the slowest of the three (Debian's OpenMesh 9 spends its time
//! in `is_collapse_ok`, string compares and allocations, on every candidate of every
//! `heap_vertex`: 175 µs per face of the 64k torus on the 2-core machine under a load of
//! 13–17), so the sizes stop at 64k faces (16k with `--quick`) and the baselines run once per
//! mesh, the lab's structures twice (one run gives the result, the other the reconstruction).
//! `topolab report --sections decimate --meshes torus --sizes 16384,65536` took 75–120 s
//! under that load; the full report's tori (1k to 64k) add about as much.

use crate::input::Failure;
use crate::native_decimate::NativeDecimater;
use std::time::Instant;
use topolab_harness::decimate::{distance, DecimateRow};
use topolab_harness::timing::median;
use topolab_structures::algorithms::changing::to_soup;
use topolab_structures::algorithms::decimate::{decimate, reconstruct, same_mesh};
use topolab_structures::{IndexHalfEdge, MeshEdit, PointerHalfEdge, PolygonSoup};

/// Tori larger than this (faces) are not decimated in a full report.
pub const MAX_FACES: usize = 65_536;
/// With `--quick`.
const MAX_FACES_QUICK: usize = 16_384;

/// The lab's structures that decimate.
const EDITABLE: [&str; 2] = ["index-half-edge", "pointer-half-edge"];

/// Times the lab's decimation on `M`: `runs` (at least 2) fresh builds, each decimated (timed);
/// the first run's result compacted and measured, the last one's reconstructed (timed) and
/// compared with the original.
fn ours<M: MeshEdit>(
    soup: &PolygonSoup,
    target: usize,
    runs: usize,
) -> topolab_structures::Result<(f64, PolygonSoup, f64, bool)> {
    let mut times = Vec::with_capacity(runs);
    let mut result = None;
    let (mut rebuilt_seconds, mut exact) = (0.0, false);
    for run in 0..runs.max(2) {
        let mut m = M::from_soup(soup)?;
        let started = Instant::now();
        let d = decimate(&mut m, target)?;
        times.push(started.elapsed().as_secs_f64());
        if run == 0 {
            m.garbage_collection();
            result = Some(to_soup(&m));
        } else {
            let started = Instant::now();
            let r = reconstruct(&mut m, &d.collapses)?;
            rebuilt_seconds = started.elapsed().as_secs_f64();
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
pub fn measure(
    cases: &[(String, String, PolygonSoup)],
    names: &[String],
    quick: bool,
    notes: &mut Vec<String>,
) -> Result<Vec<DecimateRow>, Failure> {
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
    for (mesh, family, soup) in cases {
        if family != "torus" {
            continue;
        }
        if soup.num_faces() > cap {
            skipped.push(mesh.clone());
            continue;
        }
        let faces = soup.num_faces();
        let target = faces / 10;
        let failed = |s: &str, e: topolab_structures::Error| Failure {
            message: format!("decimating {mesh} failed on {s}: {e}"),
            code: 1,
        };
        for s in EDITABLE.into_iter().filter(|s| asked(s)) {
            eprintln!("topolab report: decimate {mesh}: {s}");
            let runs = if faces <= 16_384 { 3 } else { 2 };
            let (seconds, result, rebuilt, exact) = match s {
                "pointer-half-edge" => ours::<PointerHalfEdge>(soup, target, runs),
                _ => ours::<IndexHalfEdge>(soup, target, runs),
            }
            .map_err(|e| failed(s, e))?;
            if !exact {
                return Err(Failure {
                    message: format!("the reconstruction of {mesh} on {s} did not give the original back\nThe report stops: a decimation that cannot be undone is a bug."),
                    code: 1,
                });
            }
            rows.push(DecimateRow {
                mesh: mesh.clone(),
                faces,
                target,
                structure: s.to_string(),
                seconds,
                runs: runs.max(2),
                faces_after: result.num_faces(),
                error: distance(soup, &result),
                reconstruction: Some((rebuilt, exact)),
            });
        }
        for d in natives.iter().filter(|d| d.available()) {
            eprintln!("topolab report: decimate {mesh}: {}", d.name());
            let got = d.decimate(soup, target).map_err(|e| failed(d.name(), e))?;
            rows.push(DecimateRow {
                mesh: mesh.clone(),
                faces,
                target,
                structure: d.name().to_string(),
                seconds: got.seconds,
                runs: 1,
                faces_after: got.result.num_faces(),
                error: distance(soup, &got.result),
                reconstruction: None,
            });
        }
    }
    if !skipped.is_empty() && !rows.is_empty() {
        notes.push(format!(
            "The decimation section skipped {} (above {cap} faces: OpenMesh's Decimater takes about 0.2 ms per face on the loaded 2-core machine).",
            skipped.join(", ")
        ));
    }
    Ok(rows)
}
