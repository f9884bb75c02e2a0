//! The counted part of `topolab explain NAME --op OP [--structures A,B]`: the edit's container
//! reads and the elements of its records it changed, counted in the counting build of the structures
//! ([`topolab_harness::teaching::edits::counted`]), every structure side by side, then the
//! same edit on tori of growing size, where a structure that searches grows with the mesh and
//! one that reaches the element through its relations does not.

use std::fmt::Write;
use topolab_harness::teaching::edits::counted::{
    self, CountError, CountedEdit, EditCase, GROWTH_FACES,
};
use topolab_harness::teaching::edits::Subject;
use topolab_structures::{EditOp, PolygonSoup};

/// One cell: `reads / writes`, or why there is no count.
fn cell(found: &Result<CountedEdit, CountError>) -> String {
    match found {
        Ok(c) if c.refused.is_some() => format!("refused ({} reads)", c.reads),
        Ok(c) => format!("{} / {}", c.reads, c.writes),
        Err(_) => "-".to_string(),
    }
}

/// The edit counted: on which mesh, which operation on which element.
pub struct Case<'a> {
    /// The mesh.
    pub soup: &'a PolygonSoup,
    /// The mesh as the user named it.
    pub label: &'a str,
    /// The operation.
    pub op: EditOp,
    /// The element, in the mesh's numbering.
    pub subject: &'a Subject,
    /// The element in words.
    pub description: &'a str,
}

/// The counts of the `case`'s edit for every structure of `names`, and with `growth` on the
/// tori of the growth table, as `explain --op` prints them after the records.
pub fn table(names: &[&str], case: &Case, growth: bool) -> String {
    let Case {
        soup,
        label,
        op,
        subject,
        description,
    } = *case;
    let mut out = String::new();
    let w = &mut out;
    let _ = writeln!(
        w,
        "counted ({op} of {description} on {label}; reads: container reads through the structure's accessors, counted as --trace counts a query's, the element found before; writes: elements of its records changed (fields, a face's corners)):"
    );
    let width = names.iter().map(|n| n.len()).max().unwrap_or(9).max(9);
    let _ = writeln!(
        w,
        "  {:<width$}  {:>10}  {:>8}  {:>8}",
        "structure", "cost", "reads", "writes"
    );
    let mut notes = Vec::new();
    let here = EditCase::new(soup, op, subject);
    for &name in names {
        match here
            .as_ref()
            .map_err(Clone::clone)
            .and_then(|case| case.count(name))
        {
            Ok(c) => {
                let _ = writeln!(
                    w,
                    "  {:<width$}  {:>10}  {:>8}  {:>8}",
                    c.structure, c.cost, c.reads, c.writes
                );
                if let Some(why) = c.refused {
                    notes.push(format!("{name} refused it: {why}"));
                }
            }
            Err(e) => {
                let _ = writeln!(w, "  {name:<width$}  not counted: {e}");
            }
        }
    }
    for note in notes {
        let _ = writeln!(w, "  ({note})");
    }
    if !growth {
        let _ = writeln!(
            w,
            "  (--structures A,B counts them beside, and the same edit on tori of growing size)"
        );
        return out;
    }
    let _ = writeln!(
        w,
        "\nthe same {op} on tori of growing size (the same element ids; reads / writes):"
    );
    let columns: Vec<String> = GROWTH_FACES.iter().map(|f| format!("~{f} faces")).collect();
    let _ = write!(w, "  {:<width$}", "structure");
    for c in &columns {
        let _ = write!(w, "  {c:>18}");
    }
    let _ = writeln!(w);
    let mut missing = Vec::new();
    for row in counted::growth_of(op, subject, names, &GROWTH_FACES) {
        let _ = write!(w, "  {:<width$}", row.structure);
        for (faces, found) in &row.counts {
            let _ = write!(w, "  {:>18}", cell(found));
            if let Err(e) = found {
                missing.push(format!("{} on {faces} faces: {e}", row.structure));
            }
        }
        let _ = writeln!(w);
    }
    for m in missing {
        let _ = writeln!(w, "  (- {m})");
    }
    out
}
