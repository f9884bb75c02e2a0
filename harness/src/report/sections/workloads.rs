//! "Application workloads": the Surface_mesh benchmark's workloads against mesh size.

use crate::measuring::kernels::Kernel;
use crate::page::plot;
use crate::page::plot::Style;
use crate::report::cells::lines;
use crate::report::section::{Needs, Page, Section, SizeSweep};
use crate::results::{Results, Subject};
use topolab_structures::Workload;

fn workloads(h: &mut String, r: &Results, ci: &dyn Fn(&str) -> Style) {
    h.push_str("<h2>Application workloads (Sieger &amp; Botsch, IMR 2011)</h2><div class=read><b>How to read it.</b> The workloads of the published Surface_mesh benchmark, which OpenMesh and pmp-library users compare on: <i>circulators</i> (for each vertex count its faces, for each face subtract its vertices; the total must be 0), <i>barycenter</i> (mean of all positions), <i>normals</i> (face normals, then vertex normals), <i>smoothing</i> (one step of uniform 1-ring averaging of interior vertices). Time per element on closed tori of growing size; every structure's result is cross-checked.</div><div class=plots>");
    for w in Workload::ALL {
        let series = lines(r, Subject::Workload(w), Kernel::Workload, "torus", ci);
        h.push_str(&plot::loglog(
            w.name(),
            "triangles",
            "ns per element",
            "ns per element",
            &series,
        ));
    }
    h.push_str("</div>");
}

/// The Surface_mesh workloads.
pub struct Workloads;

impl Section for Workloads {
    fn name(&self) -> &'static str {
        "workloads"
    }

    fn needs(&self) -> Needs {
        Needs::size_sweep(SizeSweep::Full)
    }

    fn render(&self, h: &mut String, page: &Page) {
        workloads(h, page.r, &|s| page.style(s));
    }
}
