//! # Vertex list (indexed face set)
//!
//! The *Eckenliste* of the lecture on polygon-mesh data structures, the layout of `.obj` files: a
//! shared list of vertex positions and, per face, the indices of its corners. Nothing else is
//! stored, so every relation that needs a neighbour is found by scanning the faces, as the lecture
//! says ("finding shared edges and vertices of polygons is still hard").
//!
//! | stores | bytes |
//! |---|---|
//! | `positions[v]`: x, y, z | 24 per vertex |
//! | `corners[c]`: vertex index of each face corner | 4 per corner (12 per triangle) |
//! | `offsets[f]`: first corner of each face | 4 per face |
//!
//! `EdgeId`: the first corner (in face order) whose outgoing side is the edge.
//!
//! | operator | how | cost |
//! |---|---|---|
//! | R00, R01, R02 | scan all faces for the vertex | O(n) |
//! | R10 | the corner and its successor (face by binary search) | O(log n) |
//! | R11, R21, R22 | a scan per edge (to find twins and edge ids) | O(k·n) |
//! | R12, boundary edge, successor, predecessor | a scan for the twin / edge id | O(n) |
//! | R20 | read the face's corners | O(k) |
//! | boundary vertex | one scan: more distinct edges than faces | O(n) |
//! | boundary curves | a twin scan per corner | O(n²) |
//!
//! Editing ([`MeshEdit`](crate::MeshEdit)): every operation, each at the cost of the scans it
//! needs (the table in `edit.rs`).
//!
//! Non-manifold vertices (several fans) are stored and answered correctly: nothing here
//! assumes a vertex has one fan. Non-manifold edges and inconsistent orientation are refused
//! like everywhere in the lab (the relations and boundary curves would not be defined).

mod edit;

use crate::core::error::Result;
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::reads::{self, read};
use crate::core::soup::PolygonSoup;
use crate::core::topology::{BoundaryCurves, Capabilities, Cost, MeshTopology, Operator};
use crate::families::corner_lists::corner_scan::{scan_cost, Corners, Naming};
use glam::DVec3;
use std::fmt::Write;

/// Shared vertices plus faces as lists of vertex indices; see the module docs.
#[derive(Clone, Debug)]
pub struct VertexList {
    /// `positions[v]`: the coordinates of vertex v.
    positions: Vec<DVec3>,
    /// The faces' corners as vertex indices, with face offsets.
    corners: Corners<u32>,
    /// `deleted[v]`: vertex v was deleted by an edit ([`crate::MeshEdit`]) and keeps its slot
    /// until `garbage_collection`; empty until the first deletion.
    deleted: Vec<bool>,
}

struct Indices;

impl Naming<u32> for Indices {
    #[inline(always)]
    fn key(&self, v: VertexId) -> u32 {
        v.0
    }
    #[inline(always)]
    fn vertex(&self, k: u32) -> VertexId {
        VertexId(k)
    }
}

impl VertexList {
    /// The positions and index buffer, as stored.
    pub fn corners(&self) -> (&[DVec3], &[u32], &[u32]) {
        (&self.positions, &self.corners.keys, &self.corners.offsets)
    }
}

impl MeshTopology for VertexList {
    const NAME: &'static str = "vertex-list";
    const FAMILY: crate::core::family::Family = crate::core::family::Family::CornerLists;

    fn capabilities() -> Capabilities {
        Capabilities {
            non_manifold_vertices: true,
            ..Capabilities::POLYGONS
        }
    }

    fn cost(op: Operator) -> Cost {
        scan_cost(op)
    }

    fn from_soup(soup: &PolygonSoup) -> Result<Self> {
        // The edge analysis only checks that the soup is an oriented manifold; nothing of it is kept.
        soup.connectivity()?;
        Ok(Self {
            positions: soup.positions.clone(),
            corners: Corners {
                keys: soup.indices().to_vec(),
                offsets: soup.offsets().to_vec(),
            },
            deleted: Vec::new(),
        })
    }

    #[inline]
    fn num_vertices(&self) -> usize {
        self.positions.len()
    }
    #[inline]
    fn num_edges(&self) -> usize {
        let mut n = 0;
        self.corners.enumerate_edges(&Indices, |_, _| n += 1);
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
            .enumerate_edges(&Indices, |_, b| n += b as usize);
        n
    }
    fn for_each_edge(&self, mut f: impl FnMut(EdgeId)) {
        self.corners
            .enumerate_edges(&Indices, |c, _| f(EdgeId::new(c)));
    }
    #[inline]
    fn position(&self, v: VertexId) -> DVec3 {
        self.positions[v.index()]
    }
    #[inline]
    fn vertex_vertices(&self, v: VertexId, mut f: impl FnMut(VertexId)) {
        self.corners.vertex_edges(v.0, |_, w| f(VertexId(w)));
    }
    #[inline]
    fn vertex_edges(&self, v: VertexId, mut f: impl FnMut(EdgeId)) {
        self.corners.vertex_edges(v.0, |e, _| f(EdgeId::new(e)));
    }
    #[inline]
    fn vertex_faces(&self, v: VertexId, f: impl FnMut(FaceId)) {
        self.corners.vertex_faces(v.0, f);
    }
    #[inline]
    fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2] {
        let (a, b) = self.corners.ends(e.index());
        [VertexId(a), VertexId(b)]
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
        for v in reads::each("corners", self.corners.face(face.index()), first as usize) {
            f(VertexId(v));
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
        self.corners.is_boundary_vertex(v.0)
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
            .position(|&v| v as usize >= self.positions.len())
        {
            return Err(crate::core::error::Error::invariant(
                Self::NAME,
                format!("corner {c} names a missing vertex"),
            ));
        }
        Ok(())
    }
    fn heap_bytes(&self) -> usize {
        self.positions.capacity() * std::mem::size_of::<DVec3>()
            + self.corners.heap_bytes()
            + self.deleted.capacity()
    }
    fn explain(&self, w: &mut dyn Write) -> std::fmt::Result {
        writeln!(
            w,
            "vertex list (indexed face set): a shared vertex list, faces as vertex indices"
        )?;
        writeln!(w, "vertices: {}", self.positions.len())?;
        for (v, p) in self.positions.iter().enumerate() {
            writeln!(w, "  v{v}: ({:.3}, {:.3}, {:.3})", p.x, p.y, p.z)?;
        }
        writeln!(w, "faces: {}", self.corners.num_faces())?;
        for f in 0..self.corners.num_faces() {
            let vs: Vec<String> = self
                .corners
                .face(f)
                .iter()
                .map(|v| format!("v{v}"))
                .collect();
            writeln!(w, "  f{f}: ({})", vs.join(", "))?;
        }
        writeln!(
            w,
            "edges are not stored: each is found by scanning the faces"
        )
    }
}
