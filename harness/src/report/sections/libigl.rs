//! "libigl as reference": libigl's whole-mesh functions, timed, their answers checked.

use crate::format::{esc, ns};
use crate::measuring::kernels::Kernel;
use crate::measuring::phases::Phase;
use crate::report::run::{Case, ReportError, Run};
use crate::report::section::{Needs, Page, Section, SizeSweep};
use crate::results::{LibiglRow, Measurement, Results, Subject};
use std::fmt::Write;
use std::path::Path;
use topolab_structures::Input;

/// The name `--structures` accepts for libigl (an outside baseline, run from Python, not a
/// structure of the registry): the libigl section runs when the list names it.
pub const LIBIGL: &str = "libigl";

fn libigl(h: &mut String, r: &Results) {
    if r.libigl.is_empty() {
        return;
    }
    h.push_str("<h2>libigl as reference</h2><div class=read><b>How to read it.</b> libigl answers these relations by building whole-mesh adjacency arrays (not by per-query circulation), timed inside Python around each call (best of several, one thread). Its checksum is compared with the lab's answer for the same operator.</div><table><tr><th class=l>mesh</th><th class=l>operator</th><th class=l>libigl function</th><th>ns per element</th><th>checksum agrees</th></tr>");
    for l in &r.libigl {
        let _ = write!(h, "<tr><td class=l>{}</td><td class=l>{}</td><td class=l>{}</td><td>{}</td><td class={}>{}</td></tr>", esc(&l.mesh), l.operator, l.function, ns(l.ns_per_item), if l.agrees { "ok" } else { "bad" }, if l.agrees { "yes" } else { "no" });
    }
    h.push_str("</table>");
}

/// libigl's reference timings on the tori, when `.venv/bin/python` with libigl exists (its
/// script's checksums compared with the lab's sweep of the same operator), and the version of
/// libigl that answered (from its script's output), when it ran.
fn measure(
    cases: &[Case],
    measurements: &[Measurement],
    notes: &mut Vec<String>,
) -> (Vec<LibiglRow>, Option<String>) {
    let python = Path::new(".venv/bin/python");
    let script = Path::new("python/libigl_reference.py");
    let ready = python.exists()
        && std::process::Command::new(python)
            .args(["-c", "import igl"])
            .output()
            .is_ok_and(|o| o.status.success());
    if !ready || !script.exists() {
        notes.push(
            "libigl was not run: .venv/bin/python with libigl is missing (bash .ci/install-deps)."
                .into(),
        );
        return (Vec::new(), None);
    }
    let dir = std::env::temp_dir().join(format!("topolab-libigl-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let mut rows = Vec::new();
    let mut version = None;
    for (name, _, soup) in cases.iter().filter(|c| c.1 == "torus") {
        eprintln!("topolab report: libigl on {name}");
        let (mesh, json) = (
            dir.join(format!("{name}.obj")),
            dir.join(format!("{name}.json")),
        );
        if topolab_structures::io::write(&mesh, soup).is_err() {
            continue;
        }
        let ran = std::process::Command::new(python)
            .arg(script)
            .arg(&mesh)
            .arg("--out")
            .arg(&json)
            .env("IGL_NUM_THREADS", "1")
            .output();
        let parsed: Option<serde_json::Value> = std::fs::read_to_string(&json)
            .ok()
            .and_then(|t| serde_json::from_str(&t).ok());
        let Some(v) = parsed.filter(|_| ran.is_ok_and(|o| o.status.success())) else {
            notes.push(format!("libigl failed on {name}"));
            continue;
        };
        if let Some(v) = v["libigl_version"].as_str() {
            version = Some(v.to_string());
        }
        let edges = soup.connectivity().map(|c| c.num_edges()).unwrap_or(0);
        for r in v["results"].as_array().into_iter().flatten() {
            let Some(subject) = r["operator"].as_str().and_then(Subject::from_name) else {
                continue;
            };
            // The lab's answer over the whole mesh: an operator's sweep, or the workload.
            let kernel = match subject {
                Subject::Query(_) => Kernel::Sweep,
                Subject::Workload(_) => Kernel::Workload,
                Subject::Construction => Kernel::Construction,
            };
            let lab = measurements.iter().find(|m| {
                m.mesh == *name
                    && m.operator == subject
                    && m.kernel == kernel
                    && m.checksum.is_some()
            });
            let (checksum, agrees) = match (
                r["checksum"].as_str(),
                r["value"].as_f64(),
                lab.and_then(|m| m.checksum.as_deref()),
            ) {
                (Some(c), _, Some(l)) => (c.to_string(), c == l),
                (None, Some(x), Some(l)) => {
                    let l: f64 = l.parse().unwrap_or(f64::NAN);
                    (
                        format!("{x:.9e}"),
                        (x - l).abs() <= 1e-6 * x.abs().max(l.abs()).max(1.0),
                    )
                }
                _ => continue,
            };
            let items = match subject {
                Subject::Query(op) => match op.input() {
                    Input::Vertex => soup.num_vertices(),
                    Input::Edge => edges,
                    // Boundary curves too: per face, like the face relations.
                    Input::Face | Input::EdgeOfFace | Input::Mesh => soup.num_faces(),
                },
                Subject::Workload(_) | Subject::Construction => soup.num_vertices(),
            };
            rows.push(LibiglRow {
                mesh: name.clone(),
                operator: subject,
                function: r["function"].as_str().unwrap_or_default().into(),
                checksum,
                agrees,
                ns_per_item: r["seconds"].as_f64().unwrap_or(f64::NAN) * 1e9 / items.max(1) as f64,
            });
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    (rows, version)
}

/// libigl's functions timed on the tori, their answers checked against the lab's sweeps and
/// workloads (so it needs them all).
pub struct Libigl;

impl Section for Libigl {
    fn name(&self) -> &'static str {
        "libigl"
    }

    fn needs(&self) -> Needs {
        Needs {
            subject: Some(LIBIGL),
            ..Needs::size_sweep(SizeSweep::Full)
        }
    }

    fn phase(&self) -> Option<Phase> {
        Some(Phase::new("libigl", "libigl"))
    }

    fn measure(&self, run: &mut Run) -> Result<(), ReportError> {
        let r = &mut *run.results;
        (r.libigl, run.libigl_version) = measure(run.cases, &r.measurements, &mut r.notes);
        Ok(())
    }

    fn render(&self, h: &mut String, page: &Page) {
        libigl(h, page.r);
    }
}
