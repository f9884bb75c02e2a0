//! The randomized incremental algorithm of the lecture on 3D convex hulls (after de Berg et al.,
//! section 11.3), with the conflict graph: expected O(n log n).
//!
//! The points are processed in a uniformly random order (a seeded ChaCha8 permutation, so a
//! run is reproducible). The bipartite conflict graph G links each point p not yet inserted
//! with the faces of the current hull it sees (`Volume6 > 0`):
//!
//! | lecture | here | meaning |
//! |---|---|---|
//! | P_conflito(f) | the conflict graph's list of f | the points that see face f, all of them |
//! | F_conflito(p) | one face p sees (`seen[p]`) and the walk from it | the faces p sees |
//!
//! Inserting pk: the faces pk sees are one connected region of the hull, so one face of
//! F_conflito(pk) and a walk over its neighbours find them all (each neighbour tested once,
//! O(1) per face removed or kept on the border, so O(faces created) in all). The faces in
//! pk's plane (`Volume6 = 0`) next to them are removed too, as in [`super::incremental`]
//! (the degenerate case the lecture excludes). [`WingedEdge::replace_by_cone`] replaces the
//! region by the cone from pk in O(region + horizon). For each horizon edge e, between the
//! removed face f1 and the kept face f2, the cone face f = (e, pk) gets
//! P_conflito(f) ⊆ P(e) = P_conflito(f1) ∪ P_conflito(f2), each candidate tested once with
//! `Volume6` against f's plane ([`super::plane`]). (The inclusion also holds when f1 is only
//! coplanar with pk: the plane of f is turned from f1's plane away from the wedge between f1
//! and f2, or equals f1's plane.) [`super::Work::conflict_work`] counts Σ|P(e)|, the sum the
//! lecture's O(n log n) bounds.
//!
//! Why one face per point is enough: a point q that still sees some face of the hull after
//! pk's insertion sees one of the new faces, and the merges give it that face. The faces q
//! saw form one connected region of the old hull; if q sees a kept face and its face
//! `seen[q]` was removed, a path between them in that region crosses the horizon at an edge
//! e whose removed face f1 and kept face f2 q both sees. The cone face on e is turned from
//! f2's plane towards f1's around e (its outward normal is a combination of theirs with
//! nonnegative weights, since pk is above or on f1's plane and below f2's), so q, above
//! both planes, sees it, and q is in P(e). A face slot freed here is reused later, so
//! `seen[q]` also holds the serial number of the face it names: at q's turn a different
//! number in the slot means the face is gone and q is inside.
//!
//! The graph is flat: every list lives in one pool (a list never changes after its face is
//! created, so it is one slice), lists of removed faces become garbage, and the live lists
//! are slid together when garbage is half of the pool (amortized O(1) per entry). Points are
//! named by their rank in the insertion order and every list is kept in increasing rank, so
//! P(e) is a merge of two sorted lists read front to back.
//! The expected number of faces created is at most 6n − 20 (the lecture's lemma);
//! [`super::Hull`] reports the count.

use super::plane::{reach, round_to_f32, FacePlane, RoundedPlane, TestCount};
use super::predicates::find_simplex;
use super::Work;
use crate::core::error::Result;
use crate::core::ids::{FaceId, VertexId};
use crate::core::topology::MeshTopology;
use crate::families::edge_lists::winged_edge::WingedEdge;
use glam::DVec3;
use rand::seq::SliceRandom;
use rand::SeedableRng;

/// One entry of a conflict list, 16 bytes: a point, by rank and position rounded to `f32`
/// ([`round_to_f32`]). The position is copied into every list that holds the point, so a
/// merge reads its two lists and writes the new one front to back and never jumps to the
/// point's coordinates elsewhere in memory (the lists of a late face are sparse over the
/// ranks, and those jumps were cache misses); the test against a new face is still exact
/// ([`RoundedPlane`] reads the point itself only when the rounding could matter).
#[derive(Copy, Clone, Debug)]
struct Conflict {
    position: [f32; 3],
    rank: u32,
}

/// Filler of the pool's room.
const ROOM: Conflict = Conflict {
    position: [0.0; 3],
    rank: u32::MAX,
};

