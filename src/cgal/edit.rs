//! [`MeshEdit`] for CGAL's `Surface_mesh` ([`SurfaceMesh`]) through CGAL's Euler operations,
//! one C function each (`cgal/edit.h`, `cgal/edit_surface_mesh.cpp`): `Euler::add_face`,
//! `Euler::remove_face` (keeping the vertices it isolates), `Euler::flip_edge`,
//! `Euler::split_edge` followed by `Euler::split_face` on each side (the 2-to-4 split),
//! `Euler::add_center_vertex`, `Euler::collapse_edge` after `does_satisfy_link_condition`,
//! and `Euler::split_vertex` followed by two `Euler::split_face` (OpenMesh's vertex split).
//! The first edit switches `Surface_mesh`'s recycling of removed slots off, so new elements
//! are appended and removed ones keep their slots, marked ([`Deletion::Marked`], CGAL's
//! `is_removed`).
//!
//! Every check runs in C++ before CGAL is called, so a refused edit changes nothing and no
//! CGAL precondition is violated: the lab's rules (the half-edge family's) and CGAL's own
//! `does_satisfy_link_condition`. Ids: `Surface_mesh`'s indices, as for the queries (edge `e`
//! has halfedges `2e` and `2e + 1`).
//!
//! Garbage collection keeps the survivors' order, as [`MeshEdit`] promises; `collect_garbage`
//! fills each hole with the last live element, so the shim builds the mesh again from its live
//! elements in order (O(n), like the half-edge family's own collection). The changing
//! workloads call `collect_garbage` itself, as the benchmark does.
//!
//! `Polyhedron_3` has no `MeshEdit` here: it erases elements from its lists at once, so the
//! lab's stable ids with marked deletions would be tables kept beside it, not CGAL's.
//!
//! | operation | CGAL's calls | cost |
//! |---|---|---|
//! | add vertex | `add_vertex` | O(1) |
//! | add face | `halfedge(a, b)` per side (checks), `Euler::add_face` | O(k) |
//! | delete face | fan check per corner, `Euler::remove_face` | O(k) |
//! | delete vertex | fan check per neighbour, `remove_face` per face, `remove_vertex` | O(k) |
//! | flip edge | `halfedge(x, y)`, `Euler::flip_edge` | O(k) |
//! | split edge | `Euler::split_edge`, `Euler::split_face` twice | O(1) |
//! | split face | `Euler::add_center_vertex` | O(k) |
//! | collapse edge | the link condition (O(k²), declared O(k) as for the half-edges), `does_satisfy_link_condition`, `Euler::collapse_edge` | O(k) |
//! | split vertex | `Euler::split_vertex` (O(k)), `Euler::split_face` twice | O(k) |
//! | garbage collection | rebuild from the live elements in order | O(n) |

use super::SurfaceMesh;
use super::{status, Cgal, SurfaceMeshClass, LIBRARY};
use crate::foreign;
use glam::DVec3;
use topolab_structures::{
    Cost, Deletion, EdgeId, EditOp, Error, FaceId, MeshEdit, MeshTopology, Refusal, Result,
    VertexId,
};

mod ffi {
    use super::super::ffi::RawMesh;

