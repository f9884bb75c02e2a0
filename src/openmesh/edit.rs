//! [`MeshEdit`] for [`OpenMesh`] through OpenMesh's own operations, one C function each
//! (`openmesh/edit.h`, `openmesh/edit.cpp`): `add_vertex`, `add_face`, `delete_face`,
//! `delete_vertex`, `TriConnectivity::flip` after `is_flip_ok`, the 2-to-4 `split(EdgeHandle,
//! VertexHandle)`, the face split `split(FaceHandle, VertexHandle)`, `collapse` after
//! `is_collapse_ok`, and `vertex_split`. The first edit requests OpenMesh's status attributes,
//! where its deletion marks live ([`Deletion::Marked`], OpenMesh's choice).
//!
//! Every check runs in C++ before OpenMesh is called, so a refused edit changes nothing and
//! OpenMesh never reaches an assertion: the lab's rules (an oriented manifold with one fan per
//! vertex after every edit; pmp's `is_collapse_ok`, which adds the tetrahedron test to
//! OpenMesh's) and OpenMesh's own predicates. Where OpenMesh allows more than the lab (a face
//! making a second fan at a vertex, a deletion splitting a vertex's fan, the collapse that
//! leaves two triangles on three vertices), the edit is refused with the lab's reason.
//!
//! Ids: OpenMesh's handles are indices and it appends new elements, so the new vertex of a
//! split is vertex `num_vertices()` before the call, and `EdgeId` stays OpenMesh's edge index
//! (as for the queries).
//!
//! What OpenMesh cannot do, refused with [`Refusal::NotImplemented`]:
//! - on a PolyMesh (polygon input), the edge flip, the 2-to-4 edge split and the vertex split:
//!   they are `TriConnectivity`'s, and `PolyConnectivity` has none of them (its `split_edge`
//!   inserts a vertex into the edge, turning the triangles beside it into quads);
//! - on a TriMesh, `add_face` with more than three corners (OpenMesh would triangulate it into
//!   several faces), refused as [`Refusal::NotTriangles`].
//!
//! Garbage collection keeps the survivors' order, as [`MeshEdit`] promises; OpenMesh's own
//! `garbage_collection` fills each hole with the last live element, renumbering survivors, so
//! the shim compacts by building the mesh again from its live elements in order (`add_vertex`,
//! `add_face`), O(n) like the half-edge family's own collection. The changing workloads
//! (`topolab_om_changing`) call OpenMesh's `garbage_collection` itself, as the benchmark does.
//!
//! | operation | OpenMesh's call | cost |
//! |---|---|---|
//! | add vertex | `add_vertex` | O(1) |
//! | add face | `find_halfedge` per side (checks), `add_face` | O(k) |
//! | delete face | fan check per corner, `delete_face(f, false)` | O(k) |
//! | delete vertex | fan check per neighbour, `delete_vertex(v, false)` | O(k) |
//! | flip edge | `find_halfedge`, `is_flip_ok`, `flip` | O(k) |
//! | split edge | `add_vertex`, `split(e, v)` | O(1) |
//! | split face | `add_vertex`, `split(f, v)` | O(k) |
//! | collapse edge | the link condition (O(k²), declared O(k) as for the half-edges), `is_collapse_ok`, `collapse` | O(k) |
//! | split vertex | `add_vertex`, `vertex_split` | O(k) |
//! | garbage collection | rebuild from the live elements in order | O(n) |

use super::{status, OpenMesh};
use crate::foreign;
use glam::DVec3;
use topolab_structures::{
    Cost, Deletion, EdgeId, EditOp, Error, FaceId, MeshEdit, MeshTopology, Refusal, Result,
    VertexId,
};

mod ffi {
    use super::super::ffi::RawMesh;

