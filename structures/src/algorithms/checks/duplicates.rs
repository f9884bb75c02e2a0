//! The redundancy checks: vertices at one position, and faces that repeat another's vertices
//! topologically or geometrically.

use super::{FindingKind, Push, UnionFind};
use crate::core::soup::PolygonSoup;
use glam::DVec3;
use std::collections::{BTreeMap, HashMap};

/// Groups vertices at the same position within `tolerance` (transitively): exact duplicates
/// through a hash of their coordinates, near ones through a grid hash of cell size
/// `tolerance` (each distinct position compared with the distinct positions of its 27
/// neighbouring cells: O(n) unless many distinct positions crowd within the tolerance).
/// Returns, per vertex, one vertex of its group (the same for the whole group).
pub(super) fn duplicate_vertices(
    soup: &PolygonSoup,
    finite: &[bool],
    tolerance: f64,
    push: &mut Push<'_>,
) -> Vec<u32> {
    let n = soup.num_vertices();
    let mut groups = UnionFind::new(n);
    // `+ 0.0` makes -0 and +0 one position.
    let exact_key = |p: DVec3| (p + DVec3::ZERO).to_array().map(f64::to_bits);
    let mut first_at: HashMap<[u64; 3], u32> = HashMap::new();
    let mut grid: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
    for v in (0..n as u32).filter(|&v| finite[v as usize]) {
        let p = soup.positions[v as usize];
        if let Some(&first) = first_at.get(&exact_key(p)) {
            groups.union(v, first, false);
            continue;
        }
        first_at.insert(exact_key(p), v);
        if tolerance <= 0.0 {
            continue;
        }
        // Saturating float-to-int casts keep far-out coordinates in (crowded) edge cells.
        let cell = (p / tolerance).floor().to_array().map(|c| c as i64);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    let key = [
                        cell[0].saturating_add(dx),
                        cell[1].saturating_add(dy),
                        cell[2].saturating_add(dz),
                    ];
                    for &w in grid.get(&key).into_iter().flatten() {
                        if soup.positions[w as usize].distance(p) <= tolerance {
                            groups.union(v, w, false);
                        }
                    }
                }
            }
        }
        grid.entry(cell).or_default().push(v);
    }
    let representative: Vec<u32> = (0..n as u32).map(|v| groups.find(v).0).collect();
    let mut members: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
    for (v, &r) in representative.iter().enumerate() {
        members.entry(r).or_default().push(v as u32);
    }
    let mut found: Vec<Vec<u32>> = members.into_values().filter(|m| m.len() > 1).collect();
    found.sort();
    for group in found {
        push(
            FindingKind::DuplicateVertices,
            group.clone(),
            vec![],
            format!("vertices {group:?} are at one position (within {tolerance})"),
        );
    }
    representative
}

/// Faces with the same vertex set (topological duplicates), and faces whose vertices are at
/// the same positions without being the same vertices (geometric duplicates). Returns, per
/// face, whether it repeats an earlier face's vertices.
pub(super) fn duplicate_faces(
    soup: &PolygonSoup,
    usable: &[bool],
    same_place: &[u32],
    push: &mut Push<'_>,
) -> Vec<bool> {
    let mut duplicate = vec![false; soup.num_faces()];
    let mut by_vertices: HashMap<Vec<u32>, u32> = HashMap::new();
    let mut by_positions: HashMap<Vec<u32>, u32> = HashMap::new();
    for j in (0..soup.num_faces()).filter(|&j| usable[j]) {
        let face = soup.face(j);
        let mut key: Vec<u32> = face.to_vec();
        key.sort_unstable();
        if let Some(&first) = by_vertices.get(&key) {
            push(
                FindingKind::DuplicateFace,
                key,
                vec![first, j as u32],
                format!("faces {first} and {j} have the same vertices"),
            );
            duplicate[j] = true;
            continue;
        }
        by_vertices.insert(key, j as u32);
        let mut places: Vec<u32> = face.iter().map(|&v| same_place[v as usize]).collect();
        places.sort_unstable();
        match by_positions.get(&places) {
            Some(&first) => push(
                FindingKind::GeometricDuplicateFace,
                face.to_vec(),
                vec![first, j as u32],
                format!("faces {first} and {j} lie at the same positions on different vertices"),
            ),
            None => {
                by_positions.insert(places, j as u32);
            }
        }
    }
    duplicate
}
