//! Adaptive refinement of triangle meshes by longest-edge bisection, over any editable
//! structure ([`MeshEdit`]): every edge longer than `max_edge` (optionally only the edges with
//! both ends inside an axis-aligned box) is split at its midpoint, longest first, until no such
//! edge is left.
//!
//! The lecture on polygon-mesh data structures asks that refinement be possible "lokal und
//! adaptiv" (slide "Was soll an polygonalen Netzen verändert werden?") and says of the
//! structures with implicit topology that they allow no adaptive refinement. The scheme here
//! is not from the lecture: it is Rivara's longest-edge bisection, carried out with the one
//! edit every editable structure offers, [`MeshEdit::split_edge`].
//!
//! **Conforming without a closure step.** Splitting an edge splits its one or two triangles
//! in two each (the new vertex joined to their third corners), so no triangle is ever left
//! with a vertex in the middle of one of its edges: the mesh stays conforming after every
//! split, and no red-green closure is needed. The topology (Euler characteristic, boundary
//! curves, genus) does not change: a split adds one vertex, and two edges and one face per
//! triangle split (interior edge: V+1, E+3, F+2; boundary edge: V+1, E+2, F+1).
//!
//! **Order.** A max-heap holds the edges still to split, keyed by length, ties broken by the
//! smaller end vertex id, then the larger; an edge enters it when it exists and qualifies (at
//! the start, or when a split makes it) and leaves it when it is split, so no edge is in it
//! twice and none goes stale. New vertices are appended (`num_vertices()` before the split, as
//! every structure promises) at `(a + b) / 2`, so the order, the new vertices and the faces are
//! the same in every structure: the result does not depend on the structure.
//!
//! **Why it is longest-edge bisection, and why it ends.** The edge split is the longest edge
//! still to split. Without a region it is therefore the longest edge of each of its triangles
//! (their other edges are still to split, so not longer, or at most `max_edge`, so shorter).
//! With a region (both ends inside, a convex box), that holds for every triangle with all three
//! corners inside; a triangle with a corner outside may have a longer edge outside the box, and
//! its new edge to that corner is outside the box too and never split. Of the edges a split of
//! an edge of length ℓ makes, the two halves have length ℓ/2, and an edge from the midpoint to
//! the third corner of a triangle whose longest edge is the split one is its median, at most
//! (√3/2) ℓ (m² = (2a² + 2b² − ℓ²)/4 with a, b ≤ ℓ). Call the input's edges round 1 and the edges
//! made by splitting an edge of round r round r + 1: an edge of round r still to split is then
//! at most (√3/2)^(r−1) L₀, with L₀ the longest input edge to split, and it is split only while
//! longer than `max_edge`. So at most [`round_bound`]`(L₀, max_edge)` =
//! ⌊ln(L₀ / max_edge) / ln(2/√3)⌋ + 1 rounds split anything, each round splits finitely many
//! edges (each split makes at most four), and the refinement ends. Each split halves an edge;
//! the bound counts rounds by the medians' factor √3/2, because a median may shrink less than
//! a half.
//!
//! Cost per split: finding the edge from its two end vertices (the structure's vertex-edge
//! query), its split (the structure's declared cost of `split_edge`), and the up to four new
//! edges pushed on the heap (O(log n)). Memory: the heap, one entry (24 bytes) per edge still
//! to split.

use crate::core::edit::{offered, EditOp, MeshEdit};
use crate::core::error::{Error, Numbering, Result};
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::topology::{first_three_corners, MeshTopology};
use glam::DVec3;
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// The name under which the refinement refuses input ([`Error::NotTriangles`]).
const NAME: &str = "adaptive refinement";

/// An axis-aligned box, closed: a point on its faces is inside.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Region {
    min: DVec3,
    max: DVec3,
}

impl Region {
    /// The box from corner `min` to corner `max`. Refused ([`Error::InvalidParameter`]) when a
    /// coordinate is not finite or `min` exceeds `max` on an axis (a flat box, `min == max` on
    /// an axis, is allowed).
    pub fn new(min: DVec3, max: DVec3) -> Result<Self> {
        let text = || {
            format!(
                "({}, {}, {}) .. ({}, {}, {})",
                min.x, min.y, min.z, max.x, max.y, max.z
            )
        };
        if !(min.is_finite() && max.is_finite()) {
            return Err(Error::InvalidParameter {
                parameter: "region",
                value: text(),
                expected: "a box of finite coordinates",
            });
        }
        if min.cmpgt(max).any() {
            return Err(Error::InvalidParameter {
                parameter: "region",
                value: text(),
                expected: "a box whose minimum is at most its maximum on every axis",
            });
        }
        Ok(Self { min, max })
    }

