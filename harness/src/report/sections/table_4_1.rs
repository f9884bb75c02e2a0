//! "Table 4.1, measured": per operator and structure, the declared cost, the fitted exponent
//! and the time at the largest size, with libigl's functions beside them.

use crate::format::ns;
use crate::measuring::kernels::Kernel;
use crate::measuring::phases::Phase;
use crate::report::cells::{cells, family_of, table_kernel};
use crate::report::run::{ReportError, Run};
use crate::report::section::{Needs, Page, Section, SizeSweep};
use crate::report::sure::ns_with_interval;
use crate::results::{Results, Status, Subject};
use crate::studies::reads::{count_all, Budget, ReadsRow};
use std::fmt::Write;
use std::time::Instant;
use topolab_structures::Operator;

fn table_4_1(h: &mut String, r: &Results, names: &[&str]) {
    h.push_str("<h2>Table 4.1, measured</h2><div class=read><b>How to read it.</b> Each row is an operator, each column a structure. In every cell: the cost the structure declares (the tables of the lecture on polygon-mesh data structures and Table 4.1 of the CHE thesis chapter), then the exponent <i>e</i> fitted to the measured time per query against mesh size (<i>t ∝ n<sup>e</sup></i>: 0 means constant time, 1 means the query scans the mesh), then the time per query at the largest size measured (the median of its rounds, each on fresh builds; hover it for its interval). Green: the measurement agrees with the theory; red: it does not (look closer: caches make O(1) queries slower on big meshes); grey: skipped because it would take too long (the estimate is shown: from the smaller sizes, or, at the first size, from the time per query of a timed sample of queries). Relations R00–R22 are measured on closed tori, boundary operators on open grids, by the sampled kernel (each round asks queries drawn afresh for that round, the same for every structure, none asked twice in a round, so no query finds its records left in cache by the cell's earlier passes; the C++ baselines answer them, like every kernel of theirs, in one loop in C++, the queries handed over in the library's own handles before the clock starts).</div>");
    h.push_str("<table><tr><th class=l>operator</th>");
    for n in names {
        let _ = write!(h, "<th>{n}</th>");
    }
    if !r.libigl.is_empty() {
        h.push_str("<th>libigl (whole-mesh build)</th>");
    }
    h.push_str("</tr>");
    for op in Operator::ALL {
        let row_fam = family_of(op);
        let kernel = table_kernel(op);
        let _ = write!(
            h,
            "<tr><th class=l>{} <span class=small>({row_fam})</span></th>",
            op.name()
        );
        for s in names {
            // Grid-only structures cannot store a torus: their row is measured on the grids.
            let refused_row_family =
                cells(r, s, Subject::Construction, Kernel::Construction, row_fam)
                    .iter()
                    .all(|m| m.status == Status::Refused);
            let fam = if refused_row_family { "grid" } else { row_fam };
            let on = if fam != row_fam {
                format!("<br><span class=small>on {fam}s</span>")
            } else {
                String::new()
            };
            let theory = r
                .structures
                .iter()
                .find(|x| x.name == *s)
                .and_then(|x| x.costs.iter().find(|c| c.operator == op))
                .map(|c| c.cost.notation())
                .unwrap_or_default();
            let fit = r.fits.iter().find(|f| {
                f.structure == *s && f.operator == op && f.kernel == kernel && f.family == fam
            });
            let cs = cells(r, s, Subject::Query(op), kernel, fam);
            let last_measured = cs.iter().rev().find(|m| m.status == Status::Measured);
            let last = cs.last();
            let (class, body) = match (last, fit) {
                (None, _) => ("skip", "not run".to_string()),
                (Some(m), _) if m.status == Status::Refused => {
                    ("skip", "cannot store this mesh".to_string())
                }
                (Some(m), f) => {
                    let class = match f {
                        Some(f) if f.agrees => "ok",
                        Some(_) => "bad",
                        None => "",
                    };
                    let e = f
                        .map(|f| format!("e = {:.2} ({})", f.exponent, f.class))
                        .unwrap_or_else(|| "e: too few sizes".into());
                    let t = match (m.status, last_measured) {
                        (Status::Skipped, _) => format!(
                            "skipped at {} tri (est. {})",
                            m.triangles,
                            m.estimate_ns_per_item.map(ns).unwrap_or_default()
                        ),
                        (_, Some(lm)) => {
                            format!("{} at {} tri", ns_with_interval(lm), lm.triangles)
                        }
                        _ => String::new(),
                    };
                    let class = if m.status == Status::Skipped && class.is_empty() {
                        "skip"
                    } else {
                        class
                    };
                    (class, format!("<span class=exp>{e}</span><br>{t}"))
                }
            };
            let _ = write!(
                h,
                "<td class={class}><span class=cost>{theory}</span>{body}{on}</td>"
            );
        }
        if !r.libigl.is_empty() {
            let l: Vec<String> = r
                .libigl
                .iter()
                .filter(|l| l.operator == Subject::Query(op))
                .map(|l| {
                    format!(
                        "{}: {} per element{}",
                        l.function,
                        ns(l.ns_per_item),
                        if l.agrees { "" } else { " (checksum differs!)" }
                    )
                })
                .collect();
            let _ = write!(
                h,
                "<td class=ref>{}</td>",
                l.last().cloned().unwrap_or_default()
            );
        }
        h.push_str("</tr>");
    }
    h.push_str("</table>");
}

/// Counts the reads of `names` (the C++ baselines and structures outside the lab are left
/// out: their reads are not the lab's to count) on the generated meshes of `sizes`, and notes
/// how long it took.
fn count(names: &[String], sizes: &[usize], notes: &mut Vec<String>) -> Vec<ReadsRow> {
    eprintln!("topolab report: counting reads per query...");
    let start = Instant::now();
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    let rows = count_all(&names, sizes, Budget::default());
    let skipped = rows.iter().filter(|r| !r.skipped.is_empty()).count();
    notes.push(format!(
        "Reads per query were counted in {:.1} s ({} rows; {skipped} stop before the largest size, whose reads the declared cost puts above {:.0e} per cell).",
        start.elapsed().as_secs_f64(),
        rows.len(),
        Budget::default().reads_per_cell
    ));
    rows
}

/// The measured Table 4.1 of the CHE thesis chapter (declared cost, fitted exponent, time),
/// and the reads per query counted.
pub struct Table41;

impl Section for Table41 {
    fn name(&self) -> &'static str {
        "table-4-1"
    }

    fn needs(&self) -> Needs {
        Needs::size_sweep(SizeSweep::Full)
    }

    fn phase(&self) -> Option<Phase> {
        Some(Phase::new("reads", "reads per query (Table 4.1)"))
    }

    fn measure(&self, run: &mut Run) -> Result<(), ReportError> {
        let r = &mut *run.results;
        r.reads = count(&run.request.names, &run.request.sizes, &mut r.notes);
        Ok(())
    }

    fn render(&self, h: &mut String, page: &Page) {
        table_4_1(h, page.r, &page.names);
        crate::report::reads::table(h, page.r);
    }
}
