//! The lecture's consistency checks (*Konsistenzprüfung*) and validity rules of polygon meshes,
//! run on a soup as read ([`RawSoup`]), reporting every problem instead of stopping at the first.
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

use crate::attributes::NewellSum;
use crate::error::Error;
use crate::io::RawSoup;
use crate::soup::{Connectivity, PolygonSoup};
use glam::{DVec2, DVec3};
use std::collections::{BTreeMap, HashMap, HashSet};

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
    /// Its boundary curves (connected sets of boundary edges).
    pub boundary_curves: usize,
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
    /// Boundary curves over all components.
    pub boundary_curves: usize,
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

/// Union-find over `0..n` that also keeps, per element, the parity of its path to the root:
/// plain unions for components, parity unions for orientability.
struct UnionFind {
    parent: Vec<u32>,
    /// Parity of the link to `parent` (the root's is `false`).
    flip: Vec<bool>,
}

impl UnionFind {
    fn new(n: usize) -> Self {
        Self {
            parent: (0..n as u32).collect(),
            flip: vec![false; n],
        }
    }

    /// The root of `x` and the parity of `x` relative to it (path compressed).
    fn find(&mut self, x: u32) -> (u32, bool) {
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
    fn union(&mut self, a: u32, b: u32, flip: bool) -> bool {
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

/// Groups vertices at the same position within `tolerance` (transitively): exact duplicates
/// through a hash of their coordinates, near ones through a grid hash of cell size
/// `tolerance` (each distinct position compared with the distinct positions of its 27
/// neighbouring cells: O(n) unless many distinct positions crowd within the tolerance).
/// Returns, per vertex, one vertex of its group (the same for the whole group).
fn duplicate_vertices(
    soup: &PolygonSoup,
    finite: &[bool],
    tolerance: f64,
    push: &mut Push<'_>,
) -> Vec<u32> {
    let n = soup.num_vertices();
    let mut groups = UnionFind::new(n);
    // `+ 0.0` makes -0 and +0 one position.
    let exact_key = |p: DVec3| (p + DVec3::ZERO).to_array().map(f64::to_bits);
    let mut first_at: HashMap<[u64; 3], u32> = HashMap::new();
    let mut grid: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
    for v in (0..n as u32).filter(|&v| finite[v as usize]) {
        let p = soup.positions[v as usize];
        if let Some(&first) = first_at.get(&exact_key(p)) {
            groups.union(v, first, false);
            continue;
        }
        first_at.insert(exact_key(p), v);
        if tolerance <= 0.0 {
            continue;
        }
        // Saturating float-to-int casts keep far-out coordinates in (crowded) edge cells.
        let cell = (p / tolerance).floor().to_array().map(|c| c as i64);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    let key = [
                        cell[0].saturating_add(dx),
                        cell[1].saturating_add(dy),
                        cell[2].saturating_add(dz),
                    ];
                    for &w in grid.get(&key).into_iter().flatten() {
                        if soup.positions[w as usize].distance(p) <= tolerance {
                            groups.union(v, w, false);
                        }
                    }
                }
            }
        }
        grid.entry(cell).or_default().push(v);
    }
    let representative: Vec<u32> = (0..n as u32).map(|v| groups.find(v).0).collect();
    let mut members: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
    for (v, &r) in representative.iter().enumerate() {
        members.entry(r).or_default().push(v as u32);
    }
    let mut found: Vec<Vec<u32>> = members.into_values().filter(|m| m.len() > 1).collect();
    found.sort();
    for group in found {
        push(
            FindingKind::DuplicateVertices,
            group.clone(),
            vec![],
            format!("vertices {group:?} are at one position (within {tolerance})"),
        );
    }
    representative
}

