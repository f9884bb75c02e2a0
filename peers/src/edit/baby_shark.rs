//! [`MeshEdit`] for baby_shark's `CornerTable` ([`BabySharkCornerTable`]); the table of
//! calls, costs and refusals is in [`crate::baby_shark_corner_table`]'s module docs.
//!
//! baby_shark's `CornerTable` offers, in its `edit` module, `flip_edge`, `split_edge`,
//! `split_face` and `collapse_edge`, and no way to add a vertex or a face (its
//! `create_vertex` and `create_corner` are private to the crate) or to remove one. The
//! adapter does the flip and the collapse. The collapse marks corners and a vertex deleted
//! (baby_shark never reuses them); the lab's ids of what it deleted keep their slots until
//! `garbage_collection`, which renumbers the adapter's tables (baby_shark has no call that
//! compacts its own arrays). The splits append corners and a vertex, and the adapter's
//! tables from the crate's corners and vertices to the lab's ids are baby_shark's
//! `EdgeAttribute` and `VertexAttribute`, which are sized when created and cannot grow
//! ("not guaranteed to stay valid if the mesh is modified"): each split would rebuild them,
//! O(n), so the splits are left out until the tables can be kept otherwise, refused as
//! [`Refusal::NotImplemented`] with the other operations baby_shark does not offer.

use super::check_flip;
use crate::baby_shark_corner_table::BabySharkCornerTable;
use baby_shark::exports::nalgebra::Vector3;
use baby_shark::mesh::corner_table::{EdgeId as SharkEdge, FaceId as SharkFace};
use glam::DVec3;
use topolab_structures::{
    refuse, Cost, Deletion, EdgeId, EditOp, Error, FaceId, MeshEdit, MeshTopology, Offers, Refusal,
    Result, VertexId,
};

impl BabySharkCornerTable {
    /// The crate's corners (edges) of face `g`.
    fn corners_of(&self, g: SharkFace) -> [SharkEdge; 3] {
        let (a, b, c) = self.mesh.face_edges(g);
        [a, b, c]
    }

    /// The lab's vertices joined by corner `c`'s edge, as an unordered pair.
    fn ends(&self, c: SharkEdge) -> [u32; 2] {
        let (a, b) = self.mesh.edge_vertices(c);
        let (a, b) = (self.vertex_ids[a], self.vertex_ids[b]);
        [a.min(b), a.max(b)]
    }

    /// Has baby_shark marked corner `c` deleted?
    fn corner_deleted(&self, c: SharkEdge) -> bool {
        self.mesh[c.corner()].is_deleted()
    }

    /// Is lab face `f` deleted: are its corners marked in baby_shark? (`false` out of range.)
    pub(crate) fn face_deleted(&self, f: FaceId) -> bool {
        self.faces
            .get(f.index())
            .is_some_and(|&g| self.corner_deleted(self.mesh.face_edges(g).0))
    }

    /// Is lab edge `e` deleted: is the corner the table keeps for it marked? A collapse
    /// points each edge it keeps at a live corner.
    pub(crate) fn edge_deleted(&self, e: EdgeId) -> bool {
        self.edges
            .get(e.index())
            .is_some_and(|&h| self.corner_deleted(h))
    }

    /// Is lab vertex `v` deleted: no crate vertex, and not one of the unused vertices the
    /// adapter keeps?
    fn vertex_deleted(&self, v: VertexId) -> bool {
        matches!(self.vertices.get(v.index()), Some(None))
            && self
                .isolated
                .binary_search_by_key(&v.0, |&(w, _)| w)
                .is_err()
    }

    /// The corner of the face running `a` → `b` whose edge is that side, if a face does.
    fn side(&self, a: VertexId, b: VertexId) -> Option<SharkEdge> {
        let x = self.vertices.get(a.index()).copied().flatten()?;
        let mut found = None;
        self.mesh.faces_around_vertex(x, |g| {
            let (p, q, r) = self.mesh.face_vertices(g);
            let c = [p, q, r].map(|y| self.vertex_ids[y]);
            // Corner i's edge runs from corner i + 1 to corner i + 2.
            for (i, k) in self.corners_of(g).into_iter().enumerate() {
                if (c[(i + 1) % 3], c[(i + 2) % 3]) == (a.0, b.0) {
                    found = Some(k);
                }
            }
        });
        found
    }
}

impl MeshEdit for BabySharkCornerTable {
    /// baby_shark marks deleted corners and vertices and never reuses them; the adapter
    /// keeps the lab's ids of what a collapse deleted until `garbage_collection`.
    const DELETION: Deletion = Deletion::Marked;

    /// baby_shark's flip and collapse, after the lab's checks; welds of edges, faces and
    /// meshes: the lab's rebuild from the welded face list.
    const OFFERS: Offers<Self> = Offers {
        flip_edge: Some(Self::flip_edge_checked),
        collapse_edge: Some(Self::collapse_edge_checked),
        rebuilds: true,
        ..Offers::NOTHING
    };

