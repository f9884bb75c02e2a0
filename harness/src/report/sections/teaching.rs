//! "Teaching": what each structure stores for the CHE thesis chapter's Figure 4.10.

use crate::report::format::esc;
use crate::report::section::{Page, Section};
use crate::results::Results;
use crate::svg;
use std::fmt::Write;

fn teaching(h: &mut String, r: &Results) {
    let _ = write!(h, "<h2>Teaching: what each structure stores for Figure 4.10</h2><div class=read>The CHE thesis chapter's example, a tetrahedron with one face removed: 4 vertices, 3 triangles, 9 half-edges, 6 edges, 1 boundary curve. Triangle t owns half-edges 3t, 3t+1, 3t+2. Open a structure to see its records, field by field, as <code>topolab explain NAME</code> prints them.</div><div class=teach><div>{}</div><div>", svg::figure_4_10());
    for t in &r.teaching {
        let _ = write!(
            h,
            "<details><summary>{}</summary><pre>{}</pre></details>",
            t.structure,
            esc(&t.text)
        );
    }
    h.push_str("</div></div>");
}

/// What each structure stores for the CHE thesis chapter's Figure 4.10.
pub struct Teaching;

impl Section for Teaching {
    fn name(&self) -> &'static str {
        "teaching"
    }

    fn render(&self, h: &mut String, page: &Page) {
        teaching(h, page.r);
        crate::reads::section::teaching(h);
    }
}
