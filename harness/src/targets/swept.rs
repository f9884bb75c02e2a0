//! The Targets that hold one structure against another on a cell of the size sweep (the vertex
//! 1-ring sweep, smoothing, construction) are read from the size sweep's own rounds on the
//! largest torus, so the Targets, the chooser, the tables and the plots read the same cells:
//! in every round both structures were built afresh and ran in a random order
//! ([`crate::measuring::rounds`]), so the ratio of a round is a ratio in turns. That mesh gets the run's
//! most rounds (the pipeline's plan); the cells the targets read are kept ([`kept`]) and their
//! rounds become the target's [`Turns`] ([`turns`]), side by side. The changing workloads' targets read
//! the changing section's rounds the same way ([`changing_turns`]).

use crate::measuring::rounds::{CellKey, MeshRounds};
use crate::studies::changing::ChangingRow;
use crate::targets::plan::{Against, Cell, Turns, CHECKS, TARGETS};
use crate::targets::text::sequential_subject;
use topolab_structures::PolygonSoup;

/// The targets of two structures on a cell of the size sweep whose structures are both among
/// `names`: (cell, structure, against).
pub fn swept(names: &[String]) -> Vec<(Cell, &'static str, &'static str)> {
    let has = |s: &str| names.iter().any(|n| n == s);
    TARGETS
        .iter()
        .filter_map(|t| match t.against {
            Against::Structure(b) if has(t.structure) && has(b) => {
                sequential_subject(t.cell).map(|_| (t.cell, t.structure, b))
            }
            _ => None,
        })
        .collect()
}

/// The cells the swept targets read, by structure: their round values are kept.
pub fn kept(names: &[String]) -> Vec<(String, CellKey)> {
    let mut out: Vec<(String, CellKey)> = Vec::new();
    for (cell, a, b) in swept(names) {
        let key = sequential_subject(cell).expect("a cell of the size sweep");
        for s in [a, b] {
            if !out.contains(&(s.to_string(), key)) {
                out.push((s.into(), key));
            }
        }
    }
    out
}

/// The [`Turns`] of every swept target of `names` from the rounds of `mesh`: for each, the
/// rounds both structures ran, their ns per item side by side; a construction target between
/// a structure with input checks of its own and one without also gets the checks' rounds
/// ([`CHECKS`]), timed alone after the same builds. `seconds` is the rounds' wall time.
pub fn turns(
    names: &[String],
    mesh: &str,
    soup: &PolygonSoup,
    rounds: &MeshRounds,
    seconds: f64,
) -> Vec<Turns> {
    let mut out = Vec::new();
    for (cell, a, b) in swept(names) {
        let key = sequential_subject(cell).expect("a cell of the size sweep");
        let of = |s: &str| rounds.kept.get(&(s.to_string(), key));
        let (Some(ra), Some(rb)) = (of(a), of(b)) else {
            continue;
        };
        let checks = (cell == Cell::Construction)
            .then(|| rounds.checks.get(a))
            .flatten();
        let value = |r: &[(usize, f64)], round: usize| r.iter().find(|x| x.0 == round).map(|x| x.1);
        let (mut xa, mut xb, mut xc) = (Vec::new(), Vec::new(), Vec::new());
        for &(round, va) in ra {
            let Some(vb) = value(rb, round) else { continue };
            let vc = checks.map(|c| value(c, round));
            if vc == Some(None) {
                continue;
            }
            xa.push(va);
            xb.push(vb);
            xc.extend(vc.flatten());
        }
        let mut structures = vec![a.to_string(), b.to_string()];
        let mut ns = vec![xa, xb];
        if checks.is_some() {
            structures.push(CHECKS.into());
            ns.push(xc);
        }
        let items = match cell {
            Cell::Construction => soup.num_faces(),
            _ => soup.num_vertices(),
        };
        out.push(Turns {
            cell,
            mesh: mesh.into(),
            items,
            structures,
            ns_per_item: ns,
            warm_up: 0,
            seconds,
        });
    }
    out
}

/// The [`Turns`] of every changing target from the changing section's rounds on `mesh`: every
/// structure ran once in every round there ([`crate::studies::changing::in_rounds`]), so round `i` of
/// two rows was taken in turns.
pub fn changing_turns(rows: &[ChangingRow], mesh: &str, soup: &PolygonSoup) -> Vec<Turns> {
    let mut out = Vec::new();
    for t in TARGETS.iter() {
        let (Cell::Changing(w), Against::Structure(b)) = (t.cell, t.against) else {
            continue;
        };
        let row = |s: &str| {
            rows.iter()
                .find(|r| r.workload == w && r.mesh == mesh && r.structure == s)
        };
        let (Some(ra), Some(rb)) = (row(t.structure), row(b)) else {
            continue;
        };
        let per_face = |r: &ChangingRow| -> Vec<f64> {
            r.round_seconds
                .iter()
                .map(|s| s * 1e9 / soup.num_faces().max(1) as f64)
                .collect()
        };
        out.push(Turns {
            cell: t.cell,
            mesh: mesh.into(),
            items: soup.num_faces(),
            structures: vec![t.structure.into(), b.into()],
            ns_per_item: vec![per_face(ra), per_face(rb)],
            warm_up: 0,
            seconds: (ra.round_seconds.iter().sum::<f64>() + rb.round_seconds.iter().sum::<f64>()),
        });
    }
    out
}
