//! Whole-mesh facts computed through a structure's operators: counts, boundary curves, Euler
//! characteristic, genus. What `topolab info` prints.
//!
//! # One definition for every structure
//!
//! The lecture on polygon-mesh data structures defines the boundary only for valid meshes; a
//! structure that accepts more (non-manifold vertices or edges, faces that disagree on
//! orientation) must still give the same answer as every other one, so the lab fixes it here
//! and the naive oracle (`testing::oracle`) implements it independently:
//!
//! - **Boundary curves, per fan.** The faces around a vertex fall into *fans*: two faces are in
//!   one fan when they share an edge at that vertex that has exactly two faces. An open fan ends
//!   in two boundary edges at the vertex, and those two follow each other on a boundary curve.
//!   So at a vertex with several fans (a bowtie) each fan's boundary continues within its own
//!   fan, and a boundary curve is a cycle of boundary edges linked that way. The rule needs no
//!   orientation. Where an edge has more than two faces, a fan may end at that edge rather than
//!   at a boundary edge: there the count is [`Undefined`].
//! - **Genus**, (2 − χ − b) / 2, only for one connected, orientable 2-manifold with or without
//!   boundary: no non-manifold edge, every used vertex one fan, faces orientable consistently
//!   (not necessarily oriented so), one component. Otherwise [`Undefined`], for the first
//!   reason in that order.
//!
//! [`summarize`] takes the boundary curves from the structure ([`MeshTopology::boundary_curves`])
//! and its counts from the structure's operators; the manifold and orientation analysis that
//! decides whether the genus is defined reads the faces through R20 (`face_vertices`).

use crate::algorithms::union_find::UnionFind;
use crate::core::error::Error;
use crate::core::ids::{FaceId, VertexId};
use crate::core::soup::{Connectivity, PolygonSoup};
use crate::core::topology::{BoundaryCurves, MeshTopology};

/// Why an invariant of [`Summary`] is not defined for a mesh (see the module docs). The same
/// words for every structure: `info` prints them, and its JSON holds them as strings.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Undefined {
    /// The mesh has no faces.
    NoFaces,
    /// This many edges have more than two faces.
    NonManifoldEdges(usize),
    /// This many vertices have faces that form several fans.
    NonManifoldVertices(usize),
    /// The faces cannot be oriented consistently (like a Möbius strip).
    NotOrientable,
    /// The faces form this many components (`topolab check` gives each one's genus).
    Components(usize),
}

impl std::fmt::Display for Undefined {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Undefined::NoFaces => write!(f, "no faces"),
            Undefined::NonManifoldEdges(n) => {
                write!(f, "{n} edge{} with more than two faces", plural(*n))
            }
            Undefined::NonManifoldVertices(n) => write!(
                f,
                "{n} {} whose faces form several fans",
                if *n == 1 { "vertex" } else { "vertices" }
            ),
            Undefined::NotOrientable => write!(f, "the faces cannot be oriented consistently"),
            Undefined::Components(n) => write!(f, "{n} components"),
        }
    }
}

/// The ending of a regular plural for a count of `n`: `""` for 1, `"s"` otherwise, so that
/// text says `1 round` and `2 rounds`.
pub fn plural(n: impl TryInto<u64>) -> &'static str {
    if n.try_into().ok() == Some(1) {
        ""
    } else {
        "s"
    }
}

/// An invariant as `info` and `check` print it: its value, or `undefined (why)`.
pub fn shown<T: std::fmt::Display>(value: Option<T>, undefined: Option<Undefined>) -> String {
    match (value, undefined) {
        (Some(v), _) => v.to_string(),
        (None, Some(why)) => format!("undefined ({why})"),
        (None, None) => "undefined".to_string(),
    }
}

impl serde::Serialize for Undefined {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// What decides whether the boundary curves and the genus are defined: found on the faces
/// alone, by [`manifold_facts`] for a structure and by the oracle for the tests.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct ManifoldFacts {
    /// Edges with more than two faces.
    pub non_manifold_edges: usize,
    /// Used vertices whose faces form more than one fan.
    pub non_manifold_vertices: usize,
    /// The faces can be oriented consistently (each edge of two faces traversed once each way).
    pub orientable: bool,
}

