//! The lecture on polygon-mesh data structures' "weld vertices" (*Ecken verschweißen*) in
//! place on the half-edges: [`MeshEdit::weld_vertices`](crate::MeshEdit::weld_vertices)
//! merges vertex `b` into vertex `a`.
//!
//! When both vertices have faces, both must be boundary vertices whose fans meet along a
//! boundary edge: `a`'s boundary runs q → a → p, `b`'s runs s → b → r, and where `s == p`
//! the boundary edges a → p and p → b become one interior edge (likewise where `r == q`).
//! Each such pair of boundary edges is merged: the kept pair's boundary half-edge takes the
//! place of the freed pair's inner half-edge in that one's face, and the freed pair is marked
//! deleted until garbage collection, like every other deletion. Twins stay `h ^ 1`, so no
//! twin link is rewritten: the merge is the face, `next` and `prev` links of one half-edge.
//! With both ends merged, `a` (and the four-edge boundary loop around it) is closed.
//!
//! Refused, nothing changed, whatever would not be an oriented manifold with one fan per
//! vertex: a face holding both vertices ([`Refusal::BadFace`]), an interior vertex welded to
//! a used one or two boundaries that meet at no edge ([`Refusal::NonManifoldVertex`]), and a
//! neighbour of both other than at a merged end ([`Refusal::NonManifoldEdge`]: the edge to it
//! would be doubled, with three or four faces or twice the same way). One vertex twice is
//! [`Refusal::SameVertex`], as in the face-rewrite structures and the CHE.
//!
//! Cost: O(k) for the checks (the faces around `b`, the neighbours of both) and the renaming
//! of `b`'s half-edges, plus O(1) per merged boundary edge (O(k) where `prev` is a walk).

use super::super::HalfEdgeLinksMut;
use crate::core::edit::{EditOp, Refusal};
use crate::core::error::Result;
use crate::families::half_edge::{HalfEdge, NONE};

impl<L: HalfEdgeLinksMut> HalfEdge<L> {
    /// The boundary half-edge that ends at `v`, [`NONE`] if `v` is interior or unused: found
    /// by rotation (O(k)), not by `prev`, which on a storage without it walks the boundary.
    fn incoming_boundary(&self, v: u32) -> u32 {
        let start = self.out_of(v);
        if start == NONE {
            return NONE;
        }
        let mut h = start;
        loop {
            if self.is_bnd(h ^ 1) {
                return h ^ 1;
            }
            h = self.cw(h);
            if h == start {
                return NONE;
            }
        }
    }

    /// The boundary half-edge `keep` takes the place of `drop ^ 1` in its face, and the pair
    /// of `drop` (a boundary half-edge running against `keep`) is marked deleted.
    fn merge_boundary_edges(&mut self, keep: u32, drop: u32) {
        let inner = drop ^ 1;
        let (before, after, f) = (self.pv(inner), self.nx(inner), self.face_of(inner));
        self.links.set_face(keep, f);
        self.links.set_next(before, keep);
        self.links.set_next(keep, after);
        if self.face_he(f) == inner {
            self.links.set_face_half_edge(f, keep);
        }
        self.marks.mark_edge(drop >> 1);
    }

    /// See the module docs.
    pub(in crate::families::half_edge::edit) fn weld_checked(
        &mut self,
        a: u32,
        b: u32,
    ) -> Result<()> {
        let op = EditOp::WeldVertices;
        self.live_vertex(a, op)?;
        self.live_vertex(b, op)?;
        if a == b {
            return Err(Self::refuse(op, Refusal::SameVertex));
        }
        let (oa, ob) = (self.out_of(a), self.out_of(b));
        if ob == NONE {
            // Nothing refers to `b`.
            self.marks.mark_vertex(b);
            return Ok(());
        }
        // No face around `b` may hold `a` (an edge a-b always has a face).
        let mut h = ob;
        loop {
            if !self.is_bnd(h) {
                let mut g = self.nx(h);
                while g != h {
                    if self.start_v(g) == a {
                        return Err(Self::refuse(op, Refusal::BadFace));
                    }
                    g = self.nx(g);
                }
            }
            h = self.cw(h);
            if h == ob {
                break;
            }
        }
        // Decided before any write: the boundary half-edges around `a` (in, out) and `b`, and
        // which ends merge, at p (a → p against p → b) and at q (q → a against b → q).
        let mut bnd = [NONE; 4];
        let (mut at_p, mut at_q) = (false, false);
        let mut ends = [NONE, NONE];
        if oa != NONE {
            // Both used: both on the boundary (a boundary vertex's half-edge is a boundary
            // one), meeting at an edge.
            if !self.is_bnd(oa) || !self.is_bnd(ob) {
                return Err(Self::refuse(op, Refusal::NonManifoldVertex));
            }
            bnd = [self.incoming_boundary(a), oa, self.incoming_boundary(b), ob];
            let [a_in, a_out, b_in, b_out] = bnd;
            let (p, q) = (self.to_v(a_out), self.start_v(a_in));
            let (r, s) = (self.to_v(b_out), self.start_v(b_in));
            // Boundary edges that would run the same way (r == p: a → p and b → p) cannot
            // meet: p would have two boundary half-edges ending at it, two fans. So the
            // result is oriented whenever it is a manifold.
            (at_p, at_q) = (s == p, r == q);
            if !at_p && !at_q {
                return Err(Self::refuse(op, Refusal::NonManifoldVertex));
            }
            if at_p {
                ends[0] = p;
            }
            if at_q {
                ends[1] = q;
            }
            // Any other neighbour of both would get two edges to `a`.
            let mut around_a = Vec::with_capacity(8);
            let mut g = oa;
            loop {
                around_a.push(self.to_v(g));
                g = self.cw(g);
                if g == oa {
                    break;
                }
            }
            around_a.sort_unstable();
            let mut g = ob;
            loop {
                let y = self.to_v(g);
                if !ends.contains(&y) && around_a.binary_search(&y).is_ok() {
                    return Err(Self::refuse(op, Refusal::NonManifoldEdge));
                }
                g = self.cw(g);
                if g == ob {
                    break;
                }
            }
        }
        // Every half-edge leaving `b` leaves `a`.
        self.move_rotation(ob, a);
        let [a_in, a_out, b_in, b_out] = bnd;
        let out_a = match (at_p, at_q) {
            // `a` was unused: it takes `b`'s fan as it is.
            (false, false) => ob,
            (true, false) => {
                // ... q → a → p → b → r ... becomes ... q → a → r ...; p is closed.
                self.merge_boundary_edges(a_out, b_in);
                self.links.set_next(a_in, b_out);
                self.links.set_outgoing(ends[0], a_out ^ 1);
                b_out
            }
            (false, true) => {
                // ... s → b → q → a → p ... becomes ... s → a → p ...; q is closed.
                self.merge_boundary_edges(a_in, b_out);
                self.links.set_next(b_in, a_out);
                self.links.set_outgoing(ends[1], a_in);
                a_out
            }
            (true, true) => {
                // The boundary loop a → p → b → q → a closes, and `a` with it.
                self.merge_boundary_edges(a_out, b_in);
                self.merge_boundary_edges(a_in, b_out);
                self.links.set_outgoing(ends[0], a_out ^ 1);
                self.links.set_outgoing(ends[1], a_in);
                a_in ^ 1
            }
        };
        self.links.set_outgoing(a, out_a);
        self.links.set_outgoing(b, NONE);
        self.marks.mark_vertex(b);
        Ok(())
    }
}
