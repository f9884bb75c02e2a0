//! Construction of the CHE containers: the chapter's Algorithms 1–4 as written, and the fast
//! construction of `O[]` and `EH` that produces identical containers without hashing.

use super::{fan_walk_algorithm_7, next, next_boundary_half_edge, opposite_of};
use crate::core::error::{Error, Result};
use crate::core::ids::HalfEdgeId;
use crate::core::soup::PolygonSoup;
use glam::DVec3;
use std::collections::{BTreeMap, HashMap};

/// The containers every level starts from, checked: the mesh is an oriented manifold
/// triangle mesh whose vertices are each one fan.
pub(crate) struct Checked {
    /// `G[v]`.
    pub g: Vec<DVec3>,
    /// `V[he]`.
    pub v: Vec<u32>,
    /// `O[he]`, `-1` on the boundary.
    pub o: Vec<i32>,
    /// `VH[v]`, `-1` for an unused vertex.
    pub vh: Vec<i32>,
}

/// Level 0 of a soup: `G[]` and `V[]` after refusing polygons and more half-edges or
/// vertices than `i32` can number (`O[]` and `VH[]` hold them with the chapter's `-1`).
/// Indices, repeated vertices and coordinates are checked by the caller: the chapter's
/// construction through [`PolygonSoup::check`], the fast one on its way.
fn level0_containers(
    soup: &PolygonSoup,
    structure: &'static str,
) -> Result<(Vec<DVec3>, Vec<u32>)> {
    if !soup.is_triangle_mesh() {
        let (face, corners) = soup.first_non_triangle().unwrap_or((0, 0));
        return Err(Error::NotTriangles {
            structure,
            face,
            corners,
        });
    }
    for (what, count, limit) in [
        ("half-edges", soup.num_corners(), i32::MAX as usize),
        ("vertices", soup.num_vertices(), i32::MAX as usize),
    ] {
        if count > limit {
            return Err(Error::TooLarge {
                what,
                count: count as u64,
            });
        }
    }
    Ok((soup.positions.clone(), soup.indices().to_vec()))
}

/// The exact error for a soup in which the fast construction found a non-manifold edge, an
/// orientation clash or a vertex of several fans: the shared edge analysis names the culprit.
fn refusal(soup: &PolygonSoup, structure: &'static str) -> Error {
    match soup.connectivity().and_then(|c| c.check_vertex_fans(soup)) {
        Err(e) => e,
        Ok(()) => Error::invariant(
            structure,
            "the fast construction found a non-manifold edge or vertex the edge analysis did not",
        ),
    }
}

/// Fast construction: `O[]` and `VH[]` by [`opposites_and_vertex_half_edges`] (which also
/// rejects bad indices and repeated vertices), then one fan walk per vertex to refuse
/// non-manifold vertices. O(n) with no hashing; any problem found is reported by the shared
/// checks ([`refusal`]), so both constructions name it alike.
pub(crate) fn build_fast(soup: &PolygonSoup, structure: &'static str) -> Result<Checked> {
    let (g, v) = level0_containers(soup, structure)?;
    if !g.iter().all(|p| p.is_finite()) {
        return Err(refusal(soup, structure));
    }
    let (o, vh) =
        opposites_and_vertex_half_edges(&v, g.len()).ok_or_else(|| refusal(soup, structure))?;
    if !every_vertex_one_fan(&o, &vh) {
        return Err(refusal(soup, structure));
    }
    Ok(Checked { g, v, o, vh })
}

/// The chapter's construction: the soup checked by the shared edge analysis, then
/// Algorithm 1 (`O[]` through a map) and Algorithm 3 (`VH[]`).
pub(crate) fn build_chapter(soup: &PolygonSoup, structure: &'static str) -> Result<Checked> {
    let (g, v) = level0_containers(soup, structure)?;
    soup.connectivity()?.check_vertex_fans(soup)?; // includes PolygonSoup::check
    let o = opposites_algorithm_1(&v);
    let vh = vertex_half_edges_algorithm_3(&v, &o, g.len());
    Ok(Checked { g, v, o, vh })
}

/// Algorithm 1 (§4.2) as written: a map keyed by the sorted vertex pair of each half-edge
/// holds the half-edge until its opposite arrives. Expects an oriented manifold (as checked
/// by `from_soup_chapter`); on other input the pairs it makes are meaningless but it does
/// not panic.
pub fn opposites_algorithm_1(v: &[u32]) -> Vec<i32> {
    let mut o = vec![-1i32; v.len()];
    let mut adjacency: HashMap<(u32, u32), u32> = HashMap::new();
    for he in 0..v.len() as u32 {
        let (v0, v1) = (v[he as usize], v[next(HalfEdgeId(he)).index()]);
        let v2 = (v0.min(v1), v0.max(v1));
        match adjacency.remove(&v2) {
            Some(other) => {
                o[he as usize] = other as i32;
                o[other as usize] = he as i32;
            }
            None => {
                adjacency.insert(v2, he);
            }
        }
    }
    o
}

