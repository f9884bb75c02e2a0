//! The one forwarding layer of `MeshTopology` for the C++ baselines: OpenMesh's and CGAL's
//! shims answer the same queries through functions of the same shapes, which differ only in
//! their prefix (`topolab_om_`, `topolab_cgal_`). A shim lists its functions once in a
//! [`TopologyApi`] ([`topology_api!`]), its wrapper implements [`ForeignMesh`], and
//! [`topology_queries!`] writes the trait's query methods, each a call of a function here.
//!
//! Ids are checked on the Rust side against the counts the wrapper keeps (a panic, as the
//! trait's contract says for an id out of range), so that the C++ side indexes without checks;
//! every status that is not `OK` is a failure of the library ([`super::infallible`]).

use super::{status, Call, Emit, EndCurve, HalfedgeRecords};
use glam::DVec3;
use std::ffi::c_void;
use topolab_structures::{
    BoundaryCurves, Cost, EdgeId, FaceId, MeshTopology, Operator, Result, VertexId, Workload,
};

/// `(mesh, id, out)`: one element's answer.
type Read<R, T> = unsafe extern "C" fn(*const R, u32, *mut T) -> i32;

/// The query functions of one shim, on its mesh type `R` (declared by [`topology_api!`]).
pub(crate) struct TopologyApi<R> {
    pub(crate) position: Call<Read<R, f64>>,
    pub(crate) edge_vertices: Call<Read<R, u32>>,
    pub(crate) is_boundary_vertex: Call<Read<R, i32>>,
    pub(crate) is_boundary_edge: Call<Read<R, i32>>,
    pub(crate) query: Call<unsafe extern "C" fn(*const R, i32, u32, Emit, *mut c_void) -> i32>,
    pub(crate) edge_neighbour: Call<unsafe extern "C" fn(*const R, u32, u32, i32, *mut i64) -> i32>,
    pub(crate) boundary_curves:
        Call<unsafe extern "C" fn(*const R, Emit, EndCurve, *mut c_void) -> i32>,
    pub(crate) halfedge: Call<Read<R, u32>>,
    pub(crate) vertex_halfedge: Call<Read<R, u32>>,
    pub(crate) face_halfedge: Call<Read<R, u32>>,
    pub(crate) heap_bytes: Call<unsafe extern "C" fn(*const R, *mut u64) -> i32>,
    pub(crate) validate: Call<unsafe extern "C" fn(*const R, *mut i32, *mut u32) -> i32>,
    pub(crate) sweep: Call<unsafe extern "C" fn(*const R, i32, *mut u64) -> i32>,
    pub(crate) prepare_workload: Call<unsafe extern "C" fn(*mut R, i32) -> i32>,
    pub(crate) workload: Call<unsafe extern "C" fn(*mut R, i32, *mut f64) -> i32>,
}

