//! [`MeshEdit`]: editing operations as one trait beside [`MeshTopology`], with the cost each
//! structure declares for each operation ([`EditOp`]). Of the operations the lecture on
//! polygon-mesh data structures asks for under "which operations must be available" (select,
//! insert, delete, weld, rotate and scale vertices, edges and faces; weld whole meshes) they
//! cover the insertion and deletion of vertices, edges ([`MeshEdit::insert_edge`],
//! [`MeshEdit::delete_edge`]) and faces, the weld of vertices (and, by
//! [`weld_meshes`](crate::algorithms::weld::weld_meshes), of whole meshes), and moving
//! vertices ([`MeshEdit::set_position`], [`MeshEdit::set_positions`]), over which
//! [`crate::algorithms::select`] selects, rotates, scales and smooths. The weld of edges or of
//! faces is not offered. Refinement and thinning, which the lecture lists as what is changed
//! in a mesh, are written over them ([`crate::algorithms::changing::sqrt3_step`],
//! [`crate::algorithms::decimate`]).
//!
//! The operations are the Euler operations of the half-edge libraries (pmp-library's
//! `SurfaceMesh`, OpenMesh): add a vertex or a face, delete a face or a vertex with its faces,
//! flip an edge between two triangles, split an edge or a face at a new vertex, collapse an
//! edge (checked with the link condition and OpenMesh's tetrahedron test) and its inverse, the
//! vertex split; structures that mark deleted elements compact them in
//! [`MeshEdit::garbage_collection`].
//!
//! ## What an edit promises
//!
//! - An operation that cannot be done (a flip of a boundary edge, a collapse that fails the
//!   link condition or the tetrahedron test, a face that would make a vertex or an edge
//!   non-manifold) returns
//!   [`Error::EditRefused`](crate::Error::EditRefused) with the reason ([`Refusal`]) and
//!   changes nothing.
//! - After every operation `validate()` holds.
//! - New elements are appended (vertex `num_vertices()` before the call, and so on). Vertex
//!   ids are stable until [`MeshEdit::garbage_collection`] in every structure; face (and
//!   edge) ids are too where the structure marks its deletions ([`Deletion::Marked`]), not
//!   where faces leave at once ([`Deletion::LastMoves`], [`Deletion::Compacted`]).
//! - Deletion: a structure that marks ([`Deletion::Marked`]) keeps deleted elements' slots,
//!   so counts, enumerations and ids include them until `garbage_collection`, which removes
//!   them keeping the survivors' order (vertex `i` before vertex `j` stays before it). Queries
//!   about a deleted element are meaningless. A vertex left without faces by a deleted face is
//!   kept, unused, as a file's unused vertices are; [`MeshEdit::delete_vertex`] removes one.

pub use crate::core::edit_op::{EditOp, Refusal};
use crate::core::error::Result;
use crate::core::ids::{EdgeId, FaceId, VertexId};
pub use crate::core::offers::{not_offered, refuse, Offers};
use crate::core::topology::{Cost, MeshTopology};
use glam::DVec3;

/// The cost of a pass over all n vertices that asks each a query of cost `query` (the
/// smoothing step's neighbours): O(n) for a local query, O(n²) for a scan.
pub const fn per_vertex_pass(query: Cost) -> Cost {
    match query {
        Cost::Constant | Cost::Log | Cost::Local | Cost::LocalSquared => Cost::Linear,
        Cost::Boundary | Cost::Linear | Cost::LocalTimesLinear | Cost::Quadratic => Cost::Quadratic,
    }
}

/// The declared cost of one [`EditOp::Smooth`] step on `M`: a pass over the n vertices that
/// asks each its neighbours (R00) and whether it is on the boundary, at `M`'s costs of those
/// queries ([`per_vertex_pass`]); the writes are O(1) each where a position is stored once.
pub fn smooth_cost<M: MeshTopology>() -> Cost {
    let scan = [
        M::cost(crate::core::operator::Operator::R00),
        M::cost(crate::core::operator::Operator::BoundaryVertex),
    ]
    .into_iter()
    .map(per_vertex_pass)
    .any(|c| c == Cost::Quadratic);
    if scan {
        Cost::Quadratic
    } else {
        Cost::Linear
    }
}

/// `Ok` when `M` offers `op`, else its refusal as not offered: the first check of an algorithm
/// written over the trait's calls (a selection's rotation, a weld's rebuild).
pub fn offered<M: MeshEdit>(op: EditOp) -> Result<()> {
    if M::supports(op) {
        Ok(())
    } else {
        Err(not_offered::<M>(op))
    }
}

/// Does `M` offer any topological edit (an operation beyond the moves, selection, smoothing
/// and garbage collection that [`Offers::NOTHING`] leaves every structure)? False for a
/// structure that moves vertices only (explicit storage, `[moves]` in the registry).
pub fn edits_topology<M: MeshEdit>() -> bool {
    EditOp::ALL
        .into_iter()
        .any(|op| !Offers::<M>::NOTHING.offers(op) && M::supports(op))
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
    /// Deleted triangles leave at once and the triangle arrays are compacted, so triangle
    /// (and half-edge) ids change: a deleted triangle's slot is taken by the last triangle
    /// (a face deletion, a collapse), or the triangles after a deleted vertex's star shift
    /// down (a vertex deletion); deleted vertices keep their slots, marked, until
    /// [`MeshEdit::garbage_collection`]. No triangle is ever marked (the CHE levels, whose
    /// arrays are indexed by triangle and half-edge).
    Compacted,
}

