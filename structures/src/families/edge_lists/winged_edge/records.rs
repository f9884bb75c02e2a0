//! The edge record of the lecture on 3D convex hulls, and what the incremental API keeps
//! beside the records.

use crate::core::ids::{EdgeId, FaceId, VertexId};
use std::collections::HashMap;

/// An edge's eight pointers, in the hull lecture's names (see the module docs for their meaning).
/// `v1 == VertexId::INVALID` marks a removed edge.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(super) struct EdgeRecord {
    /// First end: e runs v1 → v2.
    pub(super) v1: VertexId,
    /// Second end.
    pub(super) v2: VertexId,
    /// The face on the left, running v1 → v2.
    pub(super) fccw: FaceId,
    /// The face on the right, running v2 → v1; none on the boundary.
    pub(super) fcw: FaceId,
    /// The edge before e in `fccw`.
    pub(super) pccw: EdgeId,
    /// The edge after e in `fccw`.
    pub(super) nccw: EdgeId,
    /// The edge before e in `fcw`.
    pub(super) pcw: EdgeId,
    /// The edge after e in `fcw`.
    pub(super) ncw: EdgeId,
}

impl EdgeRecord {
    /// A removed edge: every pointer none.
    pub(super) const REMOVED: Self = Self {
        v1: VertexId::INVALID,
        v2: VertexId::INVALID,
        fccw: FaceId::INVALID,
        fcw: FaceId::INVALID,
        pccw: EdgeId::INVALID,
        nccw: EdgeId::INVALID,
        pcw: EdgeId::INVALID,
        ncw: EdgeId::INVALID,
    };

    #[inline]
    pub(super) fn is_live(&self) -> bool {
        self.v1.is_valid()
    }

    /// Is `f` on the left (`Some(true)`), on the right (`Some(false)`) or not a face of e?
    #[inline]
    pub(super) fn side(&self, f: FaceId) -> Option<bool> {
        if !f.is_valid() {
            None
        } else if self.fccw == f {
            Some(true)
        } else if self.fcw == f {
            Some(false)
        } else {
            None
        }
    }

    /// The edge after e in face `f`'s cycle.
    #[inline]
    pub(super) fn next_in(&self, f: FaceId) -> Option<EdgeId> {
        self.side(f)
            .map(|left| if left { self.nccw } else { self.ncw })
    }

    /// The edge before e in face `f`'s cycle.
    #[inline]
    pub(super) fn prev_in(&self, f: FaceId) -> Option<EdgeId> {
        self.side(f)
            .map(|left| if left { self.pccw } else { self.pcw })
    }

    /// Where face `f` enters and leaves e: `[v1, v2]` on the left, `[v2, v1]` on the right.
    #[inline]
    pub(super) fn ends_in(&self, f: FaceId) -> [VertexId; 2] {
        if self.fccw == f {
            [self.v1, self.v2]
        } else {
            [self.v2, self.v1]
        }
    }

    /// The end of e that is not `v`.
    #[inline]
    pub(super) fn other_end(&self, v: VertexId) -> VertexId {
        if self.v1 == v {
            self.v2
        } else {
            self.v1
        }
    }

    /// The other face than `f` (none on the boundary).
    #[inline]
    pub(super) fn other_face(&self, f: FaceId) -> FaceId {
        if self.fccw == f {
            self.fcw
        } else {
            self.fccw
        }
    }

    /// Turns the edge around (v1 ↔ v2, the right side's face and wings become the left's),
    /// leaving the right side empty: used when the left face is removed.
    pub(super) fn turn_right_side_left(&mut self) {
        *self = Self {
            v1: self.v2,
            v2: self.v1,
            fccw: self.fcw,
            pccw: self.pcw,
            nccw: self.ncw,
            ..Self::REMOVED
        };
    }
}

/// The key of an undirected edge in the incremental index: smaller end in the high half.
#[inline]
pub(super) fn ends_key(a: VertexId, b: VertexId) -> u64 {
    let (lo, hi) = if a < b { (a.0, b.0) } else { (b.0, a.0) };
    ((lo as u64) << 32) | hi as u64
}

