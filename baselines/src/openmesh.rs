//! # OpenMesh (the C++ baseline, through FFI)
//!
//! [OpenMesh](https://www.graphics.rwth-aachen.de/software/openmesh/) is the halfedge library
//! graphics engineers compare against. [`OpenMesh`] wraps a `TriMesh_ArrayKernelT` (triangle
//! input) or `PolyMesh_ArrayKernelT` (polygon input) with double-precision points, built and
//! queried through the C API of `openmesh/shim.h`. The library is OpenMesh itself, compiled by
//! `build.rs` from its pinned source (PyPI `openmesh`'s sdist, fetched into `third_party/openmesh/`
//! by `third_party/fetch.py`) with its Release flags, `-O3 -DNDEBUG`, into a static library;
//! the shim calls its own functions ([`crate::OPENMESH_BUILD`] says which version and how it
//! was built, as the report's machine table does). This module holds the `unsafe` calls of its
//! FFI (the callbacks from C++ are in the `foreign` module it shares with the `cgal` module; the
//! lab's only other `unsafe` module is the pointer half-edge's `links`, where real pointers
//! are the point); everything it exports is safe.
//!
//! The C API is a wall: every function is `noexcept`, catches every C++ exception and returns
//! a status code, which becomes [`Error::Foreign`] here (a failed build, sweep, sampled kernel
//! or workload) — no exception ever reaches Rust. The one piece of process-wide OpenMesh
//! state the shim touches, the error stream `omerr()` (connected to `std::cerr` on first use
//! behind an unsynchronised flag, then silenced so that `add_face`'s refusals become typed
//! errors), is set up exactly once per process, thread-safely, inside that guard; meshes are
//! independent, so threads may build and query meshes in parallel
//! (`baselines/tests/openmesh_threads.rs`, and `.ci/repeat-baseline-tests` in CI). OpenMesh's heap is
//! counted per thread like Rust's, by the lab's global `operator new` (`heap/heap.cpp`, see
//! `crate::alloc`), so threads do not disturb each other's measurements either.
//!
//! What OpenMesh's array kernel stores (4-byte handles):
//!
//! | stores | bytes |
//! |---|---|
//! | per vertex: position (3 × f64), one outgoing halfedge | 28 |
//! | per halfedge: to-vertex, next, prev, face (the opposite of `h` is `h ^ 1`, its edge `h / 2`) | 16 (32 per edge) |
//! | per face: one of its halfedges | 4 |
//! | per vertex, halfedge, edge and face: the traits' data item (an empty struct with the default traits, stored all the same) | 1 |
//!
//! Ids: vertex i of the input is OpenMesh's vertex i and face j its face j (OpenMesh keeps
//! insertion order); `EdgeId` is OpenMesh's edge index (edges are created by `add_face`).
//!
//! | operator | how (OpenMesh's API) | cost |
//! |---|---|---|
//! | R00, R01, R02 | `vv_range`, `ve_range`, `vf_range` (circulators) | O(k) |
//! | R10 | the edge's halfedge: `from_vertex_handle`, `to_vertex_handle` | O(1) |
//! | R11 | `next_halfedge_handle` around both faces of the edge | O(k) |
//! | R12 | `face_handle` of both halfedges | O(1) |
//! | R20, R21, R22 | `fv_ccw_range`, `fe_ccw_range`, `ff_ccw_range` | O(k) |
//! | boundary vertex | the outgoing halfedge is a boundary one (`is_boundary`) | O(1) |
//! | boundary edge | `is_boundary(edge)` | O(1) |
//! | boundary curves | scan the halfedges for unvisited boundary ones, follow `next` | O(n) |
//! | successor, predecessor | the edge's halfedge in the face, `next`/`prev` | O(1) |
//!
//! For timing, per-query FFI calls would measure the FFI, so every kernel the harness times is
//! one C++ function: construction ([`OpenMesh::construct`], the one C++ call of `reserve`,
//! `add_vertex` and `add_face`: the lab's checks and the exact edge count for `reserve` come
//! before the clock, `SeparateConstruction::admit`, and reading the mesh's counts and freeing it
//! after), each sweep ([`OpenMesh::native_sweep`]), each sampled kernel
//! ([`OpenMesh::native_sampled`]: the sampled vertices, edges, faces or (edge, face) pairs,
//! checked once before the clock and handed over as OpenMesh's handles, which are the lab's
//! indices, then answered exactly as the harness's generic kernel answers them) and each
//! workload ([`OpenMesh::native_workload`]), with the checksums of `topolab_harness::measuring::checksum`.
//! [`MeshTopology::native`] hands them to the harness, which then times no cell of OpenMesh
//! through per-query calls. Operators and workloads reach C++ as the integer codes of
//! `openmesh/shim.h`'s tables, by a typed match (`operator_code`, `workload_code`, shared with
//! the CGAL shim).
//!
//! Non-manifold vertices: OpenMesh links the boundary halfedges of a vertex's fans into one
//! cycle, so its circulators visit every fan; the conformance suite checks it (bowtie and
//! random meshes with corner-touching cells, faces in random order). That needs every fan to
//! be open: a vertex with a closed fan and another fan is refused with
//! [`Error::NonManifoldVertex`] (OpenMesh's `add_face` refuses it too, "complex vertex"), a
//! case [`Capabilities::non_manifold_vertices`](topolab_structures::Capabilities::non_manifold_vertices) cannot express.

