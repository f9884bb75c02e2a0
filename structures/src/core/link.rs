//! Which test of a collapse fails and the element that shows it ([`collapse_failure`]), and
//! the full link condition of Dey, Edelsbrunner, Guha and Nekhayev ("Topology preserving edge
//! contraction", 1999) computed on the links themselves ([`link_violations`]): what
//! [`check_collapse`] decides with, and what
//! `topolab explain --op collapse-edge` names in a refusal. `docs/editing.md` defines each test
//! by the name used here. Over the queries of [`MeshTopology`] alone, so every structure gives
//! the same answer; each helper allocates small vectors (editing and teaching, never a timed
//! query).

use crate::core::edit_op::{EditOp, Refusal};
use crate::core::error::Result;
use crate::core::ids::{FaceId, VertexId};
use crate::core::neighbourhood::{
    corners, faces_at, is_boundary_edge, is_boundary_vertex, neighbours, refuse,
};
use crate::core::topology::MeshTopology;

/// The faces around a vertex, each with its corners.
pub type Star = (Vec<FaceId>, Vec<Vec<VertexId>>);

/// The test of [`MeshEdit::collapse_edge`](crate::core::edit::MeshEdit::collapse_edge) over
/// the queries alone (pmp-library's `is_collapse_ok`, refused as [`Refusal::LinkCondition`],
/// with OpenMesh's tetrahedron test, refused as [`Refusal::TetrahedronTest`]: each test is
/// [`collapse_failure`]'s), so that
/// any structure can run it (`is_deleted` tells the vertices an edit deleted): the faces around
/// `from` with their corners when the collapse may be done, the refusal otherwise.
/// [`MeshEdit::check_collapse`](crate::core::edit::MeshEdit::check_collapse)'s default, and the
/// first half of [`collapse_edge`](crate::core::rewrite::collapse_edge).
pub fn check_collapse<M: MeshTopology>(
    m: &M,
    from: VertexId,
    to: VertexId,
    is_deleted: impl Fn(VertexId) -> bool,
) -> Result<Star> {
    let op = EditOp::CollapseEdge;
    let no = |r| Err(refuse::<M>(op, r));
    let live = |v: VertexId| v.index() < m.num_vertices() && !is_deleted(v);
    if !live(from) || !live(to) {
        return no(Refusal::NoSuchElement);
    }
    let ring0 = neighbours(m, from);
    if !ring0.contains(&to) {
        return no(Refusal::NotNeighbours);
    }
    let around = faces_at(m, from);
    let faces: Vec<Vec<VertexId>> = around.iter().map(|&f| corners(m, f)).collect();
    if faces.iter().any(|c| c.len() != 3) {
        return no(Refusal::NotTriangles);
    }
    // The tests in pmp-library's order, OpenMesh's tetrahedron test after its rule of
    // distinct third corners (`core/link.rs` names each, as docs/editing.md defines them).
    if let Some(failure) = collapse_failure(m, from, to, &faces, &ring0) {
        return no(failure.refusal());
    }
    Ok((around, faces))
}

/// The test of the collapse of `v0` into `v1` that fails, in the order the structures ask
/// them (pmp-library's `SurfaceMesh::is_collapse_ok`, with OpenMesh's tetrahedron test after
/// its rule of distinct third corners), with the element that shows it. `vl` and `vr` are the
/// third corners of the triangles running `v0 → v1` and `v1 → v0`.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum CollapseFailure {
    /// pmp-library's boundary rule "a triangle with two boundary edges": the triangle of the
    /// edge whose third corner is `corner` has both its other edges on the boundary (the
    /// collapse would leave an edge without faces).
    TriangleWithTwoBoundaryEdges {
        /// The triangle's third corner.
        corner: VertexId,
    },
    /// pmp-library's rule "distinct third corners": `vl` equals `vr`, the corner both
    /// triangles share (`None`: the edge has no triangle on either side).
    SameThirdCorner {
        /// The shared third corner.
        corner: Option<VertexId>,
    },
    /// OpenMesh's tetrahedron test (`BaseDecimaterT::is_collapse_legal`): `vl` and `vr` are
    /// neighbours and both have valence 3.
    Tetrahedron {
        /// The third corner of the triangle running `v0 → v1`.
        vl: VertexId,
        /// The third corner of the triangle running `v1 → v0`.
        vr: VertexId,
    },
    /// pmp-library's boundary rule "an interior edge between boundary vertices": `v0` and
    /// `v1` are both on the boundary but the edge has two triangles (the collapse would pinch
    /// the boundary at one vertex).
    InteriorEdgeBetweenBoundaryVertices,
    /// The link condition in its vertex-ring form (pmp-library's one-ring intersection test):
    /// the one-rings of `v0` and `v1` share `shared`, which is neither `vl` nor `vr`.
    VertexRing {
        /// The shared vertex.
        shared: VertexId,
    },
}

