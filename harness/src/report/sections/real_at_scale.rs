//! "Real meshes at scale": the refined real meshes (family `refined`: a mesh of
//! `bench-data/cache/` refined by Loop subdivision, new vertices appended after the old ones)
//! measured like the tori, each cell beside the same cell on the torus of the nearest size.

use crate::format::{esc, ns};
use crate::measuring::kernels::Kernel;
use crate::report::run::MeshFamily;
use crate::report::section::{Needs, Page, Refined, Section};
use crate::report::sure::interval_title;
use crate::results::{Measurement, MeshInfo, Results, Status, Subject};
use std::fmt::Write;
use topolab_structures::{Operator, Workload};

/// The family name of the refined meshes.
pub const FAMILY: &str = MeshFamily::Refined.name();

/// The torus whose triangle count is nearest (in ratio) to `triangles`.
fn nearest_torus(r: &Results, triangles: usize) -> Option<&MeshInfo> {
    let gap = |m: &&MeshInfo| (m.triangles as f64 / triangles.max(1) as f64).ln().abs();
    r.meshes
        .iter()
        .filter(|m| m.family == "torus")
        .min_by(|a, b| gap(a).total_cmp(&gap(b)))
}

fn find<'a>(
    r: &'a Results,
    mesh: &str,
    s: &str,
    subject: Subject,
    kernel: Kernel,
) -> Option<&'a Measurement> {
    r.measurements
        .iter()
        .find(|m| m.mesh == mesh && m.structure == s && m.operator == subject && m.kernel == kernel)
}

/// The section: one table per refined mesh; nothing when there is none.
fn section(h: &mut String, r: &Results, names: &[&str]) {
    let refined: Vec<&MeshInfo> = r.meshes.iter().filter(|m| m.family == FAMILY).collect();
    if refined.is_empty() {
        return;
    }
    h.push_str("<h2>Real meshes at scale</h2><div class=read><b>How to read it.</b> Real meshes of <code>bench-data/cache/</code> refined by Loop subdivision (each level splits every triangle into four; the new vertices are appended after the old ones, as real tools do, so neighbours are far apart in memory), measured like the tori: every operator swept over every element, the workloads, construction. Each cell: nanoseconds per element (construction: per face) and, below, the ratio to the same cell on the torus of the nearest size, whose order is ideal (above 1×: what the real mesh's order and shape cost). The element-order section renumbers the smallest of them.</div>");
    let mut rows: Vec<(String, Subject, Kernel)> = Operator::ALL
        .iter()
        .map(|&op| {
            (
                format!("{} sweep", op.name()),
                Subject::Query(op),
                Kernel::Sweep,
            )
        })
        .collect();
    rows.extend(
        Workload::ALL
            .iter()
            .map(|&w| (w.name().to_string(), Subject::Workload(w), Kernel::Workload)),
    );
    rows.push((
        "construction".into(),
        Subject::Construction,
        Kernel::Construction,
    ));
    for mesh in refined {
        let torus = nearest_torus(r, mesh.triangles);
        let _ = write!(
            h,
            "<h3>{} ({} vertices, {} triangles{})</h3><table><tr><th class=l>operator</th>",
            mesh.name,
            mesh.vertices,
            mesh.triangles,
            torus
                .map(|t| format!("; ratios to {}", t.name))
                .unwrap_or_default()
        );
        for n in names {
            let _ = write!(h, "<th>{n}</th>");
        }
        h.push_str("</tr>");
        for (label, subject, kernel) in &rows {
            let _ = write!(h, "<tr><th class=l>{label}</th>");
            for s in names {
                let here = find(r, &mesh.name, s, *subject, *kernel);
                let there = torus.and_then(|t| find(r, &t.name, s, *subject, *kernel));
                let cell = match here {
                    Some(m) if m.status == Status::Measured => {
                        let t = m.ns_per_item.unwrap_or(f64::NAN);
                        let ratio = there
                            .and_then(|o| o.ns_per_item.filter(|_| o.status == Status::Measured))
                            .map(|o| format!("<br><span class=small>{:.2}×</span>", t / o))
                            .unwrap_or_default();
                        format!(
                            "<td title=\"{}\">{}{ratio}</td>",
                            esc(&interval_title(m)),
                            ns(t)
                        )
                    }
                    Some(m) if m.status == Status::Skipped => format!(
                        "<td class=skip>skipped (est. {})</td>",
                        m.estimate_ns_per_item.map(ns).unwrap_or_default()
                    ),
                    Some(_) => "<td class=skip>refused</td>".into(),
                    None => "<td class=skip>–</td>".into(),
                };
                h.push_str(&cell);
            }
            h.push_str("</tr>");
        }
        h.push_str("</table>");
    }
}

/// Real meshes refined to 1M triangles and more (family [`FAMILY`]), measured like the tori.
pub struct RealAtScale;

impl Section for RealAtScale {
    fn name(&self) -> &'static str {
        "real-at-scale"
    }

    fn needs(&self) -> Needs {
        Needs {
            refined: Refined::Measured,
            ..Needs::NOTHING
        }
    }

    fn render(&self, h: &mut String, page: &Page) {
        section(h, page.r, &page.names);
    }
}