use crate::foreign::topology::{self, topology_api, topology_queries, ForeignMesh, TopologyApi};
use crate::foreign::{self, refusal};
use std::fmt::Write;
use std::ptr::NonNull;
use topolab_structures::algorithms::changing::Changing;
use topolab_structures::{
    BuildFacts, Constructed, Cost, Error, MeshTopology, NativeKernels, Operator, PolygonSoup,
    Result, Sample, SampledRun, SeparateConstruction, Workload,
};

/// The declarations of `openmesh/shim.h`.
mod access;
/// `MeshEdit` through OpenMesh's own operations (`openmesh/edit.h`).
mod edit;
pub mod read;

mod ffi {
    /// The C++ `topolab_om_mesh` (opaque).
    #[repr(C)]
    pub struct RawMesh {
        _opaque: [u8; 0],
        _not_send_sync_or_unpin: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
    }

    // Every function returns a status (`crate::foreign::OK` or a failure) and writes its
    // results through out-pointers; all are `noexcept` in C++ and catch every exception.

    extern "C" {
        pub fn topolab_om_build(
            xyz: *const f64,
            vertices: u32,
            indices: *const u32,
            offsets: *const u32,
            faces: u32,
            triangles: i32,
            edges_hint: u32,
            out: *mut *mut RawMesh,
            failed_face: *mut u32,
        ) -> i32;
        pub fn topolab_om_free(mesh: *mut RawMesh);
        pub fn topolab_om_summary(mesh: *const RawMesh, out: *mut u32) -> i32;
        pub fn topolab_om_sampled(
            mesh: *const RawMesh,
            op: i32,
            ids: *const u32,
            count: usize,
            out: *mut u64,
        ) -> i32;
        pub fn topolab_om_prepare_changing(mesh: *mut RawMesh) -> i32;
        pub fn topolab_om_changing(mesh: *mut RawMesh, workload: i32) -> i32;
    }
}

/// The lab's error for a failure status of shim function `call`.
fn status(call: &'static str, code: i32) -> Result<()> {
    foreign::status("OpenMesh", call, code)
}

/// An OpenMesh mesh (TriMesh for triangle input, PolyMesh otherwise); see the module docs.
pub struct OpenMesh {
    /// The C++ mesh, owned (freed in `Drop`).
    raw: NonNull<ffi::RawMesh>,
    /// A TriMesh (triangle input) rather than a PolyMesh.
    trimesh: bool,
    /// Number of vertices, edges and faces, kept here to check ids without an FFI call.
    vertices: u32,
    edges: u32,
    faces: u32,
}

impl Drop for OpenMesh {
    fn drop(&mut self) {
        // SAFETY: `raw` came from `topolab_om_build` and is freed exactly once, here.
        unsafe { ffi::topolab_om_free(self.raw.as_ptr()) }
    }
}

