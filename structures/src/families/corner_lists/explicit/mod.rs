//! # Explicit storage
//!
//! The first and simplest general structure of the lecture on polygon-mesh data structures
//! (*explizite Speicherung*): every polygon lists the coordinates of its own corners, `P =
//! ((x1,y1,z1), ..., (xk,yk,zk))`. There is no shared vertex, so a vertex shared by six triangles
//! is stored six times, and topology is found by comparing coordinates: "How does one find shared
//! edges? All edges of a vertex?" Slow on purpose, faithful to the lecture.
//!
//! | stores | bytes |
//! |---|---|
//! | `corners[c]`: x, y, z of each face corner | 24 per corner (72 per triangle) |
//! | `offsets[f]`: first corner of each face | 4 per face |
//! | id tables (below) | 24 per vertex + a hash map |
//!
//! To speak the lab's common language (vertex `i` of the input is `VertexId(i)`), it also keeps
//! the input's position of each vertex id and a map from coordinates back to ids. They only
//! translate answers into ids; no relation is found through them. Two vertices at the same
//! position cannot be told apart by coordinates, so such input is refused
//! ([`crate::Error::CoincidentVertices`]).
//!
//! `EdgeId`: the first corner (in face order) whose outgoing side is the edge.
//! Costs: as the vertex list (every relation scans the corners, comparing coordinates):
//! R00–R02 O(n), R10 O(log n), R11/R21/R22 O(k·n), R12 O(n), R20 O(k), boundary curves O(n²).
//! Non-manifold vertices are stored and answered correctly.
//!
//! Editing ([`edit`]): the lecture's point about this structure, that geometry cannot be
//! changed independently of topology, as a [`MeshEdit`](crate::MeshEdit) that moves vertices
//! at O(n) (every copy of a position found) and refuses every topological edit as not
//! implemented.

pub mod edit;

use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::reads::{self, read, traced};
use crate::core::soup::PolygonSoup;
use crate::core::topology::{BoundaryCurves, Capabilities, Cost, MeshTopology, Operator};
use crate::families::corner_lists::corner_scan::{scan_cost, Corners, Naming};
use glam::DVec3;
use std::collections::HashMap;
use std::fmt::Write;

/// Polygons as lists of coordinates; see the module docs.
#[derive(Clone, Debug)]
pub struct ExplicitStorage {
    /// Each face's corners as coordinates.
    corners: Corners<DVec3>,
    /// Translation between coordinates and the lab's vertex ids.
    ids: PositionIds,
}

#[derive(Clone, Debug)]
struct PositionIds {
    /// `positions[v]`: the input position of vertex v.
    positions: Vec<DVec3>,
    /// Coordinates (as bits) → vertex id.
    lookup: HashMap<[u64; 3], u32>,
}

#[inline]
fn bits(p: DVec3) -> [u64; 3] {
    // +0.0 and -0.0 are the same point.
    p.to_array().map(|x| (x + 0.0).to_bits())
}

impl Naming<DVec3> for PositionIds {
    #[inline]
    fn key(&self, v: VertexId) -> DVec3 {
        read!("positions", self.positions, v.index())
    }
    #[inline]
    fn vertex(&self, k: DVec3) -> VertexId {
        let v = self.lookup[&bits(k)];
        // The hash map from coordinates to the lab's vertex ids: one read, indexed by its answer.
        traced!("lookup", v, v);
        VertexId(v)
    }
}

impl MeshTopology for ExplicitStorage {
    const NAME: &'static str = "explicit";
    const FAMILY: crate::core::family::Family = crate::core::family::Family::CornerLists;

    fn capabilities() -> Capabilities {
        Capabilities {
            non_manifold_vertices: true,
            distinct_positions: true,
            ..Capabilities::POLYGONS
        }
    }

    fn cost(op: Operator) -> Cost {
        scan_cost(op)
    }

    fn from_soup(soup: &PolygonSoup) -> Result<Self> {
        soup.connectivity()?;
        let mut lookup = HashMap::with_capacity(soup.num_vertices());
        for (v, p) in soup.positions.iter().enumerate() {
            if let Some(first) = lookup.insert(bits(*p), v as u32) {
                return Err(Error::CoincidentVertices {
                    structure: Self::NAME,
                    first,
                    second: v as u32,
                });
            }
        }
        Ok(Self {
            corners: Corners {
                keys: soup
                    .indices()
                    .iter()
                    .map(|&v| soup.positions[v as usize])
                    .collect(),
                offsets: soup.offsets().to_vec(),
            },
            ids: PositionIds {
                positions: soup.positions.clone(),
                lookup,
            },
        })
    }

