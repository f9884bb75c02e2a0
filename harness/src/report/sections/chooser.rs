//! "Choosing a structure": the table at the top of the report, one row per structure, measured
//! in the same run (memory, construction, the vertex 1-ring sweep and the smoothing workload on
//! the largest torus), with what it stores and one line on when to pick it.
//!
//! The lines are written from the lecture on polygon-mesh data structures (explicit storage,
//! vertex list, edge list, winged-edge, half-edge, regular and mixed structures, with their
//! cost tables) and the CHE thesis chapter (what each level adds and what it makes cheap). They
//! state what the design gives; the numbers beside them say what it measured on this machine.

use crate::format::esc;
use crate::measuring::kernels::Kernel;
use crate::report::section::{Needs, Page, Section, SizeSweep};
use crate::report::sure::{interval_title, tied};
use crate::results::{Measurement, Results, Status, StructureInfo, Subject};
use std::fmt::Write;
use topolab_structures::{Family, Operator, Workload};

/// When to pick a structure of the lab (by its name), from the two sources; `None` for a
/// structure the lab does not know (from another crate), which gets a generic line.
pub fn when_to_pick(name: &str) -> Option<&'static str> {
    Some(match name {
        "explicit" => "Only to hand polygons over one by one (drawing, export): each polygon repeats its corners' coordinates, and shared edges and a vertex's edges are found by comparing coordinates.",
        "vertex-list" => "To store and exchange meshes (the .obj layout): each vertex stored once and geometry changeable apart from topology, but shared edges and neighbours are still found by scanning the faces.",
        "edge-list" => "When questions start from edges: an edge's end points and faces in O(1), a face's edges in O(k); a vertex's edges and neighbours scan every edge (O(n)).",
        "winged-edge" => "Polygon meshes that move along edges: an edge's faces and its successor and predecessor in both faces in O(1), a vertex's ring by its stored edge; the record the convex-hull algorithms build.",
        "pointer-half-edge" => "The lecture's half-edge as written (HE_edge with real pointers): every relation in O(1) or O(k) on any polygons, with one heap record per element followed by pointer.",
        "index-half-edge" => "General polygon meshes: every relation in O(1) or O(k) from u32 arrays indexed by half-edge (the layout of OpenMesh); the twin of h is h ^ 1.",
        "regular-grid" => "A regular grid only (an image, a height map on a lattice): topology and geometry implicit in the counts, origin and cell size; nothing stored per element.",
        "height-field" => "A grid whose points move (the lecture's mixed structure, e.g. a simulated flag): implicit topology, explicit positions; no adaptive refinement.",
        "che-l0" => "Triangle soups to draw (level 0 of the CHE: G and V only, three integers per triangle); every adjacency query scans V (O(n2)).",
        "che-l1" => "Triangle meshes walked triangle to triangle: O gives the neighbours across each edge in O(1); a vertex's star first searches V for one of its half-edges (O(n2) worst case).",
        "che-l2" => "Triangle meshes with vertex stars: VH and EH make every relation O(1) or O(deg v). EH is the CHE thesis chapter's place for edge attributes; here it holds none and each edit that changes an edge rebuilds it.",
        "che-l3" => "Level 2 plus CH, one half-edge per boundary curve: boundary curves walked in O(∂n1) instead of O(n2), for algorithms that follow the boundary (advancing fronts).",
        "openmesh" => "OpenMesh (C++), the baseline: a maintained half-edge library with its own attributes and I/O, measured through its own loops.",
        "cgal-surface-mesh" => "CGAL's Surface_mesh (C++): the index half-edge of Sieger and Botsch with property maps, when the rest of the pipeline is CGAL's (processing, Euler operations).",
        "cgal-polyhedron" => "CGAL's Polyhedron_3 (C++): the classical pointer half-edge in linked lists, for code written against it; more bytes per element than Surface_mesh.",
        "lox-half-edge" => "lox's HalfEdgeMesh (Rust crate): the index half-edge's design (u32 handles, twin h ^ 1, prev stored too) for polygon meshes, when a Rust project wants a dependency; it keeps no positions (they live beside it, as lox keeps properties in maps).",
        "lox-directed-edge" => "lox's DirectedEdgeMesh (Rust crate): per corner its twin and target, the CHE level 1's idea, half the records per triangle of a half-edge; triangles only.",
        "baby-shark-corner-table" => "baby_shark's CornerTable (Rust crate): the CHE's O table (opposite corner and vertex per corner), inside a crate that also remeshes, decimates and does booleans; its ids are opaque, so the lab keeps tables beside it.",
        "tri-mesh" => "tri-mesh (Rust crate): a triangle half-edge mesh with editing and geometry helpers, its records behind RefCell with Option fields and its twins matched by a hash map when built.",
        _ => return None,
    })
}

