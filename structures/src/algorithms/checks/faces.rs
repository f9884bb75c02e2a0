//! The checks of what is missing (vertices a face names that do not exist, faces with fewer
//! than three distinct vertices, vertices no face uses) and of faces that visit a vertex
//! twice; and which faces take part in the later checks.

use super::{written_index, FindingKind, Findings};
use crate::io::RawSoup;
use std::collections::HashSet;

/// What a face is for the later checks.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(super) enum Shape {
    /// It names a vertex that does not exist: no part in the later checks.
    Missing,
    /// Fewer than three distinct vertices: no part in the later checks.
    TooFew,
    /// Usable, but it visits a vertex more than once: no part in the edge analysis.
    Repeats,
    /// Usable, each vertex visited once.
    Simple,
}

impl Shape {
    /// Usable for the later checks (no missing vertex, three distinct vertices or more).
    pub(super) fn usable(self) -> bool {
        matches!(self, Shape::Repeats | Shape::Simple)
    }
}

/// The shape of `face` in a soup of `n` vertices; `sorted` is left holding its vertices sorted
/// (when none is missing). Computed again where it is asked, so that the checks keep nothing
/// per face: a file of millions of faces costs them nothing beyond the soup.
pub(super) fn shape(face: &[u32], n: usize, sorted: &mut Vec<u32>) -> Shape {
    if face.iter().any(|&v| v as usize >= n) {
        return Shape::Missing;
    }
    sorted.clear();
    sorted.extend_from_slice(face);
    sorted.sort_unstable();
    let repeats = sorted.windows(2).filter(|w| w[0] == w[1]).count();
    match sorted.len() - repeats {
        distinct if distinct < 3 => Shape::TooFew,
        _ if repeats > 0 => Shape::Repeats,
        _ => Shape::Simple,
    }
}

/// Missing vertices and the edges that end at one, faces with too few distinct vertices,
/// faces that repeat a vertex, and unused vertices. Returns how many faces are usable.
pub(super) fn usable_faces(raw: &RawSoup, found: &mut Findings) -> usize {
    let soup = &raw.soup;
    let n = soup.num_vertices();
    let mut usable = 0;
    let mut used = vec![false; n];
    let mut edges_without_end = HashSet::new();
    let mut sorted = Vec::new();
    let ids = found.numbering();
    for (j, face) in soup.faces().enumerate() {
        // The index as the file wrote it, in the file's numbering.
        let written = |k: usize| written_index(raw, j, k).saturating_add(ids.id(0u32) as i64);
        let fid = ids.id(j as u64);
        for &v in face.iter().filter(|&&v| (v as usize) < n) {
            used[v as usize] = true;
        }
        match shape(face, n, &mut sorted) {
            Shape::Missing => {
                let missing: Vec<usize> =
                    (0..face.len()).filter(|&k| face[k] as usize >= n).collect();
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
            }
            Shape::TooFew => {
                sorted.dedup();
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
            }
            Shape::Repeats => {
                found.add(FindingKind::RepeatedVertex, || {
                    let mut repeated: Vec<u32> = sorted
                        .windows(2)
                        .filter(|w| w[0] == w[1])
                        .map(|w| w[0])
                        .collect();
                    repeated.dedup();
                    let listed = ids.list(&repeated);
                    (
                        repeated,
                        vec![j as u32],
                        format!(
                            "face {fid} visits vertices {listed} more than once: not a simple polygon"
                        ),
                    )
                });
                usable += 1;
            }
            Shape::Simple => usable += 1,
        }
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
    usable
}
