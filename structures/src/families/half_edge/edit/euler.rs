//! The Euler operations over [`HalfEdgeLinksMut`], by half-edge ids (twin `h ^ 1`). Each
//! public operation checks everything first and refuses with a typed error before its first
//! write, so a refused edit changes nothing.

use super::HalfEdgeLinksMut;
use crate::core::edit::{EditOp, Refusal};
use crate::core::error::{Error, Result};
use crate::core::ids::{FaceId, VertexId};
use crate::core::topology::MeshTopology;
use crate::families::half_edge::{HalfEdge, NONE};
use glam::DVec3;

mod edges;
mod weld;

impl<L: HalfEdgeLinksMut> HalfEdge<L> {
    // --- reads by id -------------------------------------------------------------------------

    #[inline(always)]
    pub(super) fn nx(&self, h: u32) -> u32 {
        let l = &self.links;
        l.id(l.next(l.half_edge(h)))
    }
    #[inline(always)]
    fn pv(&self, h: u32) -> u32 {
        let l = &self.links;
        l.id(l.prev(l.half_edge(h)))
    }
    /// The vertex `h` starts at.
    #[inline(always)]
    pub(super) fn start_v(&self, h: u32) -> u32 {
        let l = &self.links;
        l.vertex(l.half_edge(h)).0
    }
    /// The vertex `h` points to.
    #[inline(always)]
    fn to_v(&self, h: u32) -> u32 {
        self.start_v(h ^ 1)
    }
    /// `h`'s face, [`NONE`] on the boundary.
    #[inline(always)]
    pub(super) fn face_of(&self, h: u32) -> u32 {
        let l = &self.links;
        l.face(l.half_edge(h)).map_or(NONE, |f| f.0)
    }
    #[inline(always)]
    fn is_bnd(&self, h: u32) -> bool {
        self.face_of(h) == NONE
    }
    /// `v`'s half-edge, [`NONE`] for an unused vertex.
    #[inline(always)]
    pub(super) fn out_of(&self, v: u32) -> u32 {
        let l = &self.links;
        l.outgoing(VertexId(v)).map_or(NONE, |h| l.id(h))
    }
    #[inline(always)]
    fn face_he(&self, f: u32) -> u32 {
        let l = &self.links;
        l.id(l.face_half_edge(FaceId(f)))
    }
    /// The next half-edge leaving the same vertex (the rotation of the queries).
    #[inline(always)]
    fn cw(&self, h: u32) -> u32 {
        self.nx(h ^ 1)
    }
    /// The half-edge from `a` to `b`, [`NONE`] if they are not neighbours.
    #[inline]
    fn find_half_edge(&self, a: u32, b: u32) -> u32 {
        let start = self.out_of(a);
        if start == NONE {
            return NONE;
        }
        let mut h = start;
        loop {
            if self.to_v(h) == b {
                return h;
            }
            h = self.cw(h);
            if h == start {
                return NONE;
            }
        }
    }
    /// Does `v` have exactly `n` edges? Stops after `n + 1` of them: the collapse's
    /// tetrahedron test asks whether a vertex has 3, and the vertices it asks about usually
    /// have twice as many or more.
    fn has_valence(&self, v: u32, n: usize) -> bool {
        let start = self.out_of(v);
        if start == NONE {
            return n == 0;
        }
        let (mut h, mut k) = (start, 0);
        loop {
            k += 1;
            h = self.cw(h);
            if h == start || k > n {
                return h == start && k == n;
            }
        }
    }
    /// Does `v` have a boundary half-edge? The queries' boundary test: one read, because a
    /// vertex's half-edge is a boundary one when it has any (the invariant
    /// [`Self::adjust_outgoing`] keeps).
    #[inline(always)]
    fn is_boundary_vertex_id(&self, v: u32) -> bool {
        self.is_boundary_vertex(VertexId(v))
    }
    /// Is the face of `h` a triangle?
    #[inline(always)]
    fn is_triangle(&self, h: u32) -> bool {
        self.nx(self.nx(self.nx(h))) == h
    }
    /// Points `v` at a boundary half-edge if it has one (pmp's `adjust_outgoing_halfedge`).
    fn adjust_outgoing(&mut self, v: u32) {
        let start = self.out_of(v);
        if start == NONE {
            return;
        }
        let mut h = start;
        loop {
            if self.is_bnd(h) {
                self.links.set_outgoing(v, h);
                return;
            }
            h = self.cw(h);
            if h == start {
                return;
            }
        }
    }

