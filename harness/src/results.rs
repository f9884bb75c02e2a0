//! The results of a report run: what `results.json` holds and the HTML is drawn from.

use crate::kernels::Kernel;
use crate::machine::Machine;
use crate::probe::Probe;
use topolab_structures::{Capabilities, Cost, Family, Operator, Step, Workload};

/// The version of `results.json`'s format, written as its `format_version`: raised when a
/// field that readers rely on (`topolab compare` reads the machine, the settings' command, the
/// meshes and the measurements) changes its meaning or its name. Adding a field does not raise
/// it. Files without the field were written before it existed; their measurements read as
/// version 1's (version 0).
pub const FORMAT_VERSION: u32 = 1;

/// Everything one run measured.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Results {
    /// [`FORMAT_VERSION`] of the code that wrote it.
    pub format_version: u32,
    /// Machine and build facts.
    pub machine: Machine,
    /// How each outside library was built, used, timed and counted ([`crate::baselines`]).
    pub baselines: Vec<crate::baselines::BaselineRun>,
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
    pub hull: Vec<HullRow>,
    /// Fitted exponents of the hull rows against n, next to the lecture's bounds.
    pub hull_fits: Vec<HullFit>,
    /// How the hull section ran Qhull (its library's version and options), when it did.
    pub qhull: Option<String>,
    /// The changing workloads (√3 subdivision, the collapse test) on the editable structures.
    pub changing: Vec<crate::changing::ChangingRow>,
    /// Adaptive refinement in one region of each torus on the editable structures (the
    /// changing section's local refinement).
    pub local_refinement: crate::changing::LocalRefinement,
    /// The lecture's editing operations, one at a time, on the editable structures and
    /// explicit storage ([`crate::report::sections::edit_ops`]).
    pub edit_ops: Vec<EditOpRow>,
    /// The Targets table's rounds: the structures of each target taking turns
    /// ([`crate::targets`]).
    pub targets: Vec<Turns>,
    /// Decimation by quadric error (the lab's, OpenMesh's, CGAL's) and the reconstruction.
    pub decimate: Vec<crate::decimate::DecimateRow>,
    /// What each structure stores for the open tetrahedron (teaching section).
    pub teaching: Vec<Teaching>,
    /// Edits shown record by record, with the mesh before and after (teaching section,
    /// `edit_explain::teaching_edits`).
    pub teaching_edits: Vec<TeachingEdit>,
    /// Reads per query of every operator on every structure against mesh size, counted
    /// ([`crate::reads::count`]).
    pub reads: Vec<ReadsRow>,
    /// Anything the reader should know (skipped baselines, missing data).
    pub notes: Vec<String>,
    /// How long each section of the run took, wall and CPU ([`crate::phases`]).
    pub phases: Vec<crate::phases::PhaseTime>,
    /// The rounds of each mesh of the size sweep.
    pub rounds: Vec<MeshRoundsRow>,
    /// The drift probe, read before every mesh of the size sweep ([`crate::probe::Drift`]).
    pub drift: Vec<crate::probe::DriftPoint>,
}

/// Settings of a run.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Settings {
    /// `--quick`.
    pub quick: bool,
    /// Triangle counts of the size sweep.
    pub sizes: Vec<usize>,
    /// Sampled queries drawn per kind and round.
    pub samples: usize,
    /// How the cells were measured in rounds.
    pub rounds: RoundSettings,
    /// A cell whose single run is estimated above this is skipped, seconds.
    pub cell_max_s: f64,
    /// The command that produced the results.
    pub command: String,
    /// The sections of the report this run measured and shows (`--sections`), by name, in
    /// page order.
    pub sections: Vec<&'static str>,
}

/// How the size sweep's cells were measured in rounds ([`crate::rounds`]).
#[derive(Clone, Debug, serde::Serialize)]
pub struct RoundSettings {
    /// Rounds every cell got.
    pub min_rounds: usize,
    /// Rounds no cell passed.
    pub max_rounds: usize,
    /// Extra rounds for wide cells could take this share of the first rounds' time.
    pub extra: f64,
    /// Queries of a sampled pass.
    pub pass: usize,
    /// Timed ns of one cell in one round, at least.
    pub round_ns: f64,
    /// An interval wider than this share of its value asked for extra rounds.
    pub wide: f64,
}

