//! The consistency checks (*Konsistenzprüfung*) and validity rules of polygon meshes of the
//! lecture on polygon-mesh data structures, run on a soup as read ([`RawSoup`]), reporting every
//! problem instead of stopping at the first.
//!
//! | group | finding | the lecture's question |
//! |---|---|---|
//! | missing | `empty-mesh`, `missing-vertex`, `edge-without-end-point`, `too-few-vertices` | is something missing? |
//! | redundant | `duplicate-vertices`, `duplicate-face`, `geometric-duplicate-face`, `unused-vertex` | is something redundant (topologically, geometrically)? |
//! | manifold | `non-manifold-edge`, `non-manifold-vertex`, `inconsistent-orientation`, `non-orientable` | an edge borders one or two facets; facets meet in nothing, a vertex or an edge |
//! | geometry | `non-finite-coordinate`, `degenerate-face` | coordinates and areas |
//! | polygon | `repeated-vertex`, `non-simple-face`, `non-planar-face`, `non-convex-face` | facets are closed, simple, planar (and convex) polygons |
//!
//! Faces with a missing vertex or fewer than three distinct vertices take no part in the
//! later checks (they have no edges to speak of); faces that repeat a vertex or an earlier
//! face's vertex set take no part in the edge analysis (they are reported already).
//!
//! Geometry is tested in floating point without exact predicates: a corner within rounding
//! of a line counts as on it. A polygon is projected onto the coordinate plane most nearly
//! parallel to it for the simplicity and convexity tests (the lecture's test by the sign of
//! successive turns, run only on simple polygons); a self-intersecting polygon whose lobes
//! cancel has zero area and is reported as degenerate. Polygons of more than
//! [`MAX_SIMPLICITY_CORNERS`] corners are not tested for self-intersection. Geometric
//! intersections between different faces (the lecture's "two facets share nothing, a vertex
//! or an edge") are not tested.

mod duplicates;
mod faces;
mod manifold;
mod polygon;

pub use duplicates::NEAR_DUPLICATES_COMPARED;
pub use polygon::MAX_SIMPLICITY_CORNERS;

use crate::algorithms::summary::Undefined;
use crate::core::soup::PolygonSoup;
use crate::io::RawSoup;
use duplicates::{duplicate_faces, duplicate_vertices};
use manifold::topology;
use polygon::polygon_checks;
use std::collections::BTreeMap;

/// What a finding is about.
#[derive(Copy, Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum FindingKind {
    /// The file holds no vertex and no face: nothing to check, and almost certainly not the
    /// mesh that was meant (an export that wrote nothing, a truncated download).
    EmptyMesh,
    /// A face refers to a vertex that does not exist (out of range, negative, beyond `u32`).
    MissingVertex,
    /// An edge of a face whose end point is a missing vertex.
    EdgeWithoutEndPoint,
    /// A face with fewer than three distinct vertices.
    TooFewVertices,
    /// A face that visits one vertex twice (with three or more distinct vertices).
    RepeatedVertex,
    /// Vertices at the same position (within the tolerance).
    DuplicateVertices,
    /// Faces with the same set of vertices (topological duplicates).
    DuplicateFace,
    /// Faces on different vertices at the same positions (geometric duplicates).
    GeometricDuplicateFace,
    /// A vertex that no face uses.
    UnusedVertex,
    /// An edge with more than two faces.
    NonManifoldEdge,
    /// A vertex whose faces form more than one fan.
    NonManifoldVertex,
    /// Two faces traverse their shared edge in the same direction.
    InconsistentOrientation,
    /// A connected component whose faces cannot be oriented consistently (a Möbius strip).
    NonOrientable,
    /// A NaN or infinite coordinate.
    NonFiniteCoordinate,
    /// A face of (nearly) zero area.
    DegenerateFace,
    /// A face whose boundary intersects itself.
    NonSimpleFace,
    /// A face whose corners are not in one plane (within the planarity tolerance).
    NonPlanarFace,
    /// A face whose successive turns change sign.
    NonConvexFace,
}