/// Declares a shim's query functions (an `extern "C"` block with the layer's signatures, one
/// symbol per field of [`TopologyApi`], in its order) and the constant [`TopologyApi`] `$api`
/// holding them.
macro_rules! topology_api {
    ($api:ident: $raw:ty = [
        $position:ident, $edge_vertices:ident, $is_boundary_vertex:ident,
        $is_boundary_edge:ident, $query:ident, $edge_neighbour:ident, $boundary_curves:ident,
        $halfedge:ident, $vertex_halfedge:ident, $face_halfedge:ident, $heap_bytes:ident,
        $validate:ident, $sweep:ident, $prepare_workload:ident, $workload:ident $(,)?
    ]) => {
        // All `noexcept` in C++, catching every exception; each returns a status
        // (`crate::foreign::OK` or a failure) and writes its results through out-pointers.
        extern "C" {
            fn $position(mesh: *const $raw, v: u32, out: *mut f64) -> i32;
            fn $edge_vertices(mesh: *const $raw, e: u32, out: *mut u32) -> i32;
            fn $is_boundary_vertex(mesh: *const $raw, v: u32, out: *mut i32) -> i32;
            fn $is_boundary_edge(mesh: *const $raw, e: u32, out: *mut i32) -> i32;
            fn $query(
                mesh: *const $raw,
                op: i32,
                id: u32,
                emit: $crate::foreign::Emit,
                context: *mut std::ffi::c_void,
            ) -> i32;
            fn $edge_neighbour(
                mesh: *const $raw,
                e: u32,
                f: u32,
                successor: i32,
                out: *mut i64,
            ) -> i32;
            fn $boundary_curves(
                mesh: *const $raw,
                emit: $crate::foreign::Emit,
                end_curve: $crate::foreign::EndCurve,
                context: *mut std::ffi::c_void,
            ) -> i32;
            fn $halfedge(mesh: *const $raw, h: u32, out: *mut u32) -> i32;
            fn $vertex_halfedge(mesh: *const $raw, v: u32, out: *mut u32) -> i32;
            fn $face_halfedge(mesh: *const $raw, f: u32, out: *mut u32) -> i32;
            fn $heap_bytes(mesh: *const $raw, out: *mut u64) -> i32;
            fn $validate(mesh: *const $raw, problem: *mut i32, element: *mut u32) -> i32;
            fn $sweep(mesh: *const $raw, op: i32, out: *mut u64) -> i32;
            fn $prepare_workload(mesh: *mut $raw, workload: i32) -> i32;
            fn $workload(mesh: *mut $raw, workload: i32, out: *mut f64) -> i32;
        }

        const $api: $crate::foreign::topology::TopologyApi<$raw> = {
            use $crate::foreign::Call;
            $crate::foreign::topology::TopologyApi {
                position: Call {
                    name: stringify!($position),
                    f: $position,
                },
                edge_vertices: Call {
                    name: stringify!($edge_vertices),
                    f: $edge_vertices,
                },
                is_boundary_vertex: Call {
                    name: stringify!($is_boundary_vertex),
                    f: $is_boundary_vertex,
                },
                is_boundary_edge: Call {
                    name: stringify!($is_boundary_edge),
                    f: $is_boundary_edge,
                },
                query: Call {
                    name: stringify!($query),
                    f: $query,
                },
                edge_neighbour: Call {
                    name: stringify!($edge_neighbour),
                    f: $edge_neighbour,
                },
                boundary_curves: Call {
                    name: stringify!($boundary_curves),
                    f: $boundary_curves,
                },
                halfedge: Call {
                    name: stringify!($halfedge),
                    f: $halfedge,
                },
                vertex_halfedge: Call {
                    name: stringify!($vertex_halfedge),
                    f: $vertex_halfedge,
                },
                face_halfedge: Call {
                    name: stringify!($face_halfedge),
                    f: $face_halfedge,
                },
                heap_bytes: Call {
                    name: stringify!($heap_bytes),
                    f: $heap_bytes,
                },
                validate: Call {
                    name: stringify!($validate),
                    f: $validate,
                },
                sweep: Call {
                    name: stringify!($sweep),
                    f: $sweep,
                },
                prepare_workload: Call {
                    name: stringify!($prepare_workload),
                    f: $prepare_workload,
                },
                workload: Call {
                    name: stringify!($workload),
                    f: $workload,
                },
            }
        };
    };
}
pub(crate) use topology_api;

/// A C++ mesh behind a shim of [`TopologyApi`]'s shape.
pub(crate) trait ForeignMesh: MeshTopology {
    /// The shim's opaque mesh type.
    type Raw;
    /// The library's name in `Error::Foreign`.
    const LIBRARY: &'static str;
    /// The shim's query functions.
    const TOPOLOGY: TopologyApi<Self::Raw>;
    /// The live C++ mesh (owned by `self`; written through only with `self` borrowed mutably).
    fn raw(&self) -> *mut Self::Raw;
    /// The element counts kept on the Rust side: vertices, edges, faces.
    fn counts(&self) -> [u32; 3];
}

