//! "Targets": the Targets table's measurement (see [`crate::targets`]): on
//! the largest torus of the run, the structures of each target built once and run in turns,
//! the changing workloads from fresh builds in turns (OpenMesh natively, as the changing
//! section runs it), every run in the measuring thread's CPU time.

use crate::format::{against_goal, class_of, esc};
use crate::measuring::phases::Phase;
use crate::measuring::probe::Probe;
use crate::measuring::timing::meter::MemoryMeter;
use crate::measuring::timing::turns::{take_turns, Answer, Run, Stopwatch};
use crate::report::cells::largest;
use crate::report::run::{Case as Mesh, ReportError, Roster, Run as SectionRun};
use crate::report::section::{Needs, Page, Section, SizeSweep};
use crate::results::{Measurement, Results, Status};
use crate::studies::changing::{mesh_checksum, MeshChecksum};
use crate::targets::group::Case;
use crate::targets::measured::{measured, ran, shown_turns};
use crate::targets::plan::{Against, Cell, Turns, CHANGING_ROUNDS, PROBE, ROUNDS, TARGETS};
use crate::targets::probe::ProbeTurns;
use crate::targets::rounds::turns;
use crate::targets::text::{
    chain_text, checks_text, missed_limit_text, one_after_another, sequential, sequential_subject,
    versus_text,
};
use std::fmt::Write;
use std::time::Instant;
#[cfg(has_openmesh)]
use topolab_baselines::openmesh::OpenMesh;
use topolab_structures::algorithms::changing::Changing;
use topolab_structures::{IndexHalfEdge, MeshEdit, MeshTopology, PointerHalfEdge, PolygonSoup};

/// One run of workload `w` on `structure` from a fresh build (not timed), as the changing
/// section runs it (OpenMesh natively), timed by a [`Stopwatch`]: ns per face of the input and
/// the resulting mesh.
fn changing_run(
    structure: &str,
    soup: &PolygonSoup,
    w: Changing,
    meter: &dyn MemoryMeter,
) -> Result<Run, String> {
    let mesh = match structure {
        "index-half-edge" => edit::<IndexHalfEdge>(soup, w, meter),
        "pointer-half-edge" => edit::<PointerHalfEdge>(soup, w, meter),
        #[cfg(has_openmesh)]
        "openmesh" => {
            let mut m = <OpenMesh as MeshTopology>::from_soup(soup).map_err(|e| e.to_string())?;
            m.prepare_changing().map_err(|e| e.to_string())?;
            timed(m, |m| m.native_changing(w), meter)
        }
        other => return Err(format!("{other} does not run the changing workloads")),
    }?;
    Ok(Run {
        ns: mesh.0 / soup.num_faces().max(1) as f64,
        answer: Answer::Mesh(mesh.1),
    })
}

/// Builds `M` (not timed) and runs `w` on it.
fn edit<M: MeshEdit>(
    soup: &PolygonSoup,
    w: Changing,
    meter: &dyn MemoryMeter,
) -> Result<(f64, MeshChecksum), String> {
    let m = M::from_soup(soup).map_err(|e| e.to_string())?;
    timed(m, |m| w.run(m), meter)
}

/// Runs `work` on `m`, timed; then the resulting mesh's checksum.
fn timed<M: MeshTopology>(
    mut m: M,
    work: impl FnOnce(&mut M) -> topolab_structures::Result<()>,
    meter: &dyn MemoryMeter,
) -> Result<(f64, MeshChecksum), String> {
    let watch = Stopwatch::start(meter);
    work(&mut m).map_err(|e| e.to_string())?;
    let ns = watch.ns();
    Ok((ns, mesh_checksum(&m)))
}

