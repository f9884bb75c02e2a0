//! # CGAL (C++ baselines, through FFI): `Surface_mesh`, `Polyhedron_3`, `convex_hull_3`
//!
//! [CGAL](https://www.cgal.org) has a production implementation of each halfedge structure the
//! lecture on polygon-mesh data structures teaches, and this module wraps both, built and
//! queried through the C API of `cgal/shim.h` (Debian's `libcgal-dev`, CGAL 5.5, header-only):
//!
//! | structure | CGAL class | storage | the lab's counterpart |
//! |---|---|---|---|
//! | [`SurfaceMesh`] (`cgal-surface-mesh`) | `CGAL::Surface_mesh<Point_3>` | index arrays (the Surface_mesh of Sieger & Botsch, IMR 2011) | `index-half-edge` |
//! | [`Polyhedron`] (`cgal-polyhedron`) | `CGAL::Polyhedron_3<K, Polyhedron_items_with_id_3>` | records in linked lists (`HalfedgeDS_list`), linked by pointers | `pointer-half-edge` |
//!
//! Both use `Simple_cartesian<double>` points (the lab's positions round-trip exactly) and
//! answer every operator through CGAL's BGL circulators (`halfedges_around_target`,
//! `vertices_around_target`, `faces_around_target`, `vertices_around_face`,
//! `halfedges_around_face`, `faces_around_face`), the interface CGAL's own algorithms use on
//! both classes: for a Polyhedron it steps `h->next()->opposite()` exactly like
//! `Halfedge_around_vertex_circulator`. For timing, per-query FFI calls would measure the FFI,
//! so every kernel the harness times is one C++ call: construction ([`Cgal::build_native`]),
//! each sweep ([`Cgal::native_sweep`]), each sampled kernel ([`Cgal::native_sampled`]: the
//! sampled vertices, edges, faces or (edge, face) pairs, checked and translated to the
//! structure's own descriptors once, before the clock, so that a `Polyhedron_3`'s timed loop
//! reads no id table; then answered exactly as the harness's generic kernel answers them) and
//! each workload ([`Cgal::native_workload`]), with the checksums of
//! `topolab_harness::measuring::checksum`. [`MeshTopology::native`] hands them to the harness, which then
//! times no cell of either structure through per-query calls. Operators and workloads reach
//! C++ as the codes of `cgal/shim.h`'s tables (the OpenMesh shim's, by the same typed match).
//!
//! Construction, the way CGAL's documentation builds each (and what the harness times, through
//! [`MeshTopology::native`]):
//! - `Surface_mesh`: `reserve`, then `add_vertex` per vertex and `add_face` per face
//!   (`add_face` is `CGAL::Euler::add_face`: it copies and sorts the face's vertices to check
//!   them, and finds each edge by circulating around its start vertex);
//! - `Polyhedron_3`: `Polyhedron_incremental_builder_3` (`begin_surface` with the counts,
//!   `add_vertex`, `add_facet`), not `polygon_soup_to_polygon_mesh`: the builder is the class's
//!   own construction interface and flags a face it cannot add, while
//!   `polygon_soup_to_polygon_mesh` ignores a refused face outside debug builds (its check is an
//!   assertion). Ids come from `Polyhedron_items_with_id_3`, set after building.
//!
//! Both are told the exact vertex, edge and face counts, from the lab's checks and edge
//! analysis before the clock (`SeparateConstruction::admit`); the timed construction is
//! [`Cgal::construct`], the library's calls alone. The `Polyhedron_3`'s ids and tables (the lab's
//! way in from an id, not CGAL's) are made after the clock, when the mesh is finished for its
//! queries (`Constructed::finish`), and every mesh is freed after the clock.
//!
//! Ids: vertex i of the input is CGAL's vertex i and face j its face j (both keep insertion
//! order); edge e is the edge with halfedges 2e and 2e + 1 (Surface_mesh's own numbering; for
//! the Polyhedron, the ids the shim gives in list order).
//!
//! What each stores (64-bit; [`MeshTopology::heap_bytes`] adds these up, and the memory section
//! of the report shows them beside the blocks the counting allocator measured, see
//! `crate::alloc`):
//!
//! | | `Surface_mesh` | `Polyhedron_3` with ids |
//! |---|---|---|
//! | per vertex | point (24), incoming halfedge (4), removed flag (1 bit) | list links (16), point (24), halfedge (8), id (8) |
//! | per halfedge | face, target vertex, next, prev (4 each) | list links (16), opposite, next, prev, vertex, face (8 each), id (8), allocated in pairs |
//! | per edge / face | removed flag / halfedge (4), removed flag | — / list links (16), halfedge (8), id (8) |
//! | tables | — | vertex, facet and edge handles by id (8 per entry), the way in from an id |
//!
//! Declared costs ([`MeshTopology::cost`], from CGAL's documentation; Table 4.1 of the report
//! shows them beside the fitted exponents): every circulator step is O(1) (`next`, `prev` and
//! `opposite` are stored or, in `Surface_mesh`, computed from the index; the reference of
//! `Polyhedron_3::Halfedge`: successive assignments `h = h->next()->opposite()` cycle
//! clockwise around the vertex and traverse all its halfedges), so relations are O(k); an
//! edge's vertices and faces, successor and predecessor are O(1). The boundary-vertex test
//! differs. `Surface_mesh`'s reference, section "Borders": for a vertex the test "means to look
//! at all incident halfedges", but "if algorithms operating on a surface mesh maintain that the
//! halfedge associated to a border vertex is a border halfedge, this is a constant time
//! operation too", which `add_face` maintains (`halfedge(v)`: "If `v` is a border vertex this
//! will be a border halfedge"), so `is_border(v, false)` reads one halfedge, O(1) (the
//! conformance suite checks its answers, non-manifold vertices included). A `Polyhedron_3`
//! vertex's halfedge is any halfedge pointing to it, so `CGAL::is_border(v, g)` circulates,
//! O(k). Boundary curves: scan the halfedges for border ones and follow `next`, O(n).
//!
//! Access models ([`MeshTopology::access`], in `access`): `Surface_mesh`'s property arrays
//! (`v:connectivity`, `h:connectivity`, `f:connectivity`) read like the index half-edge's;
//! `Polyhedron_3`'s records are nodes of `In_place_list`s, each its own heap block.
//!
//! Non-manifold vertices: both classes link the boundary halfedges of a vertex's fans into one
//! cycle (`Polyhedron_3`: "except for vertices where multiple holes join"), so circulators
//! visit every fan; a vertex with a closed fan and another fan is refused with
//! [`Error::NonManifoldVertex`] before CGAL sees it (CGAL refuses it too).
//!
//! The C API is a wall, as OpenMesh's: every function is `noexcept`, catches every C++
//! exception and returns a status code, which becomes [`Error::Foreign`] here. Its one
//! process-wide action, pinning CGAL's failure behaviour to exceptions (so that a failure
//! CGAL reports reaches the wall instead of aborting), is done once per process, thread-safely
//! (a function-local static); the builder writes nothing with `verbose` off. Meshes are
//! independent, so threads may build and query meshes in parallel (`baselines/tests/cgal_threads.rs`,
//! and `.ci/repeat-baseline-tests` in CI). CGAL's heap is counted per thread like Rust's, by
//! the lab's global `operator new` (`heap/heap.cpp`), so threads do not disturb each other's
//! measurements either.
//!
//! [`hull::convex_hull_3`] runs `CGAL::convex_hull_3` (quickhull,
//! `Exact_predicates_inexact_constructions_kernel`) for the report's hull section.

