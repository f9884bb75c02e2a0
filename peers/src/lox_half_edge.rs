//! # lox-half-edge: lox 0.1.1's `HalfEdgeMesh`
//!
//! lox's half-edge mesh with its standard configuration (`PolyConfig`: polygons, `prev`
//! stored). Twins are stored next to each other (`h ^ 1`), so lox's edge handle `e` owns
//! half-edges `2e` and `2e + 1` and is the lab's `EdgeId` `e`; vertex and face handles are
//! given out in insertion order, so they are the soup's ids. lox stores no positions: the
//! adapter keeps them beside the mesh, as lox's documentation keeps properties in a map
//! beside it.
//!
//! | operator | lox call | cost |
//! |---|---|---|
//! | R00, R01, R02 | `vertices_around_vertex`, `edges_around_vertex`, `faces_around_vertex` | O(k) |
//! | R10, R12 | `endpoints_of_edge`, `faces_of_edge` | O(1) |
//! | R20, R21, R22 | `vertices_around_face`, `edges_around_face`, `faces_around_face` | O(k) |
//! | R11 | composed: R21 of each face of R12 | O(k) |
//! | boundary vertex | `is_isolated_vertex`, `is_boundary_vertex` (lox also says so of an isolated vertex, the lab not) | O(1) |
//! | boundary edge | `is_boundary_edge` | O(1) |
//! | boundary curves | composed: enumerate edges, follow boundary edges by R01 | O(n) |
//! | successor, predecessor | composed: the edge's place in R21 | O(k) |
//!
//! ## Editing
//!
//! [`MeshEdit`](topolab_structures::MeshEdit) (in `edit::lox`) does what lox's `MeshMut` does
//! on this mesh, after the lab's checks ([`crate::edit`]):
//!
//! | operation | lox call | cost |
//! |---|---|---|
//! | add vertex | `add_vertex`; the position kept by the adapter | O(1) |
//! | add face | the lab's checks (at least three distinct corners, one fan per vertex, each directed edge once: lox panics on a third face and builds vertices of several fans), then `add_face` | O(k) |
//! | face split | `split_face`: the new vertex appended, face `f` keeps the fan's last triangle, the others appended | O(k) |
//! | set position | the adapter's positions | O(1) |
//! | garbage collection | nothing to collect: nothing is deleted | O(1) |
//!
//! Refused as [`Refusal::NotImplemented`](topolab_structures::Refusal::NotImplemented): the
//! flip and the edge split (lox's `flip_edge` and `split_edge_with_faces` require
//! `Self: TriMesh`, and `HalfEdgeMesh<PolyConfig>` is a `PolyMesh`); the deletions (lox's
//! `remove_face` leaves holes in its `StableVec`s, which no lox call compacts, so the lab's
//! `garbage_collection` could only rebuild); the collapse, the vertex split and the weld (lox
//! has none). Deletion is declared `Marked`, as lox's `StableVec`s delete; edge ids are stable
//! (a face split adds edges and keeps the others' handles).

use crate::compose;
use glam::DVec3;
use lox::core::half_edge::{HalfEdgeMesh, PolyConfig};
use lox::prelude::*;
use lox::{EdgeHandle, FaceHandle, VertexHandle};
use topolab_structures::{
    BoundaryCurves, BuildFacts, Capabilities, Constructed, Cost, EdgeId, FaceId, Family,
    MeshTopology, Operator, PolygonSoup, Result, SeparateConstruction, VertexId,
};

/// The lab's name of this structure.
pub const NAME: &str = "lox-half-edge";

/// lox's own construction apart from the lab's checks ([`SeparateConstruction`]): what the
/// report times, as it times OpenMesh's.
struct Build;

impl SeparateConstruction<LoxHalfEdge> for Build {
    fn admit<'a>(&self, soup: &'a PolygonSoup) -> Result<BuildFacts<'a>> {
        compose::admit_small_stars(soup, NAME, false)
    }

    /// As lox's documentation builds a mesh: reserve, `add_vertex` per vertex, `add_face`
    /// per face.
    fn construction(&self, facts: &BuildFacts<'_>) -> Result<Constructed<LoxHalfEdge>> {
        let soup = facts.soup();
        compose::without_panic(NAME, || {
            let mut mesh = HalfEdgeMesh::<PolyConfig>::empty();
            mesh.reserve_for_vertices(facts.vertices());
            mesh.reserve_for_faces(facts.faces());
            for _ in 0..soup.num_vertices() {
                mesh.add_vertex();
            }
            // One buffer for every face's handles: `add_face` takes a slice.
            let mut corners = Vec::new();
            for face in soup.faces() {
                corners.clear();
                corners.extend(face.iter().map(|&v| VertexHandle::new(v)));
                mesh.add_face(&corners);
            }
            Ok(Constructed::ready(LoxHalfEdge {
                mesh,
                positions: soup.positions.clone(),
            }))
        })
    }
}

