//! Decimation by quadric error (Garland & Heckbert, "Surface simplification using quadric
//! error metrics", SIGGRAPH 1997) on any [`MeshEdit`] structure, as OpenMesh's `DecimaterT`
//! with `ModQuadricT` runs it, and the reconstruction of the original mesh from its record
//! ([`reconstruct`]): the thinning "for compression and level of detail" of the lecture on
//! polygon-mesh data structures, where "the selection strategy when removing polygons" decides
//! and "reconstruction must be possible again".
//!
//! ## What it follows
//!
//! - **Quadrics** (`ModQuadricT::initialize`): per triangle the plane through it, unit normal
//!   `n = (p1 − p0) × (p2 − p0) / |…|`, `d = −n·p0`; its quadric `(n, d)(n, d)ᵀ` weighted by
//!   the triangle's area (OpenMesh's default; a degenerate triangle, `|…| ≤ FLT_MIN`, keeps
//!   the unnormalised normal and weight `|…|`, as there) is added to each of its three
//!   vertices.
//! - **Candidates** (`DecimaterT::heap_vertex`): a heap of vertices, each keyed by its best
//!   outgoing half-edge collapse, the error `(Q_from + Q_to)(p_to)` rounded to `f32` as
//!   OpenMesh's priorities are. A collapse moves `from` onto `to`: no optimal placement (the
//!   `CollapseInfo` of OpenMesh keeps `p1`, the remaining vertex's position).
//! - **Legality**: OpenMesh tests each candidate with `is_collapse_legal` before heaping it;
//!   here the candidate is tested when it comes off the heap, by [`MeshEdit::collapse_edge`]'s
//!   own refusal (the link condition and the tetrahedron test of `is_collapse_ok`, the same
//!   tests), and a refused vertex goes back on the heap with its next-best neighbour (the
//!   order `(error, to)`), which is the candidate OpenMesh would have heaped.
//! - **Geometry**: a collapse that would flip a surviving face around `from` (its normal's dot
//!   product with the old one not positive) or leave it without area is skipped like a
//!   refused one: OpenMesh's `ModNormalFlippingT` at its default 90°, the module OpenMesh users
//!   add beside `ModQuadricT` (the report's OpenMesh baseline runs `ModQuadricT` alone, so this
//!   test is work the lab does and OpenMesh does not). Without it, flat regions decimate into
//!   zero-area triangles.
//! - **After a collapse** (`postprocess_collapse`): `Q_to += Q_from`, and every former
//!   neighbour of `from` is heaped again.
//! - **Stop** (`decimate_to_faces`): when the live face count is at most the target or no
//!   candidate is left; each collapse removes two triangles.
//!
//! Two differences, both documented choices: a **boundary vertex is never removed** (OpenMesh
//! lets one slide along its boundary edge; here every collapse is the inverse of a
//! [`MeshEdit::split_vertex`], which splits interior fans only, so that [`reconstruct`] can
//! always undo it; on closed meshes, the report's tori, nothing differs), and an error that
//! round-off makes negative (flat regions) counts as 0, where OpenMesh skips the candidate.
//!
//! CGAL's `Surface_mesh_simplification::edge_collapse` with the Garland–Heckbert policies
//! differs more: it keys edges, not vertices, and places the new vertex at the quadric's
//! minimiser; the report sets both beside this one, with the error measured the same way on
//! every result.
//!
//! ## Cost
//!
//! O(n log n) for n vertices: each collapse touches the neighbourhoods of its two vertices
//! (O(k)) and updates O(k) heap keys (O(log n) each).

mod heap;
mod reconstruct;

pub use reconstruct::{reconstruct, same_mesh, Difference, Reconstruction};

use crate::core::edit::MeshEdit;
use crate::core::error::{Error, Result};
use crate::core::ids::{FaceId, VertexId};
use crate::core::topology::MeshTopology;
use glam::DVec3;
use heap::VertexHeap;

/// A symmetric 4 × 4 error quadric, its ten distinct entries in OpenMesh's `QuadricT` order
/// (`a b c d / e f g / h i / j`, the upper triangle row by row).
#[derive(Copy, Clone, Debug, Default, PartialEq)]
pub struct Quadric(pub [f64; 10]);