    // --- checks ------------------------------------------------------------------------------

    fn refuse(op: EditOp, reason: Refusal) -> Error {
        crate::core::offers::refuse::<Self>(op, reason)
    }
    pub(super) fn live_vertex(&self, v: u32, op: EditOp) -> Result<()> {
        if (v as usize) < self.links.num_vertices() && !self.marks.vertex(v) {
            Ok(())
        } else {
            Err(Self::refuse(op, Refusal::NoSuchElement))
        }
    }
    fn live_face(&self, f: u32, op: EditOp) -> Result<()> {
        if (f as usize) < self.links.num_faces() && !self.marks.face(f) {
            Ok(())
        } else {
            Err(Self::refuse(op, Refusal::NoSuchElement))
        }
    }
    fn live_edge(&self, e: u32, op: EditOp) -> Result<()> {
        if (e as usize) < self.links.num_half_edges() / 2 && !self.marks.edge(e) {
            Ok(())
        } else {
            Err(Self::refuse(op, Refusal::NoSuchElement))
        }
    }
    /// Refuses growth past `u32` ids (half-edge ids stay below 2^31: walks mark the top bit).
    pub(super) fn room(&self, vertices: u64, edges: u64, faces: u64) -> Result<()> {
        let l = &self.links;
        for (what, now, more, max) in [
            (
                "vertices",
                l.num_vertices() as u64,
                vertices,
                u32::MAX as u64 - 1,
            ),
            (
                "half-edges",
                l.num_half_edges() as u64,
                2 * edges,
                (1 << 31) - 1,
            ),
            ("faces", l.num_faces() as u64, faces, u32::MAX as u64 - 1),
        ] {
            if now + more > max {
                return Err(Error::TooLarge {
                    what,
                    count: now + more,
                });
            }
        }
        Ok(())
    }
    /// The fans `w` keeps when the faces `removed` go: runs of remaining faces around it.
    fn fans_without(&self, w: u32, removed: &[u32]) -> usize {
        let start = self.out_of(w);
        if start == NONE {
            return 0;
        }
        let present = |h: u32| {
            let f = self.face_of(h);
            f != NONE && !removed.contains(&f)
        };
        let (mut h, mut runs, mut all) = (start, 0, true);
        loop {
            let (here, before) = (present(h), present(self.nx(h ^ 1)));
            // Around `w`, the face of `cw(h)` follows the face of `h`; a run starts where a
            // present face follows an absent one.
            all &= here;
            runs += (before && !here) as usize;
            h = self.cw(h);
            if h == start {
                break;
            }
        }
        if all {
            1
        } else {
            runs
        }
    }

    // --- add and delete ------------------------------------------------------------------------

