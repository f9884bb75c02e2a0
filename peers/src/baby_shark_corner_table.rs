//! # baby-shark-corner-table: baby_shark 0.3.12's `CornerTable`
//!
//! baby_shark's corner table: per corner its vertex, its opposite corner and flags; per
//! vertex one corner, its position and flags. Face `f` owns corners `3f`, `3f + 1` and
//! `3f + 2`, and baby_shark's edge of a corner is the side opposite it: the CHE's idea (the
//! CHE thesis chapter's level 1 stores the same `O` table). It is built with
//! `CornerTable::from_vertex_and_face_iters`, the indexed constructor its documentation
//! shows, with `f64` positions (`CornerTableD`), so positions are the soup's bit for bit.
//!
//! baby_shark's ids are opaque: their constructors and their index are private to the
//! crate, and it gives them out only through its iterators (`vertices`, `faces`,
//! `unique_edges`) and its queries. So the adapter keeps, as baby_shark's documentation
//! keeps data per element, its own tables beside the mesh: the crate's id of each of the
//! lab's vertices, faces and edges, and for each corner (`EdgeAttribute`) and vertex
//! (`VertexAttribute`) the lab's id. Every answer costs one more read, through these tables.
//!
//! baby_shark marks a vertex no face uses as deleted and gives it no id, so the adapter
//! answers for such a vertex itself (no neighbours, not on the boundary) and keeps its
//! position.
//!
//! | operator | baby_shark call | cost |
//! |---|---|---|
//! | R00, R01, R02 | `vertices_around_vertex`, `edges_around_vertex`, `faces_around_vertex` | O(k) |
//! | R10, R12 | `edge_vertices`, `edge_faces` | O(1) |
//! | R20, R21 | `face_vertices`, `face_edges` | O(1) |
//! | R22 | composed: `face_edges`, then each one's `opposite_edge` | O(1) |
//! | R11 | composed: R21 of each face of R12 | O(1) |
//! | boundary vertex | `is_vertex_on_boundary` (walks the fan) | O(k) |
//! | boundary edge | `is_edge_on_boundary` | O(1) |
//! | boundary curves | `boundary_rings` and `boundary_edges` (a `HashSet` of every corner inside) | O(n) |
//! | successor, predecessor | composed: the edge's corner in the face, `previous_edge` | O(1) |
//!
//! ## Editing
//!
//! [`MeshEdit`](topolab_structures::MeshEdit) (in `edit::baby_shark`), after the lab's checks
//! ([`crate::edit`]):
//!
//! | operation | baby_shark call | cost |
//! |---|---|---|
//! | flip | the lab's checks (two triangles whose third corners are distinct and not joined: baby_shark checks nothing), then `flip_edge` on the edge's corner, O(1); the adapter re-reads the lab's edge of the six corners | O(k), the check |
//! | collapse | the lab's test (the link condition and OpenMesh's tetrahedron test, O(k²): baby_shark checks nothing), then `collapse_edge` on the corner of the face running `to` → `from` (or, on a boundary edge with only `from` → `to`, that face's, the kept record then taking `to`'s id) at `to`'s position; baby_shark walks the corners around the removed vertex | O(k²), the test |
//! | set position | `Vertex::set_position` through the table's `IndexMut`; for a vertex no face uses, the adapter's list | O(1), O(log n) |
//! | garbage collection | the adapter's tables renumbered without what collapses deleted (baby_shark's own arrays keep their deleted records: it has no compaction) | O(n) |
//!
//! Refused as [`Refusal::NotImplemented`](topolab_structures::Refusal::NotImplemented): adding
//! a vertex or a face, the deletions, the vertex split and the weld (baby_shark has no public
//! call for them); the edge and face splits (`split_edge`, `split_face`: they append corners
//! and a vertex, and the adapter's `EdgeAttribute` and `VertexAttribute` cannot grow, so each
//! would rebuild them in O(n); note that `split_edge` moves the edge's end to the split point
//! and puts the new vertex where that end was). Deletion is `Marked`, as baby_shark deletes:
//! a collapse's deleted vertex, faces and edges keep their lab ids (skipped by `validate`)
//! until `garbage_collection`; edge ids are stable (a flip keeps the flipped edge's id and its
//! four neighbours', a collapse keeps the ids of the edges it does not delete).

use crate::compose;
use baby_shark::exports::nalgebra::Vector3;
use baby_shark::mesh::corner_table::{
    CornerTable, EdgeAttribute, EdgeId as SharkEdge, FaceId as SharkFace, VertexAttribute,
    VertexId as SharkVertex,
};
use glam::DVec3;
use std::ops::ControlFlow;
use topolab_structures::{
    BoundaryCurves, BuildFacts, Capabilities, Constructed, Cost, EdgeId, Error, FaceId, Family,
    MeshTopology, Operator, PolygonSoup, Result, SeparateConstruction, VertexId,
};

