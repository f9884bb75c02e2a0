//! The naive model of the editing suite: a face list edited by hand, which says whether an
//! edit must be refused.

use crate::algorithms::select::Aabb;
use crate::core::soup::PolygonSoup;
use crate::meshes::{self, RandomMeshParams};
use crate::testing::oracle::canonical_face;
use glam::DVec3;

/// The naive model: positions and faces, `None` where deleted.
#[derive(Clone, Debug, Default)]
pub struct Model {
    /// Per vertex, its position, `None` once deleted.
    pub positions: Vec<Option<DVec3>>,
    /// Per face, its corners, `None` once deleted.
    pub faces: Vec<Option<Vec<u32>>>,
}

impl Model {
    /// The model of a soup.
    pub fn of(soup: &PolygonSoup) -> Self {
        Self {
            positions: soup.positions.iter().map(|&p| Some(p)).collect(),
            faces: soup.faces().map(|f| Some(f.to_vec())).collect(),
        }
    }

    pub(super) fn live_faces(&self) -> impl Iterator<Item = (usize, &Vec<u32>)> {
        self.faces
            .iter()
            .enumerate()
            .filter_map(|(i, f)| f.as_ref().map(|f| (i, f)))
    }

    /// The live faces, canonical and sorted.
    pub fn face_set(&self) -> Vec<Vec<u32>> {
        let mut out: Vec<Vec<u32>> = self.live_faces().map(|(_, f)| canonical_face(f)).collect();
        out.sort();
        out
    }

    /// The soup of the live faces, all vertex slots kept (a deleted vertex at the origin).
    pub(super) fn soup(
        &self,
        replace: Option<(usize, Option<Vec<u32>>)>,
        extra: &[Vec<u32>],
    ) -> PolygonSoup {
        let positions = self
            .positions
            .iter()
            .map(|p| p.unwrap_or(DVec3::ZERO))
            .collect();
        let mut faces: Vec<Vec<u32>> = Vec::new();
        for (i, f) in self.faces.iter().enumerate() {
            let f = match &replace {
                Some((j, g)) if *j == i => g.clone(),
                _ => f.clone(),
            };
            faces.extend(f);
        }
        faces.extend(extra.iter().cloned());
        PolygonSoup::from_polygons(positions, &faces)
    }

    /// Would this face list be an oriented manifold with one fan per vertex?
    pub(super) fn manifold(soup: &PolygonSoup) -> bool {
        soup.connectivity()
            .and_then(|c| c.check_vertex_fans(soup))
            .is_ok()
    }

    pub(super) fn live_vertex(&self, v: u32) -> bool {
        self.positions.get(v as usize).is_some_and(|p| p.is_some())
    }

    /// The face holding the directed edge a → b, with the corner of a.
    pub(super) fn face_with(&self, a: u32, b: u32) -> Option<(usize, usize)> {
        self.live_faces().find_map(|(i, f)| {
            let k = f.len();
            (0..k)
                .find(|&c| f[c] == a && f[(c + 1) % k] == b)
                .map(|c| (i, c))
        })
    }

    /// The vertices that share a face side with `v`, sorted.
    pub fn neighbours(&self, v: u32) -> Vec<u32> {
        let mut out = Vec::new();
        for (_, f) in self.live_faces() {
            let k = f.len();
            for c in 0..k {
                if f[c] == v {
                    out.push(f[(c + 1) % k]);
                    out.push(f[(c + k - 1) % k]);
                }
            }
        }
        out.sort_unstable();
        out.dedup();
        out
    }

    pub(super) fn is_boundary_edge(&self, a: u32, b: u32) -> bool {
        self.face_with(a, b).is_none() || self.face_with(b, a).is_none()
    }

    /// Does `v` have an edge with a face on one side only?
    pub fn is_boundary_vertex(&self, v: u32) -> bool {
        self.neighbours(v)
            .into_iter()
            .any(|w| self.is_boundary_edge(v, w))
    }

    pub(super) fn triangle(&self, f: usize) -> bool {
        self.faces[f].as_ref().is_some_and(|f| f.len() == 3)
    }

    pub(super) fn third(&self, f: usize, c: usize) -> u32 {
        let face = self.faces[f].as_ref().expect("live");
        face[(c + 2) % 3]
    }

    /// Are the live vertices' positions distinct (as explicit storage needs)?
    pub(super) fn positions_distinct(&self) -> bool {
        let mut keys: Vec<[u64; 3]> = self
            .positions
            .iter()
            .flatten()
            .map(|p| p.to_array().map(|x| (x + 0.0).to_bits()))
            .collect();
        let n = keys.len();
        keys.sort_unstable();
        keys.dedup();
        keys.len() == n
    }

    /// The live vertices inside `b`.
    pub(super) fn vertices_in(&self, b: &Aabb) -> Vec<u32> {
        (0..self.positions.len() as u32)
            .filter(|&v| self.positions[v as usize].is_some_and(|p| b.contains(p)))
            .collect()
    }

    /// The live faces whose corners are all inside `b`, canonical and sorted.
    pub(super) fn faces_in(&self, b: &Aabb) -> Vec<Vec<u32>> {
        let mut out: Vec<Vec<u32>> = self
            .live_faces()
            .filter(|(_, f)| {
                f.iter()
                    .all(|&v| self.positions[v as usize].is_some_and(|p| b.contains(p)))
            })
            .map(|(_, f)| canonical_face(f))
            .collect();
        out.sort();
        out
    }

    /// The number of live faces.
    pub fn num_live_faces(&self) -> usize {
        self.live_faces().count()
    }

    /// Removes deleted slots, keeping the order of the others.
    pub fn collect(&mut self) {
        let mut map = vec![u32::MAX; self.positions.len()];
        let mut next = 0;
        for (v, p) in self.positions.iter().enumerate() {
            if p.is_some() {
                map[v] = next;
                next += 1;
            }
        }
        self.positions.retain(|p| p.is_some());
        self.faces.retain(|f| f.is_some());
        for f in self.faces.iter_mut().flatten() {
            for v in f.iter_mut() {
                *v = map[*v as usize];
            }
        }
    }
}

/// The starting mesh of a seed: a canonical mesh or a random one, whichever `M` builds.
pub fn start_mesh(seed: u64) -> PolygonSoup {
    let canonical = meshes::canonical();
    let pick = (seed % (canonical.len() as u64 + 4)) as usize;
    if pick < canonical.len() {
        canonical[pick].soup.clone()
    } else {
        meshes::random_mesh(
            seed,
            RandomMeshParams {
                triangles_only: !seed.is_multiple_of(3),
                max_side: 5,
                keep: 0.9,
            },
        )
    }
}
