//! Meshes to test and measure on: the canonical tiny meshes (each named for what it exercises)
//! and deterministic generators of grids, tori, spheres and random meshes of any size.

use crate::soup::PolygonSoup;
use glam::DVec3;
use rand::seq::SliceRandom;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::TAU;

/// A named tiny mesh with what it is for.
#[derive(Clone, Debug)]
pub struct CanonicalMesh {
    /// Short kebab-case name.
    pub name: &'static str,
    /// What it exercises.
    pub about: &'static str,
    /// The mesh.
    pub soup: PolygonSoup,
    /// `true` when it is one of the regular grids of [`grid`].
    pub grid: bool,
}

/// The open tetrahedron of the CHE chapter's Figure 4.10: a tetrahedron without its base,
/// 4 vertices, 3 triangles, 9 half-edges, 6 edges, 1 boundary curve (vertices 0, 1, 2).
///
/// The figure is a drawing not reproduced in the text; this numbering is ours and is the one
/// every `topolab explain` printout uses: apex 3, triangle t = (t, t+1 mod 3, 3).
pub fn open_tetrahedron() -> PolygonSoup {
    let h = (2.0f64 / 3.0).sqrt();
    PolygonSoup::from_polygons(
        vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(0.5, 0.75f64.sqrt(), 0.0),
            DVec3::new(0.5, 0.75f64.sqrt() / 3.0, h),
        ],
        &[[0, 1, 3], [1, 2, 3], [2, 0, 3]],
    )
}

/// The closed tetrahedron: the open one plus its base (0, 2, 1).
pub fn closed_tetrahedron() -> PolygonSoup {
    let mut s = open_tetrahedron();
    s.push_face(&[0, 2, 1]);
    s
}

/// One triangle: every edge and vertex on the boundary.
pub fn single_triangle() -> PolygonSoup {
    PolygonSoup::from_polygons(vec![DVec3::ZERO, DVec3::X, DVec3::Y], &[[0u32, 1, 2]])
}

/// A cube of six quads, closed, outward oriented.
pub fn quad_cube() -> PolygonSoup {
    let p = (0..8)
        .map(|i| DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64))
        .collect();
    PolygonSoup::from_polygons(
        p,
        &[
            [0u32, 2, 3, 1], // z = 0, normal -z
            [4, 5, 7, 6],    // z = 1
            [0, 1, 5, 4],    // y = 0
            [2, 6, 7, 3],    // y = 1
            [0, 4, 6, 2],    // x = 0
            [1, 3, 7, 5],    // x = 1
        ],
    )
}

/// A strip of `n` quads (open, one boundary curve).
pub fn quad_strip(n: u32) -> PolygonSoup {
    grid(n as usize, 1, false)
}

/// A strip of `2n` triangles (open, one boundary curve).
pub fn triangle_strip(n: u32) -> PolygonSoup {
    grid(n as usize, 1, true)
}

/// An annulus of `n` sectors, triangulated: two boundary curves.
pub fn annulus(n: u32) -> PolygonSoup {
    let mut s = PolygonSoup::new();
    for i in 0..n {
        let a = TAU * i as f64 / n as f64;
        s.push_vertex(DVec3::new(a.cos(), a.sin(), 0.0) * 2.0);
        s.push_vertex(DVec3::new(a.cos(), a.sin(), 0.0));
    }
    for i in 0..n {
        let (o0, i0) = (2 * i, 2 * i + 1);
        let (o1, i1) = (2 * ((i + 1) % n), 2 * ((i + 1) % n) + 1);
        s.push_face(&[i0, o0, o1]);
        s.push_face(&[i0, o1, i1]);
    }
    s
}

/// Two triangles that share only vertex 0: a non-manifold vertex (two fans).
pub fn bowtie() -> PolygonSoup {
    PolygonSoup::from_polygons(
        vec![
            DVec3::ZERO,
            DVec3::new(1.0, 0.5, 0.0),
            DVec3::new(1.0, -0.5, 0.0),
            DVec3::new(-1.0, 0.5, 0.0),
            DVec3::new(-1.0, -0.5, 0.0),
        ],
        &[[0u32, 2, 1], [0, 3, 4]],
    )
}

