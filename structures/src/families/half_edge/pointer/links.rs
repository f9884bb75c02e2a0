//! The only unsafe code of the crate: the half-edge records of the lecture on polygon-mesh data
//! structures, linked by raw pointers, each record its own heap allocation, and a safe read-only
//! API over them.
//!
//! Soundness rests on three facts, all established here:
//! 1. every record is allocated by [`Records::new`] with `Box::into_raw`, its links are written
//!    once there (before any reference to a record exists), and it is never written again;
//! 2. every non-null link points to a record owned by the same [`Records`] (the arrays it is
//!    built from are validated index arrays), and records are freed only in `Drop`;
//! 3. references to records are handed out only through `&Records`, so each one lives at most
//!    as long as that borrow, and following a link from it yields a record that lives as long.

use crate::families::half_edge::{HalfEdgeArrays, NONE};
use glam::DVec3;
use std::ptr;

/// The lecture's `HE_edge`: one half-edge.
pub(super) struct HeEdge {
    /// Start vertex of the half-edge.
    vert: *const HeVert,
    /// Oppositely oriented adjacent half-edge (never null: boundary edges have a boundary
    /// half-edge).
    pair: *const HeEdge,
    /// Face the half-edge borders; null for a boundary half-edge.
    face: *const HeFace,
    /// Next half-edge around the face (or around the hole, for a boundary half-edge).
    next: *const HeEdge,
    /// Its half-edge id (`2e` or `2e + 1` for edge `e`), to answer queries in the lab's ids.
    id: u32,
}

/// The lecture's `HE_vert`: one vertex (coordinates as `f64`, the lab's precision, where the
/// lecture uses `float`).
pub(super) struct HeVert {
    /// Coordinates.
    x: f64,
    /// Coordinates.
    y: f64,
    /// Coordinates.
    z: f64,
    /// One of the half-edges emanating from the vertex (the boundary one on the boundary);
    /// null for an unused vertex.
    edge: *const HeEdge,
    /// Its vertex id.
    id: u32,
}

/// The lecture's `HE_face`: one face.
pub(super) struct HeFace {
    /// One of the half-edges bordering the face (the one leaving its first corner).
    edge: *const HeEdge,
    /// Its face id.
    id: u32,
}

/// Owner of every record: the tables map ids to records (the way in from an id) and are what
/// `Drop` frees; queries walk from record to record through the links.
pub(super) struct Records {
    /// `verts[v]`: the record of vertex v.
    verts: Vec<*mut HeVert>,
    /// `faces[f]`: the record of face f.
    faces: Vec<*mut HeFace>,
    /// `edges[h]`: the record of half-edge h.
    edges: Vec<*mut HeEdge>,
}

#[cfg(test)]
thread_local! {
    /// Records allocated and not yet freed on this thread, for the tests that check `Drop`.
    pub(super) static LIVE_RECORDS: std::cell::Cell<isize> = const { std::cell::Cell::new(0) };
}

// SAFETY: `Records` owns its records exclusively (like a `Box` per record), so moving it to
// another thread moves that ownership; nothing else points into them.
unsafe impl Send for Records {}
// SAFETY: after `new` the records are never written (fact 1) and have no interior mutability,
// so shared references from several threads only read.
unsafe impl Sync for Records {}

/// Allocates one record.
fn boxed<T>(record: T) -> *mut T {
    #[cfg(test)]
    LIVE_RECORDS.with(|n| n.set(n.get() + 1));
    Box::into_raw(Box::new(record))
}

/// Frees a record made by [`boxed`].
///
/// # Safety
/// `p` came from [`boxed`], has not been freed, and no reference to it is used afterwards.
unsafe fn free<T>(p: *mut T) {
    #[cfg(test)]
    LIVE_RECORDS.with(|n| n.set(n.get() - 1));
    // SAFETY: the caller guarantees `p` is a live allocation of `boxed`, freed once.
    drop(unsafe { Box::from_raw(p) });
}

/// The record of index `i` in `table`, or null for [`NONE`].
fn link<T>(table: &[*mut T], i: u32) -> *const T {
    if i == NONE {
        ptr::null()
    } else {
        table[i as usize]
    }
}

