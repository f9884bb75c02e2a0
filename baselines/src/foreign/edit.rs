//! One forwarding layer from [`MeshEdit`] to the edit functions of a C++ library's shim
//! (OpenMesh's `openmesh/edit.h`; CGAL's `cgal/edit.h`, for `Surface_mesh` and
//! `Polyhedron_3`), in the style of petgraph's `delegate_impl`: each library declares its C
//! functions with [`edit_api!`] (one name per operation, the signatures are the layer's) and
//! says how to reach its mesh ([`ForeignEdit`]); [`impl_mesh_edit!`] then writes the
//! `MeshEdit` impl, every method forwarding to one generic function here.
//!
//! The shims share one contract, which this layer relies on:
//! - every function is `noexcept`, catches every C++ exception and returns a status
//!   ([`super::OK`] or a failure of [`super::status`]), or [`EDIT_REFUSED`] with the reason
//!   in `*refusal`, one of the codes of [`REFUSALS`];
//! - every check runs in C++ before the library is called, so a refused edit changes
//!   nothing;
//! - ids are checked by the shim (a refusal [`Refusal::NoSuchElement`]), new elements are
//!   appended (a new vertex is `num_vertices()` before the call) and deleted ones keep their
//!   slots, marked, until the garbage collection ([`Deletion::Marked`]).
//!
//! After every call, refused or not, the counts are read again from the mesh: a failure may
//! have left part of an edit done, which the libraries do not undo.

use super::topology::ForeignMesh;
use super::{status, Call};
use glam::DVec3;
use topolab_structures::{refuse, Cost, EdgeId, EditOp, Error, FaceId, Refusal, Result, VertexId};

/// The shims' status of a refused edit (`TOPOLAB_OM_EDIT_REFUSED`, `TOPOLAB_CGAL_EDIT_REFUSED`).
pub(crate) const EDIT_REFUSED: i32 = 5;

/// The shims' refusal codes (`TOPOLAB_OM_REFUSAL_*`, `TOPOLAB_CGAL_REFUSAL_*`), in their order.
pub(crate) const REFUSALS: [Refusal; 12] = [
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
    Refusal::SameVertex,
    Refusal::TetrahedronTest,
];

/// The element kinds of the shims' `is_deleted`.
const VERTEX: i32 = 0;
const FACE: i32 = 2;

/// `(mesh, position, out)`: a new vertex.
type AddVertex<R> = unsafe extern "C" fn(*mut R, *const f64, *mut u32) -> i32;
/// `(mesh, id, refusal)`: delete, flip or collapse one element.
type OnId<R> = unsafe extern "C" fn(*mut R, u32, *mut i32) -> i32;
/// `(mesh, a, b, refusal)`: collapse `a` into `b`, or weld `b` into `a`.
type OnPair<R> = unsafe extern "C" fn(*mut R, u32, u32, *mut i32) -> i32;
/// `(mesh, id, position, refusal, out)`: split an element at a new vertex.
type SplitAt<R> = unsafe extern "C" fn(*mut R, u32, *const f64, *mut i32, *mut u32) -> i32;

/// The edit functions of one shim, on its mesh type `R` (declared by [`edit_api!`]).
pub(crate) struct EditApi<R> {
    pub(crate) add_vertex: Call<AddVertex<R>>,
    pub(crate) set_position: Call<unsafe extern "C" fn(*mut R, u32, *const f64, *mut i32) -> i32>,
    pub(crate) add_face:
        Call<unsafe extern "C" fn(*mut R, *const u32, u32, *mut i32, *mut u32) -> i32>,
    pub(crate) delete_face: Call<OnId<R>>,
    pub(crate) delete_vertex: Call<OnId<R>>,
    pub(crate) flip: Call<OnId<R>>,
    pub(crate) split_edge: Call<SplitAt<R>>,
    pub(crate) split_face: Call<SplitAt<R>>,
    pub(crate) collapse: Call<OnPair<R>>,
    #[allow(clippy::type_complexity)]
    pub(crate) split_vertex:
        Call<unsafe extern "C" fn(*mut R, u32, *const f64, u32, u32, *mut i32, *mut u32) -> i32>,
    pub(crate) weld: Call<OnPair<R>>,
    pub(crate) is_deleted: Call<unsafe extern "C" fn(*const R, i32, u32, *mut i32) -> i32>,
    pub(crate) garbage_collection: Call<unsafe extern "C" fn(*mut R) -> i32>,
    pub(crate) reserve: Call<unsafe extern "C" fn(*mut R, u32, u32, u32) -> i32>,
}