    // The declarations of `cgal/edit.h`; all `noexcept` in C++, catching every exception.
    extern "C" {
        pub fn topolab_cgal_sm_edit_add_vertex(
            mesh: *mut RawMesh,
            p: *const f64,
            out: *mut u32,
        ) -> i32;
        pub fn topolab_cgal_sm_edit_set_position(
            mesh: *mut RawMesh,
            v: u32,
            p: *const f64,
            refusal: *mut i32,
        ) -> i32;
        pub fn topolab_cgal_sm_edit_add_face(
            mesh: *mut RawMesh,
            vertices: *const u32,
            n: u32,
            refusal: *mut i32,
            out: *mut u32,
        ) -> i32;
        pub fn topolab_cgal_sm_edit_delete_face(
            mesh: *mut RawMesh,
            f: u32,
            refusal: *mut i32,
        ) -> i32;
        pub fn topolab_cgal_sm_edit_delete_vertex(
            mesh: *mut RawMesh,
            v: u32,
            refusal: *mut i32,
        ) -> i32;
        pub fn topolab_cgal_sm_edit_flip(mesh: *mut RawMesh, e: u32, refusal: *mut i32) -> i32;
        pub fn topolab_cgal_sm_edit_split_edge(
            mesh: *mut RawMesh,
            e: u32,
            p: *const f64,
            refusal: *mut i32,
            out: *mut u32,
        ) -> i32;
        pub fn topolab_cgal_sm_edit_split_face(
            mesh: *mut RawMesh,
            f: u32,
            p: *const f64,
            refusal: *mut i32,
            out: *mut u32,
        ) -> i32;
        pub fn topolab_cgal_sm_edit_collapse(
            mesh: *mut RawMesh,
            from: u32,
            to: u32,
            refusal: *mut i32,
        ) -> i32;
        pub fn topolab_cgal_sm_edit_split_vertex(
            mesh: *mut RawMesh,
            v: u32,
            p: *const f64,
            left: u32,
            right: u32,
            refusal: *mut i32,
            out: *mut u32,
        ) -> i32;
        pub fn topolab_cgal_sm_edit_is_deleted(
            mesh: *const RawMesh,
            kind: i32,
            id: u32,
            out: *mut i32,
        ) -> i32;
        pub fn topolab_cgal_sm_edit_garbage_collection(mesh: *mut RawMesh) -> i32;
        pub fn topolab_cgal_sm_edit_reserve(
            mesh: *mut RawMesh,
            vertices: u32,
            edges: u32,
            faces: u32,
        ) -> i32;
    }
}

/// `TOPOLAB_CGAL_EDIT_REFUSED` of `cgal/edit.h`.
const EDIT_REFUSED: i32 = 5;

/// The `TOPOLAB_CGAL_REFUSAL_` codes of `cgal/edit.h`, in their order.
const REFUSALS: [Refusal; 10] = [
    Refusal::NoSuchElement,
    Refusal::BadFace,
    Refusal::NonManifoldEdge,
    Refusal::NonManifoldVertex,
    Refusal::NotTriangles,
    Refusal::BoundaryEdge,
    Refusal::EdgeExists,
    Refusal::NotNeighbours,
    Refusal::LinkCondition,
    Refusal::NotImplemented,
];

/// `Surface_mesh`'s indices are `uint32_t`, the largest one its null index.
const MAX_ELEMENTS: u64 = u32::MAX as u64 - 1;

fn refused(op: EditOp, reason: Refusal) -> Error {
    Error::EditRefused {
        structure: SurfaceMesh::NAME,
        op,
        reason,
    }
}

impl Cgal<SurfaceMeshClass> {
    /// The lab's result of an edit's status: a refusal becomes [`Error::EditRefused`] with its
    /// reason, a failure [`Error::Foreign`]; the counts are read again either way (a failure
    /// may have left part of an edit done, which CGAL does not undo).
    fn edited(&mut self, op: EditOp, call: &'static str, code: i32, refusal: i32) -> Result<()> {
        self.refresh_counts()?;
        if code == EDIT_REFUSED {
            let reason = usize::try_from(refusal)
                .ok()
                .and_then(|r| REFUSALS.get(r).copied())
                .ok_or(Error::Foreign {
                    library: LIBRARY,
                    call,
                    reason: "an unknown refusal code",
                })?;
            return Err(refused(op, reason));
        }
        status(call, code)
    }

    /// Refuses growth past `Surface_mesh`'s indices.
    fn room(&self, vertices: u64, edges: u64, faces: u64) -> Result<()> {
        for (what, now, more) in [
            ("vertices", self.vertices, vertices),
            ("edges", self.edges, edges),
            ("faces", self.faces, faces),
        ] {
            if now as u64 + more > MAX_ELEMENTS {
                return Err(Error::TooLarge {
                    what,
                    count: now as u64 + more,
                });
            }
        }
        Ok(())
    }

    fn is_deleted(&self, kind: i32, id: u32) -> bool {
        let mut out = 0;
        // SAFETY: `raw` is live; the shim checks `kind` and `id`; `out` is a valid out-pointer.
        let code =
            unsafe { ffi::topolab_cgal_sm_edit_is_deleted(self.raw.as_ptr(), kind, id, &mut out) };
        foreign::infallible(LIBRARY, "topolab_cgal_sm_edit_is_deleted", code);
        out != 0
    }

