//! The [`MeshTopology`] trait that every structure implements (answering the [`Operator`]s of
//! [`crate::core::operator`], each at the [`Cost`] the structure declares), and the
//! [`NativeKernels`] a baseline behind an FFI runs itself. Queries report their answers to a
//! callback (internal iteration), so they never allocate and are monomorphised in benchmarks; a
//! caller that wants the answers in a buffer pushes them into its own (`|v| out.push(v)`).

use crate::core::access::Access;
use crate::core::error::Result;
use crate::core::ids::{EdgeId, FaceId, VertexId};
pub use crate::core::operator::{Cost, Element, Input, Operator};
use crate::core::soup::PolygonSoup;
use crate::core::workload::Workload;
use glam::DVec3;

/// What kinds of meshes a structure can store.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Capabilities {
    /// Only triangles (others are refused with [`crate::Error::NotTriangles`]).
    pub triangles_only: bool,
    /// Vertices whose faces form several fans are stored and answered correctly (otherwise
    /// refused with [`crate::Error::NonManifoldVertex`]).
    pub non_manifold_vertices: bool,
    /// Only the regular grids of [`crate::meshes::grid`] (others refused with
    /// [`crate::Error::NotAGrid`]).
    pub grids_only: bool,
    /// Vertices are identified by position, so two vertices may not coincide (explicit
    /// storage); such input is refused with [`crate::Error::CoincidentVertices`].
    pub distinct_positions: bool,
}

impl Capabilities {
    /// Polygons of any size, manifold vertices only.
    pub const POLYGONS: Self = Self {
        triangles_only: false,
        non_manifold_vertices: false,
        grids_only: false,
        distinct_positions: false,
    };
}

/// Boundary curves written into a caller-owned buffer: curve `i` is
/// `edges[starts[i]..starts[i + 1]]`, its edges in walking order (consecutive edges share a
/// vertex, the last one meets the first).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BoundaryCurves {
    /// Edges of all curves, curve after curve.
    pub edges: Vec<EdgeId>,
    /// Start of each curve in `edges`, plus one final entry (`edges.len()`).
    pub starts: Vec<u32>,
}

impl BoundaryCurves {
    /// Empties the buffer, keeping its memory.
    pub fn clear(&mut self) {
        self.edges.clear();
        self.starts.clear();
        self.starts.push(0);
    }

    /// Closes the curve whose edges were pushed since the last call.
    pub fn end_curve(&mut self) {
        if self.starts.is_empty() {
            self.starts.push(0);
        }
        self.starts.push(self.edges.len() as u32);
    }

    /// Number of curves.
    pub fn len(&self) -> usize {
        self.starts.len().saturating_sub(1)
    }

    /// `true` without curves.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The edges of curve `i`.
    pub fn curve(&self, i: usize) -> &[EdgeId] {
        &self.edges[self.starts[i] as usize..self.starts[i + 1] as usize]
    }
}

/// The first three corners of face `f` and how many corners it has: a triangle whole, a
/// polygon's first three (as OpenMesh's face-vertex walk takes them). Corners past the count
/// are `VertexId(u32::MAX)`.
#[inline(always)]
pub fn first_three_corners<M: MeshTopology>(m: &M, f: FaceId) -> ([VertexId; 3], usize) {
    let mut corners = [VertexId(u32::MAX); 3];
    let mut k = 0;
    m.face_vertices(f, |v| {
        if k < 3 {
            corners[k] = v;
        }
        k += 1;
    });
    (corners, k)
}

