//! The fans of [`Connectivity`]'s vertices: whether every vertex's star is one fan, which is
//! what the structures without non-manifold vertices ask on every construction (a walk around
//! each vertex), and how many fans each vertex has, which is what the errors and the checks
//! report (union-find over corners).

use super::{Connectivity, PolygonSoup};
use crate::core::error::{Error, Result};

impl Connectivity {
    /// Fails with [`Error::NonManifoldVertex`] on the first vertex whose star is not one fan.
    ///
    /// The answer for a mesh that passes is [`Connectivity::every_vertex_one_fan`], a walk;
    /// only a mesh that fails pays for counting the fans ([`Connectivity::vertex_fans`]), to
    /// name the first vertex with several.
    pub fn check_vertex_fans(&self, soup: &PolygonSoup) -> Result<()> {
        if self.every_vertex_one_fan(soup) {
            return Ok(());
        }
        match self
            .vertex_fans(soup)
            .iter()
            .enumerate()
            .find(|(_, &n)| n > 1)
        {
            Some((v, &fans)) => Err(Error::NonManifoldVertex {
                vertex: v as u32,
                fans: fans as usize,
            }),
            // Only a pair of the lenient analysis running one way makes the walk stop where
            // union-find joins; union-find is the definition.
            None => Ok(()),
        }
    }

    /// Fails with [`Error::StarTooLarge`] when the vertices' face counts, squared and summed,
    /// pass 16 a corner (a regular mesh takes about 6) plus 2^24 (a fraction of a second of
    /// such steps, so that a mesh with a few vertices of a few thousand faces, the caps of a
    /// finely divided cylinder, still builds). In time linear in the soup.
    ///
    /// What it guards: a construction whose every face added at a vertex searches the
    /// vertex's half-edges takes time quadratic in a vertex's faces. The C++ halfedge
    /// libraries (CGAL's Surface_mesh even in order; OpenMesh when the faces come in an order
    /// that leaves several fans open, or for a vertex of several fans, which it links into one
    /// cycle) and lox's half-edge and directed-edge meshes (one fan in shuffled order) do:
    /// 50,000 triangles around one vertex took OpenMesh minutes as separate fans and 14 s as
    /// one fan in shuffled order, Surface_mesh 7 s as one fan in order; lox's meshes took 15
    /// to 23 times as long for one shuffled fan grown 4× (5,000 to 20,000 triangles). Those
    /// adapters run this before the library sees the soup; the lab's own constructions do not
    /// need it.
    pub fn check_star_sizes(&self, soup: &PolygonSoup) -> Result<()> {
        let mut faces = vec![0u32; soup.num_vertices()];
        for &v in soup.indices() {
            faces[v as usize] += 1;
        }
        let steps: u64 = faces.iter().map(|&n| u64::from(n) * u64::from(n)).sum();
        let budget = 16 * soup.num_corners() as u64 + (1 << 24);
        if steps <= budget {
            return Ok(());
        }
        let (vertex, &most) = faces
            .iter()
            .enumerate()
            .max_by_key(|&(_, n)| *n)
            .expect("steps past the budget: a vertex with faces");
        Err(Error::StarTooLarge {
            vertex: vertex as u32,
            faces: most as usize,
            fans: self.vertex_fans(soup)[vertex] as usize,
            steps,
            budget,
        })
    }

    /// Is every used vertex's star one fan? From one corner of each vertex, the walk turns
    /// across interior edges both ways until it comes back or meets the boundary, counting the
    /// corners it reaches; the walks reach all corners exactly when every vertex is one fan (a
    /// walk stays in the fan it starts in). A pair of the lenient analysis running one way
    /// stops the walk where union-find joins the two corners, so there the walk may say
    /// `false` for a vertex union-find counts as one fan, never `true` for one it does not.
    /// O(c) for c corners (each step reads the twin through `corner_edge` and `edge_corners`,
    /// then the face's offsets), against union-find's O(c α(c)) with a per-corner forest.
    ///
    /// Every walk ends: `leaving` and `entering` are inverse one-to-one steps (a twin corner
    /// is an involution, `next_corner` a permutation), so from `s` they trace a cycle back to
    /// `s` or a path that ends at the boundary, never a loop that misses `s`.
    pub fn every_vertex_one_fan(&self, soup: &PolygonSoup) -> bool {
        let indices = soup.indices();
        let nc = indices.len();
        // start[v]: one corner of v (the last), u32::MAX for an unused vertex.
        let mut start = vec![u32::MAX; soup.num_vertices()];
        for (c, &v) in indices.iter().enumerate() {
            start[v as usize] = c as u32;
        }
        let face = |c: usize| self.corner_face[c] as usize;
        // A corner at v, turned across the edge leaving it (`Some` only across an interior
        // edge whose twin corner, once stepped to its next corner, is at v again: a pair
        // of the lenient analysis running one way is not walked).
        let leaving = |c: usize| {
            let t = self.twin_corner(c)?;
            let n = soup.next_corner(t, face(t));
            (indices[n] == indices[c]).then_some(n)
        };
        // The same across the edge entering it.
        let entering = |c: usize| {
            let t = self.twin_corner(soup.prev_corner(c, face(c)))?;
            (indices[t] == indices[c]).then_some(t)
        };
        let mut reached = 0usize;
        for &s in start.iter().filter(|&&s| s != u32::MAX) {
            let s = s as usize;
            reached += 1;
            let mut c = s;
            let mut closed = false;
            while let Some(n) = leaving(c) {
                if n == s {
                    closed = true;
                    break;
                }
                reached += 1;
                c = n;
            }
            if !closed {
                let mut c = s;
                while let Some(n) = entering(c) {
                    reached += 1;
                    c = n;
                }
            }
        }
        reached == nc
    }