    /// pmp's `add_face`, refusing what would not be an oriented manifold with one fan per
    /// vertex (where pmp relinks patches into a non-manifold vertex).
    pub(super) fn add_face_checked(&mut self, vs: &[VertexId]) -> Result<u32> {
        let op = EditOp::AddFace;
        let n = vs.len();
        if n < 3 || (1..n).any(|i| vs[..i].contains(&vs[i])) {
            return Err(Self::refuse(op, Refusal::BadFace));
        }
        for v in vs {
            self.live_vertex(v.0, op)?;
        }
        self.room(0, n as u64, 1)?;
        let mut hs = vec![NONE; n];
        let mut is_new = vec![false; n];
        for i in 0..n {
            let (a, b) = (vs[i].0, vs[(i + 1) % n].0);
            let oa = self.out_of(a);
            if oa != NONE && !self.is_bnd(oa) {
                return Err(Self::refuse(op, Refusal::NonManifoldVertex));
            }
            hs[i] = self.find_half_edge(a, b);
            is_new[i] = hs[i] == NONE;
            if !is_new[i] && !self.is_bnd(hs[i]) {
                return Err(Self::refuse(op, Refusal::NonManifoldEdge));
            }
        }
        for i in 0..n {
            let ii = (i + 1) % n;
            let v = vs[ii].0;
            // Two old sides meeting at v must be consecutive on v's one boundary gap; two new
            // sides at a used vertex would give it a second fan.
            let relink = !is_new[i] && !is_new[ii] && self.nx(hs[i]) != hs[ii];
            let second_fan = is_new[i] && is_new[ii] && self.out_of(v) != NONE;
            if relink || second_fan {
                return Err(Self::refuse(op, Refusal::NonManifoldVertex));
            }
        }
        for i in 0..n {
            if is_new[i] {
                hs[i] = self.links.push_edge(vs[i].0, vs[(i + 1) % n].0);
            }
        }
        let f = self.links.push_face(hs[n - 1]);
        let mut links: Vec<(u32, u32)> = Vec::with_capacity(3 * n);
        let mut adjust = vec![false; n];
        for i in 0..n {
            let ii = (i + 1) % n;
            let v = vs[ii].0;
            let (inner_prev, inner_next) = (hs[i], hs[ii]);
            if is_new[i] || is_new[ii] {
                let (outer_prev, outer_next) = (inner_next ^ 1, inner_prev ^ 1);
                match (is_new[i], is_new[ii]) {
                    (true, false) => {
                        links.push((self.pv(inner_next), outer_next));
                        self.links.set_outgoing(v, outer_next);
                    }
                    (false, true) => {
                        let boundary_next = self.nx(inner_prev);
                        links.push((outer_prev, boundary_next));
                        self.links.set_outgoing(v, boundary_next);
                    }
                    _ => {
                        // v was unused (checked above).
                        self.links.set_outgoing(v, outer_next);
                        links.push((outer_prev, outer_next));
                    }
                }
                links.push((inner_prev, inner_next));
            } else {
                adjust[ii] = self.out_of(v) == inner_next;
            }
            self.links.set_face(hs[i], f);
        }
        for (a, b) in links {
            self.links.set_next(a, b);
        }
        for i in 0..n {
            if adjust[i] {
                self.adjust_outgoing(vs[i].0);
            }
        }
        Ok(f)
    }

    pub(super) fn delete_face_checked(&mut self, f: u32) -> Result<()> {
        let op = EditOp::DeleteFace;
        self.live_face(f, op)?;
        // A boundary vertex keeps one fan only if the face is at an end of it.
        let start = self.face_he(f);
        let mut h = start;
        loop {
            let v = self.start_v(h);
            let on_boundary = self.is_bnd(self.out_of(v));
            if on_boundary && !self.is_bnd(self.pv(h) ^ 1) && !self.is_bnd(h ^ 1) {
                return Err(Self::refuse(op, Refusal::NonManifoldVertex));
            }
            h = self.nx(h);
            if h == start {
                break;
            }
        }
        self.delete_face_unchecked(f);
        Ok(())
    }

    /// pmp's `delete_face`, except that a vertex left without faces stays (unused).
    fn delete_face_unchecked(&mut self, f: u32) {
        self.marks.mark_face(f);
        let mut edges: Vec<u32> = Vec::with_capacity(4);
        let mut vertices: Vec<u32> = Vec::with_capacity(4);
        let start = self.face_he(f);
        let mut h = start;
        loop {
            self.links.set_face(h, NONE);
            if self.is_bnd(h ^ 1) {
                edges.push(h >> 1);
            }
            vertices.push(self.to_v(h));
            h = self.nx(h);
            if h == start {
                break;
            }
        }
        for e in edges {
            let (h0, h1) = (2 * e, 2 * e + 1);
            let (v0, next0, prev0) = (self.to_v(h0), self.nx(h0), self.pv(h0));
            let (v1, next1, prev1) = (self.to_v(h1), self.nx(h1), self.pv(h1));
            self.links.set_next(prev0, next1);
            self.links.set_next(prev1, next0);
            self.marks.mark_edge(e);
            if self.out_of(v0) == h1 {
                self.links
                    .set_outgoing(v0, if next0 == h1 { NONE } else { next0 });
            }
            if self.out_of(v1) == h0 {
                self.links
                    .set_outgoing(v1, if next1 == h0 { NONE } else { next1 });
            }
        }
        for v in vertices {
            self.adjust_outgoing(v);
        }
    }