/// The rounds one mesh of the size sweep took.
#[derive(Clone, Debug, serde::Serialize)]
pub struct MeshRoundsRow {
    /// The mesh.
    pub mesh: String,
    /// Rounds made (the most any cell got).
    pub rounds: usize,
    /// Of them, extra rounds for wide or wanted cells.
    pub extra: usize,
    /// Wall time of all of them, seconds.
    pub seconds: f64,
}

/// A structure and its declared costs.
#[derive(Clone, Debug, serde::Serialize)]
pub struct StructureInfo {
    /// Kebab-case name.
    pub name: String,
    /// Its family (what it stores for adjacency), as it declares it.
    pub family: Family,
    /// Whether it offers the editing operations (`MeshEdit`), which the changing workloads run.
    #[serde(default)]
    pub editable: bool,
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
    /// The declared cost, written in its notation, e.g. `O(k)`.
    #[serde(serialize_with = "notation")]
    pub cost: Cost,
    /// The exponent it predicts.
    pub expected_exponent: f64,
    /// What one query reads from memory, when the structure declares it (the limit of its
    /// sweeps, [`crate::limit`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub access: Option<topolab_structures::Access>,
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
    /// Its element counts, for the limits of its sweeps (`None` when its edges cannot be
    /// analysed).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub counts: Option<MeshCounts>,
    /// What `topolab repair` changed, when the file as read was refused by the structures
    /// that need an oriented manifold and its repaired version was measured instead.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub repaired: Option<topolab_structures::repair::RepairLog>,
}

/// Writes a cost in its notation (`O(k)`), as results.json has it.
fn notation<S: serde::Serializer>(cost: &Cost, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(cost.notation())
}

/// Whether a cell was measured.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Status {
    /// Measured.
    Measured,
    /// Not run: its estimated time exceeded the budget.
    Skipped,
    /// The structure cannot store this mesh.
    Refused,
}

/// What a measurement measures: building a structure, one of its operators, or a workload.
/// Results write it by name in their `operator` field (`construction`, `r00`, `normals`, ...).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum Subject {
    /// Building the structure.
    Construction,
    /// An operator.
    Query(Operator),
    /// An application workload.
    Workload(Workload),
}

impl Subject {
    /// The name results give it.
    pub const fn name(self) -> &'static str {
        match self {
            Subject::Construction => "construction",
            Subject::Query(op) => op.name(),
            Subject::Workload(w) => w.name(),
        }
    }

    /// The subject of a name (operator, workload and construction names are distinct).
    pub fn from_name(name: &str) -> Option<Self> {
        if name == Subject::Construction.name() {
            return Some(Subject::Construction);
        }
        Operator::from_name(name)
            .map(Subject::Query)
            .or_else(|| Workload::from_name(name).map(Subject::Workload))
    }
}

