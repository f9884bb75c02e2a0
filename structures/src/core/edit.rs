//! [`MeshEdit`]: the editing operations the lecture on polygon-mesh data structures asks for
//! under "which operations must be available" (insert and delete vertices, edges and faces;
//! refine; thin out, with reconstruction possible again), as one trait beside
//! [`MeshTopology`], with the cost each structure declares for each operation ([`EditOp`]).
//!
//! The operations are the Euler operations of the half-edge libraries (pmp-library's
//! `SurfaceMesh`, OpenMesh): add a vertex or a face, delete a face or a vertex with its faces,
//! flip an edge between two triangles, split an edge or a face at a new vertex, collapse an
//! edge (checked with the link condition) and its inverse, the vertex split; structures that
//! mark deleted elements compact them in [`MeshEdit::garbage_collection`].
//!
//! ## What an edit promises
//!
//! - An operation that cannot be done (a flip of a boundary edge, a collapse that fails the
//!   link condition, a face that would make a vertex or an edge non-manifold) returns
//!   [`Error::EditRefused`](crate::Error::EditRefused) with the reason ([`Refusal`]) and
//!   changes nothing.
//! - After every operation `validate()` holds.
//! - Ids are stable: new elements are appended (vertex `num_vertices()` before the call, and
//!   so on), nothing is renumbered until [`MeshEdit::garbage_collection`].
//! - Deletion: a structure that marks ([`Deletion::Marked`]) keeps deleted elements' slots,
//!   so counts, enumerations and ids include them until `garbage_collection`, which removes
//!   them keeping the survivors' order (vertex `i` before vertex `j` stays before it). Queries
//!   about a deleted element are meaningless. A vertex left without faces by a deleted face is
//!   kept, unused, as a file's unused vertices are; [`MeshEdit::delete_vertex`] removes one.

use crate::core::error::Result;
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::topology::{Cost, MeshTopology};
use glam::DVec3;

/// One editing operation of [`MeshEdit`], for its declared cost.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum EditOp {
    /// Add an unused vertex.
    AddVertex,
    /// Add a face on existing vertices.
    AddFace,
    /// Delete a face (its edges that border nothing else go with it).
    DeleteFace,
    /// Delete a vertex and every face around it.
    DeleteVertex,
    /// Flip the edge between two triangles to join their other two corners.
    FlipEdge,
    /// Split an edge (and its one or two triangles) at a new vertex.
    SplitEdge,
    /// Split a face into a fan of triangles around a new vertex.
    SplitFace,
    /// Collapse an edge into one of its end vertices, with the link condition checked.
    CollapseEdge,
    /// Split a vertex into an edge and two triangles: the inverse of a collapse.
    SplitVertex,
    /// Compact the slots of deleted elements.
    GarbageCollection,
    /// Merge two vertices into one ([`MeshEdit::weld_vertices`]).
    WeldVertices,
    /// Append a mesh and weld it along matching boundary curves
    /// ([`weld_meshes`](crate::algorithms::weld::weld_meshes)): a rebuild, O(n) everywhere.
    WeldMeshes,
}

impl EditOp {
    /// Every operation, in the order above.
    pub const ALL: [EditOp; 12] = [
        EditOp::AddVertex,
        EditOp::AddFace,
        EditOp::DeleteFace,
        EditOp::DeleteVertex,
        EditOp::FlipEdge,
        EditOp::SplitEdge,
        EditOp::SplitFace,
        EditOp::CollapseEdge,
        EditOp::SplitVertex,
        EditOp::GarbageCollection,
        EditOp::WeldVertices,
        EditOp::WeldMeshes,
    ];

    /// The kebab-case name.
    pub const fn name(self) -> &'static str {
        match self {
            EditOp::AddVertex => "add-vertex",
            EditOp::AddFace => "add-face",
            EditOp::DeleteFace => "delete-face",
            EditOp::DeleteVertex => "delete-vertex",
            EditOp::FlipEdge => "flip-edge",
            EditOp::SplitEdge => "split-edge",
            EditOp::SplitFace => "split-face",
            EditOp::CollapseEdge => "collapse-edge",
            EditOp::SplitVertex => "split-vertex",
            EditOp::GarbageCollection => "garbage-collection",
            EditOp::WeldVertices => "weld-vertices",
            EditOp::WeldMeshes => "weld-meshes",
        }
    }
}

