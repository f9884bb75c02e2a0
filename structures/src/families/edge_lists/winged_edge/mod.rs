//! # Winged-edge structure
//!
//! The *doppelt verkettete Kantenliste* (winged edge) of the lecture on polygon-mesh data
//! structures (here "the polygon-mesh lecture"), with the record of the lecture on 3D convex
//! hulls (*arestas aladas*; here "the hull lecture"), in the hull lecture's names:
//!
//! - **vertex** v: its coordinates (x, y, z) and `av(v)`, one arbitrary edge incident to v;
//! - **face** f: `af(f)`, one arbitrary edge of f's boundary;
//! - **edge** e: eight pointers, `v1, v2, fccw, fcw, pccw, nccw, pcw, ncw`.
//!
//! | field | meaning (the hull lecture) | the polygon-mesh lecture's column |
//! |---|---|---|
//! | `v1`, `v2` | the two ends; their order gives e its orientation v1 → v2 | Start, End |
//! | `fccw` | the face on the left of e = v1 v2: it runs through e from v1 to v2 in its counter-clockwise cycle | Faces: Left |
//! | `fcw` | the face on the right: it runs through e from v2 to v1; none (`-`, the polygon-mesh lecture's `N`) on the boundary | Faces: Right |
//! | `pccw` | the edge before e in `fccw`'s cycle (it ends at v1) | Left Traverse: Pred |
//! | `nccw` | the edge after e in `fccw`'s cycle (it starts at v2) | Left Traverse: Succ |
//! | `pcw` | the edge before e in `fcw`'s cycle (it ends at v2) | Right Traverse: Pred |
//! | `ncw` | the edge after e in `fcw`'s cycle (it starts at v1) | Right Traverse: Succ |
//!
//! "Precede" and "succeed" are in each face's own counter-clockwise cycle on both sides (the
//! hull lecture: *as arestas que precedem e sucedem e na face fcw(e)*; the polygon-mesh
//! lecture's example
//! `E4 = (4, 2, P1, P2, 5, 1, 2, 3)` has E2 → E4 → E3 in P2). Some texts order the cw wings
//! clockwise instead; not here. A live edge always has `fccw`: a boundary edge is oriented so
//! that its one face is on its left, and `fcw`, `pcw`, `ncw` are none.
//!
//! | stores | bytes |
//! |---|---|
//! | `positions[v]`: x, y, z | 24 per vertex |
//! | `av[v]`: one incident edge | 4 per vertex |
//! | `af[f]`: one boundary edge | 4 per face |
//! | `edges[e]`: the eight pointers, one 32-byte record | 32 per edge |
//!
//! About 66 bytes per triangle of a closed triangle mesh (n1 = 1.5 n2, n0 = n2 / 2). Vertices and
//! faces are arrays of one field each; edges are records (array of structs) because every step of a
//! walk reads several fields of the same edge together (which end is the vertex, then that side's
//! face and wing): one cache line per step instead of three or four with one array per field. The
//! hull lecture also stresses that each record has constant size.
//!
//! `EdgeId`: index into `edges`; from a soup, numbered by first appearance (as
//! [`crate::core::soup::Connectivity`] numbers them), v1 → v2 in the order the first face runs.
//!
//! ## Costs
//!
//! As the polygon-mesh lecture's table *winged-edge Struktur – Zusammenfassung*, except the
//! vertex rows: that table scans all n edges for the vertex ("Alle n Kanten nach Ecke
//! absuchen") because its edge list has no pointer from a vertex; the hull lecture's record
//! has one, `av(v)`, so the vertex star is walked from it through the wings in O(k), and that
//! is what is implemented (the table's O(n) scan would ignore a stored field).
//!
//! | given | wanted | operator | how | cost |
//! |---|---|---|---|---|
//! | vertex | outgoing edges | R01 | from `av(v)`, rotate both ways at once: the wing before e in the face where e leaves v, and the wing after e in the face where e enters v | O(k) |
//! | vertex | neighbour vertices | R00 | the other ends of those edges | O(k) |
//! | vertex | adjacent faces | R02 | the faces passed by the rotation | O(k) |
//! | vertex | on the boundary? | boundary vertex | the rotation meets a missing face | O(k) |
//! | edge | end points | R10 | `v1`, `v2` | O(1) |
//! | edge | successor, predecessor | edge successor / predecessor | `nccw`/`ncw`, `pccw`/`pcw` | O(1) |
//! | edge | adjacent faces | R12 | `fccw`, `fcw` | O(1) |
//! | edge | on the boundary? | boundary edge | `fcw` is none | O(1) |
//! | edge | edges of its faces | R11 | walk both faces' cycles from e | O(k) |
//! | face (k-gon) | vertices | R20 | walk the cycle from `af(f)`, the vertex where each edge starts | O(k) |
//! | face (k-gon) | edges | R21 | walk the cycle from `af(f)` | O(k) |
//! | face (k-gon) | neighbour faces | R22 | the other face of each edge | O(k) |
//! | mesh | boundary curves | boundary curves | scan for `fcw` none, then rotate around vertices | O(n) |
//!
//! The vertex rotation runs from `av(v)` in both directions at once until the two walks meet
//! or each reaches a missing face: two independent chains of dependent loads, each half as
//! long (the lab's fairness rule in the docs of [`MeshTopology`](crate::MeshTopology) offers
//! that walk to every structure that walks fans). The answers come in no cyclic order. Timed
//! on the 1M-triangle torus in turns with OpenMesh in one process (`cargo run --release
//! --example fan_sweep`), the two-ended walk made R00 and smoothing faster than the one-way
//! walk, with about the same instructions per vertex (callgrind on the harness's R00 sweep,
//! the command in the `fan_sweep` example's docs).
//!
//! ## Non-manifold input
//!
//! One `av(v)` reaches one fan of faces, so a vertex whose faces form several fans (a bowtie) is
//! refused by [`MeshTopology::from_soup`](crate::MeshTopology::from_soup) with
//! [`Error::NonManifoldVertex`](crate::Error::NonManifoldVertex), as are non-manifold edges and
//! inconsistent orientation.
//!
//! ## Incremental construction (for the 3D convex hull algorithms)
//!
//! [`WingedEdge::new`], [`WingedEdge::add_vertex`], [`WingedEdge::add_face`] (links the new face's
//! wings to the existing edges it shares) and [`WingedEdge::remove_face`]. Adding or removing a
//! face touches only that face's side of its edges: the wings on one side of an edge describe only
//! that side's face. Between calls a vertex may have several fans: gift wrapping adds faces that
//! touch the hull at a vertex only, and removing a face from the middle of a vertex's fan splits it
//! in two. add_face still finds every edge, through an index by end vertices that the first
//! add_face or remove_face builds (O(n) once; it is not part of the hull lecture's record, and
//! structures built by `from_soup`, which pairs edges by sorting, never pay for it). The index also
//! keeps each vertex's edges in a ring (a circular list through the edges' ends), so a vertex whose
//! `av(v)` is removed with a face takes another of its edges in O(1), even one in another fan:
//! removal costs O(k) in any order. While a vertex has several fans the vertex queries see only the
//! fan of `av(v)`, and [`MeshTopology::validate`](crate::MeshTopology::validate) reports the vertex
//! with [`Error::NonManifoldVertex`](crate::Error::NonManifoldVertex).
//!
//! Removed elements are tombstones: a removed face keeps its slot with `af = none`, an edge that
//! loses its last face keeps its slot with every pointer none. add_face and remove_face never reuse
//! ids, so a handle an algorithm holds is either live or detectably dead
//! ([`WingedEdge::is_face_live`]); [`WingedEdge::live_faces`] and
//! [`MeshTopology::for_each_edge`](crate::MeshTopology::for_each_edge) skip tombstones, the counts
//! (`num_faces`, `num_edges`) count live elements, and [`WingedEdge::compact`] closes the gaps and
//! returns the renumbering. When a face is removed from an edge's left side while the right one
//! stays, the edge is turned around (v1 ↔ v2, cw fields moved to ccw) so its remaining face is on
//! its left again. Vertices are never removed; one without edges has `av = none`.
//!
//! ## Editing ([`MeshEdit`](crate::MeshEdit))
//!
//! Every editing operation through one rewrite of the faces it changes (see `edit.rs` for the
//! costs, derived from the polygon-mesh lecture's table); faces and edges leave at once, the
//! last moving into the freed slot; deleted vertices are marked until `garbage_collection`.
//!
//! ## Cone stitching (the incremental hull algorithms' step)
//!
//! [`WingedEdge::replace_by_cone`] removes a disk of faces and adds the cone from a new vertex
//! over its border in one call, in O(faces removed + border edges): the border is walked
//! around each border vertex through the removed faces only, every vertex handle is set
//! directly (a border vertex gets its border edge, a vertex inside the disk none, the apex
//! its first new edge), and the border edges keep their ids with the new face written into
//! the removed face's side. So the bounds of the lecture on 3D convex hulls, which count the
//! faces created and removed, hold by construction. The slots the call frees are reused by
//! the next calls (a hull's slots stay near its live size); regions that are not one disk
//! bounded by one simple cycle are refused before anything changes.