impl std::fmt::Display for Subject {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl serde::Serialize for Subject {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl<'de> serde::Deserialize<'de> for Subject {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let name = <std::borrow::Cow<'de, str>>::deserialize(d)?;
        Subject::from_name(&name).ok_or_else(|| {
            serde::de::Error::custom(format!(
                "unknown operator {name:?}: not an operator, a workload or construction"
            ))
        })
    }
}

/// One cell: a structure, an operator (or workload, or construction), a kernel, a mesh.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Measurement {
    /// Structure name.
    pub structure: String,
    /// Operator, workload or construction (written by name).
    pub operator: Subject,
    /// `sweep` or `sampled` for an operator, `workload` or `construction` for the others.
    pub kernel: Kernel,
    /// Mesh name.
    pub mesh: String,
    /// Mesh family.
    pub family: String,
    /// Triangles (faces) of the mesh.
    pub triangles: usize,
    /// Measured, skipped or refused.
    pub status: Status,
    /// Nanoseconds per item (query, element, or face for construction): the median of the
    /// rounds' values ([`crate::rounds`]).
    pub ns_per_item: Option<f64>,
    /// The fastest round, per item.
    pub min_ns_per_item: Option<f64>,
    /// The slowest round, per item.
    pub max_ns_per_item: Option<f64>,
    /// Where the median lies, per item: the order-statistics interval of the rounds' median
    /// ([`crate::timing::interval`]), `[low, high]`, with the probability `ci_coverage`
    /// (at least 0.95 from six rounds on).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ns_per_item_ci: Option<[f64; 2]>,
    /// The probability that `ns_per_item_ci` holds the median.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ci_coverage: Option<f64>,
    /// Each round's value, ns per item, in the order of the rounds it took part in (empty, and
    /// not written, for a cell not measured in rounds): what the median and its interval were
    /// taken of.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub round_ns_per_item: Vec<f64>,
    /// Rounds the cell was measured in, each on a fresh build (0, and not written, for a cell
    /// not measured in rounds).
    #[serde(default, skip_serializing_if = "no_rounds")]
    pub rounds: usize,
    /// Items per run: the elements of a sweep or workload, the faces of a construction, the
    /// queries of a sampled cell's first round.
    pub items: usize,
    /// Timed runs over all rounds (a sampled cell's: its passes).
    pub reps: usize,
    /// The kernel's checksum (decimal u64, or the float result of a workload).
    pub checksum: Option<String>,
    /// Heap bytes the built structure holds (construction only), counted by the allocator
    /// with one rule for Rust's and C++'s blocks (their usable sizes).
    pub bytes: Option<u64>,
    /// Peak heap bytes during construction, above what was allocated before.
    pub peak_bytes: Option<u64>,
    /// Bytes the structure's containers should take (`heap_bytes()`).
    pub declared_bytes: Option<u64>,
    /// For skipped cells: the estimate from smaller sizes, ns per item.
    pub estimate_ns_per_item: Option<f64>,
    /// Whether the cell is a baseline's own loop ([`topolab_structures::NativeKernels`]): true
    /// for every cell of a baseline behind an FFI, skipped ones included (they would be), and
    /// false for the lab's structures, which the harness's generic kernels time.
    pub native: bool,
    /// Why refused, or other remarks.
    pub note: Option<String>,
    /// Construction only: median ns per face of the cold builds, each made right after the
    /// allocator returned its free memory to the kernel (`ns_per_item` is the warm builds',
    /// which reuse the memory of the build before them).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cold_ns_per_item: Option<f64>,
    /// Construction only: median minor page faults of one warm build.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub page_faults: Option<u64>,
    /// Construction only: median minor page faults of one cold build.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cold_page_faults: Option<u64>,
    /// Sweeps of a structure that declares its access model: the time the model allows
    /// ([`crate::limit`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub limit: Option<Limit>,
}

/// Whether a cell has no rounds (serde's test for leaving the field out).
fn no_rounds(rounds: &usize) -> bool {
    *rounds == 0
}

impl Measurement {
    /// A measured cell with nothing timed yet: every optional field empty, zero items and runs.
    pub fn new(
        structure: &str,
        operator: Subject,
        kernel: Kernel,
        mesh: &str,
        family: &str,
        triangles: usize,
    ) -> Self {
        Measurement {
            structure: structure.into(),
            operator,
            kernel,
            mesh: mesh.into(),
            family: family.into(),
            triangles,
            status: Status::Measured,
            ns_per_item: None,
            min_ns_per_item: None,
            max_ns_per_item: None,
            ns_per_item_ci: None,
            ci_coverage: None,
            round_ns_per_item: Vec::new(),
            rounds: 0,
            items: 0,
            reps: 0,
            checksum: None,
            bytes: None,
            peak_bytes: None,
            declared_bytes: None,
            estimate_ns_per_item: None,
            native: false,
            note: None,
            cold_ns_per_item: None,
            page_faults: None,
            cold_page_faults: None,
            limit: None,
        }
    }
}