impl<M: ForeignMesh> HalfedgeRecords for M {
    fn counts(&self) -> [u32; 3] {
        ForeignMesh::counts(self)
    }
    fn record_position(&self, v: u32) -> DVec3 {
        self.position(VertexId(v))
    }
    fn vertex_halfedge(&self, v: u32) -> u32 {
        // Callers iterate the vertices' range.
        read(self, &Self::TOPOLOGY.vertex_halfedge, v, u32::MAX)
    }
    /// The halfedge record `h` as the library stores it: (to vertex, next, prev, face).
    fn halfedge(&self, h: u32) -> [u32; 4] {
        let api = &Self::TOPOLOGY.halfedge;
        let mut out = [0u32; 4];
        // SAFETY: `raw` is live, `h` < 2 × edges (callers iterate that range), `out` has 4 slots.
        let code = unsafe { (api.f)(self.raw(), h, out.as_mut_ptr()) };
        super::infallible(Self::LIBRARY, api.name, code);
        out
    }
    fn face_halfedge(&self, f: u32) -> u32 {
        // Callers iterate the faces' range.
        read(self, &Self::TOPOLOGY.face_halfedge, f, u32::MAX)
    }
}

/// One answer of `api` for element `id`, which the caller checked (`start` until written).
fn read<M: ForeignMesh, T>(m: &M, api: &Call<Read<M::Raw, T>>, id: u32, start: T) -> T {
    let mut out = start;
    // SAFETY: `raw` is live, `id` is in its range (checked by the caller), `out` is a valid
    // out-pointer of the one value the function writes.
    let code = unsafe { (api.f)(m.raw(), id, &mut out) };
    super::infallible(M::LIBRARY, api.name, code);
    out
}

/// `id` if it is below the count of its kind (`which`: 0 vertices, 1 edges, 2 faces), else a
/// panic naming it.
fn checked<M: ForeignMesh>(m: &M, which: usize, id: u32, what: &dyn std::fmt::Debug) -> u32 {
    let count = ForeignMesh::counts(m)[which];
    let kind = ["vertices", "edges", "faces"][which];
    assert!(id < count, "{what:?} out of range ({count} {kind})");
    id
}

pub(crate) fn vertex<M: ForeignMesh>(m: &M, v: VertexId) -> u32 {
    checked(m, 0, v.0, &v)
}
pub(crate) fn edge<M: ForeignMesh>(m: &M, e: EdgeId) -> u32 {
    checked(m, 1, e.0, &e)
}
pub(crate) fn face<M: ForeignMesh>(m: &M, f: FaceId) -> u32 {
    checked(m, 2, f.0, &f)
}

pub(crate) fn position<M: ForeignMesh>(m: &M, v: VertexId) -> DVec3 {
    let v = vertex(m, v);
    let api = &M::TOPOLOGY.position;
    let mut out = [0.0f64; 3];
    // SAFETY: `raw` is live, `v` checked, `out` has 3 slots.
    let code = unsafe { (api.f)(m.raw(), v, out.as_mut_ptr()) };
    super::infallible(M::LIBRARY, api.name, code);
    DVec3::from_array(out)
}

pub(crate) fn edge_vertices<M: ForeignMesh>(m: &M, e: EdgeId) -> [VertexId; 2] {
    let e = edge(m, e);
    let api = &M::TOPOLOGY.edge_vertices;
    let mut out = [0u32; 2];
    // SAFETY: `raw` is live, `e` checked, `out` has 2 slots.
    let code = unsafe { (api.f)(m.raw(), e, out.as_mut_ptr()) };
    super::infallible(M::LIBRARY, api.name, code);
    out.map(VertexId)
}

pub(crate) fn is_boundary_vertex<M: ForeignMesh>(m: &M, v: VertexId) -> bool {
    read(m, &M::TOPOLOGY.is_boundary_vertex, vertex(m, v), 0) != 0
}

pub(crate) fn is_boundary_edge<M: ForeignMesh>(m: &M, e: EdgeId) -> bool {
    read(m, &M::TOPOLOGY.is_boundary_edge, edge(m, e), 0) != 0
}