/// The editing operations; see the module docs for what every edit promises. A structure
/// states the topological edits it offers in [`MeshEdit::OFFERS`], each as the function
/// that does it; the calls of this trait go through that table (do not override them).
pub trait MeshEdit: MeshTopology {
    /// How the structure deletes.
    const DELETION: Deletion;

    /// Does an edge keep its id through edits that keep the edge (a split of a face beside
    /// it, a flip elsewhere)? The changing workloads' √3 step flips the old edges by id after
    /// splitting every face, which needs it. `false` where edge ids are derived from the
    /// faces (the vertex list names an edge by a corner).
    const STABLE_EDGE_IDS: bool = true;

    /// The topological edits the structure offers, each the function that does it: the
    /// calls below go through this table and [`MeshEdit::supports`] reads it, so the two
    /// cannot disagree. The default offers nothing but the operations on positions.
    const OFFERS: Offers<Self> = Offers::NOTHING;

    /// The cost of `op` in this structure, in the notation of the queries' costs (meaningful
    /// where [`MeshEdit::supports`] says yes).
    fn edit_cost(op: EditOp) -> Cost;

    /// Does the structure offer `op`? Read from [`MeshEdit::OFFERS`]: an operation it does
    /// not offer refuses every call with [`Refusal::NotImplemented`], nothing changed. Not to
    /// be overridden (state the offer in `OFFERS`).
    fn supports(op: EditOp) -> bool {
        Self::OFFERS.offers(op)
    }

