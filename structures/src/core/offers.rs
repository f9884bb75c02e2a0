//! [`Offers`]: the topological edits a structure offers, each given as the function that does
//! it. [`MeshEdit::supports`](crate::core::edit::MeshEdit::supports) reads this table and the
//! edit calls go through it, so that what a structure says it offers and what it does cannot
//! disagree: an operation is offered exactly when its function is there, and a structure that
//! states nothing ([`Offers::NOTHING`], the default) offers nothing but the moves of its
//! vertices, refusing every other edit as not implemented in one place
//! ([`not_offered`]).

use crate::core::edit_op::{EditOp, Refusal};
use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::topology::MeshTopology;
use glam::DVec3;

/// `op` refused by `M` for `reason`: the one spelling of an edit's refusal.
pub fn refuse<M: MeshTopology>(op: EditOp, reason: Refusal) -> Error {
    Error::EditRefused {
        structure: M::NAME,
        op,
        reason,
    }
}

/// `op` refused by `M` as one it does not offer ([`Refusal::NotImplemented`]), nothing changed.
pub fn not_offered<M: MeshTopology>(op: EditOp) -> Error {
    refuse::<M>(op, Refusal::NotImplemented)
}

/// The topological edits of structure `M`: for each, the function that does it, `None` where
/// `M` does not offer it. The operations on positions (moving, selecting, rotating, scaling,
/// smoothing) and garbage collection are offered by every structure and are not in the table.
// Each field's type is its method's signature spelled out, to be read against the trait.
#[allow(clippy::type_complexity)]
pub struct Offers<M> {
    /// [`MeshEdit::add_vertex`](crate::MeshEdit::add_vertex).
    pub add_vertex: Option<fn(&mut M, DVec3) -> Result<VertexId>>,
    /// [`MeshEdit::add_face`](crate::MeshEdit::add_face).
    pub add_face: Option<fn(&mut M, &[VertexId]) -> Result<FaceId>>,
    /// [`MeshEdit::delete_face`](crate::MeshEdit::delete_face).
    pub delete_face: Option<fn(&mut M, FaceId) -> Result<()>>,
    /// [`MeshEdit::delete_vertex`](crate::MeshEdit::delete_vertex).
    pub delete_vertex: Option<fn(&mut M, VertexId) -> Result<()>>,
    /// [`MeshEdit::flip_edge`](crate::MeshEdit::flip_edge).
    pub flip_edge: Option<fn(&mut M, EdgeId) -> Result<()>>,
    /// [`MeshEdit::split_edge`](crate::MeshEdit::split_edge).
    pub split_edge: Option<fn(&mut M, EdgeId, DVec3) -> Result<VertexId>>,
    /// [`MeshEdit::split_face`](crate::MeshEdit::split_face).
    pub split_face: Option<fn(&mut M, FaceId, DVec3) -> Result<VertexId>>,
    /// [`MeshEdit::collapse_edge`](crate::MeshEdit::collapse_edge).
    pub collapse_edge: Option<fn(&mut M, VertexId, VertexId) -> Result<()>>,
    /// [`MeshEdit::split_vertex`](crate::MeshEdit::split_vertex).
    pub split_vertex: Option<fn(&mut M, VertexId, DVec3, VertexId, VertexId) -> Result<VertexId>>,
    /// [`MeshEdit::weld_vertices`](crate::MeshEdit::weld_vertices).
    pub weld_vertices: Option<fn(&mut M, VertexId, VertexId) -> Result<()>>,
    /// [`MeshEdit::insert_edge`](crate::MeshEdit::insert_edge).
    pub insert_edge: Option<fn(&mut M, FaceId, VertexId, VertexId) -> Result<FaceId>>,
    /// [`MeshEdit::delete_edge`](crate::MeshEdit::delete_edge).
    pub delete_edge: Option<fn(&mut M, EdgeId) -> Result<()>>,
    /// The welds of edges, faces and whole meshes ([`crate::algorithms::weld`]): rebuilds of
    /// the structure from the welded face list, offered by a structure that declares it can be
    /// rebuilt from every mesh a weld makes.
    pub rebuilds: bool,
}

impl<M> Offers<M> {
    /// Nothing but the operations on positions and garbage collection.
    pub const NOTHING: Self = Offers {
        add_vertex: None,
        add_face: None,
        delete_face: None,
        delete_vertex: None,
        flip_edge: None,
        split_edge: None,
        split_face: None,
        collapse_edge: None,
        split_vertex: None,
        weld_vertices: None,
        insert_edge: None,
        delete_edge: None,
        rebuilds: false,
    };

    /// Is `op` offered? The operations every structure offers are; a topological edit is when
    /// its function is in the table.
    pub const fn offers(&self, op: EditOp) -> bool {
        match op {
            EditOp::SetPosition
            | EditOp::Select
            | EditOp::RotateSelection
            | EditOp::ScaleSelection
            | EditOp::Smooth
            | EditOp::GarbageCollection => true,
            EditOp::AddVertex => self.add_vertex.is_some(),
            EditOp::AddFace => self.add_face.is_some(),
            EditOp::DeleteFace => self.delete_face.is_some(),
            EditOp::DeleteVertex => self.delete_vertex.is_some(),
            EditOp::FlipEdge => self.flip_edge.is_some(),
            EditOp::SplitEdge => self.split_edge.is_some(),
            EditOp::SplitFace => self.split_face.is_some(),
            EditOp::CollapseEdge => self.collapse_edge.is_some(),
            EditOp::SplitVertex => self.split_vertex.is_some(),
            EditOp::WeldVertices => self.weld_vertices.is_some(),
            EditOp::InsertEdge => self.insert_edge.is_some(),
            EditOp::DeleteEdge => self.delete_edge.is_some(),
            EditOp::WeldEdges | EditOp::WeldFaces | EditOp::WeldMeshes => self.rebuilds,
        }
    }
}
