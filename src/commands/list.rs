//! `topolab list`: the structures, the operators and each structure's theoretical cost per
//! operator, and the editing operations of the structures that implement `MeshEdit` with
//! their costs (every `EditOp` a row, the lecture's list among them; `—` where a structure
//! does not offer it), as a table or JSON.

use crate::commands::{explain_edit, list_counted};
use crate::input::Failure;
use crate::registry::{self, StructureVisitor};
use std::fmt::Write as _;
use topolab_structures::algorithms::schemes::Scheme;
use topolab_structures::{Capabilities, Deletion, EditOp, MeshEdit, MeshTopology, Operator};

/// An editable structure's declared cost per editing operation.
#[derive(serde::Serialize)]
pub(crate) struct EditRow {
    pub(crate) name: &'static str,
    pub(crate) deletion: Deletion,
    pub(crate) costs: Vec<(&'static str, &'static str)>,
    /// The declared cost of a step of each refinement and thinning ([`Scheme`]), `—` where
    /// the structure does not run it.
    pub(crate) schemes: Vec<(&'static str, String)>,
}

/// What an operation the structure does not implement shows instead of a cost.
pub(crate) const UNSUPPORTED: &str = "—";

/// An editable structure's row ([`edit_rows`], `explain`'s table).
pub(crate) struct EditRowOf;
impl registry::EditVisitor for EditRowOf {
    type Output = EditRow;
    fn visit<M: MeshEdit>(self) -> EditRow {
        EditRow {
            name: M::NAME,
            deletion: M::DELETION,
            costs: EditOp::ALL
                .iter()
                .map(|&op| {
                    let cost = if M::supports(op) {
                        M::edit_cost(op).notation()
                    } else {
                        UNSUPPORTED
                    };
                    (op.name(), cost)
                })
                .collect(),
            schemes: Scheme::ALL
                .iter()
                .map(|&s| {
                    let cost = s.declared::<M>();
                    (s.name(), cost.unwrap_or_else(|| UNSUPPORTED.to_string()))
                })
                .collect(),
        }
    }
}

/// The structures that implement `MeshEdit`, in registry order: the `[editable]` ones and
/// those with `[moves]` (explicit storage, which offers the operations on positions only: the
/// lecture's contrast, its moves are O(n)).
fn edit_rows() -> Vec<EditRow> {
    registry::NAMES
        .iter()
        .filter_map(|n| registry::visit_editable(n, EditRowOf))
        .collect()
}

#[derive(serde::Serialize)]
pub(crate) struct StructureRow {
    pub(crate) name: &'static str,
    /// The crate from crates.io and its exact version, for the Rust crates measured beside
    /// the lab (`lox 0.1.1`); absent for the lab's structures and the C++ baselines.
    #[serde(rename = "crate", skip_serializing_if = "Option::is_none")]
    pub(crate) from_crate: Option<String>,
    pub(crate) capabilities: Capabilities,
    pub(crate) costs: Vec<(&'static str, &'static str)>,
}

/// A structure's row of the list (`explain` reads its capabilities too).
pub(crate) struct Row;
impl StructureVisitor for Row {
    type Output = StructureRow;
    fn visit<M: MeshTopology>(self) -> StructureRow {
        StructureRow {
            name: M::NAME,
            from_crate: registry::peer_crate(M::NAME).map(|(c, v)| format!("{c} {v}")),
            capabilities: M::capabilities(),
            costs: Operator::ALL
                .iter()
                .map(|&op| (op.name(), M::cost(op).notation()))
                .collect(),
        }
    }
}

/// The text of `topolab list [--json] [--counted]`.
pub fn list(json: bool, counted: bool) -> Result<String, Failure> {
    let rows: Vec<StructureRow> = registry::NAMES
        .iter()
        .map(|n| registry::visit(n, Row).expect("registered"))
        .collect();
    let absent: Vec<_> = registry::absent_baselines()
        .into_iter()
        .map(|(name, why)| serde_json::json!({ "name": name, "why": why }))
        .collect();
    if json {
        let ops: Vec<_> = topolab_harness::measuring::catalogue::CATALOGUE.to_vec();
        let v = serde_json::json!({
            "structures": rows,
            "operators": ops,
            "editing": edit_rows(),
            "absent": absent,
        });
        let mut v = v;
        if counted {
            v["counted"] =
                serde_json::json!(list_counted::counted_cells(&explain_edit::editable()));
        }
        return Ok(serde_json::to_string_pretty(&v).expect("serialisable") + "\n");
    }
    let mut out = String::new();
    let _ = writeln!(out, "Structures and the theoretical cost of each operator");
    let _ = writeln!(
        out,
        "(n: elements scanned, k: local size (valence or face size), ∂n1: boundary edges)\n"
    );
    // Columns as wide as the longest structure name (`pointer-half-edge`) plus a gap.
    let width = rows
        .iter()
        .map(|r| r.name.len() + 2)
        .max()
        .unwrap_or(0)
        .max(14);
    let _ = write!(out, "{:<18}", "operator");
    for r in &rows {
        let _ = write!(out, "{:>width$}", r.name);
    }
    out.push('\n');
    for (i, spec) in topolab_harness::measuring::catalogue::CATALOGUE
        .iter()
        .enumerate()
    {
        let _ = write!(out, "{:<18}", spec.name);
        for r in &rows {
            let _ = write!(out, "{:>width$}", r.costs[i].1);
        }
        out.push('\n');
    }
    out.push('\n');
    for r in &rows {
        let c = r.capabilities;
        let _ = writeln!(
            out,
            "{:<width$} {}{}{}{}{}",
            r.name,
            if c.triangles_only {
                "triangles only"
            } else {
                "polygons"
            },
            if c.non_manifold_vertices {
                ", non-manifold vertices"
            } else {
                ""
            },
            if c.grids_only {
                ", regular grids only"
            } else {
                ""
            },
            if c.distinct_positions {
                ", distinct positions"
            } else {
                ""
            },
            r.from_crate
                .as_deref()
                .map(|c| format!("; the crate {c} from crates.io"))
                .unwrap_or_default(),
        );
    }
    for (name, why) in registry::absent_baselines() {
        let _ = writeln!(out, "{name:<width$} not in this build: {why}");
    }
    if !registry::HAS_PEERS {
        let _ = writeln!(
            out,
            "{:<width$} not in this build: built without the feature `peers`, which is on by default (`cargo build --release`)",
            "lox, baby_shark, tri-mesh"
        );
    }
    let edits = edit_rows();
    let _ = write!(
        out,
        "\nEditing operations (MeshEdit) and their cost\n{:<24}",
        "operation"
    );
    for r in &edits {
        let _ = write!(out, "{:>width$}", r.name);
    }
    out.push('\n');
    // One row: its name, then a cell per structure.
    let row = |out: &mut String, name: &str, cell: &dyn Fn(&EditRow) -> &str| {
        let _ = write!(out, "{name:<24}");
        for r in &edits {
            let _ = write!(out, "{:>width$}", cell(r));
        }
        out.push('\n');
    };
    for (i, op) in EditOp::ALL.iter().enumerate() {
        row(&mut out, op.name(), &|r| r.costs[i].1);
    }
    // The lecture's refinement and thinning: algorithms over the operations above, a step's
    // declared cost from the structure's.
    let _ = writeln!(
        out,
        "\nRefinement and thinning (the lecture's Verfeinerung, Ausdünnung), one step"
    );
    for (i, scheme) in Scheme::ALL.iter().enumerate() {
        row(&mut out, scheme.name(), &|r| r.schemes[i].1.as_str());
    }
    // The selection rows count what is selected, not a neighbourhood: their k says so.
    let _ = writeln!(
        out,
        "\n(n: elements scanned; k: the local size around the element edited (valence or face size), except in {} and {}, where k is the number of vertices selected)",
        EditOp::RotateSelection.name(),
        EditOp::ScaleSelection.name(),
    );
    let _ = writeln!(
        out,
        "(refinement and thinning: one step of √3 subdivision (a face split and 1.5 flips), of adaptive longest-edge bisection (the edge found from its ends, split, up to four heap pushes) and of decimation by quadric error (the collapse, the kept vertex's faces, O(k) heap keys); a scan in any part dominates)"
    );
    if counted {
        out += &list_counted::text(&explain_edit::editable(), width);
    } else {
        let _ = writeln!(
            out,
            "(`topolab list --counted` adds each operation's counted reads on tori of about 128 and 2,000 faces)"
        );
    }
    let _ = writeln!(out, "\noperators:");
    for spec in &topolab_harness::measuring::catalogue::CATALOGUE {
        let _ = writeln!(out, "  {:<18}{}", spec.name, spec.about);
    }
    Ok(out)
}
