//! [`MeshEdit`](crate::MeshEdit) for the winged-edge: every operation of
//! [`crate::core::rewrite`] over one primitive, [`FaceRewrite::rewrite`], which replaces a
//! few faces by others in the records of the lecture on 3D convex hulls.
//!
//! ## Costs
//!
//! The lecture on polygon-mesh data structures gives no editing table; an edit costs the
//! queries it needs from the table *winged-edge Struktur – Zusammenfassung* plus the records it
//! writes. The vertex rows are O(k) here, not the table's O(n) scan, because the hull
//! lecture's record stores `av(v)` (see the module docs): the edge between two vertices is
//! found by walking the fan of one from its `av` before anything changes, so a rewrite of k
//! faces costs O(k), with no index beside the record. (The hull algorithms' index by end
//! vertices, a hash map, made the edits many times slower than the half-edges' on the
//! 1M-triangle torus, one cache miss per look-up; an edit drops it, and the hull API builds
//! it again on its next call.)
//!
//! | operation | reads | writes | cost |
//! |---|---|---|---|
//! | add vertex | — | a position, `av` none | O(1) |
//! | add face | the fan of each corner (one fan after?) | k edges found or made, their wings on the new side | O(k) |
//! | delete face | the fans of its corners | its side of each edge; an edge left without faces goes | O(k) |
//! | delete vertex | its fan, the fans of its neighbours | its faces go | O(k) |
//! | flip edge | the two triangles (`fccw`, `fcw`), the ring of one far corner | two faces and the edge rewritten in place | O(k) |
//! | split edge | the one or two triangles | a vertex, up to three edges and two faces | O(k) |
//! | split face | the face's cycle | a vertex, k spokes, k − 1 faces | O(k) |
//! | collapse edge | the link condition on the two rings (each neighbour of one end looked for in the other's ring, O(k²)) and the tetrahedron test | the faces around the removed vertex | O(k²) |
//! | split vertex | one side of the fan | the moved faces, three edges, two faces | O(k) |
//! | weld vertices | the two fans and their neighbours' | the faces around the welded vertex | O(k) |
//! | insert edge | the face's cycle, one fan (is the diagonal an edge already?) | one face rewritten as two, one edge | O(k) |
//! | delete edge | the edge's two faces (`fccw`, `fcw`) | two faces rewritten as one, the edge freed | O(k) |
//! | set position | — | a position | O(1) |
//! | select | every position | — | O(n) |
//! | rotate, scale a selection | k positions | k positions | O(k) |
//! | smooth | the fan of every vertex | every interior position | O(n) |
//! | garbage collection | every record | vertices renumbered | O(n) |
//! | weld meshes | [`weld_meshes`](crate::algorithms::weld::weld_meshes): both meshes | a rebuild | O(n) |
//!
//! Ids: a rewrite gives the old faces' ids to the new faces in order and appends the rest; an
//! edge keeps its id while a face still has it, and an edge that leaves lends its slot to an
//! edge that comes in the same rewrite (a flipped edge keeps its id). Freed face and edge
//! slots are filled by the last one (re-pointing its O(k) neighbours), so ids stay dense and
//! the queries need no liveness test. A mesh with tombstones of the hull's incremental API is
//! compacted (O(n)) by its first edit.

use super::records::{ends_key, EdgeRecord};
use super::WingedEdge;
use crate::core::edit::{smooth_cost, EditOp};
use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::rewrite::{compact_vertices, mesh_edit_by_rewrite, retain_unmarked, FaceRewrite};
use crate::core::topology::Cost;
use glam::DVec3;

