//! What one measured cell is, as `results.json` writes it: the structure, the subject (an
//! operator, a workload, construction) and its numbers ([`Measurement`]), whether it was
//! measured ([`Status`]), its speed limit ([`Limit`], [`Bound`]), the rounds it was measured in
//! ([`RoundSettings`], [`Turns`], [`Cell`]), the structures' declared costs ([`StructureInfo`])
//! and the fitted exponents ([`FitRow`]). The run's whole schema is [`crate::results`].

use crate::measuring::kernels::Kernel;
use topolab_structures::{Capabilities, Cost, Family, Operator, Step, Workload};

/// How the size sweep's cells were measured in rounds ([`crate::measuring::rounds`]).
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
    /// sweeps, [`crate::measuring::speed_limit`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub access: Option<topolab_structures::Access>,
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
    /// rounds' values ([`crate::measuring::rounds`]).
    pub ns_per_item: Option<f64>,
    /// The fastest round, per item.
    pub min_ns_per_item: Option<f64>,
    /// The slowest round, per item.
    pub max_ns_per_item: Option<f64>,
    /// Where the median lies, per item: the order-statistics interval of the rounds' median
    /// ([`crate::measuring::timing::interval`]), `[low, high]`, with the probability `ci_coverage`
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
    /// ([`crate::measuring::speed_limit`]).
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
    /// probe's chase of that kind at `latency_level` ([`crate::measuring::probe::Level::step_ns`]). Not a
    /// bound of the limit, which counts plain loads as the model declares them: shown beside
    /// it, it measures what the arithmetic on the chain costs.
    #[serde(default)]
    pub chain_ns_per_item: f64,
    /// What the structure says the model leaves out, if it knows.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
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