/// Declares a shim's edit functions (an `extern "C"` block with the layer's signatures, one
/// symbol per operation, in [`EditApi`]'s order) and the constant [`EditApi`] `$api` holding
/// them.
macro_rules! edit_api {
    ($api:ident: $raw:ty = [
        $add_vertex:ident, $set_position:ident, $add_face:ident, $delete_face:ident,
        $delete_vertex:ident, $flip:ident, $split_edge:ident, $split_face:ident,
        $collapse:ident, $split_vertex:ident, $weld:ident, $is_deleted:ident,
        $garbage_collection:ident, $reserve:ident $(,)?
    ]) => {
        // All `noexcept` in C++, catching every exception (see `crate::foreign::edit`).
        extern "C" {
            fn $add_vertex(mesh: *mut $raw, p: *const f64, out: *mut u32) -> i32;
            fn $set_position(mesh: *mut $raw, v: u32, p: *const f64, refusal: *mut i32) -> i32;
            fn $add_face(
                mesh: *mut $raw,
                vertices: *const u32,
                n: u32,
                refusal: *mut i32,
                out: *mut u32,
            ) -> i32;
            fn $delete_face(mesh: *mut $raw, f: u32, refusal: *mut i32) -> i32;
            fn $delete_vertex(mesh: *mut $raw, v: u32, refusal: *mut i32) -> i32;
            fn $flip(mesh: *mut $raw, e: u32, refusal: *mut i32) -> i32;
            fn $split_edge(
                mesh: *mut $raw,
                e: u32,
                p: *const f64,
                refusal: *mut i32,
                out: *mut u32,
            ) -> i32;
            fn $split_face(
                mesh: *mut $raw,
                f: u32,
                p: *const f64,
                refusal: *mut i32,
                out: *mut u32,
            ) -> i32;
            fn $collapse(mesh: *mut $raw, from: u32, to: u32, refusal: *mut i32) -> i32;
            fn $split_vertex(
                mesh: *mut $raw,
                v: u32,
                p: *const f64,
                left: u32,
                right: u32,
                refusal: *mut i32,
                out: *mut u32,
            ) -> i32;
            fn $weld(mesh: *mut $raw, a: u32, b: u32, refusal: *mut i32) -> i32;
            fn $is_deleted(mesh: *const $raw, kind: i32, id: u32, out: *mut i32) -> i32;
            fn $garbage_collection(mesh: *mut $raw) -> i32;
            fn $reserve(mesh: *mut $raw, vertices: u32, edges: u32, faces: u32) -> i32;
        }

        const $api: $crate::foreign::edit::EditApi<$raw> = {
            use $crate::foreign::Call;
            $crate::foreign::edit::EditApi {
                add_vertex: Call {
                    name: stringify!($add_vertex),
                    f: $add_vertex,
                },
                set_position: Call {
                    name: stringify!($set_position),
                    f: $set_position,
                },
                add_face: Call {
                    name: stringify!($add_face),
                    f: $add_face,
                },
                delete_face: Call {
                    name: stringify!($delete_face),
                    f: $delete_face,
                },
                delete_vertex: Call {
                    name: stringify!($delete_vertex),
                    f: $delete_vertex,
                },
                flip: Call {
                    name: stringify!($flip),
                    f: $flip,
                },
                split_edge: Call {
                    name: stringify!($split_edge),
                    f: $split_edge,
                },
                split_face: Call {
                    name: stringify!($split_face),
                    f: $split_face,
                },
                collapse: Call {
                    name: stringify!($collapse),
                    f: $collapse,
                },
                split_vertex: Call {
                    name: stringify!($split_vertex),
                    f: $split_vertex,
                },
                weld: Call {
                    name: stringify!($weld),
                    f: $weld,
                },
                is_deleted: Call {
                    name: stringify!($is_deleted),
                    f: $is_deleted,
                },
                garbage_collection: Call {
                    name: stringify!($garbage_collection),
                    f: $garbage_collection,
                },
                reserve: Call {
                    name: stringify!($reserve),
                    f: $reserve,
                },
            }
        };
    };
}
pub(crate) use edit_api;