fn cost(op: EditOp) -> Cost {
    match op {
        EditOp::AddVertex => Cost::Constant,
        EditOp::GarbageCollection | EditOp::WeldEdges | EditOp::WeldFaces | EditOp::WeldMeshes => {
            Cost::Linear
        }
        EditOp::AddFace
        | EditOp::DeleteFace
        | EditOp::DeleteVertex
        | EditOp::FlipEdge
        | EditOp::SplitEdge
        | EditOp::SplitFace
        | EditOp::SplitVertex
        | EditOp::WeldVertices => Cost::Local,
        // The link condition compares the two rings (see the table).
        EditOp::CollapseEdge => Cost::LocalSquared,
        // The face's cycle and one fan (is the diagonal an edge already?); the edge's two
        // faces: rewrites of O(k) records.
        EditOp::InsertEdge | EditOp::DeleteEdge => Cost::Local,
        EditOp::SetPosition => Cost::Constant,
        EditOp::Select => Cost::Linear,
        // k: the vertices selected, each moved by `set_position`.
        EditOp::RotateSelection | EditOp::ScaleSelection => Cost::Local,
        EditOp::Smooth => smooth_cost::<WingedEdge>(),
    }
}

mesh_edit_by_rewrite!(WingedEdge, cost);

impl WingedEdge {
    /// Closes the hull API's tombstones, so that face and edge ids are dense, and drops its
    /// index (which edits do not keep).
    fn make_dense(&mut self) {
        if self.af.len() != self.live_faces || self.edges.len() != self.live_edges {
            self.compact();
        }
        self.index = None;
    }

    /// The edge between `a` and `b`, found in `a`'s fan: O(k).
    fn edge_between(&self, a: VertexId, b: VertexId) -> Option<EdgeId> {
        let mut found = None;
        self.walk_star(
            a,
            |e| {
                if found.is_none() && self.edges[e.index()].other_end(a) == b {
                    found = Some(e);
                }
            },
            |_| {},
        );
        found
    }

    /// Empties `face`'s side of each of its edges; an edge left without faces stays, loose
    /// (ends kept, no face), and is returned in `loose`; the face's edges go to `cycle`, its
    /// corners to `corners`.
    fn unlink_face(
        &mut self,
        face: FaceId,
        loose: &mut Vec<EdgeId>,
        cycle: &mut Vec<EdgeId>,
        corners: &mut Vec<VertexId>,
    ) {
        let first = cycle.len();
        self.walk_face(face, |e, r| {
            cycle.push(e);
            corners.push(r.ends_in(face)[0]);
        });
        for &e in &cycle[first..] {
            let r = &mut self.edges[e.index()];
            if r.fcw == face {
                (r.fcw, r.pcw, r.ncw) = (FaceId::INVALID, EdgeId::INVALID, EdgeId::INVALID);
            } else if r.fcw.is_valid() {
                r.turn_right_side_left();
            } else {
                (r.fccw, r.pccw, r.nccw) = (FaceId::INVALID, EdgeId::INVALID, EdgeId::INVALID);
                loose.push(e);
            }
        }
        self.af[face.index()] = EdgeId::INVALID;
    }

    /// Writes face `face` with corners `vs` into the records: each side found by its ends in
    /// `known` (a loose edge takes the face on its left, turned to run with it; an edge with a
    /// face takes it on its right) or made, in a slot of `spare` first, and added to `known`.
    fn link_face(
        &mut self,
        face: FaceId,
        vs: &[VertexId],
        spare: &mut Vec<EdgeId>,
        known: &mut Vec<(u64, EdgeId)>,
    ) {
        let k = vs.len();
        let mut ids = Vec::with_capacity(k);
        for i in 0..k {
            let (a, b) = (vs[i], vs[(i + 1) % k]);
            let key = ends_key(a, b);
            let found = known.iter().find(|(x, _)| *x == key).map(|&(_, e)| e);
            let e = match found {
                Some(e) => {
                    let r = &mut self.edges[e.index()];
                    if r.fccw.is_valid() {
                        r.fcw = face;
                    } else {
                        (r.v1, r.v2, r.fccw) = (a, b, face);
                    }
                    e
                }
                None => {
                    let record = EdgeRecord {
                        v1: a,
                        v2: b,
                        fccw: face,
                        ..EdgeRecord::REMOVED
                    };
                    let e = match spare.pop() {
                        Some(e) => {
                            self.edges[e.index()] = record;
                            e
                        }
                        None => {
                            self.edges.push(record);
                            EdgeId::new(self.edges.len() - 1)
                        }
                    };
                    known.push((key, e));
                    self.live_edges += 1;
                    e
                }
            };
            ids.push(e);
        }
        for i in 0..k {
            let (before, after) = (ids[(i + k - 1) % k], ids[(i + 1) % k]);
            let r = &mut self.edges[ids[i].index()];
            if r.fccw == face {
                (r.pccw, r.nccw) = (before, after);
            } else {
                (r.pcw, r.ncw) = (before, after);
            }
            self.av[vs[i].index()] = ids[i];
        }
        self.af[face.index()] = ids[0];
    }