/// Calls `f` with every answer (an index) of relation `op` of element `id` (checked by the
/// caller against the element count of `op`'s input).
pub(crate) fn query<M: ForeignMesh>(m: &M, op: Operator, id: u32, f: impl FnMut(u32)) {
    let api = &M::TOPOLOGY.query;
    let raw = m.raw();
    let code = super::with_emit(f, |emit, context| {
        // SAFETY: `raw` is live; the caller checked `id`; `emit` and `context` come from
        // `with_emit`, which keeps the context alive for the call (C++ does not keep it).
        unsafe { (api.f)(raw, super::operator_code(op), id, emit, context) }
    });
    super::infallible(M::LIBRARY, api.name, code);
}

pub(crate) fn boundary_curves<M: ForeignMesh>(m: &M, out: &mut BoundaryCurves) {
    let api = &M::TOPOLOGY.boundary_curves;
    let raw = m.raw();
    let code = super::with_curves(out, |emit, end_curve, context| {
        // SAFETY: `raw` is live; the callbacks and context come from `with_curves`, alive for
        // the whole call.
        unsafe { (api.f)(raw, emit, end_curve, context) }
    });
    // Its visited flags are the one allocation of a query in the shims: out of memory there
    // is reported like Rust's own.
    super::infallible(M::LIBRARY, api.name, code);
}

/// The successor (or predecessor) of edge `e` in face `face`.
pub(crate) fn neighbour_in_face<M: ForeignMesh>(
    m: &M,
    e: EdgeId,
    face_id: FaceId,
    successor: bool,
) -> Option<EdgeId> {
    let (e, f) = (edge(m, e), face(m, face_id));
    let api = &M::TOPOLOGY.edge_neighbour;
    let mut answer = -1;
    // SAFETY: `raw` is live, both ids were checked, `answer` is a valid out-pointer.
    let code = unsafe { (api.f)(m.raw(), e, f, successor as i32, &mut answer) };
    super::infallible(M::LIBRARY, api.name, code);
    u32::try_from(answer).ok().map(EdgeId)
}

/// What the library's containers hold by their lengths (the shim's `heap_bytes`).
pub(crate) fn heap_bytes<M: ForeignMesh>(m: &M) -> usize {
    let api = &M::TOPOLOGY.heap_bytes;
    let mut out = 0;
    // SAFETY: `raw` is live; `out` is a valid out-pointer.
    let code = unsafe { (api.f)(m.raw(), &mut out) };
    super::infallible(M::LIBRARY, api.name, code);
    out as usize
}

/// The shim's validation: the problem's code (0 for none) and the element it is about.
pub(crate) fn validate<M: ForeignMesh>(m: &M) -> Result<(i32, u32)> {
    let api = &M::TOPOLOGY.validate;
    let (mut problem, mut element) = (0, 0u32);
    // SAFETY: `raw` is live; `problem` and `element` are valid out-pointers.
    let code = unsafe { (api.f)(m.raw(), &mut problem, &mut element) };
    status(M::LIBRARY, api.name, code).map(|()| (problem, element))
}

/// The checksum of operator `op` over every element, computed by one C++ loop with the
/// library's circulators; an error when the library failed inside the loop.
pub(crate) fn sweep<M: ForeignMesh>(m: &M, op: Operator) -> Result<u64> {
    let api = &M::TOPOLOGY.sweep;
    let mut out = 0;
    // SAFETY: `raw` is live; `out` is a valid out-pointer; the shim checks the code.
    let code = unsafe { (api.f)(m.raw(), super::operator_code(op), &mut out) };
    status(M::LIBRARY, api.name, code).map(|()| out)
}

/// Prepares what `workload` needs, outside the timed call.
pub(crate) fn prepare_workload<M: ForeignMesh>(m: &mut M, workload: Workload) -> Result<()> {
    let api = &M::TOPOLOGY.prepare_workload;
    // SAFETY: `raw` is live and exclusively borrowed.
    let code = unsafe { (api.f)(m.raw(), super::workload_code(workload)) };
    status(M::LIBRARY, api.name, code)
}

