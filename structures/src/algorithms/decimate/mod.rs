//! Decimation by quadric error (Garland & Heckbert, "Surface simplification using quadric
//! error metrics", SIGGRAPH 1997) on any [`MeshEdit`] structure, with two strategies for its
//! candidates ([`Strategy`]): OpenMesh's `DecimaterT` with `ModQuadricT` alone, step for step
//! ([`Strategy::Eager`]: what the report times against OpenMesh's own Decimater), and the
//! lab's lazy one ([`Strategy::Lazy`]); and the reconstruction of the original mesh from the
//! record of either ([`reconstruct`]): the thinning "for compression and level of detail" of
//! the lecture on polygon-mesh data structures, where "the selection strategy when removing
//! polygons" decides and "reconstruction must be possible again".
//!
//! ## What both do, as OpenMesh does
//!
//! - **Quadrics** (`ModQuadricT::initialize`): per triangle the plane through it, unit normal
//!   `n = (p1 − p0) × (p2 − p0) / |…|`, `d = −n·p0`; its quadric `(n, d)(n, d)ᵀ` weighted by
//!   the triangle's area (OpenMesh's default; a degenerate triangle, `|…| ≤ FLT_MIN`, keeps
//!   the unnormalised normal and weight `|…|`, as there) is added to each of its three
//!   vertices.
//! - **Priority** (`ModQuadricT::collapse_priority`): a collapse moves `from` onto `to`, with
//!   no optimal placement (the `CollapseInfo` of OpenMesh keeps `p1`, the remaining vertex's
//!   position); its error is `(Q_from + Q_to)(p_to)`, rounded to `f32` as OpenMesh's
//!   priorities are. An error past `f32` (or NaN) is no candidate.
//! - **Heap** (`DecimaterT`'s `HeapT`, `heap.rs`): vertices, each keyed by its best collapse;
//!   the same sifting (equal keys: see **Ties** below).
//! - **After a collapse** (`postprocess_collapse`): `Q_to += Q_from`, and every former
//!   neighbour of `from` is heaped again, in the structure's rotation around `from`. The
//!   other vertices keep their keys, even those whose best collapse goes onto `to` (its
//!   quadric grew): OpenMesh's keys are as stale.
//! - **Stop** (`decimate_to_faces`): when the live face count is at most the target or no
//!   candidate is left; each collapse removes two triangles.
//!
//! ## Where the strategies differ
//!
//! - **Eager** (`DecimaterT::heap_vertex`): to key a vertex, each neighbour in turn (the
//!   structure's rotation, clockwise seen from outside as OpenMesh's circulator) is first
//!   tested for legality by [`MeshEdit::check_collapse`] (the tests of OpenMesh's
//!   `is_collapse_legal` that concern an interior vertex: `is_collapse_ok`, with its link
//!   condition, and the tetrahedron test; OpenMesh's locked and feature marks have no
//!   counterpart here), and only a legal one is priced; the smallest error wins (equal ones:
//!   see **Ties** below), and an error that round-off makes negative is
//!   skipped (OpenMesh keeps priorities `>= 0`). A vertex
//!   with no legal collapse leaves the heap. When a vertex comes off the heap its collapse is
//!   tested again (by [`MeshEdit::collapse_edge`]'s own refusal, the same tests) and, if
//!   refused, dropped: the vertex is out of the heap until a collapse next to it heaps it
//!   again. No geometric test: the report's OpenMesh baseline runs `ModQuadricT` alone.
//! - **Lazy**: a vertex is keyed by its cheapest neighbour without a legality test (the
//!   order `(error, to)`, an error that round-off makes negative counted as 0); the test is
//!   [`MeshEdit::collapse_edge`]'s refusal when the vertex comes off the heap, and a refused
//!   vertex goes back on the heap with its next-best neighbour. A collapse that would flip a
//!   surviving face around `from` (its normal's dot product with the old one not positive)
//!   or leave it without area is skipped like a refused one: OpenMesh's
//!   `ModNormalFlippingT` at its default 90°, the module OpenMesh users add beside
//!   `ModQuadricT`. Fewer legality tests than the eager strategy, and flat regions keep
//!   their area (without the test they decimate into zero-area triangles, which `topolab
//!   check` reports); not OpenMesh's algorithm, so not what the report compares with it.
//!
//! What is left between the eager strategy and OpenMesh's Decimater:
//!
//! - **Boundary**: a boundary vertex is never removed, in both strategies. OpenMesh lets one
//!   slide along a boundary edge onto a boundary neighbour; here every collapse is the
//!   inverse of a [`MeshEdit::split_vertex`], which splits interior fans only, so that
//!   [`reconstruct`] can always undo it. An interior vertex may collapse onto a boundary
//!   one, as in OpenMesh. On closed meshes, the report's tori, nothing differs. OpenMesh's
//!   other boundary rule, at least two faces at `from`, always holds for an interior vertex
//!   whose collapse passes `is_collapse_ok` (with two neighbours, its two triangles' third
//!   corners would be one vertex, which `is_collapse_ok` refuses).
//! - **Ties** ([`Ties`]): of equal errors around a vertex, OpenMesh keeps the first in the
//!   rotation from its vertex's stored half-edge, and its heap lets equal keys leave in an
//!   order set by the order it heaped them in (a removed vertex's neighbours in that
//!   rotation): an order of its storage, which another structure does not share. So
//!   [`decimate`] and [`decimate_levels`] break ties by ids ([`Ties::Ids`]: of equal errors
//!   the smallest neighbour id, of equal keys the smallest vertex id), and every structure
//!   gives the same mesh (`registry/tests/decimate_agrees.rs`); without ties the two rules
//!   agree. [`decimate_with_ties`] with [`Ties::Storage`] keeps OpenMesh's order, each
//!   rotation starting at the structure's own stored half-edge. The half-edges store the one
//!   OpenMesh does on the meshes tested: on closed tori, spheres and a genus-2 plate,
//!   symmetric ones included (whose `f32` errors tie all over, and a flat region's are 0),
//!   the eager strategy with storage ties on both half-edges makes OpenMesh's collapses
//!   exactly (`baselines/tests/decimate_openmesh.rs` in the `topolab-baselines` crate),
//!   which is what the report times against OpenMesh.
//!
//! CGAL's `Surface_mesh_simplification::edge_collapse` with the Garland–Heckbert policies
//! differs more: it keys edges, not vertices, and places the new vertex at the quadric's
//! minimiser; the report sets it beside these, with the error measured the same way on every
//! result.
//!
//! ## Cost
//!
//! O(n log n) heap work for n vertices: each collapse touches the neighbourhoods of its two
//! vertices (O(k)) and updates O(k) heap keys (O(log n) each). The eager strategy adds a
//! legality test for every neighbour of every vertex it keys, O(k) tests per key, each as
//! costly as the structure's collapse test; the lazy one tests only the candidates that come
//! off the heap.