impl Records {
    /// Allocates a record per vertex, face and half-edge and links them as `arrays` says.
    ///
    /// # Panics
    /// If `arrays` holds an index out of range (they come from [`HalfEdgeArrays::from_soup`],
    /// which makes none); the records allocated so far are then freed by `Drop`.
    pub(super) fn new(arrays: &HalfEdgeArrays, positions: &[DVec3]) -> Self {
        let mut records = Self {
            verts: Vec::with_capacity(positions.len()),
            faces: Vec::with_capacity(arrays.face_half_edge.len()),
            edges: Vec::with_capacity(arrays.num_half_edges()),
        };
        for (id, p) in positions.iter().enumerate() {
            records.verts.push(boxed(HeVert {
                x: p.x,
                y: p.y,
                z: p.z,
                edge: ptr::null(),
                id: id as u32,
            }));
        }
        for id in 0..arrays.face_half_edge.len() {
            records.faces.push(boxed(HeFace {
                edge: ptr::null(),
                id: id as u32,
            }));
        }
        for id in 0..arrays.num_half_edges() {
            records.edges.push(boxed(HeEdge {
                vert: ptr::null(),
                pair: ptr::null(),
                face: ptr::null(),
                next: ptr::null(),
                id: id as u32,
            }));
        }
        for (h, &record) in records.edges.iter().enumerate() {
            let (vert, pair, face, next) = (
                link(&records.verts, arrays.vertex[h]),
                link(&records.edges, h as u32 ^ 1),
                link(&records.faces, arrays.face[h]),
                link(&records.edges, arrays.next[h]),
            );
            // SAFETY: `record` came from `Box::into_raw` above and is owned by `records`; no
            // reference to any record exists yet, so this write is the only access.
            unsafe {
                (*record).vert = vert;
                (*record).pair = pair;
                (*record).face = face;
                (*record).next = next;
            }
        }
        for (v, &record) in records.verts.iter().enumerate() {
            let edge = link(&records.edges, arrays.vertex_half_edge[v]);
            // SAFETY: as above: a live record of `records`, written before any reference exists.
            unsafe { (*record).edge = edge };
        }
        for (f, &record) in records.faces.iter().enumerate() {
            let edge = link(&records.edges, arrays.face_half_edge[f]);
            // SAFETY: as above: a live record of `records`, written before any reference exists.
            unsafe { (*record).edge = edge };
        }
        records
    }

    /// Number of vertex, face and half-edge records.
    pub(super) fn counts(&self) -> (usize, usize, usize) {
        (self.verts.len(), self.faces.len(), self.edges.len())
    }

    /// The record of half-edge `h`.
    #[inline(always)]
    pub(super) fn edge(&self, h: u32) -> &HeEdge {
        // SAFETY: a record of `self`, alive until `self` drops, never written after `new`.
        unsafe { &*self.edges[h as usize] }
    }

    /// The record of vertex `v`.
    #[inline(always)]
    pub(super) fn vert(&self, v: u32) -> &HeVert {
        // SAFETY: a record of `self`, alive until `self` drops, never written after `new`.
        unsafe { &*self.verts[v as usize] }
    }

    /// The record of face `f`.
    #[inline(always)]
    pub(super) fn face(&self, f: u32) -> &HeFace {
        // SAFETY: a record of `self`, alive until `self` drops, never written after `new`.
        unsafe { &*self.faces[f as usize] }
    }

    /// Checks, without following any link it has not proven to be one of this mesh's
    /// records, that every record knows its own id and every link is null (where allowed) or
    /// a record of this mesh. After that, a link's target id is the id it reports, so the
    /// shared id-level validation can check the connectivity through the safe API.
    pub(super) fn validate(&self) -> Result<(), String> {
        let (verts, faces, edges) = (
            addresses(&self.verts),
            addresses(&self.faces),
            addresses(&self.edges),
        );
        for (what, sorted) in [("vertex", &verts), ("face", &faces), ("half-edge", &edges)] {
            if sorted.windows(2).any(|w| w[0].0 == w[1].0) {
                return Err(format!("two {what} ids share one record"));
            }
        }
        for (i, &record) in self.edges.iter().enumerate() {
            // SAFETY: a record of `self` (from its own table), alive, never written after `new`.
            let e = unsafe { &*record };
            if e.id != i as u32 {
                return Err(format!("half-edge record {i} says it is h{}", e.id));
            }
            if find(&verts, e.vert).is_none() {
                return Err(format!("h{i}.vert is not a vertex of this mesh"));
            }
            if find(&edges, e.pair).is_none() || find(&edges, e.next).is_none() {
                return Err(format!(
                    "h{i}.pair or h{i}.next is not a half-edge of this mesh"
                ));
            }
            if !e.face.is_null() && find(&faces, e.face).is_none() {
                return Err(format!("h{i}.face is not a face of this mesh"));
            }
        }
        for (i, &record) in self.verts.iter().enumerate() {
            // SAFETY: a record of `self` (from its own table), alive, never written after `new`.
            let v = unsafe { &*record };
            if v.id != i as u32 {
                return Err(format!("vertex record {i} says it is v{}", v.id));
            }
            if !v.edge.is_null() && find(&edges, v.edge).is_none() {
                return Err(format!("v{i}.edge is not a half-edge of this mesh"));
            }
        }
        for (i, &record) in self.faces.iter().enumerate() {
            // SAFETY: a record of `self` (from its own table), alive, never written after `new`.
            let f = unsafe { &*record };
            if f.id != i as u32 {
                return Err(format!("face record {i} says it is f{}", f.id));
            }
            if find(&edges, f.edge).is_none() {
                return Err(format!("f{i}.edge is not a half-edge of this mesh"));
            }
        }
        Ok(())
    }