    /// Moves the last edge into the free slot `e` (a removed record), re-pointing its wings,
    /// its faces' and ends' handles and the index.
    fn fill_edge_slot(&mut self, e: EdgeId) {
        let last = EdgeId::new(self.edges.len() - 1);
        if last != e {
            let r = self.edges[last.index()];
            for w in [r.pccw, r.nccw, r.pcw, r.ncw] {
                if let Some(w) = w.valid() {
                    let x = &mut self.edges[w.index()];
                    for field in [&mut x.pccw, &mut x.nccw, &mut x.pcw, &mut x.ncw] {
                        if *field == last {
                            *field = e;
                        }
                    }
                }
            }
            for f in [r.fccw, r.fcw].into_iter().filter(|f| f.is_valid()) {
                if self.af[f.index()] == last {
                    self.af[f.index()] = e;
                }
            }
            for v in [r.v1, r.v2] {
                if self.av[v.index()] == last {
                    self.av[v.index()] = e;
                }
            }
            self.edges[e.index()] = r;
        }
        self.edges.pop();
    }

    /// Moves the last face into the free slot `f`.
    fn fill_face_slot(&mut self, f: FaceId) {
        let last = FaceId::new(self.af.len() - 1);
        if last != f {
            let mut cycle = Vec::with_capacity(4);
            self.walk_face(last, |e, _| cycle.push(e));
            for e in cycle {
                let r = &mut self.edges[e.index()];
                if r.fccw == last {
                    r.fccw = f;
                } else {
                    r.fcw = f;
                }
            }
            self.af[f.index()] = self.af[last.index()];
        }
        self.af.pop();
    }
}

impl FaceRewrite for WingedEdge {
    fn push_vertex(&mut self, p: DVec3) -> Result<VertexId> {
        if self.positions.len() >= u32::MAX as usize - 1 {
            return Err(Error::TooLarge {
                what: "vertices",
                count: self.positions.len() as u64 + 1,
            });
        }
        if !self.deleted.is_empty() {
            self.deleted.push(false);
        }
        Ok(self.add_vertex(p))
    }

    fn write_position(&mut self, v: VertexId, p: DVec3) {
        self.positions[v.index()] = p;
    }

    fn is_edge(&self, e: EdgeId) -> bool {
        self.edges.get(e.index()).is_some_and(EdgeRecord::is_live)
    }

    fn vertex_deleted(&self, v: VertexId) -> bool {
        self.deleted.get(v.index()).copied().unwrap_or(false)
    }

    fn mark_vertex_deleted(&mut self, v: VertexId) {
        // The hull API's add_vertex does not grow the flags: grow them here.
        self.deleted.resize(self.positions.len(), false);
        self.deleted[v.index()] = true;
        self.av[v.index()] = EdgeId::INVALID;
    }

