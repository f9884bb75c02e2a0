//! The redundancy checks: vertices at one position, and faces that repeat another's vertices
//! topologically or geometrically.
//!
//! ## Duplicate vertices in linear time on any input
//!
//! Vertices at exactly one position (bit-equal coordinates, `-0` equal to `0`) are found
//! through a hash of their coordinates' bits: expected O(1) per vertex whatever the
//! coordinates (the hasher is keyed at random per process, so no file makes its keys
//! collide). Near duplicates, within the tolerance `t` (transitively: a chain of vertices
//! each within `t` of the next is one group), are found through a hash of grid cells of side
//! `2t`: the cube of side `2t` around a vertex overlaps at most 8 cells, and the vertex is
//! compared with the positions filed in each. A cell index that would not fit an `i64` (a
//! coordinate beyond about 4.6·10^18·t, where consecutive doubles are farther apart than `t`,
//! so that only an equal coordinate can be within `t`) is keyed by the coordinate's bits
//! instead of saturating into one crowded cell.
//!
//! What makes this linear on every input is a bound on the comparisons: a vertex is compared
//! with at most [`NEAR_DUPLICATES_COMPARED`] of the positions filed in each cell, the latest
//! ones. A cell holds more only where more than that many distinct positions lie in a cube of
//! side `2t`, which makes some of them near duplicates of each other already (a cube of side
//! `2t` splits into 64 cubes of diameter below `t`); the report then counts the vertices
//! whose search was cut short ([`super::CheckSummary::near_duplicates_not_exhaustive`]), and
//! a pair of near duplicates among them may be missed. Every group reported is right: its
//! vertices are joined by a chain of positions each within `t` of the next.

use super::{FindingKind, Findings};
use crate::algorithms::union_find::UnionFind;
use crate::core::soup::PolygonSoup;
use glam::DVec3;
use hashbrown::HashTable;
use std::collections::hash_map::RandomState;
use std::collections::HashMap;
use std::hash::BuildHasher;

/// The most positions of one grid cell a vertex is compared with in the search for near
/// duplicates (see the module docs).
pub const NEAR_DUPLICATES_COMPARED: usize = 16;

/// No vertex: the end of a cell's chain.
const NONE: u32 = u32::MAX;

/// In place of the vertex filed before: a vertex at the position of an earlier one, which is
/// not filed in the grid.
const SAME: u32 = u32::MAX - 1;

/// One coordinate's part of a cell's key: the cell index along the axis, or, for a coordinate
/// too large for an index, the coordinate's bits (only an equal coordinate is within the
/// tolerance there).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
enum Axis {
    Cell(i64),
    Exact(u64),
}

/// The cells along one axis that the interval `[x - t, x + t]` overlaps (one or two; one for
/// an [`Axis::Exact`] coordinate), for cells of side `2t`.
fn axis_cells(x: f64, t: f64) -> [Option<Axis>; 2] {
    // Indices of magnitude below 2^62 fit an i64 with room for the neighbour's +1.
    const LIMIT: f64 = 4.611_686_018_427_388e18; // 2^62
    let side = 2.0 * t;
    let (lo, hi) = (((x - t) / side).floor(), ((x + t) / side).floor());
    if !(lo.abs() < LIMIT && hi.abs() < LIMIT) {
        return [Some(Axis::Exact((x + 0.0).to_bits())), None];
    }
    let (lo, hi) = (lo as i64, hi as i64);
    [Some(Axis::Cell(lo)), (hi != lo).then_some(Axis::Cell(hi))]
}

/// The cell a position is filed in: the one holding it (the lower of two when it is exactly
/// `t` from a cell boundary does not matter: any cell it overlaps is searched).
fn home(p: DVec3, t: f64) -> [Axis; 3] {
    p.to_array().map(|x| {
        let side = 2.0 * t;
        match axis_cells(x, t)[0] {
            Some(Axis::Cell(_)) => Axis::Cell((x / side).floor() as i64),
            exact => exact.expect("always one cell"),
        }
    })
}

/// What the search did, for the tests of its growth: hash lookups and distance comparisons.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub(super) struct Work {
    pub lookups: u64,
    pub comparisons: u64,
}

/// The groups of vertices at one position (see the module docs).
pub(super) struct SamePlace {
    /// Per vertex, one vertex of its group (the same for the whole group).
    pub representative: Vec<u32>,
    /// Vertices whose search for near duplicates was cut short.
    pub not_exhaustive: usize,
    /// The work done (read by the tests of its growth).
    #[cfg_attr(not(test), allow(dead_code))]
    pub work: Work,
}