impl Quadric {
    /// The quadric of the plane `a x + b y + c z + d = 0`: the squared distance to it when
    /// `(a, b, c)` is a unit vector.
    pub fn plane(a: f64, b: f64, c: f64, d: f64) -> Self {
        Self([
            a * a,
            a * b,
            a * c,
            a * d,
            b * b,
            b * c,
            b * d,
            c * c,
            c * d,
            d * d,
        ])
    }

    /// `self + o`.
    #[inline]
    pub fn add(&self, o: &Self) -> Self {
        let mut q = *self;
        q.add_assign(o);
        q
    }

    /// `self += o`.
    #[inline]
    pub fn add_assign(&mut self, o: &Self) {
        for (a, b) in self.0.iter_mut().zip(o.0) {
            *a += b;
        }
    }

    /// `self *= s`.
    pub fn scale(&mut self, s: f64) {
        for a in &mut self.0 {
            *a *= s;
        }
    }

    /// `(p, 1) Q (p, 1)ᵀ`: the weighted sum of squared distances to the planes of `Q`.
    #[inline]
    pub fn eval(&self, p: DVec3) -> f64 {
        let [a, b, c, d, e, f, g, h, i, j] = self.0;
        let (x, y, z) = (p.x, p.y, p.z);
        a * x * x
            + 2.0 * b * x * y
            + 2.0 * c * x * z
            + 2.0 * d * x
            + e * y * y
            + 2.0 * f * y * z
            + 2.0 * g * y
            + h * z * z
            + 2.0 * i * z
            + j
    }
}

/// The quadric of triangle `(p0, p1, p2)`, area-weighted as OpenMesh's `ModQuadricT` makes it.
pub fn triangle_quadric(p0: DVec3, p1: DVec3, p2: DVec3) -> Quadric {
    let mut n = (p1 - p0).cross(p2 - p0);
    let mut area = n.length();
    if area > f64::from(f32::MIN_POSITIVE) {
        n /= area;
        area *= 0.5;
    }
    let mut q = Quadric::plane(n.x, n.y, n.z, -p0.dot(n));
    q.scale(area);
    q
}

/// The per-vertex quadrics of `m`: each live triangle's [`triangle_quadric`] added to its
/// corners (a polygon's first three corners, as OpenMesh's face-vertex walk takes them).
pub fn vertex_quadrics<M: MeshEdit>(m: &M) -> Vec<Quadric> {
    let mut q = vec![Quadric::default(); m.num_vertices()];
    let mut corners = [0u32; 3];
    for f in 0..m.num_faces() {
        let f = FaceId::new(f);
        if m.is_deleted_face(f) {
            continue;
        }
        let mut k = 0;
        m.face_vertices(f, |v| {
            if k < 3 {
                corners[k] = v.0;
            }
            k += 1;
        });
        let p = corners.map(|v| m.position(VertexId(v)));
        let fq = triangle_quadric(p[0], p[1], p[2]);
        for v in corners {
            q[v as usize].add_assign(&fq);
        }
    }
    q
}

/// The record of a decimation, one entry per collapse in the order done, structure of arrays:
/// collapse `i` moved `from[i]` (then at `position[i]`) onto `to[i]` and deleted the
/// triangles (`from`, `to`, `left`) and (`to`, `from`, `right`). What [`reconstruct`] replays
/// backwards with vertex splits.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Collapses {
    /// The removed vertex of each collapse.
    pub from: Vec<u32>,
    /// The vertex it was collapsed onto.
    pub to: Vec<u32>,
    /// The third corner of the triangle left of `from → to`.
    pub left: Vec<u32>,
    /// The third corner of the triangle right of it.
    pub right: Vec<u32>,
    /// `from`'s position.
    pub position: Vec<DVec3>,
    /// The quadric error of each collapse (its heap key, in `f64`).
    pub error: Vec<f64>,
}

impl Collapses {
    /// The number of collapses.
    pub fn len(&self) -> usize {
        self.from.len()
    }