/// A face that a point sees: its slot and the serial number of the face created there.
#[derive(Copy, Clone, Debug)]
struct Seen {
    face: FaceId,
    serial: u32,
}

/// The conflict graph G, flat (see the module docs).
struct ConflictGraph {
    /// Every list, concatenated, in `pool[..top]`; the rest is room, grown before a merge
    /// so that the merge writes by index without checking for room.
    pool: Vec<Conflict>,
    /// The end of the used part of `pool`.
    top: usize,
    /// `start[f]`: where face slot f's list begins in `pool`.
    start: Vec<usize>,
    /// `len[f]`: the length of face slot f's list (0 for a removed face).
    len: Vec<u32>,
    /// `serial[f]`: the serial number of the face in slot f (faces are numbered as created).
    serial: Vec<u32>,
    /// Faces created so far: the next serial number.
    faces: u32,
    /// Entries of `pool[..top]` in no list (lists of removed faces).
    garbage: usize,
    /// The largest coordinate magnitude of the rounded points ([`reach`]).
    reach: f64,
    /// Scratch of [`ConflictGraph::collect_garbage`]: the live lists as (start, face slot).
    live: Vec<(usize, u32)>,
    /// `seen[q]`: a face that the point of rank q sees while q is outside (see the module
    /// docs for why it stays right).
    seen: Vec<Seen>,
}

impl ConflictGraph {
    /// G for the first hull: the faces' planes by slot, and the points `rest` (input
    /// indices into `points`) by rank.
    fn new(planes: &[FacePlane], points: &[DVec3], rest: &[u32], count: &mut TestCount) -> Self {
        // One bound per face for every point: the largest coordinate magnitude of all.
        let reach_all = points
            .iter()
            .map(|p| p.abs().max_element())
            .fold(0.0, f64::max);
        let bounded: Vec<RoundedPlane> = planes
            .iter()
            .map(|p| p.for_rounded_points(reach_all))
            .collect();
        debug_assert!(planes.len() <= 8, "one bit per face of the first hull");
        // First which faces each point sees (a bit each), then the lists, each in one piece.
        let mut sees = Vec::with_capacity(rest.len());
        let mut len = vec![0u32; planes.len()];
        let mut positions = Vec::with_capacity(rest.len());
        // The points are fetched in random order: a tight loop over a block first, so the
        // fetches overlap, then the tests.
        let mut block = Vec::with_capacity(1024);
        for ranks in rest.chunks(1024) {
            block.clear();
            block.extend(ranks.iter().map(|&k| points[k as usize]));
            for &position in &block {
                let mut bits = 0u8;
                for (f, plane) in bounded.iter().enumerate() {
                    if plane.is_seen_from_point(position, count) {
                        bits |= 1 << f;
                        len[f] += 1;
                    }
                }
                sees.push(bits);
                positions.push(round_to_f32(position));
            }
        }
        let total: usize = len.iter().map(|&l| l as usize).sum();
        let mut start = Vec::with_capacity(planes.len());
        let mut next = 0;
        for &l in &len {
            start.push(next);
            next += l as usize;
        }
        // Room for the lists of the first cones before the first collection.
        let mut pool = vec![ROOM; total + total / 2 + 1024];
        let mut fill = start.clone();
        let nowhere = Seen {
            face: FaceId::INVALID,
            serial: 0,
        };
        let mut seen = vec![nowhere; sees.len()];
        for (rank, (&bits, &position)) in sees.iter().zip(&positions).enumerate() {
            for f in (0..planes.len()).filter(|f| bits & (1 << f) != 0) {
                pool[fill[f]] = Conflict {
                    position,
                    rank: rank as u32,
                };
                fill[f] += 1;
                if !seen[rank].face.is_valid() {
                    seen[rank] = Seen {
                        face: FaceId::new(f),
                        serial: f as u32,
                    };
                }
            }
        }
        ConflictGraph {
            reach: reach(&positions),
            pool,
            top: total,
            start,
            len,
            serial: (0..planes.len() as u32).collect(),
            faces: planes.len() as u32,
            garbage: 0,
            live: Vec::new(),
            seen,
        }
    }

