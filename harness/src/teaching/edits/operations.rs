//! [`edit`]: the one place that knows each operation, its subject, what it reads and the
//! call, with the [`Target`] the call acts on.

use super::st::algorithms::select::{
    rotate_selection, scale_selection, select_edges_in, select_faces_in, select_vertices_in,
    smooth_step, Aabb, EdgeSelection, FaceSelection, VertexSelection,
};

use super::st::algorithms::weld::{weld_edges, weld_faces, weld_meshes};
use super::st::{
    EdgeId, EditOp, Error, FaceId, IndexHalfEdge, MeshEdit, MeshTopology, PolygonSoup, Result,
    VertexId,
};
use super::subject::SubjectKind;
use glam::DQuat;
use glam::DVec3;

/// The tolerance of the weld of meshes: the mirror image's boundary vertices on z = 0 are
/// the mesh's own positions, bit for bit; this only forgives rounding in a file's numbers.
pub(super) const WELD_TOLERANCE: f64 = 1e-9;

/// A [`Subject`](super::Subject) found in one structure, in its ids, with the point a new vertex goes to.
#[derive(Clone, Debug)]
pub struct Target {
    /// The vertices: the edge's ends (a collapse moves the first into the second), the
    /// corners of a new face, the two vertices to weld, or a vertex and its left and right
    /// neighbours.
    pub vertices: Vec<VertexId>,
    /// The structure's id of the edge.
    pub edge: Option<EdgeId>,
    /// The structure's id of the face.
    pub face: Option<FaceId>,
    /// The structure's ids of the second edge (found to check that it is there: a weld of
    /// edges names both by their ends) and of the second face, of a weld of two.
    pub second: (Option<EdgeId>, Option<FaceId>),
    /// Where a new vertex goes: the edge's midpoint, the face's centroid, a point inside the
    /// fan that moves in a vertex split, the centroid of the mesh for an unused vertex.
    pub point: DVec3,
    /// The second mesh of a weld of meshes.
    pub other: Option<PolygonSoup>,
    /// The vertices a rotation or a scaling moves and the centre it moves them about, made by
    /// the edit's setup (`selection_at`).
    pub selection: Option<(VertexSelection, DVec3)>,
}

impl Target {
    pub(super) fn missing(what: &str) -> Error {
        Error::Unsupported(format!(
            "the edit needs {what}, which its request did not name"
        ))
    }
    /// Vertex `i` of [`Target::vertices`].
    pub fn vertex(&self, i: usize) -> Result<VertexId> {
        self.vertices
            .get(i)
            .copied()
            .ok_or_else(|| Self::missing("a vertex"))
    }
    /// [`Target::edge`], or an error.
    pub fn edge(&self) -> Result<EdgeId> {
        self.edge.ok_or_else(|| Self::missing("an edge"))
    }
    /// [`Target::face`], or an error.
    pub fn face(&self) -> Result<FaceId> {
        self.face.ok_or_else(|| Self::missing("a face"))
    }
    /// [`Target::selection`], or an error.
    pub fn selection(&self) -> Result<&(VertexSelection, DVec3)> {
        self.selection
            .as_ref()
            .ok_or_else(|| Self::missing("a selection"))
    }
    /// [`Target::other`], or an error.
    pub fn other(&self) -> Result<&PolygonSoup> {
        self.other
            .as_ref()
            .ok_or_else(|| Self::missing("a second mesh"))
    }
}

/// A call on structure `M` with a [`Target`].
pub type Call<M> = fn(&mut M, &Target) -> Result<()>;

/// What is done before the operation and neither explained nor counted, on structure `M`: an
/// edit that makes the state the operation is shown on, or a selection the operation moves
/// (kept in [`Target::selection`]).
pub type Setup<M> = fn(&mut M, &mut Target) -> Result<()>;