    /// No collapse was done.
    pub fn is_empty(&self) -> bool {
        self.from.is_empty()
    }
}

/// What [`decimate`] did.
#[derive(Clone, Debug, Default)]
pub struct Decimation {
    /// Every collapse, in order.
    pub collapses: Collapses,
    /// Live faces before.
    pub faces_before: usize,
    /// Live faces after (at most the target, unless no legal collapse was left).
    pub faces_after: usize,
}

/// The decimater's state: the per-vertex arrays of `DecimaterT` and `ModQuadricT`.
struct Decimater {
    quadric: Vec<Quadric>,
    /// Per vertex, the best neighbour to collapse onto ([`u32::MAX`]: none).
    target: Vec<u32>,
    /// Per vertex, that collapse's error: the heap key.
    priority: Vec<f32>,
    heap: VertexHeap,
}

impl Decimater {
    /// `DecimaterT::heap_vertex`: finds `v`'s best collapse (the smallest `(error, to)`, after
    /// `after` when given) and (re)heaps `v`, or takes it out when it has none.
    fn heap_vertex<M: MeshEdit>(&mut self, m: &M, v: u32, after: Option<(f32, u32)>) {
        let vid = VertexId(v);
        let mut best: Option<(f32, u32)> = None;
        if !m.is_boundary_vertex(vid) {
            let qv = self.quadric[v as usize];
            m.vertex_vertices(vid, |w| {
                let err = qv.add(&self.quadric[w.index()]).eval(m.position(w));
                // Round-off on flat regions: OpenMesh skips negative errors, they count as 0.
                let key = (err.max(0.0) as f32, w.0);
                // An error past f32 (or NaN) is no candidate, as in OpenMesh (prio < FLT_MAX).
                if key.0.is_nan() || key.0 >= f32::MAX {
                    return;
                }
                if after.is_some_and(|a| key <= a) {
                    return;
                }
                if best.is_none_or(|b| key < b) {
                    best = Some(key);
                }
            });
        }
        match best {
            Some((p, w)) => {
                self.priority[v as usize] = p;
                self.target[v as usize] = w;
                self.heap.upsert(v, &self.priority);
            }
            None => {
                self.heap.remove(v, &self.priority);
                self.target[v as usize] = u32::MAX;
                self.priority[v as usize] = -1.0;
            }
        }
    }
}

/// The third corners of the triangles left and right of `from → to` (both exist: `from` is
/// an interior vertex).
fn wings<M: MeshTopology>(m: &M, from: VertexId, to: VertexId) -> Option<(u32, u32)> {
    let (mut left, mut right) = (None, None);
    m.vertex_faces(from, |f| {
        let mut c = [u32::MAX; 4];
        let mut k = 0;
        m.face_vertices(f, |v| {
            if k < 4 {
                c[k] = v.0;
            }
            k += 1;
        });
        if k != 3 {
            return;
        }
        for i in 0..3 {
            let (a, b, x) = (c[i], c[(i + 1) % 3], c[(i + 2) % 3]);
            if (a, b) == (from.0, to.0) {
                left = Some(x);
            } else if (a, b) == (to.0, from.0) {
                right = Some(x);
            }
        }
    });
    Some((left?, right?))
}

/// Would moving `from` onto `to` keep every face around `from` that survives the collapse
/// (those without `to`) facing the same side, and not degenerate? OpenMesh's
/// `ModNormalFlippingT` test at its default maximal deviation of 90° (the new normal's dot
/// product with the old one must stay positive), which also refuses a face that would lose
/// its area: the collapses quadric error alone allows on flat regions would otherwise leave
/// zero-area triangles, which `topolab check` reports.
fn keeps_faces<M: MeshTopology>(m: &M, from: VertexId, to: VertexId) -> bool {
    let p_to = m.position(to);
    let mut ok = true;
    m.vertex_faces(from, |f| {
        if !ok {
            return;
        }
        let mut c = [VertexId(u32::MAX); 3];
        let mut k = 0;
        m.face_vertices(f, |v| {
            if k < 3 {
                c[k] = v;
            }
            k += 1;
        });
        if k != 3 || c.contains(&to) {
            return;
        }
        let p = c.map(|v| m.position(v));
        let q = c.map(|v| if v == from { p_to } else { m.position(v) });
        let before = (p[1] - p[0]).cross(p[2] - p[0]);
        let after = (q[1] - q[0]).cross(q[2] - q[0]);
        if before.dot(after) <= 0.0 || after.length() <= 1e-6 * before.length() {
            ok = false;
        }
    });
    ok
}