mod heap;
mod reconstruct;
pub mod record;

pub use reconstruct::{
    canonical_input, live_soup, reconstruct, reconstruct_from, same_mesh, Difference,
    Reconstruction,
};

use crate::core::edit::MeshEdit;
use crate::core::error::{Error, Result};
use crate::core::ids::{FaceId, VertexId};
use crate::core::topology::{first_three_corners, MeshTopology};
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
    for f in 0..m.num_faces() {
        let f = FaceId::new(f);
        if m.is_deleted_face(f) {
            continue;
        }
        let corners = first_three_corners(m, f).0;
        let p = corners.map(|v| m.position(v));
        let fq = triangle_quadric(p[0], p[1], p[2]);
        for v in corners {
            q[v.index()].add_assign(&fq);
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

/// How the decimater keeps its candidates: when a collapse is tested for legality, what
/// happens to a refused one, and whether a geometric test runs (see the module docs). Both
/// price, heap, update and stop alike, and both records are undone by [`reconstruct`].
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Strategy {
    /// As OpenMesh's `DecimaterT` with `ModQuadricT` alone: every neighbour of a vertex tested
    /// for legality before it is priced, only legal collapses heaped, one refused when it
    /// leaves the heap dropped, no geometric test. What the report times against OpenMesh's
    /// own Decimater (with [`Ties::Storage`], OpenMesh's order of ties), so that the two run
    /// one algorithm and the ratio compares structures.
    Eager,
    /// The lab's: collapses priced without a legality test and tested when they leave the
    /// heap (a refused vertex heaped again with its next-best neighbour), and a collapse that
    /// would flip or flatten a surviving face skipped (OpenMesh's `ModNormalFlippingT` at
    /// 90°): fewer legality tests, and flat regions keep their area.
    Lazy,
}

impl Strategy {
    /// Both, eager first.
    pub const ALL: [Strategy; 2] = [Strategy::Eager, Strategy::Lazy];

    /// The name on the command line and in the report.
    pub const fn name(self) -> &'static str {
        match self {
            Strategy::Eager => "eager",
            Strategy::Lazy => "lazy",
        }
    }

    /// The strategy called `name` ([`Strategy::name`]).
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|s| s.name() == name)
    }
}

