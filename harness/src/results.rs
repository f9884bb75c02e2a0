//! The results of a report run: what `results.json` holds and the HTML is drawn from.

use crate::machine::Machine;
use crate::probe::Probe;
use topolab_structures::{Capabilities, Operator};

/// Everything one run measured.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Results {
    /// Machine and build facts.
    pub machine: Machine,
    /// The memory probe, measured in the same run.
    pub probe: Probe,
    /// How the run was configured.
    pub settings: Settings,
    /// The structures measured, with their declared costs.
    pub structures: Vec<StructureInfo>,
    /// The meshes measured.
    pub meshes: Vec<MeshInfo>,
    /// One entry per (structure, operator, kernel, mesh).
    pub measurements: Vec<Measurement>,
    /// Fitted exponents of time per query against size.
    pub fits: Vec<FitRow>,
    /// libigl's reference timings, when it ran.
    pub libigl: Vec<LibiglRow>,
    /// The 3D convex hull algorithms (and Qhull) against n.
    pub hull: Vec<crate::hull::bench::HullRow>,
    /// Fitted exponents of the hull rows against n, next to the lecture's bounds.
    pub hull_fits: Vec<crate::hull::bench::HullFit>,
    /// What each structure stores for the open tetrahedron (teaching section).
    pub teaching: Vec<Teaching>,
    /// Anything the reader should know (skipped baselines, missing data).
    pub notes: Vec<String>,
}

/// Settings of a run.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Settings {
    /// `--quick`.
    pub quick: bool,
    /// Triangle counts of the size sweep.
    pub sizes: Vec<usize>,
    /// Sampled queries per kind.
    pub samples: usize,
    /// Time budget for repeating one cell, seconds.
    pub cell_budget_s: f64,
    /// A cell whose single run is estimated above this is skipped, seconds.
    pub cell_max_s: f64,
    /// The command that produced the results.
    pub command: String,
}

/// A structure and its declared costs.
#[derive(Clone, Debug, serde::Serialize)]
pub struct StructureInfo {
    /// Kebab-case name.
    pub name: String,
    /// What it stores.
    pub capabilities: Capabilities,
    /// Declared cost per operator.
    pub costs: Vec<CostRow>,
}

/// One declared cost.
#[derive(Clone, Debug, serde::Serialize)]
pub struct CostRow {
    /// The operator.
    pub operator: Operator,
    /// Its notation, e.g. `O(k)`.
    pub cost: String,
    /// The exponent it predicts.
    pub expected_exponent: f64,
}

/// A mesh of the run.
#[derive(Clone, Debug, serde::Serialize)]
pub struct MeshInfo {
    /// Its name (e.g. `torus-16k`).
    pub name: String,
    /// Its family (`torus`, `grid`, or `real`).
    pub family: String,
    /// Vertices.
    pub vertices: usize,
    /// Faces.
    pub faces: usize,
    /// Triangles (faces, when all are triangles).
    pub triangles: usize,
    /// A small SVG rendering.
    #[serde(skip)]
    pub thumbnail_svg: String,
}

/// Whether a cell was measured.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Status {
    /// Measured.
    Measured,
    /// Not run: its estimated time exceeded the budget.
    Skipped,
    /// The structure cannot store this mesh.
    Refused,
}

/// One cell: a structure, an operator (or workload, or construction), a kernel, a mesh.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Measurement {
    /// Structure name.
    pub structure: String,
    /// Operator, workload or `construction`.
    pub operator: String,
    /// `sweep`, `sampled`, `workload` or `construction`.
    pub kernel: String,
    /// Mesh name.
    pub mesh: String,
    /// Mesh family.
    pub family: String,
    /// Triangles (faces) of the mesh.
    pub triangles: usize,
    /// Measured, skipped or refused.
    pub status: Status,
    /// Median nanoseconds per item (query, element, or face for construction).
    pub ns_per_item: Option<f64>,
    /// Fastest run, per item.
    pub min_ns_per_item: Option<f64>,
    /// Slowest run, per item.
    pub max_ns_per_item: Option<f64>,
    /// Items per run.
    pub items: usize,
    /// Timed runs.
    pub reps: usize,
    /// The kernel's checksum (decimal u64, or the float result of a workload).
    pub checksum: Option<String>,
    /// Heap bytes the built structure holds (construction only; allocator-measured, or the
    /// C++ allocator's for baselines).
    pub bytes: Option<u64>,
    /// Peak heap bytes during construction, above what was allocated before.
    pub peak_bytes: Option<u64>,
    /// Bytes the structure's containers should take (`heap_bytes()`).
    pub declared_bytes: Option<u64>,
    /// For skipped cells: the estimate from smaller sizes, ns per item.
    pub estimate_ns_per_item: Option<f64>,
    /// Whether the structure ran the kernel natively (a baseline's own loop).
    pub native: bool,
    /// Why refused, or other remarks.
    pub note: Option<String>,
}

/// A fitted exponent.
#[derive(Clone, Debug, serde::Serialize)]
pub struct FitRow {
    /// Structure.
    pub structure: String,
    /// Operator.
    pub operator: String,
    /// Kernel.
    pub kernel: String,
    /// Mesh family.
    pub family: String,
    /// Fitted exponent of ns per query against triangles.
    pub exponent: f64,
    /// Its name (`constant`, `linear`, ...).
    pub class: String,
    /// The declared cost.
    pub theory: String,
    /// The exponent the declared cost predicts.
    pub expected_exponent: f64,
    /// Whether they agree.
    pub agrees: bool,
    /// Sizes used.
    pub points: usize,
}

/// One libigl reference timing.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct LibiglRow {
    /// Mesh name.
    pub mesh: String,
    /// The operator whose answer it computes.
    pub operator: String,
    /// The libigl function.
    pub function: String,
    /// Its checksum.
    pub checksum: String,
    /// Whether the checksum equals the lab's.
    pub agrees: bool,
    /// Nanoseconds per element (whole-mesh build divided by elements).
    pub ns_per_item: f64,
}

/// What a structure stores for the open tetrahedron.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Teaching {
    /// Structure.
    pub structure: String,
    /// Its `explain` text.
    pub text: String,
}
