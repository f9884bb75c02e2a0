//! # lox-directed-edge: lox 0.1.1's `DirectedEdgeMesh`
//!
//! lox's directed-edge mesh with its default configuration: per corner (half-edge) its twin
//! and its target, per vertex one outgoing half-edge; face `f` owns half-edges `3f`, `3f + 1`
//! and `3f + 2`, and half-edge `3f + i` runs from corner `i - 1` to corner `i` of
//! `vertices_around_triangle(f)`. Triangles only. Vertex and face handles are given out in
//! insertion order, so they are the soup's ids. lox stores no positions: the adapter keeps
//! them beside the mesh.
//!
//! lox offers no edges for this structure (it is not an `EdgeMesh`), so the adapter composes
//! them from the crate's own answers: `EdgeId` `e` is the half-edge `3f + i` of the edge with
//! the smaller index, and its twin is found through `faces_around_triangle(f)` (the face
//! across each half-edge, in half-edge order) and the twin face's corners: three reads.
//!
//! | operator | lox call | cost |
//! |---|---|---|
//! | R00, R02 | `vertices_around_vertex`, `faces_around_vertex` | O(k) |
//! | R01 | composed: per face around the vertex, its half-edges there and their twins | O(k) |
//! | R10, R12 | composed: `vertices_around_triangle`, `faces_around_triangle` | O(1) |
//! | R20, R22 | `vertices_around_face`, `faces_around_face` | O(1) |
//! | R21 | composed: the face's three half-edges and their twins | O(1) |
//! | R11 | composed: R21 of each face of R12 | O(1) |
//! | boundary vertex | `is_boundary_vertex` (lox also says so of an isolated vertex, the lab not) | O(1) |
//! | boundary edge | composed: the half-edge has no face across | O(1) |
//! | boundary curves | composed: enumerate edges, follow boundary edges by R01 | O(n) |
//! | successor, predecessor | composed: the edge's place in R21 | O(1) |
//!
//! ## Editing
//!
//! [`MeshEdit`](topolab_structures::MeshEdit) (in `edit::lox`) does what lox's `MeshMut` does
//! on this mesh, after the lab's checks ([`crate::edit`]):
//!
//! | operation | lox call | cost |
//! |---|---|---|
//! | add vertex | `add_vertex`; the position kept by the adapter | O(1) |
//! | add face | the lab's checks (a polygon refused as `NotTriangles`, one fan per vertex, each directed edge once), then `add_triangle`; the edge count grows by the sides that had no edge | O(k) |
//! | face split | `split_face`: the new vertex appended, face `f` keeps one triangle, two appended, three edges more; lox turns around two corners to re-link boundary twins | O(k) |
//! | set position | the adapter's positions | O(1) |
//! | garbage collection | nothing to collect: nothing is deleted | O(1) |
//!
//! Refused as [`Refusal::NotImplemented`](topolab_structures::Refusal::NotImplemented): the
//! flip and the edge split (`DirectedEdgeMesh` is no `EdgeMesh`: its `flip_edge` and
//! `split_edge_with_faces` are `unreachable!()`), the deletions, the collapse, the vertex split
//! and the weld, as for [`crate::lox_half_edge`]. Edge ids are not stable: an edge is its
//! smaller half-edge, and a face split gives one of the face's edges a half-edge of a new face.

use crate::compose;
use glam::DVec3;
use lox::core::directed_edge::{DefaultConfig, DirectedEdgeMesh};
use lox::prelude::*;
use lox::{FaceHandle, VertexHandle};
use topolab_structures::{
    BoundaryCurves, BuildFacts, Capabilities, Constructed, Cost, EdgeId, FaceId, Family,
    MeshTopology, Operator, PolygonSoup, Result, SeparateConstruction, VertexId,
};

/// The lab's name of this structure.
pub const NAME: &str = "lox-directed-edge";

/// lox's own construction apart from the lab's checks ([`SeparateConstruction`]): what the
/// report times, as it times OpenMesh's.
struct Build;

impl SeparateConstruction<LoxDirectedEdge> for Build {
    fn admit<'a>(&self, soup: &'a PolygonSoup) -> Result<BuildFacts<'a>> {
        compose::admit_small_stars(soup, NAME, true)
    }

    /// As lox's documentation builds a mesh: reserve, `add_vertex` per vertex,
    /// `add_triangle` per face.
    fn construction(&self, facts: &BuildFacts<'_>) -> Result<Constructed<LoxDirectedEdge>> {
        let soup = facts.soup();
        compose::without_panic(NAME, || {
            let mut mesh = DirectedEdgeMesh::<DefaultConfig>::empty();
            mesh.reserve_for_vertices(facts.vertices());
            mesh.reserve_for_faces(facts.faces());
            for _ in 0..soup.num_vertices() {
                mesh.add_vertex();
            }
            for face in soup.faces() {
                mesh.add_triangle([face[0], face[1], face[2]].map(VertexHandle::new));
            }
            Ok(Constructed::ready(LoxDirectedEdge {
                mesh,
                positions: soup.positions.clone(),
                edges: facts.edges() as usize,
            }))
        })
    }
}

/// lox's `DirectedEdgeMesh`, the positions kept beside it and its edge count; see the module
/// docs.
#[derive(Clone, Debug)]
pub struct LoxDirectedEdge {
    pub(crate) mesh: DirectedEdgeMesh<DefaultConfig>,
    pub(crate) positions: Vec<DVec3>,
    /// lox does not count edges here; the lab's edge analysis did, before the crate built.
    pub(crate) edges: usize,
}