/// The same `O[]` as [`opposites_algorithm_1`] without a map: a counting sort puts every
/// half-edge in the bucket of its smaller vertex (two sequential passes over `V[]`), and the
/// opposite half-edges are then neighbours in a bucket of a few entries, once sorted by
/// their larger vertex.
///
/// Returns `None` when a triangle names a vertex `>= num_vertices` or one vertex twice, or
/// when three half-edges share an edge or two traverse it in the same direction (a
/// non-manifold edge or inconsistent orientation).
pub fn opposites_by_buckets(v: &[u32], num_vertices: usize) -> Option<Vec<i32>> {
    pair_by_buckets(v, num_vertices, |_, _, _| {})
}

/// [`opposites_by_buckets`] that also computes Algorithm 3's `VH[]` while it pairs, without a
/// pass of its own: Algorithm 3's result does not depend on the order it meets the
/// half-edges (the largest boundary half-edge leaving `v` if any, else the smallest one), so
/// each half-edge offers itself as a key where boundary beats interior, then larger boundary
/// and smaller interior half-edges win. The `VH[]` is identical to
/// [`vertex_half_edges_algorithm_3`]'s.
pub fn opposites_and_vertex_half_edges(
    v: &[u32],
    num_vertices: usize,
) -> Option<(Vec<i32>, Vec<i32>)> {
    const BOUNDARY: u32 = 1 << 31;
    // Per vertex its best key so far; 0 (no key) for an unused vertex. Half-edges are below
    // i32::MAX, so an interior key `BOUNDARY - 1 - he` is never 0.
    let mut best = vec![0u32; num_vertices];
    let o = pair_by_buckets(v, num_vertices, |he, start, boundary| {
        let key = if boundary {
            BOUNDARY | he
        } else {
            BOUNDARY - 1 - he
        };
        let slot = &mut best[start as usize];
        *slot = (*slot).max(key);
    })?;
    let vh = best
        .into_iter()
        .map(|key| match key {
            0 => -1,
            k if k & BOUNDARY != 0 => (k & !BOUNDARY) as i32,
            k => (BOUNDARY - 1 - k) as i32,
        })
        .collect();
    Some((o, vh))
}

/// The counting sort and pairing of [`opposites_by_buckets`]; calls `visit(he, V[he],
/// is_boundary)` once per half-edge.
#[inline(always)]
fn pair_by_buckets(
    v: &[u32],
    num_vertices: usize,
    mut visit: impl FnMut(u32, u32, bool),
) -> Option<Vec<i32>> {
    let n = num_vertices as u32;
    // start[a + 2] counts the half-edges whose smaller vertex is a; after the prefix sums
    // start[a + 1] is where bucket a begins, and after the scatter (which advances it) where
    // it ends, so bucket a is start[a]..start[a + 1].
    let mut start = vec![0u32; num_vertices + 2];
    for t in v.chunks_exact(3) {
        let (a, b, c) = (t[0], t[1], t[2]);
        if a >= n || b >= n || c >= n || a == b || b == c || c == a {
            return None;
        }
        start[a.min(b) as usize + 2] += 1;
        start[b.min(c) as usize + 2] += 1;
        start[c.min(a) as usize + 2] += 1;
    }
    for a in 2..start.len() {
        start[a] += start[a - 1];
    }
    // Per smaller vertex, its half-edges keyed by their larger vertex, with a bit telling
    // whether the half-edge leaves the larger vertex: (larger << 32) | (leaves << 31) | he.
    const LEAVES_LARGER: u64 = 1 << 31;
    let mut bucket = vec![0u64; v.len()];
    for (t, corners) in v.chunks_exact(3).enumerate() {
        for i in 0..3 {
            let (a, b) = (corners[i], corners[(i + 1) % 3]);
            let slot = &mut start[a.min(b) as usize + 1];
            let leaves = if a > b { LEAVES_LARGER } else { 0 };
            bucket[*slot as usize] = ((a.max(b) as u64) << 32) | leaves | (3 * t + i) as u64;
            *slot += 1;
        }
    }
    let half_edge = |key: u64| (key & (LEAVES_LARGER - 1)) as u32;
    // Every half-edge is in exactly one bucket, so each O[he] is written below; zeroed memory
    // comes from the allocator without a pass of its own.
    let mut o = vec![0i32; v.len()];
    for a in 0..num_vertices {
        let keyed = &mut bucket[start[a] as usize..start[a + 1] as usize];
        keyed.sort_unstable();
        let mut i = 0;
        while i < keyed.len() {
            let larger = keyed[i] >> 32;
            let same = keyed[i..]
                .iter()
                .take_while(|&&x| x >> 32 == larger)
                .count();
            let start_of = |key: u64| {
                if key & LEAVES_LARGER != 0 {
                    larger as u32
                } else {
                    a as u32
                }
            };
            match same {
                1 => {
                    let h = half_edge(keyed[i]);
                    o[h as usize] = -1;
                    visit(h, start_of(keyed[i]), true);
                }
                2 => {
                    let (k0, k1) = (keyed[i], keyed[i + 1]);
                    if (k0 ^ k1) & LEAVES_LARGER == 0 {
                        return None; // both traverse the edge in the same direction
                    }
                    let (h0, h1) = (half_edge(k0), half_edge(k1));
                    o[h0 as usize] = h1 as i32;
                    o[h1 as usize] = h0 as i32;
                    visit(h0, start_of(k0), false);
                    visit(h1, start_of(k1), false);
                }
                _ => return None,
            }
            i += same;
        }
    }
    Some(o)
}

