//! `Incremental3D` of the lecture on 3D convex hulls: O(n²).
//!
//! ```text
//! P3 ← Tetraedro(p0, p1, p2, p3)
//! for k ← 4 .. n−1:
//!     for each face f of P(k−1): v ← Volume6(f, pk); mark f visible if v > 0
//!     if no face is visible: P(k) ← P(k−1)
//!     else: build the face of e and pk for each edge e on the border of the visible faces
//!           (the horizon), remove the visible faces
//! ```
//!
//! Beyond the lecture (which assumes no four points coplanar): once some face is strictly
//! visible (`Volume6 > 0`, so pk is outside), faces with `Volume6 = 0` (pk in their plane)
//! are removed too. They are exactly the faces that a point moved slightly further out would
//! see strictly, so the visible region is still one disk bounded by one horizon cycle, no
//! cone face is degenerate (pk on a horizon edge's line would be in the plane of the kept face
//! too), and every vertex that the new point makes non-extreme (inside a facet or on an edge
//! of the new hull) loses all its faces. The hull's vertices are therefore exactly its
//! extreme points, whatever the order; coplanar facets come out triangulated.

use super::plane::{FacePlane, TestCount};
use super::Work;
use crate::core::error::Result;
use crate::core::ids::VertexId;
use crate::families::edge_lists::winged_edge::WingedEdge;
use glam::DVec3;

/// The lecture's `Incremental3D` over `order` (distinct points; `simplex` its first
/// tetrahedron). Returns the hull (every input point a vertex, the hull's faces), the number
/// of faces created and the work. Each face's plane is kept by slot ([`FacePlane`]), and the
/// visible faces are replaced by the cone in one step ([`WingedEdge::replace_by_cone`],
/// O(visible + horizon)), so a step costs O(faces of P(k−1)): the scan.
pub(super) fn incremental(
    points: &[DVec3],
    order: &[u32],
    simplex: [u32; 4],
) -> Result<(WingedEdge, usize, Work)> {
    let (mut mesh, first) = super::start_with_tetrahedron(points, simplex)?;
    let at = |v: VertexId| points[v.index()];
    let plane = |[a, b, c]: [VertexId; 3]| FacePlane::new(at(a), at(b), at(c));
    let mut planes: Vec<FacePlane> = first.into_iter().map(plane).collect();
    let mut created = planes.len();
    let mut count = TestCount::default();
    let mut visible = Vec::new();
    let mut horizon = Vec::new();
    for &k in order.iter().filter(|k| !simplex.contains(k)) {
        let p = points[k as usize];
        visible.clear();
        let mut outside = false;
        for f in mesh.live_faces() {
            let v = planes[f.index()].volume6(p, &mut count);
            outside |= v > 0.0;
            if v >= 0.0 {
                visible.push(f);
            }
        }
        if !outside {
            continue; // pk is inside P(k−1) or on its boundary: P(k) = P(k−1).
        }
        let apex = VertexId(k);
        mesh.replace_by_cone(&visible, apex, &mut horizon)?;
        created += horizon.len();
        planes.resize(mesh.face_slots(), planes[0]);
        for h in &horizon {
            planes[h.created.index()] = plane([h.a, h.b, apex]);
        }
    }
    let work = Work {
        volume6_tests: count.tests,
        exact_tests: count.exact,
        conflict_work: 0,
    };
    Ok((mesh, created, work))
}