/// A fitted exponent.
#[derive(Clone, Debug, serde::Serialize)]
pub struct FitRow {
    /// Structure.
    pub structure: String,
    /// Operator.
    pub operator: Operator,
    /// Kernel (sweep or sampled).
    pub kernel: Kernel,
    /// Mesh family.
    pub family: String,
    /// Fitted exponent of ns per query against triangles.
    pub exponent: f64,
    /// Its name (`constant`, `linear`, ...).
    pub class: String,
    /// The declared cost, written in its notation.
    #[serde(serialize_with = "notation")]
    pub theory: Cost,
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
    /// The operator (or workload) whose answer it computes.
    pub operator: Subject,
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

/// One edit on one structure for the teaching section: the records it wrote, as
/// `topolab explain NAME --op OP` prints them, and the mesh before and after.
#[derive(Clone, Debug, serde::Serialize)]
pub struct TeachingEdit {
    /// The operation.
    pub op: topolab_structures::EditOp,
    /// The structure.
    pub structure: String,
    /// The mesh, in words.
    pub mesh: String,
    /// The element edited, in words ("edge 1 (v1 - v3)").
    pub subject: String,
    /// The records that changed, one line each (`  key.field: old -> new`, `+ key: new`,
    /// `- key: old`).
    pub changes: Vec<String>,
    /// The mesh before the edit, the element marked.
    pub before: EditPicture,
    /// The mesh after it, what the edit made marked.
    pub after: EditPicture,
}

/// A small mesh to draw: its vertices (`None` where deleted), its faces and what is marked.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct EditPicture {
    /// Each vertex's position, `None` for a deleted vertex.
    pub vertices: Vec<Option<[f64; 3]>>,
    /// The live faces, each its corners counter-clockwise.
    pub faces: Vec<Vec<u32>>,
    /// The vertices drawn marked.
    pub marked_vertices: Vec<u32>,
    /// The edges drawn marked, by their ends.
    pub marked_edges: Vec<[u32; 2]>,
}

// The rows whose modules compute them from the records above (limits, hulls, reads per
// query) are defined here, so that those modules read the schema and the schema names none
// of them.

/// The element counts a mesh's containers and a sweep's answers follow.
#[derive(Copy, Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct MeshCounts {
    /// Vertices.
    pub vertices: usize,
    /// Edges.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// Corners (the sum of the faces' sizes).
    pub corners: usize,
    /// Edges with one face.
    pub boundary_edges: usize,
}

/// Which bound sets a limit.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Bound {
    /// The bytes at the bandwidth.
    Bandwidth,
    /// The chain at the load latency.
    Latency,
    /// The harness's checksum arithmetic, per answer.
    Checksum,
}

/// The limit of one sweep cell.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Limit {
    /// The limit, ns per item: the largest of the three bounds.
    pub ns_per_item: f64,
    /// Which bound it is.
    pub bound: Bound,
    /// Bytes read per item (containers capped at their size, scans in full), over the
    /// bandwidth of `bandwidth_level`.
    pub bytes_per_item: f64,
    /// The bandwidth bound, ns per item.
    pub bandwidth_ns_per_item: f64,
    /// The probe level whose bandwidth it uses (the working set of the containers read).
    pub bandwidth_level: String,
    /// Dependent loads on the chain per item, at the latency of `latency_level`.
    pub loads_per_item: f64,
    /// The latency bound, ns per item.
    pub latency_ns_per_item: f64,
    /// The probe level whose latency it uses (the working set of one query).
    pub latency_level: String,
    /// The checksum's arithmetic, ns per item: its terms at the probe's time per term.
    pub checksum_ns_per_item: f64,
    /// Checksum terms per item (one per answer; one per edge for R10).
    #[serde(default)]
    pub checksum_terms_per_item: f64,
    /// The work of each step of the chain, as the model declares it.
    #[serde(default)]
    pub step: Step,
    /// The chain at the latency of a step doing that work, ns per item: the loads at the
    /// probe's chase of that kind at `latency_level` ([`crate::probe::Level::step_ns`]). Not a
    /// bound of the limit, which counts plain loads as the model declares them: shown beside
    /// it, it measures what the arithmetic on the chain costs.
    #[serde(default)]
    pub chain_ns_per_item: f64,
    /// What the structure says the model leaves out, if it knows.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// One timed hull. (`Default`, so that a row of an outside hull, such as CGAL's, names only
