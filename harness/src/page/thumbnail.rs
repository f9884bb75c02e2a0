//! Mesh thumbnails: a shaded orthographic view, flat shading under one fixed light, at every
//! mesh size.
//!
//! A thumbnail draws at most [`FACE_BUDGET`] polygons, so a page of thirty meshes stays a few
//! megabytes. Meshes within the budget are drawn face by face with their edges (the wireframe
//! shows the structure of a small mesh). Larger meshes are simplified *for drawing only* by
//! vertex clustering (Rossignac and Borrel's method): the bounding box is cut into a grid, the
//! vertices of one cell merge into their mean, and each triangle whose corners land in three
//! different cells survives once. The result keeps the silhouette and the shading of the whole
//! surface; drawing every k-th face instead, as before, left scattered dots on scans and a
//! hair-thin wireframe on large meshes.

use glam::DVec3;
use std::fmt::Write;
use topolab_structures::PolygonSoup;

/// At most this many polygons per thumbnail.
pub const FACE_BUDGET: usize = 2500;

/// The direction the view looks from, the light, and the screen axes.
struct View {
    view: DVec3,
    right: DVec3,
    up: DVec3,
    light: DVec3,
}

impl View {
    fn new() -> View {
        let view = DVec3::new(1.0, -1.6, 1.2).normalize();
        let right = DVec3::Z.cross(view).normalize_or(DVec3::X);
        View {
            view,
            right,
            up: view.cross(right),
            light: DVec3::new(0.3, -0.5, 1.0).normalize(),
        }
    }

    /// The grey of a face of normal `n` (unit or zero): ambient plus diffuse from the fixed
    /// light, darker for faces seen from behind (the inside of an open mesh).
    fn grey(&self, n: DVec3) -> u8 {
        let facing = n.dot(self.view);
        let shade = (0.25 + 0.75 * n.dot(self.light).abs()) * if facing < 0.0 { 0.6 } else { 1.0 };
        (60.0 + 170.0 * shade).min(235.0) as u8
    }
}

/// The polygons to draw: the faces themselves within the budget, else the clustered triangles.
fn polygons(soup: &PolygonSoup) -> Vec<Vec<DVec3>> {
    if soup.num_faces() <= FACE_BUDGET {
        return soup
            .faces()
            .map(|f| f.iter().map(|&v| soup.positions[v as usize]).collect())
            .collect();
    }
    let (lo, hi) = bounds(soup);
    let extent = (hi - lo).max(DVec3::splat(1e-12));
    // A surface crosses about (cells per axis)² cells, each giving about two triangles: start
    // from the budget and shrink the grid until the result fits.
    let mut cells = ((FACE_BUDGET as f64 / 2.0).sqrt() * 1.6) as usize;
    loop {
        let tris = cluster(soup, lo, extent, cells.max(2));
        if tris.len() <= FACE_BUDGET || cells <= 2 {
            return tris;
        }
        let shrink = (FACE_BUDGET as f64 / tris.len() as f64).sqrt() * 0.95;
        cells = ((cells as f64 * shrink) as usize).min(cells - 1);
    }
}

fn bounds(soup: &PolygonSoup) -> (DVec3, DVec3) {
    soup.positions
        .iter()
        .filter(|p| p.is_finite())
        .fold((DVec3::MAX, DVec3::MIN), |(a, b), p| (a.min(*p), b.max(*p)))
}

/// Vertex clustering on a grid of `n` cells per axis (the longest axis; the others in
/// proportion): each face, fanned into triangles, becomes the triangle of its corners'
/// cells when they are three different cells; duplicates are kept once.
fn cluster(soup: &PolygonSoup, lo: DVec3, extent: DVec3, n: usize) -> Vec<Vec<DVec3>> {
    let step = extent.max_element() / n as f64;
    let dims = (extent / step).ceil().max(DVec3::ONE);
    let (nx, ny) = (dims.x as u64 + 1, dims.y as u64 + 1);
    let cell_of = |p: DVec3| -> u64 {
        let c = ((p - lo) / step).floor().max(DVec3::ZERO);
        c.x as u64 + nx * (c.y as u64 + ny * c.z as u64)
    };
    let keys: Vec<u64> = soup.positions.iter().map(|&p| cell_of(p)).collect();
    // Dense cluster numbers, and each cluster's mean position.
    let mut sorted: Vec<u64> = keys.clone();
    sorted.sort_unstable();
    sorted.dedup();
    let id = |k: u64| sorted.binary_search(&k).unwrap_or(0) as u32;
    let mut sum = vec![DVec3::ZERO; sorted.len()];
    let mut count = vec![0u32; sorted.len()];
    for (p, &k) in soup.positions.iter().zip(&keys) {
        let c = id(k) as usize;
        sum[c] += *p;
        count[c] += 1;
    }
    let mut tris: Vec<([u32; 3], [u32; 3])> = Vec::new();
    for f in soup.faces() {
        let c: Vec<u32> = f.iter().map(|&v| id(keys[v as usize])).collect();
        for i in 1..c.len().saturating_sub(1) {
            let t = [c[0], c[i], c[i + 1]];
            if t[0] != t[1] && t[1] != t[2] && t[0] != t[2] {
                let mut key = t;
                key.sort_unstable();
                tris.push((key, t));
            }
        }
    }
    tris.sort_unstable_by_key(|t| t.0);
    tris.dedup_by_key(|t| t.0);
    tris.into_iter()
        .map(|(_, t)| {
            t.iter()
                .map(|&c| sum[c as usize] / count[c as usize].max(1) as f64)
                .collect()
        })
        .collect()
}

