//! "Teaching": what each structure stores for the CHE thesis chapter's Figure 4.10, and
//! edits shown record by record with the mesh before and after (`edits`).

use crate::format::esc;
use crate::page::svg;
use crate::report::section::{Page, Section};
use crate::results::{Results, TeachingEdit};
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

/// The edits of the run (`r.teaching_edits`), one block per operation: per structure, the
/// mesh before and after (the element edited marked before, the edges and vertices the edit
/// made marked after) and the records that changed, the lines `topolab explain NAME --op OP`
/// prints.
fn edits(h: &mut String, r: &Results) {
    if r.teaching_edits.is_empty() {
        return;
    }
    let _ = write!(h, "<h2>Teaching: one edit, record by record</h2><div class=read>Each edit on its default element, on three structures: the mesh before it (seen from above, vertices numbered, the element edited in red) and after it (in red what the edit made: the edges and vertices that are new, such as a flip's new edge or a collapse's edges from the vertex it kept; where none is new, the element's vertices that are left), and every record the structure wrote, old &rarr; new (<code>+</code> added, <code>-</code> removed), in the field names of its source. <code>topolab explain NAME --op OP</code> prints the same lines, from the same code, with what each edit reads.</div>");
    let mut ops: Vec<_> = r.teaching_edits.iter().map(|e| e.op).collect();
    ops.dedup();
    for op in ops {
        let of_op: Vec<&TeachingEdit> = r.teaching_edits.iter().filter(|e| e.op == op).collect();
        let first = of_op[0];
        let _ = write!(
            h,
            "<h3>{op}: {} on {}</h3><div class=teach>",
            esc(&first.subject),
            esc(&first.mesh)
        );
        for e in of_op {
            let _ = write!(
                h,
                "<div class=edit data-op=\"{op}\" data-structure=\"{}\"><h4>{}</h4>{}{}<details open><summary>the records it wrote ({} lines)</summary><pre>{}</pre></details></div>",
                esc(&e.structure),
                esc(&e.structure),
                svg::edit_picture(&e.before, &format!("before {op}"), 180.0),
                svg::edit_picture(&e.after, &format!("after {op}"), 180.0),
                e.changes.len(),
                esc(&e.changes.join("\n"))
            );
        }
        h.push_str("</div>");
    }
}

/// What each structure stores for the CHE thesis chapter's Figure 4.10, and edits record by
/// record.
pub struct Teaching;

impl Section for Teaching {
    fn name(&self) -> &'static str {
        "teaching"
    }

    fn render(&self, h: &mut String, page: &Page) {
        teaching(h, page.r);
        crate::report::reads::teaching(h);
        edits(h, page.r);
    }
}
