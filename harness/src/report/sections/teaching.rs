//! "Teaching": what each structure stores for the CHE thesis chapter's Figure 4.10, edits
//! shown record by record with the mesh before and after (`edits`), and the same edits
//! counted on tori of growing size beside each structure's declared cost (`counted`).

use crate::format::esc;
use crate::page::svg;
use crate::report::section::{Page, Section};
use crate::results::{Results, TeachingEdit};
use crate::teaching::edits::counted::{counted_structures, growth_of, CountError, GROWTH_FACES};
use crate::teaching::edits::{default_case, TAUGHT};
use std::fmt::Write;

/// The taught edits counted on tori of growing size, every structure beside its declared
/// cost: the same counts as `topolab explain NAME --op OP --structures A,B`, from the same
/// code. Counts, not times: the same on every machine.
fn counted(h: &mut String) {
    let names = counted_structures();
    let sizes: Vec<String> = GROWTH_FACES.iter().map(|f| format!("~{f} faces")).collect();
    let _ = write!(h, "<h2>Teaching: one edit, counted as the mesh grows</h2><div class=read>Each edit on the same element ids of tori of about {}: the container reads it makes through the structure's accessors (counted as a query's reads are, the element found before), then the fields of its records it changed, beside the cost the structure declares. A structure that reaches the element through its relations reads the same at every size; one that searches, or rebuilds a container, reads more as the mesh grows. <code>topolab explain NAME --op OP --structures A,B</code> prints the same counts, from the same code.</div>", sizes.join(", "));
    for op in TAUGHT {
        let Some(subject) = default_case(op).choice.success else {
            continue;
        };
        let _ = write!(
            h,
            "<h3>{op}</h3><table><tr><th class=l>structure</th><th>declared</th>"
        );
        for s in &sizes {
            let _ = write!(h, "<th>reads / writes, {s}</th>");
        }
        h.push_str("</tr>");
        for row in growth_of(op, &subject, &names, &GROWTH_FACES) {
            let _ = write!(
                h,
                "<tr><td class=l>{}</td><td>{}</td>",
                esc(&row.structure),
                esc(row.cost().unwrap_or("—"))
            );
            for (_, found) in &row.counts {
                let cell = match found {
                    Ok(c) if c.refused.is_some() => format!("refused ({} reads)", c.reads),
                    Ok(c) => format!("{} / {}", c.reads, c.writes),
                    Err(CountError::NotOffered(_)) => "not offered".to_string(),
                    Err(e) => format!("– ({})", esc(&e.to_string())),
                };
                let _ = write!(h, "<td>{cell}</td>");
            }
            h.push_str("</tr>");
        }
        h.push_str("</table>");
    }
}

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
        counted(h);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_taught_edits_are_counted_on_every_structure_beside_their_cost() {
        let mut h = String::new();
        counted(&mut h);
        let names = counted_structures();
        assert!(names.contains(&"explicit") && names.contains(&"index-half-edge"));
        for op in TAUGHT {
            let table = h
                .split(&format!("<h3>{op}</h3>"))
                .nth(1)
                .and_then(|t| t.split("</table>").next())
                .unwrap_or_else(|| panic!("no table for {op}"));
            for name in &names {
                let row = table
                    .split("<tr>")
                    .find(|r| r.starts_with(&format!("<td class=l>{name}</td>")))
                    .unwrap_or_else(|| panic!("{op}: no row for {name}"));
                // Explicit storage moves vertices only: none of the taught edits is offered.
                if *name == "explicit" {
                    assert!(row.contains("not offered"), "{op} {name}: {row}");
                } else {
                    assert!(
                        !row.contains("not offered") && !row.contains("–"),
                        "{op} {name}: {row}"
                    );
                }
            }
        }
        // The lesson: the vertex list's flip reads grow with the mesh, the half-edge's do not.
        let reads = |name: &str| -> Vec<u64> {
            let table = h.split("<h3>flip-edge</h3>").nth(1).unwrap();
            let row = table
                .split("<tr>")
                .find(|r| r.starts_with(&format!("<td class=l>{name}</td>")))
                .unwrap();
            row.split("<td>")
                .skip(2)
                .filter_map(|c| c.split(" / ").next()?.parse().ok())
                .collect()
        };
        let (list, half) = (reads("vertex-list"), reads("index-half-edge"));
        assert_eq!(list.len(), GROWTH_FACES.len(), "{h}");
        assert!(list[2] >= 8 * list[1] && list[1] >= 8 * list[0], "{list:?}");
        assert_eq!(half.iter().min(), half.iter().max(), "{half:?}");
    }
}
