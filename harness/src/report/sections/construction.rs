//! "Construction time": builds per face against mesh size, warm and cold.

use crate::format::ns;
use crate::measuring::kernels::Kernel;
use crate::page::plot;
use crate::page::plot::Style;
use crate::report::cells::{largest, lines};
use crate::report::section::{Needs, Page, Section, SizeSweep};
use crate::results::{Measurement, Results, Status, Subject};
use std::fmt::Write;

fn construction(h: &mut String, r: &Results, ci: &dyn Fn(&str) -> Style) {
    h.push_str("<h2>Construction time</h2><div class=read><b>How to read it.</b> Time to build each structure from the face list, per face, against mesh size (log-log), with each structure's own checks of the input; the C++ baselines are timed as their documentation builds a mesh (OpenMesh and CGAL's <code>Surface_mesh</code>: <code>reserve</code>, <code>add_vertex</code>, <code>add_face</code>; <code>Polyhedron_3</code>: its incremental builder), and the Rust crates as theirs do (lox: <code>reserve_for_vertices</code>, <code>reserve_for_faces</code>, <code>add_vertex</code>, <code>add_face</code>; baby_shark: <code>CornerTable::from_vertex_and_face_iters</code>; tri-mesh: <code>Mesh::new</code>), all without the lab's up-front checks, which run before the clock (they refuse what a library would mis-handle) and tell each library the exact numbers of vertices, edges and faces to reserve (open meshes and polygons included). The lab's own structures' checks are part of their construction and are timed with it. Nothing else is timed: no structure's destructor (each build is freed after the clock), and not the tables from id to handle the lab adds to a <code>Polyhedron_3</code>, a baby_shark corner table or a tri-mesh <code>Mesh</code> for its queries. A flat line is linear-time construction. Each build is timed in the CPU time of the measuring thread (user and system: page faults count), which other processes on a shared machine do not stretch. Builds are timed <i>warm</i>: glibc's <code>malloc</code> (which the Rust structures and the C++ baselines share) keeps the memory freed by the build before, so a build touches no fresh page whatever the run built earlier; nothing is counted while timing (the heap is measured in a build of its own). The table below also times <i>cold</i> builds, each after the allocator returned its free memory to the kernel: every page the build touches is then a page fault, whose cost on this machine is the difference.</div><div class=plots>");
    for fam in ["torus", "grid"] {
        let series = lines(r, Subject::Construction, Kernel::Construction, fam, ci);
        h.push_str(&plot::loglog(
            &format!("construction ({fam})"),
            "faces",
            "ns per face",
            "ns per face",
            &series,
        ));
    }
    h.push_str("</div>");
    let Some((mesh, tri)) = largest(r, "torus") else {
        return;
    };
    let builds: Vec<&Measurement> = r
        .measurements
        .iter()
        .filter(|m| {
            m.mesh == mesh && m.kernel == Kernel::Construction && m.status == Status::Measured
        })
        .collect();
    let om = builds.iter().copied().find(|m| m.structure == "openmesh");
    let _ = write!(h, "<table><tr><th class=l>{mesh} ({tri} faces)</th><th>warm, ns/face</th><th>cold, ns/face</th><th>cold − warm (page faults), ns/face</th><th>page faults per build, warm / cold</th><th>warm / OpenMesh</th><th>cold / OpenMesh</th></tr>");
    for m in &builds {
        let opt = |x: Option<f64>| x.map(ns).unwrap_or_else(|| "–".into());
        let faults = |x: Option<u64>| x.map(|f| f.to_string()).unwrap_or_else(|| "–".into());
        let vs = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(a), Some(b)) => format!("{:.2}×", a / b),
            _ => "–".into(),
        };
        let (warm, cold) = (m.ns_per_item, m.cold_ns_per_item);
        let _ = write!(
            h,
            "<tr><td class=l>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{} / {}</td><td>{}</td><td>{}</td></tr>",
            m.structure,
            opt(warm),
            opt(cold),
            opt(warm.zip(cold).map(|(w, c)| c - w)),
            faults(m.page_faults),
            faults(m.cold_page_faults),
            vs(warm, om.and_then(|o| o.ns_per_item)),
            vs(cold, om.and_then(|o| o.cold_ns_per_item)),
        );
    }
    h.push_str("</table>");
}

/// Construction time, warm and cold.
pub struct Construction;

impl Section for Construction {
    fn name(&self) -> &'static str {
        "construction"
    }

    fn needs(&self) -> Needs {
        Needs::size_sweep(SizeSweep::Light)
    }

    fn render(&self, h: &mut String, page: &Page) {
        construction(h, page.r, &|s| page.style(s));
    }
}