/// what it has.)
#[derive(Clone, Debug, Default, serde::Serialize)]
pub struct HullRow {
    /// `cube`, `ball` or `sphere`.
    pub shape: String,
    /// Number of points.
    pub n: usize,
    /// `gift`, `incremental`, `randomized`, or an outside hull's name (`qhull`, CGAL's
    /// `cgal-convex-hull-3`).
    pub algorithm: String,
    /// The median of the timed runs after a warm-up run (`hull::bench::warm_median`), seconds.
    pub seconds: f64,
    /// How many timed runs `seconds` is the median of (`hull::bench::timed_runs`).
    pub timed_runs: usize,
    /// Faces created during the construction (`None` for an outside hull).
    pub faces_created: Option<usize>,
    /// Vertices of the hull.
    pub hull_vertices: usize,
    /// `hull::bench::vertex_checksum` of the hull's vertices (`None` for CGAL's, whose shim returns
    /// counts only).
    pub vertex_checksum: Option<u64>,
    /// `Volume6` evaluations ([`topolab_structures::hull::Work::volume6_tests`]; `None` for an outside hull).
    pub volume6_tests: Option<u64>,
    /// Of those, the ones decided in exact arithmetic ([`topolab_structures::hull::Work::exact_tests`]; `None` for an
    /// outside hull).
    pub exact_tests: Option<u64>,
    /// Σ|P(e)|, the conflict-list work ([`topolab_structures::hull::Work::conflict_work`]; randomized only).
    pub conflict_work: Option<u64>,
    /// Peak heap bytes allocated during the call beyond what was allocated before it (the
    /// input points are not counted), counted in the warm-up run, which is not timed; `None`
    /// for an outside hull or without a memory meter.
    pub peak_bytes: Option<usize>,
}

/// The fitted exponents (t ∝ n^e, least squares on log-log axes) of one algorithm on one
/// shape, against n.
#[derive(Clone, Debug, serde::Serialize)]
pub struct HullFit {
    /// `ball`, `sphere` or `cube`.
    pub shape: String,
    /// The algorithm (an outside hull too).
    pub algorithm: String,
    /// How many sizes the fits used.
    pub sizes: usize,
    /// Exponent of the time.
    pub time_exponent: f64,
    /// Exponent of the `Volume6` tests (`None` for an outside hull).
    pub tests_exponent: Option<f64>,
    /// Exponent of Σ|P(e)| (randomized only).
    pub conflict_exponent: Option<f64>,
    /// The lecture's bound (`hull::bench::bound`): `n·h`, `n²` or `n lg n`; `None` for an outside hull.
    pub bound: Option<String>,
    /// The bound's exponent at the sizes and hull sizes measured.
    pub bound_exponent: Option<f64>,
    /// Does the work grow no faster than the bound (the work's exponent, Σ|P(e)| for the
    /// randomized algorithm and `Volume6` tests for the others, at most the bound's + 0.1)?
    pub within_bound: Option<bool>,
}

/// The reads of one operator on one structure, against mesh size (counted in the counting
/// build of the structures, whose operators and costs are its own types).
#[derive(Clone, Debug, serde::Serialize)]
pub struct ReadsRow {
    /// The structure.
    pub structure: String,
    /// The operator.
    pub operator: topolab_structures_counted::Operator,
    /// The mesh family counted on (`torus` or `grid`).
    pub family: String,
    /// The declared cost.
    pub cost: topolab_structures_counted::Cost,
    /// The exponent the declared cost predicts.
    pub expected_exponent: f64,
    /// Per size counted: (faces, mean reads per query, queries).
    pub points: Vec<(usize, f64, usize)>,
    /// Sizes (triangles asked for) skipped by the budget.
    pub skipped: Vec<usize>,
    /// The exponent fitted to the reads against the faces (two sizes or more with reads).
    pub exponent: Option<f64>,
    /// How the reads compare with the declared cost.
    pub verdict: Verdict,
}