impl LoxDirectedEdge {
    #[inline]
    fn corners(&self, f: u32) -> [u32; 3] {
        self.mesh
            .vertices_around_triangle(FaceHandle::new(f))
            .map(|v| v.idx())
    }

    /// The twin of half-edge `h` (`3f + i`), `None` on the boundary.
    #[inline]
    fn twin(&self, h: u32) -> Option<u32> {
        let (f, i) = (h / 3, (h % 3) as usize);
        let across = self.mesh.faces_around_triangle(FaceHandle::new(f));
        let g = across.to_array()[i]?.idx();
        // The twin runs into this half-edge's start, which is corner i - 1 of `f`.
        let start = self.corners(f)[(i + 2) % 3];
        let j = self.corners(g).iter().position(|&v| v == start)?;
        Some(3 * g + j as u32)
    }

    /// The lab's id of the edge of half-edge `h`.
    #[inline]
    fn edge(&self, h: u32) -> EdgeId {
        EdgeId(self.twin(h).map_or(h, |t| t.min(h)))
    }

    /// The ends of half-edge `h`: start, target.
    #[inline]
    fn ends(&self, h: u32) -> [u32; 2] {
        let c = self.corners(h / 3);
        let i = (h % 3) as usize;
        [c[(i + 2) % 3], c[i]]
    }
}

impl MeshTopology for LoxDirectedEdge {
    const NAME: &'static str = NAME;
    const FAMILY: Family = Family::RustCrate;

    fn capabilities() -> Capabilities {
        Capabilities {
            triangles_only: true,
            ..Capabilities::POLYGONS
        }
    }

    fn cost(op: Operator) -> Cost {
        match op {
            Operator::R00 | Operator::R01 | Operator::R02 => Cost::Local,
            Operator::BoundaryCurves => Cost::Linear,
            _ => Cost::Constant,
        }
    }

    fn from_soup(soup: &PolygonSoup) -> Result<Self> {
        Build.build(soup)
    }

    fn separate_construction<'a>() -> Option<&'a dyn SeparateConstruction<Self>> {
        Some(&Build)
    }

    #[inline]
    fn num_edges(&self) -> usize {
        self.edges
    }

    fn for_each_edge(&self, mut f: impl FnMut(EdgeId)) {
        for h in 0..3 * self.num_faces() as u32 {
            if self.twin(h).is_none_or(|t| h < t) {
                f(EdgeId(h));
            }
        }
    }

    /// Each edge at `v` is the outgoing half-edge of one face around `v`, except a boundary
    /// edge that runs into `v`, which is the incoming half-edge of the last face.
    #[inline]
    fn vertex_edges(&self, v: VertexId, mut f: impl FnMut(EdgeId)) {
        for g in self.mesh.faces_around_vertex(VertexHandle::new(v.0)) {
            let g = g.idx();
            let Some(i) = self.corners(g).iter().position(|&c| c == v.0) else {
                continue;
            };
            let (incoming, outgoing) = (3 * g + i as u32, 3 * g + ((i + 1) % 3) as u32);
            f(self.edge(outgoing));
            if self.twin(incoming).is_none() {
                f(EdgeId(incoming));
            }
        }
    }
    #[inline]
    fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2] {
        self.ends(e.0).map(VertexId)
    }
    #[inline]
    fn edge_edges(&self, e: EdgeId, f: impl FnMut(EdgeId)) {
        compose::edge_edges(self, e, f);
    }
    #[inline]
    fn edge_faces(&self, e: EdgeId, mut f: impl FnMut(FaceId)) {
        f(FaceId(e.0 / 3));
        if let Some(t) = self.twin(e.0) {
            f(FaceId(t / 3));
        }
    }
    /// Half-edges 1, 2, 0 of the face, so that edge `i` joins corners `i` and `i + 1`.
    #[inline]
    fn face_edges(&self, face: FaceId, mut f: impl FnMut(EdgeId)) {
        for i in [1, 2, 0] {
            f(self.edge(3 * face.0 + i));
        }
    }
    #[inline]
    fn face_faces(&self, face: FaceId, mut f: impl FnMut(FaceId)) {
        for g in self.mesh.faces_around_face(FaceHandle::new(face.0)) {
            f(FaceId(g.idx()));
        }
    }
    #[inline]
    fn is_boundary_vertex(&self, v: VertexId) -> bool {
        let v = VertexHandle::new(v.0);
        !self.mesh.is_isolated_vertex(v) && self.mesh.is_boundary_vertex(v)
    }
    #[inline]
    fn is_boundary_edge(&self, e: EdgeId) -> bool {
        self.twin(e.0).is_none()
    }
    // Boundary curves, successor and predecessor composed (see `compose`), and the lab's
    // checks of the answers as `validate`.
    compose::composed_queries!();
    compose::lox_forwarded_queries!();

    /// From lox's record layout (its arrays' capacities are private): per vertex its
    /// outgoing half-edge (4 bytes), per half-edge its twin and target (8), plus the positions
    /// kept beside the mesh.
    fn heap_bytes(&self) -> usize {
        4 * self.num_vertices()
            + 8 * 3 * self.num_faces()
            + self.positions.capacity() * std::mem::size_of::<DVec3>()
    }

    fn explain(&self, w: &mut dyn std::fmt::Write) -> std::fmt::Result {
        writeln!(
            w,
            "lox {} DirectedEdgeMesh: {} vertices (outgoing half-edge), {} faces of three half-edges (twin, target)",
            crate::versions::LOX_VERSION,
            self.num_vertices(),
            self.num_faces()
        )?;
        compose::write_one_rings(self, w)
    }
}
