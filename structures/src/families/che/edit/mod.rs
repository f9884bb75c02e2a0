//! [`MeshEdit`] for the four CHE levels: what an edit costs in a structure built for static
//! meshes (the CHE thesis chapter stores only arrays indexed by vertex, half-edge and curve,
//! and builds them once).
//!
//! Triangle `t` owns the half-edges `3t, 3t+1, 3t+2`, so an edit rewrites the three corners
//! `V[3t..3t+3]` of each triangle it changes, appends new triangles at the end of `V[]`, and
//! repairs the containers of the level around them:
//!
//! - `O[]` (level 1 on) is patched locally: the half-edges of the rewritten and new
//!   triangles, with the outer half-edges that were opposite to them before, are paired again
//!   by their vertex pairs (a sort of O(k) entries); an outer half-edge left alone becomes a
//!   boundary half-edge. For a flip these are the 6 half-edges of the two triangles and the 4
//!   outer ones.
//! - `VH[]` (level 2 on) is repaired for every vertex of the rewritten triangles: a half-edge
//!   leaving it among them or their outer neighbours, turned back to the boundary half-edge
//!   leaving it if there is one (Algorithm 3's rule), `-1` if it has no triangle left.
//! - `EH` (level 2 on) is a sorted array of each edge's smaller half-edge (Algorithm 2's keys);
//!   the keys change with the half-edge ids an edit moves, so it is rebuilt by one scan of
//!   `O[]` ([`edge_map_by_scan`]): O(n) for every edit that changes an edge.
//! - `CH[]` and the curve labels `O[he] = -k` (level 3) are kept when an edit touches no
//!   boundary half-edge; otherwise the curves are relabelled from scratch (Algorithm 4, O(n)):
//!   a boundary change can join or split curves, which no local patch of `CH[]` tells.
//!
//! Deleting a triangle compacts the arrays at once ([`Deletion::Compacted`]): the last triangle
//! moves into its slot (its three `V[]` and `O[]` entries, the `O[]` of its up to three
//! neighbours, the `VH[]` and `CH[]` entries that named its half-edges; a face deletion and a
//! collapse), or, where a vertex is deleted with its star, the rebuild keeps the other
//! triangles in order and those after the star shift down; so face ids change and no face is
//! ever marked. Only vertices are marked: a deleted vertex keeps its slot in `G[]` (and `VH[v]
//! = -1`) until [`MeshEdit::garbage_collection`] renumbers `V[]`.
//!
//! Add face, delete face, delete vertex, split vertex and weld vertices are done by rebuilding
//! `O[]`, `VH[]`, `EH` and `CH[]` from an edited copy of `V[]` with the fast construction
//! (O(n)), which also refuses a result that is not an oriented manifold with one fan per
//! vertex: whether a face fits needs the boundary loops a half-edge structure links and the
//! CHE does not store. The containers are replaced only once the rebuild succeeded, so a
//! refused edit changes nothing.
//!
//! A weld of `b` into `a` ([`MeshEdit::weld_vertices`]) renames `b`'s corners `a` in that
//! copy and marks `b` deleted. It is refused, with the half-edges' reasons, when both ids
//! name one vertex ([`Refusal::SameVertex`]), when a triangle has both
//! ([`Refusal::BadFace`], found by the scan of `V[]` that finds `b`'s corners), and when the
//! rebuild finds an edge with more than two triangles or run twice the same way
//! ([`Refusal::NonManifoldEdge`]: a neighbour of both away from where their boundaries meet)
//! or a vertex in several fans ([`Refusal::NonManifoldVertex`]: an interior vertex welded
//! to a used one, or boundaries that meet at no edge). A `b` without triangles is only
//! marked.
//!
//! Levels 0 and 1 have no `VH[]`: the star of a vertex starts with a scan of `V[]` (Algorithms
//! 5 and 6), so every edit that must look around a vertex (the flip's check that the new edge
//! does not exist, the collapse's link condition) is O(n) there; level 0 also finds each
//! opposite by Algorithm 8's scan.
//!
//! ## Costs (k: the neighbourhood the edit touches; n: the mesh)
//!
//! | operation | L0 | L1 | L2 | L3 |
//! |---|---|---|---|---|
//! | add vertex | O(1) | O(1) | O(1) | O(1) |
//! | add face, delete face, delete vertex, split vertex, weld vertices | O(n) rebuild | O(n) rebuild | O(n) rebuild | O(n) rebuild |
//! | flip edge | O(n) scans | O(n): the star scan of Algorithm 6 | O(n): `EH` | O(n): `EH` (and Algorithm 4 on the boundary) |
//! | split edge, split face | O(n) scans | O(k) | O(n): `EH` | O(n): `EH` |
//! | collapse edge | O(n) scans | O(n): star scans | O(n): `EH` | O(n): `EH` |
//! | garbage collection | O(n) | O(n) | O(n) | O(n) |
//! | set position | O(1) | O(1) | O(1) | O(1) |
//! | select | O(n) | O(n) | O(n) | O(n) |
//! | rotate, scale a selection of k vertices | O(k) | O(k) | O(k) | O(k) |
//! | smooth (every vertex's R00 and boundary test) | O(n²) | O(n²) | O(n) | O(n) |
//! | insert edge, delete edge | not offered | not offered | not offered | not offered |
//!
//! Inserting an edge (a diagonal of a face) or deleting one (merging two faces) would leave a
//! face that is not a triangle, which the CHE cannot hold: both are refused as
//! [`Refusal::NotImplemented`](crate::Refusal::NotImplemented).