/// Decimates `m` by quadric error until at most `target_faces` live faces remain or no legal
/// collapse is left (see the module docs for the algorithm). Deleted elements stay marked
/// (call [`MeshEdit::garbage_collection`] to compact them; [`reconstruct`] needs them
/// uncollected). Errors other than a collapse's refusal are returned as they come.
pub fn decimate<M: MeshEdit>(m: &mut M, target_faces: usize) -> Result<Decimation> {
    let n = m.num_vertices();
    let mut faces = (0..m.num_faces())
        .filter(|&f| !m.is_deleted_face(FaceId::new(f)))
        .count();
    let mut out = Decimation {
        faces_before: faces,
        ..Decimation::default()
    };
    let mut d = Decimater {
        quadric: vertex_quadrics(m),
        target: vec![u32::MAX; n],
        priority: vec![-1.0; n],
        heap: VertexHeap::new(n),
    };
    for v in 0..n as u32 {
        if !m.is_deleted_vertex(VertexId(v)) {
            d.heap_vertex(m, v, None);
        }
    }
    let mut support: Vec<u32> = Vec::with_capacity(16);
    let c = &mut out.collapses;
    while faces > target_faces {
        let Some(v) = d.heap.pop(&d.priority) else {
            break;
        };
        let (from, to) = (VertexId(v), VertexId(d.target[v as usize]));
        let Some((left, right)) = wings(m, from, to) else {
            // Not two triangles around the edge: the collapse would be refused.
            d.heap_vertex(m, v, Some((d.priority[v as usize], to.0)));
            continue;
        };
        if !keeps_faces(m, from, to) {
            d.heap_vertex(m, v, Some((d.priority[v as usize], to.0)));
            continue;
        }
        support.clear();
        m.vertex_vertices(from, |w| support.push(w.0));
        let position = m.position(from);
        match m.collapse_edge(from, to) {
            Ok(()) => {}
            Err(Error::EditRefused { .. }) => {
                d.heap_vertex(m, v, Some((d.priority[v as usize], to.0)));
                continue;
            }
            Err(e) => return Err(e),
        }
        faces -= 2;
        let qv = d.quadric[v as usize];
        c.from.push(v);
        c.to.push(to.0);
        c.left.push(left);
        c.right.push(right);
        c.position.push(position);
        c.error
            .push(qv.add(&d.quadric[to.index()]).eval(m.position(to)).max(0.0));
        d.quadric[to.index()].add_assign(&qv);
        for &s in &support {
            d.heap_vertex(m, s, None);
        }
    }
    out.faces_after = faces;
    Ok(out)
}