/// A library mesh that edits through a shim's [`EditApi`]: what the layer needs of it.
pub(crate) trait ForeignEdit: ForeignMesh {
    /// The shim's edit functions.
    const API: EditApi<Self::Raw>;
    /// The largest element count the library's handles can number.
    const MAX_ELEMENTS: u64;
    /// Reads the element counts from the mesh again.
    fn refresh_counts(&mut self) -> Result<()>;
}

/// The cost of each operation in the three libraries: their Euler operations (and the vertex
/// weld: CGAL's `stitch_borders` on one or two pairs, OpenMesh's connectivity setters around
/// the two fans) are local and append; the collapse's check (the lab's, in C++) looks each
/// neighbour of one end up around the other, O(k²); the garbage collection (a rebuild in
/// order, or ids given again in list order) reads every element; see each library's table.
pub(crate) fn edit_cost(op: EditOp) -> Cost {
    match op {
        EditOp::AddVertex | EditOp::SplitEdge => Cost::Constant,
        // Welding meshes is the trait's rebuild from the welded face list.
        EditOp::GarbageCollection | EditOp::WeldEdges | EditOp::WeldFaces | EditOp::WeldMeshes => {
            Cost::Linear
        }
        EditOp::AddFace
        | EditOp::WeldVertices
        | EditOp::DeleteFace
        | EditOp::DeleteVertex
        | EditOp::FlipEdge
        | EditOp::SplitFace
        | EditOp::SplitVertex => Cost::Local,
        // The shims' link condition: each neighbour of one end looked for around the other.
        EditOp::CollapseEdge => Cost::LocalSquared,
        EditOp::SetPosition => Cost::Constant,
        EditOp::Select => Cost::Linear,
        // k: the vertices selected, each moved by the shim's `set_position`.
        EditOp::RotateSelection | EditOp::ScaleSelection => Cost::Local,
        // Not offered: OpenMesh (`PolyConnectivity::insert_edge`, `remove_edge`) and CGAL
        // (`Euler::split_face`, `join_face`) have them, the shims do not bind them, so they
        // are refused as not implemented.
        EditOp::InsertEdge | EditOp::DeleteEdge => Cost::Local,
        // Declared by the structure from its query costs (`impl_mesh_edit!`).
        EditOp::Smooth => Cost::Linear,
    }
}

/// The lab's result of an edit's status: a refusal becomes [`Error::EditRefused`] with its
/// reason, a failure [`Error::Foreign`]; the counts are read again either way.
fn edited<M: ForeignEdit>(
    m: &mut M,
    op: EditOp,
    call: &'static str,
    code: i32,
    refusal: i32,
) -> Result<()> {
    m.refresh_counts()?;
    if code == EDIT_REFUSED {
        let reason = usize::try_from(refusal)
            .ok()
            .and_then(|r| REFUSALS.get(r).copied())
            .ok_or(Error::Foreign {
                library: M::LIBRARY,
                call,
                reason: "an unknown refusal code",
            })?;
        return Err(refuse::<M>(op, reason));
    }
    status(M::LIBRARY, call, code)
}

/// Refuses growth past the library's handles.
fn room<M: ForeignEdit>(m: &M, vertices: u64, edges: u64, faces: u64) -> Result<()> {
    let [v, e, f] = m.counts();
    for (what, now, more) in [
        ("vertices", v, vertices),
        ("edges", e, edges),
        ("faces", f, faces),
    ] {
        if now as u64 + more > M::MAX_ELEMENTS {
            return Err(Error::TooLarge {
                what,
                count: now as u64 + more,
            });
        }
    }
    Ok(())
}

/// Runs `f(refusal)`, a call that changes the mesh, and reports its status as `op`.
fn change<M: ForeignEdit>(
    m: &mut M,
    op: EditOp,
    call: &'static str,
    f: impl FnOnce(*mut i32) -> i32,
) -> Result<()> {
    let mut refusal = 0;
    let code = f(&mut refusal);
    edited(m, op, call, code, refusal)
}

