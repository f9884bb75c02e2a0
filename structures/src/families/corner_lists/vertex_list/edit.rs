//! [`MeshEdit`](crate::MeshEdit) for the vertex list: the operations of
//! [`crate::core::rewrite`] over its one array of corners.
//!
//! ## The lecture's operations
//!
//! The lecture on polygon-mesh data structures lists the operations a structure must offer:
//! select, insert, delete, weld, rotate and scale vertices, edges and faces, and weld whole
//! meshes, and smoothing, refinement and thinning as what is changed in a mesh. Of that list
//! the structure offers the insertion and deletion of vertices, edges
//! ([`MeshEdit::insert_edge`](crate::MeshEdit::insert_edge): a diagonal splitting a face,
//! [`MeshEdit::delete_edge`](crate::MeshEdit::delete_edge): an edge removed to merge its two
//! faces, both [`crate::core::rewrite`]'s) and faces, the vertex weld, the weld of whole
//! meshes ([`weld_meshes`](crate::algorithms::weld::weld_meshes)), and moving vertices
//! ([`MeshEdit::set_position`](crate::MeshEdit::set_position)), over which
//! [`crate::algorithms::select`] selects, rotates, scales and smooths. Not implemented: the
//! weld of edges or faces. The flip, the edge and face splits, the collapse and the vertex
//! split are pmp-library's and OpenMesh's operations, not the lecture's.
//!
//! ## Costs
//!
//! The lecture on polygon-mesh data structures says of the vertex list that "finding shared
//! edges and vertices of polygons is still hard": every edit that must know what is around a
//! vertex or an edge scans all faces (the queries' O(n), see the module docs), once per
//! vertex it checks. Writing the faces is cheap when a face keeps its number of corners (in
//! place) or is appended, and shifts the corners after it (O(n)) when a polygon becomes a
//! triangle. Every operation of [`MeshEdit`](crate::MeshEdit) is implemented; none is refused
//! for being unsupported.
//!
//! | operation | reads | cost |
//! |---|---|---|
//! | add vertex | — | O(1) |
//! | add face | the faces of each of its k corners: k scans | O(k·n) |
//! | delete face | the faces of each corner: k scans; the last face moves into its slot | O(k·n) |
//! | delete vertex | the faces of each neighbour: k scans | O(k·n) |
//! | flip edge | the faces of the edge and the far corner's neighbours: a few scans | O(n) |
//! | split edge | the faces of the edge: two scans | O(n) |
//! | split face | the face's corners; a polygon's corners shift | O(n) (O(k) for a triangle) |
//! | collapse edge | the link condition: the rings of the ends and of the two far corners | O(k·n) |
//! | split vertex | one scan per face of the moved fan | O(k·n) |
//! | weld vertices | the faces around each corner involved | O(k·n) |
//! | insert edge | whether the diagonal's ends are neighbours: a scan; the face's corners shift as it shrinks | O(n) |
//! | delete edge | the edge's two faces: a scan; the merged polygon written | O(n) |
//! | set position | — | O(1) |
//! | select | a scan of the positions | O(n) |
//! | rotate, scale a selection | k positions written | O(k) |
//! | smooth | R00 and the boundary test of every vertex: a scan each | O(n²) |
//! | garbage collection | renumber every corner | O(n) |
//! | weld meshes | a rebuild | O(n) |
//!
//! Edge ids are corners (see the module docs), so an edit renumbers the edges of the faces
//! it rewrites: [`MeshEdit::STABLE_EDGE_IDS`](crate::MeshEdit::STABLE_EDGE_IDS) is `false`.

use super::VertexList;
use crate::core::edit::{smooth_cost, EditOp};
use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::rewrite::{
    compact_vertices, mesh_edit_by_rewrite, packed, retain_unmarked, FaceRewrite,
};
use crate::core::topology::Cost;
use glam::DVec3;

fn cost(op: EditOp) -> Cost {
    match op {
        EditOp::AddVertex => Cost::Constant,
        EditOp::FlipEdge
        | EditOp::SplitEdge
        | EditOp::SplitFace
        | EditOp::GarbageCollection
        | EditOp::WeldEdges
        | EditOp::WeldFaces
        | EditOp::WeldMeshes => Cost::Linear,
        EditOp::AddFace
        | EditOp::DeleteFace
        | EditOp::DeleteVertex
        | EditOp::CollapseEdge
        | EditOp::SplitVertex
        | EditOp::WeldVertices => Cost::LocalTimesLinear,
        // Whether the diagonal's ends are joined already (a scan), the face's corners
        // shifted when it shrinks; the edge's faces (a scan), the merged polygon written.
        EditOp::InsertEdge | EditOp::DeleteEdge => Cost::Linear,
        EditOp::SetPosition => Cost::Constant,
        EditOp::Select => Cost::Linear,
        // k: the vertices selected, each moved by `set_position`.
        EditOp::RotateSelection | EditOp::ScaleSelection => Cost::Local,
        EditOp::Smooth => smooth_cost::<VertexList>(),
    }
}

mesh_edit_by_rewrite!(VertexList, cost, false);

impl FaceRewrite for VertexList {
    fn push_vertex(&mut self, p: DVec3) -> Result<VertexId> {
        if self.positions.len() >= u32::MAX as usize - 1 {
            return Err(Error::TooLarge {
                what: "vertices",
                count: self.positions.len() as u64 + 1,
            });
        }
        self.positions.push(p);
        Ok(VertexId::new(self.positions.len() - 1))
    }

    fn write_position(&mut self, v: VertexId, p: DVec3) {
        self.positions[v.index()] = p;
    }

    fn is_edge(&self, e: EdgeId) -> bool {
        e.index() < self.corners.keys.len()
    }

    fn vertex_deleted(&self, v: VertexId) -> bool {
        self.deleted.get(v.index()).copied().unwrap_or(false)
    }

    fn mark_vertex_deleted(&mut self, v: VertexId) {
        self.deleted.resize(self.positions.len(), false);
        self.deleted[v.index()] = true;
    }

    fn rewrite(&mut self, old: &[FaceId], new: &[Vec<VertexId>]) {
        let c = &mut self.corners;
        for (i, vs) in new.iter().enumerate() {
            let run: Vec<u32> = vs.iter().map(|v| v.0).collect();
            match old.get(i) {
                Some(f) => packed::set(&mut c.keys, &mut c.offsets, f.index(), &run),
                None => {
                    packed::push(&mut c.keys, &mut c.offsets, &run);
                }
            }
        }
        if old.len() > new.len() {
            let mut left: Vec<FaceId> = old[new.len()..].to_vec();
            left.sort_unstable_by(|a, b| b.cmp(a));
            for f in left {
                packed::remove(&mut c.keys, &mut c.offsets, f.index());
            }
        }
    }

    fn collect_vertices(&mut self) {
        let Some((deleted, map)) = compact_vertices(&mut self.deleted, self.positions.len()) else {
            return;
        };
        retain_unmarked(&mut self.positions, &deleted);
        for k in &mut self.corners.keys {
            *k = map[*k as usize].0;
        }
    }

    fn reserve_room(&mut self, vertices: usize, _edges: usize, faces: usize) {
        self.positions.reserve(vertices);
        self.corners.keys.reserve(3 * faces);
        self.corners.offsets.reserve(faces);
    }
}
