//! Incremental construction and removal for the 3D convex hull algorithms; see
//! "Incremental construction" in the module docs.

use super::records::{build_index, ends_key, EdgeRecord};
use super::WingedEdge;
use crate::core::error::{Error, Numbering, Result};
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::topology::MeshTopology;
use glam::DVec3;

/// How [`WingedEdge::compact`] renumbered the faces and edges.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Renumbering {
    /// Old face index → new id (`INVALID` for a removed face).
    faces: Vec<FaceId>,
    /// Old edge index → new id (`INVALID` for a removed edge).
    edges: Vec<EdgeId>,
}

impl Renumbering {
    /// The new id of the face that was `old`, `None` if it had been removed (or never existed).
    pub fn face(&self, old: FaceId) -> Option<FaceId> {
        self.faces.get(old.index()).and_then(|f| f.valid())
    }

    /// The new id of the edge that was `old`, `None` if it had been removed (or never existed).
    pub fn edge(&self, old: EdgeId) -> Option<EdgeId> {
        self.edges.get(old.index()).and_then(|e| e.valid())
    }
}

/// Incremental construction: see "Incremental construction" in the module docs.
impl WingedEdge {
    /// Adds a vertex without edges and returns its id.
    pub fn add_vertex(&mut self, p: DVec3) -> VertexId {
        self.positions.push(p);
        self.av.push(EdgeId::INVALID);
        if let Some(index) = &mut self.index {
            index.add_vertex();
        }
        VertexId::new(self.positions.len() - 1)
    }

    /// Adds the face with corners `vertices` (counter-clockwise seen from outside) and returns
    /// its id, the next face slot. Each side a → b becomes a new edge (the face on its left),
    /// or the right side of the existing edge b → a; the face's wings are linked on its side
    /// of each edge, and nothing else changes. O(k) expected (index look-ups), plus the O(n)
    /// index build on first use.
    ///
    /// Fails, leaving the structure unchanged, on fewer than three corners, an unknown or
    /// repeated vertex, an edge that already has two faces ([`Error::NonManifoldEdge`]) or
    /// one whose face runs it in the same direction ([`Error::InconsistentOrientation`]).
    pub fn add_face(&mut self, vertices: &[VertexId]) -> Result<FaceId> {
        let k = vertices.len();
        for (what, count) in [
            ("faces", self.af.len() + 1),
            ("edges", self.edges.len() + k),
        ] {
            if count >= u32::MAX as usize {
                return Err(Error::TooLarge {
                    what,
                    count: count as u64,
                });
            }
        }
        let face = FaceId::new(self.af.len());
        if k < 3 {
            return Err(Error::TooFewCorners {
                face: face.index(),
                corners: k,
                numbering: Numbering::FromZero,
            });
        }
        let n0 = self.positions.len();
        for (i, &v) in vertices.iter().enumerate() {
            if v.index() >= n0 {
                return Err(Error::IndexOutOfRange {
                    face: face.index(),
                    index: v.0 as i64,
                    vertices: n0,
                    numbering: Numbering::FromZero,
                });
            }
            if vertices[..i].contains(&v) {
                return Err(Error::RepeatedVertex {
                    face: face.index(),
                    vertex: v.0,
                    numbering: Numbering::FromZero,
                });
            }
        }
        let index = self
            .index
            .get_or_insert_with(|| build_index(n0, &self.edges));
        let side = |i: usize| (vertices[i], vertices[(i + 1) % k]);
        // First every check, then every change: a refused face leaves no trace.
        let mut existing = Vec::with_capacity(k);
        for i in 0..k {
            let (a, b) = side(i);
            let found = index.edge_by_ends.get(&ends_key(a, b)).copied();
            if let Some(e) = found {
                let r = &self.edges[e.index()];
                if r.fcw.is_valid() {
                    let mut faces = vec![r.fccw.0, r.fcw.0, face.0];
                    faces.sort_unstable();
                    return Err(Error::NonManifoldEdge {
                        a: a.0,
                        b: b.0,
                        faces,
                    });
                }
                if r.v1 == a {
                    return Err(Error::InconsistentOrientation {
                        a: a.0,
                        b: b.0,
                        f: r.fccw.0,
                        g: face.0,
                    });
                }
            }
            existing.push(found);
        }
        let mut ids = Vec::with_capacity(k);
        for (i, found) in existing.into_iter().enumerate() {
            let e = found.unwrap_or_else(|| {
                let (a, b) = side(i);
                let e = EdgeId::new(self.edges.len());
                self.edges.push(EdgeRecord {
                    v1: a,
                    v2: b,
                    fccw: face,
                    ..EdgeRecord::REMOVED
                });
                index.link(e, a, b);
                self.live_edges += 1;
                e
            });
            ids.push(e);
        }
        for i in 0..k {
            let (before, after) = (ids[(i + k - 1) % k], ids[(i + 1) % k]);
            let r = &mut self.edges[ids[i].index()];
            if r.fccw == face {
                (r.pccw, r.nccw) = (before, after);
            } else {
                (r.fcw, r.pcw, r.ncw) = (face, before, after);
            }
            let av = &mut self.av[vertices[i].index()];
            if !av.is_valid() {
                *av = ids[i];
            }
        }
        self.af.push(ids[0]);
        self.live_faces += 1;
        Ok(face)
    }

