//! `Embrulho3D` of the lecture on 3D convex hulls: gift wrapping (Chand & Kapur), O(n·h).
//!
//! ```text
//! Q ← queue of faces found; T ← winged-edge
//! f ← FaceInicial(P); insert f in Q and T
//! while Q is not empty: f ← remove from Q
//!     for each free edge e of f: f' ← FaceAdjacente(f, e); insert f' in Q and T
//! ```
//!
//! `FaceInicial`, by rotating planes as in the lecture: p0 is the point of least z (ties: least
//! y, then x, so it is extreme). The horizontal half-plane through the line L through p0
//! parallel to the x axis, pointing towards +y, is turned from Y towards Z until it meets a
//! point p1; then the plane is turned around p0 p1 until it meets p2.
//!
//! `FaceAdjacente(f, e)`: the plane of f is turned around e until every point is on its inner
//! side; one pass over the points keeps the candidate that the most turned plane meets (the
//! lecture's O(n) per edge, so O(n·h) in all).
//!
//! Beyond the lecture (which assumes no four points coplanar): a plane found this way may hold
//! more than three points. The face is then the convex polygon of all points in that plane
//! (the lecture's 2D gift wrapping, Jarvis, inside the plane, keeping the farthest of collinear
//! points), so every face is a whole facet, every free edge is a true hull edge, and points
//! inside a facet or an edge never become vertices. Each facet is stored as a fan of
//! triangles from its first corner, so all three algorithms return triangles; a facet's
//! triangulation differs between algorithms, its vertices do not. "Free" edges are tracked
//! as directed facet sides: the facet across side a → b runs b → a, and it is wrapped only if
//! no facet found so far has the side b → a.

use super::predicates::{collinear, farther_on_ray, volume6};
use super::Work;
use crate::core::error::{Error, Result};
use crate::core::ids::VertexId;
use crate::families::edge_lists::winged_edge::WingedEdge;
use glam::DVec3;
use std::cell::Cell;
use std::collections::{HashSet, VecDeque};

/// The points and the distinct ones among them (the only candidates).
struct Wrapper<'a> {
    points: &'a [DVec3],
    distinct: &'a [u32],
    /// `Volume6` evaluations so far.
    tests: Cell<u64>,
}

fn broken(message: impl Into<String>) -> Error {
    Error::invariant("gift wrapping", message)
}

impl Wrapper<'_> {
    #[inline]
    fn at(&self, i: u32) -> DVec3 {
        self.points[i as usize]
    }

    /// `Volume6`, counted.
    #[inline]
    fn volume6(&self, a: DVec3, b: DVec3, c: DVec3, p: DVec3) -> f64 {
        self.tests.set(self.tests.get() + 1);
        volume6(a, b, c, p)
    }

    /// Turns a plane around the line u v: the point q (not on the line) such that every point
    /// is on the inner side of the face (v, u, q), i.e. `Volume6(v, u, q, r) ≤ 0` for all r.
    /// One pass is enough while no two points lie at exactly opposite angles around the line,
    /// which the callers ensure (see the module docs).
    fn pivot(&self, u: DVec3, v: DVec3) -> Option<u32> {
        let mut best: Option<u32> = None;
        for &r in self.distinct {
            let pr = self.at(r);
            if collinear(u, v, pr) {
                continue;
            }
            match best {
                Some(q) if self.volume6(v, u, self.at(q), pr) <= 0.0 => {}
                _ => best = Some(r),
            }
        }
        best
    }

    /// The points in the plane of the face (a, b, c), and one point strictly inside (below).
    fn plane_points(&self, a: DVec3, b: DVec3, c: DVec3) -> Result<(Vec<u32>, DVec3)> {
        let mut on = Vec::new();
        let mut inner = None;
        for &r in self.distinct {
            let v = self.volume6(a, b, c, self.at(r));
            if v == 0.0 {
                on.push(r);
            } else if v < 0.0 {
                inner.get_or_insert(self.at(r));
            } else {
                return Err(broken("a point is outside a supporting plane"));
            }
        }
        let inner = inner.ok_or_else(|| broken("no point off a supporting plane"))?;
        Ok((on, inner))
    }

    /// 2D gift wrapping (Jarvis) of the points `on` of one plane, counter-clockwise seen from
    /// the side opposite `inner`: from the corner `start` until the next corner would be
    /// `start` again, or up to and including `stop`. Each step keeps every point on the left
    /// of the new side, and the farthest of collinear ones, so only corners are returned.
    fn jarvis(&self, on: &[u32], inner: DVec3, start: u32, stop: u32) -> Result<Vec<u32>> {
        let mut polygon = vec![start];
        let mut current = start;
        loop {
            let pc = self.at(current);
            let mut next: Option<u32> = None;
            for &s in on.iter().filter(|&&s| s != current) {
                let ps = self.at(s);
                next = Some(match next {
                    None => s,
                    Some(w) => {
                        let pw = self.at(w);
                        // Counter-clockwise seen from outside: inner is below, Volume6 < 0.
                        let v = self.volume6(pc, pw, ps, inner);
                        if v > 0.0 || (v == 0.0 && farther_on_ray(pc, pw, ps)) {
                            s
                        } else {
                            w
                        }
                    }
                });
            }
            let next = next.ok_or_else(|| broken("a facet with one point"))?;
            if next == start {
                break;
            }
            polygon.push(next);
            if next == stop {
                break;
            }
            if polygon.len() > on.len() {
                return Err(broken("the 2D wrap of a facet does not close"));
            }
            current = next;
        }
        if polygon.len() < 3 {
            return Err(broken("a facet with fewer than three corners"));
        }
        Ok(polygon)
    }

    /// The lecture's `FaceInicial`, by rotating planes (see the module docs).
    fn initial_face(&self) -> Result<Vec<u32>> {
        let lowest = |&i: &u32| {
            let p = self.at(i);
            [p.z, p.y, p.x]
        };
        let p0 = *self
            .distinct
            .iter()
            .min_by(|a, b| lowest(a).partial_cmp(&lowest(b)).expect("finite"))
            .ok_or_else(|| broken("no points"))?;
        let a = self.at(p0);
        // A second point of L (p0's line parallel to x), exactly representable.
        let along_x = if a.x + 1.0 != a.x {
            a.x + 1.0
        } else {
            a.x / 2.0
        };
        let l = DVec3::new(along_x, a.y, a.z);
        // Turning the half-plane around L from Y towards Z: every point has z ≥ p0.z, and
        // none is at the angle opposite the starting half-plane, so the pivot applies.
        let q1 = self
            .pivot(a, l)
            .ok_or_else(|| broken("all points on one line"))?;
        let (on, inner) = self.plane_points(l, a, self.at(q1))?;
        if on.iter().any(|&r| !collinear(a, self.at(q1), self.at(r))) {
            // The plane through L and p1 already holds a facet.
            return self.jarvis(&on, inner, p0, p0);
        }
        // The plane meets the hull in an edge p0 p1 (p1 the farthest point on it): turn the
        // plane around p0 p1 until it meets p2.
        let p1 = on.iter().copied().filter(|&r| r != p0).fold(q1, |w, r| {
            if farther_on_ray(a, self.at(w), self.at(r)) {
                r
            } else {
                w
            }
        });
        let b = self.at(p1);
        let p2 = self
            .pivot(a, b)
            .ok_or_else(|| broken("all points on one line"))?;
        let (on, inner) = self.plane_points(b, a, self.at(p2))?;
        self.jarvis(&on, inner, p0, p0)
    }

    /// The lecture's `FaceAdjacente`: the facet across side a → b of a facet; it runs b → a.
    fn adjacent_face(&self, a: u32, b: u32) -> Result<Vec<u32>> {
        let (pa, pb) = (self.at(a), self.at(b));
        let q = self
            .pivot(pa, pb)
            .ok_or_else(|| broken("all points on one line"))?;
        let (on, inner) = self.plane_points(pb, pa, self.at(q))?;
        self.jarvis(&on, inner, a, b)
    }
}

