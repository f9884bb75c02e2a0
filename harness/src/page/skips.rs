//! Work the report skipped, grouped for its notes: one line per reason, naming every structure
//! and mesh it applies to, instead of one line per mesh and structure (the changing workloads
//! alone used to print over sixty).

/// One skipped piece of work: `what` (e.g. a workload) of `structure` on `mesh`, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Skip {
    /// The work skipped, as the note names it (e.g. "√3 subdivision").
    pub what: String,
    /// The structure that did not run it.
    pub structure: String,
    /// The mesh it did not run on.
    pub mesh: String,
    /// Why, the same words for every mesh and structure it applies to (the grouping key).
    pub reason: String,
    /// What differs from mesh to mesh (e.g. an estimate), shown beside the mesh.
    pub detail: Option<String>,
}

/// The note lines of `skips`: one per (work, reason), in the order each first appears, each
/// naming its structures and meshes once. Structures skipped on the same meshes (and details)
/// share a clause: "√3 subdivision skipped che-l0, che-l1 on torus-4k, torus-16k: reason."
pub fn group(skips: &[Skip]) -> Vec<String> {
    // (what, reason) → [(structure, [mesh with detail])], in first-appearance order.
    type Meshes = Vec<String>;
    type ByStructure<'a> = Vec<(&'a str, Meshes)>;
    let mut groups: Vec<((&str, &str), ByStructure)> = Vec::new();
    for s in skips {
        let key = (s.what.as_str(), s.reason.as_str());
        let at = match groups.iter().position(|g| g.0 == key) {
            Some(i) => i,
            None => {
                groups.push((key, Vec::new()));
                groups.len() - 1
            }
        };
        let mesh = match &s.detail {
            Some(d) => format!("{} ({d})", s.mesh),
            None => s.mesh.clone(),
        };
        let by_structure = &mut groups[at].1;
        match by_structure.iter_mut().find(|e| e.0 == s.structure) {
            Some(e) => {
                if !e.1.contains(&mesh) {
                    e.1.push(mesh);
                }
            }
            None => by_structure.push((s.structure.as_str(), vec![mesh])),
        }
    }
    groups
        .into_iter()
        .map(|((what, reason), by_structure)| {
            // Structures with the same meshes share one clause.
            let mut clauses: Vec<(Vec<&str>, Meshes)> = Vec::new();
            for (structure, meshes) in by_structure {
                match clauses.iter_mut().find(|c| c.1 == meshes) {
                    Some(c) => c.0.push(structure),
                    None => clauses.push((vec![structure], meshes)),
                }
            }
            let clauses: Vec<String> = clauses
                .iter()
                .map(|(structures, meshes)| {
                    format!("{} on {}", structures.join(", "), meshes.join(", "))
                })
                .collect();
            format!("{what} skipped {}: {reason}.", clauses.join("; "))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn skip(what: &str, structure: &str, mesh: &str, reason: &str) -> Skip {
        Skip {
            what: what.into(),
            structure: structure.into(),
            mesh: mesh.into(),
            reason: reason.into(),
            detail: None,
        }
    }

    #[test]
    fn grouping_names_every_mesh_and_structure_once_per_reason() {
        let meshes = ["torus-4k", "torus-16k", "torus-1M"];
        let levels = ["che-l0", "che-l1", "che-l2", "che-l3"];
        let mut skips = Vec::new();
        for m in meshes {
            for s in levels {
                skips.push(skip("√3 subdivision", s, m, "O(n) per edit"));
            }
            skips.push(skip(
                "√3 subdivision",
                "vertex-list",
                m,
                "no stable edge ids",
            ));
        }
        // A duplicate, and one structure on fewer meshes.
        skips.push(skip(
            "√3 subdivision",
            "che-l0",
            "torus-4k",
            "O(n) per edit",
        ));
        skips.push(Skip {
            detail: Some("about 25 s".into()),
            ..skip("collapse test", "edge-list", "torus-1M", "too slow")
        });
        let lines = group(&skips);
        assert_eq!(lines.len(), 3, "{lines:#?}");
        assert_eq!(
            lines[0],
            "√3 subdivision skipped che-l0, che-l1, che-l2, che-l3 on torus-4k, torus-16k, torus-1M: O(n) per edit."
        );
        assert_eq!(
            lines[1],
            "√3 subdivision skipped vertex-list on torus-4k, torus-16k, torus-1M: no stable edge ids."
        );
        assert_eq!(
            lines[2],
            "collapse test skipped edge-list on torus-1M (about 25 s): too slow."
        );
        // Every structure and mesh of the input is named, each once per line.
        for s in &skips {
            let line = lines
                .iter()
                .find(|l| l.starts_with(&s.what) && l.ends_with(&format!("{}.", s.reason)))
                .expect("a line per reason");
            assert_eq!(
                line.matches(&format!("{},", s.structure)).count()
                    + line.matches(&format!("{} on", s.structure)).count(),
                1,
                "{line}"
            );
            assert!(line.contains(&s.mesh), "{line}");
        }
    }

    #[test]
    fn structures_on_different_meshes_get_their_own_clause() {
        let skips = [
            skip("collapse test", "edge-list", "torus-64k", "too slow"),
            skip("collapse test", "vertex-list", "torus-16k", "too slow"),
            skip("collapse test", "vertex-list", "torus-64k", "too slow"),
        ];
        assert_eq!(
            group(&skips),
            ["collapse test skipped edge-list on torus-64k; vertex-list on torus-16k, torus-64k: too slow."]
        );
    }
}