impl FindingKind {
    /// Every kind, in report order.
    pub const ALL: [FindingKind; 18] = [
        FindingKind::EmptyMesh,
        FindingKind::MissingVertex,
        FindingKind::EdgeWithoutEndPoint,
        FindingKind::TooFewVertices,
        FindingKind::RepeatedVertex,
        FindingKind::DuplicateVertices,
        FindingKind::DuplicateFace,
        FindingKind::GeometricDuplicateFace,
        FindingKind::UnusedVertex,
        FindingKind::NonManifoldEdge,
        FindingKind::NonManifoldVertex,
        FindingKind::InconsistentOrientation,
        FindingKind::NonOrientable,
        FindingKind::NonFiniteCoordinate,
        FindingKind::DegenerateFace,
        FindingKind::NonSimpleFace,
        FindingKind::NonPlanarFace,
        FindingKind::NonConvexFace,
    ];

    /// The kebab-case name used in reports and JSON.
    pub fn name(self) -> &'static str {
        match self {
            FindingKind::EmptyMesh => "empty-mesh",
            FindingKind::MissingVertex => "missing-vertex",
            FindingKind::EdgeWithoutEndPoint => "edge-without-end-point",
            FindingKind::TooFewVertices => "too-few-vertices",
            FindingKind::RepeatedVertex => "repeated-vertex",
            FindingKind::DuplicateVertices => "duplicate-vertices",
            FindingKind::DuplicateFace => "duplicate-face",
            FindingKind::GeometricDuplicateFace => "geometric-duplicate-face",
            FindingKind::UnusedVertex => "unused-vertex",
            FindingKind::NonManifoldEdge => "non-manifold-edge",
            FindingKind::NonManifoldVertex => "non-manifold-vertex",
            FindingKind::InconsistentOrientation => "inconsistent-orientation",
            FindingKind::NonOrientable => "non-orientable",
            FindingKind::NonFiniteCoordinate => "non-finite-coordinate",
            FindingKind::DegenerateFace => "degenerate-face",
            FindingKind::NonSimpleFace => "non-simple-face",
            FindingKind::NonPlanarFace => "non-planar-face",
            FindingKind::NonConvexFace => "non-convex-face",
        }
    }
}

/// One problem, with the elements it is about (ids as in the file: vertex i, face j).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Finding {
    /// What kind of problem.
    pub kind: FindingKind,
    /// The offending vertices (empty when the problem is a vertex that does not exist).
    pub vertices: Vec<u32>,
    /// The offending faces.
    pub faces: Vec<u32>,
    /// A sentence for people.
    pub message: String,
}

/// Tolerances of the geometric checks.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Options {
    /// Distance below which two positions are equal and a face is flat to a line (its area
    /// divided by its size): duplicate vertices, degenerate faces.
    pub tolerance: f64,
    /// Largest distance of a corner from its face's plane, relative to the face's size (the
    /// diagonal of its bounding box), for the face to count as planar.
    pub planarity_tolerance: f64,
    /// Findings of one kind kept in [`Report::findings`] (the first ones, in the order the
    /// checks meet them); the others are only counted ([`CheckSummary::counts`]), so that a
    /// file with millions of problems does not make a report millions of findings long.
    pub kept_per_kind: usize,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            tolerance: 1e-9,
            planarity_tolerance: 1e-6,
            kept_per_kind: 10,
        }
    }
}

/// One connected component (faces joined through shared vertices), as [`Components`] gives
/// it. Its counts are `u32`, as the soup's ids are.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Component {
    /// Its faces.
    pub faces: u32,
    /// Its vertices.
    pub vertices: u32,
    /// Its edges.
    pub edges: u32,
    /// Its boundary curves (per fan, as `crate::summary` defines them); `None` where an edge
    /// of it has more than two faces.
    pub boundary_curves: Option<u32>,
    /// V - E + F.
    pub euler_characteristic: i64,
    /// Its faces can be oriented consistently.
    pub orientable: bool,
    /// No non-manifold edge or vertex.
    pub manifold: bool,
    /// (2 - χ - b) / 2, for an orientable manifold component.
    pub genus: Option<i64>,
}

/// Every component of a report, in the order the report lists them. A file of separate faces
/// has one a face, so each is stored as its counts (20 bytes, against 48 for a [`Component`]):
/// its Euler characteristic and genus are computed when it is read. Serialised as the list
/// of its [`Component`]s.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Components(pub(super) Vec<Counts>);

