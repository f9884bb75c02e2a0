//! The Targets table's measurement in `topolab report` (see `topolab_harness::targets`): on
//! the largest torus of the run, the structures of each target built once and run in turns,
//! the changing workloads from fresh builds in turns (OpenMesh natively, as the changing
//! section runs it), every run in the measuring thread's CPU time.

use crate::input::Failure;
#[cfg(has_openmesh)]
use crate::openmesh::OpenMesh;
use std::marker::PhantomData;
use std::time::Instant;
use topolab_baselines::Lab;
use topolab_harness::changing::{mesh_checksum, MeshChecksum};
use topolab_harness::probe::Probe;
use topolab_harness::results::Measurement;
use topolab_harness::targets::{self, take_turns, Answer, Cell, ProbeTurns, Run, Stopwatch, Turns};
use topolab_structures::algorithms::changing::Changing;
use topolab_structures::registry::{StructureVisitor, Structures};
use topolab_structures::{IndexHalfEdge, MeshEdit, MeshTopology, PointerHalfEdge, PolygonSoup};

/// What every group's visit needs.
struct Case<'a> {
    mesh: &'a str,
    soup: &'a PolygonSoup,
    cells: &'a [Cell],
    /// What the probe measures in turns with a structure held to its limit.
    probe: Option<ProbeTurns>,
}

/// Visits a group's first structure, then its second (or times the first with the probe).
struct First<'a, X> {
    second: Option<&'a str>,
    case: &'a Case<'a>,
    list: PhantomData<fn() -> X>,
}

impl<X: Structures> StructureVisitor for First<'_, X> {
    type Output = Result<Vec<Turns>, String>;
    fn visit<A: MeshTopology>(self) -> Self::Output {
        let c = self.case;
        let b = match self.second {
            Some(targets::PROBE) | None => {
                let meter = &crate::ALLOCATOR;
                let probe = c.probe.ok_or("no limit to take turns with")?;
                return targets::with_probe::<A>(c.mesh, c.soup, c.cells, probe, meter);
            }
            Some(b) => b,
        };
        let second = Second::<A> {
            case: c,
            first: PhantomData,
        };
        <(Lab, X)>::visit(b, second).map_err(|_| format!("no structure is called {b}"))?
    }
}

/// Times a group's two structures in turns.
struct Second<'a, A> {
    case: &'a Case<'a>,
    first: PhantomData<fn() -> A>,
}

impl<A: MeshTopology> StructureVisitor for Second<'_, A> {
    type Output = Result<Vec<Turns>, String>;
    fn visit<B: MeshTopology>(self) -> Self::Output {
        let c = self.case;
        targets::pair::<A, B>(c.mesh, c.soup, c.cells, &crate::ALLOCATOR)
    }
}

/// One run of workload `w` on `structure` from a fresh build (not timed), as the changing
/// section runs it (OpenMesh natively), timed by a [`Stopwatch`]: ns per face of the input and
/// the resulting mesh.
fn changing_run(structure: &str, soup: &PolygonSoup, w: Changing) -> Result<Run, String> {
    let mesh = match structure {
        "index-half-edge" => edit::<IndexHalfEdge>(soup, w),
        "pointer-half-edge" => edit::<PointerHalfEdge>(soup, w),
        #[cfg(has_openmesh)]
        "openmesh" => {
            let mut m = <OpenMesh as MeshTopology>::from_soup(soup).map_err(|e| e.to_string())?;
            m.prepare_changing().map_err(|e| e.to_string())?;
            timed(m, |m| m.native_changing(w))
        }
        other => return Err(format!("{other} does not run the changing workloads")),
    }?;
    Ok(Run {
        ns: mesh.0 / soup.num_faces().max(1) as f64,
        answer: Answer::Mesh(mesh.1),
    })
}

