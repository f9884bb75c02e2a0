//! Replacing a disk of faces by a cone over its border, in one step: the incremental hull
//! algorithms' "remove the visible faces, add a face for each horizon edge" (the lecture on
//! 3D convex hulls, `Incremental3D`, lines 8–12). See "Cone stitching" in the module docs.

use super::records::EdgeRecord;
use super::WingedEdge;
use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::topology::MeshTopology;

/// One edge of the border of a region replaced by [`WingedEdge::replace_by_cone`], in the
/// order of the border's cycle, and the faces on each of its sides before and after.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct HorizonEdge {
    /// The edge (it stays, with its id).
    pub edge: EdgeId,
    /// Where the removed face entered the edge; also where the previous horizon edge ends.
    pub a: VertexId,
    /// Where the removed face left the edge; also where the next horizon edge starts.
    pub b: VertexId,
    /// The region's face on this edge, now removed.
    pub removed: FaceId,
    /// The face on the other side, kept.
    pub kept: FaceId,
    /// The cone face (a, b, apex) that replaced `removed` on this edge.
    pub created: FaceId,
}

/// What [`WingedEdge::replace_by_cone`] keeps between calls, so a call allocates nothing once
/// the buffers have grown: marks that tell a call's region faces and border vertices (a mark
/// equal to the call's number; older numbers mean unmarked, so no clearing), and the slots
/// that earlier calls freed.
#[derive(Clone, Debug, Default)]
pub(super) struct Stitching {
    /// `face_mark[f] == call`: f is in the current region.
    face_mark: Vec<u32>,
    /// `vertex_mark[v] == call`: v is on the current border.
    vertex_mark: Vec<u32>,
    /// The current call's number (never 0, the initial mark).
    call: u32,
    /// The current region's interior edges (both faces in the region).
    interior: Vec<EdgeId>,
    /// The current cone's edges to the apex, `spokes[i]` from the start of horizon edge i.
    spokes: Vec<EdgeId>,
    /// Face slots freed by earlier calls, reused by the next cones.
    pub(super) free_faces: Vec<FaceId>,
    /// Edge slots freed by earlier calls, reused by the next cones.
    pub(super) free_edges: Vec<EdgeId>,
}

impl Stitching {
    /// Starts a call over `faces` face slots and `vertices` vertices.
    fn start(&mut self, faces: usize, vertices: usize) {
        self.call = self.call.wrapping_add(1);
        if self.call == 0 {
            // After 2³² calls the numbers come round: forget every old mark once.
            self.face_mark.fill(0);
            self.vertex_mark.fill(0);
            self.call = 1;
        }
        if self.face_mark.len() < faces {
            self.face_mark.resize(faces, 0);
        }
        if self.vertex_mark.len() < vertices {
            self.vertex_mark.resize(vertices, 0);
        }
    }

    #[inline]
    fn in_region(&self, f: FaceId) -> bool {
        self.face_mark.get(f.index()) == Some(&self.call)
    }

    /// Heap bytes of the buffers.
    pub(super) fn heap_bytes(&self) -> usize {
        (self.face_mark.capacity()
            + self.vertex_mark.capacity()
            + self.interior.capacity()
            + self.spokes.capacity()
            + self.free_faces.capacity()
            + self.free_edges.capacity())
            * 4
    }
}

fn refused(message: impl std::fmt::Display) -> Error {
    Error::Unsupported(format!(
        "{}: cannot replace the region by a cone: {message}",
        WingedEdge::NAME
    ))
}