/// Runs a Surface_mesh benchmark workload in one C++ call.
pub(crate) fn workload<M: ForeignMesh>(m: &mut M, workload: Workload) -> Result<f64> {
    let api = &M::TOPOLOGY.workload;
    let mut out = 0.0;
    // SAFETY: `raw` is live and exclusively borrowed; `out` is a valid out-pointer.
    let code = unsafe { (api.f)(m.raw(), super::workload_code(workload), &mut out) };
    status(M::LIBRARY, api.name, code).map(|()| out)
}

/// The cost of `op` in a halfedge library: constant for the steps of a halfedge, local for
/// the circulators, linear for the boundary curves' scan; the boundary-vertex test's
/// (`boundary_vertex`) is each library's.
pub(crate) fn cost(op: Operator, boundary_vertex: Cost) -> Cost {
    match op {
        Operator::BoundaryVertex => boundary_vertex,
        Operator::R10
        | Operator::R12
        | Operator::BoundaryEdge
        | Operator::EdgeSuccessor
        | Operator::EdgePredecessor => Cost::Constant,
        Operator::R00
        | Operator::R01
        | Operator::R02
        | Operator::R11
        | Operator::R20
        | Operator::R21
        | Operator::R22 => Cost::Local,
        Operator::BoundaryCurves => Cost::Linear,
    }
}