/// What [`Components`] stores of a component: the rest of a [`Component`] follows from it.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(super) struct Counts {
    pub(super) faces: u32,
    pub(super) vertices: u32,
    pub(super) edges: u32,
    /// [`UNDEFINED`] where an edge of the component has more than two faces.
    pub(super) boundary_curves: u32,
    pub(super) orientable: bool,
    pub(super) manifold: bool,
}

/// [`Counts::boundary_curves`] when they are undefined.
pub(super) const UNDEFINED: u32 = u32::MAX;

impl Counts {
    /// The component these counts describe.
    fn component(&self) -> Component {
        let euler_characteristic =
            i64::from(self.vertices) - i64::from(self.edges) + i64::from(self.faces);
        let boundary_curves = (self.boundary_curves != UNDEFINED).then_some(self.boundary_curves);
        Component {
            faces: self.faces,
            vertices: self.vertices,
            edges: self.edges,
            boundary_curves,
            euler_characteristic,
            orientable: self.orientable,
            manifold: self.manifold,
            // χ = 2 - 2g - b for a connected orientable surface.
            genus: match (self.manifold && self.orientable, boundary_curves) {
                (true, Some(b)) => Some((2 - euler_characteristic - i64::from(b)) / 2),
                _ => None,
            },
        }
    }
}

impl Components {
    /// How many components.
    pub fn len(&self) -> usize {
        self.0.len()
    }

    /// `true` when there is none (a mesh without usable faces).
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// Component `i`, if there is one.
    pub fn get(&self, i: usize) -> Option<Component> {
        self.0.get(i).map(Counts::component)
    }

    /// Every component, in order.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = Component> + '_ {
        self.0.iter().map(Counts::component)
    }
}

impl serde::Serialize for Components {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(self.iter())
    }
}

/// Counts and topology of the faces that took part in the edge analysis.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct CheckSummary {
    /// Vertices in the file.
    pub vertices: usize,
    /// Faces in the file.
    pub faces: usize,
    /// Faces without missing vertices and with at least three distinct ones.
    pub usable_faces: usize,
    /// Edges of the usable faces.
    pub edges: usize,
    /// Edges with exactly one face.
    pub boundary_edges: usize,
    /// Boundary curves over all components (per fan, as `crate::summary` defines them);
    /// `None` where an edge has more than two faces.
    pub boundary_curves: Option<usize>,
    /// Why `boundary_curves` is not defined, when it is not (the words of `info`).
    pub boundary_curves_undefined: Option<Undefined>,
    /// V - E + F over used vertices and usable faces.
    pub euler_characteristic: i64,
    /// Each connected component.
    pub components: Components,
    /// Findings per kind (only kinds that occur), all of them: [`Report::findings`] keeps the
    /// first [`Options::kept_per_kind`] of each.
    pub counts: BTreeMap<&'static str, usize>,
    /// Vertices compared with only some of the vertices filed near them in the search for
    /// near duplicates: those in a crowded cube (more than [`NEAR_DUPLICATES_COMPARED`]
    /// distinct positions within a cube of side twice the tolerance). 0 when the search was
    /// exhaustive.
    pub near_duplicates_not_exhaustive: usize,
}

/// What [`check`] found.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Report {
    /// The first [`Options::kept_per_kind`] problems of each kind, grouped by kind in
    /// [`FindingKind::ALL`] order; how many there are of each is in [`CheckSummary::counts`].
    pub findings: Vec<Finding>,
    /// Counts and topology.
    pub summary: CheckSummary,
}

impl Report {
    /// `true` when nothing was found.
    pub fn is_clean(&self) -> bool {
        self.summary.counts.is_empty()
    }

    /// How many problems of `kind` were found (kept or not).
    pub fn count(&self, kind: FindingKind) -> usize {
        self.summary.counts.get(kind.name()).copied().unwrap_or(0)
    }

    /// How many problems were found, of every kind.
    pub fn total(&self) -> usize {
        self.summary.counts.values().sum()
    }
}

/// The findings as the checks meet them: every one counted, the first
/// [`Options::kept_per_kind`] of each kind kept. A finding's ids and message are built only
/// when it is kept. Messages number vertices and faces as the file does ([`Findings::id`]).
pub(super) struct Findings {
    kept: Vec<Finding>,
    counts: BTreeMap<FindingKind, usize>,
    keep: usize,
    /// The first id of the file's numbering (1 for OBJ).
    first: u64,
}