    /// Is the face `seen[rank]` still the one it named when it was set?
    #[inline]
    fn seen_face(&self, rank: usize) -> Option<FaceId> {
        let Seen { face, serial } = self.seen[rank];
        (face.is_valid() && self.serial[face.index()] == serial).then_some(face)
    }

    /// Makes room for `slots` face slots.
    fn cover(&mut self, slots: usize) {
        if self.len.len() < slots {
            self.start.resize(slots, 0);
            self.len.resize(slots, 0);
            self.serial.resize(slots, u32::MAX);
        }
    }

    /// P_conflito(created) from P(e) = P_conflito(removed) ∪ P_conflito(kept): each point of
    /// the merge except `rank` (the point being inserted) that sees `plane`, the new face's
    /// (`exact` gives a point's coordinates by rank, for the tests the filter leaves).
    /// Updates `seen` (see the module docs) and returns |P(e)|.
    // A function of its own (not inlined into `randomized`, where the plane's fields were
    // spilled to the stack) keeps the merge's state in registers.
    #[inline(never)]
    fn fill(
        &mut self,
        [removed, kept, created]: [FaceId; 3],
        rank: u32,
        plane: &RoundedPlane,
        exact: impl Fn(u32) -> DVec3,
        count: &mut TestCount,
    ) -> u64 {
        let serial = self.faces;
        self.faces = self.faces.wrapping_add(1);
        self.serial[created.index()] = serial;
        let range = |f: FaceId| {
            let s = self.start[f.index()];
            (s, s + self.len[f.index()] as usize)
        };
        let ((mut i, i_end), (mut j, j_end)) = (range(removed), range(kept));
        // The new list is at most the union; grow by a quarter at least, not double: the
        // pool is the algorithm's memory (`reserve_exact`: `resize` alone would let the
        // vector double its capacity).
        let room = self.top + (i_end - i) + (j_end - j);
        if room > self.pool.len() {
            let grown = room.max(self.pool.len() + self.pool.len() / 4);
            self.pool.reserve_exact(grown - self.pool.len());
            self.pool.resize(grown, ROOM);
        }
        let start = self.top;
        let mut top = start;
        let to_new = Seen {
            face: created,
            serial,
        };
        let mut merged = 0;
        let mut local = TestCount::default();
        loop {
            // The next point of the union (a point of both lists once).
            let q = match (i < i_end, j < j_end) {
                (true, true) => {
                    let (x, y) = (self.pool[i], self.pool[j]);
                    if x.rank < y.rank {
                        i += 1;
                        x
                    } else {
                        j += 1;
                        i += usize::from(x.rank == y.rank);
                        y
                    }
                }
                (true, false) => {
                    i += 1;
                    self.pool[i - 1]
                }
                (false, true) => {
                    j += 1;
                    self.pool[j - 1]
                }
                (false, false) => break,
            };
            merged += 1;
            if q.rank == rank {
                continue;
            }
            if plane.is_seen_from(q.position, || exact(q.rank), &mut local) {
                self.pool[top] = q;
                top += 1;
                self.seen[q.rank as usize] = to_new;
            }
        }
        count.tests += local.tests;
        count.exact += local.exact;
        self.top = top;
        self.start[created.index()] = start;
        self.len[created.index()] = (top - start) as u32;
        merged
    }

    /// Forgets the list of the removed face f.
    fn free(&mut self, f: FaceId) {
        self.garbage += self.len[f.index()] as usize;
        self.len[f.index()] = 0;
        self.serial[f.index()] = u32::MAX;
    }

    /// Closes the gaps of removed lists once they are half of the pool: the live lists slide
    /// down in place, in the order they lie in the pool, so no second buffer is needed and
    /// each collection copies at most one live entry per entry of garbage it frees.
    fn collect_garbage(&mut self) {
        if self.garbage < 1 << 16 || 2 * self.garbage < self.top {
            return;
        }
        self.live.clear();
        for (f, (&start, &len)) in self.start.iter().zip(&self.len).enumerate() {
            if len > 0 {
                self.live.push((start, f as u32));
            }
        }
        self.live.sort_unstable();
        let mut next = 0;
        for &(start, f) in &self.live {
            let len = self.len[f as usize] as usize;
            if start != next {
                self.pool.copy_within(start..start + len, next);
            }
            self.start[f as usize] = next;
            next += len;
        }
        self.top = next;
        self.garbage = 0;
    }
}

