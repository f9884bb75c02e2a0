//! Construction of the CHE containers: the chapter's Algorithms 1–4 as written, and the fast
//! construction of `O[]` and `EH` that produces identical containers without hashing.
//!
//! ## Where the fast construction's time goes
//!
//! Level 1's fast build ([`build_fast`]) is five passes:
//!
//! 1. copy `G[]` and check that it is finite;
//! 2. copy `V[]`;
//! 3. pair `O[]` ([`opposites_by_buckets`]);
//! 4. `VH[]` (Algorithm 3, [`vertex_half_edges_algorithm_3`]);
//! 5. the one-fan walk ([`every_vertex_one_fan`]).
//!
//! `cargo run --release --example build_sweep -- 1000000 torus 9 all passes` times them pass
//! by pass, each in turns with the whole build and OpenMesh's `add_face` build (OpenMesh
//! compiled from its pinned source at -O3 without its assertions, as the lab builds it). The
//! pairing is the largest of the five.
//!
//! The pairing waits on its bucket walk: each step loads the node of the half-edge that
//! joined the bucket before, and the twin of an edge between two strips of the torus arrives
//! a whole strip later, its node tens of KB back, out of L1. Measured against it in one
//! process, each returning the same `O[]`, none of these was faster:
//!
//! - a counting sort of the half-edges into buckets keyed by the smaller vertex (count,
//!   prefix sum, scatter `larger << 32 | he` as `u64`, then an insertion sort and a scan of
//!   each bucket, about 6 entries): its scatter (a read-modify-write of each bucket's cursor)
//!   and sorting the buckets cost more than the walk saves;
//! - buckets keyed by the origin, that is, each vertex's star, matched inside the star (a
//!   half-edge's twin leaving the vertex is the one whose destination is the origin of the
//!   triangle's previous half-edge), which gives `O[]`, `VH[]` and the one-fan check in one
//!   pass over the stars: slower than the three passes here, even with the matches compared
//!   four lanes at a time;
//! - the bucket as split `u32` arrays (key and link), or with the key read back from `V[]`
//!   to halve the scratch: slower;
//! - seven fixed slots per vertex (one cache line) with an overflow list: no faster than the
//!   bucket walk, for 32 more bytes per face to clear first;
//! - `VH[]` kept inside the pairing loop (the first half-edge leaving each vertex, then the
//!   boundary ones from `O[]`): slower, the added branch costs more than Algorithm 3's pass.
//!
//! The developers' guide's construction target asks level 1 for at most 0.3× the time of
//! OpenMesh's `add_face` build; the report's Targets section measures it in turns and shows
//! whether a run meets it, and the `passes` form above sets each pass beside OpenMesh's build.
//!
//! Cold builds (memory returned to the kernel before each build) add a first-touch page
//! fault for every page the build writes: 64 bytes per face (`G[]`, `V[]` and `O[]` 12 bytes
//! per face each, the pairing's nodes 24, `head` and `VH[]` 2 each), about as many pages as
//! OpenMesh's build touches. `build_sweep` with `cold` prints the faults per build beside the
//! times, and the report's Construction section times both warm and cold builds. Halving the
//! nodes would save about a fifth of those pages, but every `u32` layout measured made the
//! warm pairing slower.

use super::{fan_walk_algorithm_7, next, next_boundary_half_edge, opposite_of};
use crate::core::error::{Error, Result};
use crate::core::ids::HalfEdgeId;
use crate::core::soup::bucket_step_budget;
use crate::core::soup::PolygonSoup;
use glam::DVec3;
use std::collections::hash_map::Entry;
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
    check_level0(soup, structure)?;
    Ok((soup.positions.clone(), soup.indices().to_vec()))
}

/// What [`level0_containers`] refuses: polygons, and more half-edges or vertices than `i32`
/// numbers.
fn check_level0(soup: &PolygonSoup, structure: &'static str) -> Result<()> {
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
    Ok(())
}

/// The exact error for a soup in which the fast construction found a non-manifold edge, an
/// orientation clash or a vertex of several fans: the shared edge analysis names the culprit.
pub(crate) fn refusal(soup: &PolygonSoup, structure: &'static str) -> Error {
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
    // A refusal drops the containers first: the shared checks that name the problem take
    // their own arrays, and a vertex of many fans is refused after its `O[]` is built.
    let Some((o, vh)) = opposites_and_vertex_half_edges(&v, g.len()) else {
        drop((g, v));
        return Err(refusal(soup, structure));
    };
    if !every_vertex_one_fan(&o, &vh) {
        drop((g, v, o, vh));
        return Err(refusal(soup, structure));
    }
    Ok(Checked { g, v, o, vh })
}

