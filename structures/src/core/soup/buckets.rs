//! The edge analysis of [`Connectivity`] without sorting, for the soups constructions are
//! given: every edge with one corner, or two that run opposite ways.
//!
//! One pass over the corners in order. Each edge is filed in a bucket of its smaller vertex (a
//! linked list through the edges, as the CHE's construction files half-edges for `O[]`); a
//! corner looks in its bucket for an open edge to the same larger vertex: found, the corner
//! closes it; not found, it opens a new edge. Edges come out numbered by first
//! appearance with no renumbering, since an edge is opened by its smallest corner. O(c·k) for
//! c corners and buckets of at most k entries (a vertex's valence), against the sort's
//! O(c log c) and its 16 bytes per corner. Together with the fan walk of
//! [`Connectivity::every_vertex_one_fan`], it made every construction built from
//! [`Connectivity`] faster (vertex list, edge list, winged-edge, index and pointer half-edge,
//! explicit), measured as warm builds on the 1M-triangle torus with OpenMesh's `add_face`
//! build beside them; `topolab report --sections construction --sizes 1000000 --meshes torus`
//! measures them again.
//!
//! At the first edge it cannot store (a third corner, or two corners the same way) it gives
//! up, and the sorting analysis names the problem as it always has. It gives up too when its
//! buckets grow long ([`bucket_step_budget`]: a vertex of very high valence), and the sort
//! does the work.

use super::{Connectivity, PolygonSoup};

/// No corner: the end of a bucket, or the missing second corner of a boundary edge.
const NONE: u32 = u32::MAX;

/// How many steps along their buckets a pass over `items` corners or half-edges may take
/// before it gives up for a method that does not care about valences. A bucket holds the
/// edges from its vertex to larger ones, so a vertex of valence k costs about k²/2 steps:
/// 0.83–1.0 per corner counted on the generated tori (100k and 1M triangles), a 200 × 200
/// grid and a UV sphere whose poles have valence 200; 5·10¹¹ on a fan of a million triangles
/// around one vertex.
pub(crate) const fn bucket_step_budget(items: usize) -> usize {
    16 * items + 4096
}

