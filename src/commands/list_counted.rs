//! `topolab list --counted`: beside the declared cost of each editing operation, its count:
//! the container reads each structure makes for it on tori of about 128 and 2,000 faces (the
//! same element ids, the element of `explain --op`'s default), counted by the counting build
//! of the structures ([`topolab_harness::teaching::edits::counted`]), so that a declared O(n)
//! shows as reads that grow 16 times with the faces and an O(1) or O(k) as reads that stay.

use std::fmt::Write as _;
use topolab_harness::teaching::edits::counted::{growth_of, CountError, CountedEdit};
use topolab_harness::teaching::edits::default_case;
use topolab_structures::EditOp;

/// The tori the counts are made on: about 128 and 2,000 triangles (16 times as many). The
/// third size of `explain`'s growth table (32,000) is left out: an O(n²) smoothing there
/// counts billions of reads.
pub const LIST_FACES: [usize; 2] = [128, 2_000];

/// One cell of the counted table: an operation on a structure, its reads on each torus.
#[derive(serde::Serialize)]
pub(crate) struct CountedCell {
    pub(crate) op: &'static str,
    pub(crate) structure: String,
    /// The structure's declared cost of the operation (`None` where nothing was counted).
    pub(crate) declared: Option<String>,
    /// Declared a scan (O(n) or more) but read about the same on both tori: the scan reads
    /// its containers directly, which the count does not see (a count is at most the reads).
    pub(crate) scan_not_counted: bool,
    /// Per torus: its faces and the reads, or why there is no count.
    pub(crate) reads: Vec<(usize, Result<u64, String>)>,
}

/// Every operation counted on every structure of `names`.
pub(crate) fn counted_cells(names: &[&str]) -> Vec<CountedCell> {
    let mut out = Vec::new();
    for op in EditOp::ALL {
        let subject = default_case(op).choice.success;
        let rows = match &subject {
            Some(subject) => growth_of(op, subject, names, &LIST_FACES),
            None => Vec::new(),
        };
        for (i, &name) in names.iter().enumerate() {
            let reads: Vec<(usize, Result<u64, String>)> = match rows.get(i) {
                Some(row) => row
                    .counts
                    .iter()
                    .map(|(faces, found)| (*faces, reads_of(found)))
                    .collect(),
                None => vec![(0, Err("no default element".to_string()))],
            };
            let declared = rows.get(i).and_then(|r| r.cost()).map(str::to_string);
            let scan = rows.get(i).is_some_and(|r| r.scans());
            let counts: Vec<u64> = reads.iter().filter_map(|(_, r)| r.clone().ok()).collect();
            let flat = counts.len() == LIST_FACES.len()
                && counts.windows(2).all(|w| w[1] < 2 * w[0].max(1));
            out.push(CountedCell {
                op: op.name(),
                structure: name.to_string(),
                scan_not_counted: scan && flat,
                declared,
                reads,
            });
        }
    }
    out
}

fn reads_of(found: &Result<CountedEdit, CountError>) -> Result<u64, String> {
    match found {
        Ok(c) if c.refused.is_none() => Ok(c.reads),
        Ok(c) => Err(format!("refused: {}", c.refused.as_deref().unwrap_or(""))),
        Err(CountError::NotOffered(_)) => Err("not offered".to_string()),
        Err(e) => Err(e.to_string()),
    }
}

/// The counted table as text: an operation a row, a structure a column, each cell the reads
/// on the two tori (`33 → 33`), `—` where the structure does not offer the operation, `–`
/// where the torus does not take the default element (the notes below say why).
pub(crate) fn text(names: &[&str], width: usize) -> String {
    let cells = counted_cells(names);
    let mut out = String::new();
    let _ = write!(
        out,
        "\nEditing operations counted: container reads on tori of about {} and {} faces (the same element ids)\n{:<24}",
        LIST_FACES[0], LIST_FACES[1], "operation"
    );
    for n in names {
        let _ = write!(out, "{n:>width$}");
    }
    out.push('\n');
    let mut notes: Vec<String> = Vec::new();
    for op in EditOp::ALL {
        let _ = write!(out, "{:<24}", op.name());
        for c in cells.iter().filter(|c| c.op == op.name()) {
            let counts: Result<Vec<u64>, &String> =
                c.reads.iter().map(|(_, r)| r.as_ref().copied()).collect();
            let cell = match counts {
                Ok(r) => {
                    let mark = if c.scan_not_counted { "*" } else { "" };
                    r.iter().map(u64::to_string).collect::<Vec<_>>().join(" → ") + mark
                }
                Err(why) if why == "not offered" => "—".to_string(),
                Err(why) => {
                    // One note an operation: its default element, chosen on the mesh of
                    // `explain --op`'s default, is not one the torus takes (the first reason).
                    let prefix = format!("{op}: ");
                    if !notes.iter().any(|n| n.starts_with(&prefix)) {
                        notes.push(format!("{prefix}{why}"));
                    }
                    "–".to_string()
                }
            };
            let _ = write!(out, "{cell:>width$}");
        }
        out.push('\n');
    }
    let _ = writeln!(
        out,
        "(reads through each structure's accessors, the element found before, as `explain --op OP --structures A,B` counts them; — not offered; – the default element of `explain --op` is not one a torus takes, the first structure's reason:)"
    );
    let _ = writeln!(
        out,
        "(* declared a scan, yet the count does not grow with the mesh: that scan reads its containers directly, without an accessor, which the count does not see; a count is at most what an edit reads)"
    );
    for n in notes {
        let _ = writeln!(out, "  – {n}");
    }
    out
}