    // The declarations of `openmesh/edit.h`; all `noexcept` in C++, catching every exception.
    extern "C" {
        pub fn topolab_om_edit_add_vertex(mesh: *mut RawMesh, p: *const f64, out: *mut u32) -> i32;
        pub fn topolab_om_edit_set_position(
            mesh: *mut RawMesh,
            v: u32,
            p: *const f64,
            refusal: *mut i32,
        ) -> i32;
        pub fn topolab_om_edit_add_face(
            mesh: *mut RawMesh,
            vertices: *const u32,
            n: u32,
            refusal: *mut i32,
            out: *mut u32,
        ) -> i32;
        pub fn topolab_om_edit_delete_face(mesh: *mut RawMesh, f: u32, refusal: *mut i32) -> i32;
        pub fn topolab_om_edit_delete_vertex(mesh: *mut RawMesh, v: u32, refusal: *mut i32) -> i32;
        pub fn topolab_om_edit_flip(mesh: *mut RawMesh, e: u32, refusal: *mut i32) -> i32;
        pub fn topolab_om_edit_split_edge(
            mesh: *mut RawMesh,
            e: u32,
            p: *const f64,
            refusal: *mut i32,
            out: *mut u32,
        ) -> i32;
        pub fn topolab_om_edit_split_face(
            mesh: *mut RawMesh,
            f: u32,
            p: *const f64,
            refusal: *mut i32,
            out: *mut u32,
        ) -> i32;
        pub fn topolab_om_edit_collapse(
            mesh: *mut RawMesh,
            from: u32,
            to: u32,
            refusal: *mut i32,
        ) -> i32;
        pub fn topolab_om_edit_split_vertex(
            mesh: *mut RawMesh,
            v: u32,
            p: *const f64,
            left: u32,
            right: u32,
            refusal: *mut i32,
            out: *mut u32,
        ) -> i32;
        pub fn topolab_om_edit_is_deleted(
            mesh: *const RawMesh,
            kind: i32,
            id: u32,
            out: *mut i32,
        ) -> i32;
        pub fn topolab_om_edit_garbage_collection(mesh: *mut RawMesh) -> i32;
        pub fn topolab_om_edit_reserve(
            mesh: *mut RawMesh,
            vertices: u32,
            edges: u32,
            faces: u32,
        ) -> i32;
    }
}

/// `TOPOLAB_OM_EDIT_REFUSED` of `openmesh/edit.h`.
const EDIT_REFUSED: i32 = 5;

/// The `TOPOLAB_OM_REFUSAL_` codes of `openmesh/edit.h`, in their order.
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

/// OpenMesh's handles are `int`s: no element count may pass `i32::MAX`.
const MAX_ELEMENTS: u64 = i32::MAX as u64;

fn refused(op: EditOp, reason: Refusal) -> Error {
    Error::EditRefused {
        structure: OpenMesh::NAME,
        op,
        reason,
    }
}

impl OpenMesh {
    /// The lab's result of an edit's status: a refusal becomes [`Error::EditRefused`] with its
    /// reason, a failure [`Error::Foreign`]; the counts are read again either way (a failure
    /// may have left part of an edit done, which OpenMesh does not undo).
    fn edited(&mut self, op: EditOp, call: &'static str, code: i32, refusal: i32) -> Result<()> {
        self.refresh_counts()?;
        if code == EDIT_REFUSED {
            let reason = usize::try_from(refusal)
                .ok()
                .and_then(|r| REFUSALS.get(r).copied())
                .ok_or(Error::Foreign {
                    library: "OpenMesh",
                    call,
                    reason: "an unknown refusal code",
                })?;
            return Err(refused(op, reason));
        }
        status(call, code)
    }

    /// Reads the element counts from the mesh.
    fn refresh_counts(&mut self) -> Result<()> {
        let mut summary = [0u32; 4];
        // SAFETY: `raw` is live; `summary` has the 4 slots the shim fills.
        status("topolab_om_summary", unsafe {
            super::ffi::topolab_om_summary(self.raw.as_ptr(), summary.as_mut_ptr())
        })?;
        (self.vertices, self.edges, self.faces) = (summary[1], summary[2], summary[3]);
        Ok(())
    }

    /// Refuses growth past OpenMesh's `int` handles.
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
            unsafe { ffi::topolab_om_edit_is_deleted(self.raw.as_ptr(), kind, id, &mut out) };
        foreign::infallible("OpenMesh", "topolab_om_edit_is_deleted", code);
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

impl MeshEdit for OpenMesh {
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
        let code =
            unsafe { ffi::topolab_om_edit_add_vertex(self.raw.as_ptr(), xyz.as_ptr(), &mut out) };
        self.edited(EditOp::AddVertex, "topolab_om_edit_add_vertex", code, 0)?;
        Ok(VertexId(out))
    }