impl Findings {
    fn new(options: &Options, numbering: crate::core::error::Numbering) -> Self {
        Self {
            kept: Vec::new(),
            counts: BTreeMap::new(),
            keep: options.kept_per_kind,
            first: numbering.first().into(),
        }
    }

    /// Counts a finding of `kind`; keeps it, built by `build` (vertices, faces, message), while
    /// fewer than [`Options::kept_per_kind`] of its kind are kept.
    pub(super) fn add(
        &mut self,
        kind: FindingKind,
        build: impl FnOnce() -> (Vec<u32>, Vec<u32>, String),
    ) {
        let count = self.counts.entry(kind).or_default();
        *count += 1;
        if *count <= self.keep {
            let (vertices, faces, message) = build();
            self.kept.push(Finding {
                kind,
                vertices,
                faces,
                message,
            });
        }
    }

    /// How many more findings of `kind` will be kept.
    pub(super) fn room(&self, kind: FindingKind) -> usize {
        self.keep
            .saturating_sub(self.counts.get(&kind).copied().unwrap_or(0))
    }

    /// Counts `n` findings of `kind` that the caller knows are not kept (no [`Findings::room`]
    /// left for them).
    pub(super) fn count(&mut self, kind: FindingKind, n: usize) {
        if n > 0 {
            *self.counts.entry(kind).or_default() += n;
        }
    }

    /// How the file numbers its elements, for messages.
    pub(super) fn numbering(&self) -> Ids {
        Ids { first: self.first }
    }
}

/// Ids of the soup (from 0) written as the file numbers them (from 1 for OBJ), for messages.
#[derive(Copy, Clone)]
pub(super) struct Ids {
    first: u64,
}

impl Ids {
    /// One id.
    pub(super) fn id(self, id: impl Into<u64>) -> u64 {
        id.into() + self.first
    }

    /// The first [`LISTED_IDS`] of `ids`, then how many there are.
    pub(super) fn list(self, ids: &[u32]) -> String {
        let shown: Vec<String> = ids
            .iter()
            .take(LISTED_IDS)
            .map(|&v| self.id(v).to_string())
            .collect();
        match ids.len() {
            n if n <= LISTED_IDS => format!("[{}]", shown.join(", ")),
            n => format!("[{}, ... ({n} in all)]", shown.join(", ")),
        }
    }
}

/// The most ids a finding's message lists (its `vertices` and `faces` hold them all).
pub const LISTED_IDS: usize = 8;

/// Runs every check on `raw`. Time and memory are O(n) in the file's elements (hashing
/// expected O(1) per lookup), but for the polygon checks' O(k²) self-intersection test of a
/// face of k ≤ [`MAX_SIMPLICITY_CORNERS`] corners. The edge analysis runs on a copy of the
/// faces it takes part in and of the positions; [`check_owned`] runs it on `raw`'s own arrays.
pub fn check(raw: &RawSoup, options: &Options) -> Report {
    let inspected = inspect(raw, options);
    let clean = match &inspected.kept {
        Some(kept) => raw
            .soup
            .with_faces(|j| kept.binary_search(&(j as u32)).is_ok()),
        None => raw.soup.clone(),
    };
    inspected.finish(&clean)
}

/// [`check`], taking `raw`: the faces that take part in the edge analysis are kept in its
/// arrays, the others dropped in place, so that the analysis needs no copy of the mesh; the
/// positions, which the edge analysis does not read, are dropped before it (24 bytes a
/// vertex: most of a mesh of separate faces).
pub fn check_owned(mut raw: RawSoup, options: &Options) -> Report {
    let inspected = inspect(&raw, options);
    if let Some(kept) = &inspected.kept {
        let mut kept = kept.iter().peekable();
        raw.soup
            .retain_faces(|j| kept.next_if(|&&k| k as usize == j).is_some());
    }
    raw.soup.positions = Vec::new();
    inspected.finish(&raw.soup)
}