/// Runs `f(refusal, out)`, a call that makes a new vertex, and returns it.
fn new_vertex<M: ForeignEdit>(
    m: &mut M,
    op: EditOp,
    call: &'static str,
    f: impl FnOnce(*mut i32, *mut u32) -> i32,
) -> Result<VertexId> {
    room(m, 1, 3, 2)?;
    let (mut refusal, mut out) = (0, u32::MAX);
    let code = f(&mut refusal, &mut out);
    edited(m, op, call, code, refusal)?;
    Ok(VertexId(out))
}

pub(crate) fn add_vertex<M: ForeignEdit>(m: &mut M, p: DVec3) -> Result<VertexId> {
    room(m, 1, 0, 0)?;
    let (raw, xyz, api) = (m.raw(), p.to_array(), &M::API.add_vertex);
    let mut out = u32::MAX;
    // SAFETY: `raw` is live and exclusively borrowed (through `m`); `xyz` holds 3 doubles;
    // `out` is valid.
    let code = unsafe { (api.f)(raw, xyz.as_ptr(), &mut out) };
    edited(m, EditOp::AddVertex, api.name, code, 0)?;
    Ok(VertexId(out))
}

pub(crate) fn set_position<M: ForeignEdit>(m: &mut M, v: VertexId, p: DVec3) -> Result<()> {
    let (raw, xyz, api) = (m.raw(), p.to_array(), &M::API.set_position);
    // SAFETY: `raw` is live and exclusively borrowed; the shim checks `v`; `xyz` holds 3
    // doubles; `refusal` is valid.
    change(m, EditOp::SetPosition, api.name, |refusal| unsafe {
        (api.f)(raw, v.0, xyz.as_ptr(), refusal)
    })
}

pub(crate) fn add_face<M: ForeignEdit>(m: &mut M, vertices: &[VertexId]) -> Result<FaceId> {
    let n = u32::try_from(vertices.len())
        .map_err(|_| refuse::<M>(EditOp::AddFace, Refusal::BadFace))?;
    room(m, 0, n as u64, 1)?;
    let ids: Vec<u32> = vertices.iter().map(|v| v.0).collect();
    let (raw, api) = (m.raw(), &M::API.add_face);
    let (mut refusal, mut out) = (0, u32::MAX);
    // SAFETY: `raw` is live and exclusively borrowed; `ids` holds `n` vertex ids, which the
    // shim checks; `refusal` and `out` are valid.
    let code = unsafe { (api.f)(raw, ids.as_ptr(), n, &mut refusal, &mut out) };
    edited(m, EditOp::AddFace, api.name, code, refusal)?;
    Ok(FaceId(out))
}

/// A call on one id: `delete_face`, `delete_vertex` or `flip_edge`.
fn on_id<M: ForeignEdit>(m: &mut M, op: EditOp, api: &Call<OnId<M::Raw>>, id: u32) -> Result<()> {
    let raw = m.raw();
    // SAFETY: `raw` is live and exclusively borrowed; the shim checks `id`.
    change(m, op, api.name, |refusal| unsafe {
        (api.f)(raw, id, refusal)
    })
}

pub(crate) fn delete_face<M: ForeignEdit>(m: &mut M, f: FaceId) -> Result<()> {
    on_id(m, EditOp::DeleteFace, &M::API.delete_face, f.0)
}

pub(crate) fn delete_vertex<M: ForeignEdit>(m: &mut M, v: VertexId) -> Result<()> {
    on_id(m, EditOp::DeleteVertex, &M::API.delete_vertex, v.0)
}

pub(crate) fn flip_edge<M: ForeignEdit>(m: &mut M, e: EdgeId) -> Result<()> {
    on_id(m, EditOp::FlipEdge, &M::API.flip, e.0)
}

/// A split of element `id` at a new vertex at `p`.
fn split_at<M: ForeignEdit>(
    m: &mut M,
    op: EditOp,
    api: &Call<SplitAt<M::Raw>>,
    id: u32,
    p: DVec3,
) -> Result<VertexId> {
    let (raw, xyz) = (m.raw(), p.to_array());
    new_vertex(m, op, api.name, |refusal, out| {
        // SAFETY: `raw` is live and exclusively borrowed (through `m`); the shim checks `id`;
        // `xyz` holds 3 doubles; `refusal` and `out` are valid.
        unsafe { (api.f)(raw, id, xyz.as_ptr(), refusal, out) }
    })
}

