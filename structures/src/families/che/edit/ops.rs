//! The operations on a level's [`Parts`]: the checks (in the same order and with the same
//! meaning as the half-edge's Euler operations), the rewrite of `V[]`, and the local repair
//! ([`Patch`]) of the other containers; see the [module docs](super) for the costs.

use super::{nx, pv, Parts};
use crate::core::edit::{EditOp, Refusal};
use crate::core::error::Result;
use crate::core::ids::VertexId;
use crate::core::reads::{self, read};
use crate::families::che::build::{boundary_curves_algorithm_4, edge_map_by_scan};
use glam::DVec3;

/// What the local repair needs to know of the triangles an edit rewrites, taken before the
/// rewrite ([`Parts::begin`]).
pub(super) struct Patch {
    /// The outer half-edges: opposite to a half-edge of the rewritten triangles, outside them.
    outer: Vec<u32>,
    /// The vertices of the rewritten triangles (their `VH[]` is repaired).
    touched: Vec<u32>,
    /// A boundary half-edge was among the rewritten ones (level 3 relabels its curves).
    boundary: bool,
}

/// The key of the edge between `a` and `b`, the same in both directions.
fn edge_key(a: u32, b: u32) -> u64 {
    ((a.min(b) as u64) << 32) | a.max(b) as u64
}

