//! The half-edge arrays every half-edge structure is built from, made from the soup's shared
//! edge analysis ([`crate::Connectivity`], one pass by buckets for a mesh with manifold edges)
//! and its fan walk, without hash maps: linear in the corners for bounded valence.

use crate::core::error::{Error, Result};
use crate::core::soup::{Connectivity, PolygonSoup};

/// The "no element" value of the `u32` link arrays.
pub(crate) const NONE: u32 = u32::MAX;

/// Half-edge connectivity as plain `u32` arrays (structure of arrays).
///
/// Edge `e` of [`crate::Connectivity`] (numbered by first appearance) owns half-edges `2e` and
/// `2e + 1`, so the twin of `h` is `h ^ 1`. Half-edge `2e` runs along the corner that first
/// uses the edge; `2e + 1` runs along the face on the other side or, on the boundary, is an
/// explicit boundary half-edge with no face (OpenMesh's convention) whose `next` is the
/// boundary half-edge leaving its end vertex, so boundary loops are cycles of `next` as faces are.
#[derive(Clone, Debug)]
pub struct HalfEdgeArrays {
    /// `vertex[h]`: the vertex half-edge `h` starts at (the lecture's `HE_edge::vert`).
    pub(crate) vertex: Vec<u32>,
    /// `next[h]`: the next half-edge around `h`'s face or boundary loop (`HE_edge::next`).
    pub(crate) next: Vec<u32>,
    /// `face[h]`: the face `h` borders, [`NONE`] for a boundary half-edge (`HE_edge::face`).
    pub(crate) face: Vec<u32>,
    /// `vertex_half_edge[v]`: a half-edge leaving `v` (`HE_vert::edge`), the boundary one when
    /// `v` is on the boundary (so boundary tests are O(1)); [`NONE`] for an unused vertex.
    pub(crate) vertex_half_edge: Vec<u32>,
    /// `face_half_edge[f]`: the half-edge leaving face `f`'s first corner (`HE_face::edge`).
    pub(crate) face_half_edge: Vec<u32>,
}

impl HalfEdgeArrays {
    /// Builds the arrays of `soup`, refusing non-manifold edges, inconsistent orientation and
    /// non-manifold vertices (a vertex with several fans has several outgoing boundary
    /// half-edges, and one `vertex_half_edge` cannot reach them all by rotation).
    pub(crate) fn from_soup(soup: &PolygonSoup) -> Result<Self> {
        let conn = soup.manifold_connectivity()?;
        // Half-edge ids stay below 2^31, so walks may use the top bit as a mark.
        let num_half_edges = 2 * conn.num_edges() as u64;
        if num_half_edges >= 1 << 31 {
            return Err(Error::TooLarge {
                what: "half-edges",
                count: num_half_edges,
            });
        }
        let nh = num_half_edges as usize;
        let indices = soup.indices();
        // Per corner, the half-edge that runs along it (leaving its vertex inside its face).
        let corner_half_edge: Vec<u32> = (0..soup.num_corners())
            .map(|c| {
                let e = conn.corner_edge[c];
                if conn.edge_corners[e as usize][0] as usize == c {
                    2 * e
                } else {
                    2 * e + 1
                }
            })
            .collect();
        // The edge analysis is not read past the corners' half-edges but for each corner's
        // face: each corner's edge and each edge's corners are dropped before the arrays are
        // made, the corners' faces once they are (the same passes: the boundary is found in
        // `face`, its start in `vertex` and `next`).
        let Connectivity {
            edge_corners,
            corner_edge,
            corner_face,
        } = conn;
        drop((corner_edge, edge_corners));
        let next_corner = |c: usize| soup.next_corner(c, corner_face[c] as usize);

        let mut vertex = vec![NONE; nh];
        let mut face = vec![NONE; nh];
        let mut next = vec![NONE; nh];
        let mut vertex_half_edge = vec![NONE; soup.num_vertices()];
        for (c, &h) in corner_half_edge.iter().enumerate() {
            vertex[h as usize] = indices[c];
            face[h as usize] = corner_face[c];
            next[h as usize] = corner_half_edge[next_corner(c)];
            vertex_half_edge[indices[c] as usize] = h;
        }
        let face_half_edge = soup
            .offsets()
            .iter()
            .take(soup.num_faces())
            .map(|&c| corner_half_edge[c as usize])
            .collect();
        drop((corner_half_edge, corner_face));
        // Boundary half-edges: edge e's half-edge 2e runs along a corner, 2e + 1 along the
        // face on the other side, if there is one (a face in `face`). A boundary half-edge
        // starts where its twin ends, where the twin's successor starts; each one is then the
        // (only, as every vertex is one fan) boundary half-edge leaving its start vertex.
        let mut boundary = Vec::new();
        for b in (1..nh as u32).step_by(2) {
            if face[b as usize] == NONE {
                let start = vertex[next[(b ^ 1) as usize] as usize];
                vertex[b as usize] = start;
                vertex_half_edge[start as usize] = b;
                boundary.push(b);
            }
        }
        // A boundary half-edge ends where its twin starts; its successor leaves that vertex.
        for b in boundary {
            let end = vertex[(b ^ 1) as usize];
            next[b as usize] = vertex_half_edge[end as usize];
        }
        Ok(Self {
            vertex,
            next,
            face,
            vertex_half_edge,
            face_half_edge,
        })
    }

    /// Number of half-edges (twice the edges).
    pub(crate) fn num_half_edges(&self) -> usize {
        self.vertex.len()
    }

    /// Bytes of the arrays.
    pub(crate) fn heap_bytes(&self) -> usize {
        4 * (self.vertex.capacity()
            + self.next.capacity()
            + self.face.capacity()
            + self.vertex_half_edge.capacity()
            + self.face_half_edge.capacity())
    }
}