    /// A call that returns a new vertex: `f(refusal, out)` gives the status.
    fn new_vertex(
        &mut self,
        op: EditOp,
        call: &'static str,
        f: impl FnOnce(*mut i32, *mut u32) -> i32,
    ) -> Result<VertexId> {
        self.room(1, 3, 2)?;
        let (mut refusal, mut out) = (0, u32::MAX);
        let code = f(&mut refusal, &mut out);
        self.edited(op, call, code, refusal)?;
        Ok(VertexId(out))
    }
}

impl MeshEdit for Cgal<SurfaceMeshClass> {
    const DELETION: Deletion = Deletion::Marked;

    fn edit_cost(op: EditOp) -> Cost {
        match op {
            EditOp::AddVertex | EditOp::SplitEdge => Cost::Constant,
            // Welding meshes is the trait's rebuild from the welded face list.
            EditOp::GarbageCollection | EditOp::WeldMeshes => Cost::Linear,
            // Vertex welding is not implemented (refused, as for the lab's half-edges).
            EditOp::AddFace
            | EditOp::WeldVertices
            | EditOp::DeleteFace
            | EditOp::DeleteVertex
            | EditOp::FlipEdge
            | EditOp::SplitFace
            | EditOp::CollapseEdge
            | EditOp::SplitVertex => Cost::Local,
        }
    }

    fn add_vertex(&mut self, p: DVec3) -> Result<VertexId> {
        self.room(1, 0, 0)?;
        let xyz = p.to_array();
        let mut out = u32::MAX;
        // SAFETY: `raw` is live and exclusively borrowed; `xyz` holds 3 doubles; `out` is valid.
        let code = unsafe {
            ffi::topolab_cgal_sm_edit_add_vertex(self.raw.as_ptr(), xyz.as_ptr(), &mut out)
        };
        self.edited(
            EditOp::AddVertex,
            "topolab_cgal_sm_edit_add_vertex",
            code,
            0,
        )?;
        Ok(VertexId(out))
    }

    fn set_position(&mut self, v: VertexId, p: DVec3) -> Result<()> {
        let xyz = p.to_array();
        let mut refusal = 0;
        // SAFETY: `raw` is live and exclusively borrowed; the shim checks `v`; `xyz` holds 3
        // doubles; `refusal` is valid.
        let code = unsafe {
            ffi::topolab_cgal_sm_edit_set_position(
                self.raw.as_ptr(),
                v.0,
                xyz.as_ptr(),
                &mut refusal,
            )
        };
        self.edited(
            EditOp::AddVertex,
            "topolab_cgal_sm_edit_set_position",
            code,
            refusal,
        )
    }

    fn add_face(&mut self, vertices: &[VertexId]) -> Result<FaceId> {
        let n = u32::try_from(vertices.len())
            .map_err(|_| refused(EditOp::AddFace, Refusal::BadFace))?;
        self.room(0, n as u64, 1)?;
        let ids: Vec<u32> = vertices.iter().map(|v| v.0).collect();
        let (mut refusal, mut out) = (0, u32::MAX);
        // SAFETY: `raw` is live and exclusively borrowed; `ids` holds `n` vertex ids, which the
        // shim checks; `refusal` and `out` are valid.
        let code = unsafe {
            ffi::topolab_cgal_sm_edit_add_face(
                self.raw.as_ptr(),
                ids.as_ptr(),
                n,
                &mut refusal,
                &mut out,
            )
        };
        self.edited(
            EditOp::AddFace,
            "topolab_cgal_sm_edit_add_face",
            code,
            refusal,
        )?;
        Ok(FaceId(out))
    }

    fn delete_face(&mut self, f: FaceId) -> Result<()> {
        let mut refusal = 0;
        // SAFETY: `raw` is live and exclusively borrowed; the shim checks `f`.
        let code =
            unsafe { ffi::topolab_cgal_sm_edit_delete_face(self.raw.as_ptr(), f.0, &mut refusal) };
        self.edited(
            EditOp::DeleteFace,
            "topolab_cgal_sm_edit_delete_face",
            code,
            refusal,
        )
    }

    fn delete_vertex(&mut self, v: VertexId) -> Result<()> {
        let mut refusal = 0;
        // SAFETY: `raw` is live and exclusively borrowed; the shim checks `v`.
        let code = unsafe {
            ffi::topolab_cgal_sm_edit_delete_vertex(self.raw.as_ptr(), v.0, &mut refusal)
        };
        self.edited(
            EditOp::DeleteVertex,
            "topolab_cgal_sm_edit_delete_vertex",
            code,
            refusal,
        )
    }