/// Groups vertices at the same position within `tolerance` and reports each group of two or
/// more (see the module docs).
pub(super) fn duplicate_vertices(
    soup: &PolygonSoup,
    finite: &[bool],
    tolerance: f64,
    found: &mut Findings,
) -> SamePlace {
    let n = soup.num_vertices();
    let positions = &soup.positions;
    let mut groups = UnionFind::new(n);
    let mut work = Work::default();
    // The tables hold vertex ids, 5 bytes a slot, each key computed again from the position
    // of the vertex filed (no copy of the keys); each is reserved once for every vertex it may
    // receive, so that it never grows (a growing table holds its old slots and its new ones
    // at once), and the second is made once the first is gone. The hasher is keyed at random
    // per process.
    let hasher = RandomState::new();
    // `earlier[v]`: for a vertex at the position of an earlier one, `SAME`; for the others
    // filed in the grid, the vertex filed in v's cell before v.
    let near = tolerance > 0.0;
    let mut earlier: Vec<u32> = if near { vec![NONE; n] } else { Vec::new() };
    // Vertices at exactly one position, in one pass: the first vertex at each position.
    let mut distinct = 0;
    {
        // `+ 0.0` makes -0 and +0 one position.
        let key = |v: u32| {
            (positions[v as usize] + DVec3::ZERO)
                .to_array()
                .map(f64::to_bits)
        };
        let finite_vertices = finite.iter().filter(|&&ok| ok).count();
        let mut first_at: HashTable<u32> = HashTable::with_capacity(finite_vertices);
        for v in (0..n as u32).filter(|&v| finite[v as usize]) {
            work.lookups += 1;
            let k = key(v);
            let hash = hasher.hash_one(k);
            match first_at.find(hash, |&w| key(w) == k) {
                Some(&first) => {
                    groups.union(v, first, false);
                    if near {
                        earlier[v as usize] = SAME;
                    }
                }
                None => {
                    first_at.insert_unique(hash, v, |&w| hasher.hash_one(key(w)));
                    distinct += 1;
                }
            }
        }
    }
    // Near duplicates, in a second pass over the first vertex at each position, in order: the
    // grid, per cell the latest vertex filed in it (the key is its cell).
    let mut not_exhaustive = 0;
    if near {
        let cell_of = |v: u32| home(positions[v as usize], tolerance);
        let mut cells: HashTable<u32> = HashTable::with_capacity(distinct);
        for v in 0..n as u32 {
            if !finite[v as usize] || earlier[v as usize] == SAME {
                continue;
            }
            let p = positions[v as usize];
            let [x, y, z] = p.to_array().map(|c| axis_cells(c, tolerance));
            let mut cut_short = false;
            for cx in x.iter().flatten() {
                for cy in y.iter().flatten() {
                    for cz in z.iter().flatten() {
                        work.lookups += 1;
                        let cell = [*cx, *cy, *cz];
                        let found = cells.find(hasher.hash_one(cell), |&w| cell_of(w) == cell);
                        let Some(&latest) = found else {
                            continue;
                        };
                        let mut w = latest;
                        for _ in 0..NEAR_DUPLICATES_COMPARED {
                            if w == NONE {
                                break;
                            }
                            work.comparisons += 1;
                            if positions[w as usize].distance(p) <= tolerance {
                                groups.union(v, w, false);
                            }
                            w = earlier[w as usize];
                        }
                        // More filed in the cell than were compared.
                        cut_short |= w != NONE;
                    }
                }
            }
            not_exhaustive += cut_short as usize;
            let cell = cell_of(v);
            let hash = hasher.hash_one(cell);
            match cells.find_mut(hash, |&w| cell_of(w) == cell) {
                Some(latest) => {
                    earlier[v as usize] = *latest;
                    *latest = v;
                }
                None => {
                    cells.insert_unique(hash, v, |&w| hasher.hash_one(cell_of(w)));
                }
            }
        }
    }
    drop(earlier);
    // Per vertex the root of its group: the forest itself, flattened.
    let (representative, _) = groups.into_roots();
    report_groups(&representative, tolerance, found);
    SamePlace {
        representative,
        not_exhaustive,
        work,
    }
}

/// One finding per group of two or more vertices, in the order of their smallest vertex; the
/// vertices of the groups whose finding is kept are collected in one pass.
fn report_groups(representative: &[u32], tolerance: f64, found: &mut Findings) {
    let kind = FindingKind::DuplicateVertices;
    let n = representative.len();
    let mut size = vec![0u32; n];
    for &r in representative {
        size[r as usize] += 1;
    }
    let room = found.room(kind);
    let (mut firsts, mut groups) = (Vec::new(), 0);
    let mut met = vec![false; n];
    for &r in representative {
        if size[r as usize] > 1 && !met[r as usize] {
            met[r as usize] = true;
            groups += 1;
            if firsts.len() < room {
                firsts.push(r);
            }
        }
    }
    let mut members: HashMap<u32, Vec<u32>> = firsts.iter().map(|&r| (r, Vec::new())).collect();
    if !members.is_empty() {
        for (v, r) in representative.iter().enumerate() {
            if let Some(m) = members.get_mut(r) {
                m.push(v as u32);
            }
        }
    }
    let ids = found.numbering();
    for r in &firsts {
        let m = members.remove(r).unwrap_or_default();
        found.add(kind, || {
            let listed = ids.list(&m);
            (
                m,
                vec![],
                format!("vertices {listed} are at one position (within {tolerance})"),
            )
        });
    }
    found.count(kind, groups - firsts.len());
}