impl Parts<'_> {
    /// `V[h]`, a read the counting build counts (see [`crate::core::reads`]).
    #[inline(always)]
    fn v_at(&self, h: u32) -> u32 {
        read!("V", self.v, h as usize)
    }

    /// `O[h]` if the edge of `h` is interior; level 0 scans `V[]` for it (Algorithm 8).
    fn twin(&self, h: u32) -> Option<u32> {
        match self.o.as_deref() {
            Some(o) => {
                let x = read!("O", o, h as usize);
                (x >= 0).then_some(x as u32)
            }
            None => self.scan_half_edge(self.v_at(nx(h)), self.v_at(h)),
        }
    }

    /// The half-edge from `a` to `b` by a scan of `V[]`.
    fn scan_half_edge(&self, a: u32, b: u32) -> Option<u32> {
        (0..self.v.len() as u32).find(|&g| self.v_at(g) == a && self.v_at(nx(g)) == b)
    }

    /// Calls `f` with each half-edge leaving `x` until it returns `true`; returns whether it
    /// did. From `VH[x]` around the fan (Algorithm 7's step) at levels 2 and 3, by a scan of
    /// `V[]` below (Algorithms 5 and 6 start with one).
    fn any_leaving(&self, x: u32, mut f: impl FnMut(u32) -> bool) -> bool {
        match (self.vh.as_deref(), self.o.as_deref()) {
            (Some(vh), Some(o)) => {
                if x as usize >= vh.len() {
                    return false;
                }
                let start = read!("VH", vh, x as usize);
                if start < 0 {
                    return false;
                }
                let mut h = start as u32;
                for _ in 0..o.len() {
                    if f(h) {
                        return true;
                    }
                    let back = read!("O", o, pv(h) as usize);
                    if back < 0 || back as u32 == start as u32 {
                        return false;
                    }
                    h = back as u32;
                }
                false
            }
            _ => (0..self.v.len() as u32).any(|h| self.v_at(h) == x && f(h)),
        }
    }

    /// The half-edge from `a` to `b`, if there is one.
    fn find(&self, a: u32, b: u32) -> Option<u32> {
        if self.vh.is_none() {
            return self.scan_half_edge(a, b);
        }
        let mut found = None;
        self.any_leaving(a, |h| {
            let hit = self.v_at(nx(h)) == b;
            if hit {
                found = Some(h);
            }
            hit
        });
        found
    }

    /// The neighbours of `x`, sorted.
    fn neighbours(&self, x: u32) -> Vec<u32> {
        let mut out = Vec::new();
        self.any_leaving(x, |h| {
            out.push(self.v_at(nx(h)));
            out.push(self.v_at(pv(h)));
            false
        });
        out.sort_unstable();
        out.dedup();
        out
    }

    fn is_boundary_edge(&self, a: u32, b: u32) -> bool {
        self.find(a, b).is_none() || self.find(b, a).is_none()
    }

    fn is_boundary_vertex(&self, x: u32) -> bool {
        self.neighbours(x)
            .into_iter()
            .any(|w| self.is_boundary_edge(x, w))
    }

    /// The triangles of the star of `x`.
    fn star(&self, x: u32) -> Vec<u32> {
        let mut out = Vec::new();
        self.any_leaving(x, |h| {
            out.push(h / 3);
            false
        });
        out
    }

    /// Notes the outer half-edges and vertices of `region` before its triangles are rewritten.
    fn begin(&self, region: &[u32]) -> Patch {
        let mut patch = Patch {
            outer: Vec::new(),
            touched: Vec::new(),
            boundary: false,
        };
        for &t in region {
            for h in 3 * t..3 * t + 3 {
                patch.touched.push(self.v_at(h));
                if let Some(o) = self.o.as_deref() {
                    let x = read!("O", o, h as usize);
                    if x < 0 {
                        patch.boundary = true;
                    } else if !region.contains(&(x as u32 / 3)) {
                        patch.outer.push(x as u32);
                    }
                }
            }
        }
        patch
    }

    /// Repairs the containers after the triangles of `changed` were rewritten or appended and
    /// before those of `removed` (rewritten, untouched) leave; see the module docs.
    fn finish(&mut self, mut patch: Patch, changed: &[u32], removed: &mut [u32]) {
        for &t in changed {
            let first = 3 * t as usize;
            patch
                .touched
                .extend(reads::each("V", &self.v[first..first + 3], first));
        }
        patch.touched.sort_unstable();
        patch.touched.dedup();
        let v = &*self.v;
        if let Some(o) = self.o.as_deref_mut() {
            let mut keyed: Vec<(u64, u32)> = changed
                .iter()
                .flat_map(|&t| 3 * t..3 * t + 3)
                .chain(patch.outer.iter().copied())
                .map(|h| {
                    (
                        edge_key(read!("V", v, h as usize), read!("V", v, nx(h) as usize)),
                        h,
                    )
                })
                .collect();
            keyed.sort_unstable();
            for group in keyed.chunk_by(|x, y| x.0 == y.0) {
                match *group {
                    [(_, a), (_, b)] => {
                        o[a as usize] = b as i32;
                        o[b as usize] = a as i32;
                    }
                    _ => {
                        // One half-edge (the checks admit no third): a boundary edge.
                        for &(_, a) in group {
                            o[a as usize] = -1;
                        }
                        patch.boundary = true;
                    }
                }
            }
        }
        if let (Some(vh), Some(o)) = (self.vh.as_deref_mut(), self.o.as_deref()) {
            for &x in &patch.touched {
                let leaving = changed
                    .iter()
                    .flat_map(|&t| 3 * t..3 * t + 3)
                    .chain(patch.outer.iter().flat_map(|&h| {
                        let t = h / 3;
                        3 * t..3 * t + 3
                    }))
                    .find(|&h| read!("V", v, h as usize) == x);
                vh[x as usize] = match leaving {
                    None => -1,
                    Some(start) => {
                        // Turn back to the boundary half-edge leaving x, if there is one.
                        let mut h = start;
                        for _ in 0..o.len() {
                            let back = read!("O", o, h as usize);
                            if back < 0 {
                                break;
                            }
                            h = nx(back as u32);
                            if h == start {
                                break;
                            }
                        }
                        h as i32
                    }
                };
            }
        }
        removed.sort_unstable_by(|a, b| b.cmp(a));
        for &t in removed.iter() {
            self.swap_remove_triangle(t);
        }
        if let (Some(eh), Some(o)) = (self.eh.as_deref_mut(), self.o.as_deref()) {
            *eh = edge_map_by_scan(o);
        }
        if let (Some(ch), Some(o)) = (self.ch.as_deref_mut(), self.o.as_deref_mut()) {
            if patch.boundary {
                o.iter_mut().filter(|x| **x < 0).for_each(|x| *x = -1);
                *ch = boundary_curves_algorithm_4(o);
            }
        }
    }

    /// Removes triangle `t`: the last triangle moves into its slot, and the `O[]`, `VH[]` and
    /// `CH[]` entries that named the moved half-edges follow. Nothing may name `t`'s own
    /// half-edges any more.
    fn swap_remove_triangle(&mut self, t: u32) {
        let last = (self.v.len() / 3 - 1) as u32;
        if t != last {
            let moved = |h: u32| (3 * last..3 * last + 3).contains(&h);
            let to = |h: u32| h - 3 * last + 3 * t;
            for k in 0..3 {
                let (from, into) = ((3 * last + k) as usize, (3 * t + k) as usize);
                self.v[into] = read!("V", self.v, from);
                if let Some(o) = self.o.as_deref_mut() {
                    let x = read!("O", o, from);
                    o[into] = x;
                    if x >= 0 {
                        o[x as usize] = into as i32;
                    }
                }
                if let Some(vh) = self.vh.as_deref_mut() {
                    let x = self.v[into] as usize;
                    let start = read!("VH", vh, x);
                    if start >= 0 && moved(start as u32) {
                        vh[x] = to(vh[x] as u32) as i32;
                    }
                }
            }
            if let Some(ch) = self.ch.as_deref_mut() {
                reads::scanned("CH", ch, 0);
                ch.iter_mut()
                    .filter(|h| moved(**h))
                    .for_each(|h| *h = to(*h));
            }
        }
        let n = 3 * last as usize;
        self.v.truncate(n);
        if let Some(o) = self.o.as_deref_mut() {
            o.truncate(n);
        }
    }

    /// Checks that `h` names a half-edge.
    fn half_edge(&self, op: EditOp, h: u32) -> Result<u32> {
        if (h as usize) < self.v.len() {
            Ok(h)
        } else {
            Err(self.refuse(op, Refusal::NoSuchElement))
        }
    }

    pub(super) fn set_position(&mut self, x: u32, p: DVec3) -> Result<()> {
        if !self.live_vertex(x) {
            return Err(self.refuse(EditOp::SetPosition, Refusal::NoSuchElement));
        }
        self.g[x as usize] = p;
        Ok(())
    }

    pub(super) fn add_face(&mut self, vertices: &[VertexId]) -> Result<u32> {
        let op = EditOp::AddFace;
        if vertices.iter().any(|x| !self.live_vertex(x.0)) {
            return Err(self.refuse(op, Refusal::NoSuchElement));
        }
        let &[a, b, c] = vertices else {
            let reason = if vertices.len() < 3 {
                Refusal::BadFace
            } else {
                Refusal::NotTriangles
            };
            return Err(self.refuse(op, reason));
        };
        if a == b || b == c || c == a {
            return Err(self.refuse(op, Refusal::BadFace));
        }
        self.room(0, 1)?;
        let mut v = self.v.clone();
        v.extend([a.0, b.0, c.0]);
        self.rebuild(op, v, self.g.len())?;
        Ok((self.num_triangles() - 1) as u32)
    }

    pub(super) fn delete_face(&mut self, f: u32) -> Result<()> {
        let op = EditOp::DeleteFace;
        if f as usize >= self.num_triangles() {
            return Err(self.refuse(op, Refusal::NoSuchElement));
        }
        let mut v = self.v.clone();
        let last = v.len() - 3;
        v.copy_within(last.., 3 * f as usize);
        v.truncate(last);
        self.rebuild(op, v, self.g.len())
    }

    pub(super) fn delete_vertex(&mut self, x: u32) -> Result<()> {
        let op = EditOp::DeleteVertex;
        if !self.live_vertex(x) {
            return Err(self.refuse(op, Refusal::NoSuchElement));
        }
        reads::scanned("V", self.v, 0);
        let v: Vec<u32> = self
            .v
            .chunks_exact(3)
            .filter(|t| !t.contains(&x))
            .flatten()
            .copied()
            .collect();
        self.rebuild(op, v, self.g.len())?;
        self.mark_deleted(x);
        Ok(())
    }

    /// Merges `b` into `a` (see the [module docs](super)): the corners of `b` in a copy of
    /// `V[]` become `a`, and the rebuild refuses a result that is not an oriented manifold
    /// with one fan per vertex, before anything is replaced.
    pub(super) fn weld(&mut self, a: u32, b: u32) -> Result<()> {
        let op = EditOp::WeldVertices;
        if !self.live_vertex(a) || !self.live_vertex(b) {
            return Err(self.refuse(op, Refusal::NoSuchElement));
        }
        if a == b {
            return Err(self.refuse(op, Refusal::SameVertex));
        }
        let mut uses_b = false;
        reads::scanned("V", self.v, 0);
        for t in self.v.chunks_exact(3) {
            let has_b = t.contains(&b);
            if has_b && t.contains(&a) {
                return Err(self.refuse(op, Refusal::BadFace));
            }
            uses_b |= has_b;
        }
        if uses_b {
            let v: Vec<u32> = self.v.iter().map(|&x| if x == b { a } else { x }).collect();
            self.rebuild(op, v, self.g.len())?;
        }
        self.mark_deleted(b);
        Ok(())
    }

    pub(super) fn flip(&mut self, e: u32) -> Result<()> {
        let op = EditOp::FlipEdge;
        let h = self.half_edge(op, e)?;
        let g = self
            .twin(h)
            .ok_or_else(|| self.refuse(op, Refusal::BoundaryEdge))?;
        let (x, y) = (self.v_at(pv(h)), self.v_at(pv(g)));
        if x == y || self.find(x, y).is_some() || self.find(y, x).is_some() {
            return Err(self.refuse(op, Refusal::EdgeExists));
        }
        let region = [h / 3, g / 3];
        let patch = self.begin(&region);
        // (a, b, x) becomes (a, y, x) and (b, a, y) becomes (b, x, y); the half-edges x → a
        // and y → b keep their slots.
        self.v[nx(h) as usize] = y;
        self.v[nx(g) as usize] = x;
        self.finish(patch, &region, &mut []);
        Ok(())
    }

    pub(super) fn split_edge(&mut self, e: u32, p: DVec3) -> Result<u32> {
        let op = EditOp::SplitEdge;
        let h = self.half_edge(op, e)?;
        let g = self.twin(h);
        if let Some(g) = g {
            if self.v_at(pv(h)) == self.v_at(pv(g)) {
                return Err(self.refuse(op, Refusal::LinkCondition));
            }
        }
        self.room(1, 2)?;
        let sides: Vec<u32> = std::iter::once(h).chain(g).collect();
        let mut changed: Vec<u32> = sides.iter().map(|s| s / 3).collect();
        let patch = self.begin(&changed);
        let n = self.push_vertex(p);
        for s in sides {
            // (s, t, o) becomes (s, n, o) and (n, t, o) is appended.
            let (t, o) = (self.v_at(nx(s)), self.v_at(pv(s)));
            self.v[nx(s) as usize] = n;
            changed.push(self.push_triangle(n, t, o));
        }
        self.finish(patch, &changed, &mut []);
        Ok(n)
    }

    pub(super) fn split_face(&mut self, f: u32, p: DVec3) -> Result<u32> {
        if f as usize >= self.num_triangles() {
            return Err(self.refuse(EditOp::SplitFace, Refusal::NoSuchElement));
        }
        self.room(1, 2)?;
        let patch = self.begin(&[f]);
        let n = self.push_vertex(p);
        let t = 3 * f as usize;
        let (a, b, c) = (
            read!("V", self.v, t),
            read!("V", self.v, t + 1),
            read!("V", self.v, t + 2),
        );
        // (a, b, c) becomes (a, b, n); (b, c, n) and (c, a, n) are appended.
        self.v[t + 2] = n;
        let t1 = self.push_triangle(b, c, n);
        let t2 = self.push_triangle(c, a, n);
        self.finish(patch, &[f, t1, t2], &mut []);
        Ok(n)
    }

    /// The link condition as pmp-library's `is_collapse_ok` states it
    /// ([`Refusal::LinkCondition`]), with OpenMesh's tetrahedron test after its `vl == vr` rule
    /// ([`Refusal::TetrahedronTest`]; see the half-edge's collapse), asked through this level's
    /// relations.
    fn collapse_ok(&self, from: u32, to: u32) -> Result<(), Refusal> {
        let third = |a: u32, b: u32| self.find(a, b).map(|h| self.v_at(pv(h)));
        let (left, right) = (third(from, to), third(to, from));
        for (side, a, b) in [(left, to, from), (right, from, to)] {
            if let Some(x) = side {
                if self.is_boundary_edge(a, x) && self.is_boundary_edge(x, b) {
                    return Err(Refusal::LinkCondition);
                }
            }
        }
        if left == right {
            return Err(Refusal::LinkCondition);
        }
        if let (Some(l), Some(r)) = (left, right) {
            let valence = |x: u32| self.neighbours(x).len();
            if self.neighbours(l).contains(&r) && valence(l) == 3 && valence(r) == 3 {
                return Err(Refusal::TetrahedronTest);
            }
        }
        if self.is_boundary_vertex(from)
            && self.is_boundary_vertex(to)
            && !self.is_boundary_edge(from, to)
        {
            return Err(Refusal::LinkCondition);
        }
        let ring = self.neighbours(to);
        let shared = self
            .neighbours(from)
            .into_iter()
            .any(|w| w != to && Some(w) != left && Some(w) != right && ring.contains(&w));
        if shared {
            return Err(Refusal::LinkCondition);
        }
        Ok(())
    }

    pub(super) fn collapse(&mut self, from: u32, to: u32) -> Result<()> {
        let op = EditOp::CollapseEdge;
        if !self.live_vertex(from) || !self.live_vertex(to) {
            return Err(self.refuse(op, Refusal::NoSuchElement));
        }
        if !self.neighbours(from).contains(&to) {
            return Err(self.refuse(op, Refusal::NotNeighbours));
        }
        self.collapse_ok(from, to)
            .map_err(|reason| self.refuse(op, reason))?;
        let region = self.star(from);
        let patch = self.begin(&region);
        let (mut removed, mut changed) = (Vec::new(), Vec::new());
        for &t in &region {
            let corners = &mut self.v[3 * t as usize..3 * t as usize + 3];
            reads::scanned("V", corners, 3 * t as usize);
            if corners.contains(&to) {
                removed.push(t);
            } else {
                corners
                    .iter_mut()
                    .filter(|x| **x == from)
                    .for_each(|x| *x = to);
                changed.push(t);
            }
        }
        self.finish(patch, &changed, &mut removed);
        self.mark_deleted(from);
        Ok(())
    }

    pub(super) fn split_vertex(&mut self, x: u32, p: DVec3, left: u32, right: u32) -> Result<u32> {
        let op = EditOp::SplitVertex;
        if [x, left, right].iter().any(|&w| !self.live_vertex(w)) || left == right {
            return Err(self.refuse(op, Refusal::NoSuchElement));
        }
        let ring = self.neighbours(x);
        if !ring.contains(&left) || !ring.contains(&right) || left == x || right == x {
            return Err(self.refuse(op, Refusal::NotNeighbours));
        }
        // The fan that moves: from the triangle of x → left to the one of right → x. Both are
        // neighbours (checked above), so a triangle missing on the way is the boundary inside
        // the moving fan: the inverse of a boundary collapse, not implemented, as in the
        // half-edges.
        let boundary_in_fan = || self.refuse(op, Refusal::NotImplemented);
        let mut h = self.find(x, left).ok_or_else(boundary_in_fan)?;
        let mut moved = Vec::new();
        loop {
            if moved.contains(&(h / 3)) {
                return Err(self.refuse(op, Refusal::NotNeighbours));
            }
            moved.push(h / 3);
            let before = self.v_at(pv(h));
            if before == right {
                break;
            }
            h = self.find(x, before).ok_or_else(boundary_in_fan)?;
        }
        self.room(1, 2)?;
        let n = self.g.len() as u32;
        let mut v = self.v.clone();
        for t in moved {
            for c in &mut v[3 * t as usize..3 * t as usize + 3] {
                if *c == x {
                    *c = n;
                }
            }
        }
        v.extend([n, x, left, x, n, right]);
        self.rebuild(op, v, self.g.len() + 1)?;
        self.push_vertex(p);
        if let Some(vh) = self.vh.as_deref_mut() {
            // rebuild numbered VH[] with the new vertex already.
            vh.truncate(self.g.len());
        }
        Ok(n)
    }

    pub(super) fn garbage_collection(&mut self) {
        if !self.deleted.iter().any(|&d| d) {
            self.deleted.clear();
            return;
        }
        let mut map = Vec::with_capacity(self.g.len());
        let mut next = 0u32;
        for x in 0..self.g.len() as u32 {
            map.push(next);
            next += !self.is_deleted(x) as u32;
        }
        let deleted = std::mem::take(self.deleted);
        let keep = |i: usize| !deleted.get(i).copied().unwrap_or(false);
        let mut i = 0;
        self.g.retain(|_| {
            i += 1;
            keep(i - 1)
        });
        if let Some(vh) = self.vh.as_deref_mut() {
            let mut i = 0;
            vh.retain(|_| {
                i += 1;
                keep(i - 1)
            });
        }
        for x in self.v.iter_mut() {
            *x = map[*x as usize];
        }
    }

    pub(super) fn reserve(&mut self, vertices: usize, faces: usize) {
        self.g.reserve(vertices);
        self.v.reserve(3 * faces);
        if let Some(o) = self.o.as_deref_mut() {
            o.reserve(3 * faces);
        }
        if let Some(vh) = self.vh.as_deref_mut() {
            vh.reserve(vertices);
        }
    }
}
