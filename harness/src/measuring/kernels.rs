//! The timed kernels, written once for every structure and serving both the report and
//! `cargo bench`.
//!
//! An operator's kernel answers it for a list of query elements: every element (a *sweep*,
//! throughput) or a fixed seeded sample (*sampled*, latency per query). Both fold the answers
//! into the checksum of [`crate::measuring::checksum`], so the same query set gives the same number on
//! every structure. Answers that are edges enter by their end vertices, so edge-valued
//! relations (R01, R11, R21, successor, predecessor) also pay one R10 per answer — on every
//! structure alike, OpenMesh included.

use crate::measuring::checksum::{edge_key, mix};
use glam::DVec3;
use rand::seq::index::sample;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::collections::HashMap;
pub use topolab_structures::Workload;
use topolab_structures::{
    BoundaryCurves, EdgeId, FaceId, Input, MeshAttributes, MeshTopology, Operator, PolygonSoup,
    Sample, VertexId,
};

/// How a measurement exercises its subject: an operator by one of the two query kernels, a
/// workload, or a construction.
#[derive(
    Copy, Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "kebab-case")]
pub enum Kernel {
    /// Every element once (throughput).
    Sweep,
    /// A fixed, seeded random sample of query elements (latency per query).
    Sampled,
    /// An application workload, run once over the mesh.
    Workload,
    /// Building the structure from the face list.
    Construction,
}

impl Kernel {
    /// Every kernel.
    pub const ALL: [Kernel; 4] = [
        Kernel::Sweep,
        Kernel::Sampled,
        Kernel::Workload,
        Kernel::Construction,
    ];

    /// The two kernels an operator is timed with.
    pub const QUERIES: [Kernel; 2] = [Kernel::Sweep, Kernel::Sampled];

    /// The name used in results.
    pub const fn name(self) -> &'static str {
        match self {
            Kernel::Sweep => "sweep",
            Kernel::Sampled => "sampled",
            Kernel::Workload => "workload",
            Kernel::Construction => "construction",
        }
    }
}

impl std::fmt::Display for Kernel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// Query elements of one mesh, named independently of any structure: vertices and faces by
/// id, edges by a corner of the soup (its outgoing edge, and its face).
#[derive(Clone, Debug)]
pub struct QuerySet {
    /// Sampled vertices.
    pub vertices: Vec<u32>,
    /// Sampled faces.
    pub faces: Vec<u32>,
    /// Sampled edges as (end, end, face of the corner).
    pub edges: Vec<(u32, u32, u32)>,
}

/// The seeded sample of `count` queries of each kind for `soup` (fewer on tiny meshes).
pub fn sample_queries(soup: &PolygonSoup, count: usize, seed: u64) -> QuerySet {
    query_set(soup, seed, |rng, n| {
        let mut v: Vec<u32> = sample(rng, n, count.min(n))
            .into_iter()
            .map(|i| i as u32)
            .collect();
        v.sort_unstable();
        v
    })
}

/// A fresh draw of `count` queries of each kind for `soup`, in random order (not sorted by id:
/// the queries of a sampled round are random accesses, as a user's queries are): without
/// repetition when the mesh has that many elements, with repetition on a smaller mesh. The
/// sampled rounds of the report draw one set per round ([`crate::measuring::rounds`]).
pub fn draw_queries(soup: &PolygonSoup, count: usize, seed: u64) -> QuerySet {
    use rand::seq::SliceRandom;
    use rand::Rng;
    query_set(soup, seed, |rng, n| {
        if n == 0 {
            return Vec::new();
        }
        let mut v: Vec<u32> = if count <= n {
            sample(rng, n, count)
                .into_iter()
                .map(|i| i as u32)
                .collect()
        } else {
            (0..count).map(|_| rng.random_range(0..n) as u32).collect()
        };
        v.shuffle(rng);
        v
    })
}