use crate::foreign::topology::{self, topology_api, topology_queries, ForeignMesh, TopologyApi};
use crate::foreign::{self, refusal};
use std::fmt::Write;
use std::marker::PhantomData;
use std::ptr::NonNull;
use topolab_structures::{
    Access, BuildFacts, Constructed, Cost, Error, MeshTopology, NativeKernels, Operator,
    PolygonSoup, Result, Sample, SampledRun, SeparateConstruction, Workload,
};

mod access;
/// The changing workloads through CGAL's Euler operations (`cgal/edit.h`).
mod changing;
/// `MeshEdit` for the `Surface_mesh` through CGAL's Euler operations (`cgal/edit.h`).
mod edit;
pub mod hull;

/// The declarations of `cgal/shim.h`.
/// The version of the CGAL headers this build compiled, e.g. `5.5.1`.
pub fn version() -> String {
    // SAFETY: the shim returns CGAL_VERSION_STR, a static NUL-terminated string.
    unsafe { std::ffi::CStr::from_ptr(ffi::topolab_cgal_version()) }
        .to_string_lossy()
        .into_owned()
}

mod ffi {
    /// The C++ `topolab_cgal_mesh` (opaque).
    #[repr(C)]
    pub struct RawMesh {
        _opaque: [u8; 0],
        _not_send_sync_or_unpin: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
    }

