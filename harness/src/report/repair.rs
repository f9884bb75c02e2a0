//! The real meshes the structures refuse as read, repaired for the report: a mesh that the
//! structures needing an oriented manifold refuse (inconsistent orientation, a non-manifold
//! edge or vertex) would give a row of refusals; `topolab repair`'s steps make it one they
//! store, and the report measures that, marked repaired.

use topolab_structures::repair::{repair, RepairLog, Repaired, Step};
use topolab_structures::PolygonSoup;

/// Why the structures that need an oriented manifold refuse `soup` (the edge analysis every
/// structure with explicit adjacency runs, and the vertex fans), if they do.
fn refusal(soup: &PolygonSoup) -> Option<topolab_structures::Error> {
    soup.connectivity()
        .and_then(|c| c.check_vertex_fans(soup))
        .err()
}

/// `soup` as read when the structures store it, else its repair with every step and what
/// changed; a note in `notes` says which, and why.
pub fn measurable(
    name: &str,
    soup: PolygonSoup,
    notes: &mut Vec<String>,
) -> (PolygonSoup, Option<RepairLog>) {
    let Some(why) = refusal(&soup) else {
        return (soup, None);
    };
    let Repaired { soup: fixed, log } = repair(soup.clone(), &Step::ALL);
    match refusal(&fixed) {
        None => {
            notes.push(format!(
                "{name}: refused as read ({}), measured repaired: {}.",
                why.kind(),
                log.lines().join("; ")
            ));
            (fixed, Some(log))
        }
        Some(still) => {
            notes.push(format!(
                "{name}: refused as read ({why}) and after repair ({still}): measured as read."
            ));
            (soup, None)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::meshes;

    #[test]
    fn only_refused_meshes_are_repaired() {
        let mut notes = Vec::new();
        let torus = meshes::torus(6, 4);
        let (same, log) = measurable("torus", torus.clone(), &mut notes);
        assert_eq!((same, log), (torus, None));
        assert!(notes.is_empty());
        let bowtie = meshes::bowtie();
        let (fixed, log) = measurable("bowtie", bowtie, &mut notes);
        assert!(refusal(&fixed).is_none());
        assert_eq!(log.map(|l| l.new_vertices()), Some(1));
        assert!(
            notes[0].starts_with("bowtie: refused as read (non-manifold-vertex)"),
            "{notes:?}"
        );
    }
}
