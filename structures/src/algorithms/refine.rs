//! Subdivision of triangle meshes: each level splits every triangle into four, so a real mesh
//! of 75k triangles (CGAL's `bunny00`) becomes 1.2M, 4.8M and 19.3M triangles in 2, 3 and 4
//! levels, the sizes the benchmarks need.
//!
//! The lecture on polygon-mesh data structures asks for refinement ("Verfeinern um genauer zu
//! modellieren", locally and adaptively) and lists a section 4.5 "Verfeinerung von Netzen" in
//! its outline, but that section has no content; the two schemes here are the standard
//! uniform ones (midpoint, and Loop's), not taken from it.
//!
//! Both schemes have the same connectivity; they differ only in where vertices go.
//!
//! | scheme | old vertices | new vertex of edge (a, b) |
//! |---|---|---|
//! | midpoint | stay | (a + b) / 2 |
//! | Loop | (1 - n β) v + β Σ neighbours; on the boundary ¾ v + ⅛ (two boundary neighbours) | ⅜ (a + b) + ⅛ (c + d), c and d opposite; on the boundary (a + b) / 2 |
//!
//! with β = (5/8 - (3/8 + ¼ cos(2π/n))²) / n for valence n (Loop's original weights). A vertex
//! that touches more than two boundary edges, or no face, stays where it is.
//!
//! Numbering, as real tools do: old vertex i stays vertex i, and the new vertex of edge e (edges
//! numbered by first appearance, see [`Connectivity`]) is appended as vertex `V + e`. Face j's
//! four children are faces `4j..4j+4`: the three corner triangles (at its corners 0, 1, 2),
//! then the middle one. Appending keeps old vertices in place but scatters each new vertex far
//! from its neighbours in memory: the vertex order a refined mesh really has (see `ordering`).
//!
//! Cost per level: one edge analysis (one pass by buckets, see [`Connectivity`]), then
//! O(V + E + F).
//! Memory: the input, its [`Connectivity`] and the output (about 4 times the input).

use crate::core::error::{Error, Result};
use crate::core::soup::{Connectivity, PolygonSoup};
use glam::DVec3;
use std::f64::consts::TAU;

/// Where a subdivision level puts the vertices (the connectivity is the same for both).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Scheme {
    /// New vertices at edge midpoints, old vertices unchanged: the same shape, finer.
    Midpoint,
    /// Loop subdivision: a smooth (C² away from extraordinary vertices) limit surface.
    Loop,
}

impl Scheme {
    /// Every scheme.
    pub const ALL: [Scheme; 2] = [Scheme::Midpoint, Scheme::Loop];

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Scheme::Midpoint => "midpoint",
            Scheme::Loop => "loop",
        }
    }

    /// The scheme of a command-line name.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// One level of subdivision: four triangles for each triangle.
///
/// Fails on what it cannot subdivide: a face that is not a triangle
/// ([`Error::NotTriangles`]), or what [`PolygonSoup::connectivity`] refuses (bad indices,
/// non-manifold edges, inconsistent orientation).
pub fn subdivide(soup: &PolygonSoup, scheme: Scheme) -> Result<PolygonSoup> {
    if let Some((face, corners)) = soup.first_non_triangle() {
        return Err(Error::NotTriangles {
            structure: match scheme {
                Scheme::Midpoint => "midpoint subdivision",
                Scheme::Loop => "Loop subdivision",
            },
            face,
            corners,
        });
    }
    let conn = soup.connectivity()?;
    let (nv, ne, nf) = (soup.num_vertices(), conn.num_edges(), soup.num_faces());
    let mut out = PolygonSoup::with_capacity(nv + ne, 4 * nf, 12 * nf);
    out.positions = match scheme {
        Scheme::Midpoint => midpoint_positions(soup, &conn),
        Scheme::Loop => loop_positions(soup, &conn),
    };
    let indices = soup.indices();
    for j in 0..nf {
        let c = 3 * j;
        let [v0, v1, v2] = [indices[c], indices[c + 1], indices[c + 2]];
        // m_i: the new vertex of the edge leaving corner i.
        let m = |i: usize| (nv + conn.corner_edge[c + i] as usize) as u32;
        let (m0, m1, m2) = (m(0), m(1), m(2));
        out.push_face(&[v0, m0, m2]);
        out.push_face(&[m0, v1, m1]);
        out.push_face(&[m2, m1, v2]);
        out.push_face(&[m0, m1, m2]);
    }
    Ok(out)
}