impl std::fmt::Display for EditOp {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// Why an edit was refused (nothing was changed).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum Refusal {
    /// An id that is out of range or names a deleted element.
    NoSuchElement,
    /// A weld of a vertex to itself: both ids name the same vertex.
    SameVertex,
    /// A face with fewer than three corners or a repeated vertex.
    BadFace,
    /// The result would have an edge with more than two faces.
    NonManifoldEdge,
    /// The result would have a vertex whose faces form several fans.
    NonManifoldVertex,
    /// The operation needs triangles (flip, edge split, collapse) and a face is not one.
    NotTriangles,
    /// A flip of a boundary edge (it has one triangle).
    BoundaryEdge,
    /// The edge a flip or a split would create exists already.
    EdgeExists,
    /// The vertices asked for are not neighbours as the operation needs.
    NotNeighbours,
    /// A collapse that fails the link condition (the one-rings of the two vertices share a
    /// vertex that is not on a triangle of the edge), or that would join two boundaries
    /// through an interior edge or close a boundary triangle: the result would not be a
    /// manifold.
    LinkCondition,
    /// Boundary curves to weld run the same way where they meet: the result would not be
    /// oriented.
    Orientation,
    /// No boundary vertex of one mesh coincides with one of the other (within the tolerance).
    NothingToWeld,
    /// A case this structure does not implement yet (named in its docs).
    NotImplemented,
}

impl Refusal {
    /// What the refusal means, for messages.
    pub const fn message(self) -> &'static str {
        match self {
            Refusal::NoSuchElement => "an id is out of range or names a deleted element",
            Refusal::SameVertex => "both ids name the same vertex: a vertex cannot be welded to itself",
            Refusal::BadFace => "a face needs at least three distinct vertices",
            Refusal::NonManifoldEdge => "an edge would have more than two faces",
            Refusal::NonManifoldVertex => "a vertex's faces would form several fans",
            Refusal::NotTriangles => "the faces around the edge must be triangles",
            Refusal::BoundaryEdge => "a boundary edge has one triangle and cannot be flipped",
            Refusal::EdgeExists => "the edge it would create exists already",
            Refusal::NotNeighbours => "the vertices are not neighbours as required",
            Refusal::LinkCondition => {
                "the link condition fails: the result would not be a manifold"
            }
            Refusal::Orientation => {
                "the boundary curves run the same way where they meet: the result would not be oriented"
            }
            Refusal::NothingToWeld => "no boundary vertices coincide within the tolerance",
            Refusal::NotImplemented => "this case is not implemented by this structure",
        }
    }
}

impl std::fmt::Display for Refusal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.message())
    }
}

/// How a structure deletes.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Deletion {
    /// Deleted elements keep their slots, marked, until [`MeshEdit::garbage_collection`]
    /// (OpenMesh's and pmp-library's choice: ids stay valid during a sequence of edits).
    Marked,
    /// Deleted elements leave at once; `garbage_collection` has nothing to do.
    Removed,
    /// Deleted faces (and stored edges) leave at once, the last one moving into the freed
    /// slot (O(k) to re-point it); deleted vertices keep their slots, marked, until
    /// [`MeshEdit::garbage_collection`] (the structures edited through
    /// [`FaceRewrite`](crate::core::rewrite::FaceRewrite)).
    LastMoves,
}

/// The editing operations; see the module docs for what every edit promises.
pub trait MeshEdit: MeshTopology {
    /// How the structure deletes.
    const DELETION: Deletion;

    /// Does an edge keep its id through edits that keep the edge (a split of a face beside
    /// it, a flip elsewhere)? The changing workloads' √3 step flips the old edges by id after
    /// splitting every face, which needs it. `false` where edge ids are derived from the
    /// faces (the vertex list names an edge by a corner).
    const STABLE_EDGE_IDS: bool = true;

    /// The cost of `op` in this structure, in the notation of the queries' costs (meaningful
    /// where [`MeshEdit::supports`] says yes).
    fn edit_cost(op: EditOp) -> Cost;