    /// Removes face `face`: its side of each of its edges is emptied, an edge left without
    /// faces is removed, and an edge that keeps only its right face is turned around so the
    /// face is on its left. The face's slot stays as a tombstone (see the module docs). O(k)
    /// expected (index updates) in any order of removal: a vertex whose `av(v)` goes takes
    /// one of the face's surviving edges at v, else any edge from its ring in the index (v
    /// may keep edges in another fan: after add_face joined faces at a vertex only, as gift
    /// wrapping does, or after remove_face took a face from the middle of v's fan).
    ///
    /// Fails with [`Error::Unsupported`] if `face` does not exist (never added, or removed).
    pub fn remove_face(&mut self, face: FaceId) -> Result<()> {
        if !self.is_face_live(face) {
            return Err(Error::Unsupported(format!(
                "{}: face {face:?} does not exist (never added, or already removed)",
                Self::NAME
            )));
        }
        let mut cycle = Vec::new();
        self.walk_face(face, |e, _| cycle.push(e));
        let n0 = self.positions.len();
        let index = self
            .index
            .get_or_insert_with(|| build_index(n0, &self.edges));
        // Vertices whose av(v) was one of the removed edges.
        let mut orphaned = Vec::new();
        for &e in &cycle {
            let r = &mut self.edges[e.index()];
            if r.fcw == face {
                (r.fcw, r.pcw, r.ncw) = (FaceId::INVALID, EdgeId::INVALID, EdgeId::INVALID);
            } else if r.fcw.is_valid() {
                r.turn_right_side_left();
            } else {
                let (a, b) = (r.v1, r.v2);
                *r = EdgeRecord::REMOVED;
                self.live_edges -= 1;
                index.unlink(e, a, b);
                for v in [a, b] {
                    if self.av[v.index()] == e {
                        orphaned.push(v);
                    }
                }
            }
        }
        self.af[face.index()] = EdgeId::INVALID;
        self.live_faces -= 1;
        for v in orphaned {
            self.av[v.index()] = self.another_edge_at(v, &cycle);
        }
        Ok(())
    }

    /// A live edge at `v` to replace a removed `av(v)`: one of the removed face's surviving
    /// edges at v (the same fan), else any edge of v's ring in the index, else none.
    fn another_edge_at(&self, v: VertexId, cycle: &[EdgeId]) -> EdgeId {
        let at_v = |e: &EdgeId| {
            let r = self.edge(*e);
            r.is_live() && (r.v1 == v || r.v2 == v)
        };
        cycle.iter().copied().find(at_v).unwrap_or_else(|| {
            self.index
                .as_ref()
                .map_or(EdgeId::INVALID, |i| i.any_edge_at(v))
        })
    }

    /// Closes the gaps that removed faces and edges left: live faces and edges are renumbered
    /// densely in their old order, every pointer is rewritten. Returns the renumbering, for
    /// callers that hold ids. O(n).
    pub fn compact(&mut self) -> Renumbering {
        fn dense<T>(slots: &[T], live: impl Fn(&T) -> bool) -> Vec<u32> {
            let mut next = 0;
            slots
                .iter()
                .map(|s| {
                    if live(s) {
                        next += 1;
                        next - 1
                    } else {
                        u32::MAX
                    }
                })
                .collect()
        }
        let faces: Vec<FaceId> = dense(&self.af, |e| e.is_valid())
            .into_iter()
            .map(FaceId)
            .collect();
        let edges: Vec<EdgeId> = dense(&self.edges, EdgeRecord::is_live)
            .into_iter()
            .map(EdgeId)
            .collect();
        let edge = |e: EdgeId| if e.is_valid() { edges[e.index()] } else { e };
        let face = |f: FaceId| if f.is_valid() { faces[f.index()] } else { f };
        self.edges = self
            .edges
            .iter()
            .filter(|r| r.is_live())
            .map(|r| EdgeRecord {
                v1: r.v1,
                v2: r.v2,
                fccw: face(r.fccw),
                fcw: face(r.fcw),
                pccw: edge(r.pccw),
                nccw: edge(r.nccw),
                pcw: edge(r.pcw),
                ncw: edge(r.ncw),
            })
            .collect();
        self.af = self
            .af
            .iter()
            .filter(|e| e.is_valid())
            .map(|&e| edge(e))
            .collect();
        for av in &mut self.av {
            *av = edge(*av);
        }
        if self.index.is_some() {
            self.index = Some(build_index(self.positions.len(), &self.edges));
        }
        // The free slots were tombstones: gone now.
        self.stitching.free_faces.clear();
        self.stitching.free_edges.clear();
        Renumbering { faces, edges }
    }
}