/// `levels` levels of [`subdivide`]; `progress` hears each level's result (level from 1).
/// Takes the soup by value so that each level's input is freed as soon as the next exists:
/// peak memory is one level's input, its edge analysis and its output.
pub fn subdivide_levels(
    soup: PolygonSoup,
    scheme: Scheme,
    levels: usize,
    mut progress: impl FnMut(usize, &PolygonSoup),
) -> Result<PolygonSoup> {
    let mut current = soup;
    for level in 1..=levels {
        current = subdivide(&current, scheme)?;
        progress(level, &current);
    }
    Ok(current)
}

/// The end vertices of edge `e`: `a -> b` as its first corner traverses it.
fn edge_ends(soup: &PolygonSoup, conn: &Connectivity, e: usize) -> (usize, usize) {
    let c = conn.edge_corners[e][0] as usize;
    let next = soup.next_corner(c, conn.corner_face[c] as usize);
    (soup.indices()[c] as usize, soup.indices()[next] as usize)
}

/// The vertex of a triangle corner's face opposite the edge leaving it.
fn opposite(soup: &PolygonSoup, conn: &Connectivity, c: usize) -> usize {
    soup.indices()[soup.prev_corner(c, conn.corner_face[c] as usize)] as usize
}

fn midpoint_positions(soup: &PolygonSoup, conn: &Connectivity) -> Vec<DVec3> {
    let p = &soup.positions;
    let mut out = Vec::with_capacity(p.len() + conn.num_edges());
    out.extend_from_slice(p);
    out.extend((0..conn.num_edges()).map(|e| {
        let (a, b) = edge_ends(soup, conn, e);
        (p[a] + p[b]) * 0.5
    }));
    out
}