    pub(super) fn delete_vertex_checked(&mut self, v: u32) -> Result<()> {
        let op = EditOp::DeleteVertex;
        self.live_vertex(v, op)?;
        let mut faces = Vec::new();
        let mut neighbours = Vec::new();
        let start = self.out_of(v);
        if start != NONE {
            let mut h = start;
            loop {
                if !self.is_bnd(h) {
                    faces.push(self.face_of(h));
                    // Every corner of the face (a polygon's too) loses it.
                    let mut g = self.nx(h);
                    while g != h {
                        neighbours.push(self.start_v(g));
                        g = self.nx(g);
                    }
                }
                h = self.cw(h);
                if h == start {
                    break;
                }
            }
        }
        if neighbours.iter().any(|&w| self.fans_without(w, &faces) > 1) {
            return Err(Self::refuse(op, Refusal::NonManifoldVertex));
        }
        for f in faces {
            self.delete_face_unchecked(f);
        }
        debug_assert_eq!(self.out_of(v), NONE, "v has no edges left");
        self.links.set_outgoing(v, NONE);
        self.marks.mark_vertex(v);
        Ok(())
    }

    // --- flip and splits -----------------------------------------------------------------------

    /// pmp's `is_flip_ok` and `flip`.
    pub(super) fn flip_checked(&mut self, e: u32) -> Result<()> {
        let op = EditOp::FlipEdge;
        self.live_edge(e, op)?;
        let (a0, b0) = (2 * e, 2 * e + 1);
        if self.is_bnd(a0) || self.is_bnd(b0) {
            return Err(Self::refuse(op, Refusal::BoundaryEdge));
        }
        if !self.is_triangle(a0) || !self.is_triangle(b0) {
            return Err(Self::refuse(op, Refusal::NotTriangles));
        }
        let (a1, b1) = (self.nx(a0), self.nx(b0));
        let (a2, b2) = (self.nx(a1), self.nx(b1));
        let (x, y) = (self.to_v(a1), self.to_v(b1));
        if x == y || self.find_half_edge(x, y) != NONE {
            return Err(Self::refuse(op, Refusal::EdgeExists));
        }
        let (u, w) = (self.start_v(a0), self.start_v(b0));
        let (fa, fb) = (self.face_of(a0), self.face_of(b0));
        let l = &mut self.links;
        l.set_vertex(a0, y);
        l.set_vertex(b0, x);
        l.set_next(a0, a2);
        l.set_next(a2, b1);
        l.set_next(b1, a0);
        l.set_next(b0, b2);
        l.set_next(b2, a1);
        l.set_next(a1, b0);
        l.set_face(a1, fb);
        l.set_face(b1, fa);
        l.set_face_half_edge(fa, a0);
        l.set_face_half_edge(fb, b0);
        if self.out_of(w) == b0 {
            self.links.set_outgoing(w, a1);
        }
        if self.out_of(u) == a0 {
            self.links.set_outgoing(u, b1);
        }
        Ok(())
    }