/// Writes the methods of `MeshTopology` that the C++ baselines share (inside an
/// `impl MeshTopology for` block of a [`ForeignMesh`] with an inherent
/// `construct(&BuildFacts) -> Result<Constructed<Self>>`), each forwarding to this module's
/// function of the same name: capabilities (polygons; non-manifold vertices with open fans
/// only, see each library's module docs), costs ([`cost`], with the library's
/// `boundary_vertex` cost), building from a soup, the counts, the relations R00–R22, the
/// boundary tests and curves, the neighbours in a face and the heap bytes. The rest (name,
/// validation's messages, `explain`, `native`, `access`) differs per library and stays with it.
macro_rules! topology_queries {
    (boundary_vertex: $boundary_vertex:expr) => {
        fn capabilities() -> topolab_structures::Capabilities {
            topolab_structures::Capabilities {
                // With open fans only; see the module docs.
                non_manifold_vertices: true,
                ..topolab_structures::Capabilities::POLYGONS
            }
        }

        fn cost(op: topolab_structures::Operator) -> topolab_structures::Cost {
            $crate::foreign::topology::cost(op, $boundary_vertex)
        }

        fn from_soup(soup: &topolab_structures::PolygonSoup) -> topolab_structures::Result<Self> {
            Self::construct(&$crate::foreign::admit(soup)?)?.finish(soup)
        }

        fn num_vertices(&self) -> usize {
            $crate::foreign::topology::ForeignMesh::counts(self)[0] as usize
        }
        fn num_edges(&self) -> usize {
            $crate::foreign::topology::ForeignMesh::counts(self)[1] as usize
        }
        fn num_faces(&self) -> usize {
            $crate::foreign::topology::ForeignMesh::counts(self)[2] as usize
        }
        fn for_each_edge(&self, mut f: impl FnMut(topolab_structures::EdgeId)) {
            let edges = $crate::foreign::topology::ForeignMesh::counts(self)[1];
            (0..edges).for_each(|e| f(topolab_structures::EdgeId(e)));
        }
        fn position(&self, v: topolab_structures::VertexId) -> glam::DVec3 {
            $crate::foreign::topology::position(self, v)
        }
        fn vertex_vertices(
            &self,
            v: topolab_structures::VertexId,
            mut f: impl FnMut(topolab_structures::VertexId),
        ) {
            let v = $crate::foreign::topology::vertex(self, v);
            let op = topolab_structures::Operator::R00;
            $crate::foreign::topology::query(self, op, v, |w| f(topolab_structures::VertexId(w)));
        }
        fn vertex_edges(
            &self,
            v: topolab_structures::VertexId,
            mut f: impl FnMut(topolab_structures::EdgeId),
        ) {
            let v = $crate::foreign::topology::vertex(self, v);
            let op = topolab_structures::Operator::R01;
            $crate::foreign::topology::query(self, op, v, |e| f(topolab_structures::EdgeId(e)));
        }
        fn vertex_faces(
            &self,
            v: topolab_structures::VertexId,
            mut f: impl FnMut(topolab_structures::FaceId),
        ) {
            let v = $crate::foreign::topology::vertex(self, v);
            let op = topolab_structures::Operator::R02;
            $crate::foreign::topology::query(self, op, v, |g| f(topolab_structures::FaceId(g)));
        }
        fn edge_vertices(
            &self,
            e: topolab_structures::EdgeId,
        ) -> [topolab_structures::VertexId; 2] {
            $crate::foreign::topology::edge_vertices(self, e)
        }
        fn edge_edges(
            &self,
            e: topolab_structures::EdgeId,
            mut f: impl FnMut(topolab_structures::EdgeId),
        ) {
            let e = $crate::foreign::topology::edge(self, e);
            let op = topolab_structures::Operator::R11;
            $crate::foreign::topology::query(self, op, e, |x| f(topolab_structures::EdgeId(x)));
        }
        fn edge_faces(
            &self,
            e: topolab_structures::EdgeId,
            mut f: impl FnMut(topolab_structures::FaceId),
        ) {
            let e = $crate::foreign::topology::edge(self, e);
            let op = topolab_structures::Operator::R12;
            $crate::foreign::topology::query(self, op, e, |g| f(topolab_structures::FaceId(g)));
        }
        fn face_vertices(
            &self,
            face: topolab_structures::FaceId,
            mut f: impl FnMut(topolab_structures::VertexId),
        ) {
            let face = $crate::foreign::topology::face(self, face);
            let op = topolab_structures::Operator::R20;
            $crate::foreign::topology::query(self, op, face, |v| {
                f(topolab_structures::VertexId(v))
            });
        }
        fn face_edges(
            &self,
            face: topolab_structures::FaceId,
            mut f: impl FnMut(topolab_structures::EdgeId),
        ) {
            let face = $crate::foreign::topology::face(self, face);
            let op = topolab_structures::Operator::R21;
            $crate::foreign::topology::query(self, op, face, |e| f(topolab_structures::EdgeId(e)));
        }
        fn face_faces(
            &self,
            face: topolab_structures::FaceId,
            mut f: impl FnMut(topolab_structures::FaceId),
        ) {
            let face = $crate::foreign::topology::face(self, face);
            let op = topolab_structures::Operator::R22;
            $crate::foreign::topology::query(self, op, face, |g| f(topolab_structures::FaceId(g)));
        }
        fn is_boundary_vertex(&self, v: topolab_structures::VertexId) -> bool {
            $crate::foreign::topology::is_boundary_vertex(self, v)
        }
        fn is_boundary_edge(&self, e: topolab_structures::EdgeId) -> bool {
            $crate::foreign::topology::is_boundary_edge(self, e)
        }
        fn boundary_curves(&self, out: &mut topolab_structures::BoundaryCurves) {
            $crate::foreign::topology::boundary_curves(self, out)
        }
        fn edge_successor(
            &self,
            e: topolab_structures::EdgeId,
            face: topolab_structures::FaceId,
        ) -> Option<topolab_structures::EdgeId> {
            $crate::foreign::topology::neighbour_in_face(self, e, face, true)
        }
        fn edge_predecessor(
            &self,
            e: topolab_structures::EdgeId,
            face: topolab_structures::FaceId,
        ) -> Option<topolab_structures::EdgeId> {
            $crate::foreign::topology::neighbour_in_face(self, e, face, false)
        }
        /// What the library's containers hold by their lengths (the shim's `heap_bytes`): its
        /// records and every property's elements; the counting allocator measures the blocks
        /// it really holds.
        fn heap_bytes(&self) -> usize {
            $crate::foreign::topology::heap_bytes(self)
        }
    };
}
pub(crate) use topology_queries;
