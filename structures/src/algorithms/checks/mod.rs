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
mod manifold;
mod polygon;

pub use polygon::MAX_SIMPLICITY_CORNERS;

use crate::io::RawSoup;
use crate::summary::Undefined;
use duplicates::{duplicate_faces, duplicate_vertices};
use manifold::topology;
use polygon::polygon_checks;
use std::collections::{BTreeMap, HashSet};

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
}

impl Default for Options {
    fn default() -> Self {
        Self {
            tolerance: 1e-9,
            planarity_tolerance: 1e-6,
        }
    }
}

/// One connected component (faces joined through shared vertices).
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Component {
    /// Its faces.
    pub faces: usize,
    /// Its vertices.
    pub vertices: usize,
    /// Its edges.
    pub edges: usize,
    /// Its boundary curves (per fan, as `crate::summary` defines them); `None` where an edge
    /// of it has more than two faces.
    pub boundary_curves: Option<usize>,
    /// V - E + F.
    pub euler_characteristic: i64,
    /// Its faces can be oriented consistently.
    pub orientable: bool,
    /// No non-manifold edge or vertex.
    pub manifold: bool,
    /// (2 - χ - b) / 2, for an orientable manifold component.
    pub genus: Option<i64>,
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
    pub components: Vec<Component>,
    /// Findings per kind (only kinds that occur).
    pub counts: BTreeMap<&'static str, usize>,
}

/// What [`check`] found.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Report {
    /// Every problem, grouped by kind in [`FindingKind::ALL`] order.
    pub findings: Vec<Finding>,
    /// Counts and topology.
    pub summary: CheckSummary,
}

impl Report {
    /// `true` when nothing was found.
    pub fn is_clean(&self) -> bool {
        self.findings.is_empty()
    }
}

/// Union-find over `0..n` (shared by the duplicate and manifold checks, and by the repair's
/// orientation) that also keeps, per element, the parity of its path to the root: plain unions
/// for components, parity unions for orientability.
pub(crate) struct UnionFind {
    parent: Vec<u32>,
    /// Parity of the link to `parent` (the root's is `false`).
    flip: Vec<bool>,
}

impl UnionFind {
    pub(crate) fn new(n: usize) -> Self {
        Self {
            parent: (0..n as u32).collect(),
            flip: vec![false; n],
        }
    }

    /// The root of `x` and the parity of `x` relative to it (path compressed).
    pub(crate) fn find(&mut self, x: u32) -> (u32, bool) {
        let (mut root, mut parity) = (x, false);
        while self.parent[root as usize] != root {
            parity ^= self.flip[root as usize];
            root = self.parent[root as usize];
        }
        let (mut y, mut y_parity) = (x, parity);
        while self.parent[y as usize] != y {
            let (next, next_parity) = (self.parent[y as usize], y_parity ^ self.flip[y as usize]);
            self.parent[y as usize] = root;
            self.flip[y as usize] = y_parity;
            y = next;
            y_parity = next_parity;
        }
        (root, parity)
    }

    /// Joins `a` and `b` with relative parity `flip`; `false` if they were already joined
    /// with the other parity (a contradiction).
    pub(crate) fn union(&mut self, a: u32, b: u32, flip: bool) -> bool {
        let ((ra, pa), (rb, pb)) = (self.find(a), self.find(b));
        if ra == rb {
            return pa ^ pb == flip;
        }
        self.parent[ra as usize] = rb;
        self.flip[ra as usize] = pa ^ pb ^ flip;
        true
    }
}

