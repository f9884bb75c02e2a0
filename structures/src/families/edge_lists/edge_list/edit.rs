//! [`MeshEdit`](crate::MeshEdit) for the edge list: the operations of
//! [`crate::core::rewrite`] over its edge arrays and polygon lists.
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
//! From the lecture's table *Operationen in der Kantenliste*: what is around an edge or a
//! polygon is O(1) or O(k), but "finding the shared vertices of polygons is still hard":
//! whatever is around a vertex is a scan of all n edges. So an edit costs one scan per vertex
//! whose fan it checks, and a rewrite finds the edges its new polygons share with the rest of
//! the mesh by one more scan of the edges (those of the polygons it replaces are found
//! without one).
//!
//! | operation | reads | cost |
//! |---|---|---|
//! | add vertex | — | O(1) |
//! | add face | the edges of each of its k corners: k scans | O(k·n) |
//! | delete face | the edges of each corner: k scans | O(k·n) |
//! | delete vertex | the edges of each neighbour: k scans | O(k·n) |
//! | flip edge | the edge's two polygons (O(1)), the far corner's edges: a scan | O(n) |
//! | split edge | the edge's polygons, one scan for the rewrite | O(n) |
//! | split face | the polygon's edges, one scan for the rewrite | O(n) |
//! | collapse edge | the link condition: the rings of the ends and of the two far corners | O(k·n) |
//! | split vertex | one scan per polygon of the moved fan | O(k·n) |
//! | weld vertices | the edges around each corner involved | O(k·n) |
//! | insert edge | whether the diagonal's ends are neighbours: a scan; one scan for the rewrite | O(n) |
//! | delete edge | the edge's two polygons (O(1)), one scan for the rewrite | O(n) |
//! | set position | — | O(1) |
//! | select | a scan of the positions | O(n) |
//! | rotate, scale a selection | k positions written | O(k) |
//! | smooth | R00 and the boundary test of every vertex: a scan each | O(n²) |
//! | garbage collection | renumber every edge's ends | O(n) |
//! | weld meshes | a rebuild | O(n) |
//!
//! Ids: as for the winged-edge, the new polygons take the old ones' ids first, an edge keeps
//! its id while a polygon still has it (a leaving edge lends its slot to an arriving one), and
//! freed slots are filled by the last edge or polygon.

use super::EdgeList;
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
        // Whether the diagonal's ends are joined already (a scan of the edges around one),
        // and the rewrite's one scan for the edges its polygons share with the rest.
        EditOp::InsertEdge | EditOp::DeleteEdge => Cost::Linear,
        EditOp::SetPosition => Cost::Constant,
        EditOp::Select => Cost::Linear,
        // k: the vertices selected, each moved by `set_position`.
        EditOp::RotateSelection | EditOp::ScaleSelection => Cost::Local,
        EditOp::Smooth => smooth_cost::<EdgeList>(),
    }
}

mesh_edit_by_rewrite!(EdgeList, cost);

/// The key of the undirected edge {a, b}.
fn key(a: VertexId, b: VertexId) -> (VertexId, VertexId) {
    (a.min(b), a.max(b))
}

impl EdgeList {
    /// Moves the last edge into the free slot `e`, re-pointing its polygons' lists.
    fn fill_edge_slot(&mut self, e: EdgeId) {
        let last = EdgeId::new(self.edge_start.len() - 1);
        if last != e {
            for f in [self.edge_left[last.index()], self.edge_right[last.index()]] {
                if f.is_valid() {
                    let (s, t) = (
                        self.face_offsets[f.index()] as usize,
                        self.face_offsets[f.index() + 1] as usize,
                    );
                    for x in &mut self.face_edges[s..t] {
                        if *x == last {
                            *x = e;
                        }
                    }
                }
            }
            self.edge_start[e.index()] = self.edge_start[last.index()];
            self.edge_end[e.index()] = self.edge_end[last.index()];
            self.edge_left[e.index()] = self.edge_left[last.index()];
            self.edge_right[e.index()] = self.edge_right[last.index()];
        }
        self.edge_start.pop();
        self.edge_end.pop();
        self.edge_left.pop();
        self.edge_right.pop();
    }

    /// Moves the last polygon into the free slot `f`.
    fn fill_face_slot(&mut self, f: FaceId) {
        let last = FaceId::new(self.face_offsets.len() - 2);
        if last != f {
            let edges = self.edges_of(last).to_vec();
            for e in edges {
                let i = e.index();
                if self.edge_left[i] == last {
                    self.edge_left[i] = f;
                } else if self.edge_right[i] == last {
                    self.edge_right[i] = f;
                }
            }
        }
        packed::remove(&mut self.face_edges, &mut self.face_offsets, f.index());
    }
}

