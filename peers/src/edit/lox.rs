//! [`MeshEdit`] for lox's two structures ([`LoxHalfEdge`], [`LoxDirectedEdge`]); the tables
//! of calls, costs and refusals are in their module docs.
//!
//! lox's `MeshMut` offers `add_vertex`, `add_face` (`add_triangle`), `remove_face`,
//! `remove_isolated_vertex`, `split_face`, `flip_edge` and `split_edge_with_faces`, but:
//! - `flip_edge` and `split_edge_with_faces` are bound by `Self: EdgeMesh + TriMesh`; the
//!   lab's `HalfEdgeMesh<PolyConfig>` is a `PolyMesh`, so they cannot be called on it, and
//!   `DirectedEdgeMesh` is not an `EdgeMesh` (its implementations are `unreachable!()`);
//! - `remove_face` and `remove_isolated_vertex` leave holes in lox's `StableVec`s, handles
//!   kept, and lox has no call that compacts them, so the lab's `garbage_collection` (which
//!   renumbers the survivors in order) could only be a rebuild: deletion is refused;
//! - lox has no collapse, vertex split or weld.

use super::{check_add_face, new_sides};
use crate::lox_directed_edge::LoxDirectedEdge;
use crate::lox_half_edge::LoxHalfEdge;
use glam::DVec3;
use lox::prelude::*;
use lox::{FaceHandle, VertexHandle};
use topolab_structures::{
    refuse, Cost, Deletion, EditOp, FaceId, MeshEdit, MeshTopology, Offers, Refusal, Result,
    VertexId,
};

/// The declared costs, read from lox's source (and the lab's checks before each call).
fn edit_cost(op: EditOp) -> Cost {
    match op {
        // `StableVec::push`.
        EditOp::AddVertex => Cost::Constant,
        // The lab's fan test around each corner; lox's `add_face_impl` circulates around
        // each corner to find existing half-edges and fan blades.
        EditOp::AddFace => Cost::Local,
        // One new vertex, k new edges, k - 1 new faces, linked around the face (half-edge);
        // the directed-edge mesh circulates around two corners to re-link boundary twins.
        EditOp::SplitFace => Cost::Local,
        // Nothing is ever deleted (deletion is refused), so there is nothing to collect;
        // welding meshes is the lab's rebuild from the welded face list, as everywhere.
        EditOp::GarbageCollection => Cost::Constant,
        // The adapter's positions, O(1) per vertex; k: the vertices selected.
        EditOp::SetPosition => Cost::Constant,
        EditOp::RotateSelection | EditOp::ScaleSelection => Cost::Local,
        _ => Cost::Linear,
    }
}

/// The adapters' shared bodies, over the fields both have (`mesh`, `positions`).
macro_rules! lox_edit_common {
    () => {
        const DELETION: Deletion = Deletion::Marked;

        fn edit_cost(op: EditOp) -> Cost {
            if op == EditOp::Smooth {
                return topolab_structures::core::edit::smooth_cost::<Self>();
            }
            edit_cost(op)
        }

        /// Vertices and faces added and faces split: lox's own calls; welds of edges, faces and
        /// meshes: the lab's rebuild from the welded face list.
        const OFFERS: Offers<Self> = Offers {
            add_vertex: Some(|m, p| {
                let v = m.mesh.add_vertex();
                m.positions.push(p);
                Ok(VertexId(v.idx()))
            }),
            add_face: Some(Self::add_face_checked),
            split_face: Some(Self::split_face_checked),
            rebuilds: true,
            ..Offers::NOTHING
        };

        /// lox stores no positions; the adapter's are moved.
        fn set_position(&mut self, v: VertexId, p: DVec3) -> Result<()> {
            match self.positions.get_mut(v.index()) {
                Some(q) => {
                    *q = p;
                    Ok(())
                }
                None => Err(refuse::<Self>(EditOp::SetPosition, Refusal::NoSuchElement)),
            }
        }

        fn is_deleted_vertex(&self, _: VertexId) -> bool {
            false
        }
        fn is_deleted_face(&self, _: FaceId) -> bool {
            false
        }
        /// Nothing is ever deleted (deletion is refused).
        fn garbage_collection(&mut self) {}

        fn reserve(&mut self, vertices: usize, _edges: usize, faces: usize) {
            self.mesh.reserve_for_vertices(vertices as u32);
            self.mesh.reserve_for_faces(faces as u32);
            self.positions.reserve(vertices);
        }
    };
}

impl MeshEdit for LoxHalfEdge {
    lox_edit_common!();
}

