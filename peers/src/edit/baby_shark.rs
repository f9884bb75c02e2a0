//! [`MeshEdit`] for baby_shark's `CornerTable` ([`BabySharkCornerTable`]); the table of
//! calls, costs and refusals is in [`crate::baby_shark_corner_table`]'s module docs.
//!
//! baby_shark's `CornerTable` offers, in its `edit` module, `flip_edge`, `split_edge`,
//! `split_face` and `collapse_edge`, and no way to add a vertex or a face (its
//! `create_vertex` and `create_corner` are private to the crate) or to remove one. The
//! adapter does the flip. The splits append corners and a vertex, and the adapter's tables
//! from the crate's corners and vertices to the lab's ids are baby_shark's
//! `EdgeAttribute` and `VertexAttribute`, which are sized when created and cannot grow
//! ("not guaranteed to stay valid if the mesh is modified"): each split would rebuild them,
//! O(n), so the splits are left out until the tables can be kept otherwise. The collapse
//! marks corners and a vertex deleted, which the adapter's queries and `validate` would have
//! to skip; it is left out too. Each is refused as [`Refusal::NotImplemented`].

use super::{check_flip, not_implemented, refuse};
use crate::BabySharkCornerTable;
use baby_shark::exports::nalgebra::Vector3;
use baby_shark::mesh::corner_table::{EdgeId as SharkEdge, FaceId as SharkFace};
use glam::DVec3;
use topolab_structures::{
    Cost, Deletion, EdgeId, EditOp, FaceId, MeshEdit, Refusal, Result, VertexId,
};

impl BabySharkCornerTable {
    /// The crate's corners (edges) of face `g`.
    fn corners_of(&self, g: SharkFace) -> [SharkEdge; 3] {
        let (a, b, c) = self.mesh.face_edges(g);
        [a, b, c]
    }

    /// The crate's vertices joined by corner `c`'s edge, as an unordered pair.
    fn ends(&self, c: SharkEdge) -> [u32; 2] {
        let (a, b) = self.mesh.edge_vertices(c);
        let (a, b) = (self.vertex_ids[a], self.vertex_ids[b]);
        [a.min(b), a.max(b)]
    }
}

impl MeshEdit for BabySharkCornerTable {
    /// baby_shark marks deleted corners and vertices (and never reuses them); the adapter
    /// deletes nothing (see the module docs).
    const DELETION: Deletion = Deletion::Marked;

    fn edit_cost(op: EditOp) -> Cost {
        match op {
            // baby_shark's flip rewrites the six corners of the two triangles, O(1); the
            // lab's check that the new edge does not exist turns around one far corner.
            EditOp::FlipEdge => Cost::Local,
            // Nothing is ever deleted; welding meshes is the lab's rebuild from the welded
            // face list, as everywhere.
            EditOp::GarbageCollection => Cost::Constant,
            _ => Cost::Linear,
        }
    }

    fn supports(op: EditOp) -> bool {
        matches!(
            op,
            EditOp::FlipEdge | EditOp::GarbageCollection | EditOp::WeldMeshes
        )
    }

    fn add_vertex(&mut self, _: DVec3) -> Result<VertexId> {
        not_implemented::<Self, _>(EditOp::AddVertex)
    }

    /// A vertex of a face is moved in the crate (`Vertex::set_position` through the
    /// table's `IndexMut`); one no face uses is the adapter's, kept beside the mesh.
    fn set_position(&mut self, v: VertexId, p: DVec3) -> Result<()> {
        match self.vertices.get(v.index()) {
            Some(&Some(x)) => {
                self.mesh[x].set_position(Vector3::new(p.x, p.y, p.z));
                Ok(())
            }
            Some(None) => {
                let i = self
                    .isolated
                    .binary_search_by_key(&v.0, |&(w, _)| w)
                    .map_err(|_| refuse::<Self>(EditOp::AddVertex, Refusal::NoSuchElement))?;
                self.isolated[i].1 = p;
                Ok(())
            }
            None => Err(refuse::<Self>(EditOp::AddVertex, Refusal::NoSuchElement)),
        }
    }

    fn add_face(&mut self, _: &[VertexId]) -> Result<FaceId> {
        not_implemented::<Self, _>(EditOp::AddFace)
    }
    fn delete_face(&mut self, _: FaceId) -> Result<()> {
        not_implemented::<Self, _>(EditOp::DeleteFace)
    }
    fn delete_vertex(&mut self, _: VertexId) -> Result<()> {
        not_implemented::<Self, _>(EditOp::DeleteVertex)
    }

    /// baby_shark's `flip_edge` on the edge's corner, after the lab's checks: baby_shark
    /// checks nothing (on a boundary edge its walker's `move_to_opposite` finds no opposite
    /// corner, a `debug_assert!` panic in a debug build, a walk on from the wrong corner in a
    /// release build; on two triangles with the same third corner, a pillow, it leaves two
    /// degenerate triangles such as (1, 0, 0) and (0, 2, 0)).
    /// The two faces keep their corners, whose vertices change, so the adapter re-reads the
    /// lab's edge of each of the six corners: the flipped edge keeps its id, and so do the
    /// four around it.
    fn flip_edge(&mut self, e: EdgeId) -> Result<()> {
        if e.index() >= self.edges.len() {
            return Err(refuse::<Self>(EditOp::FlipEdge, Refusal::NoSuchElement));
        }
        check_flip(self, e)?;
        let h = self.edges[e.index()];
        let (g1, Some(g2)) = self.mesh.edge_faces(h) else {
            return Err(refuse::<Self>(EditOp::FlipEdge, Refusal::BoundaryEdge));
        };
        let corners: Vec<SharkEdge> = [g1, g2]
            .into_iter()
            .flat_map(|g| self.corners_of(g))
            .collect();
        let before: Vec<([u32; 2], u32)> = corners
            .iter()
            .map(|&c| (self.ends(c), self.corner_ids[c][0]))
            .collect();
        self.mesh.flip_edge(h);
        for &c in &corners {
            let ends = self.ends(c);
            let id = before
                .iter()
                .find(|(pair, _)| *pair == ends)
                .map_or(e.0, |&(_, id)| id);
            self.corner_ids[c][0] = id;
            self.edges[id as usize] = c;
        }
        Ok(())
    }

    fn split_edge(&mut self, _: EdgeId, _: DVec3) -> Result<VertexId> {
        not_implemented::<Self, _>(EditOp::SplitEdge)
    }
    fn split_face(&mut self, _: FaceId, _: DVec3) -> Result<VertexId> {
        not_implemented::<Self, _>(EditOp::SplitFace)
    }
    fn collapse_edge(&mut self, _: VertexId, _: VertexId) -> Result<()> {
        not_implemented::<Self, _>(EditOp::CollapseEdge)
    }
    /// The collapse is left out (see the module docs), so its test is refused as it is.
    fn check_collapse(&self, _: VertexId, _: VertexId) -> Result<()> {
        not_implemented::<Self, _>(EditOp::CollapseEdge)
    }
    fn split_vertex(
        &mut self,
        _: VertexId,
        _: DVec3,
        _: VertexId,
        _: VertexId,
    ) -> Result<VertexId> {
        not_implemented::<Self, _>(EditOp::SplitVertex)
    }
    fn is_deleted_vertex(&self, _: VertexId) -> bool {
        false
    }
    fn is_deleted_face(&self, _: FaceId) -> bool {
        false
    }
    /// Nothing is ever deleted (see the module docs).
    fn garbage_collection(&mut self) {}

    fn reserve(&mut self, _: usize, _: usize, _: usize) {}
}