/// Algorithm 3 (§4.3): `VH[v]` is the boundary half-edge leaving `v` if there is one (so
/// `O[VH[v]] < 0` tells boundary vertices), else the first half-edge leaving it; `-1` for a
/// vertex no triangle uses. Linear, the same in both constructions.
pub fn vertex_half_edges_algorithm_3(v: &[u32], o: &[i32], num_vertices: usize) -> Vec<i32> {
    let mut vh = vec![-1i32; num_vertices];
    for (he, (&start, &opposite)) in v.iter().zip(o).enumerate() {
        let slot = &mut vh[start as usize];
        if opposite < 0 || *slot == -1 {
            *slot = he as i32;
        }
    }
    vh
}

/// `true` when, for every vertex, the walk of its star from `VH[v]` reaches every half-edge
/// leaving it: the walks together reach all `3·n2` half-edges exactly when every vertex is
/// one fan (a second fan is never reached, since a walk stays in its fan).
pub(crate) fn every_vertex_one_fan(o: &[i32], vh: &[i32]) -> bool {
    let mut reached = 0usize;
    for &start in vh.iter().filter(|&&h| h >= 0) {
        fan_walk_algorithm_7(o, HalfEdgeId(start as u32), |_| {}, |_| reached += 1);
    }
    reached == o.len()
}

/// Algorithm 2 (§4.3) as written: a map from an edge's smaller half-edge
/// `min(he, O[he])` to its properties; the lab stores no property, so the level keeps the
/// map's keys in order (an edge's property would live at its rank).
pub fn edge_map_algorithm_2(o: &[i32]) -> Vec<u32> {
    let mut eh: BTreeMap<u32, ()> = BTreeMap::new();
    for (he, &opposite) in o.iter().enumerate() {
        let h = if opposite < 0 {
            he as u32
        } else {
            (he as u32).min(opposite as u32)
        };
        eh.entry(h).or_insert(());
    }
    eh.into_keys().collect()
}

/// The keys of Algorithm 2's edge map in one pass without a map: the half-edges that are
/// the smaller of their pair, or alone on the boundary, come out already in order.
pub fn edge_map_by_scan(o: &[i32]) -> Vec<u32> {
    let mut eh = Vec::with_capacity(o.len() / 2 + 1);
    eh.extend((0..o.len() as u32).filter(|&he| o[he as usize] < 0 || he < o[he as usize] as u32));
    eh.shrink_to_fit();
    eh
}

/// Algorithm 4 (§4.4): walks each boundary curve once, stores one half-edge of curve k in
/// `CH[k - 1]` and labels the curve's half-edges `O[he] = -k` (curves numbered from 1, so
/// every boundary test stays `O[he] < 0`). The chapter's outer test `O[he] = -1` becomes
/// "boundary and not visited", since curve 1's label is also `-1`.
pub fn boundary_curves_algorithm_4(o: &mut [i32]) -> Vec<u32> {
    let mut visited = vec![false; o.len()];
    let mut ch = Vec::new();
    for he in 0..o.len() as u32 {
        if o[he as usize] >= 0 || visited[he as usize] {
            continue;
        }
        ch.push(he);
        let label = -(ch.len() as i32);
        let mut he0 = HalfEdgeId(he);
        while !visited[he0.index()] {
            visited[he0.index()] = true;
            o[he0.index()] = label;
            he0 = next_boundary_half_edge(he0, |h| opposite_of(o, h));
        }
    }
    ch.shrink_to_fit();
    ch
}
