//! "Real meshes": the fetched meshes, each structure's sweep and construction on them.

use crate::format::esc;
use crate::measuring::kernels::Kernel;
use crate::report::section::{Needs, Page, Real, Section};
use crate::report::sure::ns_with_interval;
use crate::results::{MeshInfo, Results, Status, Subject};
use std::fmt::Write;
use topolab_structures::Operator;

fn real_meshes(h: &mut String, r: &Results, names: &[&str]) {
    let real: Vec<&MeshInfo> = r.meshes.iter().filter(|m| m.family == "real").collect();
    if real.is_empty() {
        return;
    }
    let _ = write!(h, "<h2>Real meshes</h2><div class=read><b>How to read it.</b> Meshes fetched from package registries by <code>make data</code> (see <code>bench-data/manifest.toml</code>). Each cell: the vertex 1-ring sweep in nanoseconds per vertex and the construction time per face; a structure that cannot store the mesh says why (scans and dirty inputs are refused by the structures that require an oriented manifold or triangles). {}</div><table><tr><th class=l>mesh</th><th>faces</th>", crate::page::repaired::HOW_TO_READ);
    for n in names {
        let _ = write!(h, "<th>{n}</th>");
    }
    h.push_str("</tr>");
    for mesh in real {
        let _ = write!(
            h,
            "<tr><th class=l>{}{}</th><td>{}</td>",
            esc(&mesh.name),
            crate::page::repaired::mark(mesh),
            mesh.faces
        );
        for n in names {
            let find = |op: Subject, kernel: Kernel| {
                r.measurements.iter().find(|m| {
                    m.mesh == mesh.name
                        && m.structure == *n
                        && m.operator == op
                        && m.kernel == kernel
                })
            };
            let cell = match (
                find(Subject::Construction, Kernel::Construction),
                find(Subject::Query(Operator::R00), Kernel::Sweep),
            ) {
                (Some(c), _) if c.status == Status::Refused => format!(
                    "<td class=skip title=\"{}\">refused ({})</td>",
                    esc(c.note.as_deref().unwrap_or_default()),
                    c.note
                        .as_deref()
                        .and_then(|n| n.split(':').next())
                        .unwrap_or("?")
                ),
                (Some(c), Some(s)) if s.status == Status::Measured => format!(
                    "<td>{} /v<br><span class=small>build {} /f</span></td>",
                    ns_with_interval(s),
                    ns_with_interval(c)
                ),
                (Some(_), Some(s)) if s.status == Status::Skipped => {
                    "<td class=skip>skipped</td>".to_string()
                }
                _ => "<td class=skip>–</td>".to_string(),
            };
            h.push_str(&cell);
        }
        h.push_str("</tr>");
    }
    h.push_str("</table>");
}

/// The real meshes of `bench-data/cache/` (repaired where the structures refuse them).
pub struct RealMeshes;

impl Section for RealMeshes {
    fn name(&self) -> &'static str {
        "real-meshes"
    }

    fn needs(&self) -> Needs {
        Needs {
            real: Real::Measured,
            ..Needs::NOTHING
        }
    }

    fn render(&self, h: &mut String, page: &Page) {
        real_meshes(h, page.r, &page.names);
    }
}