    /// The corner of the smallest coordinates.
    pub fn min(&self) -> DVec3 {
        self.min
    }

    /// The corner of the largest coordinates.
    pub fn max(&self) -> DVec3 {
        self.max
    }

    /// Is `p` inside the box (or on its boundary)?
    pub fn contains(&self, p: DVec3) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }
}

/// What to refine: the edges longer than `max_edge`, inside the region if one is given.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Request {
    max_edge: f64,
    region: Option<Region>,
}

impl Request {
    /// Split every edge longer than `max_edge` with both ends in `region` (every edge when
    /// `None`). Refused ([`Error::InvalidParameter`]) unless `max_edge` is finite and > 0:
    /// zero would split forever, and NaN would compare false with every length.
    pub fn new(max_edge: f64, region: Option<Region>) -> Result<Self> {
        if !(max_edge.is_finite() && max_edge > 0.0) {
            return Err(Error::InvalidParameter {
                parameter: "max_edge",
                value: max_edge.to_string(),
                expected: "a finite length greater than 0",
            });
        }
        Ok(Self { max_edge, region })
    }

    /// The longest edge left unsplit.
    pub fn max_edge(&self) -> f64 {
        self.max_edge
    }

    /// The box whose edges are refined, `None` for the whole mesh.
    pub fn region(&self) -> Option<Region> {
        self.region
    }

    /// Is the edge from `a` to `b` inside the request's region (both ends in the box; the whole
    /// mesh without one)?
    pub fn inside(&self, a: DVec3, b: DVec3) -> bool {
        self.region.is_none_or(|r| r.contains(a) && r.contains(b))
    }

    /// The length of the edge from `a` to `b` when it is to be split: inside the region and
    /// longer than `max_edge`.
    fn length_to_split(&self, a: DVec3, b: DVec3) -> Option<f64> {
        let length = a.distance(b);
        (length > self.max_edge && self.inside(a, b)).then_some(length)
    }
}

/// What [`refine_adaptive`] did.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct AdaptiveReport {
    /// Edges split (each added one vertex).
    pub edges_split: u64,
    /// Rounds that split anything: the largest round of an edge split (the input's edges are
    /// round 1, the edges a split of an edge of round r makes are round r + 1); 0 when nothing
    /// was split. At most [`round_bound`]`(longest, max_edge)`.
    pub rounds: u32,
    /// Faces before.
    pub faces_before: usize,
    /// Faces after.
    pub faces_after: usize,
    /// The longest input edge that was to be split (0 when none was).
    pub longest: f64,
}

/// The most rounds a refinement can take whose longest edge to split has length `longest`:
/// ⌊ln(longest / max_edge) / ln(2/√3)⌋ + 1 when `longest > max_edge`, else 0 (see the module
/// docs for why).
pub fn round_bound(longest: f64, max_edge: f64) -> u32 {
    if longest.partial_cmp(&max_edge) != Some(Ordering::Greater) {
        return 0;
    }
    let shrink = (2.0 / 3f64.sqrt()).ln();
    // A difference of logarithms: the ratio itself may overflow for extreme lengths.
    ((longest.ln() - max_edge.ln()) / shrink).floor() as u32 + 1
}

/// An edge still to split: its length and its end vertices, `a < b`.
#[derive(Copy, Clone, Debug)]
struct Candidate {
    length: f64,
    a: u32,
    b: u32,
    round: u32,
}

impl Candidate {
    fn new(length: f64, v: VertexId, w: VertexId, round: u32) -> Self {
        let (a, b) = if v.0 < w.0 { (v.0, w.0) } else { (w.0, v.0) };
        Self {
            length,
            a,
            b,
            round,
        }
    }
}

impl Ord for Candidate {
    /// Longest first; among equal lengths the smaller vertex ids first, so the order depends
    /// on the mesh only, never on a structure's edge numbering.
    fn cmp(&self, other: &Self) -> Ordering {
        self.length
            .total_cmp(&other.length)
            .then_with(|| other.a.cmp(&self.a))
            .then_with(|| other.b.cmp(&self.b))
    }
}