/// Measures every target whose structures are among `names` on the largest torus of `cases`
/// (name, family, soup), on the cells the size sweep measured there (`measurements`, their
/// limits annotated from `probe`): nothing without a torus. A failed run or a checksum that differs
/// between runs fails the report.
fn measure(
    cases: &[Mesh],
    (names, swept): (&[String], &[(Cell, Vec<String>)]),
    measurements: &[Measurement],
    probe: &Probe,
    structures: &dyn Roster,
    meter: &dyn MemoryMeter,
    notes: &mut Vec<String>,
) -> Result<Vec<Turns>, ReportError> {
    let Some((mesh, _, soup)) = cases
        .iter()
        .filter(|c| c.1 == "torus")
        .max_by_key(|c| c.2.num_faces())
    else {
        return Ok(Vec::new());
    };
    let (start, cpu) = (Instant::now(), meter.thread_cpu_ns());
    let mut out = Vec::new();
    // What the size sweep measured (a sweep it skipped as too long would be as long here); the
    // changing workloads on the structures that run them.
    let can = |s: &str, cell: Cell| {
        names.iter().any(|n| n == s)
            && match cell {
                Cell::Changing(_) => topolab_registry::is_editable(s),
                _ if s == PROBE => true,
                _ => sequential(measurements, mesh, s, cell).is_some(),
            }
    };
    for group in crate::targets::plan::plan(can) {
        let who = group.structures.join(" and ");
        eprintln!("topolab report: targets on {mesh}: {who} taking turns");
        let fail = |e: String| {
            ReportError::Measurement(format!("targets on {mesh}, {who}: {e}\nThe report stops."))
        };
        let (changing, built): (Vec<Cell>, Vec<Cell>) = group
            .cells
            .iter()
            .partition(|c| matches!(c, Cell::Changing(_)));
        // Two structures on a cell of the size sweep: read from its rounds on this mesh
        // already ([`crate::targets::swept`]), as the changing workloads are from the changing
        // section's rounds.
        let built: Vec<Cell> = built
            .into_iter()
            .filter(|&c| {
                !swept
                    .iter()
                    .any(|(cell, who)| *cell == c && *who == group.structures)
            })
            .collect();
        // What the probe measures in turns beside the group's sweep, from its limit.
        let held_to_limit = group.structures.get(1) == Some(&PROBE);
        let probe_turns = held_to_limit
            .then(|| {
                let m = sequential(measurements, mesh, group.structures[0], built[0])?;
                ProbeTurns::for_limit(m.limit.as_ref()?, probe)
            })
            .flatten();
        if held_to_limit && probe_turns.is_none() {
            notes.push(format!(
                "Targets: {} has no limit on {mesh}, so it is not held to one.",
                group.structures[0]
            ));
            continue;
        }
        if !built.is_empty() {
            let case = Case {
                mesh,
                soup,
                cells: &built,
                probe: probe_turns,
                meter,
            };
            let a = group.structures[0];
            let second = group.structures.get(1).copied();
            let turns = structures
                .targets(a, second, &case)
                .ok_or_else(|| fail(format!("no structure is called {a}")))?
                .map_err(fail)?;
            out.extend(turns);
        }
        // The changing section's rounds on this mesh, when it ran, are these turns already.
        let changing = changing.into_iter().filter(|&c| {
            !swept
                .iter()
                .any(|(cell, who)| *cell == c && *who == group.structures)
        });
        for cell in changing {
            let Cell::Changing(w) = cell else { continue };
            let t = Instant::now();
            let s = &group.structures;
            let ns = take_turns(cell.warm_up(), cell.rounds(), s, |i| {
                changing_run(s[i], soup, w, meter)
            })
            .map_err(fail)?;
            out.push(turns(cell, mesh, soup, s, ns, t));
        }
    }
    let cpu = meter
        .thread_cpu_ns()
        .zip(cpu)
        .map(|(b, a)| format!(" ({:.1} s of CPU)", b.saturating_sub(a) as f64 * 1e-9))
        .unwrap_or_default();
    notes.push(format!(
        "The Targets table's rounds took {:.1} s on {mesh}{cpu}.",
        start.elapsed().as_secs_f64()
    ));
    Ok(out)
}

