//! # Winged-edge structure
//!
//! The lecture's *doppelt verkettete Kantenliste* (winged edge) with the record of seed 004
//! (*arestas aladas*, the 3D convex hull lecture), in the seed's names:
//!
//! - **vertex** v: its coordinates (x, y, z) and `av(v)`, one arbitrary edge incident to v;
//! - **face** f: `af(f)`, one arbitrary edge of f's boundary;
//! - **edge** e: eight pointers, `v1, v2, fccw, fcw, pccw, nccw, pcw, ncw`.
//!
//! | field | meaning (seed 004) | the lecture's column |
//! |---|---|---|
//! | `v1`, `v2` | the two ends; their order gives e its orientation v1 → v2 | Start, End |
//! | `fccw` | the face on the left of e = v1 v2: it runs through e from v1 to v2 in its counter-clockwise cycle | Faces: Left |
//! | `fcw` | the face on the right: it runs through e from v2 to v1; none (`-`, the lecture's `N`) on the boundary | Faces: Right |
//! | `pccw` | the edge before e in `fccw`'s cycle (it ends at v1) | Left Traverse: Pred |
//! | `nccw` | the edge after e in `fccw`'s cycle (it starts at v2) | Left Traverse: Succ |
//! | `pcw` | the edge before e in `fcw`'s cycle (it ends at v2) | Right Traverse: Pred |
//! | `ncw` | the edge after e in `fcw`'s cycle (it starts at v1) | Right Traverse: Succ |
//!
//! "Precede" and "succeed" are in each face's own counter-clockwise cycle on both sides (the
//! seed: *as arestas que precedem e sucedem e na face fcw(e)*; the lecture's example
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
//! About 66 bytes per triangle of a closed triangle mesh (n1 = 1.5 n2, n0 = n2 / 2).
//! Vertices and faces are arrays of one field each; edges are records (array of structs)
//! because every step of a walk reads several fields of the same edge together (which end is
//! the vertex, then that side's face and wing): one cache line per step instead of three or
//! four with one array per field. The seed also stresses that each record has constant size.
//!
//! `EdgeId`: index into `edges`; from a soup, numbered by first appearance (as
//! [`crate::core::soup::Connectivity`] numbers them), v1 → v2 in the order the first face runs.
//!
//! ## Costs
//!
//! As the lecture's table *winged-edge Struktur – Zusammenfassung*, except the vertex rows:
//! the lecture's table scans all n edges for the vertex ("Alle n Kanten nach Ecke absuchen")
//! because its edge list has no pointer from a vertex; seed 004's record has one, `av(v)`, so
//! the vertex star is walked from it through the wings in O(k), and that is what is
//! implemented (the lecture's O(n) scan would ignore a stored field).
//!
//! | given | wanted | operator | how | cost |
//! |---|---|---|---|---|
//! | vertex | outgoing edges | R01 | from `av(v)`, rotate: the wing before e in the face where e leaves v | O(k) |
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
//! ## Non-manifold input
//!
//! One `av(v)` reaches one fan of faces, so a vertex whose faces form several fans (a bowtie)
//! is refused by [`MeshTopology::from_soup`] with [`Error::NonManifoldVertex`], as are
//! non-manifold edges and inconsistent orientation.
//!
//! ## Incremental construction (for the 3D convex hull algorithms)
//!
//! [`WingedEdge::new`], [`WingedEdge::add_vertex`], [`WingedEdge::add_face`] (links the new
//! face's wings to the existing edges it shares) and [`WingedEdge::remove_face`]. Adding or
//! removing a face touches only that face's side of its edges: the wings on one side of an
//! edge describe only that side's face. Between calls a vertex may have several fans (gift
//! wrapping adds faces that touch the hull at a vertex only): add_face still finds every
//! edge, through an index by end vertices that the first add_face or remove_face builds
//! (O(n) once; it is not part of the seed's record, and structures built by `from_soup`,
//! which pairs edges by sorting, never pay for it). While a vertex has several fans the vertex
//! queries see only the fan of `av(v)`, and [`MeshTopology::validate`] reports the vertex
//! with [`Error::NonManifoldVertex`].
//!
//! Removed elements are tombstones: a removed face keeps its slot with `af = none`, an edge
//! that loses its last face keeps its slot with every pointer none. Ids are never reused, so
//! a handle an algorithm holds is either live or detectably dead ([`WingedEdge::is_face_live`]);
//! [`WingedEdge::live_faces`] and [`MeshTopology::for_each_edge`] skip tombstones, the counts
//! (`num_faces`, `num_edges`) count live elements, and [`WingedEdge::compact`] closes the
//! gaps and returns the renumbering. When a face is removed from an edge's left side while
//! the right one stays, the edge is turned around (v1 ↔ v2, cw fields moved to ccw) so its
//! remaining face is on its left again. Vertices are never removed; one without edges has
//! `av = none`.

