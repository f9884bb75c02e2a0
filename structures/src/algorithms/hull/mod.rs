//! # 3D convex hull on the winged-edge
//!
//! The three algorithms of the lecture on 3D convex hulls, each building a [`WingedEdge`] of the
//! hull of a point set:
//!
//! | [`Algorithm`] | the lecture | module | cost |
//! |---|---|---|---|
//! | `Gift` | `Embrulho3D` (Chand & Kapur), `FaceInicial` by rotating planes | [`gift_wrap`] | O(n·h) |
//! | `Incremental` | `Incremental3D`, visibility by the sign of `Volume6` | [`incremental`] | O(n²) |
//! | `Randomized` | randomized incremental with the conflict graph | [`randomized`] | expected O(n log n) |
//!
//! **The result.** Vertex i of the winged-edge is input point i (the lab's rule); points that
//! are not hull vertices stay as vertices without edges. Faces are triangles, counter-clockwise
//! seen from outside, numbered densely (tombstones compacted). [`Hull::faces_created`] counts
//! every face the algorithm made, including those it removed later: the lecture's lemma
//! bounds its expectation by 6n − 20 for the randomized algorithm. [`Hull::work`] counts the
//! rest of what the lecture's analysis counts ([`Work`]): `Volume6` tests, and Σ|P(e)| over
//! the horizon edges for the randomized algorithm (expected O(n log n)).
//!
//! **Beyond the lecture** (it assumes no four points coplanar, which real inputs break):
//! - every orientation test is exact ([`predicates`], Shewchuk's `orient3d`; the incremental
//!   algorithms test against each face's plane prepared once, [`plane`], with the same
//!   first-stage filter, and go exact only when it is unsure);
//! - NaN or infinite coordinates: [`Error::NonFiniteCoordinate`]; coordinates whose products
//!   inside the predicates would overflow or underflow (a magnitude above 2^250, or non-zero
//!   below 2^-250): [`Error::CoordinateOutOfRange`]; fewer than four distinct
//!   points, or all on a line or a plane: [`Error::DegeneratePoints`];
//! - duplicate points are allowed: only the first occurrence (smallest index) can be a vertex;
//! - coplanar points on a hull facet: **triangulated**. The hull's vertices are exactly its
//!   extreme points (corners), never a point inside a facet or on an edge, in all three
//!   algorithms; a facet with more than three corners is cut into triangles, no triangle
//!   degenerate, all in the facet's plane. Which triangles depends on the algorithm (gift
//!   wrapping: a fan from the facet's first corner; the incremental ones: whatever the
//!   insertion order leaves), so the algorithms agree on vertices and volume, not faces.
//!
//! **Speed** (`cargo run --release -p topolab-harness --example hull_bench`, next to Qhull in
//! the same run; the report's "3D convex hulls" section): both incremental algorithms replace
//! the visible faces by the cone in one step ([`WingedEdge::replace_by_cone`],
//! O(faces removed + horizon), whatever the order), so the lecture's bounds hold by
//! construction; the randomized one keeps its conflict graph in flat arrays (see
//! [`randomized`]). Points inside the hull cost the randomized hull more than they cost
//! Qhull: it merges the conflict-list entries the lecture's O(n log n) bound counts
//! ([`Work::conflict_work`]), where Qhull's furthest-point order discards the inside points
//! early; on points on a sphere, none inside, the two come closer. The project's goal for the
//! randomized hull of 1M points in a ball is at most 1.5× Qhull's time; the report's Targets
//! section measures it and shows whether a run meets it.

pub mod gift_wrap;
pub mod incremental;
pub mod plane;
pub mod predicates;
pub mod randomized;

use crate::core::error::{Error, Result};
use crate::core::ids::{FaceId, VertexId};
use crate::core::soup::PolygonSoup;
use crate::core::topology::MeshTopology;
use crate::families::edge_lists::winged_edge::WingedEdge;
use glam::DVec3;
use rand::{Rng, SeedableRng};