    fn flip_edge(&mut self, e: EdgeId) -> Result<()> {
        let mut refusal = 0;
        // SAFETY: `raw` is live and exclusively borrowed; the shim checks `e`.
        let code = unsafe { ffi::topolab_cgal_sm_edit_flip(self.raw.as_ptr(), e.0, &mut refusal) };
        self.edited(EditOp::FlipEdge, "topolab_cgal_sm_edit_flip", code, refusal)
    }

    fn split_edge(&mut self, e: EdgeId, p: DVec3) -> Result<VertexId> {
        let raw = self.raw.as_ptr();
        let xyz = p.to_array();
        self.new_vertex(
            EditOp::SplitEdge,
            "topolab_cgal_sm_edit_split_edge",
            |refusal, out| {
                // SAFETY: `raw` is live and exclusively borrowed (through `self`); the shim checks
                // `e`; `xyz` holds 3 doubles; `refusal` and `out` are valid.
                unsafe {
                    ffi::topolab_cgal_sm_edit_split_edge(raw, e.0, xyz.as_ptr(), refusal, out)
                }
            },
        )
    }

    fn split_face(&mut self, f: FaceId, p: DVec3) -> Result<VertexId> {
        let raw = self.raw.as_ptr();
        let xyz = p.to_array();
        // A face of k corners gains k edges and k - 1 faces; k is bounded by the edge count.
        self.room(1, self.edges as u64, self.edges as u64)?;
        self.new_vertex(
            EditOp::SplitFace,
            "topolab_cgal_sm_edit_split_face",
            |refusal, out| {
                // SAFETY: as in `split_edge`, with `f` checked by the shim.
                unsafe {
                    ffi::topolab_cgal_sm_edit_split_face(raw, f.0, xyz.as_ptr(), refusal, out)
                }
            },
        )
    }

    fn collapse_edge(&mut self, from: VertexId, to: VertexId) -> Result<()> {
        let mut refusal = 0;
        // SAFETY: `raw` is live and exclusively borrowed; the shim checks both ids.
        let code = unsafe {
            ffi::topolab_cgal_sm_edit_collapse(self.raw.as_ptr(), from.0, to.0, &mut refusal)
        };
        self.edited(
            EditOp::CollapseEdge,
            "topolab_cgal_sm_edit_collapse",
            code,
            refusal,
        )
    }

    fn split_vertex(
        &mut self,
        v: VertexId,
        p: DVec3,
        left: VertexId,
        right: VertexId,
    ) -> Result<VertexId> {
        let raw = self.raw.as_ptr();
        let xyz = p.to_array();
        self.new_vertex(
            EditOp::SplitVertex,
            "topolab_cgal_sm_edit_split_vertex",
            |refusal, out| {
                // SAFETY: as in `split_edge`, with the three ids checked by the shim.
                unsafe {
                    ffi::topolab_cgal_sm_edit_split_vertex(
                        raw,
                        v.0,
                        xyz.as_ptr(),
                        left.0,
                        right.0,
                        refusal,
                        out,
                    )
                }
            },
        )
    }

    fn is_deleted_vertex(&self, v: VertexId) -> bool {
        self.is_deleted(0, v.0)
    }

    fn is_deleted_face(&self, f: FaceId) -> bool {
        self.is_deleted(2, f.0)
    }

    fn garbage_collection(&mut self) {
        // SAFETY: `raw` is live and exclusively borrowed.
        let code = unsafe { ffi::topolab_cgal_sm_edit_garbage_collection(self.raw.as_ptr()) };
        foreign::infallible(LIBRARY, "topolab_cgal_sm_edit_garbage_collection", code);
        // The counts come from the mesh, which a failed rebuild left as it was.
        if let Err(e) = self.refresh_counts() {
            panic!("{e}");
        }
    }

    fn reserve(&mut self, vertices: usize, edges: usize, faces: usize) {
        let clamp = |n: usize| n.min(MAX_ELEMENTS as usize) as u32;
        // SAFETY: `raw` is live and exclusively borrowed.
        let code = unsafe {
            ffi::topolab_cgal_sm_edit_reserve(
                self.raw.as_ptr(),
                clamp(vertices),
                clamp(edges),
                clamp(faces),
            )
        };
        // Reserving is a hint: running out of memory here shows up in the edits that follow.
        let _ = status("topolab_cgal_sm_edit_reserve", code);
    }
}