/// The lab's name of this structure.
pub const NAME: &str = "baby-shark-corner-table";

/// baby_shark's own construction apart from the lab's checks ([`SeparateConstruction`]):
/// what the report times, as it times OpenMesh's; the adapter's tables are made after the
/// clock ([`BabySharkCornerTable::tables`]), as CGAL's id tables are.
struct Build;

impl SeparateConstruction<BabySharkCornerTable> for Build {
    /// [`compose::admit`]: baby_shark's builder silently skips a face whose directed edge is
    /// already taken (a third face on an edge, or two faces one way along it) and splits a
    /// vertex with several fans into new vertices, so the lab's ids would no longer be the
    /// soup's.
    fn admit<'a>(&self, soup: &'a PolygonSoup) -> Result<BuildFacts<'a>> {
        compose::admit(soup, NAME, true)
    }

    /// `CornerTable::from_vertex_and_face_iters`, as baby_shark's documentation builds one.
    fn construction(&self, facts: &BuildFacts<'_>) -> Result<Constructed<BabySharkCornerTable>> {
        let soup = facts.soup();
        compose::without_panic(NAME, || {
            let mesh = CornerTable::<f64>::from_vertex_and_face_iters(
                soup.positions.iter().map(|p| Vector3::new(p.x, p.y, p.z)),
                soup.indices().iter().map(|&v| v as usize),
            );
            // Empty tables until `tables`, after the clock.
            let none = CornerTable::<f64>::default();
            let mesh = BabySharkCornerTable {
                vertex_ids: none.create_vertex_attribute(),
                corner_ids: none.create_edge_attribute(),
                mesh,
                vertices: Vec::new(),
                faces: Vec::new(),
                edges: Vec::new(),
                isolated: Vec::new(),
                admitted_edges: facts.edges() as usize,
            };
            Ok(Constructed::new(mesh, BabySharkCornerTable::tables))
        })
    }
}

/// baby_shark's `CornerTable<f64>` and the adapter's tables from the lab's ids to the
/// crate's and back; see the module docs.
pub struct BabySharkCornerTable {
    pub(crate) mesh: CornerTable<f64>,
    /// Per lab vertex: the crate's id, `None` for a vertex no face uses.
    pub(crate) vertices: Vec<Option<SharkVertex>>,
    /// Per crate vertex: the lab's id.
    pub(crate) vertex_ids: VertexAttribute<u32>,
    /// Per lab face: the crate's id.
    pub(crate) faces: Vec<SharkFace>,
    /// Per lab edge: the crate's edge (the corner) `unique_edges` gave for it.
    pub(crate) edges: Vec<SharkEdge>,
    /// Per crate edge (corner): the lab's edge and face.
    pub(crate) corner_ids: EdgeAttribute<[u32; 2]>,
    /// The vertices no face uses and their positions, by lab id (baby_shark keeps no id for
    /// them).
    pub(crate) isolated: Vec<(u32, DVec3)>,
    /// The edge count of the lab's analysis before the crate built, which the tables are
    /// checked against.
    pub(crate) admitted_edges: usize,
}

impl std::fmt::Debug for BabySharkCornerTable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "BabySharkCornerTable({} vertices, {} faces)",
            self.vertices.len(),
            self.faces.len()
        )
    }
}