impl WingedEdge {
    /// Replaces the faces `region` by the cone from `apex` over the region's border: each
    /// border edge a → b (as the region's face ran it) keeps its id and gets the new face
    /// (a, b, apex) in place of the removed one, with a new edge from each border vertex to
    /// the apex. `horizon` receives the border edges in the order of the cycle
    /// ([`HorizonEdge`]: edge i ends where edge i + 1 starts).
    ///
    /// Cost O(r + m) for r region faces (their edges) and m border edges, whatever the
    /// faces' order: the border is found by walking around each border vertex through the
    /// region's faces only, and every vertex handle is set directly (a border vertex gets its
    /// border edge, an inner vertex of the region, which loses all its edges, none, the apex
    /// its first spoke), so no search over the mesh happens.
    ///
    /// The new faces and edges reuse the slots that earlier calls freed (then new slots); the
    /// region's faces and inner edges become tombstones whose slots the next calls reuse, so
    /// ids stay valid until then ([`WingedEdge::add_face`] and [`WingedEdge::remove_face`]
    /// never reuse ids; [`WingedEdge::compact`] forgets the free slots).
    ///
    /// Fails with [`Error::Unsupported`], leaving the structure unchanged, if `region` is
    /// empty, names a face twice or a face that does not exist, is not a disk bounded by one
    /// simple cycle of edges each with a face outside the region (a region touching the
    /// mesh boundary, with a hole, in two pieces, or whose border passes a vertex twice), or
    /// if `apex` is not a vertex without edges.
    pub fn replace_by_cone(
        &mut self,
        region: &[FaceId],
        apex: VertexId,
        horizon: &mut Vec<HorizonEdge>,
    ) -> Result<()> {
        let mut s = std::mem::take(&mut self.stitching);
        let found = self.find_border(&mut s, region, apex, horizon);
        if found.is_ok() {
            self.stitch(&mut s, region, apex, horizon);
        }
        self.stitching = s;
        found
    }

    /// The read-only half of [`WingedEdge::replace_by_cone`]: checks the region, collects
    /// its inner edges into `s.interior` and its border cycle into `horizon`.
    fn find_border(
        &self,
        s: &mut Stitching,
        region: &[FaceId],
        apex: VertexId,
        horizon: &mut Vec<HorizonEdge>,
    ) -> Result<()> {
        horizon.clear();
        s.interior.clear();
        if apex.index() >= self.positions.len() || self.av[apex.index()].is_valid() {
            return Err(refused(format!(
                "the apex {apex:?} is not a vertex without edges"
            )));
        }
        if region.is_empty() {
            return Err(refused("the region is empty"));
        }
        s.start(self.af.len(), self.positions.len());
        for &f in region {
            if !self.is_face_live(f) {
                return Err(refused(format!("{f:?} does not exist")));
            }
            if s.in_region(f) {
                return Err(refused(format!("{f:?} is named twice")));
            }
            s.face_mark[f.index()] = s.call;
        }
        // Every side of every region face: inner (recorded once, from its left face) or on
        // the border. `sides` counts them all, which bounds the walk below.
        let (mut sides, mut border) = (0usize, 0usize);
        let mut first = None;
        let mut open = None;
        for &f in region {
            self.walk_face(f, |e, r| {
                sides += 1;
                let g = r.other_face(f);
                if !g.is_valid() {
                    open.get_or_insert(e);
                } else if s.in_region(g) {
                    if r.fccw == f {
                        s.interior.push(e);
                    }
                } else {
                    border += 1;
                    first.get_or_insert((e, f));
                }
            });
        }
        if let Some(e) = open {
            return Err(refused(format!("{e:?} is on the mesh boundary")));
        }
        let Some((e0, f0)) = first else {
            return Err(refused(
                "the region has no border (it is a whole closed mesh)",
            ));
        };
        // The border cycle: from a border edge a → b of face f, turn around b through the
        // region's faces (the edge after the current one in its face starts at b; across an
        // inner edge, the face on the other side continues) until an edge with a face outside.
        let (mut e, mut f) = (e0, f0);
        let mut steps = 0;
        loop {
            let r = self.edge(e);
            let [a, b] = r.ends_in(f);
            if s.vertex_mark[a.index()] == s.call {
                return Err(refused(format!("the border passes {a:?} twice")));
            }
            s.vertex_mark[a.index()] = s.call;
            horizon.push(HorizonEdge {
                edge: e,
                a,
                b,
                removed: f,
                kept: r.other_face(f),
                created: FaceId::INVALID,
            });
            let broken = || refused("the region's faces do not close around a border vertex");
            let (mut x, mut g) = (r.next_in(f).ok_or_else(broken)?, f);
            loop {
                steps += 1;
                if steps > sides {
                    return Err(broken());
                }
                let rx = self.edge(x);
                let other = rx.other_face(g);
                if !s.in_region(other) {
                    break;
                }
                g = other;
                x = rx.next_in(g).ok_or_else(broken)?;
            }
            (e, f) = (x, g);
            if (e, f) == (e0, f0) {
                break;
            }
            if horizon.len() == border {
                return Err(refused("the border does not close into one cycle"));
            }
        }
        if horizon.len() != border {
            return Err(refused(format!(
                "the border has {border} edges but its cycle {}: more than one border cycle",
                horizon.len()
            )));
        }
        for (what, count) in [
            ("faces", self.af.len() + border),
            ("edges", self.edges.len() + border),
        ] {
            if count >= u32::MAX as usize {
                return Err(Error::TooLarge {
                    what,
                    count: count as u64,
                });
            }
        }
        Ok(())
    }

