//! The checks of what is missing (vertices a face names that do not exist, faces with fewer
//! than three distinct vertices, vertices no face uses) and of faces that visit a vertex
//! twice; and which faces take part in the later checks.

use super::{written_index, FindingKind, Findings};
use crate::io::RawSoup;
use std::collections::HashSet;

/// Per face of the soup: usable for the later checks (no missing vertex, three distinct
/// vertices or more), and visiting a vertex more than once.
pub(super) struct Faces {
    pub usable: Vec<bool>,
    pub repeats: Vec<bool>,
}

/// Missing vertices and the edges that end at one, faces with too few distinct vertices,
/// faces that repeat a vertex, and unused vertices.
pub(super) fn usable_faces(raw: &RawSoup, found: &mut Findings) -> Faces {
    let soup = &raw.soup;
    let n = soup.num_vertices();
    let mut usable = vec![false; soup.num_faces()];
    let mut repeats = vec![false; soup.num_faces()];
    let mut used = vec![false; n];
    let mut edges_without_end = HashSet::new();
    let mut sorted = Vec::new();
    let ids = found.numbering();
    for (j, face) in soup.faces().enumerate() {
        // The index as the file wrote it, in the file's numbering.
        let written = |k: usize| written_index(raw, j, k).saturating_add(ids.id(0u32) as i64);
        let fid = ids.id(j as u64);
        let missing: Vec<usize> = (0..face.len()).filter(|&k| face[k] as usize >= n).collect();
        for &v in face.iter().filter(|&&v| (v as usize) < n) {
            used[v as usize] = true;
        }
        if !missing.is_empty() {
            found.add(FindingKind::MissingVertex, || {
                let indices: Vec<String> = missing
                    .iter()
                    .take(super::LISTED_IDS)
                    .map(|&k| written(k).to_string())
                    .collect();
                let more = match missing.len() {
                    m if m > super::LISTED_IDS => format!(", ... ({m} in all)"),
                    _ => String::new(),
                };
                (
                    vec![],
                    vec![j as u32],
                    format!(
                        "face {fid} refers to vertices [{}{more}], but there are {n} vertices",
                        indices.join(", ")
                    ),
                )
            });
            for &k in &missing {
                let len = face.len();
                for (a, b) in [((k + len - 1) % len, k), (k, (k + 1) % len)] {
                    let (wa, wb) = (written(a), written(b));
                    if a != b && edges_without_end.insert((wa.min(wb), wa.max(wb))) {
                        found.add(FindingKind::EdgeWithoutEndPoint, || {
                            (
                                vec![],
                                vec![j as u32],
                                format!("edge ({wa}, {wb}) of face {fid} has an end point that does not exist"),
                            )
                        });
                    }
                }
            }
            continue;
        }
        sorted.clear();
        sorted.extend_from_slice(face);
        sorted.sort_unstable();
        let mut repeated: Vec<u32> = sorted
            .windows(2)
            .filter(|w| w[0] == w[1])
            .map(|w| w[0])
            .collect();
        repeated.dedup();
        sorted.dedup();
        if sorted.len() < 3 {
            found.add(FindingKind::TooFewVertices, || {
                (
                    sorted.clone(),
                    vec![j as u32],
                    format!(
                        "face {fid} has {} corners on {} distinct vertices {}; a face needs three",
                        face.len(),
                        sorted.len(),
                        ids.list(&sorted)
                    ),
                )
            });
            continue;
        }
        if !repeated.is_empty() {
            found.add(FindingKind::RepeatedVertex, || {
                let listed = ids.list(&repeated);
                (
                    repeated,
                    vec![j as u32],
                    format!(
                        "face {fid} visits vertices {listed} more than once: not a simple polygon"
                    ),
                )
            });
            repeats[j] = true;
        }
        usable[j] = true;
    }
    for v in (0..n).filter(|&v| !used[v]) {
        found.add(FindingKind::UnusedVertex, || {
            (
                vec![v as u32],
                vec![],
                format!("vertex {} is used by no face", ids.id(v as u64)),
            )
        });
    }
    Faces { usable, repeats }
}