    fn edit_cost(op: EditOp) -> Cost {
        match op {
            // baby_shark's flip rewrites the six corners of the two triangles, O(1); the
            // lab's check that the new edge does not exist turns around one far corner.
            EditOp::FlipEdge => Cost::Local,
            // baby_shark's collapse walks the corners around the removed vertex, O(k); the
            // lab's link condition looks for each neighbour of one end among the other's.
            EditOp::CollapseEdge => Cost::LocalSquared,
            // Moving vertices: the adapter's `set_position`, O(1) per vertex; k: the vertices
            // selected.
            EditOp::SetPosition => Cost::Constant,
            EditOp::RotateSelection | EditOp::ScaleSelection => Cost::Local,
            EditOp::Smooth => topolab_structures::core::edit::smooth_cost::<Self>(),
            // The adapter's tables renumbered (baby_shark keeps its deleted records);
            // welding meshes is the lab's rebuild from the welded face list, as everywhere.
            _ => Cost::Linear,
        }
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
                    .map_err(|_| refuse::<Self>(EditOp::SetPosition, Refusal::NoSuchElement))?;
                self.isolated[i].1 = p;
                Ok(())
            }
            None => Err(refuse::<Self>(EditOp::SetPosition, Refusal::NoSuchElement)),
        }
    }

    fn is_deleted_vertex(&self, v: VertexId) -> bool {
        self.vertex_deleted(v)
    }
    fn is_deleted_face(&self, f: FaceId) -> bool {
        self.face_deleted(f)
    }

    /// Renumbers the adapter's tables without the deleted vertices, faces and edges, keeping
    /// the others' order; baby_shark has no call that compacts its own arrays, so its deleted
    /// records stay (and are never read).
    fn garbage_collection(&mut self) {
        let renumber = |gone: &dyn Fn(usize) -> bool, n: usize| {
            let mut next = 0u32;
            (0..n)
                .map(|i| {
                    if gone(i) {
                        u32::MAX
                    } else {
                        next += 1;
                        next - 1
                    }
                })
                .collect::<Vec<u32>>()
        };
        let vertex_map = renumber(
            &|v| self.vertex_deleted(VertexId::new(v)),
            self.vertices.len(),
        );
        let face_map = renumber(&|f| self.face_deleted(FaceId::new(f)), self.faces.len());
        let edge_map = renumber(&|e| self.edge_deleted(EdgeId::new(e)), self.edges.len());
        if [&vertex_map, &face_map, &edge_map]
            .iter()
            .all(|map| map.iter().all(|&i| i != u32::MAX))
        {
            return;
        }
        let keep = |map: &[u32], i: usize| map[i] != u32::MAX;
        let mut i = 0;
        self.vertices.retain(|_| {
            i += 1;
            keep(&vertex_map, i - 1)
        });
        let mut i = 0;
        self.faces.retain(|_| {
            i += 1;
            keep(&face_map, i - 1)
        });
        let mut i = 0;
        self.edges.retain(|_| {
            i += 1;
            keep(&edge_map, i - 1)
        });
        for (w, _) in &mut self.isolated {
            *w = vertex_map[*w as usize];
        }
        for (v, x) in self.vertices.iter().enumerate() {
            if let Some(x) = *x {
                self.vertex_ids[x] = v as u32;
            }
        }
        for f in 0..self.faces.len() {
            for k in self.corners_of(self.faces[f]) {
                let [e, _] = self.corner_ids[k];
                self.corner_ids[k] = [edge_map[e as usize], f as u32];
            }
        }
    }

    fn reserve(&mut self, _: usize, _: usize, _: usize) {}
}

