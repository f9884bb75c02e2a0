//! "Time per query against mesh size": one log-log plot per operator.

use crate::page::plot;
use crate::page::plot::Style;
use crate::report::cells::{family_of, lines, table_kernel};
use crate::report::section::{Needs, Page, Section, SizeSweep};
use crate::results::{Results, Subject};
use topolab_structures::Operator;

fn plots(h: &mut String, r: &Results, ci: &dyn Fn(&str) -> Style) {
    h.push_str("<h2>Time per query against mesh size</h2><div class=read><b>How to read them.</b> Both axes are logarithmic, so a power law is a straight line whose slope is its exponent: a flat line is a constant-time query, a line rising one decade per decade of size is a linear scan. Lines that stop early were skipped at larger sizes (too slow to measure).</div><div class=plots>");
    for op in Operator::ALL {
        let fam = family_of(op);
        let kernel = table_kernel(op);
        let series = lines(r, Subject::Query(op), kernel, fam, ci);
        h.push_str(&plot::loglog(
            &format!("{} ({fam}, {kernel})", op.name()),
            "triangles",
            "ns per query",
            "ns per query",
            &series,
        ));
    }
    h.push_str("</div>");
}

/// Time per query against mesh size, one plot per operator.
pub struct Plots;

impl Section for Plots {
    fn name(&self) -> &'static str {
        "plots"
    }

    fn needs(&self) -> Needs {
        Needs::size_sweep(SizeSweep::Full)
    }

    fn render(&self, h: &mut String, page: &Page) {
        plots(h, page.r, &|s| page.style(s));
    }
}