/// The first face of each set of vertices (with their multiplicities) among the faces filed:
/// a hash table of face ids, 5 bytes a slot, whose keys are the faces' vertices, read again
/// from the soup (see [`duplicate_faces`]).
pub(super) struct FirstFaces {
    hasher: RandomState,
    table: HashTable<u32>,
}

impl FirstFaces {
    /// Room for `faces` faces, so that the table never grows.
    fn with_capacity(faces: usize) -> Self {
        Self {
            hasher: RandomState::new(),
            table: HashTable::with_capacity(faces),
        }
    }

    /// The first face filed whose vertices, each mapped by `map`, are `key` (sorted); `j` is
    /// filed when there is none, and is the answer then. `scratch` is a buffer to sort in.
    fn first_or_file(
        &mut self,
        soup: &PolygonSoup,
        j: u32,
        key: &[u32],
        map: impl Fn(u32) -> u32,
        scratch: &mut Vec<u32>,
    ) -> u32 {
        let hash = set_hash(&self.hasher, key.iter().copied());
        let same = |f: &u32| {
            let face = soup.face(*f as usize);
            face.len() == key.len() && {
                scratch.clear();
                scratch.extend(face.iter().map(|&v| map(v)));
                scratch.sort_unstable();
                scratch == key
            }
        };
        if let Some(&first) = self.table.find(hash, same) {
            return first;
        }
        let Self { hasher, table } = self;
        table.insert_unique(hash, j, |&f| {
            set_hash(hasher, soup.face(f as usize).iter().map(|&v| map(v)))
        });
        j
    }
}

/// The hash of a set of vertices with their multiplicities: the sum of the vertices' hashes
/// (the same in any order), and of their number. The hasher is keyed at random, so no file
/// can make two sets collide on purpose.
fn set_hash(hasher: &RandomState, vertices: impl Iterator<Item = u32>) -> u64 {
    let (sum, n) = vertices.fold((0u64, 0u64), |(sum, n), v| {
        (sum.wrapping_add(hasher.hash_one(v)), n + 1)
    });
    sum.wrapping_add(hasher.hash_one(n))
}

/// Faces with the same vertex set (topological duplicates), and faces whose vertices are at
/// the same positions without being the same vertices (geometric duplicates), among the
/// `usable` faces (`count` of them). Returns the first face of each vertex set: a face whose
/// first is another repeats an earlier face's vertices ([`FirstFaces::first_of`]).
pub(super) fn duplicate_faces(
    soup: &PolygonSoup,
    usable: impl Fn(usize, &mut Vec<u32>) -> bool,
    count: usize,
    same_place: &[u32],
    found: &mut Findings,
) -> FirstFaces {
    let mut by_vertices = FirstFaces::with_capacity(count);
    let mut by_positions = FirstFaces::with_capacity(count);
    let (mut key, mut scratch) = (Vec::new(), Vec::new());
    let ids = found.numbering();
    for j in 0..soup.num_faces() {
        if !usable(j, &mut scratch) {
            continue;
        }
        let face = soup.face(j);
        key.clear();
        key.extend_from_slice(face);
        key.sort_unstable();
        let first = by_vertices.first_or_file(soup, j as u32, &key, |v| v, &mut scratch);
        if first != j as u32 {
            found.add(FindingKind::DuplicateFace, || {
                (
                    key.clone(),
                    vec![first, j as u32],
                    format!(
                        "faces {} and {} have the same vertices",
                        ids.id(first),
                        ids.id(j as u64)
                    ),
                )
            });
            continue;
        }
        key.clear();
        key.extend(face.iter().map(|&v| same_place[v as usize]));
        key.sort_unstable();
        let place = |v: u32| same_place[v as usize];
        let first = by_positions.first_or_file(soup, j as u32, &key, place, &mut scratch);
        if first != j as u32 {
            found.add(FindingKind::GeometricDuplicateFace, || {
                (
                    face.to_vec(),
                    vec![first, j as u32],
                    format!(
                        "faces {} and {} lie at the same positions on different vertices",
                        ids.id(first),
                        ids.id(j as u64)
                    ),
                )
            });
        }
    }
    by_vertices
}