/// Faces with the same vertex set (topological duplicates), and faces whose vertices are at
/// the same positions without being the same vertices (geometric duplicates). Returns, per
/// face, whether it repeats an earlier face's vertices.
fn duplicate_faces(
    soup: &PolygonSoup,
    usable: &[bool],
    same_place: &[u32],
    push: &mut Push<'_>,
) -> Vec<bool> {
    let mut duplicate = vec![false; soup.num_faces()];
    let mut by_vertices: HashMap<Vec<u32>, u32> = HashMap::new();
    let mut by_positions: HashMap<Vec<u32>, u32> = HashMap::new();
    for j in (0..soup.num_faces()).filter(|&j| usable[j]) {
        let face = soup.face(j);
        let mut key: Vec<u32> = face.to_vec();
        key.sort_unstable();
        if let Some(&first) = by_vertices.get(&key) {
            push(
                FindingKind::DuplicateFace,
                key,
                vec![first, j as u32],
                format!("faces {first} and {j} have the same vertices"),
            );
            duplicate[j] = true;
            continue;
        }
        by_vertices.insert(key, j as u32);
        let mut places: Vec<u32> = face.iter().map(|&v| same_place[v as usize]).collect();
        places.sort_unstable();
        match by_positions.get(&places) {
            Some(&first) => push(
                FindingKind::GeometricDuplicateFace,
                face.to_vec(),
                vec![first, j as u32],
                format!("faces {first} and {j} lie at the same positions on different vertices"),
            ),
            None => {
                by_positions.insert(places, j as u32);
            }
        }
    }
    duplicate
}

/// Degenerate, non-simple, non-planar and non-convex faces (triangles are planar, simple and
/// convex unless degenerate).
fn polygon_checks(soup: &PolygonSoup, j: usize, options: &Options, push: &mut Push<'_>) {
    let face = soup.face(j);
    let points = || face.iter().map(|&v| soup.positions[v as usize]);
    let mut newell = NewellSum::default();
    let (mut lo, mut hi, mut sum) = (DVec3::INFINITY, DVec3::NEG_INFINITY, DVec3::ZERO);
    for p in points() {
        newell.add(p);
        lo = lo.min(p);
        hi = hi.max(p);
        sum += p;
    }
    let area_vector = newell.finish();
    let size = (hi - lo).length();
    let k = face.len();
    // Twice the area over the size: how far the face extends across its longest direction.
    if size == 0.0 || area_vector.length() / size <= options.tolerance {
        push(
            FindingKind::DegenerateFace,
            face.to_vec(),
            vec![j as u32],
            format!("face {j} has (nearly) zero area"),
        );
        return;
    }
    if k == 3 {
        return;
    }
    let normal = area_vector.normalize();
    let centroid = sum / k as f64;
    let off_plane = points()
        .map(|p| normal.dot(p - centroid).abs())
        .fold(0.0, f64::max);
    if off_plane > options.planarity_tolerance * size {
        push(
            FindingKind::NonPlanarFace,
            face.to_vec(),
            vec![j as u32],
            format!(
                "face {j}: a corner lies {off_plane:.3e} from its plane, more than {} of its size {size:.3e}",
                options.planarity_tolerance
            ),
        );
    }
    // Project onto the coordinate plane most nearly parallel to the face.
    let drop = normal.abs().max_position();
    let flat = |p: DVec3| {
        let a = p.to_array();
        DVec2::new(a[(drop + 1) % 3], a[(drop + 2) % 3])
    };
    let corner = |i: usize| flat(soup.positions[face[i % k] as usize]);
    let simplicity = (k <= MAX_SIMPLICITY_CORNERS)
        .then(|| self_intersection(k, &corner))
        .flatten();
    if let Some((a, b)) = simplicity {
        push(
            FindingKind::NonSimpleFace,
            face.to_vec(),
            vec![j as u32],
            format!("face {j}: its edges {a} and {b} intersect"),
        );
        return;
    }
    // The lecture's test: the turn at every corner has the same sign (collinear corners,
    // turns within rounding of zero, do not count).
    let turn = |i: usize| (corner(i + 1) - corner(i)).perp_dot(corner(i + 2) - corner(i + 1));
    let flat_turn = 1e-12 * size * size;
    let (left, right) = (0..k).map(turn).fold((false, false), |(l, r), t| {
        (l || t > flat_turn, r || t < -flat_turn)
    });
    if left && right {
        push(
            FindingKind::NonConvexFace,
            face.to_vec(),
            vec![j as u32],
            format!("face {j} turns both left and right: not convex"),
        );
    }
}