    /// The C++ `topolab_cgal_sample` (opaque): a sampled kernel prepared for one mesh.
    #[repr(C)]
    pub struct RawSample {
        _opaque: [u8; 0],
        _not_send_sync_or_unpin: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
    }

    pub const SURFACE_MESH: i32 = 0;
    pub const POLYHEDRON: i32 = 1;

    // Every function returns a status (`crate::foreign::OK` or a failure) and writes its
    // results through out-pointers; all are `noexcept` in C++ and catch every exception.
    extern "C" {
        pub fn topolab_cgal_version() -> *const std::ffi::c_char;
        pub fn topolab_cgal_build(
            structure: i32,
            xyz: *const f64,
            vertices: u32,
            indices: *const u32,
            offsets: *const u32,
            faces: u32,
            edges_hint: u32,
            out: *mut *mut RawMesh,
            failed_face: *mut u32,
        ) -> i32;
        pub fn topolab_cgal_finish(mesh: *mut RawMesh) -> i32;
        pub fn topolab_cgal_free(mesh: *mut RawMesh);
        pub fn topolab_cgal_summary(mesh: *const RawMesh, out: *mut u32) -> i32;
        pub fn topolab_cgal_prepare_sample(
            mesh: *const RawMesh,
            op: i32,
            ids: *const u32,
            count: usize,
            out: *mut *mut RawSample,
        ) -> i32;
        pub fn topolab_cgal_sampled(sample: *const RawSample, out: *mut u64) -> i32;
        pub fn topolab_cgal_free_sample(sample: *mut RawSample);
        pub fn topolab_cgal_convex_hull(
            xyz: *const f64,
            n: u32,
            repeat: u32,
            seconds: *mut f64,
            out: *mut u32,
            volume: *mut f64,
        ) -> i32;
    }
}

/// The library name in [`Error::Foreign`].
const LIBRARY: &str = "CGAL";

/// The lab's error for a failure status of shim function `call`.
fn status(call: &'static str, code: i32) -> Result<()> {
    foreign::status(LIBRARY, call, code)
}

/// Which CGAL class a [`Cgal`] holds: what differs between the two (see the module docs).
pub trait CgalStructure: 'static {
    /// The structure's name in the lab (CLI, JSON, report).
    const NAME: &'static str;
    /// The shim's structure code.
    const CODE: i32;
    /// What builds it, for refusals ("CGAL's Surface_mesh::add_face").
    const BUILDER: &'static str;
    /// The first line of `explain`.
    const TITLE: &'static str;
    /// The cost of the boundary-vertex test (the one operator whose cost differs).
    const BOUNDARY_VERTEX: Cost;
    /// What CGAL's loop of `op` reads ([`MeshTopology::access`]).
    fn access(op: Operator) -> Option<Access>;
}

/// `CGAL::Surface_mesh`: index-based halfedges; see the module docs.
#[derive(Debug)]
pub enum SurfaceMeshClass {}

impl CgalStructure for SurfaceMeshClass {
    const NAME: &'static str = "cgal-surface-mesh";
    const CODE: i32 = ffi::SURFACE_MESH;
    const BUILDER: &'static str = "CGAL's Surface_mesh::add_face";
    const TITLE: &'static str = "CGAL::Surface_mesh (C++, index-based halfedges in arrays): \
halfedge h's opposite is h ^ 1, its edge h / 2; a border vertex keeps a border halfedge";
    const BOUNDARY_VERTEX: Cost = Cost::Constant;
    fn access(op: Operator) -> Option<Access> {
        access::surface_mesh(op)
    }
}