/// lox's `HalfEdgeMesh` and the positions the adapter keeps beside it; see the module docs.
#[derive(Clone, Debug)]
pub struct LoxHalfEdge {
    pub(crate) mesh: HalfEdgeMesh<PolyConfig>,
    pub(crate) positions: Vec<DVec3>,
}

impl MeshTopology for LoxHalfEdge {
    const NAME: &'static str = NAME;
    const FAMILY: Family = Family::RustCrate;

    fn capabilities() -> Capabilities {
        Capabilities::POLYGONS
    }

    fn cost(op: Operator) -> Cost {
        match op {
            Operator::R10 | Operator::R12 | Operator::BoundaryVertex | Operator::BoundaryEdge => {
                Cost::Constant
            }
            Operator::BoundaryCurves => Cost::Linear,
            _ => Cost::Local,
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
        self.mesh.num_edges() as usize
    }

    fn for_each_edge(&self, mut f: impl FnMut(EdgeId)) {
        for e in self.mesh.edge_handles() {
            f(EdgeId(e.idx()));
        }
    }

    #[inline]
    fn vertex_edges(&self, v: VertexId, mut f: impl FnMut(EdgeId)) {
        for e in self.mesh.edges_around_vertex(VertexHandle::new(v.0)) {
            f(EdgeId(e.idx()));
        }
    }
    #[inline]
    fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2] {
        self.mesh
            .endpoints_of_edge(EdgeHandle::new(e.0))
            .map(|v| VertexId(v.idx()))
    }
    #[inline]
    fn edge_edges(&self, e: EdgeId, f: impl FnMut(EdgeId)) {
        compose::edge_edges(self, e, f);
    }
    #[inline]
    fn edge_faces(&self, e: EdgeId, mut f: impl FnMut(FaceId)) {
        for g in self.mesh.faces_of_edge(EdgeHandle::new(e.0)) {
            f(FaceId(g.idx()));
        }
    }
    #[inline]
    fn face_edges(&self, face: FaceId, mut f: impl FnMut(EdgeId)) {
        for e in self.mesh.edges_around_face(FaceHandle::new(face.0)) {
            f(EdgeId(e.idx()));
        }
    }
    #[inline]
    fn face_faces(&self, face: FaceId, mut f: impl FnMut(FaceId)) {
        for g in self.mesh.faces_around_face(FaceHandle::new(face.0)) {
            f(FaceId(g.idx()));
        }
    }
    /// lox calls an isolated vertex a boundary vertex; the lab does not (no boundary edge
    /// meets it), so the adapter asks lox both questions.
    #[inline]
    fn is_boundary_vertex(&self, v: VertexId) -> bool {
        let v = VertexHandle::new(v.0);
        !self.mesh.is_isolated_vertex(v) && self.mesh.is_boundary_vertex(v)
    }
    #[inline]
    fn is_boundary_edge(&self, e: EdgeId) -> bool {
        self.mesh.is_boundary_edge(EdgeHandle::new(e.0))
    }
    // Boundary curves, successor and predecessor composed (see `compose`), and the lab's
    // checks of the answers as `validate`.
    compose::composed_queries!();
    compose::lox_forwarded_queries!();

    /// From lox's record layout (its arrays' capacities are private): per vertex its
    /// outgoing half-edge (4 bytes), per face one half-edge (4), per half-edge face, target,
    /// next and prev (16), plus the positions kept beside the mesh. lox's `StableVec`s also
    /// keep a deletion bit per element, which only the allocator's measurement sees.
    fn heap_bytes(&self) -> usize {
        4 * self.num_vertices()
            + 4 * self.num_faces()
            + 16 * 2 * self.num_edges()
            + self.positions.capacity() * std::mem::size_of::<DVec3>()
    }

    fn explain(&self, w: &mut dyn std::fmt::Write) -> std::fmt::Result {
        writeln!(
            w,
            "lox {} HalfEdgeMesh<PolyConfig>: {} vertices (outgoing half-edge), {} faces (one half-edge), {} half-edges (face, target, next, prev; twin = h ^ 1)",
            crate::versions::LOX_VERSION,
            self.num_vertices(),
            self.num_faces(),
            2 * self.num_edges()
        )?;
        compose::write_one_rings(self, w)
    }
}