mod ops;

use super::build::{
    boundary_curves_algorithm_4, edge_map_by_scan, every_vertex_one_fan,
    opposites_and_vertex_half_edges,
};
use super::{CheL0, CheL1, CheL2, CheL3};
use crate::core::edit::{smooth_cost, Deletion, EditOp, MeshEdit, Offers, Refusal};
use crate::core::error::{Error, Result};
use crate::core::ids::{FaceId, HalfEdgeId, VertexId};
use crate::core::topology::{Cost, MeshTopology};
use glam::DVec3;

/// The containers of one level, borrowed for an edit; `None` where the level has none.
pub(super) struct Parts<'a> {
    /// The structure's name, for errors.
    name: &'static str,
    /// `G[]`.
    g: &'a mut Vec<DVec3>,
    /// `V[]`.
    v: &'a mut Vec<u32>,
    /// The deleted-vertex marks.
    deleted: &'a mut Vec<bool>,
    /// `O[]` (level 1 on).
    o: Option<&'a mut Vec<i32>>,
    /// `VH[]` (level 2 on).
    vh: Option<&'a mut Vec<i32>>,
    /// `EH` (level 2 on).
    eh: Option<&'a mut Vec<u32>>,
    /// `CH[]` (level 3).
    ch: Option<&'a mut Vec<u32>>,
}

fn nx(h: u32) -> u32 {
    super::next(HalfEdgeId(h)).0
}

fn pv(h: u32) -> u32 {
    super::prev(HalfEdgeId(h)).0
}