    /// pmp's `split(Edge, Vertex)` for triangles: edge a-b becomes a-v and v-b, and each
    /// triangle (a, b, c) beside it becomes (a, v, c) and (v, b, c).
    pub(super) fn split_edge_checked(&mut self, e: u32, p: DVec3) -> Result<u32> {
        let op = EditOp::SplitEdge;
        self.live_edge(e, op)?;
        let (h0, o0) = (2 * e, 2 * e + 1);
        if (!self.is_bnd(h0) && !self.is_triangle(h0))
            || (!self.is_bnd(o0) && !self.is_triangle(o0))
        {
            return Err(Self::refuse(op, Refusal::NotTriangles));
        }
        // Two triangles (a, b, c) and (b, a, c) would both give an edge v-c.
        if !self.is_bnd(h0) && !self.is_bnd(o0) && self.to_v(self.nx(h0)) == self.to_v(self.nx(o0))
        {
            return Err(Self::refuse(op, Refusal::EdgeExists));
        }
        self.room(1, 3, 2)?;
        let a = self.start_v(h0);
        let v = self.links.push_vertex(p);
        let e1 = self.links.push_edge(v, a);
        let t1 = e1 ^ 1;
        // The boundary neighbours are read before any link changes.
        let before_h0 = if self.is_bnd(h0) { self.pv(h0) } else { NONE };
        let after_o0 = if self.is_bnd(o0) { self.nx(o0) } else { NONE };
        self.links.set_vertex(h0, v);
        if !self.is_bnd(h0) {
            let f0 = self.face_of(h0);
            let h1 = self.nx(h0);
            let h2 = self.nx(h1);
            let c = self.start_v(h2);
            let e0 = self.links.push_edge(v, c);
            let t0 = e0 ^ 1;
            let f1 = self.links.push_face(h2);
            let l = &mut self.links;
            l.set_next(h1, t0);
            l.set_next(t0, h0);
            l.set_face(t0, f0);
            l.set_face_half_edge(f0, h0);
            l.set_next(t1, e0);
            l.set_next(e0, h2);
            l.set_next(h2, t1);
            l.set_face(t1, f1);
            l.set_face(e0, f1);
            l.set_face(h2, f1);
        } else {
            self.links.set_next(before_h0, t1);
            self.links.set_next(t1, h0);
        }
        if !self.is_bnd(o0) {
            let f3 = self.face_of(o0);
            let o1 = self.nx(o0);
            let o2 = self.nx(o1);
            let d = self.start_v(o2);
            let e2 = self.links.push_edge(v, d);
            let t2 = e2 ^ 1;
            let f2 = self.links.push_face(o1);
            let l = &mut self.links;
            l.set_next(o0, e2);
            l.set_next(e2, o2);
            l.set_face(e2, f3);
            l.set_face_half_edge(f3, o0);
            l.set_next(e1, o1);
            l.set_next(o1, t2);
            l.set_next(t2, e1);
            l.set_face(e1, f2);
            l.set_face(o1, f2);
            l.set_face(t2, f2);
        } else {
            self.links.set_next(e1, after_o0);
            self.links.set_next(o0, e1);
        }
        let out = if self.is_bnd(o0) { e1 } else { h0 };
        self.links.set_outgoing(v, out);
        if self.out_of(a) == h0 {
            self.links.set_outgoing(a, t1);
        }
        Ok(v)
    }

    /// pmp's `split(Face, Vertex)`: a fan of triangles around a new vertex; `f` keeps the
    /// triangle on its half-edge, the others are appended in the face's order.
    pub(super) fn split_face_checked(&mut self, f: u32, p: DVec3) -> Result<u32> {
        let op = EditOp::SplitFace;
        self.live_face(f, op)?;
        let hend = self.face_he(f);
        let mut k = 1u64;
        let mut h = self.nx(hend);
        while h != hend {
            k += 1;
            h = self.nx(h);
        }
        self.room(1, k, k - 1)?;
        let v = self.links.push_vertex(p);
        Ok(self.split_face_at(f, v))
    }