pub(crate) fn split_edge<M: ForeignEdit>(m: &mut M, e: EdgeId, p: DVec3) -> Result<VertexId> {
    split_at(m, EditOp::SplitEdge, &M::API.split_edge, e.0, p)
}

pub(crate) fn split_face<M: ForeignEdit>(m: &mut M, f: FaceId, p: DVec3) -> Result<VertexId> {
    // A face of k corners gains k edges and k - 1 faces; k is bounded by the edge count.
    let edges = m.counts()[1] as u64;
    room(m, 1, edges, edges)?;
    split_at(m, EditOp::SplitFace, &M::API.split_face, f.0, p)
}

pub(crate) fn collapse_edge<M: ForeignEdit>(m: &mut M, from: VertexId, to: VertexId) -> Result<()> {
    let (raw, api) = (m.raw(), &M::API.collapse);
    // SAFETY: `raw` is live and exclusively borrowed; the shim checks both ids.
    change(m, EditOp::CollapseEdge, api.name, |refusal| unsafe {
        (api.f)(raw, from.0, to.0, refusal)
    })
}

pub(crate) fn weld_vertices<M: ForeignEdit>(m: &mut M, a: VertexId, b: VertexId) -> Result<()> {
    let (raw, api) = (m.raw(), &M::API.weld);
    // SAFETY: `raw` is live and exclusively borrowed; the shim checks both ids.
    change(m, EditOp::WeldVertices, api.name, |refusal| unsafe {
        (api.f)(raw, a.0, b.0, refusal)
    })
}

pub(crate) fn split_vertex<M: ForeignEdit>(
    m: &mut M,
    v: VertexId,
    p: DVec3,
    left: VertexId,
    right: VertexId,
) -> Result<VertexId> {
    let (raw, xyz, api) = (m.raw(), p.to_array(), &M::API.split_vertex);
    new_vertex(m, EditOp::SplitVertex, api.name, |refusal, out| {
        // SAFETY: as in `split_at`, with the three ids checked by the shim.
        unsafe { (api.f)(raw, v.0, xyz.as_ptr(), left.0, right.0, refusal, out) }
    })
}

fn is_deleted<M: ForeignEdit>(m: &M, kind: i32, id: u32) -> bool {
    let api = &M::API.is_deleted;
    let mut out = 0;
    // SAFETY: `raw` is live; the shim checks `kind` and `id`; `out` is a valid out-pointer.
    let code = unsafe { (api.f)(m.raw(), kind, id, &mut out) };
    super::infallible(M::LIBRARY, api.name, code);
    out != 0
}

pub(crate) fn is_deleted_vertex<M: ForeignEdit>(m: &M, v: VertexId) -> bool {
    is_deleted(m, VERTEX, v.0)
}

pub(crate) fn is_deleted_face<M: ForeignEdit>(m: &M, f: FaceId) -> bool {
    is_deleted(m, FACE, f.0)
}

pub(crate) fn garbage_collection<M: ForeignEdit>(m: &mut M) {
    let api = &M::API.garbage_collection;
    // SAFETY: `raw` is live and exclusively borrowed.
    let code = unsafe { (api.f)(m.raw()) };
    super::infallible(M::LIBRARY, api.name, code);
    // The counts come from the mesh, which a failed collection left as it was.
    if let Err(e) = m.refresh_counts() {
        panic!("{e}");
    }
}

pub(crate) fn reserve<M: ForeignEdit>(m: &mut M, vertices: usize, edges: usize, faces: usize) {
    let clamp = |n: usize| n.min(M::MAX_ELEMENTS as usize).min(u32::MAX as usize) as u32;
    let api = &M::API.reserve;
    // SAFETY: `raw` is live and exclusively borrowed.
    let code = unsafe { (api.f)(m.raw(), clamp(vertices), clamp(edges), clamp(faces)) };
    // Reserving is a hint: running out of memory here shows up in the edits that follow.
    let _ = status(M::LIBRARY, api.name, code);
}