/// The queries `pick` draws from `0..n` for the vertices, the faces and the corners (their
/// edges), in that order from one generator seeded with `seed`.
fn query_set(
    soup: &PolygonSoup,
    seed: u64,
    pick: impl Fn(&mut ChaCha8Rng, usize) -> Vec<u32>,
) -> QuerySet {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let vertices = pick(&mut rng, soup.num_vertices());
    let faces = pick(&mut rng, soup.num_faces());
    let edges = corner_edges(soup, pick(&mut rng, soup.num_corners()));
    QuerySet {
        vertices,
        faces,
        edges,
    }
}

/// The edges of `corners` of `soup` as (end, end, face of the corner).
fn corner_edges(soup: &PolygonSoup, corners: Vec<u32>) -> Vec<(u32, u32, u32)> {
    let offsets = soup.offsets();
    corners
        .into_iter()
        .map(|c| {
            let c = c as usize;
            let f = offsets.partition_point(|&o| o as usize <= c) - 1;
            let n = soup.next_corner(c, f);
            (soup.indices()[c], soup.indices()[n], f as u32)
        })
        .collect()
}

/// Query elements in one structure's ids, prepared outside any timed region.
#[derive(Clone, Debug, Default)]
pub struct Queries {
    /// Vertices to query.
    pub vertices: Vec<VertexId>,
    /// Edges to query.
    pub edges: Vec<EdgeId>,
    /// Faces to query.
    pub faces: Vec<FaceId>,
    /// (edge, face) pairs for successor and predecessor.
    pub edge_faces: Vec<(EdgeId, FaceId)>,
    /// Whether `vertices` and `faces` are every vertex and face in id order (a sweep's
    /// queries, [`Queries::all`]): the kernels then count the ids instead of reading them from
    /// the lists, as OpenMesh's native loops iterate its elements. Reading a list of every id
    /// streamed 4 more bytes per query through the cache on every Rust structure and on none
    /// of the native baselines. Set only by the constructors, which make it true.
    pub(crate) dense: bool,
}

impl Queries {
    /// Every element of `m` (built from `soup`): the sweep's queries. The (edge, face) pairs
    /// come from the soup's corners with edges looked up by their end vertices, so building
    /// them costs O(n) on every structure (asking a scanning structure for R21 of every face
    /// would cost O(n²) before anything is timed).
    pub fn all<M: MeshTopology>(m: &M, soup: &PolygonSoup) -> Self {
        let mut edges = Vec::with_capacity(m.num_edges());
        m.for_each_edge(|e| edges.push(e));
        let by_ends = edges_by_ends(m, &edges);
        Self::all_by(m, soup, edges, &by_ends)
    }

    /// [`Queries::all`] from `m`'s `edges` and their look-up table by end vertices.
    fn all_by<M: MeshTopology>(
        m: &M,
        soup: &PolygonSoup,
        edges: Vec<EdgeId>,
        by_ends: &HashMap<u64, EdgeId>,
    ) -> Self {
        let mut edge_faces = Vec::with_capacity(soup.num_corners());
        for (f, face) in soup.faces().enumerate() {
            for (i, &a) in face.iter().enumerate() {
                let b = face[(i + 1) % face.len()];
                edge_faces.push((by_ends[&edge_key(a, b)], FaceId::new(f)));
            }
        }
        Self {
            vertices: (0..m.num_vertices()).map(VertexId::new).collect(),
            faces: (0..m.num_faces()).map(FaceId::new).collect(),
            edges,
            edge_faces,
            dense: true,
        }
    }

    /// Every vertex of `m` in id order and nothing else: the queries of a vertex sweep, without
    /// the edges and (edge, face) pairs, whose hash map of edges is costly to build on a large
    /// mesh.
    pub fn every_vertex<M: MeshTopology>(m: &M) -> Self {
        Self {
            vertices: (0..m.num_vertices()).map(VertexId::new).collect(),
            dense: true,
            ..Self::default()
        }
    }

    /// The sampled vertices of `set` and nothing else: the sampled queries of a vertex
    /// operator, without the hash map of edges [`Queries::sampled`] builds.
    pub fn sampled_vertices(set: &QuerySet) -> Self {
        Self {
            vertices: set.vertices.iter().map(|&v| VertexId(v)).collect(),
            dense: false,
            ..Self::default()
        }
    }

