//! [`MeshEdit`] for tri-mesh's `Mesh` ([`TriMesh`]); the table of calls, costs and refusals
//! is in [`crate::tri_mesh`]'s module docs.
//!
//! tri-mesh's `Mesh` offers `add_vertex`, `set_vertex_position`, `add_face`, `remove_face`,
//! `flip_edge`, `split_edge`, `split_face` and `collapse_edge`. Its ids live in arrays with a
//! free list: a removed element's id is freed and handed to the next new element (last
//! freed, first reused), and nothing compacts them. The adapter's queries take the crate's
//! vertex and face ids for the lab's (the crate gives them out in insertion order while
//! nothing is removed), so the operations that remove vertices or faces (`remove_face`,
//! `collapse_edge`) are left out: after one, the next new vertex or face would take a freed
//! id instead of being appended, and the lab's vertex ids must stay until
//! `garbage_collection`. They are refused as [`Refusal::NotImplemented`].

use super::{check_add_face, check_flip, check_split_edge};
use crate::tri_mesh::TriMesh;
use glam::DVec3;
use topolab_structures::{
    refuse, Cost, Deletion, EdgeId, EditOp, Error, FaceId, MeshEdit, Offers, Refusal, Result,
    VertexId,
};
use tri_mesh::{FaceID, HalfEdgeID, Vector3, VertexID};

impl TriMesh {
    /// Is `e` the lab's id of an edge of the mesh: in the table, its half-edge and twin each
    /// other's, and the smaller of the two? (A half-edge tri-mesh removed keeps its stale
    /// record, whose twin no longer points back.)
    fn is_edge(&self, e: EdgeId) -> bool {
        let Some(&h) = self.half_edges.get(e.index()) else {
            return false;
        };
        let walker = self.mesh.walker_from_halfedge(h);
        let (Some(t), Some(_)) = (walker.twin_id(), walker.vertex_id()) else {
            return false;
        };
        self.mesh.walker_from_halfedge(t).twin_id() == Some(h) && self.edge(h) == e
    }

    /// Records a half-edge tri-mesh may have just created: the table maps the crate's number
    /// to its id (the lab's `EdgeId` of an edge is the number of its smaller half-edge).
    fn note_half_edge(&mut self, h: HalfEdgeID) {
        let i = *h as usize;
        if i >= self.half_edges.len() {
            self.half_edges.resize(i + 1, h);
        }
        self.half_edges[i] = h;
    }

    /// Records the half-edges of face `g` and their twins.
    fn note_face(&mut self, g: FaceID) {
        let around: Vec<HalfEdgeID> = self.mesh.face_halfedge_iter(g).collect();
        for h in around {
            self.note_half_edge(h);
            if let Some(t) = self.mesh.walker_from_halfedge(h).twin_id() {
                self.note_half_edge(t);
            }
        }
    }

    /// Records a vertex tri-mesh just created: appended, since no vertex is ever removed.
    fn note_vertex(&mut self, v: VertexID) -> Result<VertexId> {
        if *v as usize != self.vertices.len() {
            return Err(self.broken(format!(
                "tri-mesh gave the new vertex id {}, not {}",
                *v,
                self.vertices.len()
            )));
        }
        self.vertices.push(v);
        Ok(VertexId(*v))
    }

    /// Records the faces around new vertex `v` that the table does not have yet (a split's
    /// new faces, appended by tri-mesh in order) and every half-edge around them.
    fn note_faces_around(&mut self, v: VertexID) -> Result<()> {
        let mut faces: Vec<FaceID> = self
            .mesh
            .vertex_halfedge_iter(v)
            .filter_map(|h| self.mesh.walker_from_halfedge(h).face_id())
            .collect();
        faces.sort_unstable();
        for &g in &faces {
            if *g as usize == self.faces.len() {
                self.faces.push(g);
            } else if *g as usize > self.faces.len() {
                return Err(self.broken(format!(
                    "tri-mesh gave a new face id {}, not {}",
                    *g,
                    self.faces.len()
                )));
            }
            self.note_face(g);
        }
        let around: Vec<HalfEdgeID> = self.mesh.vertex_halfedge_iter(v).collect();
        for h in around {
            self.note_half_edge(h);
            if let Some(t) = self.mesh.walker_from_halfedge(h).twin_id() {
                self.note_half_edge(t);
            }
        }
        Ok(())
    }

    fn broken(&self, message: String) -> Error {
        Error::Invariant {
            structure: crate::tri_mesh::NAME,
            message,
        }
    }
}

impl MeshEdit for TriMesh {
    /// tri-mesh removes at once, freeing the id for the next new element; the adapter never
    /// removes (see the module docs).
    const DELETION: Deletion = Deletion::Removed;

    /// tri-mesh's `add_face` replaces the boundary half-edge of an edge the new face takes
    /// by a new one, so that edge's id (its smaller half-edge) may change.
    const STABLE_EDGE_IDS: bool = false;