/// Runs every check on `raw`.
pub fn check(raw: &RawSoup, options: &Options) -> Report {
    let soup = &raw.soup;
    let mut findings = Vec::new();
    let mut push = |kind, vertices: Vec<u32>, faces: Vec<u32>, message: String| {
        findings.push(Finding {
            kind,
            vertices,
            faces,
            message,
        })
    };
    let n = soup.num_vertices();
    if n == 0 && soup.num_faces() == 0 {
        push(
            FindingKind::EmptyMesh,
            vec![],
            vec![],
            "the file has no vertices and no faces".into(),
        );
    }
    let finite: Vec<bool> = soup.positions.iter().map(|p| p.is_finite()).collect();
    for (v, _) in finite.iter().enumerate().filter(|(_, ok)| !**ok) {
        let p = soup.positions[v];
        push(
            FindingKind::NonFiniteCoordinate,
            vec![v as u32],
            vec![],
            format!("vertex {v} is at ({}, {}, {})", p.x, p.y, p.z),
        );
    }

    // Missing elements, and which faces are usable for everything else.
    let mut usable = vec![false; soup.num_faces()];
    let mut repeats = vec![false; soup.num_faces()];
    let mut used = vec![false; n];
    let mut edges_without_end = HashSet::new();
    let mut sorted = Vec::new();
    for (j, face) in soup.faces().enumerate() {
        let written = |k: usize| written_index(raw, j, k);
        let missing: Vec<usize> = (0..face.len()).filter(|&k| face[k] as usize >= n).collect();
        for &v in face.iter().filter(|&&v| (v as usize) < n) {
            used[v as usize] = true;
        }
        if !missing.is_empty() {
            let indices: Vec<i64> = missing.iter().map(|&k| written(k)).collect();
            push(
                FindingKind::MissingVertex,
                vec![],
                vec![j as u32],
                format!("face {j} refers to vertices {indices:?}, but there are {n} vertices"),
            );
            for &k in &missing {
                let len = face.len();
                for (a, b) in [((k + len - 1) % len, k), (k, (k + 1) % len)] {
                    let (wa, wb) = (written(a), written(b));
                    if a != b && edges_without_end.insert((wa.min(wb), wa.max(wb))) {
                        push(
                            FindingKind::EdgeWithoutEndPoint,
                            vec![],
                            vec![j as u32],
                            format!("edge ({wa}, {wb}) of face {j} has an end point that does not exist"),
                        );
                    }
                }
            }
            continue;
        }
        sorted.clear();
        sorted.extend_from_slice(face);
        sorted.sort_unstable();
        let mut repeated: Vec<u32> = sorted
            .windows(2)
            .filter(|w| w[0] == w[1])
            .map(|w| w[0])
            .collect();
        repeated.dedup();
        sorted.dedup();
        if sorted.len() < 3 {
            push(
                FindingKind::TooFewVertices,
                sorted.clone(),
                vec![j as u32],
                format!(
                    "face {j} has {} corners on {} distinct vertices; a face needs three",
                    face.len(),
                    sorted.len()
                ),
            );
            continue;
        }
        if !repeated.is_empty() {
            push(
                FindingKind::RepeatedVertex,
                repeated.clone(),
                vec![j as u32],
                format!(
                    "face {j} visits vertices {repeated:?} more than once: not a simple polygon"
                ),
            );
            repeats[j] = true;
        }
        usable[j] = true;
    }
    for v in (0..n).filter(|&v| !used[v]) {
        push(
            FindingKind::UnusedVertex,
            vec![v as u32],
            vec![],
            format!("vertex {v} is used by no face"),
        );
    }

    let same_place = duplicate_vertices(soup, &finite, options.tolerance, &mut push);
    let duplicate = duplicate_faces(soup, &usable, &same_place, &mut push);
    for j in (0..soup.num_faces()).filter(|&j| usable[j]) {
        let face = soup.face(j);
        if face.iter().all(|&v| finite[v as usize]) {
            polygon_checks(soup, j, options, &mut push);
        }
    }

    // The edge analysis on the usable faces that visit each vertex once and are not a
    // duplicate of an earlier face (already reported); face ids mapped back.
    let analysed = |j: usize| usable[j] && !duplicate[j] && !repeats[j];
    let kept: Vec<u32> = (0..soup.num_faces() as u32)
        .filter(|&j| analysed(j as usize))
        .collect();
    let clean = soup.with_faces(analysed);
    let summary = topology(&clean, &kept, soup, &mut push);

    findings.sort_by_key(|f| f.kind);
    let mut summary = summary;
    for f in &findings {
        *summary.counts.entry(f.kind.name()).or_default() += 1;
    }
    Report { findings, summary }
}

/// The index the file wrote at corner `k` of face `j` (0-based), also when it does not fit `u32`.
fn written_index(raw: &RawSoup, j: usize, k: usize) -> i64 {
    let v = raw.soup.face(j)[k];
    if v != crate::io::UNREPRESENTABLE {
        return v as i64;
    }
    // The readers list them in file order, that is by (face, corner).
    raw.unrepresentable
        .binary_search_by_key(&(j, k), |u| (u.face, u.corner))
        .map_or(v as i64, |i| raw.unrepresentable[i].index)
}

type Push<'a> = dyn FnMut(FindingKind, Vec<u32>, Vec<u32>, String) + 'a;