fn loop_positions(soup: &PolygonSoup, conn: &Connectivity) -> Vec<DVec3> {
    let p = &soup.positions;
    let nv = p.len();
    // Per vertex: sum and number of neighbours, and the same over boundary edges only.
    let mut neighbour_sum = vec![DVec3::ZERO; nv];
    let mut valence = vec![0u32; nv];
    let mut boundary_sum = vec![DVec3::ZERO; nv];
    let mut boundary_edges = vec![0u32; nv];
    for (e, corners) in conn.edge_corners.iter().enumerate() {
        let (a, b) = edge_ends(soup, conn, e);
        neighbour_sum[a] += p[b];
        neighbour_sum[b] += p[a];
        valence[a] += 1;
        valence[b] += 1;
        if corners[1] == u32::MAX {
            boundary_sum[a] += p[b];
            boundary_sum[b] += p[a];
            boundary_edges[a] += 1;
            boundary_edges[b] += 1;
        }
    }
    let mut out = Vec::with_capacity(nv + conn.num_edges());
    out.extend((0..nv).map(|v| match (boundary_edges[v], valence[v]) {
        (0, n) if n > 0 => {
            let n = n as f64;
            let w = 0.375 + 0.25 * (TAU / n).cos();
            let beta = (0.625 - w * w) / n;
            p[v] * (1.0 - n * beta) + neighbour_sum[v] * beta
        }
        (2, _) => p[v] * 0.75 + boundary_sum[v] * 0.125,
        _ => p[v],
    }));
    out.extend(conn.edge_corners.iter().enumerate().map(|(e, &[c0, c1])| {
        let (a, b) = edge_ends(soup, conn, e);
        if c1 == u32::MAX {
            return (p[a] + p[b]) * 0.5;
        }
        let (c, d) = (
            opposite(soup, conn, c0 as usize),
            opposite(soup, conn, c1 as usize),
        );
        (p[a] + p[b]) * 0.375 + (p[c] + p[d]) * 0.125
    }));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::meshes;
    use crate::testing::oracle::Oracle;

    fn euler(s: &PolygonSoup) -> i64 {
        let e = s.connectivity().unwrap().num_edges();
        s.num_vertices() as i64 - e as i64 + s.num_faces() as i64
    }

    fn test_meshes() -> Vec<PolygonSoup> {
        vec![
            meshes::closed_tetrahedron(),
            meshes::open_tetrahedron(),
            meshes::annulus(5),
            meshes::torus(5, 3),
            meshes::perforated_plate(2, 1, 300),
        ]
    }

    #[test]
    fn each_level_has_four_times_the_faces_and_the_same_topology() {
        for scheme in Scheme::ALL {
            for s in test_meshes() {
                let curves = Oracle::new(&s).boundary_curve_count();
                let mut faces = vec![];
                let fine = subdivide_levels(s.clone(), scheme, 2, |_, r| faces.push(r.num_faces()))
                    .unwrap();
                assert_eq!(faces, vec![4 * s.num_faces(), 16 * s.num_faces()]);
                assert_eq!(euler(&fine), euler(&s), "{}", scheme.name());
                assert_eq!(Oracle::new(&fine).boundary_curve_count(), curves);
                fine.connectivity()
                    .unwrap()
                    .check_vertex_fans(&fine)
                    .unwrap();
                assert!(fine.positions.iter().all(|p| p.is_finite()));
            }
        }
    }

    #[test]
    fn old_vertices_keep_their_numbers_and_new_ones_are_appended_per_edge() {
        let s = meshes::open_tetrahedron();
        let conn = s.connectivity().unwrap();
        let fine = subdivide(&s, Scheme::Midpoint).unwrap();
        assert_eq!(fine.num_vertices(), 4 + 6);
        assert_eq!(&fine.positions[..4], &s.positions[..]);
        // Edge 0 leaves corner 0 (vertex 0 -> 1): its midpoint is vertex 4.
        assert_eq!(conn.corner_edge[0], 0);
        assert_eq!(fine.positions[4], (s.positions[0] + s.positions[1]) * 0.5);
        assert_eq!(fine.face(0), &[0, 4, 4 + conn.corner_edge[2]]);
        assert_eq!(
            fine.face(3),
            &[4, 4 + conn.corner_edge[1], 4 + conn.corner_edge[2]]
        );
    }

    #[test]
    fn loop_of_a_closed_mesh_stays_closed_and_shrinks_it() {
        let s = meshes::sphere(6, 8);
        let fine = subdivide_levels(s, Scheme::Loop, 2, |_, _| {}).unwrap();
        let conn = fine.connectivity().unwrap();
        assert!(conn.edge_corners.iter().all(|e| e[1] != u32::MAX));
        // Loop approximates: convex control points move inwards, never outside the unit sphere.
        let max = fine
            .positions
            .iter()
            .map(|p| p.length())
            .fold(0.0, f64::max);
        assert!(max < 1.0 && max > 0.8, "{max}");
    }

    #[test]
    fn polygons_and_bad_input_are_refused_with_an_error() {
        for scheme in Scheme::ALL {
            let err = subdivide(&meshes::quad_cube(), scheme).unwrap_err();
            assert!(matches!(
                err,
                Error::NotTriangles {
                    face: 0,
                    corners: 4,
                    ..
                }
            ));
            let mut bad = meshes::single_triangle();
            bad.push_face(&[0, 1, 7]);
            assert!(matches!(
                subdivide(&bad, scheme),
                Err(Error::IndexOutOfRange { .. })
            ));
        }
        assert_eq!(Scheme::from_name("loop"), Some(Scheme::Loop));
        assert_eq!(Scheme::from_name("butterfly"), None);
    }
}