    /// Bytes of the records and the tables (the allocator's per-allocation overhead, about
    /// 8 to 16 bytes per record with glibc, is not counted).
    pub(super) fn heap_bytes(&self) -> usize {
        use std::mem::size_of;
        self.verts.len() * size_of::<HeVert>()
            + self.faces.len() * size_of::<HeFace>()
            + self.edges.len() * size_of::<HeEdge>()
            + (self.verts.capacity() + self.faces.capacity() + self.edges.capacity())
                * size_of::<usize>()
    }
}

/// The addresses of a table's records, sorted, each with its table index.
fn addresses<T>(table: &[*mut T]) -> Vec<(usize, u32)> {
    let mut sorted: Vec<(usize, u32)> = table
        .iter()
        .enumerate()
        .map(|(i, &p)| (p as usize, i as u32))
        .collect();
    sorted.sort_unstable();
    sorted
}

/// The table index of the record at `p`, if `p` is one of the sorted records.
fn find<T>(sorted: &[(usize, u32)], p: *const T) -> Option<u32> {
    sorted
        .binary_search_by_key(&(p as usize), |x| x.0)
        .ok()
        .map(|i| sorted[i].1)
}

impl HeEdge {
    /// Its half-edge id.
    #[inline(always)]
    pub(super) fn id(&self) -> u32 {
        self.id
    }
    /// `pair`.
    #[inline(always)]
    pub(super) fn pair(&self) -> &HeEdge {
        // SAFETY: never null, a record of the same `Records` (fact 2), which outlives `&self`
        // (fact 3) and is not written after `new` (fact 1).
        unsafe { &*self.pair }
    }
    /// `next`.
    #[inline(always)]
    pub(super) fn next(&self) -> &HeEdge {
        // SAFETY: as for `pair`: never null, same owner, outlives `&self`, never written.
        unsafe { &*self.next }
    }
    /// `vert`.
    #[inline(always)]
    pub(super) fn vert(&self) -> &HeVert {
        // SAFETY: as for `pair`: never null, same owner, outlives `&self`, never written.
        unsafe { &*self.vert }
    }
    /// `face`, `None` for a boundary half-edge.
    #[inline(always)]
    pub(super) fn face(&self) -> Option<&HeFace> {
        // SAFETY: null or a record of the same owner, which outlives `&self`, never written.
        unsafe { self.face.as_ref() }
    }
}

impl HeVert {
    /// Its vertex id.
    #[inline(always)]
    pub(super) fn id(&self) -> u32 {
        self.id
    }
    /// Its coordinates.
    #[inline(always)]
    pub(super) fn position(&self) -> DVec3 {
        DVec3::new(self.x, self.y, self.z)
    }
    /// `edge`, `None` for an unused vertex.
    #[inline(always)]
    pub(super) fn edge(&self) -> Option<&HeEdge> {
        // SAFETY: null or a record of the same owner, which outlives `&self`, never written.
        unsafe { self.edge.as_ref() }
    }
}

impl HeFace {
    /// Its face id.
    #[inline(always)]
    pub(super) fn id(&self) -> u32 {
        self.id
    }
    /// `edge`.
    #[inline(always)]
    pub(super) fn edge(&self) -> &HeEdge {
        // SAFETY: never null, a record of the same owner, which outlives `&self`, never written.
        unsafe { &*self.edge }
    }
}

impl Drop for Records {
    fn drop(&mut self) {
        for &p in &self.edges {
            // SAFETY: made by `boxed` in `new`, each table entry distinct, freed only here.
            unsafe { free(p) };
        }
        for &p in &self.faces {
            // SAFETY: made by `boxed` in `new`, each table entry distinct, freed only here.
            unsafe { free(p) };
        }
        for &p in &self.verts {
            // SAFETY: made by `boxed` in `new`, each table entry distinct, freed only here.
            unsafe { free(p) };
        }
    }
}

#[cfg(test)]
impl Records {
    /// Points `h.next` at half-edge `target`, breaking the mesh on purpose (validation tests).
    pub(super) fn relink_next(&mut self, h: u32, target: u32) {
        let target = self.edges[target as usize];
        // SAFETY: `&mut self` is exclusive, so no reference to any record is alive; the record
        // belongs to `self` and stays allocated.
        unsafe { (*self.edges[h as usize]).next = target };
    }
}