/// The checks before the edge analysis, and what the analysis needs of them.
struct Inspected {
    found: Findings,
    /// The faces of the edge analysis, when not all of them: usable, visiting each vertex
    /// once, and not a duplicate of an earlier face (already reported).
    kept: Option<Vec<u32>>,
    vertices: usize,
    faces: usize,
    not_exhaustive: usize,
}

/// Every check but the edge analysis (which [`Inspected::finish`] runs on the faces kept).
fn inspect(raw: &RawSoup, options: &Options) -> Inspected {
    let soup = &raw.soup;
    let mut found = Findings::new(options, raw.numbering);
    let n = soup.num_vertices();
    if n == 0 && soup.num_faces() == 0 {
        found.add(FindingKind::EmptyMesh, || {
            (
                vec![],
                vec![],
                "the file has no vertices and no faces".into(),
            )
        });
    }
    let finite: Vec<bool> = soup.positions.iter().map(|p| p.is_finite()).collect();
    let ids = found.numbering();
    for (v, _) in finite.iter().enumerate().filter(|(_, ok)| !**ok) {
        let p = soup.positions[v];
        found.add(FindingKind::NonFiniteCoordinate, || {
            (
                vec![v as u32],
                vec![],
                format!(
                    "vertex {} is at ({}, {}, {})",
                    ids.id(v as u64),
                    p.x,
                    p.y,
                    p.z
                ),
            )
        });
    }
    let usable_count = faces::usable_faces(raw, &mut found);
    let shape = |j: usize, sorted: &mut Vec<u32>| faces::shape(soup.face(j), n, sorted);
    let same_place = duplicate_vertices(soup, &finite, options.tolerance, &mut found);
    let usable = |j: usize, sorted: &mut Vec<u32>| shape(j, sorted).usable();
    let firsts = duplicate_faces(
        soup,
        usable,
        usable_count,
        &same_place.representative,
        &mut found,
    );
    drop(same_place.representative);
    let mut sorted = Vec::new();
    for j in 0..soup.num_faces() {
        let face = soup.face(j);
        if usable(j, &mut sorted) && face.iter().all(|&v| finite[v as usize]) {
            polygon_checks(soup, j, options, &mut found);
        }
    }
    drop(finite);

    // The edge analysis on the usable faces that visit each vertex once and are not a
    // duplicate of an earlier face (already reported); face ids mapped back. Counted before
    // they are listed: when every face takes part, no list.
    let (mut key, mut scratch) = (Vec::new(), Vec::new());
    let mut analysed = |j: usize| {
        shape(j, &mut sorted) == faces::Shape::Simple
            && firsts.first_of(soup, j, &mut key, &mut scratch) == Some(j as u32)
    };
    let count = (0..soup.num_faces()).filter(|&j| analysed(j)).count();
    let kept = (count < soup.num_faces()).then(|| {
        (0..soup.num_faces() as u32)
            .filter(|&j| analysed(j as usize))
            .collect()
    });
    Inspected {
        found,
        kept,
        vertices: n,
        faces: soup.num_faces(),
        not_exhaustive: same_place.not_exhaustive,
    }
}

impl Inspected {
    /// The edge analysis on `clean` (the faces kept), and the report.
    fn finish(self, clean: &PolygonSoup) -> Report {
        let Inspected {
            mut found,
            kept,
            vertices,
            faces,
            not_exhaustive,
        } = self;
        let mut summary = topology(clean, kept.as_deref(), (vertices, faces), &mut found);
        summary.near_duplicates_not_exhaustive = not_exhaustive;
        let Findings {
            mut kept, counts, ..
        } = found;
        kept.sort_by_key(|f| f.kind);
        summary.counts = counts.into_iter().map(|(k, n)| (k.name(), n)).collect();
        Report {
            findings: kept,
            summary,
        }
    }
}

/// The index the file wrote at corner `k` of face `j` (0-based), also when it does not fit `u32`.
pub(super) fn written_index(raw: &RawSoup, j: usize, k: usize) -> i64 {
    let v = raw.soup.face(j)[k];
    if v != crate::io::UNREPRESENTABLE {
        return v as i64;
    }
    // The readers list them in file order, that is by (face, corner).
    raw.unrepresentable
        .binary_search_by_key(&(j, k), |u| (u.face, u.corner))
        .map_or(v as i64, |i| raw.unrepresentable[i].index)
}