/// A quad, a triangle and a pentagon glued along edges (mixed k-gons, open).
pub fn mixed_polygons() -> PolygonSoup {
    PolygonSoup::from_polygons(
        vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(0.5, 1.7, 0.0),
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(2.5, 0.7, 0.0),
            DVec3::new(2.0, 1.4, 0.0),
        ],
        &[vec![0u32, 1, 2, 3], vec![3, 2, 4], vec![1, 5, 6, 7, 2]],
    )
}

/// Every canonical tiny mesh, in a fixed order.
pub fn canonical() -> Vec<CanonicalMesh> {
    let m = |name, about, soup, grid| CanonicalMesh {
        name,
        about,
        soup,
        grid,
    };
    vec![
        m(
            "single-triangle",
            "one face, all boundary",
            single_triangle(),
            false,
        ),
        m(
            "open-tetrahedron",
            "the CHE chapter's Figure 4.10: 4 vertices, 3 triangles, 6 edges, 1 boundary curve",
            open_tetrahedron(),
            false,
        ),
        m(
            "closed-tetrahedron",
            "closed, no boundary",
            closed_tetrahedron(),
            false,
        ),
        m("quad-cube", "closed quads (k-gons)", quad_cube(), false),
        m("quad-strip", "open quads", quad_strip(3), true),
        m("triangle-strip", "open triangles", triangle_strip(3), true),
        m("annulus", "two boundary curves", annulus(6), false),
        m("torus", "closed, genus 1", torus(4, 3), false),
        m("grid", "triangulated open grid", grid(3, 2, true), true),
        m("quad-grid", "open quad grid", grid(3, 3, false), true),
        m(
            "mixed-polygons",
            "a quad, a triangle and a pentagon",
            mixed_polygons(),
            false,
        ),
        m(
            "bowtie",
            "a non-manifold vertex (two fans)",
            bowtie(),
            false,
        ),
    ]
}

/// The canonical mesh of a name.
pub fn canonical_by_name(name: &str) -> Option<CanonicalMesh> {
    canonical().into_iter().find(|m| m.name == name)
}

/// An open `nx` × `ny` grid in the z = 0 plane with unit cells: `(nx+1)(ny+1)` vertices,
/// vertex `(i, j)` is `j (nx+1) + i` at `(i, j, 0)`. Cells row by row; each cell is a quad
/// `(a, b, c, d)` or, `triangulated`, the triangles `(a, b, c)` and `(a, c, d)`.
pub fn grid(nx: usize, ny: usize, triangulated: bool) -> PolygonSoup {
    let per = if triangulated { 2 } else { 1 };
    let mut s = PolygonSoup::with_capacity((nx + 1) * (ny + 1), nx * ny * per, nx * ny * 4 + 2);
    for j in 0..=ny {
        for i in 0..=nx {
            s.push_vertex(DVec3::new(i as f64, j as f64, 0.0));
        }
    }
    let w = (nx + 1) as u32;
    for j in 0..ny as u32 {
        for i in 0..nx as u32 {
            let a = j * w + i;
            let (b, c, d) = (a + 1, a + w + 1, a + w);
            if triangulated {
                s.push_face(&[a, b, c]);
                s.push_face(&[a, c, d]);
            } else {
                s.push_face(&[a, b, c, d]);
            }
        }
    }
    s
}