/// The randomized incremental hull of the distinct points `distinct`, in the order of a
/// permutation drawn from `seed`. Returns the hull, the number of faces created and the work.
pub(super) fn randomized(
    points: &[DVec3],
    distinct: &[u32],
    seed: u64,
) -> Result<(WingedEdge, usize, Work)> {
    let mut order = distinct.to_vec();
    order.shuffle(&mut rand_chacha::ChaCha8Rng::seed_from_u64(seed));
    let simplex = find_simplex(points, &order)?;
    let (mut mesh, first) = super::start_with_tetrahedron(points, simplex)?;
    // Points still to insert, in insertion order; a point is named by its rank here.
    let rest: Vec<u32> = order.into_iter().filter(|k| !simplex.contains(k)).collect();
    let at = |v: VertexId| points[v.index()];

    // corners[f]: face slot f's corners, so its plane needs no walk of the winged-edge.
    let mut corners: Vec<[VertexId; 3]> = first.to_vec();
    let plane = |c: &[VertexId; 3]| FacePlane::new(at(c[0]), at(c[1]), at(c[2]));
    let mut count = TestCount::default();
    let planes: Vec<FacePlane> = corners.iter().map(plane).collect();
    let mut graph = ConflictGraph::new(&planes, points, &rest, &mut count);

    let mut work = Work::default();
    let mut created = first.len();
    // tested[f] == stamp: face slot f was tested in the current walk.
    let (mut tested, mut stamp) = (Vec::<u32>::new(), 0u32);
    let mut region = Vec::new();
    let mut horizon = Vec::new();
    for (rank, &k) in rest.iter().enumerate() {
        let Some(f0) = graph.seen_face(rank).filter(|&f| mesh.is_face_live(f)) else {
            continue; // pk sees no face: it is inside P(k−1) or on its boundary.
        };
        let p = points[k as usize];
        // Serial numbers are 32 bits and come round after 2³² faces: a live face that pk
        // sees is right whatever its number, so the number is only a shortcut.
        if !plane(&corners[f0.index()]).is_seen_from(p, &mut count) {
            continue;
        }
        // The region: the faces pk sees or is in the plane of, connected to f0.
        stamp = stamp.checked_add(1).unwrap_or_else(|| {
            tested.fill(0);
            1
        });
        if tested.len() < mesh.face_slots() {
            tested.resize(mesh.face_slots(), 0);
        }
        region.clear();
        region.push(f0);
        tested[f0.index()] = stamp;
        let mut next = 0;
        while next < region.len() {
            let f = region[next];
            next += 1;
            mesh.face_faces(f, |g| {
                if tested[g.index()] != stamp {
                    tested[g.index()] = stamp;
                    if plane(&corners[g.index()]).volume6(p, &mut count) >= 0.0 {
                        region.push(g);
                    }
                }
            });
        }
        let apex = VertexId(k);
        mesh.replace_by_cone(&region, apex, &mut horizon)?;
        created += horizon.len();
        corners.resize(mesh.face_slots(), [VertexId::INVALID; 3]);
        graph.cover(mesh.face_slots());
        for h in &horizon {
            corners[h.created.index()] = [h.a, h.b, apex];
            let cone = FacePlane::new(at(h.a), at(h.b), p).for_rounded_points(graph.reach);
            let faces = [h.removed, h.kept, h.created];
            let exact = |q: u32| points[rest[q as usize] as usize];
            work.conflict_work += graph.fill(faces, rank as u32, &cone, exact, &mut count);
        }
        for &f in &region {
            graph.free(f);
        }
        graph.collect_garbage();
    }
    work.volume6_tests = count.tests;
    work.exact_tests = count.exact;
    Ok((mesh, created, work))
}
