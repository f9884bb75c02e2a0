//! The lecture on polygon-mesh data structures' insertion and deletion of an edge
//! (*Kanten einfügen, löschen*) on the half-edges, the lab's procedure (the lecture names the
//! operations, not a method): [`MeshEdit::insert_edge`](crate::MeshEdit::insert_edge) splits a
//! face by a diagonal, a new pair of half-edges linked into its cycle and a new face for one
//! of the two cycles; [`MeshEdit::delete_edge`](crate::MeshEdit::delete_edge) unlinks an
//! interior edge's pair, joins the two cycles into the first face and marks the edge and the
//! second face deleted, like every other deletion.
//!
//! Cost: O(k), a walk around the face or faces (and, for an insertion, around one end to see
//! whether the diagonal is an edge already).

use super::super::HalfEdgeLinksMut;
use crate::core::edit::{EditOp, Refusal};
use crate::core::error::Result;
use crate::families::half_edge::{HalfEdge, NONE};

impl<L: HalfEdgeLinksMut> HalfEdge<L> {
    /// The half-edges of face `f`'s cycle, from its half-edge.
    fn cycle(&self, f: u32) -> Vec<u32> {
        let start = self.face_he(f);
        let mut out = vec![start];
        let mut h = self.nx(start);
        while h != start {
            out.push(h);
            h = self.nx(h);
        }
        out
    }

    /// [`MeshEdit::insert_edge`](crate::MeshEdit::insert_edge): returns the new face, the cycle
    /// from `b` to `a`; `f` keeps the one from `a` to `b`.
    pub(in crate::families::half_edge::edit) fn insert_edge_checked(
        &mut self,
        f: u32,
        a: u32,
        b: u32,
    ) -> Result<u32> {
        let op = EditOp::InsertEdge;
        self.live_face(f, op)?;
        self.live_vertex(a, op)?;
        self.live_vertex(b, op)?;
        let cycle = self.cycle(f);
        let k = cycle.len();
        let at = |v: u32| cycle.iter().position(|&h| self.start_v(h) == v);
        let (Some(i), Some(j)) = (at(a), at(b)) else {
            return Err(Self::refuse(op, Refusal::NotDiagonal));
        };
        if i == j || (i + 1) % k == j || (j + 1) % k == i {
            return Err(Self::refuse(op, Refusal::NotDiagonal));
        }
        if self.find_half_edge(a, b) != NONE {
            return Err(Self::refuse(op, Refusal::EdgeExists));
        }
        self.room(0, 1, 1)?;
        // ha leaves a, hb leaves b; pa ends at a, pb ends at b (all in f).
        let (ha, hb) = (cycle[i], cycle[j]);
        let (pa, pb) = (cycle[(i + k - 1) % k], cycle[(j + k - 1) % k]);
        let d = self.links.push_edge(a, b);
        let g = self.links.push_face(d ^ 1);
        let l = &mut self.links;
        // f: a → b (d), then b's side round to a.
        l.set_next(pa, d);
        l.set_next(d, hb);
        l.set_face(d, f);
        l.set_face_half_edge(f, d);
        // g: b → a (d ^ 1), then a's side round to b.
        l.set_next(pb, d ^ 1);
        l.set_next(d ^ 1, ha);
        l.set_face(d ^ 1, g);
        let mut h = ha;
        while h != d ^ 1 {
            self.links.set_face(h, g);
            h = self.nx(h);
        }
        Ok(g)
    }

    /// [`MeshEdit::delete_edge`](crate::MeshEdit::delete_edge): the face of the edge's first
    /// half-edge keeps the merged cycle.
    pub(in crate::families::half_edge::edit) fn delete_edge_checked(
        &mut self,
        e: u32,
    ) -> Result<()> {
        let op = EditOp::DeleteEdge;
        self.live_edge(e, op)?;
        let (h, o) = (2 * e, 2 * e + 1);
        if self.is_bnd(h) || self.is_bnd(o) {
            return Err(Self::refuse(op, Refusal::BoundaryEdge));
        }
        let (f1, f2) = (self.face_of(h), self.face_of(o));
        if f1 == f2 {
            return Err(Self::refuse(op, Refusal::BadFace));
        }
        // The merged polygon's corners: each face's corners but the edge's ends once.
        let mut corners: Vec<u32> = self.cycle(f1).iter().map(|&x| self.start_v(x)).collect();
        corners.extend(
            self.cycle(f2)
                .iter()
                .map(|&x| self.start_v(x))
                .filter(|&v| v != self.start_v(h) && v != self.start_v(o)),
        );
        if (1..corners.len()).any(|t| corners[..t].contains(&corners[t])) {
            return Err(Self::refuse(op, Refusal::BadFace));
        }
        let (a, b) = (self.start_v(h), self.start_v(o));
        let (ph, nh, po, no) = (self.pv(h), self.nx(h), self.pv(o), self.nx(o));
        let mut x = no;
        while x != o {
            self.links.set_face(x, f1);
            x = self.nx(x);
        }
        let l = &mut self.links;
        l.set_next(ph, no);
        l.set_next(po, nh);
        l.set_face_half_edge(f1, nh);
        if self.out_of(a) == h {
            self.links.set_outgoing(a, no);
        }
        if self.out_of(b) == o {
            self.links.set_outgoing(b, nh);
        }
        self.marks.mark_edge(e);
        self.marks.mark_face(f2);
        Ok(())
    }
}