impl std::fmt::Debug for OpenMesh {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("OpenMesh")
            .field("trimesh", &self.is_trimesh())
            .field("vertices", &self.vertices)
            .field("edges", &self.edges)
            .field("faces", &self.faces)
            .finish()
    }
}

impl OpenMesh {
    /// OpenMesh's own construction, as its documentation does it: `reserve` with the facts'
    /// counts, then `add_vertex` per vertex and `add_face` per face, in one C++ call and
    /// nothing else (the harness times it). The mesh answers queries after
    /// [`Constructed::finish`], which reads its counts.
    ///
    /// A face that `add_face` refuses is reported with the lab's error for it (the edge
    /// analysis of [`PolygonSoup::connectivity`] or the non-manifold vertex it touches).
    pub fn construct(facts: &BuildFacts<'_>) -> Result<Constructed<Self>> {
        let soup = facts.soup();
        let mut failed_face = u32::MAX;
        let mut raw = std::ptr::null_mut();
        // SAFETY: `facts` holds a soup that passed `check`: every index < vertex count, every
        // face >= 3 corners, and counts that fit u32; positions are 3 contiguous f64 each
        // (DVec3 is repr(C), size asserted in `foreign`); offsets has faces + 1 entries; a
        // TriMesh is asked for only when every face is a triangle; both out-pointers are
        // valid. The C++ side copies everything it keeps.
        let code = unsafe {
            ffi::topolab_om_build(
                soup.positions.as_ptr().cast::<f64>(),
                facts.vertices(),
                soup.indices().as_ptr(),
                soup.offsets().as_ptr(),
                facts.faces(),
                soup.is_triangle_mesh() as i32,
                facts.edges(),
                &mut raw,
                &mut failed_face,
            )
        };
        if code == foreign::REFUSED {
            return Err(refusal(soup, failed_face as usize, "OpenMesh's add_face"));
        }
        status("topolab_om_build", code)?;
        let Some(raw) = NonNull::new(raw) else {
            return status("topolab_om_build", foreign::EXCEPTION).map(|_| unreachable!());
        };
        // Owned from here on (freed when dropped); no id is in range until `finish`.
        let mesh = Self {
            raw,
            trimesh: false,
            vertices: 0,
            edges: 0,
            faces: 0,
        };
        Ok(Constructed::new(mesh, |mesh, _| mesh.read_counts()))
    }

    /// Reads the kind and counts of the mesh, which the wrapper keeps to check ids without an
    /// FFI call (after building and after a change).
    fn read_counts(&mut self) -> Result<()> {
        let mut summary = [0u32; 4];
        // SAFETY: `raw` is live; `summary` has the 4 slots the shim fills.
        status("topolab_om_summary", unsafe {
            ffi::topolab_om_summary(self.raw.as_ptr(), summary.as_mut_ptr())
        })?;
        let [trimesh, vertices, edges, faces] = summary;
        self.trimesh = trimesh != 0;
        (self.vertices, self.edges, self.faces) = (vertices, edges, faces);
        Ok(())
    }

    /// [`OpenMesh::construct`] and its finishing step in one, with `edges_hint` edges
    /// reserved, after [`PolygonSoup::check`] only: the checks of
    /// [`MeshTopology::from_soup`], which every structure makes, are left to the library.
    pub fn build_native(soup: &PolygonSoup, edges_hint: usize) -> Result<Self> {
        Self::construct(&BuildFacts::new(soup, edges_hint)?)?.finish(soup)
    }

    /// `true` for a TriMesh (triangle input), `false` for a PolyMesh.
    pub fn is_trimesh(&self) -> bool {
        self.trimesh
    }

    /// The checksum of operator `op` over every element, computed by one C++ loop with
    /// OpenMesh's circulators; an error when OpenMesh failed inside the loop.
    pub fn native_sweep(&self, op: Operator) -> Result<u64> {
        topology::sweep(self, op)
    }