/// Faces with more corners are not tested for self-intersection: the pairwise test is
/// O(k²) (a 4096-gon takes about 8 million segment tests).
pub const MAX_SIMPLICITY_CORNERS: usize = 4096;

/// The first pair of edges (edge `i` from corner `i` to `i + 1`) of a closed polygon that meet
/// other than at a shared corner, or adjacent edges that fold back onto each other.
fn self_intersection(k: usize, corner: &impl Fn(usize) -> DVec2) -> Option<(usize, usize)> {
    let orient = |a: DVec2, b: DVec2, c: DVec2| (b - a).perp_dot(c - a);
    let on_segment = |a: DVec2, b: DVec2, p: DVec2| {
        orient(a, b, p) == 0.0 && p.cmpge(a.min(b)).all() && p.cmple(a.max(b)).all()
    };
    for a in 0..k {
        let (p, q) = (corner(a), corner(a + 1));
        // Adjacent edge folding back: the next corner lies on this edge.
        if on_segment(p, q, corner(a + 2)) {
            return Some((a, (a + 1) % k));
        }
        for b in a + 2..k {
            if (b + 1) % k == a {
                continue; // adjacent through the closing corner
            }
            let (r, s) = (corner(b), corner(b + 1));
            let (d1, d2) = (orient(p, q, r), orient(p, q, s));
            let (d3, d4) = (orient(r, s, p), orient(r, s, q));
            let crosses = d1 * d2 < 0.0 && d3 * d4 < 0.0;
            let touches = on_segment(p, q, r)
                || on_segment(p, q, s)
                || on_segment(r, s, p)
                || on_segment(r, s, q);
            if crosses || touches {
                return Some((a, b));
            }
        }
    }
    None
}