/// [`Connectivity`] of a checked soup of `num_vertices` vertices (its positions' count, or
/// what it was before they were dropped) by buckets (see the module docs), or `None` when
/// some edge has more than two corners or two corners running the same way, or when the
/// buckets take more than [`bucket_step_budget`] steps (a vertex of very high valence).
pub(super) fn connectivity_by_buckets(
    soup: &PolygonSoup,
    num_vertices: usize,
) -> Option<Connectivity> {
    let nc = soup.num_corners();
    let indices = soup.indices();
    let mut corner_face = Vec::with_capacity(nc);
    let mut corner_edge = Vec::with_capacity(nc);
    let mut edge_corners: Vec<[u32; 2]> = Vec::with_capacity(nc / 2 + 1);
    // The buckets are lists of edges: head[a], the last edge filed in the bucket of vertex a;
    // filed[e], edge e's larger vertex and the edge filed before it. A step along a bucket is
    // one load, and the edge a corner finds is the index it found it at (no second table to
    // read), next to its corners in `edge_corners`.
    let mut head = vec![NONE; num_vertices];
    let mut filed: Vec<[u32; 2]> = Vec::with_capacity(nc / 2 + 1);
    let mut steps_left = bucket_step_budget(nc);
    for (f, w) in soup.offsets().windows(2).enumerate() {
        let (first, end) = (w[0] as usize, w[1] as usize);
        for c in first..end {
            corner_face.push(f as u32);
            let from = indices[c];
            let to = indices[if c + 1 == end { first } else { c + 1 }];
            let (smaller, larger) = (from.min(to), from.max(to));
            let mut at = head[smaller as usize];
            let edge = loop {
                if at == NONE {
                    // The first corner of its edge: on the boundary until another closes it.
                    let e = edge_corners.len() as u32;
                    edge_corners.push([c as u32, NONE]);
                    filed.push([larger, head[smaller as usize]]);
                    head[smaller as usize] = e;
                    break e;
                }
                let [far, link] = filed[at as usize];
                if far == larger {
                    let pair = &mut edge_corners[at as usize];
                    // A third corner, or a second running the same way as the first.
                    if pair[1] != NONE || indices[pair[0] as usize] == from {
                        return None;
                    }
                    pair[1] = c as u32;
                    break at;
                }
                at = link;
                steps_left -= 1;
                if steps_left == 0 {
                    return None;
                }
            };
            corner_edge.push(edge);
        }
    }
    edge_corners.shrink_to_fit();
    Some(Connectivity {
        edge_corners,
        corner_edge,
        corner_face,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::error::Error;
    use crate::meshes::{self, RandomMeshParams};
    use proptest::prelude::*;

    /// The two analyses agree: the same edges, numbered alike, with the same corners, on `soup`
    /// (a checked soup); where the sorting analysis finds a problem, the buckets give up.
    fn agrees_with_sorting(soup: &PolygonSoup) -> std::result::Result<(), TestCaseError> {
        let (sorted, problems) = Connectivity::analyse_by_sorting(soup, false);
        match connectivity_by_buckets(soup, soup.num_vertices()) {
            Some(b) => {
                prop_assert!(problems.is_empty(), "buckets stored {problems:?}");
                prop_assert_eq!(b.edge_corners, sorted.edge_corners);
                prop_assert_eq!(b.corner_edge, sorted.corner_edge);
                prop_assert_eq!(b.corner_face, sorted.corner_face);
            }
            None => prop_assert!(!problems.is_empty(), "buckets gave up on a good soup"),
        }
        Ok(())
    }

    #[test]
    fn buckets_agree_with_sorting_on_the_canonical_meshes() {
        let all = meshes::canonical();
        assert!(all.len() > 5);
        for m in all {
            if m.soup.check().is_ok() {
                agrees_with_sorting(&m.soup).unwrap_or_else(|e| panic!("{}: {e}", m.name));
            }
        }
    }

    #[test]
    fn buckets_give_up_where_sorting_finds_a_problem() {
        let p = vec![glam::DVec3::ZERO; 5];
        // Three triangles on edge 0-1; then two triangles running 0 -> 1 both.
        let fin = PolygonSoup::from_polygons(p.clone(), &[[0, 1, 2], [1, 0, 3], [0, 1, 4]]);
        let same = PolygonSoup::from_polygons(p, &[[0, 1, 2], [0, 1, 3]]);
        for (soup, problem) in [
            (fin, "non-manifold-edge"),
            (same, "inconsistent-orientation"),
        ] {
            assert!(connectivity_by_buckets(&soup, soup.num_vertices()).is_none());
            let e: Error = soup.connectivity().unwrap_err();
            assert_eq!(e.kind(), problem);
        }
    }

    #[test]
    fn a_vertex_of_high_valence_is_left_to_the_sort() {
        // A fan of 3000 quads around vertex 0: about 4.5M bucket steps, past the budget.
        let k = 3000u32;
        let positions = vec![glam::DVec3::ZERO; 2 * k as usize + 2];
        let faces: Vec<[u32; 4]> = (0..k)
            .map(|i| [0, 2 * i + 1, 2 * i + 2, 2 * i + 3])
            .collect();
        let soup = PolygonSoup::from_polygons(positions, &faces);
        assert!((k as usize).pow(2) / 2 > bucket_step_budget(soup.num_corners()));
        assert!(connectivity_by_buckets(&soup, soup.num_vertices()).is_none());
        let (by_sorting, problems) = Connectivity::analyse_by_sorting(&soup, true);
        assert!(problems.is_empty());
        let c = soup.connectivity().expect("a fan of quads is a manifold");
        assert_eq!(c.edge_corners, by_sorting.edge_corners);
        assert_eq!(c.corner_edge, by_sorting.corner_edge);
    }

    proptest! {
        /// Random soups, most of them bad ([`super::super::random_soups`]).
        #[test]
        fn buckets_agree_with_sorting_on_random_soups(soup in super::super::random_soups()) {
            agrees_with_sorting(&soup)?;
        }

        /// Random subsets of a grid's cells (quads, or triangle pairs), vertices relabelled
        /// and faces shuffled: every edge has one or two corners running opposite ways, so
        /// the buckets must store them all.
        #[test]
        fn buckets_store_every_subset_of_a_grid(seed in any::<u64>()) {
            let soup = meshes::random_mesh(seed, RandomMeshParams::default());
            prop_assert!(connectivity_by_buckets(&soup, soup.num_vertices()).is_some());
            agrees_with_sorting(&soup)?;
        }
    }
}