/// The smallest value (by `value`) of a measure among `of` on the largest torus each was
/// measured on, with its structure and mesh, and the others it cannot be told apart from
/// (their intervals overlap its: [`tied`]), with their values, when `value` is the cell's time
/// (a count, such as bytes, has no interval).
fn best<'a>(
    r: &'a Results,
    of: &[&'a StructureInfo],
    value: &dyn Fn(&Measurement) -> Option<f64>,
    subject: Subject,
    kernel: Kernel,
) -> Option<Best<'a>> {
    let mut all: Vec<(&'a str, f64, &'a Measurement)> = of
        .iter()
        .filter_map(|s| {
            let m = cell(r, &s.name, subject, kernel, "torus")?;
            Some((s.name.as_str(), value(m)?, m))
        })
        .collect();
    all.sort_by(|a, b| a.1.total_cmp(&b.1));
    let (name, x, m) = *all.first()?;
    let timed = value(m) == m.ns_per_item;
    let ties = all[1..]
        .iter()
        .filter(|o| timed && tied(m, o.2))
        .map(|o| (o.0, o.1))
        .collect();
    Some(Best {
        name,
        value: x,
        mesh: m.mesh.as_str(),
        ties,
    })
}

/// The best of a measure and the structures tied with it.
struct Best<'a> {
    name: &'a str,
    value: f64,
    mesh: &'a str,
    ties: Vec<(&'a str, f64)>,
}

impl Best<'_> {
    /// `name` (bold with `bold`) and its value with `digits` decimals, then the tied ones.
    fn text(&self, bold: bool, digits: usize) -> String {
        let name = if bold {
            format!("<b>{}</b>", self.name)
        } else {
            self.name.to_string()
        };
        let mut t = format!("{name}, {:.digits$}", self.value);
        if !self.ties.is_empty() {
            let others: Vec<String> = self
                .ties
                .iter()
                .map(|(s, x)| format!("{s} {x:.digits$}"))
                .collect();
            let _ = write!(
                t,
                " (tied, their intervals overlap, with {})",
                others.join(", ")
            );
        }
        t
    }
}

