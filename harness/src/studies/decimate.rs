//! Decimation by quadric error in the report: the lab's decimater
//! (`topolab_structures::algorithms::decimate` on the editable structures, with each of its
//! strategies: eager, OpenMesh's `DecimaterT` + `ModQuadricT` step for step, and lazy, the
//! lab's) beside OpenMesh's and CGAL's (run natively), to the same face count, and the
//! reconstruction of the original by vertex splits. The Targets row compares the index
//! half-edge's eager decimation with OpenMesh's Decimater: one algorithm on two structures.
//!
//! Every result is measured the same way, by us, on the result meshes ([`distance`]): the
//! distance from each vertex of the original to the decimated surface (exact point–triangle
//! distances, the nearest triangle found through a uniform grid), its maximum (a one-sided
//! Hausdorff distance sampled at the original's vertices) and its mean, relative to the
//! original's bounding-box diagonal.

use crate::measuring::checksum::mix;
use crate::measuring::timing::turns::Spread;
use glam::DVec3;
use topolab_structures::algorithms::decimate::Strategy;
use topolab_structures::PolygonSoup;

/// One decimation in the report.
#[derive(Clone, Debug, serde::Serialize)]
pub struct DecimateRow {
    /// The mesh decimated.
    pub mesh: String,
    /// Its faces.
    pub faces: usize,
    /// The face count asked for.
    pub target: usize,
    /// The decimater (the structure's name; `openmesh` and `cgal-surface-mesh` run natively).
    pub structure: String,
    /// The lab decimater's strategy (`None` for the native decimaters).
    pub strategy: Option<Strategy>,
    /// Median seconds of the decimation (quadrics, heap, collapses; not the build).
    pub seconds: f64,
    /// Runs.
    pub runs: usize,
    /// Seconds of each run, round by round, when the decimaters of this mesh took turns (the
    /// Targets row's pair on the run's largest torus); empty otherwise.
    pub turns: Vec<f64>,
    /// Faces of the result.
    pub faces_after: usize,
    /// The result's error ([`distance`]).
    pub error: Distance,
    /// The reconstruction by vertex splits, for the lab's structures: median seconds, and
    /// whether the original came back exactly.
    pub reconstruction: Option<(f64, bool)>,
}

impl DecimateRow {
    /// The decimater as the report names it: the structure, with the lab's strategy.
    pub fn decimater(&self) -> String {
        match self.strategy {
            Some(s) => format!("{} ({s})", self.structure),
            None => self.structure.clone(),
        }
    }
}

/// Distances from a mesh's vertices to another surface, relative to the first mesh's
/// bounding-box diagonal.
#[derive(Copy, Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct Distance {
    /// The largest.
    pub max: f64,
    /// The mean.
    pub mean: f64,
}

