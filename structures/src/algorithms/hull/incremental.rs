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

use super::predicates::volume6;
use crate::core::error::{Error, Result};
use crate::core::ids::{FaceId, VertexId};
use crate::core::topology::MeshTopology;
use crate::families::edge_lists::winged_edge::WingedEdge;
use glam::DVec3;

/// A face of the hull being built: its corners (counter-clockwise from outside) and the face
/// across each side (`neighbours[i]` across `corners[i] → corners[i + 1]`).
pub(super) fn triangle(mesh: &WingedEdge, f: FaceId) -> ([VertexId; 3], [FaceId; 3]) {
    let mut corners = [VertexId::INVALID; 3];
    let mut neighbours = [FaceId::INVALID; 3];
    let mut i = 0;
    mesh.face_edges(f, |e| {
        if i < 3 {
            // edge_faces reports the left face (the one running v1 → v2) first.
            let mut sides = [FaceId::INVALID; 2];
            let mut n = 0;
            mesh.edge_faces(e, |g| {
                sides[n.min(1)] = g;
                n += 1;
            });
            let [a, b] = mesh.edge_vertices(e);
            let (start, other) = if sides[0] == f {
                (a, sides[1])
            } else {
                (b, sides[0])
            };
            corners[i] = start;
            neighbours[i] = other;
        }
        i += 1;
    });
    (corners, neighbours)
}

/// `Volume6` of face `f` of `mesh` and the point `p`.
pub(super) fn face_volume6(mesh: &WingedEdge, f: FaceId, p: DVec3) -> f64 {
    let (c, _) = triangle(mesh, f);
    volume6(
        mesh.position(c[0]),
        mesh.position(c[1]),
        mesh.position(c[2]),
        p,
    )
}

/// One horizon edge `a → b` (as the removed face ran it) and what replaced it.
#[derive(Copy, Clone, Debug)]
pub(super) struct HorizonEdge {
    /// Start of the edge in the removed face.
    pub a: VertexId,
    /// End of the edge in the removed face.
    pub b: VertexId,
    /// The visible face on this edge, now removed.
    pub removed: FaceId,
    /// The face on the other side, kept.
    pub kept: FaceId,
    /// The cone face (a, b, p) that replaced `removed` on this edge.
    pub created: FaceId,
}

/// Replaces the visible faces (`visible`, also marked in `is_visible` by face slot) by the
/// cone from `apex` over their border: each horizon edge a → b gets the face (a, b, apex).
/// Fills `horizon` with the horizon edges and the faces created; clears the faces' marks.
pub(super) fn replace_visible_by_cone(
    mesh: &mut WingedEdge,
    visible: &[FaceId],
    is_visible: &mut [bool],
    apex: VertexId,
    horizon: &mut Vec<HorizonEdge>,
) -> Result<()> {
    horizon.clear();
    for &f in visible {
        let (corners, neighbours) = triangle(mesh, f);
        for i in 0..3 {
            let kept = neighbours[i];
            if !kept.is_valid() {
                return Err(Error::invariant(
                    "convex hull",
                    format!("{f} has a side without a face"),
                ));
            }
            if !is_visible[kept.index()] {
                horizon.push(HorizonEdge {
                    a: corners[i],
                    b: corners[(i + 1) % 3],
                    removed: f,
                    kept,
                    created: FaceId::INVALID,
                });
            }
        }
    }
    // Remove in breadth-first order from one face, so each vertex's faces tend to go in
    // rotation order: removing them out of order makes WingedEdge::remove_face scan all
    // edges for a new av(v). `is_visible` turns false as a face is queued.
    let mut queue = Vec::with_capacity(visible.len());
    if let Some(&first) = visible.first() {
        is_visible[first.index()] = false;
        queue.push(first);
    }
    let mut next = 0;
    while next < queue.len() {
        let f = queue[next];
        next += 1;
        let (_, neighbours) = triangle(mesh, f);
        for g in neighbours {
            if g.is_valid() && is_visible[g.index()] {
                is_visible[g.index()] = false;
                queue.push(g);
            }
        }
        mesh.remove_face(f)?;
    }
    // The visible faces are connected; should one not be, it is removed all the same.
    for &f in visible {
        if mesh.is_face_live(f) {
            is_visible[f.index()] = false;
            mesh.remove_face(f)?;
        }
    }
    for h in horizon.iter_mut() {
        h.created = mesh.add_face(&[h.a, h.b, apex])?;
    }
    Ok(())
}

/// Grows `marks` to cover every face slot of `mesh`.
pub(super) fn cover_slots(marks: &mut Vec<bool>, mesh: &WingedEdge) {
    if marks.len() < mesh.face_slots() {
        marks.resize(mesh.face_slots(), false);
    }
}

/// The lecture's `Incremental3D` over `order` (distinct points; `simplex` its first tetrahedron).
/// Returns the hull (every input point a vertex, the hull's faces) and the faces created.
pub(super) fn incremental(
    points: &[DVec3],
    order: &[u32],
    simplex: [u32; 4],
) -> Result<(WingedEdge, usize)> {
    let (mut mesh, mut created) = super::start_with_tetrahedron(points, simplex)?;
    let mut is_visible = Vec::new();
    let mut visible = Vec::new();
    let mut horizon = Vec::new();
    for &k in order.iter().filter(|k| !simplex.contains(k)) {
        let p = points[k as usize];
        visible.clear();
        let mut outside = false;
        for f in mesh.live_faces() {
            let v = face_volume6(&mesh, f, p);
            outside |= v > 0.0;
            if v >= 0.0 {
                visible.push(f);
            }
        }
        if !outside {
            continue; // pk is inside P(k−1) or on its boundary: P(k) = P(k−1).
        }
        cover_slots(&mut is_visible, &mesh);
        visible.iter().for_each(|f| is_visible[f.index()] = true);
        replace_visible_by_cone(
            &mut mesh,
            &visible,
            &mut is_visible,
            VertexId(k),
            &mut horizon,
        )?;
        created += horizon.len();
        // Removed faces stay as tombstones; close the gaps once they outnumber the live faces
        // so the scan above stays proportional to the hull (no face id is held across steps).
        if mesh.face_slots() > 2 * mesh.num_faces() + 64 {
            mesh.compact();
            is_visible.clear();
        }
    }
    Ok((mesh, created))
}