/// Builds `M` (not timed) and runs `w` on it.
fn edit<M: MeshEdit>(soup: &PolygonSoup, w: Changing) -> Result<(f64, MeshChecksum), String> {
    let m = M::from_soup(soup).map_err(|e| e.to_string())?;
    timed(m, |m| w.run(m))
}

/// Runs `work` on `m`, timed; then the resulting mesh's checksum.
fn timed<M: MeshTopology>(
    mut m: M,
    work: impl FnOnce(&mut M) -> topolab_structures::Result<()>,
) -> Result<(f64, MeshChecksum), String> {
    let watch = Stopwatch::start(&crate::ALLOCATOR);
    work(&mut m).map_err(|e| e.to_string())?;
    let ns = watch.ns();
    Ok((ns, mesh_checksum(&m)))
}

/// Measures every target whose structures are among `names` on the largest torus of `cases`
/// (name, family, soup), on the cells the size sweep measured there (`measurements`, their
/// limits annotated from `probe`): nothing without a torus. A failed run or a checksum that differs
/// between runs fails the report.
pub fn measure<X: Structures>(
    cases: &[(String, String, PolygonSoup)],
    names: &[String],
    measurements: &[Measurement],
    probe: &Probe,
    notes: &mut Vec<String>,
) -> Result<Vec<Turns>, Failure> {
    let Some((mesh, _, soup)) = cases
        .iter()
        .filter(|c| c.1 == "torus")
        .max_by_key(|c| c.2.num_faces())
    else {
        return Ok(Vec::new());
    };
    let (start, cpu) = (Instant::now(), crate::alloc::thread_cpu_ns());
    let mut out = Vec::new();
    // What the size sweep measured (a sweep it skipped as too long would be as long here); the
    // changing workloads on the structures that run them.
    let can = |s: &str, cell: Cell| {
        names.iter().any(|n| n == s)
            && match cell {
                Cell::Changing(_) => crate::registry::is_editable(s),
                _ if s == targets::PROBE => true,
                _ => targets::sequential(measurements, mesh, s, cell).is_some(),
            }
    };
    for group in targets::plan(can) {
        let who = group.structures.join(" and ");
        eprintln!("topolab report: targets on {mesh}: {who} taking turns");
        let fail = |e: String| Failure {
            message: format!("targets on {mesh}, {who}: {e}\nThe report stops."),
            code: 1,
        };
        let (changing, built): (Vec<Cell>, Vec<Cell>) = group
            .cells
            .iter()
            .partition(|c| matches!(c, Cell::Changing(_)));
        // What the probe measures in turns beside the group's sweep, from its limit.
        let held_to_limit = group.structures.get(1) == Some(&targets::PROBE);
        let probe_turns = held_to_limit
            .then(|| {
                let m = targets::sequential(measurements, mesh, group.structures[0], built[0])?;
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
            };
            let first = First::<X> {
                second: group.structures.get(1).copied(),
                case: &case,
                list: PhantomData,
            };
            let a = group.structures[0];
            let turns = <(Lab, X)>::visit(a, first)
                .map_err(|_| fail(format!("no structure is called {a}")))?
                .map_err(fail)?;
            out.extend(turns);
        }
        for cell in changing {
            let Cell::Changing(w) = cell else { continue };
            let t = Instant::now();
            let s = &group.structures;
            let ns = take_turns(cell.warm_up(), cell.rounds(), s, |i| {
                changing_run(s[i], soup, w)
            })
            .map_err(fail)?;
            out.push(targets::turns(cell, mesh, soup, s, ns, t));
        }
    }
    let cpu = crate::alloc::thread_cpu_ns()
        .zip(cpu)
        .map(|(b, a)| format!(" ({:.1} s of CPU)", b.saturating_sub(a) as f64 * 1e-9))
        .unwrap_or_default();
    notes.push(format!(
        "The Targets table's rounds took {:.1} s on {mesh}{cpu}.",
        start.elapsed().as_secs_f64()
    ));
    Ok(out)
}
