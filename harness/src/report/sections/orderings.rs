//! "Element order": the vertex 1-ring sweep of a mesh renumbered in each order.

use crate::kernels::sample_queries;
use crate::measure::{cross_check, MeshCase};
use crate::phases::Phase;
use crate::report::format::ns;
use crate::report::run::{ReportError, Run};
use crate::report::section::{Needs, Page, Refined, Section};
use crate::report::sections::real_at_scale::FAMILY;
use crate::results::{Measurement, Results, Status};
use std::fmt::Write;

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
                    let _ = write!(h, "<td>{}</td>", m.ns_per_item.map(ns).unwrap_or_default());
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
    let (cases, plan, results) = (run.cases, run.plan, &mut *run.results);
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
    for (base, _, soup) in torus.into_iter().chain(refined) {
        for ordering in topolab_structures::ordering::Ordering::ALL {
            eprintln!("topolab report: ordering {} of {base}", ordering.name());
            let re = topolab_structures::ordering::reorder(soup, ordering).soup;
            let name = format!("{base}/{}", ordering.name());
            let queries = sample_queries(&re, 1, 0);
            let case = MeshCase {
                name: &name,
                family: "ordering",
                soup: &re,
                queries: &queries,
            };
            for s in &structures {
                let m = run
                    .structures
                    .sweep(s, &case, plan)
                    .ok_or_else(|| ReportError::Usage(format!("no structure is called {s}")))?
                    .map_err(ReportError::Measurement)?;
                results.measurements.push(m);
            }
            cross_check(&results.measurements, &name).map_err(ReportError::Measurement)?;
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