impl BabySharkCornerTable {
    #[inline]
    fn edge_id(&self, e: SharkEdge) -> EdgeId {
        EdgeId(self.corner_ids[e][0])
    }
    #[inline]
    fn vertex_id(&self, v: SharkVertex) -> VertexId {
        VertexId(self.vertex_ids[v])
    }
    /// The lab's id of a crate face: the face of its first corner's edge.
    #[inline]
    fn face_id(&self, g: SharkFace) -> FaceId {
        FaceId(self.corner_ids[self.mesh.face_edges(g).0][1])
    }
    /// The crate's half-edge (corner) of lab edge `e` in lab face `face`, if it has one.
    #[inline]
    fn edge_in(&self, e: EdgeId, face: FaceId) -> Option<SharkEdge> {
        let h = *self.edges.get(e.index())?;
        let in_face = |x: SharkEdge| self.corner_ids[x][1] == face.0;
        if in_face(h) {
            Some(h)
        } else {
            self.mesh.opposite_edge(h).filter(|&o| in_face(o))
        }
    }
    /// The adapter's tables, read from the crate's iterators after its construction (the
    /// finishing step of [`Build`]): any count that differs from the soup's is reported as a
    /// broken invariant, not answered.
    fn tables(&mut self, soup: &PolygonSoup) -> Result<()> {
        let mesh = std::mem::take(&mut self.mesh);
        let faces: Vec<SharkFace> = mesh.faces().collect();
        if faces.len() != soup.num_faces() {
            return Err(Self::invariant(format!(
                "baby_shark kept {} of {} faces",
                faces.len(),
                soup.num_faces()
            )));
        }
        let mut vertices = vec![None; soup.num_vertices()];
        let mut vertex_ids = mesh.create_vertex_attribute::<u32>();
        let mut corner_ids = mesh.create_edge_attribute::<[u32; 2]>();
        for (f, (&g, corners)) in faces.iter().zip(soup.faces()).enumerate() {
            let (a, b, c) = mesh.face_vertices(g);
            for (x, &v) in [a, b, c].into_iter().zip(corners) {
                match vertices[v as usize] {
                    Some(y) if y != x => {
                        return Err(Self::invariant(format!(
                            "baby_shark split vertex {v} into several"
                        )))
                    }
                    _ => vertices[v as usize] = Some(x),
                }
                vertex_ids[x] = v;
            }
            let (e0, e1, e2) = mesh.face_edges(g);
            for e in [e0, e1, e2] {
                corner_ids[e][1] = f as u32;
            }
        }
        let mut edges = Vec::with_capacity(self.admitted_edges);
        for e in mesh.unique_edges() {
            let id = edges.len() as u32;
            edges.push(e);
            corner_ids[e][0] = id;
            if let Some(o) = mesh.opposite_edge(e) {
                corner_ids[o][0] = id;
            }
        }
        if edges.len() != self.admitted_edges {
            return Err(Self::invariant(format!(
                "baby_shark has {} edges, the soup {}",
                edges.len(),
                self.admitted_edges
            )));
        }
        let isolated = (0..soup.num_vertices())
            .filter(|&v| vertices[v].is_none())
            .map(|v| (v as u32, soup.positions[v]))
            .collect();
        *self = Self {
            mesh,
            vertices,
            vertex_ids,
            faces,
            edges,
            corner_ids,
            isolated,
            admitted_edges: self.admitted_edges,
        };
        Ok(())
    }

    fn invariant(message: String) -> Error {
        Error::Invariant {
            structure: NAME,
            message,
        }
    }
}