/// How one operation is done and explained on structure `M` ([`edit`]).
pub struct Edit<M> {
    /// What it acts on.
    pub kind: SubjectKind,
    /// The neighbourhood it reads, in words that hold for every structure (each family reads
    /// it its own way).
    pub reads: &'static str,
    /// Does it read that neighbourhood through the structure's relations, and rewrite it
    /// (`true`), or read nothing or every record whatever the structure (`false`)?
    pub local: bool,
    /// What is done first, not explained and not counted: an edit that makes the state the
    /// operation is shown on, or the selection a rotation or scaling moves (as a caller holds
    /// its selection before it moves it, so that the move's count is the move's).
    pub setup: Option<(&'static str, Setup<M>)>,
    /// The operation.
    pub call: Call<M>,
}

pub(super) fn plain<M>(kind: SubjectKind, reads: &'static str, call: Call<M>) -> Edit<M> {
    Edit {
        kind,
        reads,
        local: true,
        setup: None,
        call,
    }
}

/// The one place that knows each operation (see the module docs): what it acts on, what it
/// reads, and the call on structure `M`.
pub fn edit<M: MeshEdit>(op: EditOp) -> Edit<M> {
    use SubjectKind as K;
    match op {
        EditOp::AddVertex => Edit {
            kind: K::Nothing,
            reads: "nothing: a vertex record is appended",
            local: false,
            setup: None,
            call: |m, t| m.add_vertex(t.point).map(drop),
        },
        EditOp::AddFace => plain(
            K::Corners,
            "the fans of the new face's corners (is each a boundary vertex, is each side already an edge, and which way does it run)",
            |m, t| m.add_face(&t.vertices).map(drop),
        ),
        EditOp::DeleteFace => plain(
            K::Face,
            "the face's sides and corners and the fans of its corners (does each corner keep one fan?)",
            |m, t| m.delete_face(t.face()?),
        ),
        EditOp::DeleteVertex => plain(
            K::Vertex,
            "the faces around the vertex and the fans of their corners (does each keep one fan?)",
            |m, t| m.delete_vertex(t.vertex(0)?),
        ),
        EditOp::FlipEdge => plain(K::Edge, "the edge's two triangles and the fans of their corners", |m, t| {
            m.flip_edge(t.edge()?)
        }),
        EditOp::SplitEdge => plain(
            K::Edge,
            "the edge's one or two triangles and the fans of their corners",
            |m, t| m.split_edge(t.edge()?, t.point).map(drop),
        ),
        EditOp::SplitFace => plain(K::Face, "the face's sides and corners", |m, t| {
            m.split_face(t.face()?, t.point).map(drop)
        }),
        EditOp::CollapseEdge => plain(
            K::Edge,
            "the rings of both ends and of the two far corners, then the faces around the removed vertex",
            |m, t| m.collapse_edge(t.vertex(0)?, t.vertex(1)?),
        ),
        EditOp::SplitVertex => plain(
            K::VertexAndNeighbours,
            "the faces around the vertex from the left neighbour to the right one, which move to the new vertex",
            |m, t| {
                m.split_vertex(t.vertex(0)?, t.point, t.vertex(1)?, t.vertex(2)?)
                    .map(drop)
            },
        ),
        EditOp::GarbageCollection => Edit {
            kind: K::Vertex,
            reads: "every record (the survivors move down over the deleted slots and every id that names them is renumbered)",
            local: false,
            // A vertex deleted first, so that there is something to collect; a structure that
            // deletes nothing (explicit storage) collects nothing, and says so by writing none.
            setup: M::supports(EditOp::DeleteVertex)
                .then_some(("delete-vertex", |m, t| m.delete_vertex(t.vertex(0)?))),
            call: |m, _| {
                m.garbage_collection();
                Ok(())
            },
        },
        EditOp::WeldVertices => plain(
            K::TwoVertices,
            "the faces around both vertices and the neighbours of both (do their boundaries meet along an edge?)",
            |m, t| m.weld_vertices(t.vertex(0)?, t.vertex(1)?),
        ),
        EditOp::WeldMeshes => Edit {
            kind: K::MirrorImage,
            reads: "every face and boundary vertex of both meshes: the result is built again from the welded face list",
            local: false,
            setup: None,
            call: |m, t| {
                let other = M::from_soup(t.other()?)?;
                *m = weld_meshes(m, &other, WELD_TOLERANCE)?;
                Ok(())
            },
        },
        EditOp::SetPosition => Edit {
            kind: K::Vertex,
            reads: "nothing of the topology in a structure that stores a position once, in the vertex's record, where it is written; explicit storage holds a copy in every corner and compares every corner with the old coordinates to find them (O(n))",
            local: false,
            setup: None,
            call: |m, t| m.set_position(t.vertex(0)?, t.point),
        },
        EditOp::Select => Edit {
            kind: K::Selected,
            reads: "every vertex's position (one scan; for an edge or a face, every edge's ends or every face's corners), keeping those inside the box around the element (a vertex's reaches halfway to its nearest neighbour, an edge's or a face's is its bounding box); nothing is written: the selection is a sorted list of ids beside the structure",
            local: false,
            setup: None,
            call: |m, t| select_at(m, t).map(drop),
        },
        EditOp::RotateSelection => Edit {
            kind: K::Selected,
            reads: "the positions of the selection of select at the element (made before, not counted: its vertices, an edge's ends, a face's corners; about a vertex's neighbours' centroid, an edge's midpoint, a face's centroid); they are rotated by 30 degrees about the x axis through that centre and written back",
            local: false,
            setup: Some(("select", |m, t| {
                t.selection = Some(selection_at(m, t)?);
                Ok(())
            })),
            call: |m, t| {
                let (s, centre) = t.selection()?;
                rotate_selection(m, s, *centre, DQuat::from_rotation_x(30f64.to_radians()))
            },
        },
        EditOp::ScaleSelection => Edit {
            kind: K::Selected,
            reads: "the positions of the selection of select at the element (made before, not counted: its vertices, an edge's ends, a face's corners; about a vertex's neighbours' centroid, an edge's midpoint, a face's centroid); they are scaled by 1/2 about that centre and written back",
            local: false,
            setup: Some(("select", |m, t| {
                t.selection = Some(selection_at(m, t)?);
                Ok(())
            })),
            call: |m, t| {
                let (s, centre) = t.selection()?;
                scale_selection(m, s, *centre, DVec3::splat(0.5))
            },
        },
        EditOp::InsertEdge => plain(
            K::FaceAndCorners,
            "the face's cycle of corners (are the two corners in it, and not neighbours?)",
            |m, t| m.insert_edge(t.face()?, t.vertex(0)?, t.vertex(1)?).map(drop),
        ),
        EditOp::DeleteEdge => plain(
            K::Edge,
            "the edge's two faces and their cycles of corners (is it interior, and would the merged polygon repeat a corner?)",
            |m, t| m.delete_edge(t.edge()?),
        ),
        EditOp::WeldEdges => Edit {
            kind: K::TwoEdges,
            reads: "every face (the boundary sides, to find how each edge runs); the welded face list is built again, the second edge's ends renamed as the first's and gone, later vertex ids moving down",
            local: false,
            setup: None,
            call: |m, t| {
                let (e, g) = ([t.vertex(0)?, t.vertex(1)?], [t.vertex(2)?, t.vertex(3)?]);
                *m = weld_edges(m, e, g)?;
                Ok(())
            },
        },
        EditOp::WeldFaces => Edit {
            kind: K::TwoFaces,
            reads: "both faces' corners and positions (which corners meet: the closest pairing), then every face; the face list without the two is built again, the second face's corners renamed as the first's and gone, later vertex ids moving down",
            local: false,
            setup: None,
            call: |m, t| {
                let second = t.second.1.ok_or_else(|| Target::missing("a second face"))?;
                *m = weld_faces(m, t.face()?, second)?;
                Ok(())
            },
        },
        EditOp::Smooth => Edit {
            kind: K::WholeMesh,
            reads: "every vertex: is it on the boundary, and its neighbours' positions (R00), summed in increasing id order; every interior vertex's new position is written after all are read",
            local: false,
            setup: None,
            call: |m, _| smooth_step(m).map(drop),
        },
    }
}

/// The box [`EditOp::Select`] selects in: around vertex `v`, reaching halfway to its nearest
/// neighbour in each direction, so that it holds `v` and no other vertex of a mesh whose
/// vertices are apart.
pub(super) fn selection_box<M: MeshTopology>(m: &M, v: VertexId) -> Aabb {
    let p = m.position(v);
    let mut nearest = f64::INFINITY;
    m.vertex_vertices(v, |w| nearest = nearest.min(m.position(w).distance(p)));
    let reach = if nearest.is_finite() {
        nearest / 2.0
    } else {
        0.0
    };
    Aabb {
        min: p - DVec3::splat(reach),
        max: p + DVec3::splat(reach),
    }
}

/// The box around a face's corners or an edge's ends, bounds included.
fn bounds(points: &[DVec3]) -> Aabb {
    let (min, max) = points.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), &p| (lo.min(p), hi.max(p)),
    );
    Aabb { min, max }
}