/// A shaded orthographic thumbnail of `soup`, `size` pixels square (see the module docs).
pub fn thumbnail(soup: &PolygonSoup, size: f64) -> String {
    let v = View::new();
    let (lo, hi) = bounds(soup);
    let centre = (lo + hi) * 0.5;
    let scale = size * 0.45 / ((hi - lo).length() * 0.5).max(1e-12);
    let polys = polygons(soup);
    // Small meshes show their edges; a simplified one is drawn edge-less (its clusters'
    // triangles are not the mesh's faces), each polygon outlined in its own grey so that no
    // seam shows between neighbours.
    let wireframe = soup.num_faces() <= FACE_BUDGET;
    let mut drawn: Vec<(f64, String)> = Vec::with_capacity(polys.len());
    for ps in polys {
        let ps: Vec<DVec3> = ps.into_iter().map(|p| p - centre).collect();
        let mut n = DVec3::ZERO;
        for i in 0..ps.len() {
            n += ps[i].cross(ps[(i + 1) % ps.len()]);
        }
        let g = v.grey(n.normalize_or_zero());
        let b = g.saturating_add(15);
        let depth = ps.iter().map(|p| p.dot(v.view)).sum::<f64>() / ps.len() as f64;
        let mut pts = String::new();
        for p in &ps {
            let _ = write!(
                pts,
                "{:.1},{:.1} ",
                size / 2.0 + p.dot(v.right) * scale,
                size / 2.0 - p.dot(v.up) * scale
            );
        }
        let stroke = if wireframe {
            r#"stroke="rgb(40,40,60)" stroke-width="0.3""#.to_string()
        } else {
            format!(r#"stroke="rgb({g},{g},{b})" stroke-width="0.4""#)
        };
        drawn.push((
            depth,
            format!(r#"<polygon points="{pts}" fill="rgb({g},{g},{b})" {stroke}/>"#),
        ));
    }
    drawn.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut s = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{size}" height="{size}" viewBox="0 0 {size} {size}">"#
    );
    for (_, p) in drawn {
        s.push_str(&p);
    }
    s.push_str("</svg>");
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::meshes;

    /// The fill greys of a thumbnail's polygons.
    fn greys(svg: &str) -> Vec<u8> {
        svg.match_indices("fill=\"rgb(")
            .filter_map(|(i, m)| {
                let rest = &svg[i + m.len()..];
                rest[..rest.find(',')?].parse().ok()
            })
            .collect()
    }

    #[test]
    fn a_large_mesh_is_simplified_to_a_shaded_surface_within_the_budget() {
        let soup = meshes::from_spec("torus:200000").unwrap();
        let svg = thumbnail(&soup, 140.0);
        let n = svg.matches("<polygon").count();
        // Within the budget, yet far more than scattered samples: a closed surface.
        assert!((FACE_BUDGET / 4..=FACE_BUDGET).contains(&n), "{n} polygons");
        // Shaded: many different greys, not one flat colour or a wireframe.
        let mut g = greys(&svg);
        g.sort_unstable();
        g.dedup();
        assert!(g.len() >= 20, "{} greys", g.len());
        // Every polygon is a clustered triangle.
        assert!(svg
            .split("<polygon points=\"")
            .skip(1)
            .all(|p| p[..p.find('"').unwrap()].split_whitespace().count() == 3));
    }

    #[test]
    fn clustering_covers_the_surface_it_simplifies() {
        // The simplified torus's projected area matches the full one's within a few percent:
        // no holes where faces were dropped (sampling every k-th face covered about 1/k).
        let soup = meshes::from_spec("torus:40000").unwrap();
        let (lo, hi) = bounds(&soup);
        let area = |tris: &[Vec<DVec3>]| -> f64 {
            tris.iter()
                .map(|t| {
                    (1..t.len() - 1)
                        .map(|i| (t[i] - t[0]).cross(t[i + 1] - t[0]).length() / 2.0)
                        .sum::<f64>()
                })
                .sum()
        };
        let full: Vec<Vec<DVec3>> = soup
            .faces()
            .map(|f| f.iter().map(|&v| soup.positions[v as usize]).collect())
            .collect();
        let simple = cluster(&soup, lo, hi - lo, 30);
        assert!(simple.len() < full.len() / 4);
        let ratio = area(&simple) / area(&full);
        assert!((0.85..1.05).contains(&ratio), "area ratio {ratio}");
    }

    #[test]
    fn a_small_mesh_is_drawn_face_by_face_with_its_edges() {
        let t = thumbnail(&meshes::torus(6, 4), 120.0);
        assert_eq!(t.matches("<polygon").count(), 48);
        assert_eq!(t.matches("stroke=\"rgb(40,40,60)\"").count(), 48);
    }
}
