//! `validate()` of the winged-edge: every record, face cycle, vertex rotation and the
//! incremental index checked against each other.

use super::records::{edge_end, ends_key, EdgeRecord};
use super::WingedEdge;
use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::topology::MeshTopology;

/// `validate()`, in four parts.
impl WingedEdge {
    pub(super) fn broken(message: String) -> Result<()> {
        Err(Error::invariant(Self::NAME, message))
    }

    pub(super) fn is_edge_live(&self, e: EdgeId) -> bool {
        self.edges.get(e.index()).is_some_and(EdgeRecord::is_live)
    }

    /// Every edge record: ends, faces and wings exist; each wing points back (the edge after
    /// e in f has e before it, and the reverse) and shares the vertex where they meet; a
    /// removed record is fully cleared; no two edges join the same vertices; the live count.
    pub(super) fn check_records(&self) -> Result<()> {
        let n0 = self.positions.len();
        if self.av.len() != n0 {
            return Self::broken(format!("{} av entries for {n0} vertices", self.av.len()));
        }
        let mut keys = Vec::with_capacity(self.live_edges);
        for (i, r) in self.edges.iter().enumerate() {
            let e = EdgeId::new(i);
            if !r.is_live() {
                if *r != EdgeRecord::REMOVED {
                    return Self::broken(format!("removed edge e{i} keeps pointers: {r:?}"));
                }
                continue;
            }
            keys.push(ends_key(r.v1, r.v2));
            if r.v1.index() >= n0 || r.v2.index() >= n0 || r.v1 == r.v2 {
                return Self::broken(format!("e{i} has ends {:?}, {:?}", r.v1, r.v2));
            }
            if !self.is_face_live(r.fccw) {
                return Self::broken(format!("e{i} has no live fccw: {:?}", r.fccw));
            }
            if r.fcw.is_valid() && (!self.is_face_live(r.fcw) || r.fcw == r.fccw) {
                return Self::broken(format!("e{i} has fcw {:?} (fccw {:?})", r.fcw, r.fccw));
            }
            if !r.fcw.is_valid() && (r.pcw.is_valid() || r.ncw.is_valid()) {
                return Self::broken(format!("boundary edge e{i} has cw wings"));
            }
            for face in [r.fccw, r.fcw].into_iter().filter(|f| f.is_valid()) {
                let (Some(before), Some(after)) = (r.prev_in(face), r.next_in(face)) else {
                    return Self::broken(format!("e{i} lacks wings in {face:?}"));
                };
                if !self.is_edge_live(before) || !self.is_edge_live(after) {
                    return Self::broken(format!("e{i} has a wing to a missing edge in {face:?}"));
                }
                let (p, n) = (self.edge(before), self.edge(after));
                if p.next_in(face) != Some(e) || n.prev_in(face) != Some(e) {
                    return Self::broken(format!(
                        "in {face:?}, the wings of e{i} ({before:?}, {after:?}) do not point back to it"
                    ));
                }
                let [start, end] = r.ends_in(face);
                if p.ends_in(face)[1] != start || n.ends_in(face)[0] != end {
                    return Self::broken(format!(
                        "in {face:?}, e{i} does not share its ends with its wings"
                    ));
                }
            }
        }
        if keys.len() != self.live_edges {
            return Self::broken(format!(
                "{} live edge records, count says {}",
                keys.len(),
                self.live_edges
            ));
        }
        keys.sort_unstable();
        if let Some(w) = keys.windows(2).find(|w| w[0] == w[1]) {
            return Self::broken(format!(
                "two edges join v{} and v{}",
                w[0] >> 32,
                w[0] as u32
            ));
        }
        Ok(())
    }

    /// Every face: `af(f)` is one of its edges, and the wings from it make one cycle through
    /// every edge that names f, of at least three edges; removed faces are named by no edge.
    pub(super) fn check_faces(&self) -> Result<()> {
        let mut sides = vec![0usize; self.af.len()];
        for r in self.edges.iter().filter(|r| r.is_live()) {
            for f in [r.fccw, r.fcw].into_iter().filter(|f| f.is_valid()) {
                sides[f.index()] += 1;
            }
        }
        let mut live = 0;
        for (f, &start) in self.af.iter().enumerate() {
            let face = FaceId::new(f);
            if !start.is_valid() {
                continue;
            }
            live += 1;
            if !self.is_edge_live(start) || self.edge(start).side(face).is_none() {
                return Self::broken(format!("af(f{f}) = {start:?} is not an edge of f{f}"));
            }
            let mut cycle = 0;
            self.walk_face(face, |_, _| cycle += 1);
            if cycle != sides[f] || cycle < 3 {
                return Self::broken(format!(
                    "the cycle of f{f} has {cycle} edges, {} edges name it",
                    sides[f]
                ));
            }
        }
        if live != self.live_faces {
            return Self::broken(format!("{live} live faces, count says {}", self.live_faces));
        }
        Ok(())
    }