/// [`build_fast`] consuming the soup: its positions and corners become `G[]` and `V[]`
/// without a copy, so the soup and the structure are never held at once. A soup it refuses is
/// put back together for the shared checks to name the problem.
pub(crate) fn build_fast_owned(soup: PolygonSoup, structure: &'static str) -> Result<Checked> {
    check_level0(&soup, structure)?;
    let (g, v) = soup
        .into_triangles()
        .map_err(|soup| refusal(&soup, structure))?;
    let refuse =
        |g: Vec<DVec3>, v: Vec<u32>| refusal(&PolygonSoup::from_triangles(g, v), structure);
    if !g.iter().all(|p| p.is_finite()) {
        return Err(refuse(g, v));
    }
    // `O[]` and `VH[]` are dropped before a refusal's shared checks take their own arrays.
    match opposites_and_vertex_half_edges(&v, g.len()) {
        Some((o, vh)) if every_vertex_one_fan(&o, &vh) => Ok(Checked { g, v, o, vh }),
        Some(containers) => {
            drop(containers);
            Err(refuse(g, v))
        }
        None => Err(refuse(g, v)),
    }
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

/// The same `O[]` as [`opposites_algorithm_1`] without a map: Algorithm 1's one pass over the
/// half-edges, with the map replaced by a bucket per smaller vertex, kept as a linked list of
/// the first half-edge of each edge met so far. A half-edge looks in its smaller vertex's
/// bucket (a few entries) for an earlier half-edge with the same larger vertex: found, the two
/// are opposite; not found, it joins the bucket. `O[]` is written in half-edge order (each
/// entry once, its partner's overwritten when the partner arrives), so nothing is zeroed first.
///
/// A bucket holds the edges from its vertex to larger ones, so a vertex of valence k costs
/// about k²/2 steps: about one per half-edge on a mesh of bounded valence, 5·10¹¹ on a fan of
/// a million triangles around one vertex. Past 16 steps per half-edge the pairing is finished
/// by a hash map of edges instead, which gives the same `O[]`.
///
/// Returns `None` when `V[]` is not whole triangles or holds more half-edges or vertices than
/// `i32` numbers (the chapter's `O[]` and `VH[]` are signed), when a triangle names a vertex
/// `>= num_vertices` or one vertex twice, or when three half-edges share an edge or two
/// traverse it in the same direction (a non-manifold edge or inconsistent orientation).
pub fn opposites_by_buckets(v: &[u32], num_vertices: usize) -> Option<Vec<i32>> {
    const EMPTY: u32 = u32::MAX;
    let limit = i32::MAX as usize;
    if !v.len().is_multiple_of(3) || v.len() > limit || num_vertices > limit {
        return None;
    }
    let n = num_vertices as u32;
    // head[a]: the last half-edge that joined the bucket of a. node[he] of a half-edge in a
    // bucket: its larger vertex, whether it leaves the larger vertex, and the half-edge that
    // joined before it, as (larger << 33) | (leaves << 32) | link, so a step along the bucket
    // is one load.
    let mut head = vec![EMPTY; num_vertices];
    let mut node: Vec<u64> = Vec::with_capacity(v.len());
    let mut o: Vec<i32> = Vec::with_capacity(v.len());
    let mut steps_left = bucket_step_budget(v.len());
    for (t, corners) in v.chunks_exact(3).enumerate() {
        for (he, from, to) in triangle_sides(t, corners, n)? {
            let (smaller, larger) = (from.min(to), from.max(to));
            let leaves = (from > to) as u64;
            let mut at = head[smaller as usize];
            loop {
                if at == EMPTY {
                    // The first half-edge of its edge: on the boundary until its opposite comes.
                    o.push(-1);
                    node.push((larger as u64) << 33 | leaves << 32 | head[smaller as usize] as u64);
                    head[smaller as usize] = he;
                    break;
                }
                let found = node[at as usize];
                if (found >> 33) as u32 == larger {
                    if o[at as usize] >= 0 || (found >> 32) & 1 == leaves {
                        return None; // a third half-edge, or both in the same direction
                    }
                    o[at as usize] = he as i32;
                    o.push(at as i32);
                    node.push(u64::MAX); // not in a bucket: its edge is found through `at`
                    break;
                }
                at = found as u32;
                steps_left -= 1;
                if steps_left == 0 {
                    // The buckets' arrays are dropped before the map's are made.
                    drop((head, node, o));
                    return opposites_by_map(v, num_vertices);
                }
            }
        }
    }
    Some(o)
}

/// The half-edges of triangle `t`, whose corners are `corners`, as (half-edge, start, end);
/// `None` when the triangle names a vertex `>= n` or one vertex twice.
#[inline(always)]
fn triangle_sides(t: usize, corners: &[u32], n: u32) -> Option<[(u32, u32, u32); 3]> {
    let (a, b, c) = (corners[0], corners[1], corners[2]);
    if a >= n || b >= n || c >= n || a == b || b == c || c == a {
        return None;
    }
    let he = 3 * t as u32;
    Some([(he, a, b), (he + 1, b, c), (he + 2, c, a)])
}

/// [`opposites_by_buckets`]'s `O[]` and refusals through a hash map of edges, as Algorithm 1
/// pairs them, for meshes with a vertex of high valence: O(n) expected whatever the valences.
fn opposites_by_map(v: &[u32], num_vertices: usize) -> Option<Vec<i32>> {
    let n = num_vertices as u32;
    let mut o = vec![-1i32; v.len()];
    // The first half-edge of each edge, by its sorted end vertices: room for as many edges as
    // half-edges (all on the boundary: a vertex of many fans), so that the table never grows,
    // which would hold the old table and the new one, twice as large, at once.
    let mut first: HashMap<(u32, u32), u32> = HashMap::with_capacity(v.len());
    for (t, corners) in v.chunks_exact(3).enumerate() {
        for (he, from, to) in triangle_sides(t, corners, n)? {
            match first.entry((from.min(to), from.max(to))) {
                Entry::Vacant(slot) => {
                    slot.insert(he);
                }
                Entry::Occupied(slot) => {
                    let at = *slot.get() as usize;
                    if o[at] >= 0 || v[at] == from {
                        return None; // a third half-edge, or both in the same direction
                    }
                    o[at] = he as i32;
                    o[he as usize] = at as i32;
                }
            }
        }
    }
    Some(o)
}

/// [`opposites_by_buckets`] and Algorithm 3's `VH[]` ([`vertex_half_edges_algorithm_3`]) from
/// it: the largest boundary half-edge leaving each vertex, else the smallest one.
pub fn opposites_and_vertex_half_edges(
    v: &[u32],
    num_vertices: usize,
) -> Option<(Vec<i32>, Vec<i32>)> {
    let o = opposites_by_buckets(v, num_vertices)?;
    let vh = vertex_half_edges_algorithm_3(v, &o, num_vertices);
    Some((o, vh))
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
pub fn every_vertex_one_fan(o: &[i32], vh: &[i32]) -> bool {
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
    eh.extend(
        crate::core::reads::each("O", o, 0)
            .zip(0u32..)
            .filter(|&(x, he)| x < 0 || he < x as u32)
            .map(|(_, he)| he),
    );
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
        if crate::core::reads::read!("O", o, he as usize) >= 0 || visited[he as usize] {
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

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// `V[]` of a fan of `k` triangles around vertex 0, closed into a disc when `closed`.
    fn fan(k: u32, closed: bool) -> Vec<u32> {
        let rim = |i: u32| if closed { 1 + i % k } else { 1 + i };
        (0..k).flat_map(|i| [0, rim(i), rim(i + 1)]).collect()
    }

    #[test]
    fn a_vertex_of_high_valence_is_paired_by_the_map() {
        // Valence 3000: about 4.5M bucket steps against a budget of 16·9000 + 4096.
        for closed in [false, true] {
            let v = fan(3000, closed);
            let k = 3000usize;
            assert!(k * k / 2 > bucket_step_budget(v.len()));
            let o = opposites_by_buckets(&v, 3002).expect("a fan is a manifold");
            assert_eq!(o, opposites_algorithm_1(&v));
            // On the boundary: the rim's k edges, and the two end spokes of an open fan.
            let boundary = if closed { k } else { k + 2 };
            assert_eq!(o.iter().filter(|&&x| x < 0).count(), boundary);
        }
    }

    proptest! {
        /// The map pairs and refuses as the buckets do, on random triangle lists over a few
        /// vertices (mostly non-manifold or inconsistently oriented, some out of range).
        #[test]
        fn the_map_answers_as_the_buckets(v in prop::collection::vec(0u32..8, 0..40)) {
            let v = &v[..v.len() / 3 * 3];
            prop_assert_eq!(opposites_by_map(v, 7), opposites_by_buckets(v, 7));
        }
    }
}