/// What the incremental API keeps beside the hull lecture's records (see the module docs).
#[derive(Clone, Debug, Default)]
pub(super) struct IncrementalIndex {
    /// Each live edge by its end vertices ([`ends_key`]).
    pub(super) edge_by_ends: HashMap<u64, EdgeId>,
    /// `first[v]`: an edge end ([`edge_end`]) at v, the entry to v's ring; none when v has no
    /// edges. A vertex that loses the edge `av(v)` takes another from here, in O(1), even
    /// when that edge is in another fan of v.
    pub(super) first: Vec<u32>,
    /// `ring[x]`: for the edge end x, the next and the previous edge end in the ring of its
    /// vertex (a circular list of all live edges at the vertex).
    pub(super) ring: Vec<[u32; 2]>,
}

/// No edge end.
const NO_END: u32 = u32::MAX;

/// The edge end of e at its end v: 2e at the smaller of its end vertices, 2e + 1 at the
/// larger (by id, so turning the edge around keeps its ends' names).
#[inline]
pub(super) fn edge_end(e: EdgeId, a: VertexId, b: VertexId, v: VertexId) -> u32 {
    2 * e.0 + u32::from(v == a.max(b))
}

impl IncrementalIndex {
    /// Makes room for a new vertex, without edges.
    pub(super) fn add_vertex(&mut self) {
        self.first.push(NO_END);
    }

    /// Records the new live edge e = {a, b}.
    pub(super) fn link(&mut self, e: EdgeId, a: VertexId, b: VertexId) {
        self.edge_by_ends.insert(ends_key(a, b), e);
        if self.ring.len() < 2 * e.index() + 2 {
            self.ring.resize(2 * e.index() + 2, [NO_END; 2]);
        }
        for v in [a, b] {
            let x = edge_end(e, a, b, v);
            let head = self.first[v.index()];
            if head == NO_END {
                self.first[v.index()] = x;
                self.ring[x as usize] = [x, x];
            } else {
                let next = self.ring[head as usize][0];
                self.ring[x as usize] = [next, head];
                self.ring[head as usize][0] = x;
                self.ring[next as usize][1] = x;
            }
        }
    }

    /// Forgets the edge e = {a, b}, which is being removed.
    pub(super) fn unlink(&mut self, e: EdgeId, a: VertexId, b: VertexId) {
        self.edge_by_ends.remove(&ends_key(a, b));
        for v in [a, b] {
            let x = edge_end(e, a, b, v);
            let [next, prev] = self.ring[x as usize];
            if next == x {
                self.first[v.index()] = NO_END;
            } else {
                self.ring[prev as usize][0] = next;
                self.ring[next as usize][1] = prev;
                if self.first[v.index()] == x {
                    self.first[v.index()] = next;
                }
            }
            self.ring[x as usize] = [NO_END; 2];
        }
    }

    /// A live edge at v, none if v has none.
    #[inline]
    pub(super) fn any_edge_at(&self, v: VertexId) -> EdgeId {
        match self.first[v.index()] {
            NO_END => EdgeId::INVALID,
            x => EdgeId(x / 2),
        }
    }

    /// The edges in v's ring, in ring order (for validation).
    pub(super) fn ring_of(&self, v: VertexId, mut f: impl FnMut(u32) -> bool) {
        let head = self.first[v.index()];
        if head == NO_END {
            return;
        }
        let mut x = head;
        loop {
            if !f(x) {
                return;
            }
            x = self.ring[x as usize][0];
            if x == head || x == NO_END {
                return;
            }
        }
    }

    /// Heap bytes.
    pub(super) fn heap_bytes(&self) -> usize {
        // The hash map's buckets (key + value) plus one control byte each.
        self.edge_by_ends.capacity() * (std::mem::size_of::<(u64, EdgeId)>() + 1)
            + self.first.capacity() * 4
            + self.ring.capacity() * 8
    }
}

/// The incremental index of `edges` over `vertices` vertices (see [`IncrementalIndex`]).
pub(super) fn build_index(vertices: usize, edges: &[EdgeRecord]) -> IncrementalIndex {
    let mut index = IncrementalIndex {
        edge_by_ends: HashMap::with_capacity(edges.len()),
        first: vec![NO_END; vertices],
        ring: vec![[NO_END; 2]; 2 * edges.len()],
    };
    for (e, r) in edges.iter().enumerate().filter(|(_, r)| r.is_live()) {
        index.link(EdgeId::new(e), r.v1, r.v2);
    }
    index
}