impl LoxHalfEdge {
    /// lox's `add_face`, after the lab's checks: lox panics on fewer than three corners and
    /// on an edge with a third face, and builds a vertex of several fans (a "multi-blade")
    /// where the lab refuses one.
    fn add_face_checked(&mut self, vertices: &[VertexId]) -> Result<FaceId> {
        check_add_face(self, vertices, false)?;
        let corners: Vec<VertexHandle> = vertices.iter().map(|v| VertexHandle::new(v.0)).collect();
        Ok(FaceId(self.mesh.add_face(&corners).idx()))
    }

    /// lox's `split_face`: the new vertex is appended, face `f` keeps one triangle of the
    /// fan and the others are appended.
    fn split_face_checked(&mut self, f: FaceId, p: DVec3) -> Result<VertexId> {
        if f.index() >= self.num_faces() {
            return Err(refuse::<Self>(EditOp::SplitFace, Refusal::NoSuchElement));
        }
        let v = self.mesh.split_face(FaceHandle::new(f.0));
        self.positions.push(p);
        Ok(VertexId(v.idx()))
    }
}

impl MeshEdit for LoxDirectedEdge {
    lox_edit_common!();

    /// An edge's id is its smaller half-edge (`3f + i`), and a face split gives one of the
    /// face's edges a half-edge of a new face, so edge ids are not stable.
    const STABLE_EDGE_IDS: bool = false;
}

impl LoxDirectedEdge {
    /// lox's `add_triangle`, after the lab's checks (lox's directed-edge mesh stores
    /// triangles only: a polygon is refused as [`Refusal::NotTriangles`]).
    fn add_face_checked(&mut self, vertices: &[VertexId]) -> Result<FaceId> {
        check_add_face(self, vertices, true)?;
        let added = new_sides(self, vertices);
        let corners = [vertices[0], vertices[1], vertices[2]].map(|v| VertexHandle::new(v.0));
        let f = self.mesh.add_triangle(corners);
        self.edges += added;
        Ok(FaceId(f.idx()))
    }

    /// lox's `split_face`: the new vertex is appended, face `f` keeps one triangle and two
    /// are appended; three edges join the new vertex to the corners.
    fn split_face_checked(&mut self, f: FaceId, p: DVec3) -> Result<VertexId> {
        if f.index() >= self.num_faces() {
            return Err(refuse::<Self>(EditOp::SplitFace, Refusal::NoSuchElement));
        }
        let v = self.mesh.split_face(FaceHandle::new(f.0));
        self.positions.push(p);
        self.edges += 3;
        Ok(VertexId(v.idx()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::EdgeId;
    use topolab_structures::PolygonSoup;

    fn quad_and_triangle() -> PolygonSoup {
        let p = |x, y| DVec3::new(x, y, 0.0);
        PolygonSoup::from_polygons(
            vec![
                p(0.0, 0.0),
                p(1.0, 0.0),
                p(1.0, 1.0),
                p(0.0, 1.0),
                p(2.0, 0.5),
            ],
            &[vec![0, 1, 2, 3], vec![1, 4, 2]],
        )
    }

    #[test]
    fn a_quad_splits_into_four_triangles_around_an_appended_vertex() {
        let mut m = LoxHalfEdge::from_soup(&quad_and_triangle()).unwrap();
        let v = m.split_face(FaceId(0), DVec3::new(0.5, 0.5, 0.0)).unwrap();
        assert_eq!(v, VertexId(5));
        assert_eq!((m.num_vertices(), m.num_faces(), m.num_edges()), (6, 5, 10));
        assert_eq!(m.position(v), DVec3::new(0.5, 0.5, 0.0));
        m.validate().unwrap();
    }

    #[test]
    fn unsupported_operations_are_refused_as_not_implemented() {
        let soup = topolab_structures::meshes::canonical()[0].soup.clone();
        let mut m = LoxDirectedEdge::from_soup(&soup).unwrap();
        let refused = |r: Result<()>| match r {
            Err(topolab_structures::Error::EditRefused { reason, .. }) => reason,
            other => panic!("{other:?}"),
        };
        assert_eq!(refused(m.flip_edge(EdgeId(0))), Refusal::NotImplemented);
        assert_eq!(refused(m.delete_face(FaceId(0))), Refusal::NotImplemented);
        assert_eq!(
            refused(m.collapse_edge(VertexId(0), VertexId(1))),
            Refusal::NotImplemented
        );
        assert!(!LoxDirectedEdge::supports(EditOp::FlipEdge));
        assert!(LoxDirectedEdge::supports(EditOp::SplitFace));
    }
}