/// The paragraph for Rust users under the table, from this run's numbers: per measure, the
/// best of the Rust crates measured and the best of the lab's own structures beside it, which
/// crates store polygons and which edit. Nothing when no crate ran.
fn rust_users(h: &mut String, r: &Results) {
    let crates: Vec<&StructureInfo> = r
        .structures
        .iter()
        .filter(|s| s.family == Family::RustCrate)
        .collect();
    if crates.is_empty() {
        return;
    }
    let lab: Vec<&StructureInfo> = r
        .structures
        .iter()
        .filter(|s| !matches!(s.family, Family::RustCrate | Family::Outside))
        .collect();
    let measures: [(&str, Subject, Kernel, &str); 3] = [
        (
            "builds fastest",
            Subject::Construction,
            Kernel::Construction,
            "ns/face",
        ),
        (
            "sweeps vertex 1-rings fastest",
            Subject::Query(Operator::R00),
            Kernel::Sweep,
            "ns/vertex",
        ),
        (
            "smooths fastest",
            Subject::Workload(Workload::Smoothing),
            Kernel::Workload,
            "ns/vertex",
        ),
    ];
    let mut lines = Vec::new();
    let bytes = |m: &Measurement| m.bytes.map(|b| b as f64 / m.triangles.max(1) as f64);
    let per_item = |m: &Measurement| m.ns_per_item;
    if let Some(c) = best(
        r,
        &crates,
        &bytes,
        Subject::Construction,
        Kernel::Construction,
    ) {
        let lab_best = best(r, &lab, &bytes, Subject::Construction, Kernel::Construction)
            .map(|b| format!(" (of the lab's structures, {})", b.text(false, 0)))
            .unwrap_or_default();
        lines.push(format!(
            "takes the fewest bytes per triangle on {}: {}{lab_best}",
            c.mesh,
            c.text(true, 0)
        ));
    }
    for (what, subject, kernel, unit) in measures {
        if let Some(c) = best(r, &crates, &per_item, subject, kernel) {
            let lab_best = best(r, &lab, &per_item, subject, kernel)
                .map(|b| format!(" (of the lab's structures, {})", b.text(false, 1)))
                .unwrap_or_default();
            lines.push(format!("{what}: {} {unit}{lab_best}", c.text(true, 1)));
        }
    }
    let names = |pick: &dyn Fn(&StructureInfo) -> bool| {
        let v: Vec<&str> = crates
            .iter()
            .filter(|s| pick(s))
            .map(|s| s.name.as_str())
            .collect();
        if v.is_empty() {
            "none".to_string()
        } else {
            v.join(", ")
        }
    };
    let polygons = names(&|s| !s.capabilities.triangles_only && !s.capabilities.grids_only);
    let editable = names(&|s| s.editable);
    let _ = write!(
        h,
        "<p><b>For Rust users.</b> Of the Rust crates measured in this run (their construction timed like the C++ baselines', without the lab's checks, which they need before an untrusted mesh reaches them: see Targets), the crate that {}. Polygons: {polygons}; the others store triangles only. Editing through the lab's operations: {editable}. The Targets table holds the lab's index half-edge and CHE levels against the crate of the same design.</p>",
        lines.join("; the crate that ")
    );
}

/// What the structure stores, by its capabilities.
fn stores(s: &StructureInfo) -> &'static str {
    let c = &s.capabilities;
    if c.grids_only {
        "grids only"
    } else if c.triangles_only {
        "triangles"
    } else {
        "polygons"
    }
}

/// The cell of `s` for `subject`/`kernel` on the largest mesh of `family` it was measured on.
fn cell<'a>(
    r: &'a Results,
    s: &str,
    subject: Subject,
    kernel: Kernel,
    family: &str,
) -> Option<&'a Measurement> {
    r.measurements
        .iter()
        .filter(|m| {
            m.structure == s
                && m.operator == subject
                && m.kernel == kernel
                && m.family == family
                && m.status == Status::Measured
        })
        .max_by_key(|m| m.triangles)
}

fn ns(x: Option<f64>) -> String {
    match x {
        Some(x) if x >= 1e3 => format!("{:.1} µs", x / 1e3),
        Some(x) if x >= 10.0 => format!("{x:.0}"),
        Some(x) => format!("{x:.1}"),
        None => "–".into(),
    }
}