/// A closed triangulated torus of `nu` × `nv` vertices (`2 nu nv` triangles), ordered ring by ring.
///
/// # Panics
/// If `nu < 3` or `nv < 3`.
pub fn torus(nu: usize, nv: usize) -> PolygonSoup {
    assert!(nu >= 3 && nv >= 3, "a torus needs at least 3 x 3 vertices");
    let (r_big, r_small) = (1.0, 0.35);
    let mut s = PolygonSoup::with_capacity(nu * nv, 2 * nu * nv, 6 * nu * nv);
    for i in 0..nu {
        let u = TAU * i as f64 / nu as f64;
        for j in 0..nv {
            let v = TAU * j as f64 / nv as f64;
            let r = r_big + r_small * v.cos();
            s.push_vertex(DVec3::new(r * u.cos(), r * u.sin(), r_small * v.sin()));
        }
    }
    let id = |i: usize, j: usize| ((i % nu) * nv + (j % nv)) as u32;
    for i in 0..nu {
        for j in 0..nv {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            s.push_face(&[a, b, c]);
            s.push_face(&[a, c, d]);
        }
    }
    s
}

/// A torus with about `triangles` triangles (at least 18), rings about three times the tube.
pub fn torus_with_triangles(triangles: usize) -> PolygonSoup {
    let cells = (triangles / 2).max(9) as f64;
    let nv = ((cells / 3.0).sqrt().round() as usize).max(3);
    let nu = ((cells / nv as f64).round() as usize).max(3);
    torus(nu, nv)
}

/// A closed UV sphere: `rings` ≥ 2 latitude bands, `segments` ≥ 3 longitudes, two poles;
/// `2 segments (rings - 1)` triangles.
pub fn sphere(rings: usize, segments: usize) -> PolygonSoup {
    assert!(
        rings >= 2 && segments >= 3,
        "a sphere needs 2 rings and 3 segments"
    );
    let mut s = PolygonSoup::new();
    s.push_vertex(DVec3::Z);
    for r in 1..rings {
        let theta = std::f64::consts::PI * r as f64 / rings as f64;
        for k in 0..segments {
            let phi = TAU * k as f64 / segments as f64;
            s.push_vertex(DVec3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            ));
        }
    }
    let south = s.push_vertex(-DVec3::Z).0;
    let ring = |r: usize, k: usize| (1 + (r - 1) * segments + k % segments) as u32;
    for k in 0..segments {
        s.push_face(&[0, ring(1, k), ring(1, k + 1)]);
    }
    for r in 1..rings - 1 {
        for k in 0..segments {
            let (a, b, c, d) = (
                ring(r, k),
                ring(r + 1, k),
                ring(r + 1, k + 1),
                ring(r, k + 1),
            );
            s.push_face(&[a, b, c]);
            s.push_face(&[a, c, d]);
        }
    }
    for k in 0..segments {
        s.push_face(&[south, ring(rings - 1, k + 1), ring(rings - 1, k)]);
    }
    s
}

/// What kind of random mesh [`random_mesh`] makes.
#[derive(Copy, Clone, Debug)]
pub struct RandomMeshParams {
    /// Only triangles (otherwise a mix of triangles and quads).
    pub triangles_only: bool,
    /// Largest grid side.
    pub max_side: usize,
    /// Probability of keeping each cell (holes make boundaries, and non-manifold vertices).
    pub keep: f64,
}

impl Default for RandomMeshParams {
    fn default() -> Self {
        Self {
            triangles_only: false,
            max_side: 7,
            keep: 0.8,
        }
    }
}