    /// The sample `set` in `m`'s ids (edges looked up by their end vertices).
    pub fn sampled<M: MeshTopology>(m: &M, set: &QuerySet) -> Self {
        let mut edges = Vec::with_capacity(m.num_edges());
        m.for_each_edge(|e| edges.push(e));
        Self::sampled_by(&edges_by_ends(m, &edges), set)
    }

    /// Every element of `m` (as [`Queries::all`]) and each of `sets` in `m`'s ids (as
    /// [`Queries::sampled`]), with one look-up table of edges for all of them.
    pub fn all_and_sampled<M: MeshTopology>(
        m: &M,
        soup: &PolygonSoup,
        sets: &[QuerySet],
    ) -> (Self, Vec<Self>) {
        let mut edges = Vec::with_capacity(m.num_edges());
        m.for_each_edge(|e| edges.push(e));
        let by_ends = edges_by_ends(m, &edges);
        let sampled = sets.iter().map(|s| Self::sampled_by(&by_ends, s)).collect();
        (Self::all_by(m, soup, edges, &by_ends), sampled)
    }

    /// `set` in the ids of the structure whose edges by end vertices are `by_ends`.
    fn sampled_by(by_ends: &HashMap<u64, EdgeId>, set: &QuerySet) -> Self {
        let edge = |a: u32, b: u32| by_ends[&edge_key(a, b)];
        Self {
            vertices: set.vertices.iter().map(|&v| VertexId(v)).collect(),
            faces: set.faces.iter().map(|&f| FaceId(f)).collect(),
            edges: set.edges.iter().map(|&(a, b, _)| edge(a, b)).collect(),
            edge_faces: set
                .edges
                .iter()
                .map(|&(a, b, f)| (edge(a, b), FaceId(f)))
                .collect(),
            dense: false,
        }
    }

    /// At most `n` queries of each kind, evenly spread over this set: a probe, cheap enough to
    /// time on any mesh. Spread, not the first ones: a sample is sorted by id, and a scan for
    /// a low id can stop early, so the first queries would be the cheapest.
    pub fn spread(&self, n: usize) -> Self {
        fn pick<T: Copy>(all: &[T], n: usize) -> Vec<T> {
            let k = n.min(all.len());
            (0..k).map(|i| all[i * all.len() / k]).collect()
        }
        Self {
            vertices: pick(&self.vertices, n),
            edges: pick(&self.edges, n),
            faces: pick(&self.faces, n),
            edge_faces: pick(&self.edge_faces, n),
            dense: false,
        }
    }

    /// This set cut into passes of `size` queries of each kind: pass `j` holds the `j`-th
    /// `size` vertices, edges, faces and (edge, face) pairs (fewer in the last pass of a kind,
    /// none past its end). The passes of a sampled round ([`crate::measuring::rounds`]).
    pub fn passes(&self, size: usize) -> Vec<Self> {
        let size = size.max(1);
        let longest = [
            self.vertices.len(),
            self.edges.len(),
            self.faces.len(),
            self.edge_faces.len(),
        ]
        .into_iter()
        .max()
        .unwrap_or(0);
        fn part<T: Copy>(all: &[T], j: usize, size: usize) -> Vec<T> {
            all.iter().skip(j * size).take(size).copied().collect()
        }
        (0..longest.div_ceil(size))
            .map(|j| Self {
                vertices: part(&self.vertices, j, size),
                edges: part(&self.edges, j, size),
                faces: part(&self.faces, j, size),
                edge_faces: part(&self.edge_faces, j, size),
                dense: false,
            })
            .collect()
    }

