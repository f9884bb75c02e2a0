//! # tri-mesh: tri-mesh 0.6.1's `Mesh`
//!
//! tri-mesh's half-edge mesh (half-edges with `Option` fields in arrays behind `RefCell`,
//! twins matched by a hash map when it is built), built with `Mesh::new` from the
//! `three_d_asset::TriMesh` its documentation builds it from. Its ids are given out by its
//! iterators and read back through `Deref<Target = u32>`: vertices and faces in input order,
//! so they are the soup's ids. The adapter keeps the ids its iterators gave (one `u32` per
//! vertex, face and half-edge), so that a query turns the lab's id into tri-mesh's with one
//! read, without the crate's `unsafe fn new` meant for tests. `EdgeId` `e` is the half-edge
//! of the edge that `edge_iter` yields (the one with the smaller id).
//!
//! | operator | tri-mesh call | cost |
//! |---|---|---|
//! | R00, R01, R02 | `vertex_halfedge_iter` and a walker per half-edge | O(k) |
//! | R10, R12 | `edge_vertices`; the walker's face and its twin's | O(1) |
//! | R20, R21, R22 | `face_halfedge_iter` and a walker per half-edge | O(k) |
//! | R11 | composed: R21 of each face of R12 | O(k) |
//! | boundary vertex | `is_vertex_on_boundary` (walks the 1-ring) | O(k) |
//! | boundary edge | `is_edge_on_boundary` | O(1) |
//! | boundary curves | composed: enumerate edges, follow boundary edges by R01 | O(n) |
//! | successor, predecessor | composed: the edge's place in R21 | O(k) |
//!
//! ## Editing
//!
//! [`MeshEdit`](topolab_structures::MeshEdit) (in `edit::tri_mesh`), after the lab's checks
//! ([`crate::edit`]); tri-mesh checks nothing itself beyond a flip's boundary edge and
//! existing new edge. The adapter adds each new vertex, face and half-edge to its tables.
//!
//! | operation | tri-mesh call | cost |
//! |---|---|---|
//! | add vertex | `Mesh::add_vertex` | O(1) |
//! | add face | the lab's checks (a polygon refused as `NotTriangles`, one fan per vertex, each directed edge once), then `Mesh::add_face`, whose `connecting_edge` turns around each corner | O(k) |
//! | flip | the lab's checks (two triangles whose third corners are distinct and not joined), then `Mesh::flip_edge`, whose `connecting_edge` turns around a corner | O(k) |
//! | edge split | the lab's check (the two triangles do not share their third corner), then `Mesh::split_edge` | O(1) |
//! | face split | `Mesh::split_face` | O(1) |
//! | set position | `Mesh::set_vertex_position` | O(1) |
//! | garbage collection | nothing to collect: nothing is removed | O(1) |
//!
//! Refused as [`Refusal::NotImplemented`](topolab_structures::Refusal::NotImplemented): face
//! deletion (`remove_face`) and the collapse (`collapse_edge`, which also moves the kept vertex
//! to the edge's midpoint): tri-mesh frees a removed element's id for the next new one, and the
//! adapter takes tri-mesh's ids for the lab's, so a new vertex would then not be appended;
//! vertex deletion, the vertex split and the weld (tri-mesh has none). Deletion is declared
//! `Removed`, as tri-mesh removes; edge ids are not stable (`add_face` replaces the boundary
//! half-edge of an edge the new face takes, and an edge's id is its smaller half-edge).

use crate::compose;
use glam::DVec3;
use three_d_asset::{Indices, Positions};
use topolab_structures::{
    BoundaryCurves, BuildFacts, Capabilities, Constructed, Cost, EdgeId, FaceId, Family,
    MeshTopology, Operator, PolygonSoup, Result, SeparateConstruction, VertexId,
};
use tri_mesh::{FaceID, HalfEdgeID, Mesh, Vector3, VertexID};

/// The lab's name of this structure.
pub const NAME: &str = "tri-mesh";