/// `CGAL::Polyhedron_3`: pointer-based halfedges in linked lists; see the module docs.
#[derive(Debug)]
pub enum PolyhedronClass {}

impl CgalStructure for PolyhedronClass {
    const NAME: &'static str = "cgal-polyhedron";
    const CODE: i32 = ffi::POLYHEDRON;
    const BUILDER: &'static str = "CGAL's Polyhedron_incremental_builder_3";
    const TITLE: &'static str = "CGAL::Polyhedron_3 (C++, a list node per vertex, halfedge pair \
and facet, linked by pointers), shown by the ids of Polyhedron_items_with_id_3: halfedge h's \
opposite is h ^ 1, its edge h / 2";
    const BOUNDARY_VERTEX: Cost = Cost::Local;
    fn access(op: Operator) -> Option<Access> {
        access::polyhedron(op)
    }
}

/// `CGAL::Surface_mesh` as a lab structure (`cgal-surface-mesh`).
pub type SurfaceMesh = Cgal<SurfaceMeshClass>;
/// `CGAL::Polyhedron_3` as a lab structure (`cgal-polyhedron`).
pub type Polyhedron = Cgal<PolyhedronClass>;

/// A CGAL mesh of class `S`; see the module docs.
pub struct Cgal<S: CgalStructure> {
    /// The C++ mesh, owned (freed in `Drop`).
    raw: NonNull<ffi::RawMesh>,
    /// Number of vertices, edges and faces, kept here to check ids without an FFI call.
    vertices: u32,
    edges: u32,
    faces: u32,
    class: PhantomData<S>,
}

impl<S: CgalStructure> Drop for Cgal<S> {
    fn drop(&mut self) {
        // SAFETY: `raw` came from `topolab_cgal_build` and is freed exactly once, here.
        unsafe { ffi::topolab_cgal_free(self.raw.as_ptr()) }
    }
}

impl<S: CgalStructure> std::fmt::Debug for Cgal<S> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct(S::NAME)
            .field("vertices", &self.vertices)
            .field("edges", &self.edges)
            .field("faces", &self.faces)
            .finish()
    }
}

impl<S: CgalStructure> Cgal<S> {
    /// CGAL's own construction (see the module docs) from the facts' counts, in one C++ call
    /// and nothing else (the harness times it). The mesh answers queries after
    /// [`Constructed::finish`], which gives a `Polyhedron_3` its id tables and reads the
    /// counts.
    ///
    /// A face CGAL refuses is reported with the lab's error for it (the edge analysis of
    /// [`PolygonSoup::connectivity`] or the non-manifold vertex it touches).
    pub fn construct(facts: &BuildFacts<'_>) -> Result<Constructed<Self>> {
        let soup = facts.soup();
        let mut failed_face = u32::MAX;
        let mut raw = std::ptr::null_mut();
        // SAFETY: `facts` holds a soup that passed `check`: every index < vertex count, every
        // face >= 3 corners, and counts that fit u32; positions are 3 contiguous f64 each
        // (DVec3 is repr(C), size asserted in `foreign`); offsets has faces + 1 entries; both
        // out-pointers are valid. The C++ side copies everything it keeps.
        let code = unsafe {
            ffi::topolab_cgal_build(
                S::CODE,
                soup.positions.as_ptr().cast::<f64>(),
                facts.vertices(),
                soup.indices().as_ptr(),
                soup.offsets().as_ptr(),
                facts.faces(),
                facts.edges(),
                &mut raw,
                &mut failed_face,
            )
        };
        if code == foreign::REFUSED {
            return Err(refusal(soup, failed_face as usize, S::BUILDER));
        }
        status("topolab_cgal_build", code)?;
        let Some(raw) = NonNull::new(raw) else {
            return status("topolab_cgal_build", foreign::EXCEPTION).map(|_| unreachable!());
        };
        // Owned from here on (freed when dropped); no id is in range until `finish`.
        let mesh = Self {
            raw,
            vertices: 0,
            edges: 0,
            faces: 0,
            class: PhantomData,
        };
        Ok(Constructed::new(mesh, |mesh, _| mesh.finish()))
    }