mod edit;
mod editing;
mod records;
mod stitching;
#[cfg(test)]
mod tests;
mod topology;
mod validation;

pub use editing::Renumbering;
pub use stitching::HorizonEdge;

use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::reads::{read, traced};
use glam::DVec3;
use records::{EdgeRecord, IncrementalIndex};

/// The winged-edge records of the lecture on 3D convex hulls; see the module docs.
#[derive(Clone, Debug, Default)]
pub struct WingedEdge {
    /// `positions[v]`: the coordinates of vertex v.
    positions: Vec<DVec3>,
    /// `av[v]`: one edge incident to v (the hull lecture's av(v)); none for a vertex without edges.
    av: Vec<EdgeId>,
    /// `af[f]`: one edge of f's boundary (the hull lecture's af(f)); none for a removed face.
    af: Vec<EdgeId>,
    /// `edges[e]`: e's eight pointers; removed edges are [`EdgeRecord::REMOVED`].
    edges: Vec<EdgeRecord>,
    /// Number of live edges (records that are not removed).
    live_edges: usize,
    /// Number of live faces (`af` not none).
    live_faces: usize,
    /// The incremental API's index, built by its first use.
    index: Option<IncrementalIndex>,
    /// What [`WingedEdge::replace_by_cone`] keeps between calls (marks, free slots).
    stitching: stitching::Stitching,
    /// `deleted[v]`: vertex v was deleted by an edit ([`crate::MeshEdit`]) and keeps its slot
    /// until `garbage_collection`; empty until the first deletion.
    deleted: Vec<bool>,
}