    #[inline]
    fn num_vertices(&self) -> usize {
        self.ids.positions.len()
    }
    #[inline]
    fn num_edges(&self) -> usize {
        let mut n = 0;
        self.corners.enumerate_edges(&self.ids, |_, _| n += 1);
        n
    }
    #[inline]
    fn num_faces(&self) -> usize {
        self.corners.num_faces()
    }
    #[inline]
    fn num_boundary_edges(&self) -> usize {
        let mut n = 0;
        self.corners
            .enumerate_edges(&self.ids, |_, b| n += b as usize);
        n
    }
    fn for_each_edge(&self, mut f: impl FnMut(EdgeId)) {
        self.corners
            .enumerate_edges(&self.ids, |c, _| f(EdgeId::new(c)));
    }
    #[inline]
    fn position(&self, v: VertexId) -> DVec3 {
        self.ids.positions[v.index()]
    }
    #[inline]
    fn vertex_vertices(&self, v: VertexId, mut f: impl FnMut(VertexId)) {
        self.corners
            .vertex_edges(self.ids.key(v), |_, w| f(self.ids.vertex(w)));
    }
    #[inline]
    fn vertex_edges(&self, v: VertexId, mut f: impl FnMut(EdgeId)) {
        self.corners
            .vertex_edges(self.ids.key(v), |e, _| f(EdgeId::new(e)));
    }
    #[inline]
    fn vertex_faces(&self, v: VertexId, f: impl FnMut(FaceId)) {
        self.corners.vertex_faces(self.ids.key(v), f);
    }
    #[inline]
    fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2] {
        let (a, b) = self.corners.ends(e.index());
        [self.ids.vertex(a), self.ids.vertex(b)]
    }
    #[inline]
    fn edge_edges(&self, e: EdgeId, f: impl FnMut(EdgeId)) {
        self.corners.edge_edges(e.index(), f);
    }
    #[inline]
    fn edge_faces(&self, e: EdgeId, f: impl FnMut(FaceId)) {
        self.corners.edge_faces(e.index(), f);
    }
    #[inline]
    fn face_vertices(&self, face: FaceId, mut f: impl FnMut(VertexId)) {
        let first = read!("offsets", self.corners.offsets, face.index());
        for p in reads::each("corners", self.corners.face(face.index()), first as usize) {
            f(self.ids.vertex(p));
        }
    }
    #[inline]
    fn face_edges(&self, face: FaceId, f: impl FnMut(EdgeId)) {
        self.corners.face_edges(face.index(), f);
    }
    #[inline]
    fn face_faces(&self, face: FaceId, f: impl FnMut(FaceId)) {
        self.corners.face_faces(face.index(), f);
    }
    #[inline]
    fn is_boundary_vertex(&self, v: VertexId) -> bool {
        self.corners.is_boundary_vertex(self.ids.key(v))
    }
    #[inline]
    fn is_boundary_edge(&self, e: EdgeId) -> bool {
        self.corners.twin(e.index()).is_none()
    }
    #[inline]
    fn boundary_curves(&self, out: &mut BoundaryCurves) {
        self.corners.boundary_curves(out);
    }
    #[inline]
    fn edge_successor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        self.corners
            .neighbour_in_face(e.index(), face.index(), true)
    }
    #[inline]
    fn edge_predecessor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        self.corners
            .neighbour_in_face(e.index(), face.index(), false)
    }
    fn validate(&self) -> Result<()> {
        self.corners.validate(Self::NAME)?;
        if let Some(c) = self
            .corners
            .keys
            .iter()
            .position(|p| !self.ids.lookup.contains_key(&bits(*p)))
        {
            return Err(Error::invariant(
                Self::NAME,
                format!("corner {c} has coordinates of no vertex"),
            ));
        }
        Ok(())
    }
    fn heap_bytes(&self) -> usize {
        // The hash map: its buckets (key + value) plus one control byte each.
        self.corners.heap_bytes()
            + self.ids.positions.capacity() * 24
            + self.ids.lookup.capacity() * (std::mem::size_of::<([u64; 3], u32)>() + 1)
    }
    fn explain(&self, w: &mut dyn Write) -> std::fmt::Result {
        writeln!(
            w,
            "explicit storage: every polygon lists its own corner coordinates"
        )?;
        writeln!(w, "faces: {}", self.corners.num_faces())?;
        for f in 0..self.corners.num_faces() {
            let ps: Vec<String> = self
                .corners
                .face(f)
                .iter()
                .map(|p| format!("({:.3}, {:.3}, {:.3})", p.x, p.y, p.z))
                .collect();
            writeln!(w, "  P{f} = ({})", ps.join(", "))?;
        }
        writeln!(
            w,
            "shared vertices and edges are not stored: they are found by comparing coordinates"
        )
    }
}