/// How a row's reads compare with its declared cost.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Verdict {
    /// The fitted exponent is the declared cost's (within [`TOLERANCE`](crate::reads::count::TOLERANCE)).
    Matches,
    /// It is not: a finding about the code or the declared cost.
    Differs,
    /// Nothing is read (the grids' arithmetic).
    NoReads,
    /// Fewer than two sizes counted.
    TooFew,
}

/// What a target times.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Cell {
    /// The vertex 1-ring sweep (R00 over every vertex), per vertex.
    R00Sweep,
    /// The smoothing workload, per vertex.
    Smoothing,
    /// Construction from the polygon soup, warm builds (reusing the memory the build before
    /// freed), per face.
    Construction,
    /// A changing workload from a fresh build (the build not timed), per face of the input.
    Changing(topolab_structures::algorithms::changing::Changing),
    /// The 3D convex hull of `hull::bench::HULL_POINTS` random points in a ball, per point: the lab's
    /// randomized algorithm against an outside library's hull, taking turns in the hull
    /// section (each side's clock as the hull table's: around the call alone).
    Hull,
}

/// The rounds of one cell: the structures that took turns and each one's runs.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Turns {
    /// What was timed.
    pub cell: Cell,
    /// On which mesh.
    pub mesh: String,
    /// Items per run (vertices or faces).
    pub items: usize,
    /// The structures, in the order of their turns.
    pub structures: Vec<String>,
    /// Nanoseconds per item of every timed run, by structure (as `structures`) then round.
    pub ns_per_item: Vec<Vec<f64>>,
    /// Untimed warm-up rounds before them.
    pub warm_up: usize,
    /// Wall time of all the rounds, warm-up included, seconds.
    pub seconds: f64,
}

impl Turns {
    /// The runs of `structure`, if it took turns.
    pub fn runs(&self, structure: &str) -> Option<&[f64]> {
        let i = self.structures.iter().position(|s| s == structure)?;
        self.ns_per_item.get(i).map(Vec::as_slice)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cell(operator: Subject, kernel: Kernel) -> Measurement {
        Measurement {
            ns_per_item: Some(9540.225490196079),
            min_ns_per_item: Some(9504.588235294117),
            max_ns_per_item: Some(49622.12745098039),
            items: 102,
            reps: 23,
            checksum: Some("13793524636986848482".into()),
            ..Measurement::new("explicit", operator, kernel, "torus-200", "torus", 204)
        }
    }

    /// A measurement of results.json as the report wrote it before its fields were typed.
    const R02_SWEEP: &str = r#"{
  "structure": "explicit",
  "operator": "r02",
  "kernel": "sweep",
  "mesh": "torus-200",
  "family": "torus",
  "triangles": 204,
  "status": "measured",
  "ns_per_item": 9540.225490196079,
  "min_ns_per_item": 9504.588235294117,
  "max_ns_per_item": 49622.12745098039,
  "items": 102,
  "reps": 23,
  "checksum": "13793524636986848482",
  "bytes": null,
  "peak_bytes": null,
  "declared_bytes": null,
  "estimate_ns_per_item": null,
  "native": false,
  "note": null
}"#;

    #[test]
    fn a_measurement_serializes_as_results_json_always_had_it() {
        let m = cell(Subject::Query(Operator::R02), Kernel::Sweep);
        assert_eq!(serde_json::to_string_pretty(&m).unwrap(), R02_SWEEP);
        for (subject, kernel, operator_field, kernel_field) in [
            (
                Subject::Construction,
                Kernel::Construction,
                "construction",
                "construction",
            ),
            (
                Subject::Query(Operator::BoundaryVertex),
                Kernel::Sampled,
                "boundary-vertex",
                "sampled",
            ),
            (
                Subject::Workload(Workload::Circulators),
                Kernel::Workload,
                "circulators",
                "workload",
            ),
        ] {
            let v = serde_json::to_value(cell(subject, kernel)).unwrap();
            assert_eq!(v["operator"], operator_field);
            assert_eq!(v["kernel"], kernel_field);
        }
    }