    /// Prepares OpenMesh's sampled kernel of `op` over the queries of `sample` (see
    /// [`SampledKernel`]): every id checked against this mesh here, once, so that the timed
    /// runs check nothing. An error when `op` has no sampled kernel (boundary curves), when the
    /// sample is not the kind of query `op` takes, or when it names an element the mesh does
    /// not have ([`Error::ElementOutOfRange`]).
    pub fn native_sampled(&self, op: Operator, sample: Sample<'_>) -> Result<SampledKernel<'_>> {
        let ids = foreign::sample_ids(Self::NAME, op, sample, ForeignMesh::counts(self))?;
        Ok(SampledKernel {
            mesh: self,
            op: foreign::operator_code(op),
            ids,
            queries: sample.len(),
        })
    }

    /// Requests what `workload` needs (normals for [`Workload::Normals`]), so that a timed
    /// [`OpenMesh::native_workload`] runs only the workload; an error when OpenMesh could not
    /// add the properties.
    pub fn prepare_workload(&mut self, workload: Workload) -> Result<()> {
        topology::prepare_workload(self, workload)
    }

    /// Runs a Surface_mesh benchmark workload (Sieger & Botsch) in one C++ call; an error when
    /// OpenMesh failed inside it. [`Workload::Normals`] adds normal properties (requested on
    /// first use unless [`OpenMesh::prepare_workload`] did it). What each returns:
    ///
    /// | workload | what | returns |
    /// |---|---|---|
    /// | `circulators` | for each vertex count its faces, for each face subtract its vertices | the incidences counted (NaN if the two counts disagree) |
    /// | `barycenter` | the mean of all positions | the sum of its coordinates |
    /// | `normals` | face normals, then vertex normals (normalised sum of unit face normals) | the sum of all vertex normal coordinates |
    /// | `smoothing` | one step of uniform 1-ring averaging of interior vertices | the sum of all coordinates afterwards |
    pub fn native_workload(&mut self, workload: Workload) -> Result<f64> {
        topology::workload(self, workload)
    }

    /// Requests what the changing workloads need (OpenMesh's status attributes, which its
    /// deletion marks live in): outside the timed call. A TriMesh only.
    pub fn prepare_changing(&mut self) -> Result<()> {
        if !self.trimesh {
            return Err(Error::Unsupported(
                "OpenMesh runs the changing workloads on triangle meshes only".into(),
            ));
        }
        // SAFETY: `raw` is live and exclusively borrowed.
        let code = unsafe { ffi::topolab_om_prepare_changing(self.raw.as_ptr()) };
        status("topolab_om_prepare_changing", code)
    }

    /// Runs a changing workload of the Surface_mesh benchmark in place, in one C++ call, as
    /// the protocol runs it (see `topolab_structures::algorithms::changing`); the counts are
    /// read again afterwards. The shim requests the status attributes itself if
    /// [`OpenMesh::prepare_changing`] did not.
    pub fn native_changing(&mut self, workload: Changing) -> Result<()> {
        if !self.trimesh {
            return self.prepare_changing();
        }
        let code = match workload {
            Changing::Sqrt3 => 0,
            Changing::Collapse => 1,
        };
        // SAFETY: `raw` is live and exclusively borrowed; the shim checks the code.
        let code = unsafe { ffi::topolab_om_changing(self.raw.as_ptr(), code) };
        status("topolab_om_changing", code)?;
        self.read_counts()
    }
}

topology_api!(TOPOLOGY: ffi::RawMesh = [
    topolab_om_position,
    topolab_om_edge_vertices,
    topolab_om_is_boundary_vertex,
    topolab_om_is_boundary_edge,
    topolab_om_query,
    topolab_om_edge_neighbour,
    topolab_om_boundary_curves,
    topolab_om_halfedge,
    topolab_om_vertex_halfedge,
    topolab_om_face_halfedge,
    topolab_om_heap_bytes,
    topolab_om_validate,
    topolab_om_sweep,
    topolab_om_prepare_workload,
    topolab_om_workload,
]);

impl ForeignMesh for OpenMesh {
    type Raw = ffi::RawMesh;
    const LIBRARY: &'static str = "OpenMesh";
    const TOPOLOGY: TopologyApi<ffi::RawMesh> = TOPOLOGY;

    fn raw(&self) -> *mut ffi::RawMesh {
        self.raw.as_ptr()
    }

