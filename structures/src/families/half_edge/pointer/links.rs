//! The only unsafe code of the crate: the half-edge records of the lecture on polygon-mesh data
//! structures, linked by raw pointers, each record its own heap allocation, and a safe read-only
//! API over them.
//!
//! Soundness rests on three facts, all established here:
//! 1. every record is allocated by [`Records::new`] or the `push_*` methods with
//!    `Box::into_raw`, and its fields are written only there and by the `set_*` methods of the
//!    editing operations, which take `&mut Records`: while they run, no reference to any record
//!    exists (references are handed out only through `&Records`);
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
// SAFETY: records are written only through `&mut Records` (fact 1) and have no interior
// mutability, so shared references from several threads only read.
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
        // SAFETY: a record of `self`, alive until `self` drops, not written while `&self` lives.
        unsafe { &*self.edges[h as usize] }
    }

    /// The record of vertex `v`.
    #[inline(always)]
    pub(super) fn vert(&self, v: u32) -> &HeVert {
        // SAFETY: a record of `self`, alive until `self` drops, not written while `&self` lives.
        unsafe { &*self.verts[v as usize] }
    }

    /// The record of face `f`.
    #[inline(always)]
    pub(super) fn face(&self, f: u32) -> &HeFace {
        // SAFETY: a record of `self`, alive until `self` drops, not written while `&self` lives.
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
            // SAFETY: a record of `self` (from its own table), alive, not written while `&self` lives.
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
            // SAFETY: a record of `self` (from its own table), alive, not written while `&self` lives.
            let v = unsafe { &*record };
            if v.id != i as u32 {
                return Err(format!("vertex record {i} says it is v{}", v.id));
            }
            if !v.edge.is_null() && find(&edges, v.edge).is_none() {
                return Err(format!("v{i}.edge is not a half-edge of this mesh"));
            }
        }
        for (i, &record) in self.faces.iter().enumerate() {
            // SAFETY: a record of `self` (from its own table), alive, not written while `&self` lives.
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
        // (fact 3) and is not written while `&self` lives (fact 1).
        unsafe { &*self.pair }
    }
    /// `next`.
    #[inline(always)]
    pub(super) fn next(&self) -> &HeEdge {
        // SAFETY: as for `pair`: never null, same owner, outlives `&self`, not written while `&self` lives.
        unsafe { &*self.next }
    }
    /// `vert`.
    #[inline(always)]
    pub(super) fn vert(&self) -> &HeVert {
        // SAFETY: as for `pair`: never null, same owner, outlives `&self`, not written while `&self` lives.
        unsafe { &*self.vert }
    }
    /// `face`, `None` for a boundary half-edge.
    #[inline(always)]
    pub(super) fn face(&self) -> Option<&HeFace> {
        // SAFETY: null or a record of the same owner, which outlives `&self`, not written while `&self` lives.
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
        // SAFETY: null or a record of the same owner, which outlives `&self`, not written while `&self` lives.
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
        // SAFETY: never null, a record of the same owner, which outlives `&self`, not written while `&self` lives.
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

/// Writes through `&mut Records` for the editing operations. Each takes ids of records of
/// `self` (in range: the callers are the checked operations) and writes one field.
impl Records {
    /// `h.next = n`.
    pub(super) fn set_next(&mut self, h: u32, n: u32) {
        let target = self.edges[n as usize];
        // SAFETY: `&mut self` is exclusive, so no reference to any record is alive (fact 1);
        // the record belongs to `self`, and `target` is a record of `self` (fact 2).
        unsafe { (*self.edges[h as usize]).next = target };
    }
    /// `h.vert = v`.
    pub(super) fn set_vert(&mut self, h: u32, v: u32) {
        let target = self.verts[v as usize];
        // SAFETY: as in `set_next`.
        unsafe { (*self.edges[h as usize]).vert = target };
    }
    /// `h.face = f` (null for [`NONE`]).
    pub(super) fn set_face(&mut self, h: u32, f: u32) {
        let target = link(&self.faces, f);
        // SAFETY: as in `set_next`; null is allowed for `face`.
        unsafe { (*self.edges[h as usize]).face = target };
    }
    /// `v.edge = h` (null for [`NONE`]).
    pub(super) fn set_vert_edge(&mut self, v: u32, h: u32) {
        let target = link(&self.edges, h);
        // SAFETY: as in `set_next`; null is allowed for a vertex's `edge`.
        unsafe { (*self.verts[v as usize]).edge = target };
    }
    /// `f.edge = h`.
    pub(super) fn set_face_edge(&mut self, f: u32, h: u32) {
        let target = self.edges[h as usize];
        // SAFETY: as in `set_next`.
        unsafe { (*self.faces[f as usize]).edge = target };
    }
    /// Moves vertex `v` to `p`.
    pub(super) fn set_position(&mut self, v: u32, p: DVec3) {
        let record = self.verts[v as usize];
        // SAFETY: as in `set_next`.
        unsafe {
            (*record).x = p.x;
            (*record).y = p.y;
            (*record).z = p.z;
        }
    }
    /// A new vertex record at `p` with no edge; its id.
    pub(super) fn push_vert(&mut self, p: DVec3) -> u32 {
        let id = self.verts.len() as u32;
        self.verts.push(boxed(HeVert {
            x: p.x,
            y: p.y,
            z: p.z,
            edge: ptr::null(),
            id,
        }));
        id
    }
    /// Two new half-edge records, `h` (returned) from `a` to `b` and `h + 1` back, each
    /// other's `pair`, each its own `next` until the caller links them, with no face.
    pub(super) fn push_edge_pair(&mut self, a: u32, b: u32) -> u32 {
        let h = self.edges.len() as u32;
        for (id, v) in [(h, a), (h + 1, b)] {
            let vert = self.verts[v as usize];
            self.edges.push(boxed(HeEdge {
                vert,
                pair: ptr::null(),
                face: ptr::null(),
                next: ptr::null(),
                id,
            }));
        }
        let (x, y) = (self.edges[h as usize], self.edges[h as usize + 1]);
        // SAFETY: both records were just allocated by `self`; no reference to them exists.
        unsafe {
            (*x).pair = y;
            (*y).pair = x;
            (*x).next = x;
            (*y).next = y;
        }
        h
    }
    /// A new face record whose edge is `h`; its id.
    pub(super) fn push_face(&mut self, h: u32) -> u32 {
        let id = self.faces.len() as u32;
        let edge = self.edges[h as usize];
        self.faces.push(boxed(HeFace { edge, id }));
        id
    }
    /// Room in the id tables.
    pub(super) fn reserve(&mut self, vertices: usize, edges: usize, faces: usize) {
        self.verts.reserve(vertices);
        self.edges.reserve(2 * edges);
        self.faces.reserve(faces);
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