use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::soup::PolygonSoup;
use crate::core::topology::{BoundaryCurves, Capabilities, Cost, MeshTopology, Operator};
use crate::families::edge_lists::boundary_walk;
use glam::DVec3;
use std::collections::HashMap;
use std::fmt::Write;

/// An edge's eight pointers, in the seed's names (see the module docs for their meaning).
/// `v1 == VertexId::INVALID` marks a removed edge.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
struct EdgeRecord {
    /// First end: e runs v1 → v2.
    v1: VertexId,
    /// Second end.
    v2: VertexId,
    /// The face on the left, running v1 → v2.
    fccw: FaceId,
    /// The face on the right, running v2 → v1; none on the boundary.
    fcw: FaceId,
    /// The edge before e in `fccw`.
    pccw: EdgeId,
    /// The edge after e in `fccw`.
    nccw: EdgeId,
    /// The edge before e in `fcw`.
    pcw: EdgeId,
    /// The edge after e in `fcw`.
    ncw: EdgeId,
}

impl EdgeRecord {
    /// A removed edge: every pointer none.
    const REMOVED: Self = Self {
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
    fn is_live(&self) -> bool {
        self.v1.is_valid()
    }

    /// Is `f` on the left (`Some(true)`), on the right (`Some(false)`) or not a face of e?
    #[inline]
    fn side(&self, f: FaceId) -> Option<bool> {
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
    fn next_in(&self, f: FaceId) -> Option<EdgeId> {
        self.side(f)
            .map(|left| if left { self.nccw } else { self.ncw })
    }

    /// The edge before e in face `f`'s cycle.
    #[inline]
    fn prev_in(&self, f: FaceId) -> Option<EdgeId> {
        self.side(f)
            .map(|left| if left { self.pccw } else { self.pcw })
    }

    /// Where face `f` enters and leaves e: `[v1, v2]` on the left, `[v2, v1]` on the right.
    #[inline]
    fn ends_in(&self, f: FaceId) -> [VertexId; 2] {
        if self.fccw == f {
            [self.v1, self.v2]
        } else {
            [self.v2, self.v1]
        }
    }

    /// The end of e that is not `v`.
    #[inline]
    fn other_end(&self, v: VertexId) -> VertexId {
        if self.v1 == v {
            self.v2
        } else {
            self.v1
        }
    }

    /// The other face than `f` (none on the boundary).
    #[inline]
    fn other_face(&self, f: FaceId) -> FaceId {
        if self.fccw == f {
            self.fcw
        } else {
            self.fccw
        }
    }

    /// Turns the edge around (v1 ↔ v2, the right side's face and wings become the left's),
    /// leaving the right side empty: used when the left face is removed.
    fn turn_right_side_left(&mut self) {
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
fn ends_key(a: VertexId, b: VertexId) -> u64 {
    let (lo, hi) = if a < b { (a.0, b.0) } else { (b.0, a.0) };
    ((lo as u64) << 32) | hi as u64
}

/// What the incremental API keeps beside the seed's records (see the module docs).
#[derive(Clone, Debug, Default)]
struct IncrementalIndex {
    /// Each live edge by its end vertices ([`ends_key`]).
    edge_by_ends: HashMap<u64, EdgeId>,
    /// `degree[v]`: the number of live edges at v, so a vertex that loses the edge `av(v)`
    /// knows whether another one is left without a search.
    degree: Vec<u32>,
}

/// The seed's winged-edge records; see the module docs.
#[derive(Clone, Debug, Default)]
pub struct WingedEdge {
    /// `positions[v]`: the coordinates of vertex v.
    positions: Vec<DVec3>,
    /// `av[v]`: one edge incident to v (the seed's av(v)); none for a vertex without edges.
    av: Vec<EdgeId>,
    /// `af[f]`: one edge of f's boundary (the seed's af(f)); none for a removed face.
    af: Vec<EdgeId>,
    /// `edges[e]`: e's eight pointers; removed edges are [`EdgeRecord::REMOVED`].
    edges: Vec<EdgeRecord>,
    /// Number of live edges (records that are not removed).
    live_edges: usize,
    /// Number of live faces (`af` not none).
    live_faces: usize,
    /// The incremental API's index, built by its first use.
    index: Option<IncrementalIndex>,
}

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

impl WingedEdge {
    /// An empty structure, to be filled with [`WingedEdge::add_vertex`] and
    /// [`WingedEdge::add_face`].
    pub fn new() -> Self {
        Self::default()
    }

    #[inline]
    fn edge(&self, e: EdgeId) -> &EdgeRecord {
        &self.edges[e.index()]
    }

    /// Walks the fan of faces around `v` from its edge `start`: calls `on_edge` once for each
    /// edge and `on_face` once for each face of the fan; returns whether the fan is open (v on
    /// the boundary). Forward, each step goes from an edge e to the wing before it in the face
    /// where e leaves v (`pccw` if v = v1, `pcw` if v = v2); if that face is missing, the walk
    /// resumes from `start` backward, through the wing after it in the face where it enters v.
    fn walk_fan(
        &self,
        v: VertexId,
        start: EdgeId,
        mut on_edge: impl FnMut(EdgeId),
        mut on_face: impl FnMut(FaceId),
    ) -> bool {
        let mut e = start;
        loop {
            on_edge(e);
            let r = self.edge(e);
            let (leaving, before) = if r.v1 == v {
                (r.fccw, r.pccw)
            } else {
                (r.fcw, r.pcw)
            };
            let Some(face) = leaving.valid() else { break };
            on_face(face);
            e = before;
            if e == start {
                return false;
            }
        }
        let mut e = start;
        loop {
            let r = self.edge(e);
            let (entering, after) = if r.v2 == v {
                (r.fccw, r.nccw)
            } else {
                (r.fcw, r.ncw)
            };
            let Some(face) = entering.valid() else {
                return true;
            };
            on_face(face);
            e = after;
            on_edge(e);
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
        match self.av[v.index()].valid() {
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

impl MeshTopology for WingedEdge {
    const NAME: &'static str = "winged-edge";

    fn capabilities() -> Capabilities {
        Capabilities::POLYGONS
    }

    fn cost(op: Operator) -> Cost {
        match op {
            Operator::R00 | Operator::R01 | Operator::R02 | Operator::BoundaryVertex => Cost::Local,
            Operator::R10 | Operator::R12 | Operator::BoundaryEdge => Cost::Constant,
            Operator::EdgeSuccessor | Operator::EdgePredecessor => Cost::Constant,
            Operator::R11 | Operator::R20 | Operator::R21 | Operator::R22 => Cost::Local,
            Operator::BoundaryCurves => Cost::Linear,
        }
    }

    fn from_soup(soup: &PolygonSoup) -> Result<Self> {
        let conn = soup.connectivity()?;
        conn.check_vertex_fans(soup)?;
        let corner_face = |c: usize| conn.corner_face[c] as usize;
        // The edges leaving the corners before and after corner c in its face.
        let wings = |c: usize| {
            let f = corner_face(c);
            (
                EdgeId(conn.corner_edge[soup.prev_corner(c, f)]),
                EdgeId(conn.corner_edge[soup.next_corner(c, f)]),
            )
        };
        let mut edges = Vec::with_capacity(conn.num_edges());
        for &[first, other] in &conn.edge_corners {
            let first = first as usize;
            let (pccw, nccw) = wings(first);
            let mut record = EdgeRecord {
                v1: VertexId(soup.indices()[first]),
                v2: VertexId(soup.indices()[soup.next_corner(first, corner_face(first))]),
                fccw: FaceId::new(corner_face(first)),
                pccw,
                nccw,
                ..EdgeRecord::REMOVED
            };
            if other != u32::MAX {
                let other = other as usize;
                (record.pcw, record.ncw) = wings(other);
                record.fcw = FaceId::new(corner_face(other));
            }
            edges.push(record);
        }
        // av(v): the edge leaving v's last corner; af(f): the edge leaving f's first corner.
        let mut av = vec![EdgeId::INVALID; soup.num_vertices()];
        for (&v, &e) in soup.indices().iter().zip(&conn.corner_edge) {
            av[v as usize] = EdgeId(e);
        }
        let af = (0..soup.num_faces())
            .map(|f| EdgeId(conn.corner_edge[soup.face_start(f)]))
            .collect();
        Ok(Self {
            positions: soup.positions.clone(),
            av,
            af,
            live_edges: edges.len(),
            live_faces: soup.num_faces(),
            edges,
            index: None,
        })
    }

    fn num_vertices(&self) -> usize {
        self.positions.len()
    }
    fn num_edges(&self) -> usize {
        self.live_edges
    }
    fn num_faces(&self) -> usize {
        self.live_faces
    }
    fn for_each_edge(&self, mut f: impl FnMut(EdgeId)) {
        for (e, r) in self.edges.iter().enumerate() {
            if r.is_live() {
                f(EdgeId::new(e));
            }
        }
    }
    fn position(&self, v: VertexId) -> DVec3 {
        self.positions[v.index()]
    }

    fn vertex_vertices(&self, v: VertexId, mut f: impl FnMut(VertexId)) {
        self.walk_star(v, |e| f(self.edge(e).other_end(v)), |_| {});
    }
    fn vertex_edges(&self, v: VertexId, f: impl FnMut(EdgeId)) {
        self.walk_star(v, f, |_| {});
    }
    fn vertex_faces(&self, v: VertexId, f: impl FnMut(FaceId)) {
        self.walk_star(v, |_| {}, f);
    }
    fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2] {
        let r = self.edge(e);
        [r.v1, r.v2]
    }
    fn edge_edges(&self, e: EdgeId, mut f: impl FnMut(EdgeId)) {
        self.edge_faces(e, |face| {
            self.walk_face(face, |x, _| {
                if x != e {
                    f(x);
                }
            })
        });
    }
    fn edge_faces(&self, e: EdgeId, mut f: impl FnMut(FaceId)) {
        let r = self.edge(e);
        f(r.fccw);
        if let Some(right) = r.fcw.valid() {
            f(right);
        }
    }
    fn face_vertices(&self, face: FaceId, mut f: impl FnMut(VertexId)) {
        self.walk_face(face, |_, r| f(r.ends_in(face)[0]));
    }
    fn face_edges(&self, face: FaceId, mut f: impl FnMut(EdgeId)) {
        self.walk_face(face, |e, _| f(e));
    }
    fn face_faces(&self, face: FaceId, mut f: impl FnMut(FaceId)) {
        self.walk_face(face, |_, r| {
            if let Some(other) = r.other_face(face).valid() {
                f(other);
            }
        });
    }
    fn is_boundary_vertex(&self, v: VertexId) -> bool {
        self.walk_star(v, |_| {}, |_| {})
    }
    fn is_boundary_edge(&self, e: EdgeId) -> bool {
        !self.edge(e).fcw.is_valid()
    }
    fn boundary_curves(&self, out: &mut BoundaryCurves) {
        boundary_walk::boundary_curves(self, out);
    }
    fn edge_successor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        self.edges.get(e.index())?.next_in(face)
    }
    fn edge_predecessor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        self.edges.get(e.index())?.prev_in(face)
    }

    fn validate(&self) -> Result<()> {
        self.check_records()?;
        self.check_faces()?;
        self.check_vertices()?;
        self.check_index()
    }

    fn heap_bytes(&self) -> usize {
        let index = self.index.as_ref().map_or(0, |i| {
            // The hash map's buckets (key + value) plus one control byte each.
            i.edge_by_ends.capacity() * (std::mem::size_of::<(u64, EdgeId)>() + 1)
                + i.degree.capacity() * 4
        });
        self.positions.capacity() * std::mem::size_of::<DVec3>()
            + (self.av.capacity() + self.af.capacity()) * 4
            + self.edges.capacity() * std::mem::size_of::<EdgeRecord>()
            + index
    }

    fn explain(&self, w: &mut dyn Write) -> std::fmt::Result {
        let name = |x: u32, prefix: &str| {
            if x == u32::MAX {
                "-".to_string()
            } else {
                format!("{prefix}{x}")
            }
        };
        writeln!(
            w,
            "winged-edge (doppelt verkettete Kantenliste, arestas aladas): seed 004's records"
        )?;
        writeln!(w, "- = none (the lecture's N); pccw/nccw = before/after e in fccw (left face, runs v1 -> v2),")?;
        writeln!(w, "pcw/ncw = before/after e in fcw (right face, runs v2 -> v1), each in the face's own cycle")?;
        writeln!(
            w,
            "vertices: {} (coordinates, av = one incident edge)",
            self.positions.len()
        )?;
        for (v, (p, e)) in self.positions.iter().zip(&self.av).enumerate() {
            writeln!(
                w,
                "  v{v}: ({:.3}, {:.3}, {:.3})  av = {}",
                p.x,
                p.y,
                p.z,
                name(e.0, "e")
            )?;
        }
        writeln!(
            w,
            "faces: {} (af = one edge of the face's cycle)",
            self.live_faces
        )?;
        for (f, e) in self.af.iter().enumerate() {
            writeln!(w, "  f{f}: af = {}", name(e.0, "e"))?;
        }
        writeln!(w, "edges: {}", self.live_edges)?;
        writeln!(
            w,
            "  {:>4}  {:>4} {:>4}  {:>5} {:>5}  {:>5} {:>5} {:>5} {:>5}",
            "e", "v1", "v2", "fccw", "fcw", "pccw", "nccw", "pcw", "ncw"
        )?;
        for (e, r) in self.edges.iter().enumerate() {
            writeln!(
                w,
                "  {:>4}  {:>4} {:>4}  {:>5} {:>5}  {:>5} {:>5} {:>5} {:>5}",
                format!("e{e}"),
                name(r.v1.0, "v"),
                name(r.v2.0, "v"),
                name(r.fccw.0, "f"),
                name(r.fcw.0, "f"),
                name(r.pccw.0, "e"),
                name(r.nccw.0, "e"),
                name(r.pcw.0, "e"),
                name(r.ncw.0, "e"),
            )?;
        }
        writeln!(
            w,
            "all edges of a vertex: rotate from av through the wings, O(k)"
        )
    }
}

/// The incremental index of `edges` over `vertices` vertices (see [`IncrementalIndex`]).
fn build_index(vertices: usize, edges: &[EdgeRecord]) -> IncrementalIndex {
    let mut index = IncrementalIndex {
        edge_by_ends: HashMap::with_capacity(edges.len()),
        degree: vec![0; vertices],
    };
    for (e, r) in edges.iter().enumerate().filter(|(_, r)| r.is_live()) {
        index
            .edge_by_ends
            .insert(ends_key(r.v1, r.v2), EdgeId::new(e));
        index.degree[r.v1.index()] += 1;
        index.degree[r.v2.index()] += 1;
    }
    index
}

/// Incremental construction: see "Incremental construction" in the module docs.
impl WingedEdge {
    /// Adds a vertex without edges and returns its id.
    pub fn add_vertex(&mut self, p: DVec3) -> VertexId {
        self.positions.push(p);
        self.av.push(EdgeId::INVALID);
        if let Some(index) = &mut self.index {
            index.degree.push(0);
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
            });
        }
        let n0 = self.positions.len();
        for (i, &v) in vertices.iter().enumerate() {
            if v.index() >= n0 {
                return Err(Error::IndexOutOfRange {
                    face: face.index(),
                    index: v.0 as i64,
                    vertices: n0,
                });
            }
            if vertices[..i].contains(&v) {
                return Err(Error::RepeatedVertex {
                    face: face.index(),
                    vertex: v.0,
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
                index.edge_by_ends.insert(ends_key(a, b), e);
                index.degree[a.index()] += 1;
                index.degree[b.index()] += 1;
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
    /// face is on its left. The face's slot stays as a tombstone (see the module docs). O(k),
    /// plus a scan of the edges for a vertex that loses the last edge of one fan while it
    /// still has edges in another (only possible between add_face calls that leave several fans).
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
                index.edge_by_ends.remove(&ends_key(a, b));
                for v in [a, b] {
                    index.degree[v.index()] -= 1;
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

    /// A live edge at `v` to replace a removed `av(v)`: none if v has no edges left, else one
    /// of the removed face's surviving edges at v, else (v's other fans) a scan of the edges.
    fn another_edge_at(&self, v: VertexId, cycle: &[EdgeId]) -> EdgeId {
        if self
            .index
            .as_ref()
            .is_some_and(|i| i.degree[v.index()] == 0)
        {
            return EdgeId::INVALID;
        }
        let at_v = |e: &EdgeId| {
            let r = self.edge(*e);
            r.is_live() && (r.v1 == v || r.v2 == v)
        };
        cycle
            .iter()
            .copied()
            .find(at_v)
            .or_else(|| (0..self.edges.len()).map(EdgeId::new).find(at_v))
            .unwrap_or(EdgeId::INVALID)
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
        if let Some(index) = &mut self.index {
            for e in index.edge_by_ends.values_mut() {
                *e = edge(*e);
            }
        }
        Renumbering { faces, edges }
    }
}

/// `validate()`, in four parts.
impl WingedEdge {
    fn broken(message: String) -> Result<()> {
        Err(Error::invariant(Self::NAME, message))
    }

    fn is_edge_live(&self, e: EdgeId) -> bool {
        self.edges.get(e.index()).is_some_and(EdgeRecord::is_live)
    }

    /// Every edge record: ends, faces and wings exist; each wing points back (the edge after
    /// e in f has e before it, and the reverse) and shares the vertex where they meet; a
    /// removed record is fully cleared; no two edges join the same vertices; the live count.
    fn check_records(&self) -> Result<()> {
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
    fn check_faces(&self) -> Result<()> {
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
    fn check_vertices(&self) -> Result<()> {
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
    /// each vertex's edge count.
    fn check_index(&self) -> Result<()> {
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
        if index.degree != self.degrees() {
            return Self::broken("the index's edge counts per vertex are wrong".into());
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::conformance::compare;
    use crate::testing::meshes;

    fn ids(vs: &[u32]) -> Vec<VertexId> {
        vs.iter().map(|&v| VertexId(v)).collect()
    }

    /// The closed tetrahedron's four corners, without faces.
    fn four_vertices() -> WingedEdge {
        let mut m = WingedEdge::new();
        for p in &meshes::closed_tetrahedron().positions {
            m.add_vertex(*p);
        }
        m
    }

    #[test]
    fn records_match_the_lectures_example() {
        // The lecture's P1 = (E5, E4, E1) and P2 = (E2, E4, E3) over V1..V4, 0-based.
        let soup = PolygonSoup::from_polygons(
            vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y],
            &[[0u32, 3, 1], [2, 1, 3]],
        );
        let m = WingedEdge::from_soup(&soup).unwrap();
        // Our edges by first appearance: e0 = E5, e1 = E4, e2 = E1, e3 = E2, e4 = E3.
        let (e, f) = (EdgeId, FaceId);
        // E4 = (4, 2, P1, P2, 5, 1, 2, 3).
        assert_eq!(
            m.edges[1],
            EdgeRecord {
                v1: VertexId(3),
                v2: VertexId(1),
                fccw: f(0),
                fcw: f(1),
                pccw: e(0),
                nccw: e(2),
                pcw: e(3),
                ncw: e(4),
            }
        );
        // E1 = (2, 1, P1, N, 4, 5, N, N).
        assert_eq!(
            m.edges[2],
            EdgeRecord {
                v1: VertexId(1),
                v2: VertexId(0),
                fccw: f(0),
                pccw: e(1),
                nccw: e(0),
                ..EdgeRecord::REMOVED
            }
        );
        m.validate().unwrap();
    }

    #[test]
    fn faces_added_one_by_one_make_the_closed_tetrahedron() {
        let soup = meshes::closed_tetrahedron();
        let mut m = four_vertices();
        // (edges, boundary edges) after each face.
        let expected = [(3, 3), (5, 4), (6, 3), (6, 0)];
        for (j, face) in soup.faces().enumerate() {
            let added = m.add_face(&ids(face)).unwrap();
            assert_eq!(added, FaceId::new(j));
            m.validate()
                .unwrap_or_else(|e| panic!("after face {j}: {e}"));
            assert_eq!((m.num_edges(), m.num_boundary_edges()), expected[j]);
            // Every answer matches the oracle of the faces added so far.
            compare(&m, &soup.with_faces(|g| g <= j)).unwrap();
        }
    }

    #[test]
    fn removing_faces_leaves_tombstones_that_compact_closes() {
        let soup = meshes::closed_tetrahedron();
        let mut m = WingedEdge::from_soup(&soup).unwrap();
        // Without the base it is the open tetrahedron.
        m.remove_face(FaceId(3)).unwrap();
        m.validate().unwrap();
        compare(&m, &meshes::open_tetrahedron()).unwrap();
        // Removing face 0 removes edge {0, 1}, its only edge without another face.
        m.remove_face(FaceId(0)).unwrap();
        m.validate().unwrap();
        assert!(!m.is_face_live(FaceId(0)));
        assert_eq!(
            (m.num_faces(), m.num_edges(), m.face_slots(), m.edge_slots()),
            (2, 5, 4, 6)
        );
        assert_eq!(m.live_faces().collect::<Vec<_>>(), [FaceId(1), FaceId(2)]);
        let err = m.remove_face(FaceId(0)).unwrap_err();
        assert_eq!(err.kind(), "unsupported");
        let renumbering = m.compact();
        m.validate().unwrap();
        assert_eq!((m.face_slots(), m.edge_slots()), (2, 5));
        assert_eq!(renumbering.face(FaceId(0)), None);
        assert_eq!(renumbering.face(FaceId(2)), Some(FaceId(1)));
        assert_eq!(renumbering.edge(EdgeId(0)), None);
        compare(&m, &soup.with_faces(|j| j == 1 || j == 2)).unwrap();
        // Removing every face leaves isolated vertices and no edges.
        m.remove_face(FaceId(0)).unwrap();
        m.remove_face(FaceId(1)).unwrap();
        m.validate().unwrap();
        assert_eq!((m.num_faces(), m.num_edges()), (0, 0));
        assert!(m.av.iter().all(|e| !e.is_valid()));
    }

    #[test]
    fn a_removed_face_can_be_added_again() {
        let mut m = WingedEdge::from_soup(&meshes::closed_tetrahedron()).unwrap();
        m.remove_face(FaceId(1)).unwrap();
        assert_eq!(m.add_face(&ids(&[1, 2, 3])).unwrap(), FaceId(4));
        m.validate().unwrap();
        assert_eq!((m.num_faces(), m.num_boundary_edges()), (4, 0));
    }

    #[test]
    fn refused_faces_leave_the_structure_unchanged() {
        let mut m = four_vertices();
        m.add_face(&ids(&[0, 1, 3])).unwrap();
        let before = m.clone();
        let cases: [(&[u32], &str); 5] = [
            (&[0, 1], "too-few-corners"),
            (&[0, 1, 7], "index-out-of-range"),
            (&[0, 2, 0], "repeated-vertex"),
            // Runs 0 -> 1 like face 0.
            (&[0, 1, 2], "inconsistent-orientation"),
            (&[1, 0, 2], "ok"),
        ];
        for (face, kind) in cases {
            match m.add_face(&ids(face)) {
                Err(e) => {
                    assert_eq!(e.kind(), kind, "{face:?}: {e}");
                    assert_eq!(m.edges, before.edges);
                    assert_eq!(m.af, before.af);
                    m.validate().unwrap();
                }
                Ok(_) => assert_eq!(kind, "ok", "{face:?} was accepted"),
            }
        }
        // Edge {0, 1} now has two faces: a third is refused.
        let err = m.add_face(&ids(&[0, 1, 2])).unwrap_err();
        assert_eq!(err.kind(), "non-manifold-edge", "{err}");
    }

    #[test]
    fn a_vertex_with_two_fans_is_reported_until_a_face_joins_them() {
        let bowtie = meshes::bowtie();
        let mut m = WingedEdge::new();
        for p in &bowtie.positions {
            m.add_vertex(*p);
        }
        m.add_face(&ids(&[0, 2, 1])).unwrap();
        m.add_face(&ids(&[0, 3, 4])).unwrap();
        let err = m.validate().unwrap_err();
        assert!(
            matches!(err, Error::NonManifoldVertex { vertex: 0, fans: 2 }),
            "{err}"
        );
        // The face between the two fans uses edges of both: the index finds them.
        m.add_face(&ids(&[0, 1, 3])).unwrap();
        m.validate().unwrap();
        let mut faces = Vec::new();
        m.vertex_faces(VertexId(0), |f| faces.push(f.0));
        faces.sort_unstable();
        assert_eq!(faces, [0, 1, 2]);
        assert_eq!(m.num_edges(), 7);
    }

    /// `validate()` in the middle of incremental work: fine, or a vertex with several fans
    /// (which add_face and remove_face may leave), never a broken wing. When fine, every answer
    /// matches the oracle of the live faces.
    fn check_intermediate(m: &WingedEdge, soup: &PolygonSoup, live: &[bool], step: &str) {
        match m.validate() {
            Ok(()) => {
                let mut dense = m.clone();
                dense.compact();
                compare(&dense, &soup.with_faces(|j| live[j]))
                    .unwrap_or_else(|e| panic!("{step}: {e}"));
            }
            Err(Error::NonManifoldVertex { .. }) => {}
            Err(e) => panic!("{step}: {e}"),
        }
    }

    #[test]
    fn faces_added_and_removed_in_random_orders_keep_every_invariant() {
        use rand::seq::SliceRandom;
        use rand::SeedableRng;
        for seed in 0..4u64 {
            let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
            let mut order: Vec<u32> = (0..meshes::torus(5, 4).num_faces() as u32).collect();
            order.shuffle(&mut rng);
            // Face j of `soup` is the j-th face added.
            let soup = meshes::torus(5, 4).reorder_faces(&order);
            let mut m = WingedEdge::new();
            soup.positions.iter().for_each(|&p| {
                m.add_vertex(p);
            });
            let mut live = vec![false; soup.num_faces()];
            for (j, face) in soup.faces().enumerate() {
                m.add_face(&ids(face)).unwrap();
                live[j] = true;
                check_intermediate(&m, &soup, &live, &format!("seed {seed}, add {j}"));
            }
            m.validate().unwrap();
            compare(&m, &soup).unwrap();
            let mut removal: Vec<usize> = (0..soup.num_faces()).collect();
            removal.shuffle(&mut rng);
            for j in removal {
                m.remove_face(FaceId::new(j)).unwrap();
                live[j] = false;
                check_intermediate(&m, &soup, &live, &format!("seed {seed}, remove {j}"));
            }
            assert_eq!((m.num_faces(), m.num_edges()), (0, 0));
            assert!(m.av.iter().all(|e| !e.is_valid()));
        }
    }

    #[test]
    fn validate_reports_a_wing_that_does_not_point_back() {
        let mut m = WingedEdge::from_soup(&meshes::closed_tetrahedron()).unwrap();
        m.edges[0].nccw = m.edges[0].pccw;
        let err = m.validate().unwrap_err();
        assert_eq!(err.kind(), "invariant", "{err}");
        let mut m = WingedEdge::from_soup(&meshes::open_tetrahedron()).unwrap();
        m.av[3] = EdgeId(0); // edge 0 joins v0 and v1
        assert_eq!(m.validate().unwrap_err().kind(), "invariant");
        let mut m = WingedEdge::from_soup(&meshes::open_tetrahedron()).unwrap();
        m.live_faces = 4;
        assert_eq!(m.validate().unwrap_err().kind(), "invariant");
    }

    #[test]
    fn heap_bytes_are_the_documented_bytes_per_element() {
        let soup = meshes::torus(6, 5);
        let m = WingedEdge::from_soup(&soup).unwrap();
        let (n0, n1, n2) = (m.num_vertices(), m.num_edges(), m.num_faces());
        assert_eq!(m.heap_bytes(), 28 * n0 + 32 * n1 + 4 * n2);
        // 66 bytes per triangle on a closed triangle mesh, as the module docs say.
        assert_eq!(m.heap_bytes(), 66 * n2);
    }

    #[test]
    fn explain_prints_the_seeds_fields_for_the_open_tetrahedron() {
        let m = WingedEdge::from_soup(&meshes::open_tetrahedron()).unwrap();
        let mut text = String::new();
        m.explain(&mut text).unwrap();
        for field in [
            "v1", "v2", "fccw", "fcw", "pccw", "nccw", "pcw", "ncw", "av = ", "af = ",
        ] {
            assert!(text.contains(field), "{field} missing:\n{text}");
        }
        // Edge 0 runs v0 -> v1 in face 0 = (0, 1, 3), on the boundary: no cw side.
        let row = text
            .lines()
            .find(|l| l.trim_start().starts_with("e0 "))
            .unwrap();
        let fields: Vec<&str> = row.split_whitespace().collect();
        assert_eq!(fields, ["e0", "v0", "v1", "f0", "-", "e2", "e1", "-", "-"]);
    }
}