/// What [`EditOp::Select`] selects at the element of `t`, with what its centre is made of.
enum Picked {
    /// The faces with every corner in a face's bounding box; the face's corners.
    Faces(FaceSelection, Vec<DVec3>),
    /// The edges with both ends in an edge's bounding box; the edge's ends.
    Edges(EdgeSelection, [DVec3; 2]),
    /// The vertices in the box around a vertex that reaches halfway to its nearest neighbour
    /// ([`selection_box`]); the vertex.
    Vertices(VertexSelection, VertexId),
}

/// The selection at the element of `t` (a face, an edge or a vertex): one scan of the
/// elements of its kind.
fn select_at<M: MeshEdit>(m: &M, t: &Target) -> Result<Picked> {
    if let Some(f) = t.face {
        let mut corners = Vec::new();
        m.face_vertices(f, |v| corners.push(m.position(v)));
        return Ok(Picked::Faces(
            select_faces_in(m, &bounds(&corners)),
            corners,
        ));
    }
    if let Some(e) = t.edge {
        let ends = m.edge_vertices(e).map(|v| m.position(v));
        return Ok(Picked::Edges(select_edges_in(m, &bounds(&ends)), ends));
    }
    let v = t.vertex(0)?;
    Ok(Picked::Vertices(
        select_vertices_in(m, &selection_box(m, v)),
        v,
    ))
}