    /// The queries `op` asks over this set, as a baseline's sampled kernel takes them
    /// ([`topolab_structures::NativeKernels::sampled`]); `None` for an operator about the whole
    /// mesh (boundary curves), which has no queries to sample.
    pub fn sample(&self, op: Operator) -> Option<Sample<'_>> {
        match op.input() {
            Input::Vertex => Some(Sample::Vertices(&self.vertices)),
            Input::Edge => Some(Sample::Edges(&self.edges)),
            Input::Face => Some(Sample::Faces(&self.faces)),
            Input::EdgeOfFace => Some(Sample::EdgesOfFaces(&self.edge_faces)),
            Input::Mesh => None,
        }
    }

    /// How many queries `op` makes over this set.
    pub fn count(&self, op: Operator) -> usize {
        match op.input() {
            Input::Vertex => self.vertices.len(),
            Input::Edge => self.edges.len(),
            Input::Face => self.faces.len(),
            Input::EdgeOfFace => self.edge_faces.len(),
            Input::Mesh => 1,
        }
    }
}

/// `m`'s edge ids by their end vertices.
fn edges_by_ends<M: MeshTopology>(m: &M, edges: &[EdgeId]) -> HashMap<u64, EdgeId> {
    edges
        .iter()
        .map(|&e| {
            let [a, b] = m.edge_vertices(e);
            (edge_key(a.0, b.0), e)
        })
        .collect()
}

#[inline(always)]
fn key<M: MeshTopology>(m: &M, e: EdgeId) -> u64 {
    let [a, b] = m.edge_vertices(e);
    edge_key(a.0, b.0)
}

/// Calls `f` with every id of `list`, counted instead of read when `dense` says the list is
/// every id in order (see [`Queries`]). One loop with one call of `f`: with two loops, one
/// per case, LLVM stopped inlining a large `f` (the CHE's fan walk) into them.
#[inline(always)]
// The index is the id when `dense`; an iterator over `list` would read it in both cases.
#[allow(clippy::needless_range_loop)]
fn each<T: Copy>(list: &[T], dense: bool, id: impl Fn(usize) -> T, mut f: impl FnMut(T)) {
    for i in 0..list.len() {
        f(if dense { id(i) } else { list[i] });
    }
}

/// Answers `op` for every query of `q` and returns the checksum. Reuses `curves` as the
/// caller-owned buffer of boundary curves.
///
/// Each query's terms are summed in a local of the query (`s`), kept in a register, and then
/// added to the total, as OpenMesh's native loops sum each element's terms. A total captured
/// by reference in the answers' callback was stored to the stack at every answer wherever
/// the structure's walk kept LLVM from promoting it (the CHE's fan walk: twice per step).
pub fn run<M: MeshTopology>(m: &M, op: Operator, q: &Queries, curves: &mut BoundaryCurves) -> u64 {
    let mut sum = 0u64;
    let mut add = |x: u64| sum = sum.wrapping_add(x);
    // Every query `x` of `list`: `body` passes each term of `x`'s answers to `term`, which sums
    // them in the query's own `s`; then `s` joins the total.
    macro_rules! per_query {
        ($list:expr, $dense:expr, $id:expr, |$x:pat_param, $term:ident| $body:expr) => {
            each($list, $dense, $id, |$x| {
                let mut s = 0u64;
                let mut $term = |t: u64| s = s.wrapping_add(t);
                $body;
                add(s)
            })
        };
    }
    let (d, new_v, new_f, new_e) = (q.dense, VertexId::new, FaceId::new, EdgeId::new);
    match op {
        Operator::R00 => per_query!(&q.vertices, d, new_v, |v, term| m
            .vertex_vertices(v, |w| term(mix(v.0 as u64, w.0 as u64)))),
        Operator::R01 => per_query!(&q.vertices, d, new_v, |v, term| m
            .vertex_edges(v, |e| term(mix(v.0 as u64, key(m, e))))),
        Operator::R02 => per_query!(&q.vertices, d, new_v, |v, term| m
            .vertex_faces(v, |f| term(mix(v.0 as u64, f.0 as u64)))),
        // Edge ids are each structure's own, so the edges are always read from the list.
        Operator::R10 => per_query!(&q.edges, false, new_e, |e, term| {
            let [a, b] = m.edge_vertices(e);
            term(mix(a.0.min(b.0) as u64, a.0.max(b.0) as u64))
        }),
        Operator::R11 => per_query!(&q.edges, false, new_e, |e, term| {
            let k = key(m, e);
            m.edge_edges(e, |x| term(mix(k, key(m, x))))
        }),
        Operator::R12 => per_query!(&q.edges, false, new_e, |e, term| {
            let k = key(m, e);
            m.edge_faces(e, |f| term(mix(k, f.0 as u64)))
        }),
        Operator::R20 => per_query!(&q.faces, d, new_f, |f, term| m
            .face_vertices(f, |v| term(mix(f.0 as u64, v.0 as u64)))),
        Operator::R21 => per_query!(&q.faces, d, new_f, |f, term| m
            .face_edges(f, |e| term(mix(f.0 as u64, key(m, e))))),
        Operator::R22 => per_query!(&q.faces, d, new_f, |f, term| m
            .face_faces(f, |g| term(mix(f.0 as u64, g.0 as u64)))),
        Operator::BoundaryVertex => each(&q.vertices, d, new_v, |v| {
            if m.is_boundary_vertex(v) {
                add(mix(v.0 as u64, 1))
            }
        }),
        Operator::BoundaryEdge => q.edges.iter().for_each(|&e| {
            if m.is_boundary_edge(e) {
                add(mix(key(m, e), 1))
            }
        }),
        Operator::BoundaryCurves => {
            m.boundary_curves(curves);
            for i in 0..curves.len() {
                let c = curves.curve(i);
                c.iter().for_each(|&e| add(mix(c.len() as u64, key(m, e))));
            }
        }
        Operator::EdgeSuccessor => q.edge_faces.iter().for_each(|&(e, f)| {
            if let Some(s) = m.edge_successor(e, f) {
                add(mix(key(m, e), key(m, s)))
            }
        }),
        Operator::EdgePredecessor => q.edge_faces.iter().for_each(|&(e, f)| {
            if let Some(p) = m.edge_predecessor(e, f) {
                add(mix(key(m, e), key(m, p)))
            }
        }),
    }
    sum
}