/// A random mesh from `seed`: a random subset of a grid's cells (each cell a quad or two
/// triangles), with vertices relabelled and faces shuffled at random. Unused vertices stay,
/// and cells touching only at a corner make non-manifold vertices: both are intended.
pub fn random_mesh(seed: u64, params: RandomMeshParams) -> PolygonSoup {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let nx = rng.random_range(1..=params.max_side);
    let ny = rng.random_range(1..=params.max_side);
    let w = (nx + 1) as u32;
    let mut s = PolygonSoup::new();
    for j in 0..=ny {
        for i in 0..=nx {
            let jitter = DVec3::new(
                rng.random::<f64>(),
                rng.random::<f64>(),
                rng.random::<f64>(),
            );
            s.push_vertex(DVec3::new(i as f64, j as f64, 0.0) + 0.2 * jitter);
        }
    }
    for j in 0..ny as u32 {
        for i in 0..nx as u32 {
            if !rng.random_bool(params.keep) {
                continue;
            }
            let a = j * w + i;
            let (b, c, d) = (a + 1, a + w + 1, a + w);
            if params.triangles_only || rng.random_bool(0.5) {
                if rng.random_bool(0.5) {
                    s.push_face(&[a, b, c]);
                    s.push_face(&[a, c, d]);
                } else {
                    s.push_face(&[a, b, d]);
                    s.push_face(&[b, c, d]);
                }
            } else {
                s.push_face(&[a, b, c, d]);
            }
        }
    }
    if s.num_faces() == 0 {
        s.push_face(&[0, 1, w + 1]);
    }
    let mut perm: Vec<u32> = (0..s.num_vertices() as u32).collect();
    perm.shuffle(&mut rng);
    let mut order: Vec<u32> = (0..s.num_faces() as u32).collect();
    order.shuffle(&mut rng);
    s.relabel_vertices(&perm).reorder_faces(&order)
}

/// A built-in mesh named on the command line: a canonical mesh name, or a generator with a
/// face count, `torus:N`, `sphere:N`, `grid:N` (triangles) or `quad-grid:N` (quads), for about
/// N faces. `None` for anything else.
pub fn from_spec(spec: &str) -> Option<PolygonSoup> {
    if let Some(m) = canonical_by_name(spec) {
        return Some(m.soup);
    }
    let (kind, n) = spec.split_once(':')?;
    let n: usize = n.replace('_', "").parse().ok()?;
    let n = n.max(2);
    let side = |cells: usize| ((cells as f64).sqrt().round() as usize).max(1);
    match kind {
        "torus" => Some(torus_with_triangles(n)),
        "sphere" => {
            let s = side(n / 2).max(3);
            Some(sphere(s, s))
        }
        "grid" => {
            let s = side(n / 2);
            Some(grid(s, s, true))
        }
        "quad-grid" => {
            let s = side(n);
            Some(grid(s, s, false))
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn canonical_meshes_are_valid_soups() {
        for m in canonical() {
            m.soup.check().unwrap_or_else(|e| panic!("{}: {e}", m.name));
            m.soup
                .connectivity()
                .unwrap_or_else(|e| panic!("{}: {e}", m.name));
        }
    }

    #[test]
    fn open_tetrahedron_counts_match_the_chapter() {
        let s = open_tetrahedron();
        let c = s.connectivity().unwrap();
        assert_eq!(
            (s.num_vertices(), s.num_faces(), s.num_corners()),
            (4, 3, 9)
        );
        assert_eq!(c.num_edges(), 6);
        let boundary = c.edge_corners.iter().filter(|e| e[1] == u32::MAX).count();
        assert_eq!(boundary, 3);
    }

    #[test]
    fn generators_give_closed_surfaces_with_the_right_euler_characteristic() {
        for (s, chi) in [
            (torus(5, 4), 0),
            (sphere(4, 6), 2),
            (closed_tetrahedron(), 2),
        ] {
            let c = s.connectivity().unwrap();
            assert!(c.edge_corners.iter().all(|e| e[1] != u32::MAX));
            let euler = s.num_vertices() as i64 - c.num_edges() as i64 + s.num_faces() as i64;
            assert_eq!(euler, chi);
        }
        let t = torus_with_triangles(1000).num_faces();
        assert!((950..=1050).contains(&t), "{t} triangles");
    }

    #[test]
    fn bowtie_has_a_two_fan_vertex_and_random_meshes_are_reproducible() {
        let b = bowtie();
        assert_eq!(b.connectivity().unwrap().vertex_fans(&b)[0], 2);
        let p = RandomMeshParams::default();
        assert_eq!(random_mesh(7, p), random_mesh(7, p));
        assert_ne!(random_mesh(7, p), random_mesh(8, p));
    }
}