    /// The finishing step of [`Cgal::construct`]: the lab's ids (`topolab_cgal_finish`), then
    /// the counts, which the wrapper keeps to check ids without an FFI call.
    fn finish(&mut self) -> Result<()> {
        // SAFETY: `raw` is live and exclusively borrowed.
        status("topolab_cgal_finish", unsafe {
            ffi::topolab_cgal_finish(self.raw.as_ptr())
        })?;
        self.refresh_counts()
    }

    /// [`Cgal::construct`] and its finishing step in one, with `edges_hint` edges reserved,
    /// after [`PolygonSoup::check`] only: the checks of [`MeshTopology::from_soup`], which
    /// every structure makes, are left to CGAL.
    pub fn build_native(soup: &PolygonSoup, edges_hint: usize) -> Result<Self> {
        Self::construct(&BuildFacts::new(soup, edges_hint)?)?.finish(soup)
    }

    /// The checksum of operator `op` over every element, computed by one C++ loop with CGAL's
    /// circulators; an error when CGAL failed inside the loop.
    pub fn native_sweep(&self, op: Operator) -> Result<u64> {
        topology::sweep(self, op)
    }

    /// Prepares CGAL's sampled kernel of `op` over the queries of `sample` (see
    /// [`SampledKernel`]): every id checked against this mesh here and translated by the shim to
    /// the structure's own descriptors (a `Polyhedron_3`'s handles from its id tables), once,
    /// so that the timed runs translate and check nothing. An error when `op` has no sampled
    /// kernel (boundary curves), when the sample is not the kind of query `op` takes, when it
    /// names an element the mesh does not have ([`Error::ElementOutOfRange`]), or when CGAL
    /// failed to prepare it.
    pub fn native_sampled(&self, op: Operator, sample: Sample<'_>) -> Result<SampledKernel<'_, S>> {
        let ids = foreign::sample_ids(S::NAME, op, sample, ForeignMesh::counts(self))?;
        let mut raw = std::ptr::null_mut();
        // SAFETY: `self.raw` is live; `op` has a sampled kernel and `ids` holds `sample.len()`
        // queries of its input, every id checked against the mesh; `&mut raw` is a valid
        // out-pointer. The shim copies what it keeps from `ids`.
        let code = unsafe {
            ffi::topolab_cgal_prepare_sample(
                self.raw.as_ptr(),
                foreign::operator_code(op),
                ids.as_ptr(),
                sample.len(),
                &mut raw,
            )
        };
        status("topolab_cgal_prepare_sample", code)?;
        match NonNull::new(raw) {
            Some(raw) => Ok(SampledKernel {
                raw,
                mesh: PhantomData,
            }),
            None => {
                status("topolab_cgal_prepare_sample", foreign::EXCEPTION).map(|_| unreachable!())
            }
        }
    }

    /// Allocates what `workload` needs (the normal arrays for [`Workload::Normals`], the
    /// buffer of [`Workload::Smoothing`]), so that a timed [`Cgal::native_workload`] computes
    /// only; an error when the allocation failed.
    pub fn prepare_workload(&mut self, workload: Workload) -> Result<()> {
        topology::prepare_workload(self, workload)
    }

    /// Runs a Surface_mesh benchmark workload (Sieger & Botsch) in one C++ call; an error when
    /// CGAL failed inside it. The results go to arrays indexed by the lab's ids, kept across
    /// runs. What each returns (as the OpenMesh baseline's):
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
}

topology_api!(TOPOLOGY: ffi::RawMesh = [
    topolab_cgal_position,
    topolab_cgal_edge_vertices,
    topolab_cgal_is_boundary_vertex,
    topolab_cgal_is_boundary_edge,
    topolab_cgal_query,
    topolab_cgal_edge_neighbour,
    topolab_cgal_boundary_curves,
    topolab_cgal_halfedge,
    topolab_cgal_vertex_halfedge,
    topolab_cgal_face_halfedge,
    topolab_cgal_heap_bytes,
    topolab_cgal_validate,
    topolab_cgal_sweep,
    topolab_cgal_prepare_workload,
    topolab_cgal_workload,
]);

impl<S: CgalStructure> ForeignMesh for Cgal<S> {
    type Raw = ffi::RawMesh;
    const LIBRARY: &'static str = LIBRARY;
    const TOPOLOGY: TopologyApi<ffi::RawMesh> = TOPOLOGY;