impl ManifoldFacts {
    /// The boundary-curve count `curves` as the definition allows it: undefined where an
    /// edge has more than two faces.
    pub fn boundary_curves(&self, curves: usize) -> Result<usize, Undefined> {
        match self.non_manifold_edges {
            0 => Ok(curves),
            n => Err(Undefined::NonManifoldEdges(n)),
        }
    }

    /// The genus from χ, the boundary-curve count and the component count, where defined.
    pub fn genus(
        &self,
        faces: usize,
        components: usize,
        euler_characteristic: i64,
        curves: usize,
    ) -> Result<i64, Undefined> {
        if faces == 0 {
            return Err(Undefined::NoFaces);
        }
        self.boundary_curves(curves)?;
        if self.non_manifold_vertices > 0 {
            return Err(Undefined::NonManifoldVertices(self.non_manifold_vertices));
        }
        if !self.orientable {
            return Err(Undefined::NotOrientable);
        }
        if components != 1 {
            return Err(Undefined::Components(components));
        }
        // χ = 2 - 2g - b for one connected orientable surface (even and ≥ 0 there).
        Ok((2 - euler_characteristic - curves as i64) / 2)
    }
}

/// [`ManifoldFacts`] of a structure's faces, read through R20: the edge analysis of
/// [`Connectivity::analyse`] (which goes on past problems), its fans, and orientability by
/// union-find with parity over the faces of each two-face edge. O(c log c) for c corners.
///
/// A structure that refuses non-manifold vertices holds an oriented 2-manifold (every structure
/// also refuses what [`PolygonSoup::connectivity`] refuses: non-manifold edges and faces that
/// disagree on orientation), so its facts are known without the pass, and `info` on it takes
/// no memory beyond the structure. The conformance suite holds each structure to its
/// capabilities, and the differential test (`testing::differential`) to the oracle.
pub fn manifold_facts<M: MeshTopology>(m: &M) -> ManifoldFacts {
    if !M::capabilities().non_manifold_vertices {
        return ManifoldFacts {
            non_manifold_edges: 0,
            non_manifold_vertices: 0,
            orientable: true,
        };
    }
    // The faces as a soup (positions unused: the analysis reads the indices), one face at a
    // time through a reused buffer, into arrays sized by a first pass (no doubling).
    let nf = m.num_faces();
    let mut corners = 0;
    for f in 0..nf {
        m.face_vertices(FaceId::new(f), |_| corners += 1);
    }
    let mut soup = PolygonSoup::with_capacity(m.num_vertices(), nf, corners);
    soup.positions.resize(m.num_vertices(), Default::default());
    let mut face = Vec::with_capacity(8);
    for f in 0..nf {
        face.clear();
        m.face_vertices(FaceId::new(f), |v| face.push(v.0));
        soup.push_face(&face);
    }
    let (conn, problems) = Connectivity::analyse(&soup, false);
    let non_manifold_edges = problems
        .iter()
        .filter(|p| matches!(p, Error::NonManifoldEdge { .. }))
        .count();
    let non_manifold_vertices = conn.vertex_fans(&soup).iter().filter(|&&n| n > 1).count();
    let mut orientation = UnionFind::new(soup.num_faces());
    let mut orientable = true;
    for &[c0, c1] in &conn.edge_corners {
        if c1 != u32::MAX {
            let same_direction = soup.indices()[c0 as usize] == soup.indices()[c1 as usize];
            let (f, g) = (conn.corner_face[c0 as usize], conn.corner_face[c1 as usize]);
            orientable &= orientation.union(f, g, same_direction);
        }
    }
    ManifoldFacts {
        non_manifold_edges,
        non_manifold_vertices,
        orientable,
    }
}

