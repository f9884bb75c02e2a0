//! The rounds of two structures taking turns on the cells a target times: each built once (or
//! built in every run, for construction), each run timed by a [`Stopwatch`].

use crate::measuring::kernels::{run, run_workload, Queries, Workload, WorkloadBuffers};
use crate::measuring::measure::Builder;
use crate::measuring::timing::meter::MemoryMeter;
use crate::measuring::timing::turns::{take_turns, Answer, Run, Stopwatch};
use crate::targets::plan::{Cell, Turns, CHECKS, HULL_POINTS};
use std::time::Instant;
use topolab_structures::{BoundaryCurves, InputChecks, MeshTopology, Operator, PolygonSoup};

/// A structure built once, with what its timed runs need.
pub struct Built<M> {
    m: M,
    q: Queries,
    curves: BoundaryCurves,
    buf: WorkloadBuffers,
}

impl<M: MeshTopology> Built<M> {
    /// Builds `M` from `soup`.
    pub fn new(soup: &PolygonSoup) -> Result<Self, String> {
        let m = M::from_soup(soup).map_err(|e| format!("cannot build {}: {e}", M::NAME))?;
        // Every vertex, the sweep's queries of R00 as `Queries::all` has them; no cell of a
        // target reads the others.
        let q = Queries::every_vertex(&m);
        Ok(Self {
            m,
            q,
            curves: BoundaryCurves::default(),
            buf: WorkloadBuffers::default(),
        })
    }

    /// One run of a sweep or of smoothing, natively for a baseline, as the size sweep runs it,
    /// timed by a [`Stopwatch`] on `meter`.
    pub fn run(&mut self, cell: Cell, meter: &dyn MemoryMeter) -> Result<Run, String> {
        let native = M::native();
        let watch = Stopwatch::start(meter);
        let (items, answer) = match cell {
            Cell::R00Sweep => {
                let op = Operator::R00;
                let sum = match native {
                    Some(k) => k
                        .sweep(&self.m, op)
                        .map_err(|e| format!("native kernel failed: {e}"))?,
                    None => run(&self.m, op, &self.q, &mut self.curves),
                };
                (self.q.count(op), Answer::Sum(sum))
            }
            Cell::Smoothing => {
                let w = Workload::Smoothing;
                let value = match native {
                    Some(k) => k
                        .workload(&mut self.m, w)
                        .map_err(|e| format!("native kernel failed: {e}"))?,
                    None => run_workload(&self.m, w, &mut self.buf),
                };
                (
                    w.items(self.m.num_vertices(), self.m.num_faces()),
                    Answer::Value(value),
                )
            }
            Cell::Construction | Cell::Changing(_) | Cell::Hull => {
                return Err(format!("{cell:?} is not run on a built structure"))
            }
        };
        let ns = watch.ns();
        Ok(Run {
            ns: std::hint::black_box(ns) / items.max(1) as f64,
            answer,
        })
    }
}

/// One build of `M`, as the size sweep times construction ([`Builder`]: the baseline's own
/// construction when it has one), timed by a [`Stopwatch`] on `meter`; the structure is
/// finished and dropped after the clock.
pub fn build<M: MeshTopology>(
    builder: &Builder<M>,
    meter: &dyn MemoryMeter,
) -> Result<Run, String> {
    let watch = Stopwatch::start(meter);
    let built = std::hint::black_box(builder.build());
    let ns = watch.ns();
    let m = built
        .and_then(|b| builder.finish(b))
        .map_err(|e| format!("cannot build {}: {e}", M::NAME))?;
    let answer = Answer::Counts([m.num_vertices(), m.num_edges(), m.num_faces()]);
    let faces = m.num_faces();
    drop(m);
    Ok(Run {
        ns: ns / faces.max(1) as f64,
        answer,
    })
}

/// A structure's own checks of `soup` alone ([`MeshTopology::input_checks`]), timed by a
/// [`Stopwatch`] on `meter` ([`CHECKS`]); they answer the soup's counts, as a build does.
fn checks(
    input_checks: InputChecks,
    soup: &PolygonSoup,
    meter: &dyn MemoryMeter,
) -> Result<Run, String> {
    let watch = Stopwatch::start(meter);
    let checked = std::hint::black_box(input_checks(soup));
    let ns = watch.ns();
    let edges = checked
        .map_err(|e| format!("the checks refused the soup: {e}"))?
        .num_edges();
    Ok(Run {
        ns: ns / soup.num_faces().max(1) as f64,
        answer: Answer::Counts([soup.num_vertices(), edges, soup.num_faces()]),
    })
}

/// Times `A` and `B` on `mesh` taking turns on each of `cells` (sweeps, smoothing,
/// construction; not the changing workloads, which need editing): both are built once first,
/// when a cell needs them built.
pub fn pair<A: MeshTopology, B: MeshTopology>(
    mesh: &str,
    soup: &PolygonSoup,
    cells: &[Cell],
    meter: &dyn MemoryMeter,
) -> Result<Vec<Turns>, String> {
    let names = [A::NAME, B::NAME];
    let mut built = None;
    let mut out = Vec::new();
    for &cell in cells {
        let start = Instant::now();
        let (contenders, ns) = if cell == Cell::Construction {
            // The lab's checks and the facts a baseline is told, once, before any clock.
            let cannot =
                |name: &str, e: topolab_structures::Error| format!("cannot build {name}: {e}");
            let a = Builder::<A>::new(soup).map_err(|e| cannot(A::NAME, e))?;
            let b = Builder::<B>::new(soup).map_err(|e| cannot(B::NAME, e))?;
            // The lab's structure against an outside one: the checks its build includes and
            // the other's does not take a third turn, when they are a step of their own.
            let own_checks = match (A::input_checks(), B::separate_construction()) {
                (Some(checks), Some(_)) => Some(checks),
                _ => None,
            };
            let mut contenders = names.to_vec();
            contenders.extend(own_checks.map(|_| CHECKS));
            let ns = take_turns(cell.warm_up(), cell.rounds(), &contenders, |i| {
                match (i, own_checks) {
                    (0, _) => build(&a, meter),
                    (1, _) => build(&b, meter),
                    (_, Some(own)) => checks(own, soup, meter),
                    (_, None) => Err("no third contender".into()),
                }
            })?;
            (contenders, ns)
        } else {
            if built.is_none() {
                built = Some((Built::<A>::new(soup)?, Built::<B>::new(soup)?));
            }
            let (a, b) = built.as_mut().expect("built above");
            let ns = take_turns(cell.warm_up(), cell.rounds(), &names, |i| match i {
                0 => a.run(cell, meter),
                _ => b.run(cell, meter),
            })?;
            (names.to_vec(), ns)
        };
        out.push(turns(cell, mesh, soup, &contenders, ns, start));
    }
    Ok(out)
}

/// The [`Turns`] of `cell`'s runs `ns`, timed since `start`.
pub fn turns(
    cell: Cell,
    mesh: &str,
    soup: &PolygonSoup,
    names: &[&str],
    ns: Vec<Vec<f64>>,
    start: Instant,
) -> Turns {
    let items = match cell {
        Cell::R00Sweep | Cell::Smoothing => soup.num_vertices(),
        Cell::Construction | Cell::Changing(_) => soup.num_faces(),
        Cell::Hull => HULL_POINTS,
    };
    Turns {
        cell,
        mesh: mesh.into(),
        items,
        structures: names.iter().map(|s| s.to_string()).collect(),
        ns_per_item: ns,
        warm_up: cell.warm_up(),
        seconds: start.elapsed().as_secs_f64(),
    }
}