    /// The split of face `f` at the unused vertex `v` (checked by the caller).
    #[inline]
    fn split_face_at(&mut self, f: u32, v: u32) -> u32 {
        let hend = self.face_he(f);
        let mut h = self.nx(hend);
        let first = self.links.push_edge(self.to_v(hend), v);
        self.links.set_next(hend, first);
        self.links.set_face(first, f);
        let mut hold = first ^ 1;
        while h != hend {
            let hnext = self.nx(h);
            let fnew = self.links.push_face(h);
            let hnew = self.links.push_edge(self.to_v(h), v);
            let l = &mut self.links;
            l.set_next(hnew, hold);
            l.set_next(hold, h);
            l.set_next(h, hnew);
            l.set_face(hnew, fnew);
            l.set_face(hold, fnew);
            l.set_face(h, fnew);
            hold = hnew ^ 1;
            h = hnext;
        }
        let l = &mut self.links;
        l.set_next(hold, hend);
        l.set_next(first, hold);
        l.set_face(hold, f);
        l.set_outgoing(v, hold);
        v
    }

    // --- collapse and its inverse ----------------------------------------------------------

    /// pmp's `is_collapse_ok` for the half-edge `h` from v0 to v1 (both sides triangles), with
    /// OpenMesh's tetrahedron test (its Decimater's `is_collapse_legal`) after pmp's `vl == vr`
    /// rule: `None` when the collapse may be done, else the refusal,
    /// [`Refusal::TetrahedronTest`] for the tetrahedron test and [`Refusal::LinkCondition`]
    /// for every other test.
    fn collapse_refusal(&self, h: u32) -> Option<Refusal> {
        let o = h ^ 1;
        let (v0, v1) = (self.start_v(h), self.to_v(h));
        let (mut vl, mut vr) = (NONE, NONE);
        if !self.is_bnd(h) {
            let h1 = self.nx(h);
            let h2 = self.nx(h1);
            vl = self.to_v(h1);
            // The edges v1-vl and vl-v0 must not both be boundary edges.
            if self.is_bnd(h1 ^ 1) && self.is_bnd(h2 ^ 1) {
                return Some(Refusal::LinkCondition);
            }
        }
        if !self.is_bnd(o) {
            let o1 = self.nx(o);
            let o2 = self.nx(o1);
            vr = self.to_v(o1);
            if self.is_bnd(o1 ^ 1) && self.is_bnd(o2 ^ 1) {
                return Some(Refusal::LinkCondition);
            }
        }
        if vl == vr {
            return Some(Refusal::LinkCondition);
        }
        // OpenMesh's tetrahedron test (its Decimater's, not `is_collapse_ok`'s): collapsing an
        // edge of a closed tetrahedron would leave two triangles on the same three vertices,
        // which the link condition in its vertex-ring form below passes and the full link
        // condition fails; the test refuses every collapse whose vl and vr are neighbours of
        // valence 3 (on the open tetrahedron too, where the result would be one triangle).
        if vl != NONE
            && vr != NONE
            && self.find_half_edge(vl, vr) != NONE
            && self.has_valence(vl, 3)
            && self.has_valence(vr, 3)
        {
            return Some(Refusal::TetrahedronTest);
        }
        // An edge between two boundary vertices must be a boundary edge.
        if self.is_boundary_vertex_id(v0)
            && self.is_boundary_vertex_id(v1)
            && !self.is_bnd(h)
            && !self.is_bnd(o)
        {
            return Some(Refusal::LinkCondition);
        }
        // The link condition: the one-rings of v0 and v1 share only vl and vr.
        let start = self.out_of(v0);
        let mut g = start;
        loop {
            let vv = self.to_v(g);
            if vv != v1 && vv != vl && vv != vr && self.find_half_edge(vv, v1) != NONE {
                return Some(Refusal::LinkCondition);
            }
            g = self.cw(g);
            if g == start {
                return None;
            }
        }
    }

    /// The tests of [`Self::collapse_checked`], nothing changed: the half-edge from `from`
    /// to `to` when the collapse may be done, the refusal otherwise.
    pub(super) fn collapse_check(&self, from: u32, to: u32) -> Result<u32> {
        let op = EditOp::CollapseEdge;
        self.live_vertex(from, op)?;
        self.live_vertex(to, op)?;
        let h = self.find_half_edge(from, to);
        if h == NONE {
            return Err(Self::refuse(op, Refusal::NotNeighbours));
        }
        // Every face around `from` must be a triangle: a larger face holding both ends would
        // repeat a vertex.
        let mut g = h;
        loop {
            if !self.is_bnd(g) && !self.is_triangle(g) {
                return Err(Self::refuse(op, Refusal::NotTriangles));
            }
            g = self.cw(g);
            if g == h {
                break;
            }
        }
        if let Some(reason) = self.collapse_refusal(h) {
            return Err(Self::refuse(op, reason));
        }
        Ok(h)
    }