    fn rewrite(&mut self, old: &[FaceId], new: &[Vec<VertexId>]) {
        self.make_dense();
        // The edges the new faces already have, found while every fan is whole.
        let mut known: Vec<(u64, EdgeId)> = Vec::with_capacity(8);
        for vs in new {
            let k = vs.len();
            for i in 0..k {
                let (a, b) = (vs[i], vs[(i + 1) % k]);
                let key = ends_key(a, b);
                if !known.iter().any(|(x, _)| *x == key) {
                    if let Some(e) = self.edge_between(a, b) {
                        known.push((key, e));
                    }
                }
            }
        }
        let (mut loose, mut cycle, mut corners) = (Vec::new(), Vec::new(), Vec::new());
        for &f in old {
            self.unlink_face(f, &mut loose, &mut cycle, &mut corners);
        }
        // Loose edges that no new face has leave now, their slots lent to new edges.
        let mut spare = Vec::new();
        for e in loose {
            let r = self.edges[e.index()];
            let key = ends_key(r.v1, r.v2);
            if !known.iter().any(|(x, _)| *x == key) {
                self.edges[e.index()] = EdgeRecord::REMOVED;
                self.live_edges -= 1;
                spare.push(e);
            }
        }
        // The first edges made take the lowest lent slots.
        spare.sort_unstable_by(|a, b| b.cmp(a));
        for (i, vs) in new.iter().enumerate() {
            let face = match old.get(i) {
                Some(&f) => f,
                None => {
                    self.af.push(EdgeId::INVALID);
                    FaceId::new(self.af.len() - 1)
                }
            };
            self.link_face(face, vs, &mut spare, &mut known);
        }
        // A corner of an old face whose handle left takes another edge of its own: one of the
        // old faces' edges at it that stays (the fan is connected, so if the vertex keeps a
        // face, such an edge joins it to a removed one), else none.
        let at = |r: &EdgeRecord, v: VertexId| r.is_live() && (r.v1 == v || r.v2 == v);
        for v in corners {
            let handle = self.av[v.index()];
            if handle
                .valid()
                .is_some_and(|h| at(&self.edges[h.index()], v))
            {
                continue;
            }
            self.av[v.index()] = cycle
                .iter()
                .copied()
                .find(|&x| at(&self.edges[x.index()], v))
                .unwrap_or(EdgeId::INVALID);
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
        self.live_faces = self.af.len();
    }

    fn collect_vertices(&mut self) {
        let Some((deleted, map)) = compact_vertices(&mut self.deleted, self.positions.len()) else {
            return;
        };
        retain_unmarked(&mut self.positions, &deleted);
        retain_unmarked(&mut self.av, &deleted);
        for r in self.edges.iter_mut().filter(|r| r.is_live()) {
            r.v1 = map[r.v1.index()];
            r.v2 = map[r.v2.index()];
        }
        self.index = None;
    }

    fn reserve_room(&mut self, vertices: usize, edges: usize, faces: usize) {
        self.positions.reserve(vertices);
        self.av.reserve(vertices);
        self.edges.reserve(edges);
        self.af.reserve(faces);
    }
}

#[cfg(test)]
mod tests {
    use crate::core::edit::MeshEdit;
    use crate::core::ids::EdgeId;
    use crate::core::ids::FaceId;
    use crate::core::ids::VertexId;
    use crate::core::topology::MeshTopology;
    use crate::families::edge_lists::winged_edge::WingedEdge;
    use crate::meshes;

    #[test]
    fn a_flip_keeps_the_edge_id_and_a_split_keeps_the_face_id() {
        let soup = meshes::torus(6, 5);
        let mut m = WingedEdge::from_soup(&soup).expect("manifold");
        let e = EdgeId(7);
        let [a, b] = m.edge_vertices(e);
        m.flip_edge(e).expect("an interior edge of a torus flips");
        let [c, d] = m.edge_vertices(e);
        assert!(
            [c, d] != [a, b] && [c, d] != [b, a],
            "e7 joins other vertices now"
        );
        let faces = m.num_faces();
        let n = m.split_face(FaceId(3), glam::DVec3::ZERO).expect("splits");
        let mut around = Vec::new();
        m.face_vertices(FaceId(3), |v| around.push(v));
        assert!(around.contains(&n), "face 3 is one of the new triangles");
        assert_eq!(m.num_faces(), faces + 2);
        m.validate().expect("valid");
        assert_eq!(n, VertexId::new(soup.num_vertices()));
    }
}