/// tri-mesh's own construction apart from the lab's checks ([`SeparateConstruction`]): what
/// the report times, as it times OpenMesh's; the adapter's id tables are read after the clock,
/// as CGAL's are made.
struct Build;

impl SeparateConstruction<TriMesh> for Build {
    fn admit<'a>(&self, soup: &'a PolygonSoup) -> Result<BuildFacts<'a>> {
        compose::admit(soup, NAME, true)
    }

    /// `Mesh::new` from the `three_d_asset::TriMesh` its documentation builds it from.
    fn construction(&self, facts: &BuildFacts<'_>) -> Result<Constructed<TriMesh>> {
        let soup = facts.soup();
        compose::without_panic(NAME, || {
            let input = three_d_asset::TriMesh {
                positions: Positions::F64(
                    soup.positions
                        .iter()
                        .map(|p| Vector3::new(p.x, p.y, p.z))
                        .collect(),
                ),
                indices: Indices::U32(soup.indices().to_vec()),
                ..Default::default()
            };
            let mesh = TriMesh {
                mesh: Mesh::new(&input),
                vertices: Vec::new(),
                faces: Vec::new(),
                half_edges: Vec::new(),
            };
            Ok(Constructed::new(mesh, |m, _| {
                m.vertices = m.mesh.vertex_iter().collect();
                m.faces = m.mesh.face_iter().collect();
                m.half_edges = m.mesh.halfedge_iter().collect();
                Ok(())
            }))
        })
    }
}

/// tri-mesh's `Mesh` and the ids its iterators gave; see the module docs.
pub struct TriMesh {
    pub(crate) mesh: Mesh,
    pub(crate) vertices: Vec<VertexID>,
    pub(crate) faces: Vec<FaceID>,
    pub(crate) half_edges: Vec<HalfEdgeID>,
}

impl std::fmt::Debug for TriMesh {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "TriMesh({} vertices, {} faces)",
            self.vertices.len(),
            self.faces.len()
        )
    }
}

impl TriMesh {
    #[inline]
    fn vertex(&self, v: VertexId) -> VertexID {
        self.vertices[v.index()]
    }
    #[inline]
    pub(crate) fn half_edge(&self, e: EdgeId) -> HalfEdgeID {
        self.half_edges[e.index()]
    }
    /// The lab's id of the edge of half-edge `h`: the smaller of its and its twin's.
    #[inline]
    pub(crate) fn edge(&self, h: HalfEdgeID) -> EdgeId {
        let twin = self.mesh.walker_from_halfedge(h).twin_id();
        EdgeId(twin.map_or(*h, |t| (*h).min(*t)))
    }
}

impl MeshTopology for TriMesh {
    const NAME: &'static str = NAME;
    const FAMILY: Family = Family::RustCrate;

    fn capabilities() -> Capabilities {
        Capabilities {
            triangles_only: true,
            ..Capabilities::POLYGONS
        }
    }

    fn cost(op: Operator) -> Cost {
        match op {
            Operator::R10 | Operator::R12 | Operator::BoundaryEdge => Cost::Constant,
            Operator::BoundaryCurves => Cost::Linear,
            _ => Cost::Local,
        }
    }

    fn from_soup(soup: &PolygonSoup) -> Result<Self> {
        Build.build(soup)
    }

    fn separate_construction<'a>() -> Option<&'a dyn SeparateConstruction<Self>> {
        Some(&Build)
    }

    #[inline]
    fn num_vertices(&self) -> usize {
        self.mesh.no_vertices()
    }
    #[inline]
    fn num_edges(&self) -> usize {
        self.mesh.no_edges()
    }
    #[inline]
    fn num_faces(&self) -> usize {
        self.mesh.no_faces()
    }

    fn for_each_edge(&self, mut f: impl FnMut(EdgeId)) {
        for h in self.mesh.edge_iter() {
            f(EdgeId(*h));
        }
    }

    #[inline]
    fn position(&self, v: VertexId) -> DVec3 {
        let p = self.mesh.vertex_position(self.vertex(v));
        DVec3::new(p.x, p.y, p.z)
    }