/// Which of the lecture's algorithms builds the hull.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum Algorithm {
    /// Gift wrapping (Chand & Kapur), O(n·h).
    Gift,
    /// Incremental, O(n²), points in input order.
    Incremental,
    /// Randomized incremental with the conflict graph, expected O(n log n).
    Randomized {
        /// Seed of the insertion order.
        seed: u64,
    },
}

impl Algorithm {
    /// The three algorithms (the randomized one with `seed`).
    pub fn all(seed: u64) -> [Algorithm; 3] {
        [
            Algorithm::Gift,
            Algorithm::Incremental,
            Algorithm::Randomized { seed },
        ]
    }

    /// The name the CLI uses: `gift`, `incremental`, `randomized`.
    pub fn name(&self) -> &'static str {
        match self {
            Algorithm::Gift => "gift",
            Algorithm::Incremental => "incremental",
            Algorithm::Randomized { .. } => "randomized",
        }
    }

    /// The algorithm called `name` ([`Algorithm::name`]); `seed` for the randomized one.
    pub fn from_name(name: &str, seed: u64) -> Result<Algorithm> {
        Algorithm::all(seed)
            .into_iter()
            .find(|a| a.name() == name)
            .ok_or_else(|| {
                Error::Unsupported(format!(
                    "unknown hull algorithm {name:?}; expected gift, incremental or randomized"
                ))
            })
    }
}

/// A convex hull and what building it cost.
#[derive(Clone, Debug)]
pub struct Hull {
    /// The hull: vertex i is input point i, faces are the hull's triangles (see module docs).
    pub mesh: WingedEdge,
    /// Faces the algorithm created, including those removed later.
    pub faces_created: usize,
    /// The work the lecture's cost analysis counts.
    pub work: Work,
}

/// The work behind a hull, in the units of the lecture's analysis: what the bounds O(n·h),
/// O(n²) and expected O(n log n) count.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct Work {
    /// `Volume6` evaluations, the algorithms' unit of work: gift wrapping tests every point
    /// for each facet side it turns around (`FaceAdjacente`, O(n) each, O(n·h) in all), the
    /// incremental algorithm every face of P(k−1) for each point (O(n²) in all), the
    /// randomized one the candidates of the conflict lists plus the faces around each
    /// visible region (Σ|P(e)| + O(faces created)).
    pub volume6_tests: u64,
    /// Of `volume6_tests`, those that the floating-point filter of the face's plane could not
    /// decide, so that exact arithmetic did. The incremental algorithms filter against each
    /// face's plane; gift wrapping calls the adaptive predicate directly and counts none.
    pub exact_tests: u64,
    /// Σ|P(e)| over the horizon edges e of every insertion: the sizes of the merged conflict
    /// lists, expected O(n log n) (the lecture, after de Berg et al.). Randomized only; 0 for
    /// the others.
    pub conflict_work: u64,
}

impl Hull {
    /// The input points that are hull vertices, in increasing order.
    pub fn vertices(&self) -> Vec<VertexId> {
        let mut on_hull = vec![false; self.mesh.num_vertices()];
        for f in self.mesh.live_faces() {
            self.mesh.face_vertices(f, |v| on_hull[v.index()] = true);
        }
        (0..on_hull.len())
            .filter(|&v| on_hull[v])
            .map(VertexId::new)
            .collect()
    }

    /// The enclosed volume (sum of the signed tetrahedra from the origin, in floating point).
    pub fn volume(&self) -> f64 {
        let soup = self.to_soup();
        soup.faces()
            .map(|f| {
                let [a, b, c] = [f[0], f[1], f[2]].map(|v| soup.positions[v as usize]);
                a.dot(b.cross(c))
            })
            .sum::<f64>()
            / 6.0
    }