impl Parts<'_> {
    fn refuse(&self, op: EditOp, reason: Refusal) -> Error {
        Error::EditRefused {
            structure: self.name,
            op,
            reason,
        }
    }

    fn num_triangles(&self) -> usize {
        self.v.len() / 3
    }

    fn is_deleted(&self, x: u32) -> bool {
        self.deleted.get(x as usize).copied().unwrap_or(false)
    }

    fn live_vertex(&self, x: u32) -> bool {
        (x as usize) < self.g.len() && !self.is_deleted(x)
    }

    /// Room for `vertices` and `triangles` more, numbered by `i32` as the containers are.
    fn room(&self, vertices: usize, triangles: usize) -> Result<()> {
        for (what, count) in [
            ("vertices", self.g.len() + vertices),
            ("half-edges", self.v.len() + 3 * triangles),
        ] {
            if count > i32::MAX as usize {
                return Err(Error::TooLarge {
                    what,
                    count: count as u64,
                });
            }
        }
        Ok(())
    }

    /// Appends an unused vertex.
    fn push_vertex(&mut self, p: DVec3) -> u32 {
        self.g.push(p);
        if let Some(vh) = self.vh.as_deref_mut() {
            vh.push(-1);
        }
        (self.g.len() - 1) as u32
    }

    /// Appends triangle `(a, b, c)` with boundary opposites (the patch pairs them); returns it.
    fn push_triangle(&mut self, a: u32, b: u32, c: u32) -> u32 {
        self.v.extend([a, b, c]);
        if let Some(o) = self.o.as_deref_mut() {
            o.extend([-1, -1, -1]);
        }
        (self.v.len() / 3 - 1) as u32
    }

    fn mark_deleted(&mut self, x: u32) {
        if self.deleted.len() <= x as usize {
            self.deleted.resize(self.g.len(), false);
        }
        self.deleted[x as usize] = true;
    }

    /// Proves again, after an edit that rewrote `V[]`, `O[]` or `VH[]`, what the timed walk of
    /// levels 2 and 3 relies on to read them unchecked (`fan::ranges_hold`): one pass, within
    /// the O(n) that every such edit costs on those levels anyway (the `EH` rebuild). A
    /// failure is a bug in this module, never the input's doing, and would otherwise be
    /// undefined behaviour in the next query, so it stops the program.
    fn assert_ranges(&self) {
        if let (Some(o), Some(vh)) = (self.o.as_deref(), self.vh.as_deref()) {
            assert!(
                super::fan::ranges_hold(self.v, o, vh),
                "{}: an edit left an id out of range in V[], O[] or VH[] (a bug in the CHE's edit code)",
                self.name
            );
        }
    }

    /// Replaces every container but `G[]` by those built from `v` with the fast
    /// construction, refused (nothing changed) when `v` is not an oriented manifold with one
    /// fan per vertex; `num_vertices` counts a vertex the caller is about to add.
    fn rebuild(&mut self, op: EditOp, v: Vec<u32>, num_vertices: usize) -> Result<()> {
        // The rebuild reads the whole new `V[]`, at least once each: counted so.
        crate::core::reads::scanned("V", &v, 0);
        let (mut o, vh) = opposites_and_vertex_half_edges(&v, num_vertices)
            .ok_or_else(|| self.refuse(op, Refusal::NonManifoldEdge))?;
        if !every_vertex_one_fan(&o, &vh) {
            return Err(self.refuse(op, Refusal::NonManifoldVertex));
        }
        if let Some(eh) = self.eh.as_deref_mut() {
            *eh = edge_map_by_scan(&o);
        }
        if let Some(ch) = self.ch.as_deref_mut() {
            *ch = boundary_curves_algorithm_4(&mut o);
        }
        if let Some(x) = self.vh.as_deref_mut() {
            *x = vh;
        }
        if let Some(x) = self.o.as_deref_mut() {
            *x = o;
        }
        *self.v = v;
        Ok(())
    }
}

/// The cost table of the module docs.
fn edit_cost(level: u8, op: EditOp) -> Cost {
    match (level, op) {
        (_, EditOp::AddVertex | EditOp::SetPosition) => Cost::Constant,
        // k: the vertices selected, each moved by `set_position`.
        (_, EditOp::RotateSelection | EditOp::ScaleSelection) => Cost::Local,
        (1, EditOp::SplitEdge | EditOp::SplitFace) => Cost::Local,
        // The rebuilds (weld vertices among them), the `EH` rebuild and the scans of V[].
        _ => Cost::Linear,
    }
}