    /// Does the structure implement `op`? An operation it does not refuses every call with
    /// [`Refusal::NotImplemented`].
    fn supports(op: EditOp) -> bool {
        op != EditOp::WeldVertices
    }

    /// Adds an unused vertex at `p`.
    fn add_vertex(&mut self, p: DVec3) -> Result<VertexId>;
    /// Moves vertex `v` to `p` (no topology changes).
    fn set_position(&mut self, v: VertexId, p: DVec3) -> Result<()>;
    /// Adds the face with corners `vertices` (counter-clockwise), refused when the result
    /// would not be an oriented manifold.
    fn add_face(&mut self, vertices: &[VertexId]) -> Result<FaceId>;
    /// Deletes face `f`; its edges that border no other face go too, its vertices stay.
    fn delete_face(&mut self, f: FaceId) -> Result<()>;
    /// Deletes vertex `v` and every face around it.
    fn delete_vertex(&mut self, v: VertexId) -> Result<()>;
    /// Flips edge `e` between two triangles: it then joins their two other corners.
    fn flip_edge(&mut self, e: EdgeId) -> Result<()>;
    /// Splits edge `e` at a new vertex at `p`, splitting its one or two triangles in two.
    fn split_edge(&mut self, e: EdgeId, p: DVec3) -> Result<VertexId>;
    /// Splits face `f` into a fan of triangles around a new vertex at `p`.
    fn split_face(&mut self, f: FaceId, p: DVec3) -> Result<VertexId>;
    /// Collapses the edge from `from` to `to` into `to`: `from` and the one or two triangles
    /// of the edge are deleted. Refused unless the link condition holds.
    fn collapse_edge(&mut self, from: VertexId, to: VertexId) -> Result<()>;
    /// Would `collapse_edge(from, to)` be done? Its tests alone, nothing changed: `Ok(())`,
    /// or the refusal it would return. A decimater that keeps only legal candidates asks
    /// this of every neighbour it prices (OpenMesh's `DecimaterT` does, in `heap_vertex`).
    /// The default runs the face-rewrite structures' test through the queries
    /// ([`crate::core::rewrite`]); a structure whose collapse has its own test overrides it
    /// with that test.
    fn check_collapse(&self, from: VertexId, to: VertexId) -> Result<()> {
        crate::core::rewrite::check_collapse(self, from, to).map(drop)
    }
    /// Splits vertex `v` into the edge from a new vertex at `p` to `v`, with the triangles
    /// (new, `v`, `left`) and (`v`, new, `right`); the faces around `v` from `left` to
    /// `right` (clockwise seen from outside, `right` excluded) move to the new vertex. The
    /// inverse of `collapse_edge(new, v)` whose triangles had `left` and `right` as third
    /// corners.
    fn split_vertex(
        &mut self,
        v: VertexId,
        p: DVec3,
        left: VertexId,
        right: VertexId,
    ) -> Result<VertexId>;
    /// Merges vertex `b` into vertex `a`: every face around `b` then has `a` instead, and `b`
    /// is deleted. Refused, nothing changed, when `a` and `b` are the same vertex
    /// ([`Refusal::SameVertex`]), when a face has both ([`Refusal::BadFace`]), or when the
    /// result would not be an oriented manifold (an edge with three faces, or `a`'s faces in
    /// several fans: the boundaries of `a` and `b` must meet along an edge, or one of them
    /// have no faces).
    fn weld_vertices(&mut self, a: VertexId, b: VertexId) -> Result<()> {
        let _ = (a, b);
        Err(crate::Error::EditRefused {
            structure: Self::NAME,
            op: EditOp::WeldVertices,
            reason: Refusal::NotImplemented,
        })
    }
    /// Is vertex `v` deleted (and not yet collected)?
    fn is_deleted_vertex(&self, v: VertexId) -> bool;
    /// Is face `f` deleted (and not yet collected)?
    fn is_deleted_face(&self, f: FaceId) -> bool;
    /// Removes the slots of deleted elements, keeping the order of the others.
    fn garbage_collection(&mut self);
    /// Reserves room for `vertices`, `edges` and `faces` more elements.
    fn reserve(&mut self, vertices: usize, edges: usize, faces: usize);
}