    /// The hull as a soup over every input point (vertex i is point i).
    pub fn to_soup(&self) -> PolygonSoup {
        let m = &self.mesh;
        let positions = (0..m.num_vertices())
            .map(|v| m.position(VertexId::new(v)))
            .collect();
        let mut soup = PolygonSoup::from_polygons(positions, &[] as &[[u32; 3]]);
        let mut corners = Vec::with_capacity(3);
        for f in 0..m.num_faces() {
            corners.clear();
            m.face_vertices(FaceId::new(f), |v| corners.push(v.0));
            soup.push_face(&corners);
        }
        soup
    }

    /// The hull with its vertices only (renumbered in input order), for writing a file.
    pub fn to_compact_soup(&self) -> PolygonSoup {
        let full = self.to_soup();
        let vertices = self.vertices();
        let mut new_index = vec![u32::MAX; full.num_vertices()];
        let mut soup = PolygonSoup::new();
        for (i, v) in vertices.iter().enumerate() {
            new_index[v.index()] = i as u32;
            soup.push_vertex(full.positions[v.index()]);
        }
        for f in full.faces() {
            let corners: Vec<u32> = f.iter().map(|&v| new_index[v as usize]).collect();
            soup.push_face(&corners);
        }
        soup
    }
}

/// The convex hull of `points` by `algorithm`; errors as in the module docs.
pub fn convex_hull(points: &[DVec3], algorithm: Algorithm) -> Result<Hull> {
    let prepared = predicates::prepare(points)?;
    let (mut mesh, faces_created, work) = match algorithm {
        Algorithm::Gift => gift_wrap::gift_wrap(points, &prepared.distinct)?,
        Algorithm::Incremental => {
            incremental::incremental(points, &prepared.distinct, prepared.simplex)?
        }
        Algorithm::Randomized { seed } => randomized::randomized(points, &prepared.distinct, seed)?,
    };
    mesh.compact();
    Ok(Hull {
        mesh,
        faces_created,
        work,
    })
}

/// A shape to draw random points from.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Shape {
    /// Uniform in the cube [−1, 1]³ (h grows like log² n).
    Cube,
    /// Uniform in the unit ball (h grows like n^(1/3)).
    Ball,
    /// Uniform on the unit sphere: every point is a hull vertex (h = n).
    Sphere,
}

impl Shape {
    /// The shape called `cube`, `ball` or `sphere`.
    pub fn from_name(name: &str) -> Result<Shape> {
        match name {
            "cube" => Ok(Shape::Cube),
            "ball" => Ok(Shape::Ball),
            "sphere" => Ok(Shape::Sphere),
            _ => Err(Error::Unsupported(format!(
                "unknown shape {name:?}; expected cube, ball or sphere"
            ))),
        }
    }
}

/// `n` random points from `shape`, reproducible from `seed` (ChaCha8).
pub fn random_points(shape: Shape, n: usize, seed: u64) -> Vec<DVec3> {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut cube = move || {
        DVec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        )
    };
    (0..n)
        .map(|_| match shape {
            Shape::Cube => cube(),
            // Rejection from the cube: exact uniformity, no trigonometry.
            Shape::Ball | Shape::Sphere => loop {
                let p = cube();
                let r2 = p.length_squared();
                if r2 <= 1.0 && r2 > 1e-12 {
                    break if shape == Shape::Sphere {
                        p / r2.sqrt()
                    } else {
                        p
                    };
                }
            },
        })
        .collect()
}

/// A winged-edge with every point of `points` as a vertex and the outward tetrahedron
/// `simplex` as its faces (the lecture's `Tetraedro`), and the tetrahedron's faces by slot.
/// Built from a soup, so the structure has no incremental index to keep up: the hull
/// algorithms change it only with [`WingedEdge::replace_by_cone`].
fn start_with_tetrahedron(
    points: &[DVec3],
    simplex: [u32; 4],
) -> Result<(WingedEdge, [[VertexId; 3]; 4])> {
    let faces = predicates::tetrahedron_faces(points, simplex);
    let mesh = WingedEdge::from_owned_soup(PolygonSoup::from_polygons(points.to_vec(), &faces))?;
    Ok((mesh, faces.map(|f| f.map(VertexId))))
}