impl std::fmt::Display for Strategy {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
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
    /// Per target of [`decimate_levels`], in order, the number of collapses done when it was
    /// reached (the first that many of [`Decimation::collapses`]); one entry for
    /// [`decimate`].
    pub levels: Vec<usize>,
}

/// How the decimater orders collapses of equal error, around a vertex and in its heap.
/// Symmetric meshes tie all over (a generated torus's `f32` errors come in a handful of
/// values, a flat region's are all 0), so the rule decides which mesh comes out.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, Hash)]
pub enum Ties {
    /// By vertex ids, so that every structure gives the same mesh: of a vertex's collapses of
    /// equal error the one onto the smallest neighbour id, and of vertices keyed equally the
    /// smallest id leaves the heap first. What [`decimate`] and [`decimate_levels`] do.
    #[default]
    Ids,
    /// By the structure's storage, as OpenMesh's Decimater: of equal errors around a vertex
    /// the first in the structure's rotation from its stored half-edge, vertices keyed equally
    /// in the order of OpenMesh's `HeapT` for the operations done (which depends on the order
    /// the rotation heaps them in). On the two half-edges, which store the half-edge OpenMesh
    /// does, the eager strategy so makes OpenMesh's own collapses on symmetric meshes too;
    /// other structures start their rotations elsewhere and give other meshes. What the
    /// report times against OpenMesh, through [`decimate_with_ties`].
    Storage,
}

/// The decimater's state: the per-vertex arrays of `DecimaterT` and `ModQuadricT`; `IDS`:
/// [`Ties::Ids`] (a constant, so that neither rule pays for the other in its loops).
struct Decimater<const IDS: bool> {
    quadric: Vec<Quadric>,
    /// Per vertex, the best neighbour to collapse onto ([`u32::MAX`]: none).
    target: Vec<u32>,
    /// Per vertex, that collapse's error: the heap key.
    priority: Vec<f32>,
    heap: VertexHeap<IDS>,
}