    #[inline]
    fn vertex_vertices(&self, v: VertexId, mut f: impl FnMut(VertexId)) {
        for h in self.mesh.vertex_halfedge_iter(self.vertex(v)) {
            if let Some(w) = self.mesh.walker_from_halfedge(h).vertex_id() {
                f(VertexId(*w));
            }
        }
    }
    #[inline]
    fn vertex_edges(&self, v: VertexId, mut f: impl FnMut(EdgeId)) {
        for h in self.mesh.vertex_halfedge_iter(self.vertex(v)) {
            f(self.edge(h));
        }
    }
    #[inline]
    fn vertex_faces(&self, v: VertexId, mut f: impl FnMut(FaceId)) {
        for h in self.mesh.vertex_halfedge_iter(self.vertex(v)) {
            if let Some(g) = self.mesh.walker_from_halfedge(h).face_id() {
                f(FaceId(*g));
            }
        }
    }
    #[inline]
    fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2] {
        let (a, b) = self.mesh.edge_vertices(self.half_edge(e));
        [VertexId(*a), VertexId(*b)]
    }
    #[inline]
    fn edge_edges(&self, e: EdgeId, f: impl FnMut(EdgeId)) {
        compose::edge_edges(self, e, f);
    }
    #[inline]
    fn edge_faces(&self, e: EdgeId, mut f: impl FnMut(FaceId)) {
        let mut walker = self.mesh.walker_from_halfedge(self.half_edge(e));
        if let Some(g) = walker.face_id() {
            f(FaceId(*g));
        }
        if let Some(g) = walker.as_twin().face_id() {
            f(FaceId(*g));
        }
    }
    #[inline]
    fn face_vertices(&self, face: FaceId, mut f: impl FnMut(VertexId)) {
        for h in self.mesh.face_halfedge_iter(self.faces[face.index()]) {
            if let Some(v) = self.mesh.walker_from_halfedge(h).vertex_id() {
                f(VertexId(*v));
            }
        }
    }
    #[inline]
    fn face_edges(&self, face: FaceId, mut f: impl FnMut(EdgeId)) {
        for h in self.mesh.face_halfedge_iter(self.faces[face.index()]) {
            f(self.edge(h));
        }
    }
    #[inline]
    fn face_faces(&self, face: FaceId, mut f: impl FnMut(FaceId)) {
        for h in self.mesh.face_halfedge_iter(self.faces[face.index()]) {
            if let Some(g) = self.mesh.walker_from_halfedge(h).as_twin().face_id() {
                f(FaceId(*g));
            }
        }
    }
    #[inline]
    fn is_boundary_vertex(&self, v: VertexId) -> bool {
        self.mesh.is_vertex_on_boundary(self.vertex(v))
    }
    #[inline]
    fn is_boundary_edge(&self, e: EdgeId) -> bool {
        self.mesh.is_edge_on_boundary(self.half_edge(e))
    }
    // Boundary curves, successor and predecessor composed (see `compose`), and the lab's
    // checks of the answers as `validate`.
    compose::composed_queries!();

    /// From tri-mesh's record layout (its arrays are private): per vertex an
    /// `Option<HalfEdgeID>` and an f64 position (8 + 24 bytes), per half-edge four
    /// `Option<u32>` fields (32), per face an `Option<HalfEdgeID>` (8); plus the adapter's id
    /// tables (4 bytes per vertex, face and half-edge).
    fn heap_bytes(&self) -> usize {
        let half_edges = self.mesh.no_halfedges();
        (32 + 4) * self.num_vertices() + (32 + 4) * half_edges + (8 + 4) * self.num_faces()
    }

    fn explain(&self, w: &mut dyn std::fmt::Write) -> std::fmt::Result {
        writeln!(
            w,
            "tri-mesh {} Mesh: {} vertices (position, half-edge), {} faces (half-edge), {} half-edges (vertex, twin, next, face; boundary half-edges have no face and no next)",
            crate::versions::TRI_MESH_VERSION,
            self.num_vertices(),
            self.num_faces(),
            self.mesh.no_halfedges()
        )?;
        compose::write_one_rings(self, w)
    }
}