/// One interface to every mesh data structure of the lab.
///
/// Vertex and face ids are the input's ([`PolygonSoup`] order); edge ids are the structure's own
/// and are enumerated by [`MeshTopology::for_each_edge`]. Queries call `f` once per answer and
/// never allocate (the enumeration `for_each_edge` may; see there). Relations are multisets; R20
/// and R21 answer in the face's cyclic order.
///
/// ## Fairness
///
/// The lab compares structures, so each one is measured at the speed its design allows, under
/// the same rules:
///
/// - **Inlining.** Every query method of every impl carries `#[inline]`: the counts,
///   [`MeshTopology::position`] and the operators' methods (every method except how a
///   structure is described, built, enumerated, validated, measured and explained, and the
///   baselines' native loops). A benchmark in another crate can then inline any query, and no
///   structure is left behind a call while another is inlined. `structures/tests/inlining.rs`
///   reads every registered structure's impl and fails on a query method without it.
/// - **Walking a fan.** R00, R01 and R02 answer sets, so a structure may walk a vertex's fan
///   from both ends at once: two independent chains of dependent loads instead of one. That
///   walk was offered to every structure that walks fans and is kept where it measured
///   faster: the CHE levels 2 and 3 (interior vertices; a boundary vertex's other end is not
///   stored) and the winged-edge. The index and the pointer half-edge rotate one way: the
///   second chain measured no faster there (see
///   [`families::half_edge`](crate::families::half_edge)). Traces for teaching (the CHE's
///   `vertex_star`) keep their source's order.
/// - **Bounds checks.** Every index is checked, with one exception: a structure that never
///   changes its arrays after it is built may check once, when it is built, that every id
///   they hold is in range, and then read without checks. The CHE levels 2 and 3 do this in
///   their vertex star (one audited module, `families::che::fan`), and `validate()` checks
///   the ranges again. The index half-edge and the winged-edge are edited in place
///   (`MeshEdit`; `add_face` and `remove_face`), so a check made when they are built would
///   not stay true. The index half-edge was measured with unchecked reads anyway, and they did
///   not pay (see [`families::half_edge`](crate::families::half_edge)). Where a query reads
///   several arrays at one index, their lengths are asserted equal once per query, so one
///   check covers them (the index half-edge's per-half-edge arrays).
/// - **Baselines** (OpenMesh) are used as their documented API is used, inside their own
///   loops ([`MeshTopology::native`]), and are not re-tuned.
///
/// A structure owns what it stores (`'static`): the harness holds every structure of a mesh
/// side by side, as one kind of value, through the rounds of a measurement.
pub trait MeshTopology: Sized + 'static {
    /// The kebab-case name used in the CLI, JSON and report.
    const NAME: &'static str;

    /// The family it belongs to (what it stores for adjacency); the default, for structures
    /// the lab did not write, is [`crate::Family::Outside`].
    const FAMILY: crate::core::family::Family = crate::core::family::Family::Outside;

    /// What kinds of meshes it stores.
    fn capabilities() -> Capabilities;

    /// The theoretical cost of `op` in this structure (the polygon-mesh lecture's tables, the CHE
    /// thesis chapter's Table 4.1).
    fn cost(op: Operator) -> Cost;

    /// Builds the structure; fails with a typed error on input it cannot store.
    fn from_soup(soup: &PolygonSoup) -> Result<Self>;

    /// [`MeshTopology::from_soup`] consuming the soup, for a caller that needs it no more
    /// (`topolab info`): a structure whose arrays are the soup's (the CHE's `G[]` and `V[]`)
    /// takes them instead of copying them, so the soup and the structure are not held at
    /// once. The same structure and the same refusals as `from_soup`; the default builds from
    /// the soup, then drops it.
    fn from_soup_owned(soup: PolygonSoup) -> Result<Self> {
        Self::from_soup(&soup)
    }

    /// Number of vertices (including unused ones).
    fn num_vertices(&self) -> usize;
    /// Number of undirected edges.
    fn num_edges(&self) -> usize;
    /// Number of faces.
    fn num_faces(&self) -> usize;
    /// Number of boundary edges (edges with one face).
    #[inline]
    fn num_boundary_edges(&self) -> usize {
        let mut n = 0;
        self.for_each_edge(|e| n += self.is_boundary_edge(e) as usize);
        n
    }

    /// Calls `f` with every edge id, each once.
    ///
    /// An enumeration, not one of the queries: the callers (the harness building its query
    /// lists, the conformance suite) run it once, outside any timing, so a structure that
    /// stores no edges may allocate here. CHE level 0 does: without `O[]` it sorts its
    /// half-edges by vertex pair in a temporary buffer (O(n2 log n2)) instead of scanning for
    /// each half-edge's twin (O(n2²)), and its `num_edges` counts this enumeration.
    fn for_each_edge(&self, f: impl FnMut(EdgeId));

    /// Position of vertex `v`.
    fn position(&self, v: VertexId) -> DVec3;

    /// R00: the neighbour vertices of `v`.
    fn vertex_vertices(&self, v: VertexId, f: impl FnMut(VertexId));
    /// R01: the edges incident to `v`.
    fn vertex_edges(&self, v: VertexId, f: impl FnMut(EdgeId));
    /// R02: the faces incident to `v`.
    fn vertex_faces(&self, v: VertexId, f: impl FnMut(FaceId));
    /// R10: the two end vertices of `e`.
    fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2];
    /// R11: the other edges of the faces incident to `e`.
    fn edge_edges(&self, e: EdgeId, f: impl FnMut(EdgeId));
    /// R12: the one or two faces of `e`.
    fn edge_faces(&self, e: EdgeId, f: impl FnMut(FaceId));
    /// R20: the vertices of `face` in order.
    fn face_vertices(&self, face: FaceId, f: impl FnMut(VertexId));
    /// R21: the edges of `face` in order (edge i joins vertex i and i + 1 of R20).
    fn face_edges(&self, face: FaceId, f: impl FnMut(EdgeId));
    /// R22: the faces across the edges of `face` (boundary edges contribute nothing).
    fn face_faces(&self, face: FaceId, f: impl FnMut(FaceId));

    /// Is `v` on the boundary (incident to a boundary edge)?
    fn is_boundary_vertex(&self, v: VertexId) -> bool;
    /// Is `e` on the boundary (one face only)?
    fn is_boundary_edge(&self, e: EdgeId) -> bool;
    /// Writes every boundary curve into `out` (cleared first), as the lab defines them (see
    /// [`crate::summary`]): at a vertex whose faces form several fans, each fan's two boundary
    /// edges follow each other, so each fan's boundary continues within that fan.
    fn boundary_curves(&self, out: &mut BoundaryCurves);
    /// The edge after `e` in `face`'s cycle, `None` if `e` is not an edge of `face`.
    fn edge_successor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId>;
    /// The edge before `e` in `face`'s cycle, `None` if `e` is not an edge of `face`.
    fn edge_predecessor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId>;

    /// Checks every invariant of the structure's containers.
    fn validate(&self) -> Result<()>;

    /// Bytes its containers hold (capacity of every array, each record counted once): what
    /// the structure *should* take, to compare with the allocator's measurement.
    fn heap_bytes(&self) -> usize;

    /// For teaching: what the structure stores, record by record, with the lecture's field names.
    fn explain(&self, w: &mut dyn std::fmt::Write) -> std::fmt::Result;

    /// The kernels a baseline runs itself, for timing (see [`NativeKernels`]): with them, every
    /// kernel of the structure is timed natively; `None` (the default): the harness times
    /// [`MeshTopology::from_soup`] and its own generic kernels.
    /// (A baseline returns a constant; the lifetime `'a` spares the structures generic over
    /// a type, such as the half-edge over its links, a `'static` bound.)
    fn native<'a>() -> Option<&'a dyn NativeKernels<Self>> {
        None
    }

    /// Construction in two steps for a structure built by another project's code (the C++
    /// baselines, the Rust crates of `topolab-peers`; see [`SeparateConstruction`]): the lab's
    /// checks before the clock, the project's own build under it, so that the report times
    /// every outside project's construction alike; `None` (the default): the harness times
    /// [`MeshTopology::from_soup`], whose checks are part of the lab's own structures' build.
    fn separate_construction<'a>() -> Option<&'a dyn SeparateConstruction<Self>> {
        None
    }

    /// The checks of its input that [`MeshTopology::from_soup`] makes as a step of their own
    /// before it builds (the structures built from the soup's edge analysis:
    /// [`PolygonSoup::manifold_connectivity`]), so that the report can time them apart: a
    /// construction target against an outside project, whose checks run before its clock,
    /// shows their share. `None` (the default): no such step (the CHE pairs its half-edges and
    /// checks them in one pass).
    fn input_checks() -> Option<InputChecks> {
        None
    }

    /// What one query of `op` reads from memory ([`Access`]: bytes per container, dependent
    /// loads on its longest chain), declared beside [`MeshTopology::cost`] for the limit the
    /// report puts on each sweep; `None` (the default): no model, no limit.
    fn access(op: Operator) -> Option<Access> {
        let _ = op;
        None
    }
}