impl<const IDS: bool> Decimater<IDS> {
    /// Keys `v` by `best` (its collapse's error and target) and heaps it, or takes it out of
    /// the heap when it has none: the end of `DecimaterT::heap_vertex`.
    fn key(&mut self, v: u32, best: Option<(f32, u32)>) {
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

    /// The error of collapsing `v` onto `w`: `(Q_v + Q_w)(p_w)`.
    fn error<M: MeshTopology>(&self, m: &M, v: VertexId, w: VertexId) -> f64 {
        self.quadric[v.index()]
            .add(&self.quadric[w.index()])
            .eval(m.position(w))
    }

    /// The eager strategy's search (`DecimaterT::heap_vertex`): every neighbour `w` of `v`
    /// in the structure's rotation whose collapse [`MeshEdit::check_collapse`] allows, priced;
    /// the smallest `f32` error wins, of equal ones the smallest `w` with ids, the first in
    /// the rotation without, skipping what OpenMesh skips (a negative error, NaN, `FLT_MAX`
    /// and beyond). A boundary `v` has none (module docs).
    fn cheapest_legal<M: MeshEdit>(&self, m: &M, v: VertexId) -> Option<(f32, u32)> {
        if m.is_boundary_vertex(v) {
            return None;
        }
        let mut best: Option<(f32, u32)> = None;
        m.vertex_vertices(v, |w| {
            // OpenMesh tests legality first and prices only what passes.
            if m.check_collapse(v, w).is_err() {
                return;
            }
            let p = self.error(m, v, w) as f32;
            let better = |(b, bw): (f32, u32)| p < b || (IDS && p == b && w.0 < bw);
            if (0.0..f32::MAX).contains(&p) && best.is_none_or(better) {
                best = Some((p, w.0));
            }
        });
        best
    }

    /// The lazy strategy's search: the neighbour `w` of `v` with the smallest
    /// `(error, w)` after `after` when given (an order by ids under either tie rule: the
    /// refused vertex's next-best neighbour needs it), untested (a negative error counts as 0; past
    /// `f32` or NaN is no candidate). A boundary `v` has none (module docs).
    fn cheapest<M: MeshTopology>(
        &self,
        m: &M,
        v: VertexId,
        after: Option<(f32, u32)>,
    ) -> Option<(f32, u32)> {
        if m.is_boundary_vertex(v) {
            return None;
        }
        let mut best: Option<(f32, u32)> = None;
        m.vertex_vertices(v, |w| {
            let key = (self.error(m, v, w).max(0.0) as f32, w.0);
            if key.0.is_nan() || key.0 >= f32::MAX || after.is_some_and(|a| key <= a) {
                return;
            }
            if best.is_none_or(|b| key < b) {
                best = Some(key);
            }
        });
        best
    }

    /// Keys `v` afresh by the strategy's search.
    fn heap_vertex<M: MeshEdit>(&mut self, m: &M, v: u32, strategy: Strategy) {
        let best = match strategy {
            Strategy::Eager => self.cheapest_legal(m, VertexId(v)),
            Strategy::Lazy => self.cheapest(m, VertexId(v), None),
        };
        self.key(v, best);
    }

    /// `v`'s collapse, just off the heap, was refused: the eager strategy drops it (as
    /// OpenMesh does: `v` stays out of the heap until a collapse next to it keys it again),
    /// the lazy one keys `v` by its next-best neighbour.
    fn refused<M: MeshTopology>(&mut self, m: &M, v: u32, strategy: Strategy) {
        if strategy == Strategy::Lazy {
            let after = (self.priority[v as usize], self.target[v as usize]);
            let best = self.cheapest(m, VertexId(v), Some(after));
            self.key(v, best);
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
/// zero-area triangles, which `topolab check` reports. Each normal is taken at `from`'s
/// corner, whichever corner the structure lists first, so that its rounding, and the answer
/// on a face that is all but flat, is the same on every structure.
fn keeps_faces<M: MeshTopology>(m: &M, from: VertexId, to: VertexId) -> bool {
    let p_to = m.position(to);
    let mut ok = true;
    m.vertex_faces(from, |f| {
        if !ok {
            return;
        }
        let (c, k) = first_three_corners(m, f);
        if k != 3 || c.contains(&to) {
            return;
        }
        let i = c.iter().position(|&v| v == from).unwrap_or(0);
        let (a, b) = (m.position(c[(i + 1) % 3]), m.position(c[(i + 2) % 3]));
        let p_from = m.position(from);
        let before = (a - p_from).cross(b - p_from);
        let after = (a - p_to).cross(b - p_to);
        if before.dot(after) <= 0.0 || after.length() <= 1e-6 * before.length() {
            ok = false;
        }
    });
    ok
}

/// Decimates `m` by quadric error with `strategy` until at most `target_faces` live faces
/// remain or no legal collapse is left (see the module docs for the algorithm), ties broken
/// by ids ([`Ties::Ids`]: the same mesh on every structure). Deleted elements stay marked
/// (call [`MeshEdit::garbage_collection`] to compact them; [`reconstruct`] needs them
/// uncollected). Errors other than a collapse's refusal are returned as they come.
pub fn decimate<M: MeshEdit>(
    m: &mut M,
    target_faces: usize,
    strategy: Strategy,
) -> Result<Decimation> {
    decimate_with_ties(m, target_faces, strategy, Ties::Ids)
}

/// [`decimate`] with the tie rule `ties`: [`Ties::Storage`] is OpenMesh's order, which the
/// report's comparison with OpenMesh's Decimater runs.
pub fn decimate_with_ties<M: MeshEdit>(
    m: &mut M,
    target_faces: usize,
    strategy: Strategy,
    ties: Ties,
) -> Result<Decimation> {
    match ties {
        Ties::Ids => run::<M, true>(m, &[target_faces], strategy, |_, _| {}),
        Ties::Storage => run::<M, false>(m, &[target_faces], strategy, |_, _| {}),
    }
}

/// [`decimate`] through several targets in one run: the collapses go on, one heap and one set
/// of quadrics throughout, until at most `targets[0]` live faces remain, then `at_level(m, 0)`
/// sees the mesh, then on to `targets[1]`, and so on (the targets in the order given; one not
/// below the live count is reached at once). A target no legal collapse reaches is passed
/// with the mesh as far as it went. One run rather than one [`decimate`] per target, so that
/// a level's collapses are those a single decimation to it would make: the quadrics keep
/// what earlier collapses added to them. [`Decimation::levels`] says how many collapses were
/// done at each level. Ties by ids, as [`decimate`].
pub fn decimate_levels<M: MeshEdit>(
    m: &mut M,
    targets: &[usize],
    strategy: Strategy,
    at_level: impl FnMut(&M, usize),
) -> Result<Decimation> {
    run::<M, true>(m, targets, strategy, at_level)
}

/// [`decimate_levels`] with ties by ids (`IDS`) or by storage.
fn run<M: MeshEdit, const IDS: bool>(
    m: &mut M,
    targets: &[usize],
    strategy: Strategy,
    mut at_level: impl FnMut(&M, usize),
) -> Result<Decimation> {
    let n = m.num_vertices();
    let mut faces = (0..m.num_faces())
        .filter(|&f| !m.is_deleted_face(FaceId::new(f)))
        .count();
    let mut out = Decimation {
        faces_before: faces,
        ..Decimation::default()
    };
    let mut d = Decimater::<IDS> {
        quadric: vertex_quadrics(m),
        target: vec![u32::MAX; n],
        priority: vec![-1.0; n],
        heap: VertexHeap::new(n),
    };
    for v in 0..n as u32 {
        if !m.is_deleted_vertex(VertexId(v)) {
            d.heap_vertex(m, v, strategy);
        }
    }
    let mut support: Vec<u32> = Vec::with_capacity(16);
    for (level, &target_faces) in targets.iter().enumerate() {
        let c = &mut out.collapses;
        while faces > target_faces {
            let Some(v) = d.heap.pop(&d.priority) else {
                break;
            };
            let (from, to) = (VertexId(v), VertexId(d.target[v as usize]));
            let Some((left, right)) = wings(m, from, to) else {
                // Not two triangles around the edge: the collapse would be refused.
                d.refused(m, v, strategy);
                continue;
            };
            if strategy == Strategy::Lazy && !keeps_faces(m, from, to) {
                d.refused(m, v, strategy);
                continue;
            }
            support.clear();
            m.vertex_vertices(from, |w| support.push(w.0));
            let position = m.position(from);
            match m.collapse_edge(from, to) {
                Ok(()) => {}
                Err(Error::EditRefused { .. }) => {
                    d.refused(m, v, strategy);
                    continue;
                }
                Err(e) => return Err(e),
            }
            faces -= 2;
            c.from.push(v);
            c.to.push(to.0);
            c.left.push(left);
            c.right.push(right);
            c.position.push(position);
            c.error.push(d.error(m, from, to).max(0.0));
            let qv = d.quadric[v as usize];
            d.quadric[to.index()].add_assign(&qv);
            for &s in &support {
                d.heap_vertex(m, s, strategy);
            }
        }
        out.levels.push(c.len());
        at_level(m, level);
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
    use crate::families::half_edge::index::IndexHalfEdge;
    use crate::meshes;

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
        for strategy in Strategy::ALL {
            let mut m = IndexHalfEdge::from_soup(&soup).expect("manifold");
            let d = decimate(&mut m, 48, strategy).expect("decimates");
            assert_eq!(d.faces_before, 480);
            assert!(
                d.faces_after <= 48 && d.faces_after >= 46,
                "{strategy}: {}",
                d.faces_after
            );
            assert_eq!(d.collapses.len(), (480 - d.faces_after) / 2);
            m.validate().expect("valid");
            m.garbage_collection();
            assert_eq!(m.num_faces(), d.faces_after);
            // Errors are the heap's order only roughly (keys change), but never negative.
            assert!(d.collapses.error.iter().all(|&e| e >= 0.0));
        }
    }

    #[test]
    fn strategies_are_named_both_ways() {
        for s in Strategy::ALL {
            assert_eq!(Strategy::from_name(s.name()), Some(s));
        }
        assert_eq!(Strategy::from_name("greedy"), None);
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
        for strategy in Strategy::ALL {
            let mut m = IndexHalfEdge::from_soup(&meshes::sphere(6, 8)).expect("manifold");
            let d = decimate(&mut m, 0, strategy).expect("decimates");
            assert!(d.faces_after >= 4, "{strategy}: {}", d.faces_after);
            m.validate().expect("valid");
        }
    }
}