    #[test]
    fn measurements_round_trip_and_unknown_names_are_refused() {
        let parsed: Measurement = serde_json::from_str(R02_SWEEP).unwrap();
        assert_eq!(
            (parsed.operator, parsed.kernel, parsed.status),
            (
                Subject::Query(Operator::R02),
                Kernel::Sweep,
                Status::Measured
            )
        );
        for subject in Operator::ALL
            .map(Subject::Query)
            .into_iter()
            .chain(Workload::ALL.map(Subject::Workload))
            .chain([Subject::Construction])
        {
            // Names are distinct: each one parses back to its own subject.
            assert_eq!(Subject::from_name(subject.name()), Some(subject));
            for kernel in Kernel::ALL {
                let mut m = cell(subject, kernel);
                // serde_json reads decimals back exactly only when they are binary fractions.
                (m.ns_per_item, m.min_ns_per_item, m.max_ns_per_item) =
                    (Some(9540.25), Some(9504.5), Some(49622.125));
                let text = serde_json::to_string(&m).unwrap();
                assert_eq!(serde_json::from_str::<Measurement>(&text).unwrap(), m);
            }
        }
        let wrong = R02_SWEEP.replace("\"r02\"", "\"r03\"");
        let err = serde_json::from_str::<Measurement>(&wrong).unwrap_err();
        assert!(
            err.to_string().contains("unknown operator \"r03\""),
            "{err}"
        );
        let wrong = R02_SWEEP.replace("\"sweep\"", "\"swept\"");
        assert!(serde_json::from_str::<Measurement>(&wrong).is_err());
    }

    #[test]
    fn costs_and_fits_are_written_in_the_lecture_notation() {
        let cost = CostRow {
            operator: Operator::EdgeSuccessor,
            cost: Cost::Boundary,
            expected_exponent: 0.5,
            access: None,
        };
        assert_eq!(
            serde_json::to_string(&cost).unwrap(),
            r#"{"operator":"edge-successor","cost":"O(∂n1)","expected_exponent":0.5}"#
        );
        let fit = FitRow {
            structure: "che-l0".into(),
            operator: Operator::BoundaryEdge,
            kernel: Kernel::Sampled,
            family: "grid".into(),
            exponent: 0.9257697736871451,
            class: "linear".into(),
            theory: Cost::Linear,
            expected_exponent: 1.0,
            agrees: true,
            points: 2,
        };
        assert_eq!(
            serde_json::to_string_pretty(&fit).unwrap(),
            r#"{
  "structure": "che-l0",
  "operator": "boundary-edge",
  "kernel": "sampled",
  "family": "grid",
  "exponent": 0.9257697736871451,
  "class": "linear",
  "theory": "O(n)",
  "expected_exponent": 1.0,
  "agrees": true,
  "points": 2
}"#
        );
    }
}

/// What one cell of the report's edit-ops section ([`crate::report::sections::edit_ops`])
/// gave.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
#[serde(rename_all = "kebab-case", tag = "status")]
pub enum EditOpOutcome {
    /// Timed.
    Measured {
        /// Median nanoseconds per operation over the samples.
        ns_per_op: f64,
        /// Samples, each on a fresh mesh.
        samples: usize,
        /// Operations timed together per sample.
        ops_per_sample: usize,
        /// The samples' checksums, summed (compared between structures).
        checksum: u64,
    },
    /// The structure does not offer the operation.
    NotOffered,
    /// Skipped: the declared cost predicts too long, or the preparation needs an operation
    /// the structure does not offer.
    Skipped {
        /// Why (the same words on every mesh, so that the notes group them).
        reason: String,
        /// What differs by mesh (the estimate).
        detail: Option<String>,
    },
}

/// One operation on one structure and torus.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct EditOpRow {
    /// The operation.
    pub op: topolab_structures::EditOp,
    /// The torus.
    pub mesh: String,
    /// Its faces.
    pub faces: usize,
    /// The structure.
    pub structure: String,
    /// The cost it declares for the operation.
    pub declared: Cost,
    /// What was measured, or why not.
    pub outcome: EditOpOutcome,
}