impl MeshTopology for BabySharkCornerTable {
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
            Operator::R00 | Operator::R01 | Operator::R02 | Operator::BoundaryVertex => Cost::Local,
            Operator::BoundaryCurves => Cost::Linear,
            _ => Cost::Constant,
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
        self.vertices.len()
    }
    #[inline]
    fn num_edges(&self) -> usize {
        self.edges.len()
    }
    #[inline]
    fn num_faces(&self) -> usize {
        self.faces.len()
    }

    fn for_each_edge(&self, mut f: impl FnMut(EdgeId)) {
        for e in 0..self.edges.len() as u32 {
            f(EdgeId(e));
        }
    }

    #[inline]
    fn position(&self, v: VertexId) -> DVec3 {
        match self.vertices[v.index()] {
            Some(x) => {
                let p = self.mesh.vertex_position(x);
                DVec3::new(p.x, p.y, p.z)
            }
            None => match self.isolated.binary_search_by_key(&v.0, |&(w, _)| w) {
                Ok(i) => self.isolated[i].1,
                Err(_) => DVec3::NAN,
            },
        }
    }

    #[inline]
    fn vertex_vertices(&self, v: VertexId, mut f: impl FnMut(VertexId)) {
        if let Some(x) = self.vertices[v.index()] {
            self.mesh
                .vertices_around_vertex(x, |w| f(self.vertex_id(w)));
        }
    }
    #[inline]
    fn vertex_edges(&self, v: VertexId, mut f: impl FnMut(EdgeId)) {
        if let Some(x) = self.vertices[v.index()] {
            self.mesh
                .edges_around_vertex(x, |e| f(self.edge_id(e.id())));
        }
    }
    #[inline]
    fn vertex_faces(&self, v: VertexId, mut f: impl FnMut(FaceId)) {
        if let Some(x) = self.vertices[v.index()] {
            self.mesh.faces_around_vertex(x, |g| f(self.face_id(g)));
        }
    }
    #[inline]
    fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2] {
        let (a, b) = self.mesh.edge_vertices(self.edges[e.index()]);
        [self.vertex_id(a), self.vertex_id(b)]
    }
    #[inline]
    fn edge_edges(&self, e: EdgeId, f: impl FnMut(EdgeId)) {
        compose::edge_edges(self, e, f);
    }
    #[inline]
    fn edge_faces(&self, e: EdgeId, mut f: impl FnMut(FaceId)) {
        let (g, across) = self.mesh.edge_faces(self.edges[e.index()]);
        f(self.face_id(g));
        if let Some(g) = across {
            f(self.face_id(g));
        }
    }
    #[inline]
    fn face_vertices(&self, face: FaceId, mut f: impl FnMut(VertexId)) {
        let (a, b, c) = self.mesh.face_vertices(self.faces[face.index()]);
        for x in [a, b, c] {
            f(self.vertex_id(x));
        }
    }
    /// baby_shark's edge of a corner is the side opposite it, so corner 0's edge joins
    /// vertices 1 and 2: the lab's order (edge `i` joins vertices `i` and `i + 1`) is the
    /// crate's edges 2, 0, 1.
    #[inline]
    fn face_edges(&self, face: FaceId, mut f: impl FnMut(EdgeId)) {
        let (e0, e1, e2) = self.mesh.face_edges(self.faces[face.index()]);
        for e in [e2, e0, e1] {
            f(self.edge_id(e));
        }
    }
    #[inline]
    fn face_faces(&self, face: FaceId, mut f: impl FnMut(FaceId)) {
        let (e0, e1, e2) = self.mesh.face_edges(self.faces[face.index()]);
        for e in [e2, e0, e1] {
            if let Some(o) = self.mesh.opposite_edge(e) {
                f(FaceId(self.corner_ids[o][1]));
            }
        }
    }
    #[inline]
    fn is_boundary_vertex(&self, v: VertexId) -> bool {
        self.vertices[v.index()].is_some_and(|x| self.mesh.is_vertex_on_boundary(x))
    }
    #[inline]
    fn is_boundary_edge(&self, e: EdgeId) -> bool {
        self.mesh.is_edge_on_boundary(self.edges[e.index()])
    }
    #[inline]
    fn boundary_curves(&self, out: &mut BoundaryCurves) {
        out.clear();
        for ring in self.mesh.boundary_rings() {
            self.mesh.boundary_edges(ring, |e| {
                out.edges.push(self.edge_id(e));
                ControlFlow::Continue(())
            });
            out.end_curve();
        }
    }
    /// In a triangle the edge after corner `c`'s is corner `c + 1`'s, two steps back.
    #[inline]
    fn edge_successor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        let h = self.edge_in(e, face)?;
        Some(self.edge_id(self.mesh.previous_edge(self.mesh.previous_edge(h))))
    }
    #[inline]
    fn edge_predecessor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        let h = self.edge_in(e, face)?;
        Some(self.edge_id(self.mesh.previous_edge(h)))
    }

    /// The lab's checks of the answers ([`compose::validate_live_answers`]: the faces and
    /// edges a collapse deleted keep their slots until garbage collection and are skipped),
    /// and that the tables agree with the crate: each lab id goes to the crate and back
    /// unchanged.
    fn validate(&self) -> Result<()> {
        for (v, x) in self.vertices.iter().enumerate() {
            if x.is_some_and(|x| self.vertex_ids[x] as usize != v) {
                return Err(Self::invariant(format!("vertex {v} does not map back")));
            }
        }
        for (f, &g) in self.faces.iter().enumerate() {
            if self.face_id(g).index() != f {
                return Err(Self::invariant(format!("face {f} does not map back")));
            }
        }
        for (e, &h) in self.edges.iter().enumerate() {
            if self.edge_id(h).index() != e {
                return Err(Self::invariant(format!("edge {e} does not map back")));
            }
        }
        compose::validate_live_answers(self, |f| self.face_deleted(f), |e| self.edge_deleted(e))
    }

    /// From baby_shark's record layout (its arrays are private): per corner its opposite
    /// corner, vertex and flags (12 bytes), per vertex its corner, `f64` position and flags
    /// (32); plus the adapter's tables: per corner the lab's edge and face (8), per lab
    /// vertex the crate's id (8) and per crate vertex the lab's (4), per face and per edge
    /// the crate's id (4), and the isolated vertices' positions.
    fn heap_bytes(&self) -> usize {
        let corners = 3 * self.faces.len();
        (12 + 8) * corners
            + (32 + 4) * self.vertices.len()
            + self.vertices.capacity() * std::mem::size_of::<Option<SharkVertex>>()
            + self.faces.capacity() * std::mem::size_of::<SharkFace>()
            + self.edges.capacity() * std::mem::size_of::<SharkEdge>()
            + self.isolated.capacity() * std::mem::size_of::<(u32, DVec3)>()
    }

    fn explain(&self, w: &mut dyn std::fmt::Write) -> std::fmt::Result {
        writeln!(
            w,
            "baby_shark {} CornerTable<f64>: {} vertices (corner, position), {} corners (opposite corner, vertex); corner c's edge is the side opposite it",
            crate::versions::BABY_SHARK_VERSION,
            self.vertices.len() - self.isolated.len(),
            3 * self.faces.len()
        )?;
        compose::write_one_rings(self, w)
    }
}
