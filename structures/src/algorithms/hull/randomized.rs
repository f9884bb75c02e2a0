//! The randomized incremental algorithm of the lecture on 3D convex hulls, with the conflict graph:
//! expected O(n log n).
//!
//! The points are processed in a uniformly random order (a seeded ChaCha8 permutation, so a
//! run is reproducible). The bipartite conflict graph G links each point p not yet inserted
//! with the faces of the current hull it sees (`Volume6 > 0`):
//!
//! | seed | here | meaning |
//! |---|---|---|
//! | P_conflito(f) | `face_conflicts[f]` | the points that see face f |
//! | F_conflito(p) | `point_conflicts[p]` | the faces p sees |
//!
//! Inserting pk: F_conflito(pk) are the faces to remove (empty: pk is inside, skip it). The
//! faces in pk's plane (`Volume6 = 0`) next to them are removed too, as in
//! [`super::incremental`] (the degenerate case the lecture excludes). For each horizon edge e,
//! between the removed face f1 and the kept face f2, the cone face f = (e, pk) gets
//! P_conflito(f) ⊆ P(e) = P_conflito(f1) ∪ P_conflito(f2), each candidate tested once with
//! `Volume6`. (The inclusion also holds when f1 is only coplanar with pk: the plane of f is
//! turned from f1's plane away from the wedge between f1 and f2, or equals f1's plane.)
//!
//! Points are named by their rank in the insertion order and every conflict list is kept in
//! increasing rank, so P(e) is a merge of two sorted lists.
//!
//! Removing a face from G: its own list is freed; the points' lists keep the dead id (face
//! ids are never reused) and skip it when read, which keeps removal O(1) per face. The
//! expected number of faces created is at most 6n − 20 (the lecture's lemma); [`super::Hull`]
//! reports the count.

use super::incremental::{cover_slots, face_volume6, replace_visible_by_cone, triangle};
use super::predicates::{find_simplex, volume6};
use crate::core::error::Result;
use crate::core::ids::{FaceId, VertexId};
use crate::core::topology::MeshTopology;
use crate::families::edge_lists::winged_edge::WingedEdge;
use glam::DVec3;
use rand::seq::SliceRandom;
use rand::SeedableRng;

/// The randomized incremental hull of the distinct points `distinct`, in the order of a
/// permutation drawn from `seed`. Returns the hull and the number of faces created.
pub(super) fn randomized(
    points: &[DVec3],
    distinct: &[u32],
    seed: u64,
) -> Result<(WingedEdge, usize)> {
    let mut order = distinct.to_vec();
    order.shuffle(&mut rand_chacha::ChaCha8Rng::seed_from_u64(seed));
    let simplex = find_simplex(points, &order)?;
    let (mut mesh, mut created) = super::start_with_tetrahedron(points, simplex)?;
    // Points still to insert, in insertion order; a point is named by its rank here. Conflict
    // lists hold ranks in increasing order, so P(e) is a merge of two sorted lists (no
    // duplicate marks) and reads `ordered` front to back instead of jumping around `points`.
    let rest: Vec<u32> = order.into_iter().filter(|k| !simplex.contains(k)).collect();
    let ordered: Vec<DVec3> = rest.iter().map(|&k| points[k as usize]).collect();

    // face_conflicts[f]: P_conflito(f); point_conflicts[rank]: F_conflito(p), dead ids skipped.
    let mut face_conflicts: Vec<Vec<u32>> = vec![Vec::new(); mesh.face_slots()];
    let mut point_conflicts: Vec<Vec<FaceId>> = vec![Vec::new(); rest.len()];
    let initial: Vec<FaceId> = mesh.live_faces().collect();
    for (rank, &q) in ordered.iter().enumerate() {
        for &f in &initial {
            if face_volume6(&mesh, f, q) > 0.0 {
                face_conflicts[f.index()].push(rank as u32);
                point_conflicts[rank].push(f);
            }
        }
    }

    let mut is_visible = Vec::new();
    let mut visible = Vec::new();
    let mut horizon = Vec::new();
    for (rank, &k) in rest.iter().enumerate() {
        let p = ordered[rank];
        let conflicts = std::mem::take(&mut point_conflicts[rank]);
        cover_slots(&mut is_visible, &mesh);
        visible.clear();
        for f in conflicts.into_iter().filter(|&f| mesh.is_face_live(f)) {
            is_visible[f.index()] = true;
            visible.push(f);
        }
        if visible.is_empty() {
            continue; // pk sees no face: it is inside P(k−1) or on its boundary.
        }
        // The faces in pk's plane next to the visible ones (a walk, since they touch them).
        let mut next = 0;
        while next < visible.len() {
            let (_, neighbours) = triangle(&mesh, visible[next]);
            next += 1;
            for g in neighbours {
                if g.is_valid() && !is_visible[g.index()] && face_volume6(&mesh, g, p) == 0.0 {
                    is_visible[g.index()] = true;
                    visible.push(g);
                }
            }
        }
        replace_visible_by_cone(
            &mut mesh,
            &visible,
            &mut is_visible,
            VertexId(k),
            &mut horizon,
        )?;
        created += horizon.len();
        face_conflicts.resize(mesh.face_slots(), Vec::new());
        for h in &horizon {
            let [a, b] = [h.a, h.b].map(|v| mesh.position(v));
            let mut new_conflicts = Vec::new();
            // pk itself is in the removed face's list; every earlier point has left G.
            merge_sorted(
                &face_conflicts[h.removed.index()],
                &face_conflicts[h.kept.index()],
                |q| {
                    if q as usize != rank && volume6(a, b, p, ordered[q as usize]) > 0.0 {
                        new_conflicts.push(q);
                        point_conflicts[q as usize].push(h.created);
                    }
                },
            );
            face_conflicts[h.created.index()] = new_conflicts;
        }
        for f in &visible {
            face_conflicts[f.index()] = Vec::new();
        }
    }
    Ok((mesh, created))
}

/// Calls `f` once for each value of the union of the increasing lists `a` and `b`, in
/// increasing order.
fn merge_sorted(a: &[u32], b: &[u32], mut f: impl FnMut(u32)) {
    let (mut i, mut j) = (0, 0);
    loop {
        let next = match (a.get(i), b.get(j)) {
            (Some(&x), Some(&y)) => x.min(y),
            (Some(&x), None) => x,
            (None, Some(&y)) => y,
            (None, None) => return,
        };
        i += usize::from(a.get(i) == Some(&next));
        j += usize::from(b.get(j) == Some(&next));
        f(next);
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn merge_sorted_gives_the_union_once() {
        let mut out = Vec::new();
        super::merge_sorted(&[1, 4, 6, 9], &[2, 4, 9, 12], |x| out.push(x));
        assert_eq!(out, [1, 2, 4, 6, 9, 12]);
        out.clear();
        super::merge_sorted(&[], &[3], |x| out.push(x));
        assert_eq!(out, [3]);
    }
}