/// The section: nothing when no structure was measured on a torus or grid.
fn section(h: &mut String, r: &Results) {
    if !r
        .measurements
        .iter()
        .any(|m| m.family == "torus" || m.family == "grid")
    {
        return;
    }
    h.push_str("<h2>Choosing a structure</h2><div class=read><b>How to read it.</b> Measured in this run, on the largest closed torus (a structure that stores only grids: on the largest grid, marked): the heap bytes per triangle of the built structure, geometry included (every structure's blocks counted alike, the C++ baselines' too: see Memory per triangle); construction per face (warm builds); the vertex 1-ring sweep (R00 over every vertex) and one step of uniform smoothing, per vertex. <i>Editable</i>: whether the structure implements the lab's editing operations (<code>MeshEdit</code>): of the operations the lecture on polygon-mesh data structures asks for (select, insert, delete, weld, rotate and scale vertices, edges and faces; weld whole meshes), the insertion and deletion of vertices and faces and the weld of vertices and of whole meshes; the edge flip, the edge and face splits, the edge collapse and the vertex split come from pmp-library and OpenMesh (see Changing workloads). The last column says when the design fits, from the lecture on polygon-mesh data structures and the CHE thesis chapter. Hover a number for the mesh and its interval; two structures whose intervals overlap cannot be told apart in this run.</div>");
    h.push_str("<table><tr><th class=l>structure</th><th class=l>family</th><th>bytes per triangle</th><th>construction, ns/face</th><th>R00 sweep, ns/vertex</th><th>smoothing, ns/vertex</th><th class=l>stores</th><th class=l>editable</th><th class=l>pick it when</th></tr>");
    for s in &r.structures {
        let refused_torus = r.measurements.iter().any(|m| {
            m.structure == s.name
                && m.family == "torus"
                && m.kernel == Kernel::Construction
                && m.status == Status::Refused
        });
        let fam = if refused_torus { "grid" } else { "torus" };
        let build = cell(r, &s.name, Subject::Construction, Kernel::Construction, fam);
        let bytes = build.and_then(|m| m.bytes.map(|b| b as f64 / m.triangles.max(1) as f64));
        let r00 = cell(
            r,
            &s.name,
            Subject::Query(Operator::R00),
            Kernel::Sweep,
            fam,
        );
        let smooth = cell(
            r,
            &s.name,
            Subject::Workload(Workload::Smoothing),
            Kernel::Workload,
            fam,
        );
        let td = |m: Option<&Measurement>, x: Option<f64>| match m {
            Some(m) => format!(
                "<td title=\"{} ({} triangles): {}\">{}{}</td>",
                m.mesh,
                m.triangles,
                esc(&interval_title(m)),
                ns(x),
                if fam == "grid" {
                    " <span class=small>(grid)</span>"
                } else {
                    ""
                }
            ),
            None => "<td class=skip>–</td>".into(),
        };
        let pick = when_to_pick(&s.name).unwrap_or(match s.family {
            Family::Outside | Family::RustCrate => "A structure from outside the lab: see its own documentation; its numbers are measured like the lab's.",
            _ => "–",
        });
        let _ = write!(
            h,
            "<tr><th class=l>{}</th><td class=l>{}</td>{}{}{}{}<td class=l>{}</td><td class=l>{}</td><td class=l>{}</td></tr>",
            s.name,
            s.family,
            match (build, bytes) {
                (Some(m), Some(b)) => format!(
                    "<td title=\"{} ({} triangles)\">{b:.0}{}</td>",
                    m.mesh,
                    m.triangles,
                    if fam == "grid" { " <span class=small>(grid)</span>" } else { "" }
                ),
                _ => "<td class=skip>–</td>".into(),
            },
            td(build, build.and_then(|m| m.ns_per_item)),
            td(r00, r00.and_then(|m| m.ns_per_item)),
            td(smooth, smooth.and_then(|m| m.ns_per_item)),
            stores(s),
            if s.editable { "yes" } else { "not yet" },
            pick
        );
    }
    h.push_str("</table>");
    rust_users(h, r);
}

/// "Choosing a structure", at the top: per structure its memory, construction, R00 sweep
/// and smoothing on the largest torus, what it stores and when to pick it.
pub struct Chooser;

impl Section for Chooser {
    fn name(&self) -> &'static str {
        "chooser"
    }

    fn needs(&self) -> Needs {
        Needs::size_sweep(SizeSweep::Full)
    }

    fn before_machine(&self) -> bool {
        true
    }

    fn render(&self, h: &mut String, page: &Page) {
        section(h, page.r);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_structure_of_the_lab_has_a_line_on_when_to_pick_it() {
        for &name in topolab_structures::registry::NAMES {
            let line = when_to_pick(name).unwrap_or_else(|| panic!("{name} has no line"));
            assert!(line.ends_with('.') && line.len() < 260, "{name}: {line}");
        }
        for baseline in ["openmesh", "cgal-surface-mesh", "cgal-polyhedron"] {
            assert!(when_to_pick(baseline).is_some(), "{baseline}");
        }
        for peer in [
            "lox-half-edge",
            "lox-directed-edge",
            "baby-shark-corner-table",
            "tri-mesh",
        ] {
            let line = when_to_pick(peer).unwrap_or_else(|| panic!("{peer} has no line"));
            assert!(line.ends_with('.') && line.len() < 260, "{peer}: {line}");
        }
        assert_eq!(when_to_pick("sorted-edge-table"), None);
    }
}