    /// tri-mesh's own calls, after the lab's checks; welds of edges, faces and meshes: the
    /// lab's rebuild from the welded face list. Deletion, collapse and the vertex split are
    /// left out (see the module docs).
    const OFFERS: Offers<Self> = Offers {
        add_vertex: Some(Self::add_vertex_checked),
        add_face: Some(Self::add_face_checked),
        flip_edge: Some(Self::flip_edge_checked),
        split_edge: Some(Self::split_edge_checked),
        split_face: Some(Self::split_face_checked),
        rebuilds: true,
        ..Offers::NOTHING
    };

    fn edit_cost(op: EditOp) -> Cost {
        match op {
            // `IDMap::insert_new`.
            EditOp::AddVertex => Cost::Constant,
            // `connecting_edge` turns around each corner; `flip_edge` asks it of the new
            // edge's ends (and the lab's checks turn around a corner).
            EditOp::AddFace | EditOp::FlipEdge => Cost::Local,
            // A fixed number of walker steps and new records, and the adapter's notes of the
            // few faces around the new vertex.
            EditOp::SplitEdge | EditOp::SplitFace => Cost::Constant,
            // Nothing is ever removed, so there is nothing to collect; welding meshes is the
            // lab's rebuild from the welded face list, as everywhere.
            EditOp::GarbageCollection => Cost::Constant,
            // Moving vertices: the adapter's `set_position`, O(1) per vertex; k: the vertices
            // selected.
            EditOp::SetPosition => Cost::Constant,
            EditOp::RotateSelection | EditOp::ScaleSelection => Cost::Local,
            EditOp::Smooth => topolab_structures::core::edit::smooth_cost::<Self>(),
            _ => Cost::Linear,
        }
    }

    fn set_position(&mut self, v: VertexId, p: DVec3) -> Result<()> {
        let Some(&x) = self.vertices.get(v.index()) else {
            return Err(refuse::<Self>(EditOp::SetPosition, Refusal::NoSuchElement));
        };
        self.mesh
            .set_vertex_position(x, Vector3::new(p.x, p.y, p.z));
        Ok(())
    }

    fn is_deleted_vertex(&self, _: VertexId) -> bool {
        false
    }
    fn is_deleted_face(&self, _: FaceId) -> bool {
        false
    }
    /// Nothing is ever removed (see the module docs).
    fn garbage_collection(&mut self) {}

    fn reserve(&mut self, vertices: usize, edges: usize, faces: usize) {
        self.vertices.reserve(vertices);
        self.faces.reserve(faces);
        self.half_edges.reserve(2 * edges);
    }
}

impl TriMesh {
    fn add_vertex_checked(&mut self, p: DVec3) -> Result<VertexId> {
        let v = self.mesh.add_vertex(Vector3::new(p.x, p.y, p.z));
        self.note_vertex(v)
    }

    /// tri-mesh's `add_face`, after the lab's checks: tri-mesh checks nothing (a face on a
    /// directed edge already taken, or making a vertex of several fans, would be linked
    /// wrongly) and stores triangles only.
    fn add_face_checked(&mut self, vertices: &[VertexId]) -> Result<FaceId> {
        check_add_face(self, vertices, true)?;
        let [a, b, c] = [0, 1, 2].map(|i| self.vertices[vertices[i].index()]);
        let g = self.mesh.add_face(a, b, c);
        if *g as usize != self.faces.len() {
            return Err(self.broken(format!(
                "tri-mesh gave the new face id {}, not {}",
                *g,
                self.faces.len()
            )));
        }
        self.faces.push(g);
        self.note_face(g);
        Ok(FaceId(*g))
    }

    /// tri-mesh's `flip_edge`, after the lab's checks (tri-mesh's own refuse a boundary edge
    /// and an existing new edge, but not two triangles with the same third corner).
    fn flip_edge_checked(&mut self, e: EdgeId) -> Result<()> {
        if !self.is_edge(e) {
            return Err(refuse::<Self>(EditOp::FlipEdge, Refusal::NoSuchElement));
        }
        check_flip(self, e)?;
        self.mesh
            .flip_edge(self.half_edge(e))
            .map_err(|err| self.broken(format!("tri-mesh refused a flip the lab allows: {err:?}")))
    }

    /// tri-mesh's `split_edge`, after the lab's checks (tri-mesh checks nothing: on two
    /// triangles with the same third corner it would make an edge of four triangles).
    fn split_edge_checked(&mut self, e: EdgeId, p: DVec3) -> Result<VertexId> {
        if !self.is_edge(e) {
            return Err(refuse::<Self>(EditOp::SplitEdge, Refusal::NoSuchElement));
        }
        check_split_edge(self, e)?;
        let v = self
            .mesh
            .split_edge(self.half_edge(e), Vector3::new(p.x, p.y, p.z));
        let id = self.note_vertex(v)?;
        self.note_faces_around(v)?;
        Ok(id)
    }

    /// tri-mesh's `split_face`: face `f` keeps one triangle, two are appended.
    fn split_face_checked(&mut self, f: FaceId, p: DVec3) -> Result<VertexId> {
        let Some(&g) = self.faces.get(f.index()) else {
            return Err(refuse::<Self>(EditOp::SplitFace, Refusal::NoSuchElement));
        };
        let v = self.mesh.split_face(g, Vector3::new(p.x, p.y, p.z));
        let id = self.note_vertex(v)?;
        self.note_faces_around(v)?;
        Ok(id)
    }
}