impl CollapseFailure {
    /// The refusal the structures return for it: [`Refusal::TetrahedronTest`] for the
    /// tetrahedron test, [`Refusal::LinkCondition`] for every other test.
    pub const fn refusal(self) -> Refusal {
        match self {
            CollapseFailure::Tetrahedron { .. } => Refusal::TetrahedronTest,
            _ => Refusal::LinkCondition,
        }
    }
}

/// The third corners `(vl, vr)` of the triangles running `v0 → v1` and `v1 → v0`, among
/// `faces`, the corners of the faces around `v0` (`None` where a side has no triangle).
pub fn third_corners(
    faces: &[Vec<VertexId>],
    v0: VertexId,
    v1: VertexId,
) -> (Option<VertexId>, Option<VertexId>) {
    let third = |a: VertexId, b: VertexId| {
        faces.iter().find_map(|c| {
            let k = c.len();
            (0..k)
                .find(|&i| c[i] == a && c[(i + 1) % k] == b)
                .map(|i| c[(i + 2) % k])
        })
    };
    (third(v0, v1), third(v1, v0))
}

/// The corners of the faces around `v`.
pub fn faces_around<M: MeshTopology>(m: &M, v: VertexId) -> Vec<Vec<VertexId>> {
    faces_at(m, v).into_iter().map(|f| corners(m, f)).collect()
}

/// The first test the collapse of `v0` into `v1` fails, or `None` when it may be done; `v0`
/// and `v1` are live neighbours whose faces are triangles, `faces` the corners of the faces
/// around `v0` ([`faces_around`]) and `ring0` its neighbours, sorted (passed in, as the
/// collapse has them already: on the structures whose queries scan, each is a scan).
pub fn collapse_failure<M: MeshTopology>(
    m: &M,
    v0: VertexId,
    v1: VertexId,
    faces: &[Vec<VertexId>],
    ring0: &[VertexId],
) -> Option<CollapseFailure> {
    let (vl, vr) = third_corners(faces, v0, v1);
    for (side, a, b) in [(vl, v1, v0), (vr, v0, v1)] {
        if let Some(x) = side {
            if is_boundary_edge(m, a, x) && is_boundary_edge(m, x, b) {
                return Some(CollapseFailure::TriangleWithTwoBoundaryEdges { corner: x });
            }
        }
    }
    if vl == vr {
        return Some(CollapseFailure::SameThirdCorner { corner: vl });
    }
    if let (Some(l), Some(r)) = (vl, vr) {
        let valence = |v: VertexId| neighbours(m, v).len();
        if neighbours(m, l).contains(&r) && valence(l) == 3 && valence(r) == 3 {
            return Some(CollapseFailure::Tetrahedron { vl: l, vr: r });
        }
    }
    if is_boundary_vertex(m, v0) && is_boundary_vertex(m, v1) && !is_boundary_edge(m, v0, v1) {
        return Some(CollapseFailure::InteriorEdgeBetweenBoundaryVertices);
    }
    ring_shared(m, ring0, v1, vl, vr)
        .first()
        .map(|&shared| CollapseFailure::VertexRing { shared })
}

/// The vertices of `ring0` (the one-ring of `v0`) that the one-ring of `v1` shares besides
/// `v1`, `vl` and `vr`, in `ring0`'s order: the vertex-ring form of the link condition holds
/// where there is none.
pub fn ring_shared<M: MeshTopology>(
    m: &M,
    ring0: &[VertexId],
    v1: VertexId,
    vl: Option<VertexId>,
    vr: Option<VertexId>,
) -> Vec<VertexId> {
    let ring1 = neighbours(m, v1);
    ring0
        .iter()
        .copied()
        .filter(|&w| w != v1 && Some(w) != vl && Some(w) != vr && ring1.contains(&w))
        .collect()
}