impl PartialOrd for Candidate {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl PartialEq for Candidate {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Candidate {}

/// Refuses what the refinement cannot take, before any change: a face that is not a triangle
/// ([`Error::NotTriangles`]), a coordinate that is not finite
/// ([`Error::NonFiniteCoordinate`]: its edges would be infinitely long).
fn admit<M: MeshTopology + MeshEdit>(m: &M) -> Result<()> {
    for f in 0..m.num_faces() {
        let face = FaceId::new(f);
        if m.is_deleted_face(face) {
            continue;
        }
        let mut corners = 0;
        m.face_vertices(face, |_| corners += 1);
        if corners != 3 {
            return Err(Error::NotTriangles {
                structure: NAME,
                face: f,
                corners,
            });
        }
    }
    for v in 0..m.num_vertices() {
        let vertex = VertexId::new(v);
        if m.is_deleted_vertex(vertex) {
            continue;
        }
        let p = m.position(vertex);
        if let Some(&value) = p.to_array().iter().find(|c| !c.is_finite()) {
            return Err(Error::NonFiniteCoordinate {
                vertex: v,
                value,
                numbering: Numbering::FromZero,
            });
        }
    }
    Ok(())
}

/// Each input edge to split, with its number of faces (1 on the boundary, 2 inside), calling
/// `f(length, faces)`.
fn each_edge_to_split<M: MeshEdit>(
    m: &M,
    request: &Request,
    mut f: impl FnMut(VertexId, VertexId, f64, usize),
) {
    m.for_each_edge(|e| {
        let [a, b] = m.edge_vertices(e);
        if m.is_deleted_vertex(a) || m.is_deleted_vertex(b) {
            return;
        }
        if let Some(length) = request.length_to_split(m.position(a), m.position(b)) {
            let mut faces = 0;
            m.edge_faces(e, |_| faces += 1);
            f(a, b, length, faces);
        }
    });
}

/// The fewest faces the refinement of `m` can end with: each input edge to split, of length ℓ
/// and with k faces, ends as 2^j pieces with j the fewest halvings that bring ℓ to `max_edge`
/// or below (its pieces are split at their midpoints while longer, whatever else is split), and
/// each of its 2^j − 1 splits adds k faces. A lower bound, exact for a single edge; the medians
/// a split makes are often split too, so real counts are larger (about (ℓ / `max_edge`)² faces
/// per face). Saturates at `u128::MAX`. Refuses what [`refine_adaptive`] refuses.
pub fn fewest_faces<M: MeshEdit>(m: &M, request: &Request) -> Result<u128> {
    admit(m)?;
    let mut total = m.num_faces() as u128;
    each_edge_to_split(m, request, |_, _, length, faces| {
        let mut halvings = 0u32;
        let mut piece = length;
        while piece > request.max_edge && halvings < 128 {
            piece *= 0.5;
            halvings += 1;
        }
        let splits = 1u128.checked_shl(halvings).map_or(u128::MAX, |p| p - 1);
        total = total.saturating_add(splits.saturating_mul(faces as u128));
    });
    Ok(total)
}

/// The faces the refinement of `m` is predicted to end with, for the estimate a caller states
/// before the work (and admits the memory for): [`fewest_faces`], or more where the area says
/// so. A triangle all of whose corners are in the region (every triangle without one) and
/// which has an edge to split ends as triangles whose edges are at most `max_edge` and, being
/// halves of longer edges or medians of them, mostly longer than `max_edge / 2`: it is counted
/// as its area over that of an equilateral triangle of side √0.4 `max_edge` (about 0.63
/// `max_edge`, the side that makes the counts come out: within 10% on tori of 24 and 2,000
/// faces, 10% to 20% under on a sphere and a genus-2 plate), at least one. An estimate, not a bound: skinny input
/// triangles end as fewer, closures along the region's border as more; the refinement keeps
/// its own budget. Saturates at `u128::MAX`. Refuses what [`refine_adaptive`] refuses.
pub fn predicted_faces<M: MeshEdit>(m: &M, request: &Request) -> Result<u128> {
    let fewest = fewest_faces(m, request)?;
    // The area of an equilateral triangle of side² 0.4 max_edge².
    let small = 3f64.sqrt() / 4.0 * 0.4 * request.max_edge * request.max_edge;
    let mut total = 0f64;
    for f in 0..m.num_faces() {
        let face = FaceId::new(f);
        if m.is_deleted_face(face) {
            continue;
        }
        let corners = first_three_corners(m, face).0.map(|v| m.position(v));
        let [a, b, c] = corners;
        let inside = request
            .region
            .is_none_or(|r| corners.iter().all(|&p| r.contains(p)));
        let splits = [(a, b), (b, c), (c, a)]
            .iter()
            .any(|&(p, q)| request.length_to_split(p, q).is_some());
        total += if inside && splits {
            (0.5 * (b - a).cross(c - a).length() / small).max(1.0)
        } else {
            1.0
        };
    }
    // `as` saturates: an infinite or huge total becomes u128::MAX.
    Ok(fewest.max(total.ceil() as u128))
}

/// The edge from `a` to `b`, if there is one (through the structure's vertex-edge query).
fn find_edge<M: MeshTopology>(m: &M, a: VertexId, b: VertexId) -> Option<EdgeId> {
    let mut found = None;
    m.vertex_edges(a, |e| {
        if found.is_none() && m.edge_vertices(e).contains(&b) {
            found = Some(e);
        }
    });
    found
}

/// Refines `m` as [`Request`] asks: every edge longer than `max_edge` (with both ends in the
/// region, if given) split at its midpoint, longest first, until none is left (see the module
/// docs). `max_faces` is the caller's budget: a split that would make the face count pass it
/// is not done and the refinement stops with [`Error::BudgetExceeded`], the mesh valid but
/// partly refined.
///
/// Refused before any change: a structure that does not offer [`EditOp::SplitEdge`] (as not
/// offered), polygons ([`Error::NotTriangles`]) and non-finite coordinates
/// ([`Error::NonFiniteCoordinate`]). Run it on a mesh without deleted elements (after
/// [`MeshEdit::garbage_collection`]); vertices that no face uses stay as they are.
pub fn refine_adaptive<M: MeshEdit>(
    m: &mut M,
    request: &Request,
    max_faces: usize,
) -> Result<AdaptiveReport> {
    refine_adaptive_with_progress(m, request, max_faces, |_| {})
}

/// Splits between two calls of [`refine_adaptive_with_progress`]'s `progress`.
pub const PROGRESS_EVERY: u64 = 1 << 12;

/// [`refine_adaptive`], calling `progress(faces)` with the face count every
/// [`PROGRESS_EVERY`] splits, so that a long refinement can show how far it is.
pub fn refine_adaptive_with_progress<M: MeshEdit>(
    m: &mut M,
    request: &Request,
    max_faces: usize,
    mut progress: impl FnMut(usize),
) -> Result<AdaptiveReport> {
    offered::<M>(EditOp::SplitEdge)?;
    admit(m)?;
    let mut report = AdaptiveReport {
        edges_split: 0,
        rounds: 0,
        faces_before: m.num_faces(),
        faces_after: m.num_faces(),
        longest: 0.0,
    };
    let mut heap = BinaryHeap::new();
    each_edge_to_split(m, request, |a, b, length, _| {
        heap.push(Candidate::new(length, a, b, 1));
    });
    report.longest = heap.peek().map_or(0.0, |c| c.length);
    while let Some(c) = heap.pop() {
        let (a, b) = (VertexId(c.a), VertexId(c.b));
        // An edge leaves the heap only when split, and only its split removes it: it is there.
        let e = find_edge(m, a, b).ok_or_else(|| {
            Error::invariant(
                M::NAME,
                format!("adaptive refinement: edge {a} - {b} is gone"),
            )
        })?;
        let mut faces = 0;
        m.edge_faces(e, |_| faces += 1);
        if m.num_faces() + faces > max_faces {
            return Err(Error::BudgetExceeded {
                what: "faces",
                limit: max_faces as u64,
            });
        }
        let middle = 0.5 * (m.position(a) + m.position(b));
        let v = m.split_edge(e, middle)?;
        report.edges_split += 1;
        report.rounds = report.rounds.max(c.round);
        if report.edges_split.is_multiple_of(PROGRESS_EVERY) {
            progress(m.num_faces());
        }
        // The new vertex's edges: the two halves and one to each third corner.
        let m = &*m;
        m.vertex_vertices(v, |w| {
            if let Some(length) = request.length_to_split(middle, m.position(w)) {
                heap.push(Candidate::new(length, v, w, c.round + 1));
            }
        });
    }
    report.faces_after = m.num_faces();
    Ok(report)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::families::half_edge::index::IndexHalfEdge;
    use crate::meshes;

    #[test]
    fn bad_requests_are_typed_errors() {
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let e = Request::new(bad, None).unwrap_err();
            assert_eq!(e.kind(), "invalid-parameter", "{bad}: {e}");
        }
        let e = Region::new(DVec3::ONE, DVec3::ZERO).unwrap_err();
        assert_eq!(e.kind(), "invalid-parameter", "{e}");
        let e = Region::new(DVec3::ZERO, DVec3::new(1.0, f64::NAN, 1.0)).unwrap_err();
        assert_eq!(e.kind(), "invalid-parameter", "{e}");
        assert!(Region::new(DVec3::ZERO, DVec3::new(1.0, 0.0, 1.0)).is_ok());
    }

