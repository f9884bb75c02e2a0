//! The canonical tiny meshes, each named for what it exercises.

use super::generators::grid;
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

/// The open tetrahedron of the CHE thesis chapter's Figure 4.10: a tetrahedron without its base,
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

/// Calls `$callback!` with the one list of canonical meshes, in their fixed order, one entry
/// `test_name => "name", "what it exercises", soup expression, is_grid;` per mesh (after the
/// tokens given behind a `;`, if any). [`canonical`] builds its meshes from it and the
/// [`conformance!`](macro@crate::conformance) macro one test per mesh, so a new canonical mesh
/// is one line here.
#[macro_export]
macro_rules! for_each_canonical_mesh {
    ($($callback:ident)::+ $(; $($args:tt)*)?) => {
        $($callback)::+! { $($($args)*)? ;
            single_triangle => "single-triangle", "one face, all boundary",
                $crate::meshes::single_triangle(), false;
            open_tetrahedron => "open-tetrahedron",
                "the CHE thesis chapter's Figure 4.10: 4 vertices, 3 triangles, 6 edges, 1 boundary curve",
                $crate::meshes::open_tetrahedron(), false;
            closed_tetrahedron => "closed-tetrahedron", "closed, no boundary",
                $crate::meshes::closed_tetrahedron(), false;
            quad_cube => "quad-cube", "closed quads (k-gons)", $crate::meshes::quad_cube(), false;
            quad_strip => "quad-strip", "open quads", $crate::meshes::quad_strip(3), true;
            triangle_strip => "triangle-strip", "open triangles",
                $crate::meshes::triangle_strip(3), true;
            annulus => "annulus", "two boundary curves", $crate::meshes::annulus(6), false;
            torus => "torus", "closed, genus 1", $crate::meshes::torus(4, 3), false;
            grid => "grid", "triangulated open grid", $crate::meshes::grid(3, 2, true), true;
            quad_grid => "quad-grid", "open quad grid", $crate::meshes::grid(3, 3, false), true;
            mixed_polygons => "mixed-polygons", "a quad, a triangle and a pentagon",
                $crate::meshes::mixed_polygons(), false;
            bowtie => "bowtie", "a non-manifold vertex (two fans)", $crate::meshes::bowtie(), false;
        }
    };
}

/// Builds the [`CanonicalMesh`]es of [`for_each_canonical_mesh!`]'s list.
macro_rules! canonical_meshes {
    (; $($test:ident => $name:literal, $about:literal, $soup:expr, $grid:expr;)*) => {
        vec![$(CanonicalMesh { name: $name, about: $about, soup: $soup, grid: $grid }),*]
    };
}

/// Every canonical tiny mesh, in a fixed order.
pub fn canonical() -> Vec<CanonicalMesh> {
    crate::for_each_canonical_mesh!(canonical_meshes)
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