/// The Targets section: every target measured in turns, on the largest torus of the run.
fn render(h: &mut String, r: &Results) {
    let Some((mesh, tri)) = largest(r, "torus") else {
        return;
    };
    let ran = |s: &str| ran(r, s);
    // Measured on the largest torus of the cases, which is this one (the hull's on its points).
    let turns = shown_turns(r, mesh);
    let swept_rounds = r
        .rounds
        .iter()
        .find(|x| x.mesh == mesh)
        .map_or(0, |x| x.rounds);
    let _ = write!(
        h,
        "<h2>Targets ({mesh}, {tri} triangles, this run)</h2><div class=read><b>How to read it.</b> Each target is a ratio of two times measured in turns: in every round both sides ran, each on a fresh build, one after the other in a random order, so that a change of load on the machine slows both sides of a round alike and no ratio is one draw of where a structure's arrays landed; every run is timed in the measuring thread's CPU time. A target between two structures on the 1-ring sweep, smoothing or construction reads the size sweep's own rounds on this mesh (all {swept_rounds} of them, the run's most: the same cells the chooser and the tables show); a target against a limit takes its own {ROUNDS} rounds after one warm-up round, the structure built afresh each round and swept once untimed before its timed sweep; the changing workloads take {CHANGING_ROUNDS} rounds, each run from a fresh build. Each round gives one ratio; <i>in turns</i> is their median, <i>interval</i> the order-statistics interval of that median (its coverage falls below 95% with fewer than six rounds), and the target is met when the median is at most the goal; where the interval reaches across the goal, the next run may say otherwise. Against a limit (see Sweeps and their limits), the sweep takes turns with the probe: its sequential read of the working set that sets the limit's bandwidth bound, its chase through the working set that sets the latency bound (plain loads, and steps doing the chain's own arithmetic), and its checksum arithmetic; each round's sweep is divided by the limit at the bandwidth, load latency and time per term of that round. <i>Cells' ratio</i> is the ratio of the two cells' medians as the tables show them. Every run's checksum agrees with the first, or the report stops.</div><table><tr><th class=l>target</th><th>in turns (median)</th><th>interval</th><th>rounds</th><th>cells' ratio</th><th>goal</th><th>met</th></tr>"
    );
    for t in TARGETS.iter().filter(|t| ran(t.structure)) {
        let against = match t.against {
            Against::Structure(b) if !ran(b) => continue,
            Against::Structure(b) => format!("{b}'s"),
            Against::Limit => "its limit".into(),
        };
        let cold = match (t.cell, t.against) {
            (Cell::Construction, Against::Structure(b)) => {
                let cold =
                    |s| sequential(&r.measurements, mesh, s, Cell::Construction)?.cold_ns_per_item;
                cold(t.structure)
                    .zip(cold(b))
                    .map(|(a, b)| format!("; cold builds, the cells' ratio: {:.2}×", a / b))
                    .unwrap_or_default()
            }
            _ => String::new(),
        };
        let limit =
            sequential(&r.measurements, mesh, t.structure, t.cell).and_then(|m| m.limit.as_ref());
        let spread = measured(&turns, t, limit);
        let (value, range, rounds, met) = match spread {
            Some(s) => (
                against_goal(s.median, t.goal),
                format!("{:.2}–{:.2}", s.low, s.high),
                s.rounds.to_string(),
                if s.median <= t.goal { "yes" } else { "no" },
            ),
            None => ("not measured".into(), "–".into(), "–".into(), "–"),
        };
        let class = class_of(met);
        let skipped = || {
            r.measurements.iter().any(|m| {
                m.mesh == mesh
                    && m.structure == t.structure
                    && m.status == Status::Skipped
                    && sequential_subject(t.cell) == Some((m.operator, m.kernel))
            })
        };
        let why = match (t.against, limit) {
            (Against::Limit, Some(l)) if met == "no" => {
                esc(&missed_limit_text(&turns, t, l, &r.probe))
            }
            (Against::Limit, Some(l)) => esc(&chain_text(&turns, t, l).unwrap_or_default()),
            (Against::Structure(b), _) if t.cell == Cell::Construction => {
                esc(&checks_text(&turns, t, b).unwrap_or_default())
            }
            (Against::Structure(b), _) if met == "no" => {
                esc(&versus_text(&r.measurements, mesh, t, b).unwrap_or_default())
            }
            _ if spread.is_none() && skipped() => {
                "not timed in turns: the size sweep skipped this cell as too long".into()
            }
            _ => String::new(),
        };
        let why = if why.is_empty() {
            why
        } else {
            format!("<br><span class=small>{why}</span>")
        };
        let seq = one_after_another(r, mesh, t)
            .map(|x| format!("{x:.2}×"))
            .unwrap_or_else(|| "–".into());
        let _ = write!(
            h,
            "<tr><td class=l>{} {} / {against}{cold}{why}</td><td>{value}</td><td>{range}</td><td>{rounds}</td><td>{seq}</td><td>≤ {}×</td><td class={class}>{met}</td></tr>",
            t.structure,
            t.cell.text(),
            t.goal
        );
    }
    // Decimation is timed in its own section, the index half-edge and OpenMesh taking turns on
    // the run's largest torus there: its row shows the median of their per-round ratios.
    for row in crate::studies::decimate::targets(&r.decimate) {
        let (value, met) = match row.value {
            Some(v) => (
                against_goal(v, row.goal),
                if v <= row.goal { "yes" } else { "no" },
            ),
            None => ("not measured".into(), "–"),
        };
        let (range, rounds) = match row.spread {
            Some(s) => (format!("{:.2}–{:.2}", s.low, s.high), s.rounds.to_string()),
            None => ("–".into(), "–".into()),
        };
        let class = class_of(met);
        let _ = write!(
            h,
            "<tr><td class=l>{}<br><span class=small>timed in turns in the Decimation section</span></td><td>{value}</td><td>{range}</td><td>{rounds}</td><td>–</td><td>≤ {}×</td><td class={class}>{met}</td></tr>",
            esc(&row.what),
            row.goal
        );
    }
    let seconds: f64 = turns.iter().map(|t| t.seconds).sum();
    let _ = write!(
        h,
        "</table><p class=small>The rounds of this table took {seconds:.1} s. Warm builds reuse the memory the build before them freed (see Construction time for cold builds and page faults). Limits: see Sweeps and their limits. Bytes per triangle, measured: see Memory per triangle.</p>"
    );
}

/// The project's performance targets on the largest torus, last: the project's own
/// bookkeeping, after what a reader came for.
pub struct Targets;

impl Section for Targets {
    fn name(&self) -> &'static str {
        "targets"
    }

    fn needs(&self) -> Needs {
        Needs::size_sweep(SizeSweep::Full)
    }

    fn phase(&self) -> Option<Phase> {
        Some(Phase::new("targets", "Targets turns"))
    }

    fn measure(&self, run: &mut SectionRun) -> Result<(), ReportError> {
        let r = &mut *run.results;
        // After the hull section's own turns, if it ran, the size sweep's of the targets
        // between two structures on its cells and the changing section's.
        let swept: Vec<(Cell, Vec<String>)> = r
            .targets
            .iter()
            .map(|t| (t.cell, t.structures.iter().take(2).cloned().collect()))
            .collect();
        let turns = measure(
            run.cases,
            (&run.request.names, &swept),
            &r.measurements,
            &r.probe,
            run.structures,
            run.meter,
            &mut r.notes,
        )?;
        r.targets.extend(turns);
        Ok(())
    }

    fn render(&self, h: &mut String, page: &Page) {
        render(h, page.r);
    }
}