    /// The changing half of [`WingedEdge::replace_by_cone`], after [`Self::find_border`].
    fn stitch(
        &mut self,
        s: &mut Stitching,
        region: &[FaceId],
        apex: VertexId,
        horizon: &mut [HorizonEdge],
    ) {
        let m = horizon.len();
        for h in horizon.iter_mut() {
            h.created = s.free_faces.pop().unwrap_or_else(|| {
                self.af.push(EdgeId::INVALID);
                FaceId::new(self.af.len() - 1)
            });
        }
        s.spokes.clear();
        for _ in 0..m {
            let e = s.free_edges.pop().unwrap_or_else(|| {
                self.edges.push(EdgeRecord::REMOVED);
                EdgeId::new(self.edges.len() - 1)
            });
            s.spokes.push(e);
        }
        for &e in &s.interior {
            let r = self.edges[e.index()];
            for v in [r.v1, r.v2] {
                // A region vertex off the border loses every edge it had.
                if s.vertex_mark[v.index()] != s.call {
                    self.av[v.index()] = EdgeId::INVALID;
                }
            }
            if let Some(index) = &mut self.index {
                index.unlink(e, r.v1, r.v2);
            }
            self.edges[e.index()] = EdgeRecord::REMOVED;
        }
        // Face F_i = (a_i, b_i, apex) runs h_i, then spoke i + 1 (b_i → apex), then spoke i
        // (apex → a_i). Spoke i runs a_i → apex: on its left F_{i−1}, on its right F_i.
        for i in 0..m {
            let (prev, next) = ((i + m - 1) % m, (i + 1) % m);
            let h = horizon[i];
            let (spoke, spoke_next) = (s.spokes[i], s.spokes[next]);
            self.edges[spoke.index()] = EdgeRecord {
                v1: h.a,
                v2: apex,
                fccw: horizon[prev].created,
                pccw: horizon[prev].edge,
                nccw: s.spokes[prev],
                fcw: h.created,
                pcw: spoke_next,
                ncw: h.edge,
            };
            let r = &mut self.edges[h.edge.index()];
            if r.fccw == h.removed {
                (r.fccw, r.pccw, r.nccw) = (h.created, spoke, spoke_next);
            } else {
                (r.fcw, r.pcw, r.ncw) = (h.created, spoke, spoke_next);
            }
            self.af[h.created.index()] = h.edge;
            self.av[h.a.index()] = h.edge;
            if let Some(index) = &mut self.index {
                index.link(spoke, h.a, apex);
            }
        }
        self.av[apex.index()] = s.spokes[0];
        for &f in region {
            self.af[f.index()] = EdgeId::INVALID;
        }
        s.free_faces.extend_from_slice(region);
        s.free_edges.extend_from_slice(&s.interior);
        self.live_faces = self.live_faces + m - region.len();
        self.live_edges = self.live_edges + m - s.interior.len();
    }
}