/// The facets found so far (the lecture's queue Q, and what tells free sides from the others).
#[derive(Default)]
struct Found {
    /// Facets whose sides are still to be wrapped (the lecture's Q).
    queue: VecDeque<Vec<u32>>,
    /// Directed sides of every facet found: the facet across a → b is found iff b → a is here.
    sides: HashSet<(u32, u32)>,
    /// Facets found.
    facets: usize,
    /// Triangles added to the winged-edge (each facet's fan).
    triangles: usize,
}

impl Found {
    /// Records `facet` (the lecture's InsiraFila and InsiraWE): its sides, its fan in `mesh`.
    fn insert(&mut self, facet: Vec<u32>, mesh: &mut WingedEdge) -> Result<()> {
        for i in 0..facet.len() {
            if !self.sides.insert((facet[i], facet[(i + 1) % facet.len()])) {
                return Err(broken("a facet side found twice"));
            }
        }
        for i in 1..facet.len() - 1 {
            mesh.add_face(&[facet[0], facet[i], facet[i + 1]].map(VertexId))?;
            self.triangles += 1;
        }
        self.facets += 1;
        self.queue.push_back(facet);
        Ok(())
    }
}

/// `Embrulho3D` over the distinct points `distinct`. Returns the hull, the number of
/// triangles created (every facet's fan) and the work.
pub(super) fn gift_wrap(points: &[DVec3], distinct: &[u32]) -> Result<(WingedEdge, usize, Work)> {
    let wrapper = Wrapper {
        points,
        distinct,
        tests: Cell::new(0),
    };
    let mut mesh = WingedEdge::new();
    points.iter().for_each(|&p| {
        mesh.add_vertex(p);
    });
    let mut found = Found::default();
    found.insert(wrapper.initial_face()?, &mut mesh)?;
    while let Some(facet) = found.queue.pop_front() {
        for i in 0..facet.len() {
            let (a, b) = (facet[i], facet[(i + 1) % facet.len()]);
            if found.sides.contains(&(b, a)) {
                continue; // Not free: the facet across was found already.
            }
            // A polytope with n vertices has at most 2n − 4 facets: more means a bug, and
            // stopping here keeps a bug from looping.
            if found.facets >= 2 * distinct.len() {
                return Err(broken("more facets than a polytope can have"));
            }
            found.insert(wrapper.adjacent_face(a, b)?, &mut mesh)?;
        }
    }
    let work = Work {
        volume6_tests: wrapper.tests.get(),
        ..Work::default()
    };
    Ok((mesh, found.triangles, work))
}