impl FirstFaces {
    /// The first face filed with the vertices of face `j` of `soup` (`j` itself when it was
    /// filed); `None` when none was (face `j` was not filed, nor one with its vertices).
    pub(super) fn first_of(
        &self,
        soup: &PolygonSoup,
        j: usize,
        key: &mut Vec<u32>,
        scratch: &mut Vec<u32>,
    ) -> Option<u32> {
        key.clear();
        key.extend_from_slice(soup.face(j));
        key.sort_unstable();
        let hash = set_hash(&self.hasher, key.iter().copied());
        self.table
            .find(hash, |f| {
                let face = soup.face(*f as usize);
                face.len() == key.len() && {
                    scratch.clear();
                    scratch.extend_from_slice(face);
                    scratch.sort_unstable();
                    scratch == key
                }
            })
            .copied()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algorithms::checks::Options;
    use crate::core::error::Numbering;

    /// The search on `n` vertices at `position(i)`: its work, and the groups it reported.
    fn search(n: usize, position: impl Fn(usize) -> DVec3) -> (Work, usize, usize) {
        let soup = PolygonSoup::from_polygons((0..n).map(position).collect(), &[] as &[[u32; 3]]);
        let options = Options::default();
        let mut found = Findings::new(&options, Numbering::FromZero);
        let same = duplicate_vertices(&soup, &vec![true; n], options.tolerance, &mut found);
        let groups = found
            .counts
            .get(&FindingKind::DuplicateVertices)
            .copied()
            .unwrap_or(0);
        (same.work, groups, same.not_exhaustive)
    }

    /// The hostile families of issue 52 and a plain one, each grown 4×: the work (hash
    /// lookups and distance comparisons) grows at most 5× (it is linear: at most 9 lookups and
    /// 8 × 16 comparisons a vertex), where the grid of old grew 16× on the first three.
    #[test]
    fn the_search_stays_linear_on_hostile_coordinates() {
        // 1.0 and the doubles 3i ulps above it.
        let ulp_steps = |i: usize| f64::from_bits(1.0f64.to_bits() + 3 * i as u64);
        type Position = Box<dyn Fn(usize) -> DVec3>;
        let families: [(&str, Position); 4] = [
            // Distinct coordinates of 1e10 and more: cell indices past i64 of old.
            (
                "far",
                Box::new(|i| DVec3::new(1e10 + 1024.0 * i as f64, 2e10, 3e10)),
            ),
            // Distinct positions a few ulps apart, all within the tolerance.
            (
                "ulps",
                Box::new(move |i| DVec3::new(ulp_steps(i), 1.0, 1.0)),
            ),
            // Distinct positions that underflow a float, all within the tolerance.
            ("tiny", Box::new(|i| DVec3::new(i as f64 * 1e-50, 0.0, 0.0))),
            // A plain grid of points 1 apart.
            (
                "grid",
                Box::new(|i| DVec3::new((i % 97) as f64, (i / 97) as f64, 0.0)),
            ),
        ];
        for (name, position) in families {
            let (small, _, _) = search(2_000, &position);
            let (large, groups, cut) = search(8_000, &position);
            let (w0, w1) = (
                small.lookups + small.comparisons,
                large.lookups + large.comparisons,
            );
            assert!(w0 >= 2_000, "{name}: {small:?}");
            assert!(
                w1 <= 5 * w0,
                "{name}: work {w0} at 2000 vertices, {w1} at 8000 ({small:?}, {large:?})"
            );
            match name {
                // All within the tolerance of a neighbour: one group, found although the
                // cells are crowded.
                "ulps" | "tiny" => assert_eq!((groups, cut > 0), (1, true), "{name}"),
                _ => assert_eq!((groups, cut), (0, 0), "{name}"),
            }
        }
    }

    #[test]
    fn coordinates_too_large_for_a_cell_index_are_keyed_exactly() {
        let t = 1e-9;
        // 1e300 / 2e-9 is no i64: keyed by its bits, one cell, no neighbour along the axis.
        assert_eq!(
            axis_cells(1e300, t),
            [Some(Axis::Exact(1e300f64.to_bits())), None]
        );
        assert_eq!(axis_cells(-0.0, t), axis_cells(0.0, t));
        // [0.5e-9, 2.5e-9] overlaps the cells [0, 2e-9) and [2e-9, 4e-9).
        assert_eq!(
            axis_cells(1.5e-9, t),
            [Some(Axis::Cell(0)), Some(Axis::Cell(1))]
        );
        // Equal far coordinates group; distinct ones (farther apart than the tolerance, as
        // doubles there are) do not.
        let (_, groups, _) = search(4, |i| DVec3::new(1e300, (i / 2) as f64, 0.0));
        assert_eq!(groups, 2);
    }
}