/// Caller-owned buffers of the workloads (allocated once, outside the timed region).
#[derive(Clone, Debug, Default)]
pub struct WorkloadBuffers {
    face_normals: Vec<DVec3>,
    vertex_out: Vec<DVec3>,
}

/// Runs a workload; returns its result as a float checksum (the sum of every resulting
/// coordinate, or the incidence count for circulators). Panics if the circulator total is not 0,
/// which would mean the structure's R02 and R20 disagree.
pub fn run_workload<M: MeshTopology>(m: &M, w: Workload, buf: &mut WorkloadBuffers) -> f64 {
    let (nv, nf) = (m.num_vertices(), m.num_faces());
    match w {
        Workload::Circulators => {
            let (mut total, mut count) = (0i64, 0i64);
            for v in 0..nv {
                m.vertex_faces(VertexId::new(v), |_| {
                    total += 1;
                    count += 1;
                });
            }
            for f in 0..nf {
                m.face_vertices(FaceId::new(f), |_| total -= 1);
            }
            assert_eq!(
                total,
                0,
                "{}: vertex-face and face-vertex circulators disagree",
                M::NAME
            );
            count as f64
        }
        Workload::Barycenter => {
            let mut sum = DVec3::ZERO;
            for v in 0..nv {
                sum += m.position(VertexId::new(v));
            }
            let c = sum / nv.max(1) as f64;
            c.x + c.y + c.z
        }
        Workload::Normals => {
            buf.face_normals.resize(nf, DVec3::ZERO);
            buf.vertex_out.resize(nv, DVec3::ZERO);
            for f in 0..nf {
                buf.face_normals[f] = m.face_normal(FaceId::new(f));
            }
            let mut total = 0.0;
            for v in 0..nv {
                let mut n = DVec3::ZERO;
                m.vertex_faces(VertexId::new(v), |f| n += buf.face_normals[f.index()]);
                let n = n.normalize_or_zero();
                buf.vertex_out[v] = n;
                total += n.x + n.y + n.z;
            }
            total
        }
        Workload::Smoothing => {
            buf.vertex_out.resize(nv, DVec3::ZERO);
            for v in 0..nv {
                let vid = VertexId::new(v);
                let p = m.position(vid);
                buf.vertex_out[v] = if m.is_boundary_vertex(vid) {
                    p
                } else {
                    let (mut sum, mut k) = (DVec3::ZERO, 0u32);
                    m.vertex_vertices(vid, |w| {
                        sum += m.position(w);
                        k += 1;
                    });
                    if k == 0 {
                        p
                    } else {
                        sum / k as f64
                    }
                };
            }
            buf.vertex_out.iter().map(|p| p.x + p.y + p.z).sum()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::{meshes, ExplicitStorage, VertexList};

    #[test]
    fn two_structures_agree_on_every_kernel_and_workload() {
        let soup = meshes::annulus(7);
        let (a, b) = (
            VertexList::from_soup(&soup).unwrap(),
            ExplicitStorage::from_soup(&soup).unwrap(),
        );
        let set = sample_queries(&soup, 5, 1);
        let mut curves = BoundaryCurves::default();
        for op in Operator::ALL {
            for (qa, qb) in [
                (Queries::all(&a, &soup), Queries::all(&b, &soup)),
                (Queries::sampled(&a, &set), Queries::sampled(&b, &set)),
            ] {
                let (x, y) = (run(&a, op, &qa, &mut curves), run(&b, op, &qb, &mut curves));
                assert_eq!(x, y, "{op:?}");
                if op != Operator::BoundaryVertex || soup.num_vertices() > 0 {
                    assert_ne!(x, 0, "{op:?} answered nothing");
                }
            }
        }
        // A sweep's queries count their ids: the same answers as reading them from the list,
        // and the list is not read (every entry replaced by vertex 0 changes nothing).
        let all = Queries::all(&a, &soup);
        let listed = Queries {
            dense: false,
            ..all.clone()
        };
        let mut stale = Queries::every_vertex(&a);
        stale.vertices.fill(VertexId(0));
        for op in [Operator::R00, Operator::R02, Operator::R20] {
            let x = run(&a, op, &all, &mut curves);
            assert_eq!(x, run(&a, op, &listed, &mut curves), "{op:?}");
        }
        let r00 = run(&a, Operator::R00, &all, &mut curves);
        assert_eq!(run(&a, Operator::R00, &stale, &mut curves), r00);
        stale.dense = false;
        assert_ne!(run(&a, Operator::R00, &stale, &mut curves), r00);
        let mut buf = WorkloadBuffers::default();
        for w in Workload::ALL {
            assert_eq!(
                run_workload(&a, w, &mut buf),
                run_workload(&b, w, &mut buf),
                "{w:?}"
            );
        }
        // 14 triangles, 3 corners each.
        assert_eq!(run_workload(&a, Workload::Circulators, &mut buf), 42.0);
    }

    #[test]
    fn a_probe_spreads_over_the_sample_instead_of_taking_its_cheap_start() {
        let q = Queries {
            vertices: (0..100).map(VertexId).collect(),
            faces: (0..3).map(FaceId).collect(),
            ..Default::default()
        };
        let probe = q.spread(4);
        assert_eq!(
            probe.vertices,
            [0, 25, 50, 75].map(VertexId),
            "evenly spread, not the first four"
        );
        assert_eq!(probe.faces, q.faces, "all of a short list");
        assert!(probe.edges.is_empty());
    }

    #[test]
    fn a_different_answer_changes_the_checksum() {
        let closed = VertexList::from_soup(&meshes::closed_tetrahedron()).unwrap();
        let open = VertexList::from_soup(&meshes::open_tetrahedron()).unwrap();
        let mut curves = BoundaryCurves::default();
        let (qc, qo) = (
            Queries::all(&closed, &meshes::closed_tetrahedron()),
            Queries::all(&open, &meshes::open_tetrahedron()),
        );
        assert_ne!(
            run(&closed, Operator::R22, &qc, &mut curves),
            run(&open, Operator::R22, &qo, &mut curves)
        );
    }
}
