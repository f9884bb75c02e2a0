//! The editing part of `topolab explain NAME`: for a structure that implements `MeshEdit`,
//! how it deletes and the declared cost of each editing operation, beside the records the
//! rest of `explain` prints (the same costs as `topolab list`).

use super::list::EditRowOf;
use crate::registry;
use std::fmt::Write as _;
use topolab_structures::Deletion;

/// The lines `explain` appends for the structure called `name`.
pub fn edit_costs(name: &str) -> String {
    let mut out = String::new();
    let Some(row) = registry::visit_editable(name, EditRowOf) else {
        let _ = writeln!(out, "\nediting: {name} does not implement MeshEdit");
        return out;
    };
    let deletion = match row.deletion {
        Deletion::Marked => "deleted elements stay, marked, until garbage collection",
        Deletion::Removed => "deleted elements leave at once",
        Deletion::LastMoves => {
            "deleted faces and edges leave at once, the last one taking the slot; deleted vertices stay, marked, until garbage collection"
        }
        Deletion::Compacted => {
            "deleted triangles leave at once, the arrays compacted (the last triangle taking a deleted one's slot, or the triangles after a deleted vertex's star shifting down), so triangle and half-edge ids change; deleted vertices stay, marked, until garbage collection"
        }
    };
    let _ = writeln!(out, "\nediting (MeshEdit): {deletion}");
    for (op, cost) in &row.costs {
        let _ = writeln!(out, "  {op:<20}{cost}");
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn explain_shows_the_declared_edit_costs_of_editable_structures_only() {
        let winged = edit_costs("winged-edge");
        assert!(winged.contains("flip-edge           O(k)"), "{winged}");
        assert!(winged.contains("weld-vertices       O(k)"), "{winged}");
        let list = edit_costs("vertex-list");
        assert!(list.contains("collapse-edge       O(k·n)"), "{list}");
        let half = edit_costs("index-half-edge");
        assert!(half.contains("weld-vertices       O(k)"), "{half}");
        // The link condition looks each neighbour of one end up around the other.
        assert!(half.contains("collapse-edge       O(k²)"), "{half}");
        assert!(winged.contains("collapse-edge       O(k²)"), "{winged}");
        let che = edit_costs("che-l2");
        assert!(che.contains("flip-edge           O(n)"), "{che}");
        assert!(
            che.contains("deleted triangles leave at once")
                && !che.contains("deleted elements stay"),
            "the CHE compacts its triangles at once, it marks only vertices: {che}"
        );
        assert!(che.contains("weld-vertices       O(n)"), "a rebuild: {che}");
        assert!(edit_costs("regular-grid").contains("does not implement MeshEdit"));
        // The C++ baselines edit through their own Euler operations, with declared costs.
        for name in crate::registry::CPP_BASELINES {
            let text = edit_costs(name);
            if crate::registry::NAMES.contains(&name) {
                assert!(text.contains("split-edge          O(1)"), "{text}");
                assert!(text.contains("stay, marked"), "{text}");
            }
        }
    }
}