    #[test]
    fn polygons_are_refused_before_any_change() {
        let soup = meshes::quad_cube();
        let mut m = crate::families::edge_lists::winged_edge::WingedEdge::from_soup(&soup).unwrap();
        let request = Request::new(0.1, None).unwrap();
        let e = refine_adaptive(&mut m, &request, usize::MAX).unwrap_err();
        assert_eq!(e.kind(), "not-triangles", "{e}");
        assert_eq!(m.num_faces(), soup.num_faces());
    }

    #[test]
    fn one_long_edge_is_halved_and_its_fewest_faces_are_exact() {
        // One triangle with a long base: the base is halved three times (8 pieces), the
        // medians are short enough to stay.
        let mut soup = crate::core::soup::PolygonSoup::new();
        for p in [[0.0, 0.0, 0.0], [8.0, 0.0, 0.0], [4.0, 0.5, 0.0]] {
            soup.push_vertex(DVec3::from_array(p));
        }
        soup.push_face(&[0, 1, 2]);
        let mut m = IndexHalfEdge::from_soup(&soup).unwrap();
        let request = Request::new(
            1.0,
            Some(Region::new(DVec3::splat(-1.0), DVec3::new(9.0, 0.1, 1.0)).unwrap()),
        )
        .unwrap();
        assert_eq!(fewest_faces(&m, &request).unwrap(), 8);
        let report = refine_adaptive(&mut m, &request, usize::MAX).unwrap();
        assert_eq!((report.edges_split, report.faces_after), (7, 8));
        assert_eq!(report.rounds, 3);
        m.validate().unwrap();
        // A budget below what it needs stops it with a typed error.
        let mut m = IndexHalfEdge::from_soup(&soup).unwrap();
        let e = refine_adaptive(&mut m, &request, 5).unwrap_err();
        assert_eq!(e.kind(), "budget-exceeded", "{e}");
        m.validate().unwrap();
    }