    /// Per vertex, the number of fans its faces fall into (0 for an unused vertex, 1 for a
    /// manifold vertex). Union-find over corners joined across interior edges, O(c α(c)).
    pub fn vertex_fans(&self, soup: &PolygonSoup) -> Vec<u32> {
        // Counted on the forest itself: constructions call this, and their timings and peaks
        // are measured, so no per-corner array beyond the forest.
        let mut parent = self.fan_forest(soup);
        let mut fans = vec![0u32; soup.num_vertices()];
        for c in 0..soup.num_corners() {
            if find_root(&mut parent, c as u32) == c as u32 {
                fans[soup.indices[c] as usize] += 1;
            }
        }
        fans
    }

    /// Per corner, the fan of its vertex it lies in, named by one corner of that fan (the
    /// same for the whole fan): corners at one vertex are in one fan when a walk across
    /// interior edges (edges of exactly two corners) joins their faces around the vertex. A
    /// non-manifold edge joins nothing: its faces meet there as at a cut. O(c α(c)).
    pub fn corner_fans(&self, soup: &PolygonSoup) -> Vec<u32> {
        let mut parent = self.fan_forest(soup);
        for c in 0..parent.len() as u32 {
            parent[c as usize] = find_root(&mut parent, c);
        }
        parent
    }

    /// The union-find forest over corners of [`Connectivity::corner_fans`]: corners that meet
    /// at a vertex across an interior edge are joined.
    pub(crate) fn fan_forest(&self, soup: &PolygonSoup) -> Vec<u32> {
        let mut parent: Vec<u32> = (0..soup.num_corners() as u32).collect();
        for &[c0, c1] in &self.edge_corners {
            if c1 == u32::MAX {
                continue;
            }
            let (c0, c1) = (c0 as usize, c1 as usize);
            let n0 = soup.next_corner(c0, self.corner_face[c0] as usize);
            let n1 = soup.next_corner(c1, self.corner_face[c1] as usize);
            // c0 goes a->b, c1 goes b->a: at a, corners c0 and n1 meet; at b, n0 and c1. (A
            // pair of the lenient analysis may both go a->b: then c0, c1 meet at a, n0, n1 at b.)
            let same_direction = soup.indices[c0] == soup.indices[c1];
            let meetings = if same_direction {
                [(c0, c1), (n0, n1)]
            } else {
                [(c0, n1), (n0, c1)]
            };
            for (x, y) in meetings {
                let (rx, ry) = (
                    find_root(&mut parent, x as u32),
                    find_root(&mut parent, y as u32),
                );
                if rx != ry {
                    parent[rx as usize] = ry;
                }
            }
        }
        parent
    }
}

/// The root of `x` in a union-find forest, halving the path on the way.
pub(crate) fn find_root(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let p = parent[parent[x as usize] as usize];
        parent[x as usize] = p;
        x = p;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::meshes::{self, RandomMeshParams};
    use proptest::prelude::*;

    /// The walk's answer is union-find's: no vertex with more than one fan.
    fn walk_agrees(soup: &PolygonSoup) -> std::result::Result<(), TestCaseError> {
        let c = soup
            .connectivity()
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        let one_fan_each = c.vertex_fans(soup).iter().all(|&n| n <= 1);
        prop_assert_eq!(c.every_vertex_one_fan(soup), one_fan_each);
        prop_assert_eq!(c.check_vertex_fans(soup).is_ok(), one_fan_each);
        Ok(())
    }

    #[test]
    fn the_walk_finds_the_bowtie_and_passes_the_other_canonical_meshes() {
        let mut several = Vec::new();
        for m in meshes::canonical() {
            let c = m.soup.connectivity().unwrap();
            walk_agrees(&m.soup).unwrap_or_else(|e| panic!("{}: {e}", m.name));
            if !c.every_vertex_one_fan(&m.soup) {
                several.push(m.name);
            }
        }
        assert_eq!(several, ["bowtie"]);
    }

    proptest! {
        /// Random soups over few vertices, analysed leniently (non-manifold edges and pairs
        /// running one way kept): the walk ends, and it never passes a vertex of several fans.
        #[test]
        fn the_walk_is_safe_on_the_lenient_analysis(soup in super::super::random_soups()) {
            let (c, _) = Connectivity::analyse(&soup, false);
            if c.every_vertex_one_fan(&soup) {
                prop_assert!(c.vertex_fans(&soup).iter().all(|&n| n <= 1));
            }
        }

        /// Random subsets of a grid's cells: cells that meet only at a corner make vertices
        /// of two or more fans, open and closed fans both occur, vertices are relabelled.
        #[test]
        fn the_walk_agrees_with_union_find_on_random_meshes(seed in any::<u64>()) {
            walk_agrees(&meshes::random_mesh(seed, RandomMeshParams::default()))?;
        }

        /// Two copies of a closed torus sharing one vertex: two closed fans there, which no
        /// boundary edge gives away.
        #[test]
        fn the_walk_counts_closed_fans(nu in 3usize..6, nv in 3usize..6, shared in 0u32..9) {
            let t = meshes::torus(nu, nv);
            let n = t.num_vertices() as u32;
            let shared = shared % n;
            let mut positions = t.positions.clone();
            positions.extend(t.positions.iter().copied());
            let mut faces: Vec<Vec<u32>> = t.faces().map(<[u32]>::to_vec).collect();
            for f in t.faces() {
                faces.push(f.iter().map(|&v| if v == shared { shared } else { v + n }).collect());
            }
            let soup = PolygonSoup::from_polygons(positions, &faces);
            prop_assert!(!soup.connectivity().unwrap().every_vertex_one_fan(&soup));
            walk_agrees(&soup)?;
        }
    }
}