/// The edge analysis (non-manifold edges and vertices, orientation), components, boundary
/// curves, Euler characteristic and genus, on `clean` (the faces `kept` of `soup`).
fn topology(
    clean: &PolygonSoup,
    kept: &[u32],
    soup: &PolygonSoup,
    push: &mut Push<'_>,
) -> CheckSummary {
    let (conn, problems) = Connectivity::analyse(clean, false);
    let original = |f: u32| kept[f as usize];
    let nf = clean.num_faces();
    // Components: faces joined through shared vertices, keyed by the root of their vertices.
    let mut joined = UnionFind::new(clean.num_vertices());
    for face in clean.faces() {
        for w in face.windows(2) {
            joined.union(w[0], w[1], false);
        }
    }
    let root_of_face: Vec<u32> = clean.faces().map(|f| joined.find(f[0]).0).collect();
    let mut components: BTreeMap<u32, Component> = BTreeMap::new();
    // Orientation: faces across an interior edge agree (parity 0), across an edge both
    // traverse the same way they disagree (parity 1); an odd cycle means no orientation exists.
    let mut orientation = UnionFind::new(nf);
    let mut first_face_of_non_orientable: BTreeMap<u32, u32> = BTreeMap::new();
    let mut relate = |f: u32, g: u32, flip: bool, orientation: &mut UnionFind| {
        if !orientation.union(f, g, flip) {
            first_face_of_non_orientable
                .entry(root_of_face[f as usize])
                .or_insert(original(f));
        }
    };
    for problem in problems {
        match problem {
            Error::NonManifoldEdge { a, b, faces } => {
                component(&mut components, joined.find(a).0).manifold = false;
                let faces: Vec<u32> = faces.into_iter().map(original).collect();
                push(
                    FindingKind::NonManifoldEdge,
                    vec![a, b],
                    faces.clone(),
                    format!(
                        "edge ({a}, {b}) is shared by {} faces {faces:?}",
                        faces.len()
                    ),
                );
            }
            Error::InconsistentOrientation { a, b, f, g } => {
                let (f, g) = (original(f), original(g));
                push(
                    FindingKind::InconsistentOrientation,
                    vec![a, b],
                    vec![f, g],
                    format!("faces {f} and {g} both traverse edge ({a} -> {b})"),
                );
            }
            _ => {}
        }
    }
    for (v, &fans) in conn.vertex_fans(clean).iter().enumerate() {
        if fans > 1 {
            component(&mut components, joined.find(v as u32).0).manifold = false;
            push(
                FindingKind::NonManifoldVertex,
                vec![v as u32],
                vec![],
                format!("vertex {v}: its faces form {fans} separate fans"),
            );
        }
    }
    // Corners per edge: 1 on the boundary, 2 for an interior edge (or an inconsistent pair),
    // more on a non-manifold edge.
    let mut corners_per_edge = vec![0u32; conn.num_edges()];
    for &e in &conn.corner_edge {
        corners_per_edge[e as usize] += 1;
    }
    // Boundary curves: the connected sets of boundary edges.
    let mut curves = UnionFind::new(clean.num_vertices());
    let mut boundary_edges = 0;
    for (e, &[c0, c1]) in conn.edge_corners.iter().enumerate() {
        let (f, c0) = (conn.corner_face[c0 as usize], c0 as usize);
        component(&mut components, root_of_face[f as usize]).edges += 1;
        if c1 != u32::MAX {
            let same_direction = clean.indices()[c0] == clean.indices()[c1 as usize];
            relate(
                f,
                conn.corner_face[c1 as usize],
                same_direction,
                &mut orientation,
            );
        } else if corners_per_edge[e] == 1 {
            let next = clean.next_corner(c0, f as usize);
            curves.union(clean.indices()[c0], clean.indices()[next], false);
            boundary_edges += 1;
        }
    }
    let mut counted_curves = HashSet::new();
    for (e, &[c0, _]) in conn.edge_corners.iter().enumerate() {
        if corners_per_edge[e] == 1 {
            let curve = curves.find(clean.indices()[c0 as usize]).0;
            if counted_curves.insert(curve) {
                let f = conn.corner_face[c0 as usize];
                component(&mut components, root_of_face[f as usize]).boundary_curves += 1;
            }
        }
    }
    for &root in &root_of_face {
        component(&mut components, root).faces += 1;
    }
    let mut in_use = vec![false; clean.num_vertices()];
    for &v in clean.indices() {
        in_use[v as usize] = true;
    }
    for v in (0..clean.num_vertices() as u32).filter(|&v| in_use[v as usize]) {
        component(&mut components, joined.find(v).0).vertices += 1;
    }
    for (root, face) in first_face_of_non_orientable {
        component(&mut components, root).orientable = false;
        push(
            FindingKind::NonOrientable,
            vec![],
            vec![face],
            format!("the component of face {face} cannot be oriented consistently (like a Möbius strip)"),
        );
    }
    let components: Vec<Component> = components
        .into_values()
        .map(|mut c| {
            c.euler_characteristic = c.vertices as i64 - c.edges as i64 + c.faces as i64;
            // χ = 2 - 2g - b for a connected orientable surface.
            let twice_genus = 2 - c.euler_characteristic - c.boundary_curves as i64;
            c.genus = (c.manifold && c.orientable && twice_genus >= 0 && twice_genus % 2 == 0)
                .then_some(twice_genus / 2);
            c
        })
        .collect();
    CheckSummary {
        vertices: soup.num_vertices(),
        faces: soup.num_faces(),
        usable_faces: nf,
        edges: conn.num_edges(),
        boundary_edges,
        boundary_curves: components.iter().map(|c| c.boundary_curves).sum(),
        euler_characteristic: components.iter().map(|c| c.euler_characteristic).sum(),
        components,
        counts: BTreeMap::new(),
    }
}

/// The component with vertex root `root`, created empty (and manifold) on first use.
fn component(components: &mut BTreeMap<u32, Component>, root: u32) -> &mut Component {
    components.entry(root).or_insert(Component {
        faces: 0,
        vertices: 0,
        edges: 0,
        boundary_curves: 0,
        euler_characteristic: 0,
        orientable: true,
        manifold: true,
        genus: None,
    })
}