    /// The prediction is at least the lower bound, and near what a refinement of a torus and of
    /// a sphere makes (within a factor of two), with and without a region.
    #[test]
    fn the_prediction_is_near_the_refinement() {
        let region = Region::new(DVec3::splat(-0.2), DVec3::splat(2.0)).unwrap();
        for (soup, max_edge, region) in [
            (meshes::torus(12, 8), 0.05, None),
            (meshes::sphere(8, 12), 0.04, None),
            (meshes::torus(12, 8), 0.05, Some(region)),
        ] {
            let request = Request::new(max_edge, region).unwrap();
            let mut m = IndexHalfEdge::from_soup(&soup).unwrap();
            let predicted = predicted_faces(&m, &request).unwrap();
            assert!(predicted >= fewest_faces(&m, &request).unwrap());
            let mut calls = Vec::new();
            let report =
                refine_adaptive_with_progress(&mut m, &request, usize::MAX, |f| calls.push(f))
                    .unwrap();
            let (got, p) = (report.faces_after as f64, predicted as f64);
            assert!(
                p <= 2.0 * got && got <= 2.0 * p,
                "{p} predicted, {got} made"
            );
            // Progress every PROGRESS_EVERY splits, the face count growing.
            assert_eq!(calls.len() as u64, report.edges_split / PROGRESS_EVERY);
            assert!(calls.windows(2).all(|w| w[0] < w[1]), "{calls:?}");
        }
    }

    #[test]
    fn the_round_bound() {
        assert_eq!(round_bound(1.0, 1.0), 0);
        assert_eq!(round_bound(1.0, 2.0), 0);
        assert_eq!(round_bound(1.1, 1.0), 1);
        // (2/√3)^4 = 16/9 ≈ 1.78.
        assert_eq!(round_bound(1.77, 1.0), 4);
        assert_eq!(round_bound(1.78, 1.0), 5);
        // The ratio overflows f64; the bound does not.
        let extreme = round_bound(f64::MAX, f64::MIN_POSITIVE);
        assert!((9000..10_000).contains(&extreme), "{extreme}");
    }
}