/// Counts and topological invariants of a mesh, as one structure computed them.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Summary {
    /// The structure that answered.
    pub structure: &'static str,
    /// Number of vertices (including unused ones).
    pub vertices: usize,
    /// Vertices used by no face.
    pub unused_vertices: usize,
    /// Number of edges.
    pub edges: usize,
    /// Number of faces.
    pub faces: usize,
    /// Number of boundary edges.
    pub boundary_edges: usize,
    /// Number of boundary curves (per fan, see the module docs), where defined.
    pub boundary_curves: Option<usize>,
    /// Why `boundary_curves` is not defined, when it is not.
    pub boundary_curves_undefined: Option<Undefined>,
    /// Connected components (of faces, through shared edges and vertices).
    pub components: usize,
    /// V - E + F over used vertices.
    pub euler_characteristic: i64,
    /// Genus, (2 - χ - b) / 2, where defined (one connected orientable 2-manifold).
    pub genus: Option<i64>,
    /// Why `genus` is not defined, when it is not.
    pub genus_undefined: Option<Undefined>,
    /// Used vertices whose faces form more than one fan ([`ManifoldFacts`]).
    pub non_manifold_vertices: usize,
    /// Every face is a triangle.
    pub triangles_only: bool,
}

impl Summary {
    /// The summary of these counts, with the boundary curves and the genus as `facts` allow.
    pub fn new(
        structure: &'static str,
        [vertices, unused_vertices, edges, faces, boundary_edges, curves, components]: [usize; 7],
        triangles_only: bool,
        facts: &ManifoldFacts,
    ) -> Self {
        let euler_characteristic =
            (vertices - unused_vertices) as i64 - edges as i64 + faces as i64;
        let boundary_curves = facts.boundary_curves(curves);
        let genus = facts.genus(faces, components, euler_characteristic, curves);
        Summary {
            structure,
            vertices,
            unused_vertices,
            edges,
            faces,
            boundary_edges,
            boundary_curves: boundary_curves.ok(),
            boundary_curves_undefined: boundary_curves.err(),
            components,
            euler_characteristic,
            genus: genus.ok(),
            genus_undefined: genus.err(),
            non_manifold_vertices: facts.non_manifold_vertices,
            triangles_only,
        }
    }
}

/// Computes the [`Summary`] through `m`'s relations (R02, R20 and the boundary curves).
/// Components are the faces joined through shared vertices, found with one pass of R02 over
/// the vertices (each vertex's faces joined to its first), so that a vertex of valence k costs
/// O(k) once: a flood fill that read the faces of every vertex of every face cost O(k²) at a
/// vertex of valence k (seconds for a fan of 50,000 triangles around one vertex).
pub fn summarize<M: MeshTopology>(m: &M) -> Summary {
    let (nv, nf) = (m.num_vertices(), m.num_faces());
    let mut unused = 0;
    let mut joined = UnionFind::new(nf);
    for v in 0..nv {
        let mut first = None;
        m.vertex_faces(VertexId::new(v), |f| match first {
            None => first = Some(f.0),
            Some(g) => {
                joined.union(f.0, g, false);
            }
        });
        unused += first.is_none() as usize;
    }
    let components = (0..nf as u32).filter(|&f| joined.find(f).0 == f).count();
    drop(joined);
    // The curves' edges reserved for the boundary edges (each in one curve), so that a mesh
    // of many boundary edges does not double its buffer past them.
    let boundary_edges = m.num_boundary_edges();
    let mut curves = BoundaryCurves {
        edges: Vec::with_capacity(boundary_edges),
        starts: Vec::new(),
    };
    m.boundary_curves(&mut curves);
    let mut triangles_only = nf > 0;
    for f in 0..nf {
        let mut k = 0;
        m.face_vertices(FaceId::new(f), |_| k += 1);
        triangles_only &= k == 3;
    }
    Summary::new(
        M::NAME,
        [
            nv,
            unused,
            m.num_edges(),
            nf,
            boundary_edges,
            curves.len(),
            components,
        ],
        triangles_only,
        &manifold_facts(m),
    )
}