impl WingedEdge {
    /// An empty structure, to be filled with [`WingedEdge::add_vertex`] and
    /// [`WingedEdge::add_face`].
    pub fn new() -> Self {
        Self::default()
    }

    #[inline]
    fn edge(&self, e: EdgeId) -> &EdgeRecord {
        let r = &self.edges[e.index()];
        traced!("E", e.0, *r);
        r
    }

    /// Walks the fan of faces around `v` from its edge `start`: calls `on_edge` once for each
    /// edge and `on_face` once for each face of the fan; returns whether the fan is open (v on
    /// the boundary). Two walks run at once, each until it meets the other (a closed fan) or a
    /// missing face (the boundary): forward, from an edge e to the wing before it in the face
    /// where e leaves v (`pccw` if v = v1, `pcw` if v = v2); backward, to the wing after it in
    /// the face where e enters v (`nccw` if v = v2, `ncw` if v = v1). Two independent chains of
    /// dependent loads instead of one; the answers come in neither walk's order.
    #[inline]
    fn walk_fan(
        &self,
        v: VertexId,
        start: EdgeId,
        mut on_edge: impl FnMut(EdgeId),
        mut on_face: impl FnMut(FaceId),
    ) -> bool {
        // One step from edge e: forward, the face where e leaves v and the wing before e in
        // it; backward, the face where e enters v and the wing after e in it.
        let step = |e: EdgeId, forward: bool| {
            let r = self.edge(e);
            match ((r.v1 == v) == forward, forward) {
                (true, true) => (r.fccw, r.pccw),
                (true, false) => (r.fccw, r.nccw),
                (false, true) => (r.fcw, r.pcw),
                (false, false) => (r.fcw, r.ncw),
            }
        };
        on_edge(start);
        // The edge each walk (forward, backward) reached last; none once it met the boundary.
        let mut reached = [start, start];
        loop {
            for (walk, forward) in [(0, true), (1, false)] {
                if !reached[walk].is_valid() {
                    continue;
                }
                let (face, wing) = step(reached[walk], forward);
                let Some(face) = face.valid() else {
                    reached[walk] = EdgeId::INVALID;
                    continue;
                };
                on_face(face);
                if wing == reached[1 - walk] {
                    return false;
                }
                on_edge(wing);
                reached[walk] = wing;
            }
            if !reached[0].is_valid() && !reached[1].is_valid() {
                return true;
            }
        }
    }

    /// [`WingedEdge::walk_fan`] from `av(v)`; nothing for a vertex without edges.
    #[inline]
    fn walk_star(
        &self,
        v: VertexId,
        on_edge: impl FnMut(EdgeId),
        on_face: impl FnMut(FaceId),
    ) -> bool {
        match read!("av", self.av, v.index()).valid() {
            Some(start) => self.walk_fan(v, start, on_edge, on_face),
            None => false,
        }
    }

    /// Calls `f` with each edge of face `face` in its cycle, from `af(face)`.
    #[inline]
    fn walk_face(&self, face: FaceId, mut f: impl FnMut(EdgeId, &EdgeRecord)) {
        let Some(start) = self.af.get(face.index()).and_then(|e| e.valid()) else {
            return;
        };
        traced!("af", face.0, start);
        let mut e = start;
        loop {
            let r = self.edge(e);
            f(e, r);
            match r.next_in(face) {
                Some(next) if next != start => e = next,
                _ => return,
            }
        }
    }

    /// Is `f` a face that exists (added and not removed)?
    pub fn is_face_live(&self, f: FaceId) -> bool {
        self.af.get(f.index()).is_some_and(|e| e.is_valid())
    }

    /// Every live face, in increasing id order.
    pub fn live_faces(&self) -> impl Iterator<Item = FaceId> + '_ {
        (0..self.af.len())
            .map(FaceId::new)
            .filter(|&f| self.is_face_live(f))
    }

    /// Number of face slots, live or removed: face ids run below it.
    pub fn face_slots(&self) -> usize {
        self.af.len()
    }

    /// Number of edge slots, live or removed: edge ids run below it.
    pub fn edge_slots(&self) -> usize {
        self.edges.len()
    }
}
