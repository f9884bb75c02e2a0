//! "Sweeps and their limits": every sweep on the largest torus against the time its
//! structure's access model allows on this machine.

use crate::format::{esc, ns};
use crate::measuring::kernels::Kernel;
use crate::measuring::speed_limit::{limit_text, times_limit};
use crate::report::cells::largest;
use crate::report::section::{Needs, Page, Section, SizeSweep};
use crate::report::sure::ns_with_interval;
use crate::results::{Results, Status, Subject};
use std::fmt::Write;
use topolab_structures::Operator;

fn sweeps(h: &mut String, r: &Results, names: &[&str]) {
    let Some((mesh, tri)) = largest(r, "torus") else {
        return;
    };
    let _ = write!(h, "<h2>Sweeps and their limits ({mesh}, {tri} triangles)</h2><div class=read><b>How to read it.</b> A sweep answers the operator for every element; the cell shows nanoseconds per element. Below it, the measured time as a multiple of its <i>limit</i>, the time the structure's declared access model allows on this machine (the probe's bandwidth and load latency by working-set size, under Machine): the largest of the bytes the sweep reads at the bandwidth (each container's cache lines once, as a sweep in storage order reads them; a scan in full for every query), its chain of dependent loads (each step of a fan walk is one) at the latency of one query's working set, and the checksum's arithmetic per answer. The reads of the edge keys the checksum mixes in count too. 1× = as fast as the design allows; well above = work the model leaves out (arithmetic on the chain, branches, bookkeeping) or a layout poorer than declared; below 1× = consecutive queries overlapped their short chains, which the model counts one after the other; limit 0 = the model reads nothing per element (the boundary curves of a closed torus), so no ratio is given; – = no model declared. Hover a cell for its bounds. The last row is each structure's worst cell.</div><table><tr><th class=l>operator</th>");
    for n in names {
        let _ = write!(h, "<th>{n}</th>");
    }
    h.push_str("</tr>");
    let sweep = |s: &str, op: Operator| {
        r.measurements.iter().find(|m| {
            m.structure == s
                && m.mesh == mesh
                && m.operator == Subject::Query(op)
                && m.kernel == Kernel::Sweep
        })
    };
    for op in Operator::ALL {
        let _ = write!(h, "<tr><th class=l>{}</th>", op.name());
        for s in names {
            let cell = match sweep(s, op) {
                Some(m) if m.status == Status::Measured => {
                    let t = ns_with_interval(m);
                    match (times_limit(m), &m.limit) {
                        (Some(x), Some(l)) => format!(
                            "<td title=\"{}\">{t}<br><span class=small>{x:.1}× limit</span></td>",
                            esc(&limit_text(l)),
                        ),
                        (None, Some(_)) => format!(
                            "<td title=\"the model reads nothing per element here\">{t}<br><span class=small>limit 0</span></td>"
                        ),
                        _ => format!("<td>{t}<br><span class=small>–</span></td>"),
                    }
                }
                Some(m) if m.status == Status::Skipped => format!(
                    "<td class=skip>skipped (est. {})</td>",
                    m.estimate_ns_per_item.map(ns).unwrap_or_default()
                ),
                _ => "<td class=skip>–</td>".into(),
            };
            h.push_str(&cell);
        }
        h.push_str("</tr>");
    }
    h.push_str("<tr><th class=l>worst × limit</th>");
    for s in names {
        let worst = Operator::ALL
            .into_iter()
            .filter_map(|op| Some((times_limit(sweep(s, op)?)?, op)))
            .max_by(|a, b| a.0.total_cmp(&b.0));
        match worst {
            Some((x, op)) => {
                let _ = write!(h, "<td><b>{x:.1}×</b> ({})</td>", op.name());
            }
            None => h.push_str("<td class=skip>–</td>"),
        }
    }
    h.push_str("</tr></table>");
}

/// Every sweep against its limit.
pub struct Sweeps;

impl Section for Sweeps {
    fn name(&self) -> &'static str {
        "sweeps"
    }

    fn needs(&self) -> Needs {
        Needs::size_sweep(SizeSweep::Full)
    }

    fn render(&self, h: &mut String, page: &Page) {
        sweeps(h, page.r, &page.names);
    }
}