/// The selection of [`select_at`] as the vertices that [`EditOp::RotateSelection`] and
/// [`EditOp::ScaleSelection`] move (a face's corners, an edge's ends), and the centre they
/// move about: a face's centroid, an edge's midpoint, a vertex's neighbours' centroid (so that
/// the vertex itself moves).
pub(super) fn selection_at<M: MeshEdit>(m: &M, t: &Target) -> Result<(VertexSelection, DVec3)> {
    Ok(match select_at(m, t)? {
        Picked::Faces(s, corners) => (s.vertices(m), centroid(corners)),
        Picked::Edges(s, [p, q]) => (s.vertices(m), (p + q) / 2.0),
        Picked::Vertices(s, v) => {
            let mut ring = Vec::new();
            m.vertex_vertices(v, |w| ring.push(m.position(w)));
            (s, centroid(ring))
        }
    })
}

/// What [`edit`] says `op` acts on.
pub fn kind_of(op: EditOp) -> SubjectKind {
    edit::<IndexHalfEdge>(op).kind
}

pub(super) fn centroid(points: impl IntoIterator<Item = DVec3>) -> DVec3 {
    let (sum, n) = points
        .into_iter()
        .fold((DVec3::ZERO, 0.0), |(s, n), p| (s + p, n + 1.0));
    if n > 0.0 {
        sum / n
    } else {
        DVec3::ZERO
    }
}