    pub(super) fn collapse_checked(&mut self, from: u32, to: u32) -> Result<()> {
        let h = self.collapse_check(from, to)?;
        self.collapse_unchecked(h);
        Ok(())
    }

    /// pmp's `collapse`: the start vertex of `h` goes, its end stays.
    #[inline]
    pub(crate) fn collapse_unchecked(&mut self, h: u32) {
        let h1 = self.pv(h);
        let o1 = self.nx(h ^ 1);
        self.remove_edge(h);
        if self.nx(self.nx(h1)) == h1 {
            self.remove_loop(h1);
        }
        if self.nx(self.nx(o1)) == o1 {
            self.remove_loop(o1);
        }
    }

    /// Every half-edge of the rotation through `start` now leaves `v` (the rotation is read
    /// through `next`, which this does not change).
    fn move_rotation(&mut self, start: u32, v: u32) {
        let mut g = start;
        loop {
            self.links.set_vertex(g, v);
            g = self.cw(g);
            if g == start {
                break;
            }
        }
    }

    /// pmp's `remove_edge_helper`. Where neither end was on the boundary, `vh` has no
    /// boundary half-edge afterwards either (it keeps its own half-edges and takes `vo`'s), so
    /// pmp's `adjust_outgoing_halfedge`, a walk around `vh` that would find none, is skipped:
    /// the result is the same, and on a closed mesh callgrind counted a large share of the
    /// collapse test's instructions in the walk (see `remove_loop`).
    fn remove_edge(&mut self, h: u32) {
        let (hn, hp) = (self.nx(h), self.pv(h));
        let o = h ^ 1;
        let (on, op) = (self.nx(o), self.pv(o));
        let (fh, fo) = (self.face_of(h), self.face_of(o));
        let (vh, vo) = (self.to_v(h), self.start_v(h));
        let boundary = self.is_boundary_vertex_id(vh) || self.is_boundary_vertex_id(vo);
        self.move_rotation(self.out_of(vo), vh);
        self.links.set_next(hp, hn);
        self.links.set_next(op, on);
        if fh != NONE {
            self.links.set_face_half_edge(fh, hn);
        }
        if fo != NONE {
            self.links.set_face_half_edge(fo, on);
        }
        if self.out_of(vh) == o {
            self.links.set_outgoing(vh, hn);
        }
        if boundary {
            self.adjust_outgoing(vh);
        }
        self.links.set_outgoing(vo, NONE);
        self.marks.mark_vertex(vo);
        self.marks.mark_edge(h >> 1);
    }

    /// pmp's `remove_loop_helper`: a face of two half-edges `h0`, `next(h0)` goes, and
    /// `next(h0)` takes the place of `h0`'s twin. A vertex of the loop that had no boundary
    /// half-edge has none afterwards (its half-edges lose one and change no face to none:
    /// `h1` takes `o0`'s face, which is a face when `v0` is interior), so its
    /// `adjust_outgoing_halfedge` walk is skipped, with the same result.
    fn remove_loop(&mut self, h0: u32) {
        let h1 = self.nx(h0);
        let (o0, o1) = (h0 ^ 1, h1 ^ 1);
        let (v0, v1) = (self.to_v(h0), self.to_v(h1));
        let (b0, b1) = (
            self.is_boundary_vertex_id(v0),
            self.is_boundary_vertex_id(v1),
        );
        let (fh, fo) = (self.face_of(h0), self.face_of(o0));
        let (after, before) = (self.nx(o0), self.pv(o0));
        self.links.set_next(h1, after);
        self.links.set_next(before, h1);
        self.links.set_face(h1, fo);
        self.links.set_outgoing(v0, h1);
        if b0 {
            self.adjust_outgoing(v0);
        }
        self.links.set_outgoing(v1, o1);
        if b1 {
            self.adjust_outgoing(v1);
        }
        if fo != NONE && self.face_he(fo) == o0 {
            self.links.set_face_half_edge(fo, h1);
        }
        if fh != NONE {
            self.marks.mark_face(fh);
        }
        self.marks.mark_edge(h0 >> 1);
    }