    /// Live edges per vertex.
    fn degrees(&self) -> Vec<u32> {
        let mut degree = vec![0u32; self.positions.len()];
        for r in self.edges.iter().filter(|r| r.is_live()) {
            degree[r.v1.index()] += 1;
            degree[r.v2.index()] += 1;
        }
        degree
    }

    /// Every vertex: `av(v)` is an edge at v (none exactly when v has no edges), and the
    /// rotation from it reaches all of v's edges (one fan), else [`Error::NonManifoldVertex`].
    /// The rotation terminates because the wings passed [`Self::check_records`].
    pub(super) fn check_vertices(&self) -> Result<()> {
        for (v, (&av, degree)) in self.av.iter().zip(self.degrees()).enumerate() {
            let vertex = VertexId::new(v);
            let Some(start) = av.valid() else {
                if degree != 0 {
                    return Self::broken(format!("v{v} has {degree} edges but av(v{v}) is none"));
                }
                continue;
            };
            if !self.is_edge_live(start)
                || (self.edge(start).v1 != vertex && self.edge(start).v2 != vertex)
            {
                return Self::broken(format!("av(v{v}) = {start:?} is not an edge of v{v}"));
            }
            let mut reached = 0;
            self.walk_fan(vertex, start, |_| reached += 1, |_| {});
            if reached != degree {
                return Err(Error::NonManifoldVertex {
                    vertex: v as u32,
                    fans: self.count_fans(vertex),
                });
            }
        }
        Ok(())
    }

    /// The number of fans around `v` (only called when there is more than one).
    fn count_fans(&self, v: VertexId) -> usize {
        let mut unseen: Vec<EdgeId> = (0..self.edges.len())
            .map(EdgeId::new)
            .filter(|&e| {
                let r = self.edge(e);
                r.is_live() && (r.v1 == v || r.v2 == v)
            })
            .collect();
        let mut fans = 0;
        while let Some(start) = unseen.pop() {
            fans += 1;
            self.walk_fan(v, start, |e| unseen.retain(|&x| x != e), |_| {});
        }
        fans
    }

    /// The incremental index, if built: every live edge under its ends and nothing else, and
    /// each vertex's ring holding exactly its live edges.
    pub(super) fn check_index(&self) -> Result<()> {
        let Some(index) = &self.index else {
            return Ok(());
        };
        if index.edge_by_ends.len() != self.live_edges {
            return Self::broken(format!(
                "the index holds {} edges, {} are live",
                index.edge_by_ends.len(),
                self.live_edges
            ));
        }
        for (e, r) in self.edges.iter().enumerate().filter(|(_, r)| r.is_live()) {
            if index.edge_by_ends.get(&ends_key(r.v1, r.v2)) != Some(&EdgeId::new(e)) {
                return Self::broken(format!("the index does not find e{e}"));
            }
        }
        // Each vertex's ring: exactly its live edges, each linked both ways.
        if index.first.len() != self.positions.len() {
            return Self::broken("the index's rings do not cover every vertex".into());
        }
        for (v, degree) in self.degrees().into_iter().enumerate() {
            let vertex = VertexId::new(v);
            let mut count = 0u32;
            let mut bad = None;
            index.ring_of(vertex, |x| {
                count += 1;
                let e = EdgeId(x / 2);
                let ok = self.is_edge_live(e) && {
                    let r = self.edge(e);
                    edge_end(e, r.v1, r.v2, vertex) == x
                        && (r.v1 == vertex || r.v2 == vertex)
                        && index.ring[index.ring[x as usize][0] as usize][1] == x
                };
                if !ok {
                    bad = Some(e);
                }
                ok && count <= degree
            });
            if let Some(e) = bad {
                return Self::broken(format!("the ring of v{v} holds {e:?} wrongly"));
            }
            if count != degree {
                return Self::broken(format!(
                    "the ring of v{v} holds {count} edges, v{v} has {degree}"
                ));
            }
        }
        Ok(())
    }
}