    fn raw(&self) -> *mut ffi::RawMesh {
        self.raw.as_ptr()
    }

    fn counts(&self) -> [u32; 3] {
        [self.vertices, self.edges, self.faces]
    }
}

impl<S: CgalStructure> MeshTopology for Cgal<S> {
    const NAME: &'static str = S::NAME;

    topology_queries!(boundary_vertex: S::BOUNDARY_VERTEX);

    fn validate(&self) -> Result<()> {
        let (problem, element) = topology::validate(self)?;
        let message = match problem {
            0 => return Ok(()),
            1 => format!("halfedge {element}: next/prev/opposite/face links disagree"),
            2 => format!("vertex {element}: its halfedge does not point to it"),
            3 => format!("face {element}: its halfedge belongs to another face"),
            _ => "CGAL's own is_valid() fails".to_string(),
        };
        Err(Error::invariant(S::NAME, message))
    }

    fn explain(&self, w: &mut dyn Write) -> std::fmt::Result {
        foreign::explain_halfedges(w, self, S::TITLE, ("incoming", "in"))
    }

    fn native<'a>() -> Option<&'a dyn NativeKernels<Self>> {
        Some(&Kernels)
    }

    fn separate_construction<'a>() -> Option<&'a dyn SeparateConstruction<Self>> {
        Some(&Kernels)
    }

    fn access(op: Operator) -> Option<Access> {
        S::access(op)
    }
}

/// CGAL's sampled kernel of one operator, prepared by [`Cgal::native_sampled`]: the queries as
/// the structure's own descriptors, held by the shim (freed in `Drop`), answered by one C++
/// loop per run. It borrows its mesh, which the C++ side refers to.
pub struct SampledKernel<'a, S: CgalStructure> {
    /// The C++ `topolab_cgal_sample`, owned.
    raw: NonNull<ffi::RawSample>,
    /// The mesh the sample refers to, kept alive and unchanged while it lives.
    mesh: PhantomData<&'a Cgal<S>>,
}

impl<S: CgalStructure> SampledKernel<'_, S> {
    /// The checksum of the prepared queries, computed by one C++ loop with CGAL's circulators,
    /// answering each as the harness's generic kernel does; an error when CGAL failed inside
    /// the loop.
    pub fn run(&self) -> Result<u64> {
        let mut out = 0;
        // SAFETY: `raw` came from `topolab_cgal_prepare_sample` and is live; its mesh is
        // borrowed unchanged for the kernel's lifetime; `out` is a valid out-pointer.
        let code = unsafe { ffi::topolab_cgal_sampled(self.raw.as_ptr(), &mut out) };
        status("topolab_cgal_sampled", code).map(|()| out)
    }
}

impl<S: CgalStructure> Drop for SampledKernel<'_, S> {
    fn drop(&mut self) {
        // SAFETY: `raw` came from `topolab_cgal_prepare_sample` and is freed exactly once, here.
        unsafe { ffi::topolab_cgal_free_sample(self.raw.as_ptr()) }
    }
}

/// CGAL's own loops, as the harness times them ([`MeshTopology::native`]).
struct Kernels;

impl<S: CgalStructure> SeparateConstruction<Cgal<S>> for Kernels {
    fn admit<'a>(&self, soup: &'a PolygonSoup) -> Result<BuildFacts<'a>> {
        foreign::admit(soup)
    }

    fn construction(&self, facts: &BuildFacts<'_>) -> Result<Constructed<Cgal<S>>> {
        Cgal::construct(facts)
    }
}

impl<S: CgalStructure> NativeKernels<Cgal<S>> for Kernels {
    fn sweep(&self, mesh: &Cgal<S>, op: Operator) -> Result<u64> {
        mesh.native_sweep(op)
    }

    fn sampled<'a>(
        &self,
        mesh: &'a Cgal<S>,
        op: Operator,
        sample: Sample<'_>,
    ) -> Result<SampledRun<'a>> {
        let kernel = mesh.native_sampled(op, sample)?;
        Ok(Box::new(move || kernel.run()))
    }

    fn workload(&self, mesh: &mut Cgal<S>, workload: Workload) -> Result<f64> {
        mesh.native_workload(workload)
    }
}
