//! Splits non-manifold vertices and edges: a vertex whose faces form several fans (two cones
//! touching at their tips; the end points of an edge of three or more faces) becomes one vertex
//! per fan, so that the faces around each vertex form one fan and every edge borders at most
//! two faces.
//!
//! The fans are [`Connectivity::corner_fans`]: corners at a vertex are in one fan when a walk
//! across edges of exactly two faces joins them, so a non-manifold edge is a cut. Once its end
//! points are split, no three of its faces share both ends: around each end point the faces
//! form paths between cuts, and a path has two ends, so at most two of the edge's faces are in
//! one fan there.

use super::{RepairLog, Split};
use crate::core::error::Error;
use crate::core::soup::{Connectivity, PolygonSoup};

/// `soup` with the end points of its non-manifold edges split into one vertex per fan (when
/// `edges`) and its other vertices of several fans too (when `vertices`). The vertex keeps its
/// first fan (in corner order); each other fan gets a new vertex, appended, at its position.
/// Counts and splits go to `log`.
pub(super) fn split(
    soup: &PolygonSoup,
    edges: bool,
    vertices: bool,
    log: &mut RepairLog,
) -> PolygonSoup {
    let (conn, problems) = Connectivity::analyse(soup, false);
    let mut on_non_manifold_edge = vec![false; soup.num_vertices()];
    for problem in &problems {
        if let Error::NonManifoldEdge { a, b, .. } = *problem {
            log.non_manifold_edges += 1;
            on_non_manifold_edge[a as usize] = true;
            on_non_manifold_edge[b as usize] = true;
        }
    }
    if !edges && !vertices {
        return soup.clone();
    }
    let fan = conn.corner_fans(soup);
    let mut positions = soup.positions.clone();
    // Per fan (named by its root corner): its vertex in the output.
    let mut fan_vertex = vec![u32::MAX; soup.num_corners()];
    // Per vertex: the fans it has, once it has more than one.
    let mut fans = vec![0u32; soup.num_vertices()];
    let mut indices = Vec::with_capacity(soup.num_corners());
    for (c, &v) in soup.indices().iter().enumerate() {
        let root = fan[c] as usize;
        if fan_vertex[root] == u32::MAX {
            let split = if on_non_manifold_edge[v as usize] {
                edges
            } else {
                vertices
            };
            fans[v as usize] += 1;
            fan_vertex[root] = if fans[v as usize] > 1 && split {
                positions.push(soup.positions[v as usize]);
                (positions.len() - 1) as u32
            } else {
                v
            };
        }
        indices.push(fan_vertex[root]);
    }
    for (v, &n) in fans.iter().enumerate().filter(|(_, &n)| n > 1) {
        let split = Split {
            vertex: v as u32,
            fans: n,
        };
        match (on_non_manifold_edge[v], edges, vertices) {
            (true, true, _) => log.edge_splits.push(split),
            (false, _, true) => log.vertex_splits.push(split),
            _ => {}
        }
    }
    let mut out = PolygonSoup::with_capacity(positions.len(), soup.num_faces(), soup.num_corners());
    out.positions = positions;
    for j in 0..soup.num_faces() {
        out.push_face(&indices[soup.face_start(j)..soup.face_start(j + 1)]);
    }
    out
}