    /// Moves vertex `v` to `p` (no topology changes).
    fn set_position(&mut self, v: VertexId, p: DVec3) -> Result<()>;
    /// Adds an unused vertex at `p`.
    fn add_vertex(&mut self, p: DVec3) -> Result<VertexId> {
        match Self::OFFERS.add_vertex {
            Some(f) => f(self, p),
            None => Err(not_offered::<Self>(EditOp::AddVertex)),
        }
    }
    /// Adds the face with corners `vertices` (counter-clockwise), refused when the result
    /// would not be an oriented manifold.
    fn add_face(&mut self, vertices: &[VertexId]) -> Result<FaceId> {
        match Self::OFFERS.add_face {
            Some(f) => f(self, vertices),
            None => Err(not_offered::<Self>(EditOp::AddFace)),
        }
    }
    /// Deletes face `f`; its edges that border no other face go too, its vertices stay.
    fn delete_face(&mut self, f: FaceId) -> Result<()> {
        match Self::OFFERS.delete_face {
            Some(call) => call(self, f),
            None => Err(not_offered::<Self>(EditOp::DeleteFace)),
        }
    }
    /// Deletes vertex `v` and every face around it.
    fn delete_vertex(&mut self, v: VertexId) -> Result<()> {
        match Self::OFFERS.delete_vertex {
            Some(f) => f(self, v),
            None => Err(not_offered::<Self>(EditOp::DeleteVertex)),
        }
    }
    /// Flips edge `e` between two triangles: it then joins their two other corners.
    fn flip_edge(&mut self, e: EdgeId) -> Result<()> {
        match Self::OFFERS.flip_edge {
            Some(f) => f(self, e),
            None => Err(not_offered::<Self>(EditOp::FlipEdge)),
        }
    }
    /// Splits edge `e` at a new vertex at `p`, splitting its one or two triangles in two.
    fn split_edge(&mut self, e: EdgeId, p: DVec3) -> Result<VertexId> {
        match Self::OFFERS.split_edge {
            Some(f) => f(self, e, p),
            None => Err(not_offered::<Self>(EditOp::SplitEdge)),
        }
    }
    /// Splits face `f` into a fan of triangles around a new vertex at `p`.
    fn split_face(&mut self, f: FaceId, p: DVec3) -> Result<VertexId> {
        match Self::OFFERS.split_face {
            Some(call) => call(self, f, p),
            None => Err(not_offered::<Self>(EditOp::SplitFace)),
        }
    }
    /// Collapses the edge from `from` to `to` into `to`: `from` and the one or two triangles
    /// of the edge are deleted. Refused unless the link condition holds
    /// ([`Refusal::LinkCondition`]) and OpenMesh's tetrahedron test passes
    /// ([`Refusal::TetrahedronTest`]).
    fn collapse_edge(&mut self, from: VertexId, to: VertexId) -> Result<()> {
        match Self::OFFERS.collapse_edge {
            Some(f) => f(self, from, to),
            None => Err(not_offered::<Self>(EditOp::CollapseEdge)),
        }
    }
    /// Would `collapse_edge(from, to)` be done? Its tests alone, nothing changed: `Ok(())`,
    /// or the refusal it would return. A decimater that keeps only legal candidates asks
    /// this of every neighbour it prices (OpenMesh's `DecimaterT` does, in `heap_vertex`).
    /// The default runs the face-rewrite structures' test through the queries
    /// ([`crate::core::rewrite`]); a structure whose collapse has its own test overrides it
    /// with that test.
    fn check_collapse(&self, from: VertexId, to: VertexId) -> Result<()> {
        if !Self::supports(EditOp::CollapseEdge) {
            return Err(not_offered::<Self>(EditOp::CollapseEdge));
        }
        crate::core::link::check_collapse(self, from, to, |v| self.is_deleted_vertex(v)).map(drop)
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
    ) -> Result<VertexId> {
        match Self::OFFERS.split_vertex {
            Some(f) => f(self, v, p, left, right),
            None => Err(not_offered::<Self>(EditOp::SplitVertex)),
        }
    }
    /// Merges vertex `b` into vertex `a`: every face around `b` then has `a` instead, and `b`
    /// is deleted. Refused, nothing changed, when `a` and `b` are the same vertex
    /// ([`Refusal::SameVertex`]), when a face has both ([`Refusal::BadFace`]), or when the
    /// result would not be an oriented manifold (an edge with three faces, or `a`'s faces in
    /// several fans: the boundaries of `a` and `b` must meet along an edge, or one of them
    /// have no faces).
    fn weld_vertices(&mut self, a: VertexId, b: VertexId) -> Result<()> {
        match Self::OFFERS.weld_vertices {
            Some(f) => f(self, a, b),
            None => Err(not_offered::<Self>(EditOp::WeldVertices)),
        }
    }
    /// Moves several vertices at once: `moves` lists each vertex with its new position.
    /// Refused, nothing changed, when a vertex is out of range or deleted
    /// ([`Refusal::NoSuchElement`]). The default checks every vertex, then calls
    /// [`MeshEdit::set_position`] for each: O(1) per vertex where a position is stored once.
    /// Explicit storage, which stores a position once per corner, overrides it with one pass.
    fn set_positions(&mut self, moves: &[(VertexId, DVec3)]) -> Result<()> {
        if moves
            .iter()
            .any(|&(v, _)| v.index() >= self.num_vertices() || self.is_deleted_vertex(v))
        {
            return Err(refuse::<Self>(EditOp::SetPosition, Refusal::NoSuchElement));
        }
        for &(v, p) in moves {
            self.set_position(v, p)?;
        }
        Ok(())
    }
    /// Inserts an edge between corners `a` and `b` of face `f`, which are not neighbours in
    /// it: `f` becomes the polygon from `a` to `b` (its corners in order) and a new face, whose
    /// id is returned, the polygon from `b` to `a`. Refused, nothing changed, when `f` or a
    /// vertex does not exist ([`Refusal::NoSuchElement`]), when `a` and `b` are not two corners
    /// of `f` that are not neighbours in it ([`Refusal::NotDiagonal`]), or when `a` and `b`
    /// are already joined by an edge ([`Refusal::EdgeExists`]: the edge would have more than
    /// two faces).
    fn insert_edge(&mut self, f: FaceId, a: VertexId, b: VertexId) -> Result<FaceId> {
        match Self::OFFERS.insert_edge {
            Some(call) => call(self, f, a, b),
            None => Err(not_offered::<Self>(EditOp::InsertEdge)),
        }
    }
    /// Deletes the interior edge `e`, merging its two faces into one polygon (the face running
    /// from one end to the other keeps its id as far as the structure's deletion allows; see
    /// [`Deletion`]). Refused, nothing changed, when `e` does not exist
    /// ([`Refusal::NoSuchElement`]), is a boundary edge ([`Refusal::BoundaryEdge`]), or the
    /// merged polygon would have a corner twice ([`Refusal::BadFace`]: the two faces share
    /// another vertex than the edge's ends, as around a vertex of valence 2).
    fn delete_edge(&mut self, e: EdgeId) -> Result<()> {
        match Self::OFFERS.delete_edge {
            Some(f) => f(self, e),
            None => Err(not_offered::<Self>(EditOp::DeleteEdge)),
        }
    }
    /// Is vertex `v` deleted (and not yet collected)?
    fn is_deleted_vertex(&self, v: VertexId) -> bool;
    /// Is face `f` deleted (and not yet collected)?
    fn is_deleted_face(&self, f: FaceId) -> bool;
    /// Is edge `e` deleted (and not yet collected)? Only a structure whose deletion is
    /// [`Deletion::Marked`] keeps a deleted edge's slot; the default, `false`, is every other's
    /// answer (a deleted edge's slot is reused or removed at once).
    fn is_deleted_edge(&self, e: EdgeId) -> bool {
        let _ = e;
        false
    }
    /// Removes the slots of deleted elements, keeping the order of the others.
    fn garbage_collection(&mut self);
    /// Reserves room for `vertices`, `edges` and `faces` more elements.
    fn reserve(&mut self, vertices: usize, edges: usize, faces: usize);
}