/// Writes `impl MeshEdit for $ty`, every method forwarding to this module's function of the
/// same name ([`ForeignEdit`] must be implemented for `$ty`).
macro_rules! impl_mesh_edit {
    ($ty:ty) => {
        impl topolab_structures::MeshEdit for $ty {
            const DELETION: topolab_structures::Deletion = topolab_structures::Deletion::Marked;

            fn edit_cost(op: topolab_structures::EditOp) -> topolab_structures::Cost {
                if op == topolab_structures::EditOp::Smooth {
                    return topolab_structures::core::edit::smooth_cost::<Self>();
                }
                $crate::foreign::edit::edit_cost(op)
            }
            /// Everything but the insertion and deletion of an edge, which the libraries have
            /// (OpenMesh's `insert_edge` and `remove_edge`, CGAL's `Euler::split_face` and
            /// `join_face`) but the shims do not bind.
            const OFFERS: topolab_structures::Offers<Self> = topolab_structures::Offers {
                add_vertex: Some($crate::foreign::edit::add_vertex),
                add_face: Some($crate::foreign::edit::add_face),
                delete_face: Some($crate::foreign::edit::delete_face),
                delete_vertex: Some($crate::foreign::edit::delete_vertex),
                flip_edge: Some($crate::foreign::edit::flip_edge),
                split_edge: Some($crate::foreign::edit::split_edge),
                split_face: Some($crate::foreign::edit::split_face),
                collapse_edge: Some($crate::foreign::edit::collapse_edge),
                split_vertex: Some($crate::foreign::edit::split_vertex),
                weld_vertices: Some($crate::foreign::edit::weld_vertices),
                insert_edge: None,
                delete_edge: None,
                rebuilds: true,
            };
            fn set_position(
                &mut self,
                v: topolab_structures::VertexId,
                p: glam::DVec3,
            ) -> topolab_structures::Result<()> {
                $crate::foreign::edit::set_position(self, v, p)
            }
            fn is_deleted_vertex(&self, v: topolab_structures::VertexId) -> bool {
                $crate::foreign::edit::is_deleted_vertex(self, v)
            }
            fn is_deleted_face(&self, f: topolab_structures::FaceId) -> bool {
                $crate::foreign::edit::is_deleted_face(self, f)
            }
            fn garbage_collection(&mut self) {
                $crate::foreign::edit::garbage_collection(self)
            }
            fn reserve(&mut self, vertices: usize, edges: usize, faces: usize) {
                $crate::foreign::edit::reserve(self, vertices, edges, faces)
            }
        }
    };
}
pub(crate) use impl_mesh_edit;

#[cfg(test)]
mod tests {
    use super::*;

    /// `NO_SUCH_ELEMENT` → `NoSuchElement`.
    fn camel(name: &str) -> String {
        name.split('_')
            .map(|w| w[..1].to_string() + &w[1..].to_lowercase())
            .collect()
    }

    #[test]
    fn refusal_codes_are_those_of_both_edit_headers() {
        for (header, prefix) in [
            (include_str!("../../cpp/openmesh/edit.h"), "TOPOLAB_OM_"),
            (include_str!("../../cpp/cgal/edit.h"), "TOPOLAB_CGAL_"),
        ] {
            let defines: Vec<(String, i32)> = header
                .lines()
                .filter_map(|l| l.strip_prefix("#define "))
                .filter_map(|l| l.strip_prefix(prefix))
                .filter_map(|l| {
                    let (name, value) = l.split_once(' ')?;
                    Some((name.to_string(), value.trim().parse().ok()?))
                })
                .collect();
            let refusals: Vec<&(String, i32)> = defines
                .iter()
                .filter(|(name, _)| name.starts_with("REFUSAL_"))
                .collect();
            assert_eq!(refusals.len(), REFUSALS.len(), "{prefix}: {refusals:?}");
            for (name, code) in refusals {
                let reason = REFUSALS[*code as usize];
                assert_eq!(
                    format!("{reason:?}"),
                    camel(&name["REFUSAL_".len()..]),
                    "{name}"
                );
            }
            assert!(
                defines.contains(&("EDIT_REFUSED".to_string(), EDIT_REFUSED)),
                "{prefix}EDIT_REFUSED"
            );
        }
    }
}
