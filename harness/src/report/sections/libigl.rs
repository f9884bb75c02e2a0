//! "libigl as reference": libigl's whole-mesh functions, timed, their answers checked.

use crate::report::format::{esc, ns};
use crate::results::Results;
use std::fmt::Write;

pub(crate) fn libigl(h: &mut String, r: &Results) {
    if r.libigl.is_empty() {
        return;
    }
    h.push_str("<h2>libigl as reference</h2><div class=read><b>How to read it.</b> libigl answers these relations by building whole-mesh adjacency arrays (not by per-query circulation), timed inside Python around each call (best of several, one thread). Its checksum is compared with the lab's answer for the same operator.</div><table><tr><th class=l>mesh</th><th class=l>operator</th><th class=l>libigl function</th><th>ns per element</th><th>checksum agrees</th></tr>");
    for l in &r.libigl {
        let _ = write!(h, "<tr><td class=l>{}</td><td class=l>{}</td><td class=l>{}</td><td>{}</td><td class={}>{}</td></tr>", esc(&l.mesh), l.operator, l.function, ns(l.ns_per_item), if l.agrees { "ok" } else { "bad" }, if l.agrees { "yes" } else { "no" });
    }
    h.push_str("</table>");
}
