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
use crate::core::soup::{find_root, Connectivity, PolygonSoup};

/// Splits, in `soup`, the end points of its non-manifold edges into one vertex per fan (when
/// `edges`) and its other vertices of several fans too (when `vertices`). The vertex keeps its
/// first fan (in corner order); each other fan gets a new vertex, appended, at its position.
/// Counts and splits go to `log`.
pub(super) fn split(soup: &mut PolygonSoup, edges: bool, vertices: bool, log: &mut RepairLog) {
    let (conn, problems) = Connectivity::analyse(soup, false);
    let mut on_non_manifold_edge = vec![false; soup.num_vertices()];
    for problem in &problems {
        if let Error::NonManifoldEdge { a, b, .. } = *problem {
            log.non_manifold_edges += 1;
            on_non_manifold_edge[a as usize] = true;
            on_non_manifold_edge[b as usize] = true;
        }
    }
    drop(problems);
    if !edges && !vertices {
        return;
    }
    // Per corner the fan it lies in, named by its root corner; the analysis is not needed
    // past it.
    let mut fan = conn.fan_forest(soup);
    drop(conn);
    let n = soup.num_vertices() as u32;
    // Per fan (named by its root corner): its vertex in the output, a new one numbered from
    // `n` on in corner order; per vertex, the fans it has.
    let mut fan_vertex = vec![u32::MAX; soup.num_corners()];
    let mut fans = vec![0u32; soup.num_vertices()];
    let mut new = 0;
    for c in 0..soup.num_corners() {
        let v = soup.indices()[c];
        let root = find_root(&mut fan, c as u32) as usize;
        if fan_vertex[root] == u32::MAX {
            let split = if on_non_manifold_edge[v as usize] {
                edges
            } else {
                vertices
            };
            fans[v as usize] += 1;
            fan_vertex[root] = if fans[v as usize] > 1 && split {
                new += 1;
                n + new - 1
            } else {
                v
            };
        }
    }
    soup.positions.reserve_exact(new as usize);
    for c in 0..soup.num_corners() {
        let root = find_root(&mut fan, c as u32) as usize;
        let (v, w) = (soup.indices()[c], fan_vertex[root]);
        if w == soup.num_vertices() as u32 {
            // The next new vertex, first met here (they are numbered in corner order).
            soup.positions.push(soup.positions[v as usize]);
        }
        soup.indices_mut()[c] = w;
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
}