    /// OpenMesh's `vertex_split` (the inverse of `collapse`): see
    /// [`MeshEdit::split_vertex`](crate::MeshEdit::split_vertex).
    pub(super) fn split_vertex_checked(
        &mut self,
        v1: u32,
        p: DVec3,
        vl: u32,
        vr: u32,
    ) -> Result<u32> {
        let op = EditOp::SplitVertex;
        for v in [v1, vl, vr] {
            self.live_vertex(v, op)?;
        }
        if vl == vr || vl == v1 || vr == v1 {
            return Err(Self::refuse(op, Refusal::NotNeighbours));
        }
        let (a, b) = (self.find_half_edge(v1, vr), self.find_half_edge(v1, vl));
        if a == NONE || b == NONE {
            return Err(Self::refuse(op, Refusal::NotNeighbours));
        }
        // The half-edges after `a` up to `b` move to the new vertex; their faces must be
        // faces (a boundary inside the moved fan is the inverse of a boundary collapse,
        // which this phase does not implement).
        let mut g = self.cw(a);
        loop {
            if self.is_bnd(g) {
                return Err(Self::refuse(op, Refusal::NotImplemented));
            }
            if g == b {
                break;
            }
            g = self.cw(g);
        }
        self.room(1, 3, 2)?;
        let tb = b ^ 1;
        let (fa, ftb) = (self.face_of(a), self.face_of(tb));
        let (prev_a, next_a) = (self.pv(a), self.nx(a));
        let (prev_tb, next_tb) = (self.pv(tb), self.nx(tb));
        let v0 = self.links.push_vertex(p);
        let mut g = self.cw(a);
        loop {
            self.links.set_vertex(g, v0);
            if g == b {
                break;
            }
            g = self.cw(g);
        }
        self.links.set_vertex(a, v0);
        let x = self.links.push_edge(v0, v1);
        let y = x ^ 1;
        let l0 = self.links.push_edge(v1, vl);
        let l1 = l0 ^ 1;
        let r0 = self.links.push_edge(v1, vr);
        let r1 = r0 ^ 1;
        let tl = self.links.push_face(x);
        let tr = self.links.push_face(y);
        // r0 takes a's place in a's old loop, l1 takes tb's place in tb's; when the two are
        // consecutive (tb then a), l1 and r0 follow each other.
        let pa = if prev_a == tb { l1 } else { prev_a };
        let nb = if next_tb == a { r0 } else { next_tb };
        let l = &mut self.links;
        l.set_next(pa, r0);
        l.set_next(r0, next_a);
        l.set_next(prev_tb, l1);
        l.set_next(l1, nb);
        l.set_face(r0, fa);
        l.set_face(l1, ftb);
        l.set_next(x, l0);
        l.set_next(l0, tb);
        l.set_next(tb, x);
        for h in [x, l0, tb] {
            l.set_face(h, tl);
        }
        l.set_next(y, a);
        l.set_next(a, r1);
        l.set_next(r1, y);
        for h in [y, a, r1] {
            l.set_face(h, tr);
        }
        if fa != NONE && self.face_he(fa) == a {
            self.links.set_face_half_edge(fa, r0);
        }
        if ftb != NONE && self.face_he(ftb) == tb {
            self.links.set_face_half_edge(ftb, l1);
        }
        self.links.set_outgoing(v0, b);
        self.links.set_outgoing(v1, y);
        self.adjust_outgoing(v1);
        if self.out_of(vl) == tb {
            self.links.set_outgoing(vl, l1);
        }
        self.adjust_outgoing(vl);
        self.adjust_outgoing(vr);
        Ok(v0)
    }
}