/// The fewest faces a triangle mesh with `m`'s topology can keep, and the rule: per
/// connected component, a closed surface of genus g needs at least `2 (V − 2 + 2g)` faces
/// with `V` the fewest vertices of a triangulation of it (Heawood's bound, `⌈(7 + √(1 + 48
/// g)) / 2⌉`, reached except for g = 2, where it is 10; 4 for the sphere, the tetrahedron:
/// 4 faces; 7 for the torus: 14 faces); a component with a boundary needs at least one.
pub fn minimum_faces<M: MeshTopology>(m: &M) -> usize {
    // Components by union-find over the edges.
    let n = m.num_vertices();
    let mut parent: Vec<u32> = (0..n as u32).collect();
    fn find(p: &mut [u32], mut x: u32) -> u32 {
        while p[x as usize] != x {
            p[x as usize] = p[p[x as usize] as usize];
            x = p[x as usize];
        }
        x
    }
    m.for_each_edge(|e| {
        let [a, b] = m.edge_vertices(e);
        let (ra, rb) = (find(&mut parent, a.0), find(&mut parent, b.0));
        if ra != rb {
            parent[ra as usize] = rb;
        }
    });
    // Per root: vertices, edges, faces, boundary edges.
    let mut count = vec![[0i64; 4]; n];
    let mut used = vec![false; n];
    m.for_each_edge(|e| {
        let [a, _] = m.edge_vertices(e);
        let r = find(&mut parent, a.0) as usize;
        count[r][1] += 1;
        count[r][3] += m.is_boundary_edge(e) as i64;
        used[a.index()] = true;
        used[m.edge_vertices(e)[1].index()] = true;
    });
    for (v, _) in used.iter().enumerate().filter(|(_, &u)| u) {
        let r = find(&mut parent, v as u32) as usize;
        count[r][0] += 1;
    }
    for f in 0..m.num_faces() {
        let mut first = None;
        m.face_vertices(FaceId::new(f), |v| {
            first.get_or_insert(v.0);
        });
        if let Some(v) = first {
            let r = find(&mut parent, v) as usize;
            count[r][2] += 1;
        }
    }
    count
        .iter()
        .filter(|c| c[2] > 0)
        .map(|&[v, e, f, b]| {
            if b > 0 {
                return 1;
            }
            let genus = ((2 - (v - e + f)) / 2).max(0);
            let least = match genus {
                0 => 4,
                2 => 10,
                g => ((7.0 + ((1 + 48 * g) as f64).sqrt()) / 2.0).ceil() as i64,
            };
            (2 * (least - 2 + 2 * genus)) as usize
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::meshes;
    use crate::IndexHalfEdge;

    #[test]
    fn a_plane_quadric_measures_squared_distance_times_area() {
        let q = triangle_quadric(
            DVec3::ZERO,
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(0.0, 2.0, 0.0),
        );
        // Area 2, the plane z = 0: 2 · 3².
        assert!((q.eval(DVec3::new(5.0, -1.0, 3.0)) - 18.0).abs() < 1e-12);
    }

    #[test]
    fn decimating_a_torus_reaches_the_target_and_stays_valid() {
        let soup = meshes::torus(20, 12);
        let mut m = IndexHalfEdge::from_soup(&soup).expect("manifold");
        let d = decimate(&mut m, 48).expect("decimates");
        assert_eq!(d.faces_before, 480);
        assert!(
            d.faces_after <= 48 && d.faces_after >= 46,
            "{}",
            d.faces_after
        );
        assert_eq!(d.collapses.len(), (480 - d.faces_after) / 2);
        m.validate().expect("valid");
        m.garbage_collection();
        assert_eq!(m.num_faces(), d.faces_after);
        // Errors are the heap's order only roughly (keys change), but never negative.
        assert!(d.collapses.error.iter().all(|&e| e >= 0.0));
    }

    #[test]
    fn the_minimum_follows_the_genus() {
        let tetra = IndexHalfEdge::from_soup(&meshes::closed_tetrahedron()).expect("ok");
        assert_eq!(minimum_faces(&tetra), 4);
        let torus = IndexHalfEdge::from_soup(&meshes::torus(8, 6)).expect("ok");
        assert_eq!(minimum_faces(&torus), 14);
        let grid = IndexHalfEdge::from_soup(&meshes::grid(4, 4, true)).expect("ok");
        assert_eq!(minimum_faces(&grid), 1);
        let g3 = IndexHalfEdge::from_soup(&meshes::perforated_plate(3, 0, 600)).expect("ok");
        // Heawood: ⌈(7 + √145) / 2⌉ = 10 vertices, 2 (10 − 2 + 6) = 28 faces.
        assert_eq!(minimum_faces(&g3), 28);
    }

    #[test]
    fn a_sphere_goes_down_to_a_tetrahedron_at_the_least() {
        let mut m = IndexHalfEdge::from_soup(&meshes::sphere(6, 8)).expect("manifold");
        let d = decimate(&mut m, 0).expect("decimates");
        assert!(d.faces_after >= 4, "{}", d.faces_after);
        m.validate().expect("valid");
    }
}