    fn set_position(&mut self, v: VertexId, p: DVec3) -> Result<()> {
        let xyz = p.to_array();
        let mut refusal = 0;
        // SAFETY: `raw` is live and exclusively borrowed; the shim checks `v`; `xyz` holds 3
        // doubles; `refusal` is valid.
        let code = unsafe {
            ffi::topolab_om_edit_set_position(self.raw.as_ptr(), v.0, xyz.as_ptr(), &mut refusal)
        };
        self.edited(
            EditOp::AddVertex,
            "topolab_om_edit_set_position",
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
            ffi::topolab_om_edit_add_face(
                self.raw.as_ptr(),
                ids.as_ptr(),
                n,
                &mut refusal,
                &mut out,
            )
        };
        self.edited(EditOp::AddFace, "topolab_om_edit_add_face", code, refusal)?;
        Ok(FaceId(out))
    }

    fn delete_face(&mut self, f: FaceId) -> Result<()> {
        let mut refusal = 0;
        // SAFETY: `raw` is live and exclusively borrowed; the shim checks `f`.
        let code =
            unsafe { ffi::topolab_om_edit_delete_face(self.raw.as_ptr(), f.0, &mut refusal) };
        self.edited(
            EditOp::DeleteFace,
            "topolab_om_edit_delete_face",
            code,
            refusal,
        )
    }

    fn delete_vertex(&mut self, v: VertexId) -> Result<()> {
        let mut refusal = 0;
        // SAFETY: `raw` is live and exclusively borrowed; the shim checks `v`.
        let code =
            unsafe { ffi::topolab_om_edit_delete_vertex(self.raw.as_ptr(), v.0, &mut refusal) };
        self.edited(
            EditOp::DeleteVertex,
            "topolab_om_edit_delete_vertex",
            code,
            refusal,
        )
    }

    fn flip_edge(&mut self, e: EdgeId) -> Result<()> {
        let mut refusal = 0;
        // SAFETY: `raw` is live and exclusively borrowed; the shim checks `e`.
        let code = unsafe { ffi::topolab_om_edit_flip(self.raw.as_ptr(), e.0, &mut refusal) };
        self.edited(EditOp::FlipEdge, "topolab_om_edit_flip", code, refusal)
    }

    fn split_edge(&mut self, e: EdgeId, p: DVec3) -> Result<VertexId> {
        let raw = self.raw.as_ptr();
        let xyz = p.to_array();
        self.new_vertex(
            EditOp::SplitEdge,
            "topolab_om_edit_split_edge",
            |refusal, out| {
                // SAFETY: `raw` is live and exclusively borrowed (through `self`); the shim checks
                // `e`; `xyz` holds 3 doubles; `refusal` and `out` are valid.
                unsafe { ffi::topolab_om_edit_split_edge(raw, e.0, xyz.as_ptr(), refusal, out) }
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
            "topolab_om_edit_split_face",
            |refusal, out| {
                // SAFETY: as in `split_edge`, with `f` checked by the shim.
                unsafe { ffi::topolab_om_edit_split_face(raw, f.0, xyz.as_ptr(), refusal, out) }
            },
        )
    }

    fn collapse_edge(&mut self, from: VertexId, to: VertexId) -> Result<()> {
        let mut refusal = 0;
        // SAFETY: `raw` is live and exclusively borrowed; the shim checks both ids.
        let code =
            unsafe { ffi::topolab_om_edit_collapse(self.raw.as_ptr(), from.0, to.0, &mut refusal) };
        self.edited(
            EditOp::CollapseEdge,
            "topolab_om_edit_collapse",
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
            "topolab_om_edit_split_vertex",
            |refusal, out| {
                // SAFETY: as in `split_edge`, with the three ids checked by the shim.
                unsafe {
                    ffi::topolab_om_edit_split_vertex(
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
        let code = unsafe { ffi::topolab_om_edit_garbage_collection(self.raw.as_ptr()) };
        foreign::infallible("OpenMesh", "topolab_om_edit_garbage_collection", code);
        // The counts come from the mesh, which a failed rebuild left as it was.
        if let Err(e) = self.refresh_counts() {
            panic!("{e}");
        }
    }

    fn reserve(&mut self, vertices: usize, edges: usize, faces: usize) {
        let clamp = |n: usize| n.min(MAX_ELEMENTS as usize) as u32;
        // SAFETY: `raw` is live and exclusively borrowed.
        let code = unsafe {
            ffi::topolab_om_edit_reserve(
                self.raw.as_ptr(),
                clamp(vertices),
                clamp(edges),
                clamp(faces),
            )
        };
        // Reserving is a hint: running out of memory here shows up in the edits that follow.
        let _ = status("topolab_om_edit_reserve", code);
    }
}