impl BabySharkCornerTable {
    /// baby_shark's `flip_edge` on the edge's corner, after the lab's checks: baby_shark
    /// checks nothing (on a boundary edge its walker's `move_to_opposite` finds no opposite
    /// corner, a `debug_assert!` panic in a debug build, a walk on from the wrong corner in a
    /// release build; on two triangles with the same third corner, a pillow, it leaves two
    /// degenerate triangles such as (1, 0, 0) and (0, 2, 0)).
    /// The two faces keep their corners, whose vertices change, so the adapter re-reads the
    /// lab's edge of each of the six corners: the flipped edge keeps its id, and so do the
    /// four around it.
    fn flip_edge_checked(&mut self, e: EdgeId) -> Result<()> {
        if e.index() >= self.edges.len() || self.edge_deleted(e) {
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

    /// baby_shark's `collapse_edge`, after the lab's test ([`MeshEdit::check_collapse`]: the
    /// link condition and OpenMesh's tetrahedron test; baby_shark checks nothing). baby_shark
    /// collapses the side opposite a corner into the side's first end: the corner of the face
    /// running `to` → `from` keeps `to`; where only `from` → `to` has a face (a boundary
    /// edge), baby_shark keeps `from`'s record and the adapter gives it `to`'s lab id. The
    /// kept vertex is put at `to`'s position. Of each removed triangle's two other sides,
    /// the one at `to` keeps its id (its corner across now faces the one across the other),
    /// the one at `from` is deleted with the edge itself and the triangle.
    fn collapse_edge_checked(&mut self, from: VertexId, to: VertexId) -> Result<()> {
        self.check_collapse(from, to)?;
        let (Some(x_from), Some(x_to)) = (self.vertices[from.index()], self.vertices[to.index()])
        else {
            return Err(refuse::<Self>(EditOp::CollapseEdge, Refusal::NoSuchElement));
        };
        let (h, kept) = match (self.side(to, from), self.side(from, to)) {
            (Some(h), _) => (h, x_to),
            (None, Some(h)) => (h, x_from),
            (None, None) => {
                return Err(refuse::<Self>(EditOp::CollapseEdge, Refusal::NotNeighbours))
            }
        };
        // Per removed triangle: (the id that stays, its corner across), (the id deleted, its
        // own corner and its corner across).
        let mut sides = Vec::with_capacity(2);
        let faces = self.mesh.edge_faces(h);
        for g in [Some(faces.0), faces.1].into_iter().flatten() {
            let mut keep = None;
            let mut gone = None;
            for k in self.corners_of(g) {
                let ends = self.ends(k);
                let id = self.corner_ids[k][0];
                let across = self.mesh.opposite_edge(k);
                if ends.contains(&from.0) && ends.contains(&to.0) {
                    continue;
                } else if ends.contains(&to.0) {
                    keep = Some((id, across));
                } else {
                    gone = Some((id, k, across));
                }
            }
            match (keep, gone) {
                (Some(keep), Some(gone)) => sides.push((keep, gone)),
                _ => {
                    return Err(Error::Invariant {
                        structure: Self::NAME,
                        message: format!(
                            "a face of edge {}-{} is not a triangle on it",
                            from.0, to.0
                        ),
                    })
                }
            }
        }
        let p = self.position(to);
        self.mesh.collapse_edge(h, &Vector3::new(p.x, p.y, p.z));
        for ((keep, keep_across), (gone, gone_corner, gone_across)) in sides {
            if let Some(c) = gone_across {
                self.corner_ids[c][0] = keep;
            }
            if let Some(c) = keep_across.or(gone_across) {
                self.edges[keep as usize] = c;
            }
            self.edges[gone as usize] = gone_corner;
        }
        self.vertices[to.index()] = Some(kept);
        self.vertex_ids[kept] = to.0;
        self.vertices[from.index()] = None;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::PolygonSoup;

    /// A quad as two triangles, 0-2 the diagonal.
    fn quad() -> BabySharkCornerTable {
        let p = |x, y| DVec3::new(x, y, 0.0);
        let soup = PolygonSoup::from_polygons(
            vec![p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)],
            &[vec![0, 1, 2], vec![0, 2, 3]],
        );
        BabySharkCornerTable::from_soup(&soup).unwrap()
    }

    fn faces(m: &BabySharkCornerTable) -> Vec<Vec<u32>> {
        (0..m.num_faces())
            .map(FaceId::new)
            .filter(|&f| !m.is_deleted_face(f))
            .map(|f| {
                let mut c = Vec::new();
                m.face_vertices(f, |v| c.push(v.0));
                topolab_structures::testing::editing::canonical_face(&c)
            })
            .collect()
    }

    /// Boundary edge 0 → 1 has a face on that side only, so baby_shark keeps vertex 0's
    /// record; the adapter gives it vertex 1's id and position.
    #[test]
    fn a_boundary_collapse_keeps_the_lab_s_vertex_whichever_record_baby_shark_keeps() {
        for (from, to, left) in [(0, 1, vec![1, 2, 3]), (1, 0, vec![0, 2, 3])] {
            let mut m = quad();
            let at = m.position(VertexId(to));
            m.collapse_edge(VertexId(from), VertexId(to)).unwrap();
            assert!(m.is_deleted_vertex(VertexId(from)));
            assert!(!m.is_deleted_vertex(VertexId(to)));
            assert_eq!(m.position(VertexId(to)), at);
            assert_eq!(faces(&m), vec![left.clone()]);
            m.validate().unwrap();
            m.garbage_collection();
            assert_eq!((m.num_vertices(), m.num_faces(), m.num_edges()), (3, 1, 3));
            m.validate().unwrap();
            let soup = topolab_structures::algorithms::changing::to_soup(&m);
            topolab_structures::testing::conformance::compare(&m, &soup).unwrap();
        }
    }
}
