//! `validate()` of both half-edge storages, through their primitives. Slots an edit deleted
//! and `garbage_collection` has not yet removed ([`Marks`]) are skipped; no live element may
//! point to one.

use super::edit::Marks;
use super::HalfEdgeLinks;
use crate::core::error::{Error, Result};
use crate::core::ids::{FaceId, VertexId};

/// Every invariant of half-edge connectivity, checked through the primitives by ids.
pub(super) fn validate_links<L: HalfEdgeLinks>(l: &L, marks: &Marks) -> Result<()> {
    let fail = |message: String| Err(Error::invariant(L::NAME, message));
    let (nh, nv, nf) = (l.num_half_edges(), l.num_vertices(), l.num_faces());
    if nh % 2 != 0 {
        return fail(format!("{nh} half-edges: half-edges come in pairs"));
    }
    let mut leaving = vec![0u32; nv];
    let mut directed = Vec::with_capacity(nh);
    let mut with_face = 0usize;
    // `next` must be a permutation, so every face and boundary loop closes.
    let mut has_prev = vec![false; nh];
    for id in 0..nh as u32 {
        if marks.edge(id >> 1) {
            continue;
        }
        let h = l.half_edge(id);
        if l.id(h) != id {
            return fail(format!("half-edge {id} reports id {}", l.id(h)));
        }
        let t = l.twin(h);
        if l.id(t) != id ^ 1 || l.twin(t) != h {
            return fail(format!(
                "pair of h{id} is h{}, expected h{}",
                l.id(t),
                id ^ 1
            ));
        }
        let (a, b) = (l.vertex(h), l.vertex(t));
        if a.index() >= nv || b.index() >= nv || a == b {
            return fail(format!("h{id} runs v{} -> v{}", a.0, b.0));
        }
        let n = l.next(h);
        if marks.edge(l.id(n) >> 1) {
            return fail(format!("h{id} is followed by a deleted half-edge"));
        }
        if marks.vertex(a.0) || l.face(h).is_some_and(|f| marks.face(f.0)) {
            return fail(format!(
                "h{id} starts at a deleted vertex or borders a deleted face"
            ));
        }
        if l.vertex(n) != b {
            return fail(format!(
                "h{id} ends at v{}, but its next h{} starts at v{}",
                b.0,
                l.id(n),
                l.vertex(n).0
            ));
        }
        if l.face(n) != l.face(h) {
            return fail(format!(
                "h{id} and its next h{} border different faces",
                l.id(n)
            ));
        }
        if has_prev[l.id(n) as usize] {
            return fail(format!("h{} is the next of two half-edges", l.id(n)));
        }
        has_prev[l.id(n) as usize] = true;
        if l.stored_prev(n).is_some_and(|p| p != id) {
            return fail(format!("prev of h{} is not h{id}", l.id(n)));
        }
        match l.face(h) {
            Some(f) if f.index() >= nf => return fail(format!("h{id} names missing face {f}")),
            Some(_) => with_face += 1,
            None if l.face(t).is_none() => {
                return fail(format!("edge e{} has no face on either side", id >> 1))
            }
            None => {}
        }
        leaving[a.index()] += 1;
        directed.push((a.0, b.0));
    }
    directed.sort_unstable();
    if let Some(w) = directed.windows(2).find(|w| w[0] == w[1]) {
        return fail(format!("two half-edges run v{} -> v{}", w[0].0, w[0].1));
    }
    let mut in_face_loops = 0usize;
    for f in 0..nf {
        if marks.face(f as u32) {
            continue;
        }
        let fid = FaceId::new(f);
        let start = l.face_half_edge(fid);
        let mut h = start;
        let mut len = 0usize;
        loop {
            if l.face(h) != Some(fid) {
                return fail(format!("the loop of f{f} reaches h{}", l.id(h)));
            }
            len += 1;
            h = l.next(h);
            if h == start {
                break;
            }
            if len > nh {
                return fail(format!("the loop of f{f} does not close"));
            }
        }
        if len < 3 {
            return fail(format!("f{f} has {len} half-edges"));
        }
        in_face_loops += len;
    }
    if in_face_loops != with_face {
        return fail(format!(
            "{with_face} half-edges border faces but the face loops hold {in_face_loops}"
        ));
    }
    for (v, &count) in leaving.iter().enumerate() {
        let vid = VertexId::new(v);
        if marks.vertex(v as u32) && (count != 0 || l.outgoing(vid).is_some()) {
            return fail(format!("deleted v{v} still has half-edges"));
        }
        let Some(start) = l.outgoing(vid) else {
            if count != 0 {
                return fail(format!("v{v} has no half-edge but {count} leave it"));
            }
            continue;
        };
        let (mut h, mut steps, mut boundary) = (start, 0u32, false);
        loop {
            if marks.edge(l.id(h) >> 1) {
                return fail(format!("the rotation of v{v} reaches deleted h{}", l.id(h)));
            }
            if l.vertex(h) != vid {
                return fail(format!("the rotation of v{v} reaches h{}", l.id(h)));
            }
            boundary |= l.face(h).is_none();
            steps += 1;
            h = l.next(l.twin(h));
            if h == start || steps > count {
                break;
            }
        }
        if steps != count || h != start {
            return fail(format!(
                "the rotation of v{v} reaches {steps} of its {count} outgoing half-edges"
            ));
        }
        if boundary && l.face(start).is_some() {
            return fail(format!(
                "v{v} is on the boundary but its half-edge h{} is not a boundary half-edge",
                l.id(start)
            ));
        }
    }
    Ok(())
}