/// [`collapse_failure`] with what it is given found first: for teaching, where the collapse
/// has not looked around `v0` yet.
pub fn collapse_failure_at<M: MeshTopology>(
    m: &M,
    v0: VertexId,
    v1: VertexId,
) -> Option<CollapseFailure> {
    collapse_failure(m, v0, v1, &faces_around(m, v0), &neighbours(m, v0))
}

/// A vertex of a link: a vertex of the mesh, or ω, the one vertex the boundary is coned off
/// to (every boundary edge x - y gives the triangle x, y, ω), so that the link of a boundary
/// vertex is a closed cycle too.
#[derive(Copy, Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum LinkVertex {
    /// A vertex of the mesh.
    Vertex(VertexId),
    /// The cone's apex over the boundary.
    Omega,
}

impl std::fmt::Display for LinkVertex {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            LinkVertex::Vertex(v) => write!(f, "v{}", v.0),
            LinkVertex::Omega => f.write_str("ω"),
        }
    }
}

/// A link, or a part of one: its vertices and its edges (each `[smaller, larger]`), sorted.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Link {
    /// The vertices.
    pub vertices: Vec<LinkVertex>,
    /// The edges.
    pub edges: Vec<[LinkVertex; 2]>,
}

impl Link {
    fn sorted(mut self) -> Self {
        self.vertices.sort_unstable();
        self.vertices.dedup();
        for e in &mut self.edges {
            e.sort_unstable();
        }
        self.edges.sort_unstable();
        self.edges.dedup();
        self
    }

    /// Nothing in it.
    pub fn is_empty(&self) -> bool {
        self.vertices.is_empty() && self.edges.is_empty()
    }
}

/// Lk(v) of a vertex whose faces are triangles, with the boundary coned off to ω: for each
/// triangle (v, x, y) the vertices x, y and the edge x - y; for each boundary edge v - x the
/// vertices x, ω and the edge x - ω.
pub fn vertex_link<M: MeshTopology>(m: &M, v: VertexId) -> Link {
    let mut link = Link::default();
    for c in faces_around(m, v) {
        let k = c.len();
        if let Some(i) = c.iter().position(|&w| w == v) {
            let (x, y) = (c[(i + 1) % k], c[(i + 2) % k]);
            link.vertices
                .extend([LinkVertex::Vertex(x), LinkVertex::Vertex(y)]);
            link.edges
                .push([LinkVertex::Vertex(x), LinkVertex::Vertex(y)]);
        }
    }
    for w in neighbours(m, v) {
        if is_boundary_edge(m, v, w) {
            link.vertices
                .extend([LinkVertex::Vertex(w), LinkVertex::Omega]);
            link.edges.push([LinkVertex::Vertex(w), LinkVertex::Omega]);
        }
    }
    link.sorted()
}

/// Lk(ab) of the edge a - b, with the boundary coned off to ω: the third corners of its
/// triangles, and ω where it is a boundary edge (an edge's link has no edges on a surface).
pub fn edge_link<M: MeshTopology>(m: &M, a: VertexId, b: VertexId) -> Link {
    let faces = faces_around(m, a);
    let (vl, vr) = third_corners(&faces, a, b);
    let mut link = Link::default();
    link.vertices
        .extend(vl.into_iter().chain(vr).map(LinkVertex::Vertex));
    if is_boundary_edge(m, a, b) {
        link.vertices.push(LinkVertex::Omega);
    }
    link.sorted()
}

/// The full link condition of Dey et al., Lk(a) ∩ Lk(b) = Lk(ab), comparing vertices and
/// edges of the links (with the boundary coned off to ω): what Lk(a) ∩ Lk(b) has and Lk(ab)
/// has not, empty where the condition holds. Lk(ab) is always in the intersection, so this
/// difference is the whole test.
pub fn link_violations<M: MeshTopology>(m: &M, a: VertexId, b: VertexId) -> Link {
    let (la, lb, lab) = (vertex_link(m, a), vertex_link(m, b), edge_link(m, a, b));
    Link {
        vertices: la
            .vertices
            .iter()
            .filter(|x| lb.vertices.contains(x) && !lab.vertices.contains(x))
            .copied()
            .collect(),
        edges: la
            .edges
            .iter()
            .filter(|e| lb.edges.contains(e))
            .copied()
            .collect(),
    }
}