/// Implements [`MeshEdit`] for a level from its [`Parts`] (the operations are in `ops`).
macro_rules! che_edit {
    ($ty:ty, $level:literal, |$s:ident| $parts:expr) => {
        impl $ty {
            fn parts(&mut self) -> Parts<'_> {
                let $s = self;
                $parts
            }
            /// Runs an edit that rewrites topology, then proves the ranges again.
            fn edited<T>(&mut self, edit: impl FnOnce(&mut Parts<'_>) -> Result<T>) -> Result<T> {
                let mut parts = self.parts();
                let r = edit(&mut parts);
                parts.assert_ranges();
                r
            }
        }

        impl MeshEdit for $ty {
            const DELETION: Deletion = Deletion::Compacted;

            fn edit_cost(op: EditOp) -> Cost {
                if op == EditOp::Smooth {
                    return smooth_cost::<Self>();
                }
                edit_cost($level, op)
            }
            /// Everything but the insertion and deletion of an edge, which would leave a
            /// face that is not a triangle.
            const OFFERS: Offers<Self> = Offers {
                add_vertex: Some(|m, p| {
                    let mut parts = m.parts();
                    parts.room(1, 0)?;
                    Ok(VertexId(parts.push_vertex(p)))
                }),
                add_face: Some(|m, vertices| m.edited(|p| p.add_face(vertices)).map(FaceId)),
                delete_face: Some(|m, f| m.edited(|p| p.delete_face(f.0))),
                delete_vertex: Some(|m, v| m.edited(|p| p.delete_vertex(v.0))),
                flip_edge: Some(|m, e| m.edited(|p| p.flip(e.0))),
                split_edge: Some(|m, e, p| {
                    m.edited(|parts| parts.split_edge(e.0, p)).map(VertexId)
                }),
                split_face: Some(|m, f, p| {
                    m.edited(|parts| parts.split_face(f.0, p)).map(VertexId)
                }),
                collapse_edge: Some(|m, from, to| m.edited(|p| p.collapse(from.0, to.0))),
                split_vertex: Some(|m, v, p, left, right| {
                    m.edited(|parts| parts.split_vertex(v.0, p, left.0, right.0))
                        .map(VertexId)
                }),
                weld_vertices: Some(|m, a, b| m.edited(|p| p.weld(a.0, b.0))),
                insert_edge: None,
                delete_edge: None,
                rebuilds: true,
            };
            fn set_position(&mut self, v: VertexId, p: DVec3) -> Result<()> {
                self.parts().set_position(v.0, p)
            }
            fn is_deleted_vertex(&self, v: VertexId) -> bool {
                self.deleted_marks()
                    .get(v.index())
                    .copied()
                    .unwrap_or(false)
            }
            fn is_deleted_face(&self, _f: FaceId) -> bool {
                false // deleted triangles leave V[] at once (see the module docs)
            }
            fn garbage_collection(&mut self) {
                let _ = self.edited(|p| {
                    p.garbage_collection();
                    Ok(())
                });
            }
            fn reserve(&mut self, vertices: usize, _edges: usize, faces: usize) {
                self.parts().reserve(vertices, faces)
            }
        }
    };
}

impl CheL0 {
    fn deleted_marks(&self) -> &[bool] {
        &self.deleted
    }
}
impl CheL1 {
    fn deleted_marks(&self) -> &[bool] {
        &self.l0.deleted
    }
}
impl CheL2 {
    fn deleted_marks(&self) -> &[bool] {
        &self.l1.l0.deleted
    }
}
impl CheL3 {
    fn deleted_marks(&self) -> &[bool] {
        &self.l2.l1.l0.deleted
    }
}

che_edit!(CheL0, 0, |s| Parts {
    name: <CheL0 as MeshTopology>::NAME,
    g: &mut s.g,
    v: &mut s.v,
    deleted: &mut s.deleted,
    o: None,
    vh: None,
    eh: None,
    ch: None,
});
che_edit!(CheL1, 1, |s| Parts {
    name: <CheL1 as MeshTopology>::NAME,
    g: &mut s.l0.g,
    v: &mut s.l0.v,
    deleted: &mut s.l0.deleted,
    o: Some(&mut s.o),
    vh: None,
    eh: None,
    ch: None,
});
che_edit!(CheL2, 2, |s| Parts {
    name: <CheL2 as MeshTopology>::NAME,
    g: &mut s.l1.l0.g,
    v: &mut s.l1.l0.v,
    deleted: &mut s.l1.l0.deleted,
    o: Some(&mut s.l1.o),
    vh: Some(&mut s.vh),
    eh: Some(&mut s.eh),
    ch: None,
});
che_edit!(CheL3, 3, |s| Parts {
    name: <CheL3 as MeshTopology>::NAME,
    g: &mut s.l2.l1.l0.g,
    v: &mut s.l2.l1.l0.v,
    deleted: &mut s.l2.l1.l0.deleted,
    o: Some(&mut s.l2.l1.o),
    vh: Some(&mut s.l2.vh),
    eh: Some(&mut s.l2.eh),
    ch: Some(&mut s.ch),
});