    fn counts(&self) -> [u32; 3] {
        [self.vertices, self.edges, self.faces]
    }
}

impl MeshTopology for OpenMesh {
    const NAME: &'static str = "openmesh";

    topology_queries!(boundary_vertex: Cost::Constant);

    fn validate(&self) -> Result<()> {
        let (problem, element) = topology::validate(self)?;
        let message = match problem {
            0 => return Ok(()),
            1 => format!("halfedge {element}: next/prev/face links disagree"),
            2 => format!("vertex {element}: its outgoing halfedge does not start at it"),
            _ => format!("face {element}: its halfedge belongs to another face"),
        };
        Err(Error::invariant(Self::NAME, message))
    }

    fn explain(&self, w: &mut dyn Write) -> std::fmt::Result {
        let kernel = if self.is_trimesh() {
            "TriMesh_ArrayKernelT"
        } else {
            "PolyMesh_ArrayKernelT"
        };
        let title = format!(
            "OpenMesh {kernel} (C++ halfedge structure): halfedge h's opposite is h ^ 1, its edge h / 2"
        );
        foreign::explain_halfedges(w, self, &title, ("outgoing", "out"))
    }

    fn native<'a>() -> Option<&'a dyn NativeKernels<Self>> {
        Some(&Kernels)
    }

    fn separate_construction<'a>() -> Option<&'a dyn SeparateConstruction<Self>> {
        Some(&Kernels)
    }

    fn access(op: Operator) -> Option<topolab_structures::Access> {
        access::model(op)
    }
}

/// OpenMesh's sampled kernel of one operator, prepared by [`OpenMesh::native_sampled`]: its
/// checked queries in OpenMesh's handles, which are the indices the lab uses (one id per
/// query, or an edge and a face for successor and predecessor), handed to one C++ loop per run.
pub struct SampledKernel<'a> {
    /// The mesh, borrowed unchanged while the kernel lives.
    mesh: &'a OpenMesh,
    /// The operator's code in the shim's table.
    op: i32,
    /// The ids, each checked against `mesh`.
    ids: Vec<u32>,
    /// How many queries `ids` holds.
    queries: usize,
}

impl SampledKernel<'_> {
    /// The checksum of the prepared queries, computed by one C++ loop with OpenMesh's
    /// circulators, answering each as the harness's generic kernel does; an error when OpenMesh
    /// failed inside the loop.
    pub fn run(&self) -> Result<u64> {
        let mut out = 0;
        // SAFETY: the mesh is live and borrowed unchanged for the kernel's lifetime; `op` has
        // a sampled kernel and `ids` holds `queries` queries of its input, every id checked
        // against the mesh by `native_sampled`; `out` is a valid out-pointer.
        let code = unsafe {
            ffi::topolab_om_sampled(
                self.mesh.raw.as_ptr(),
                self.op,
                self.ids.as_ptr(),
                self.queries,
                &mut out,
            )
        };
        status("topolab_om_sampled", code).map(|()| out)
    }
}

/// OpenMesh's own loops, as the harness times them ([`MeshTopology::native`]).
struct Kernels;

impl SeparateConstruction<OpenMesh> for Kernels {
    fn admit<'a>(&self, soup: &'a PolygonSoup) -> Result<BuildFacts<'a>> {
        foreign::admit(soup)
    }

    fn construction(&self, facts: &BuildFacts<'_>) -> Result<Constructed<OpenMesh>> {
        OpenMesh::construct(facts)
    }
}

impl NativeKernels<OpenMesh> for Kernels {
    fn sweep(&self, mesh: &OpenMesh, op: Operator) -> Result<u64> {
        mesh.native_sweep(op)
    }

    fn sampled<'a>(
        &self,
        mesh: &'a OpenMesh,
        op: Operator,
        sample: Sample<'_>,
    ) -> Result<SampledRun<'a>> {
        let kernel = mesh.native_sampled(op, sample)?;
        Ok(Box::new(move || kernel.run()))
    }

    fn workload(&self, mesh: &mut OpenMesh, workload: Workload) -> Result<f64> {
        mesh.native_workload(workload)
    }
}
