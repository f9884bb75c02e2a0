//! The hull study's rows as `results.json` writes them: one timed hull ([`HullRow`]) and the
//! exponents fitted against n ([`HullFit`]).

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
