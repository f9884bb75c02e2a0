//! The canonical tiny meshes, each named for what it exercises.

use super::generators::{grid, torus};
use crate::core::soup::PolygonSoup;
use glam::DVec3;
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
    fn bowtie_has_a_two_fan_vertex() {
        let b = bowtie();
        assert_eq!(b.connectivity().unwrap().vertex_fans(&b)[0], 2);
    }
}
