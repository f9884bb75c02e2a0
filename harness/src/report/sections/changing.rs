//! "Changing meshes": the changing workloads of the Surface_mesh benchmark (√3 subdivision,
//! the collapse test) on the editable structures and the outside libraries.

use crate::changing::ChangingRow;
use crate::phases::Phase;
use crate::report::section::{Needs, Page, Section};
use std::fmt::Write;

/// The report section.
pub(crate) fn render(h: &mut String, rows: &[ChangingRow]) {
    if rows.is_empty() {
        return;
    }
    h.push_str("<h2>Changing meshes: √3 subdivision and the collapse test (Sieger &amp; Botsch, IMR 2011)</h2><div class=read><b>How to read it.</b> The two workloads of the published Surface_mesh benchmark that change the mesh, run as its protocol runs them: <i>sqrt3</i> is one step of √3 subdivision (new positions of the old interior vertices, every old face split at its centroid, every old edge flipped where a flip is allowed); <i>collapse-test</i> splits every face at a new vertex, collapses every new vertex back and garbage-collects the deleted elements. The lab's structures run them through their editing operations (<code>MeshEdit</code>: checked flips and collapses, the link condition included); OpenMesh runs the protocol's loop in C++ (its collapse unchecked, as the protocol calls it), and so do CGAL's Surface_mesh and Polyhedron_3, through CGAL's Euler operations as CGAL's own Surface_mesh benchmark does. Each time is the median of fresh builds (the build not timed), per face of the input. Every resulting mesh is compared (counts and a hash of the face list) across structures; a disagreement stops the report. <i>Declared costs</i>: what each structure declares for the operations the workload does (all of them: <code>topolab explain NAME</code>); a structure whose declared costs predict more than 20 s (2 s in a quick run) (the vertex list's and the edge list's scans on large meshes) is skipped, with the estimate in the notes.</div>");
    h.push_str("<table><tr><th class=l>workload</th><th class=l>mesh</th><th>faces</th><th class=l>structure</th><th>ms</th><th>ns per face</th><th>× OpenMesh</th><th>result V / E / F</th><th class=l>declared costs</th></tr>");
    for r in rows {
        let om = rows
            .iter()
            .find(|o| o.workload == r.workload && o.mesh == r.mesh && o.structure == "openmesh")
            .map(|o| format!("{:.2}", r.seconds / o.seconds))
            .unwrap_or_else(|| "–".into());
        let _ = write!(
            h,
            "<tr><td class=l>{}</td><td class=l>{}</td><td>{}</td><td class=l>{}</td><td>{:.1}</td><td>{:.1}</td><td>{om}</td><td>{} / {} / {}</td><td class=l>{}</td></tr>",
            r.workload.name(),
            r.mesh,
            r.faces,
            r.structure,
            r.seconds * 1e3,
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
pub struct Changing;

impl Section for Changing {
    fn name(&self) -> &'static str {
        "changing"
    }

    fn needs(&self) -> Needs {
        Needs::GENERATED
    }

    fn phase(&self) -> Option<Phase> {
        Some(Phase::new("changing", "changing workloads"))
    }

    fn render(&self, h: &mut String, page: &Page) {
        render(h, &page.r.changing);
    }
}
