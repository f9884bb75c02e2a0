//! "libigl as reference": libigl's whole-mesh functions, timed, their answers checked.

use crate::phases::Phase;
use crate::report::format::{esc, ns};
use crate::report::section::{Needs, Page, Section, SizeSweep};
use crate::results::Results;
use std::fmt::Write;

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

    fn render(&self, h: &mut String, page: &Page) {
        libigl(h, page.r);
    }
}