/// The sampled queries of one operator, in the lab's ids of the structure they are asked of
/// ([`Operator::input`] says which kind an operator takes): what a baseline's sampled kernel
/// ([`NativeKernels::sampled`]) answers, the same queries as the harness's generic kernel.
#[derive(Copy, Clone, Debug)]
pub enum Sample<'a> {
    /// Vertices ([`Input::Vertex`]).
    Vertices(&'a [VertexId]),
    /// Edges ([`Input::Edge`]).
    Edges(&'a [EdgeId]),
    /// Faces ([`Input::Face`]).
    Faces(&'a [FaceId]),
    /// (edge, face) pairs ([`Input::EdgeOfFace`]): the successor or predecessor of the edge in
    /// that face.
    EdgesOfFaces(&'a [(EdgeId, FaceId)]),
}

impl Sample<'_> {
    /// The kind of query this sample holds.
    pub const fn input(&self) -> Input {
        match self {
            Sample::Vertices(_) => Input::Vertex,
            Sample::Edges(_) => Input::Edge,
            Sample::Faces(_) => Input::Face,
            Sample::EdgesOfFaces(_) => Input::EdgeOfFace,
        }
    }

    /// How many queries it holds.
    pub const fn len(&self) -> usize {
        match self {
            Sample::Vertices(ids) => ids.len(),
            Sample::Edges(ids) => ids.len(),
            Sample::Faces(ids) => ids.len(),
            Sample::EdgesOfFaces(pairs) => pairs.len(),
        }
    }

    /// `true` when it holds no query.
    pub const fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// A structure's checks of its input as a step of their own ([`MeshTopology::input_checks`]):
/// the soup's edge analysis, or its refusal.
pub type InputChecks = fn(&PolygonSoup) -> Result<crate::core::soup::Connectivity>;

/// The construction of a structure built by another project's code (a C++ baseline behind
/// the FFI, a Rust crate of `topolab-peers`), in three steps, so that the harness's clock
/// covers the project's own construction and nothing else: [`SeparateConstruction::admit`]
/// before the clock (the lab's checks, which refuse what the project would mis-handle, and
/// the counts it reserves for), [`SeparateConstruction::construction`] timed, and
/// [`Constructed::finish`] after the clock (what the lab adds for its queries: id tables,
/// counts). The structure is dropped after the clock too, like every structure's. The lab's
/// own structures have no such split: their checks are part of their construction and are
/// timed with it. Reached through [`MeshTopology::separate_construction`];
/// `from_soup` of such a structure is `admit`, `construction` and `finish` in a row.
pub trait SeparateConstruction<M> {
    /// The lab's checks of `soup` that [`MeshTopology::from_soup`] makes before the project
    /// builds (so that a soup is refused as `from_soup` refuses it, with the same typed error),
    /// and the facts the construction is told ([`BuildFacts`]). Not timed.
    fn admit<'a>(&self, soup: &'a PolygonSoup) -> Result<BuildFacts<'a>>;

    /// Construction the way the project's own API does it (OpenMesh: `reserve` with the
    /// facts' counts, `add_vertex`, `add_face`; lox: `add_vertex`, `add_face`), without the
    /// lab's checks, which are not the project's cost: what the harness times. Given facts
    /// that did not come from [`SeparateConstruction::admit`], a face the project refuses is
    /// an error named the lab's way, never a panic.
    fn construction(&self, facts: &BuildFacts<'_>) -> Result<Constructed<M>>;

    /// [`MeshTopology::from_soup`] of such a structure: admit, construct and finish in a row.
    fn build(&self, soup: &PolygonSoup) -> Result<M> {
        self.construction(&self.admit(soup)?)?.finish(soup)
    }
}

/// A baseline's sampled kernel, prepared by [`NativeKernels::sampled`]: each call runs the
/// whole loop over the prepared queries on the other side of the FFI and returns the harness's
/// checksum, or the library's failure inside the loop.
pub type SampledRun<'a> = Box<dyn Fn() -> Result<u64> + 'a>;

/// The kernels of a baseline behind an FFI boundary (OpenMesh, CGAL), which the harness times
/// instead of its own: per-query calls across the FFI would measure the FFI instead of the
/// library, so whole loops run on the other side and return the harness's checksum. Reached
/// through [`MeshTopology::native`].
///
/// Its construction comes in separate steps too ([`SeparateConstruction`], a supertrait, so
/// that no baseline can have native kernels and a construction timed with the lab's checks).
///
/// A baseline has every kernel: a structure with native kernels is timed by them alone,
/// never by the harness's generic kernels, so a kernel that cannot run is an error of the
/// measurement, not a silent fallback. `Err` is also how a failure of the library inside a
/// loop arrives (an exception caught at the FFI wall): a loud error, never a silent zero.
pub trait NativeKernels<M>: SeparateConstruction<M> {
    /// A whole sweep of `op` over every element of `mesh`, folded into the harness's checksum.
    fn sweep(&self, mesh: &M, op: Operator) -> Result<u64>;

    /// Prepares the sampled kernel of `op` over `sample`, once, before anything is timed:
    /// checks every id against `mesh` and hands the queries to the library in its own handles,
    /// so that the timed run translates nothing. The run answers exactly the queries of
    /// `sample`, as the harness's generic kernel does, with the same checksum. An error when
    /// `sample` is not the kind of query `op` takes, holds an id `mesh` does not have, or `op`
    /// has no sampled kernel ([`Input::Mesh`]).
    fn sampled<'a>(&self, mesh: &'a M, op: Operator, sample: Sample<'_>) -> Result<SampledRun<'a>>;

    /// An application workload, returning its result. Takes `&mut M` because a baseline may
    /// keep its results (normals) in the mesh; running it twice must give the same result.
    fn workload(&self, mesh: &mut M, workload: Workload) -> Result<f64>;
}

/// What a baseline's construction is told about its soup before the clock starts: the soup,
/// checked ([`PolygonSoup::check`]: every index in range, so a construction given these facts
/// needs no check of its own before handing the indices to a library), and its vertex, edge
/// and face counts, the numbers a library's `reserve` takes. The lab's own structures build
/// from the soup alone, which has the same facts: its vertex and face counts, and the edges
/// they count in their edge analysis, which they need for their links anyway and which is
/// timed as part of their construction. A library finds edges its own way (`add_face`) and
/// needs their number only to reserve, so it is told it ([`SeparateConstruction::admit`] takes it
/// from the same analysis, exact for open meshes and polygons too).
#[derive(Copy, Clone, Debug)]
pub struct BuildFacts<'a> {
    soup: &'a PolygonSoup,
    edges: u32,
}

impl<'a> BuildFacts<'a> {
    /// The facts of `soup` with `edges` edges (at most `u32::MAX` is kept): fails when the
    /// soup does not pass [`PolygonSoup::check`]. The edge count is a reservation, not a
    /// promise the library relies on: exact from the lab's edge analysis
    /// ([`crate::Connectivity::num_edges`]), anything else from a caller that wants to see a
    /// library grow its arrays.
    pub fn new(soup: &'a PolygonSoup, edges: usize) -> Result<Self> {
        soup.check()?;
        Ok(Self {
            soup,
            edges: u32::try_from(edges).unwrap_or(u32::MAX),
        })
    }

    /// The soup, checked.
    pub fn soup(&self) -> &'a PolygonSoup {
        self.soup
    }

    /// Its number of vertices.
    pub fn vertices(&self) -> u32 {
        // `check` refuses counts that do not fit `u32`.
        self.soup.num_vertices() as u32
    }

    /// Its number of (undirected) edges, as given to [`BuildFacts::new`].
    pub fn edges(&self) -> u32 {
        self.edges
    }

    /// Its number of faces.
    pub fn faces(&self) -> u32 {
        self.soup.num_faces() as u32
    }
}

/// A structure as its timed construction left it ([`SeparateConstruction::construction`], or
/// [`Constructed::ready`] around a lab structure): it answers no query before
/// [`Constructed::finish`], which runs after the clock what the lab adds to the library's
/// structure for its queries (CGAL's `Polyhedron_3`: the tables from id to handle; for every
/// baseline, reading its counts), and hands the structure over. Dropping it frees the
/// structure.
pub struct Constructed<M> {
    mesh: M,
    finish: fn(&mut M, &PolygonSoup) -> Result<()>,
}

impl<M> Constructed<M> {
    /// `mesh`, which `finish` makes ready for queries, given the soup it was built from (for
    /// tables from the lab's ids to the project's).
    pub fn new(mesh: M, finish: fn(&mut M, &PolygonSoup) -> Result<()>) -> Self {
        Self { mesh, finish }
    }

    /// `mesh`, ready for queries already (the lab's structures, built by
    /// [`MeshTopology::from_soup`]).
    pub fn ready(mesh: M) -> Self {
        Self::new(mesh, |_, _| Ok(()))
    }

    /// Runs the finishing step with the soup the structure was built from; the structure,
    /// ready for queries.
    pub fn finish(self, soup: &PolygonSoup) -> Result<M> {
        let Self { mut mesh, finish } = self;
        finish(&mut mesh, soup)?;
        Ok(mesh)
    }
}

impl<M> std::fmt::Debug for Constructed<M> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Constructed { .. }")
    }
}