impl FaceRewrite for EdgeList {
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
        e.index() < self.edge_start.len()
    }

    fn vertex_deleted(&self, v: VertexId) -> bool {
        self.deleted.get(v.index()).copied().unwrap_or(false)
    }

    fn mark_vertex_deleted(&mut self, v: VertexId) {
        self.deleted.resize(self.positions.len(), false);
        self.deleted[v.index()] = true;
    }

    fn rewrite(&mut self, old: &[FaceId], new: &[Vec<VertexId>]) {
        // Empty the old polygons' side of their edges; an edge left without polygons is loose.
        let mut loose = Vec::new();
        let mut known: Vec<((VertexId, VertexId), EdgeId)> = Vec::new();
        for &f in old {
            for e in self.edges_of(f).to_vec() {
                let i = e.index();
                known.push((key(self.edge_start[i], self.edge_end[i]), e));
                if self.edge_right[i] == f {
                    self.edge_right[i] = FaceId::INVALID;
                } else if self.edge_right[i].is_valid() {
                    self.edge_left[i] = self.edge_right[i];
                    self.edge_right[i] = FaceId::INVALID;
                    (self.edge_start[i], self.edge_end[i]) = (self.edge_end[i], self.edge_start[i]);
                } else {
                    self.edge_left[i] = FaceId::INVALID;
                    loose.push(e);
                }
            }
        }
        // The sides of the new polygons, and which of them exist: the old polygons' edges,
        // then one scan of all edges for the rest.
        let mut sides: Vec<(VertexId, VertexId)> = Vec::new();
        for vs in new {
            let k = vs.len();
            sides.extend((0..k).map(|i| key(vs[i], vs[(i + 1) % k])));
        }
        sides.sort_unstable();
        sides.dedup();
        known.retain(|(k, _)| sides.binary_search(k).is_ok());
        let missing: Vec<(VertexId, VertexId)> = sides
            .iter()
            .copied()
            .filter(|s| !known.iter().any(|(k, _)| k == s))
            .collect();
        if !missing.is_empty() {
            for (i, (&a, &b)) in self.edge_start.iter().zip(&self.edge_end).enumerate() {
                if a.is_valid() && missing.contains(&key(a, b)) {
                    known.push((key(a, b), EdgeId::new(i)));
                }
            }
        }
        let mut spare = Vec::new();
        for e in loose {
            let k = key(self.edge_start[e.index()], self.edge_end[e.index()]);
            if !known.iter().any(|(x, _)| *x == k) {
                self.edge_start[e.index()] = VertexId::INVALID;
                self.edge_end[e.index()] = VertexId::INVALID;
                spare.push(e);
            }
        }
        spare.sort_unstable_by(|a, b| b.cmp(a));
        for (i, vs) in new.iter().enumerate() {
            let face = match old.get(i) {
                Some(&f) => f,
                None => FaceId::new(self.face_offsets.len() - 1),
            };
            let k = vs.len();
            let mut run = Vec::with_capacity(k);
            for j in 0..k {
                let (a, b) = (vs[j], vs[(j + 1) % k]);
                let found = known.iter().find(|(x, _)| *x == key(a, b)).map(|&(_, e)| e);
                let e = match found {
                    Some(e) if self.edge_left[e.index()].is_valid() => {
                        self.edge_right[e.index()] = face;
                        e
                    }
                    Some(e) => {
                        let i = e.index();
                        (self.edge_start[i], self.edge_end[i], self.edge_left[i]) = (a, b, face);
                        e
                    }
                    None => {
                        let e = match spare.pop() {
                            Some(e) => e,
                            None => {
                                self.edge_start.push(a);
                                self.edge_end.push(b);
                                self.edge_left.push(face);
                                self.edge_right.push(FaceId::INVALID);
                                EdgeId::new(self.edge_start.len() - 1)
                            }
                        };
                        let i = e.index();
                        (self.edge_start[i], self.edge_end[i]) = (a, b);
                        (self.edge_left[i], self.edge_right[i]) = (face, FaceId::INVALID);
                        known.push((key(a, b), e));
                        e
                    }
                };
                run.push(e);
            }
            if i < old.len() {
                packed::set(
                    &mut self.face_edges,
                    &mut self.face_offsets,
                    face.index(),
                    &run,
                );
            } else {
                packed::push(&mut self.face_edges, &mut self.face_offsets, &run);
            }
        }
        spare.sort_unstable_by(|a, b| b.cmp(a));
        for e in spare {
            self.fill_edge_slot(e);
        }
        if old.len() > new.len() {
            let mut left: Vec<FaceId> = old[new.len()..].to_vec();
            left.sort_unstable_by(|a, b| b.cmp(a));
            for f in left {
                self.fill_face_slot(f);
            }
        }
    }

    fn collect_vertices(&mut self) {
        let Some((deleted, map)) = compact_vertices(&mut self.deleted, self.positions.len()) else {
            return;
        };
        retain_unmarked(&mut self.positions, &deleted);
        for v in self.edge_start.iter_mut().chain(self.edge_end.iter_mut()) {
            *v = map[v.index()];
        }
    }

    fn reserve_room(&mut self, vertices: usize, edges: usize, faces: usize) {
        self.positions.reserve(vertices);
        self.edge_start.reserve(edges);
        self.edge_end.reserve(edges);
        self.edge_left.reserve(edges);
        self.edge_right.reserve(edges);
        self.face_edges.reserve(3 * faces);
        self.face_offsets.reserve(faces);
    }
}
