//! "Element order": the vertex 1-ring sweep of a mesh renumbered in each order.

use crate::measuring::kernels::Kernel;
use crate::measuring::measure::{cross_check, Estimator, MeshCase};
use crate::measuring::phases::Phase;
use crate::measuring::rounds::{round_sets, run_rounds, Contender, SetUp, Setup};
use crate::report::run::{ReportError, Run};
use crate::report::section::{Needs, Page, Refined, Section};
use crate::report::sections::real_at_scale::FAMILY;
use crate::report::sure::ns_with_interval;
use crate::results::{Measurement, Results, Status, Subject};
use std::fmt::Write;
use topolab_structures::{Operator, PolygonSoup};

fn orderings(h: &mut String, r: &Results, names: &[&str]) {
    let all: Vec<&Measurement> = r
        .measurements
        .iter()
        .filter(|m| m.family == "ordering")
        .collect();
    // One table per renumbered mesh (the torus, a refined real mesh), in the run's order.
    let mut bases: Vec<&str> = all
        .iter()
        .map(|m| m.mesh.split('/').next().unwrap_or_default())
        .collect();
    bases.dedup();
    for base in bases {
        let ms: Vec<&Measurement> = all
            .iter()
            .copied()
            .filter(|m| m.mesh.split('/').next() == Some(base))
            .collect();
        ordering_table(h, base, &ms, names);
    }
}

fn ordering_table(h: &mut String, base: &str, ms: &[&Measurement], names: &[&str]) {
    let mut meshes: Vec<&str> = ms.iter().map(|m| m.mesh.as_str()).collect();
    meshes.dedup();
    let cols: Vec<&str> = names
        .iter()
        .copied()
        .filter(|n| ms.iter().any(|m| m.structure == *n))
        .collect();
    let _ = write!(h, "<h2>Element order ({base})</h2><div class=read><b>How to read it.</b> The same mesh with its vertices renumbered (faces follow their smallest vertex): as generated (or as refined: each new vertex appended after the old ones, as real tools do), at random, along a Morton or Hilbert curve, breadth-first. The cell is the vertex 1-ring sweep (R00 over every vertex), nanoseconds per vertex. Order decides how often a query leaves the cache: a random order makes every structure pay the memory latency the probe measured.</div><table><tr><th class=l>order</th>");
    for c in &cols {
        let _ = write!(h, "<th>{c}</th>");
    }
    h.push_str("</tr>");
    for mesh in meshes {
        let _ = write!(
            h,
            "<tr><th class=l>{}</th>",
            mesh.split('/').nth(1).unwrap_or(mesh)
        );
        for c in &cols {
            match ms.iter().find(|m| m.mesh == mesh && m.structure == *c) {
                Some(m) if m.status == Status::Measured => {
                    let _ = write!(h, "<td>{}</td>", ns_with_interval(m));
                }
                _ => h.push_str("<td class=skip>–</td>"),
            }
        }
        h.push_str("</tr>");
    }
    h.push_str("</table>");
}

/// The structures whose vertex 1-ring is compared across element orderings.
const ORDERING_STRUCTURES: [&str; 7] = [
    "index-half-edge",
    "che-l2",
    "pointer-half-edge",
    "winged-edge",
    "openmesh",
    "cgal-surface-mesh",
    "cgal-polyhedron",
];

/// The effect of element order: the largest torus (at most 256k triangles) and the smallest
/// refined real mesh, each renumbered by each ordering, and the R00 sweep of a few structures
/// on each (and of every structure from outside the lab: whoever adds a structure wants to see
/// how it takes reordering).
fn measure(run: &mut Run) -> Result<(), ReportError> {
    let (cases, plan) = (run.cases, run.plan);
    let torus = cases
        .iter()
        .filter(|c| c.1 == "torus" && c.2.num_faces() <= 300_000)
        .max_by_key(|c| c.2.num_faces());
    let refined = cases
        .iter()
        .filter(|c| c.1 == FAMILY)
        .min_by_key(|c| c.2.num_faces());
    let added = &run.request.added;
    let structures: Vec<&String> = run
        .request
        .names
        .iter()
        .filter(|n| ORDERING_STRUCTURES.contains(&n.as_str()) || added.contains(n))
        .collect();
    let plan = crate::report::clock::plan_for(plan, true, "ordering", false);
    for (base, _, soup) in torus.into_iter().chain(refined) {
        // Every order of the mesh beside every other, in the same rounds: each structure on
        // each order built afresh and swept once a round, in a random order.
        let orders: Vec<(String, PolygonSoup)> = topolab_structures::ordering::Ordering::ALL
            .into_iter()
            .map(|o| {
                let re = topolab_structures::ordering::reorder(soup, o).soup;
                (format!("{base}/{}", o.name()), re)
            })
            .collect();
        let cases: Vec<MeshCase> = orders
            .iter()
            .map(|(name, re)| MeshCase {
                name,
                family: "ordering",
                soup: re,
                seed: 0,
            })
            .collect();
        eprintln!(
            "topolab report: the orders of {base}, {} structures on each, in rounds",
            structures.len()
        );
        let est = Estimator::default();
        let mut contenders: Vec<Box<dyn Contender + '_>> = Vec::new();
        let mut refused = Vec::new();
        for case in &cases {
            // The probe that skips a sweep too long to run (a scanning structure added from
            // outside the lab).
            let sets = round_sets(case, &plan);
            for s in &structures {
                let set_up = SetUp {
                    case,
                    sets: &sets,
                    plan: &plan,
                    meter: run.meter,
                    est: &est,
                    checks: false,
                };
                let setup = run
                    .structures
                    .set_up(s, set_up)
                    .ok_or_else(|| ReportError::Usage(format!("no structure is called {s}")))?
                    .map_err(ReportError::Measurement)?;
                match setup {
                    Setup::Ready(c) => contenders.push(c),
                    Setup::Refused(m) => {
                        let mut m = *m;
                        // The order's row shows the sweep the structure could not make.
                        m.operator = Subject::Query(Operator::R00);
                        m.kernel = Kernel::Sweep;
                        refused.push(m);
                    }
                }
            }
        }
        run_rounds(&mut contenders, &plan.rounds, run.meter, &mut |_| {})
            .map_err(ReportError::Measurement)?;
        let mut est = est;
        let r00 = (Subject::Query(Operator::R00), Kernel::Sweep);
        for c in contenders {
            run.results.measurements.extend(
                c.finish(&mut est)
                    .into_iter()
                    .filter(|m| (m.operator, m.kernel) == r00),
            );
        }
        run.results.measurements.extend(refused);
        for (name, _) in &orders {
            cross_check(&run.results.measurements, name).map_err(ReportError::Measurement)?;
        }
    }
    Ok(())
}

/// The vertex 1-ring sweep of a torus and a refined real mesh in each element order.
pub struct Orderings;

impl Section for Orderings {
    fn name(&self) -> &'static str {
        "orderings"
    }

    fn needs(&self) -> Needs {
        Needs {
            generated: true,
            refined: Refined::Made,
            ..Needs::NOTHING
        }
    }

    fn phase(&self) -> Option<Phase> {
        Some(Phase::new("orderings", "orderings"))
    }

    fn measure(&self, run: &mut Run) -> Result<(), ReportError> {
        measure(run)
    }

    fn render(&self, h: &mut String, page: &Page) {
        orderings(h, page.r, &page.names);
    }
}