/// The closest point to `p` on triangle `abc` (Ericson, Real-Time Collision Detection, 5.1.5).
fn closest_on_triangle(p: DVec3, a: DVec3, b: DVec3, c: DVec3) -> DVec3 {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return a + ab * (d1 / (d1 - d3));
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return a + ac * (d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    let denom = va + vb + vc;
    if denom.abs() < f64::MIN_POSITIVE {
        return a;
    }
    a + ab * (vb / denom) + ac * (vc / denom)
}

/// The triangles of a mesh binned in a uniform grid of cubes (compressed rows: the triangles
/// of cell `c` are `items[start[c]..start[c + 1]]`), each in every cell its bounding box
/// meets.
struct Grid {
    min: DVec3,
    cell: f64,
    dims: [usize; 3],
    start: Vec<u32>,
    items: Vec<u32>,
}

impl Grid {
    fn new(soup: &PolygonSoup) -> Self {
        let (mut min, mut max) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
        for &p in &soup.positions {
            min = min.min(p);
            max = max.max(p);
        }
        let extent = (max - min).max(DVec3::splat(1e-12));
        // About one triangle per cell.
        let n = soup.num_faces().max(1) as f64;
        let cell = (extent.x * extent.y * extent.z / n)
            .cbrt()
            .max(extent.max_element() / 256.0);
        let dims = [extent.x, extent.y, extent.z].map(|e| ((e / cell).ceil() as usize).max(1));
        let mut g = Self {
            min,
            cell,
            dims,
            start: vec![0; dims[0] * dims[1] * dims[2] + 1],
            items: Vec::new(),
        };
        for pass in 0..2 {
            for (f, face) in soup.faces().enumerate() {
                let (mut lo, mut hi) =
                    (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
                for &v in face {
                    lo = lo.min(soup.positions[v as usize]);
                    hi = hi.max(soup.positions[v as usize]);
                }
                let (a, b) = (g.coords(lo), g.coords(hi));
                for z in a[2]..=b[2] {
                    for y in a[1]..=b[1] {
                        for x in a[0]..=b[0] {
                            let c = g.index([x, y, z]);
                            if pass == 0 {
                                g.start[c + 1] += 1;
                            } else {
                                g.items[g.start[c] as usize] = f as u32;
                                g.start[c] += 1;
                            }
                        }
                    }
                }
            }
            if pass == 0 {
                for c in 1..g.start.len() {
                    g.start[c] += g.start[c - 1];
                }
                g.items = vec![0; g.start[g.start.len() - 1] as usize];
            } else {
                // The fill advanced each start to the next cell's: shift back.
                for c in (1..g.start.len()).rev() {
                    g.start[c] = g.start[c - 1];
                }
                g.start[0] = 0;
            }
        }
        g
    }

    fn coords(&self, p: DVec3) -> [usize; 3] {
        let q = (p - self.min) / self.cell;
        let q = [q.x, q.y, q.z];
        [0, 1, 2].map(|i| (q[i].max(0.0) as usize).min(self.dims[i] - 1))
    }

    fn index(&self, [x, y, z]: [usize; 3]) -> usize {
        (z * self.dims[1] + y) * self.dims[0] + x
    }

    /// The distance from `p` to the nearest triangle: rings of cells around `p`'s cell (its
    /// projection on the grid's box, which is no farther from any point of the box) until
    /// the best distance found is no larger than the distance to the next ring.
    fn distance(&self, soup: &PolygonSoup, p: DVec3) -> f64 {
        let c = self.coords(p);
        let mut best = f64::INFINITY;
        let rings = self.dims.iter().copied().max().unwrap_or(1);
        for r in 0..=rings {
            let lo = c.map(|x| x.saturating_sub(r));
            let hi = [0, 1, 2].map(|i| (c[i] + r).min(self.dims[i] - 1));
            for z in lo[2]..=hi[2] {
                for y in lo[1]..=hi[1] {
                    for x in lo[0]..=hi[0] {
                        let on_ring = [x, y, z].iter().zip(c).any(|(&a, b)| a.abs_diff(b) == r);
                        if !on_ring {
                            continue;
                        }
                        let cell = self.index([x, y, z]);
                        for &f in
                            &self.items[self.start[cell] as usize..self.start[cell + 1] as usize]
                        {
                            let t = soup.face(f as usize);
                            let [a, b, cc] = [t[0], t[1], t[2]].map(|v| soup.positions[v as usize]);
                            best = best.min(p.distance(closest_on_triangle(p, a, b, cc)));
                        }
                    }
                }
            }
            if best <= r as f64 * self.cell {
                break;
            }
        }
        best
    }
}

/// The distances from every vertex of `original` used by a face to the surface of the
/// triangle mesh `result`, relative to `original`'s bounding-box diagonal.
pub fn distance(original: &PolygonSoup, result: &PolygonSoup) -> Distance {
    if result.num_faces() == 0 {
        return Distance {
            max: f64::INFINITY,
            mean: f64::INFINITY,
        };
    }
    let grid = Grid::new(result);
    let (mut min, mut max) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    let mut used = vec![false; original.num_vertices()];
    for &v in original.indices() {
        used[v as usize] = true;
    }
    let (mut sum, mut worst, mut n) = (0.0, 0.0f64, 0usize);
    for (v, &p) in original.positions.iter().enumerate() {
        if !used[v] {
            continue;
        }
        min = min.min(p);
        max = max.max(p);
        let d = grid.distance(result, p);
        sum += d;
        worst = worst.max(d);
        n += 1;
    }
    let diagonal = (max - min).length().max(f64::MIN_POSITIVE);
    Distance {
        max: worst / diagonal,
        mean: sum / n.max(1) as f64 / diagonal,
    }
}

/// The checksum on which the Targets row's pair must agree in every round: the result mesh
/// by positions (neither decimater moves a vertex, and the ids differ: OpenMesh's garbage
/// collection reorders its vertices), the wrapping sum over triangles of their corners'
/// coordinate bits folded with [`mix`], each triangle read from its smallest corner (by
/// bits) on. Face order and where a triangle starts do not matter; orientation does.
pub fn result_checksum(triangles: impl Iterator<Item = [DVec3; 3]>) -> u64 {
    let bits = |p: DVec3| p.to_array().map(f64::to_bits);
    triangles.fold(0u64, |sum, t| {
        let first = (0..3).min_by_key(|&i| bits(t[i])).unwrap_or(0);
        let h = (0..3).flat_map(|i| bits(t[(first + i) % 3])).fold(3, mix);
        sum.wrapping_add(h)
    })
}

/// A Targets row of the decimation: what it compares, the ratio (`None`: not measured), the
/// spread of the per-round ratios when the two took turns, and the goal.
#[derive(Clone, Debug, PartialEq)]
pub struct TargetRow {
    /// What is compared, on which mesh.
    pub what: String,
    /// The ratio: the median of the per-round ratios when the two took turns, else the ratio
    /// of their medians.
    pub value: Option<f64>,
    /// The per-round ratios, when the two took turns.
    pub spread: Option<Spread>,
    /// The goal (at most).
    pub goal: f64,
}

/// The Targets rows: the index half-edge's eager decimation (OpenMesh's algorithm) against
/// OpenMesh's Decimater on the largest torus both ran, at the same target (goal 1.5). The
/// lazy strategy runs another algorithm, so its rows stay in the section.
pub fn targets(rows: &[DecimateRow]) -> Vec<TargetRow> {
    let om = rows
        .iter()
        .filter(|r| r.structure == "openmesh" && r.mesh.starts_with("torus"))
        .max_by_key(|r| r.faces);
    let Some(om) = om else {
        return Vec::new();
    };
    let ours = rows.iter().find(|r| {
        r.structure == "index-half-edge" && r.strategy == Some(Strategy::Eager) && r.mesh == om.mesh
    });
    let spread = ours.and_then(|r| Spread::of_ratios(&r.turns, &om.turns));
    vec![TargetRow {
        what: format!(
            "index-half-edge decimation to 10%, OpenMesh's algorithm (eager) / OpenMesh Decimater ({}, time ratio)",
            om.mesh
        ),
        value: spread
            .map(|s| s.median)
            .or_else(|| ours.map(|r| r.seconds / om.seconds)),
        spread,
        goal: 1.5,
    }]
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::meshes;

    fn row(structure: &str, strategy: Option<Strategy>, turns: [f64; 3]) -> DecimateRow {
        DecimateRow {
            mesh: "torus-16k".into(),
            faces: 16_432,
            target: 1_643,
            structure: structure.into(),
            strategy,
            seconds: turns[1],
            runs: 3,
            turns: turns.to_vec(),
            faces_after: 1_642,
            error: Distance::default(),
            reconstruction: None,
        }
    }

    #[test]
    fn the_targets_row_times_the_eager_index_half_edge_against_openmesh() {
        // The lazy row, another algorithm, comes first and must not be taken.
        let rows = [
            row("index-half-edge", Some(Strategy::Lazy), [1.0, 1.0, 1.0]),
            row("index-half-edge", Some(Strategy::Eager), [3.0, 4.0, 6.0]),
            row("openmesh", None, [2.0, 2.0, 3.0]),
        ];
        let t = targets(&rows);
        assert_eq!(t.len(), 1);
        // Per-round ratios 1.5, 2, 2: their median.
        assert_eq!(t[0].value, Some(2.0));
        assert!(t[0].what.contains("(eager)"), "{}", t[0].what);
        assert_eq!(rows[1].decimater(), "index-half-edge (eager)");
        assert_eq!(rows[2].decimater(), "openmesh");
    }

    #[test]
    fn the_result_checksum_ignores_numbering_and_sees_orientation_and_positions() {
        let soup = meshes::torus(6, 4);
        let triangles = |s: &PolygonSoup| -> Vec<[DVec3; 3]> {
            s.faces()
                .map(|f| [f[0], f[1], f[2]].map(|v| s.positions[v as usize]))
                .collect()
        };
        let t = triangles(&soup);
        let sum = result_checksum(t.iter().copied());
        // Faces in another order, each starting at another corner.
        let shuffled = t.iter().rev().map(|&[a, b, c]| [b, c, a]);
        assert_eq!(result_checksum(shuffled), sum);
        let flipped = t
            .iter()
            .enumerate()
            .map(|(i, &[a, b, c])| if i == 0 { [a, c, b] } else { [a, b, c] });
        assert_ne!(result_checksum(flipped), sum);
        let mut moved = soup.clone();
        moved.positions[0].x += 1e-12;
        assert_ne!(result_checksum(triangles(&moved).into_iter()), sum);
    }

    #[test]
    fn a_mesh_is_at_distance_zero_from_itself_and_a_shifted_copy_is_not() {
        let soup = meshes::torus(12, 8);
        let d = distance(&soup, &soup);
        assert!(d.max < 1e-12, "{d:?}");
        let mut moved = soup.clone();
        for p in &mut moved.positions {
            p.z += 0.1;
        }
        let d = distance(&soup, &moved);
        // The torus's diagonal is √(2.7² + 2.7² + 0.7²) ≈ 3.88; no vertex is farther than 0.1.
        assert!(d.max > 0.0 && d.max <= 0.1 / 3.8, "{d:?}");
        assert!(d.mean > 0.0 && d.mean <= d.max);
    }

    #[test]
    fn the_nearest_point_is_found_through_the_grid_as_by_brute_force() {
        let soup = meshes::perturb(&meshes::sphere(8, 12), 0.05, 3);
        let grid = Grid::new(&soup);
        for i in 0..50 {
            let t = i as f64 * 0.37;
            let p = DVec3::new(t.sin() * 1.7, (2.0 * t).cos() * 0.4, (0.5 * t).sin() * 1.3);
            let brute = soup
                .faces()
                .map(|f| {
                    let [a, b, c] = [f[0], f[1], f[2]].map(|v| soup.positions[v as usize]);
                    p.distance(closest_on_triangle(p, a, b, c))
                })
                .fold(f64::INFINITY, f64::min);
            assert!((grid.distance(&soup, p) - brute).abs() < 1e-12, "{p}");
        }
    }
}
