//! One edit explained: the records an editing operation ([`EditOp`]) writes in a structure,
//! old → new, and a picture of the mesh before and after it. `topolab explain NAME --op OP`
//! prints it; the report's teaching section draws it ([`crate::results::TeachingEdit`]).
//! Both go through this module, so the lines the report shows are the lines the command
//! prints.
//!
//! [`edit`] is the one place that knows each operation: what it acts on ([`SubjectKind`]),
//! what it reads of that neighbourhood, an edit done before it where it needs one (garbage
//! collection collects what a vertex deletion marked), and the call. It is an exhaustive
//! `match` on [`EditOp`], so an operation added to the enum is a compile error there until it
//! is given its arm, and one arm is all it needs: the command line, the default element
//! ([`choose`]) and the records follow from it.
//!
//! Elements are numbered the same on every structure ([`Subject`]): vertices and faces as the
//! mesh's (a built structure keeps the soup's vertex ids; a face is found in each structure by
//! its corners), edges as the index half-edge numbers them (the mesh's edges in order of first
//! appearance, which `--trace` uses too; an edge is found in each structure by its ends).

pub mod records;

use crate::results::{EditPicture, TeachingEdit};
use glam::DQuat;
use glam::DVec3;
use records::{diff, records};
use std::collections::HashSet;
use topolab_structures::algorithms::select::{
    rotate_selection, scale_selection, select_vertices_in, smooth_step, Aabb, VertexSelection,
};
use topolab_structures::algorithms::weld::{weld_edges, weld_faces, weld_meshes};
use topolab_structures::meshes;
use topolab_structures::{
    EdgeId, EditOp, Error, FaceId, IndexHalfEdge, MeshEdit, MeshTopology, PolygonSoup, Refusal,
    Result, VertexId,
};

/// What an editing operation acts on, and how `explain --op` asks for it.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum SubjectKind {
    /// Nothing of the mesh: the operation adds a vertex (at a point it is given).
    Nothing,
    /// A vertex (`--vertex V`).
    Vertex,
    /// An edge (`--edge E`).
    Edge,
    /// A face (`--face F`).
    Face,
    /// The corners of a new face, counter-clockwise (`--vertices A,B,C`).
    Corners,
    /// Two vertices (`--vertices A,B`).
    TwoVertices,
    /// A vertex and two of its neighbours (`--vertex V --vertices L,R`).
    VertexAndNeighbours,
    /// A second mesh: the mesh's mirror image across the plane z = 0, turned so that it is
    /// oriented the other way (no element to name: `--mesh` chooses the mesh).
    MirrorImage,
    /// A face and two of its corners that are not neighbours in it (`--face F --vertices A,B`).
    FaceAndCorners,
    /// The whole mesh: every vertex (no element to name).
    WholeMesh,
    /// Two edges (`--edges E,F`).
    TwoEdges,
    /// Two faces (`--faces F,G`).
    TwoFaces,
}

impl SubjectKind {
    /// Does this kind name no element (the operation has one subject on a mesh)?
    pub const fn is_single(self) -> bool {
        matches!(
            self,
            SubjectKind::Nothing | SubjectKind::MirrorImage | SubjectKind::WholeMesh
        )
    }
}

impl SubjectKind {
    /// How the command line names this kind of element, for messages.
    pub const fn flags(self) -> &'static str {
        match self {
            SubjectKind::Nothing => "no element",
            SubjectKind::Vertex => "--vertex V",
            SubjectKind::Edge => "--edge E",
            SubjectKind::Face => "--face F",
            SubjectKind::Corners => "--vertices A,B,C (three or more corners)",
            SubjectKind::TwoVertices => "--vertices A,B",
            SubjectKind::VertexAndNeighbours => "--vertex V --vertices L,R",
            SubjectKind::MirrorImage => {
                "no element (the mesh of --mesh is welded to its mirror image)"
            }
            SubjectKind::FaceAndCorners => {
                "--face F --vertices A,B (two corners of the face that are not neighbours in it)"
            }
            SubjectKind::WholeMesh => "no element (every vertex of the mesh of --mesh)",
            SubjectKind::TwoEdges => "--edges E,F (two boundary edges)",
            SubjectKind::TwoFaces => "--faces F,G",
        }
    }
}

/// The element an edit is done to, in the numbering of the module docs.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Subject {
    /// Nothing of the mesh ([`SubjectKind::Nothing`]).
    Nothing,
    /// A vertex.
    Vertex(u32),
    /// An edge.
    Edge(u32),
    /// A face.
    Face(u32),
    /// The corners of a new face ([`SubjectKind::Corners`]) or two vertices
    /// ([`SubjectKind::TwoVertices`]).
    Vertices(Vec<u32>),
    /// A vertex and two of its neighbours ([`SubjectKind::VertexAndNeighbours`]).
    VertexAndNeighbours {
        /// The vertex.
        vertex: u32,
        /// The neighbour on the left of the new edge.
        left: u32,
        /// The neighbour on its right.
        right: u32,
    },
    /// The mesh's mirror image ([`SubjectKind::MirrorImage`]).
    MirrorImage,
    /// A face and two of its corners ([`SubjectKind::FaceAndCorners`]).
    FaceAndCorners {
        /// The face.
        face: u32,
        /// The corner the new edge starts at.
        a: u32,
        /// The corner it ends at.
        b: u32,
    },
    /// The whole mesh ([`SubjectKind::WholeMesh`]).
    WholeMesh,
    /// Two edges ([`SubjectKind::TwoEdges`]).
    Edges([u32; 2]),
    /// Two faces ([`SubjectKind::TwoFaces`]).
    Faces([u32; 2]),
}

impl Subject {
    /// The kind of element this is.
    pub fn kind(&self) -> SubjectKind {
        match self {
            Subject::Nothing => SubjectKind::Nothing,
            Subject::Vertex(_) => SubjectKind::Vertex,
            Subject::Edge(_) => SubjectKind::Edge,
            Subject::Face(_) => SubjectKind::Face,
            Subject::Vertices(v) if v.len() == 2 => SubjectKind::TwoVertices,
            Subject::Vertices(_) => SubjectKind::Corners,
            Subject::VertexAndNeighbours { .. } => SubjectKind::VertexAndNeighbours,
            Subject::MirrorImage => SubjectKind::MirrorImage,
            Subject::FaceAndCorners { .. } => SubjectKind::FaceAndCorners,
            Subject::WholeMesh => SubjectKind::WholeMesh,
            Subject::Edges(_) => SubjectKind::TwoEdges,
            Subject::Faces(_) => SubjectKind::TwoFaces,
        }
    }
}

/// The tolerance of the weld of meshes: the mirror image's boundary vertices on z = 0 are
/// the mesh's own positions, bit for bit; this only forgives rounding in a file's numbers.
const WELD_TOLERANCE: f64 = 1e-9;

/// A [`Subject`] found in one structure, in its ids, with the point a new vertex goes to.
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
}

impl Target {
    fn missing(what: &str) -> Error {
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
    /// [`Target::other`], or an error.
    pub fn other(&self) -> Result<&PolygonSoup> {
        self.other
            .as_ref()
            .ok_or_else(|| Self::missing("a second mesh"))
    }
}

/// A call on structure `M` with a [`Target`].
pub type Call<M> = fn(&mut M, &Target) -> Result<()>;

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
    /// An edit done first and not explained: the state the operation is shown on.
    pub setup: Option<(&'static str, Call<M>)>,
    /// The operation.
    pub call: Call<M>,
}

fn plain<M>(kind: SubjectKind, reads: &'static str, call: Call<M>) -> Edit<M> {
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
            setup: Some(("delete-vertex", |m, t| m.delete_vertex(t.vertex(0)?))),
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
            reads: "nothing of the topology: the vertex's position is written where it is stored (once, in the vertex's record, in every structure --op explains; explicit storage, which holds a copy in every corner, must find each)",
            local: false,
            setup: None,
            call: |m, t| m.set_position(t.vertex(0)?, t.point),
        },
        EditOp::Select => Edit {
            kind: K::Vertex,
            reads: "every vertex's position (one scan), keeping those inside the box around the vertex that reaches halfway to its nearest neighbour; nothing is written: the selection is a sorted list of vertex ids beside the structure",
            local: false,
            setup: None,
            call: |m, t| {
                select_vertices_in(m, &selection_box(m, t.vertex(0)?));
                Ok(())
            },
        },
        EditOp::RotateSelection => Edit {
            kind: K::Vertex,
            reads: "the selection of select (the vertex, in the box reaching halfway to its nearest neighbour) and its neighbours' positions (the centre: their centroid); the selected positions are rotated by 30 degrees about the x axis through that centre and written back",
            local: false,
            setup: None,
            call: |m, t| {
                let (s, centre) = selection_about_ring(m, t.vertex(0)?)?;
                rotate_selection(m, &s, centre, DQuat::from_rotation_x(30f64.to_radians()))
            },
        },
        EditOp::ScaleSelection => Edit {
            kind: K::Vertex,
            reads: "the selection of select (the vertex, in the box reaching halfway to its nearest neighbour) and its neighbours' positions (the centre: their centroid); the selected positions are scaled by 1/2 about that centre and written back",
            local: false,
            setup: None,
            call: |m, t| {
                let (s, centre) = selection_about_ring(m, t.vertex(0)?)?;
                scale_selection(m, &s, centre, DVec3::splat(0.5))
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
fn selection_box<M: MeshTopology>(m: &M, v: VertexId) -> Aabb {
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

/// The selection of [`EditOp::Select`] at `v`, and the centroid of `v`'s neighbours, about
/// which [`EditOp::RotateSelection`] and [`EditOp::ScaleSelection`] move it.
fn selection_about_ring<M: MeshEdit>(m: &M, v: VertexId) -> Result<(VertexSelection, DVec3)> {
    let s = select_vertices_in(m, &selection_box(m, v));
    let mut ring = Vec::new();
    m.vertex_vertices(v, |w| ring.push(m.position(w)));
    Ok((s, centroid(ring)))
}

/// What [`edit`] says `op` acts on.
pub fn kind_of(op: EditOp) -> SubjectKind {
    edit::<IndexHalfEdge>(op).kind
}

/// A [`Subject`] with what every structure needs to find it and do the edit, found once on
/// the index half-edge (the reference whose numbering [`Subject`] uses).
#[derive(Clone, Debug)]
pub struct Prepared {
    /// The element.
    pub subject: Subject,
    /// The vertices (see [`Target::vertices`]).
    vertices: Vec<u32>,
    /// The edge's ends, for an edge.
    ends: Option<[u32; 2]>,
    /// The face's corners, for a face.
    corners: Option<Vec<u32>>,
    /// The second edge's ends and the second face's corners, for a weld of two.
    second: (Option<[u32; 2]>, Option<Vec<u32>>),
    /// See [`Target::point`].
    point: DVec3,
    /// See [`Target::other`].
    other: Option<PolygonSoup>,
    /// The element in words ("edge 1 (v1 - v3)", "face 2 (v2, v0, v3)").
    pub description: String,
}

fn out_of_range(element: topolab_structures::Element, id: u32, count: usize) -> Error {
    Error::ElementOutOfRange {
        structure: "the mesh",
        element,
        id,
        count: count as u32,
    }
}

fn corners_of<M: MeshTopology>(m: &M, f: FaceId) -> Vec<u32> {
    let mut c = Vec::new();
    m.face_vertices(f, |v| c.push(v.0));
    c
}

fn centroid(points: impl IntoIterator<Item = DVec3>) -> DVec3 {
    let (sum, n) = points
        .into_iter()
        .fold((DVec3::ZERO, 0.0), |(s, n), p| (s + p, n + 1.0));
    if n > 0.0 {
        sum / n
    } else {
        DVec3::ZERO
    }
}

/// The mirror image of `soup` across z = 0, each face reversed so that it is oriented as a
/// mirror image must be to meet the original along its boundary on that plane.
pub fn mirror_image(soup: &PolygonSoup) -> PolygonSoup {
    let positions = soup
        .positions
        .iter()
        .map(|p| DVec3::new(p.x, p.y, -p.z))
        .collect();
    let faces: Vec<Vec<u32>> = soup
        .faces()
        .map(|f| f.iter().rev().copied().collect())
        .collect();
    PolygonSoup::from_polygons(positions, &faces)
}

/// Checks `subject` against what `op` acts on and against `reference` (the index half-edge of
/// `soup`), and finds what every structure needs for it. A subject of the wrong kind is
/// [`Error::Unsupported`], an id past the mesh's count [`Error::ElementOutOfRange`].
pub fn prepare(
    op: EditOp,
    subject: Subject,
    soup: &PolygonSoup,
    reference: &IndexHalfEdge,
) -> Result<Prepared> {
    use topolab_structures::Element as E;
    let kind = kind_of(op);
    if subject.kind() != kind {
        return Err(Error::Unsupported(format!("{op} takes {}", kind.flags())));
    }
    let nv = reference.num_vertices();
    let vertex = |v: u32| {
        if (v as usize) < nv {
            Ok(v)
        } else {
            Err(out_of_range(E::Vertex, v, nv))
        }
    };
    let at = |v: u32| reference.position(VertexId(v));
    let mut prepared = Prepared {
        subject: subject.clone(),
        vertices: Vec::new(),
        ends: None,
        corners: None,
        second: (None, None),
        point: centroid(soup.positions.iter().copied()),
        other: None,
        description: String::new(),
    };
    prepared.description = match &subject {
        Subject::Nothing => {
            let p = prepared.point;
            format!(
                "a new vertex at the mesh's centroid ({:.3}, {:.3}, {:.3})",
                p.x, p.y, p.z
            )
        }
        Subject::Vertex(v) => {
            prepared.vertices = vec![vertex(*v)?];
            match op {
                EditOp::SetPosition => {
                    let p = (at(*v) + prepared.point) / 2.0;
                    prepared.point = p;
                    format!(
                        "vertex {v}, moved halfway to the mesh's centroid, to ({:.3}, {:.3}, {:.3})",
                        p.x, p.y, p.z
                    )
                }
                EditOp::Select | EditOp::RotateSelection | EditOp::ScaleSelection => format!(
                    "vertex {v} (the selection: the vertices in the box around it that reaches halfway to its nearest neighbour)"
                ),
                _ => format!("vertex {v}"),
            }
        }
        Subject::Edge(e) => {
            let ne = reference.num_edges();
            if *e as usize >= ne {
                return Err(out_of_range(E::Edge, *e, ne));
            }
            let [a, b] = reference.edge_vertices(EdgeId(*e)).map(|v| v.0);
            prepared.ends = Some([a, b]);
            prepared.vertices = vec![a, b];
            prepared.point = (at(a) + at(b)) / 2.0;
            format!("edge {e} (v{a} - v{b})")
        }
        Subject::Face(f) => {
            let nf = reference.num_faces();
            if *f as usize >= nf {
                return Err(out_of_range(E::Face, *f, nf));
            }
            let c = corners_of(reference, FaceId(*f));
            prepared.point = centroid(c.iter().map(|&v| at(v)));
            let words = c.iter().map(|v| format!("v{v}")).collect::<Vec<_>>();
            prepared.corners = Some(c);
            format!("face {f} ({})", words.join(", "))
        }
        Subject::Vertices(vs) => {
            for &v in vs {
                vertex(v)?;
            }
            prepared.vertices = vs.clone();
            let words = vs.iter().map(|v| v.to_string()).collect::<Vec<_>>();
            if vs.len() == 2 {
                format!("vertices {} and {}", vs[0], vs[1])
            } else {
                format!("the face on vertices {}", words.join(", "))
            }
        }
        Subject::VertexAndNeighbours {
            vertex: v,
            left,
            right,
        } => {
            prepared.vertices = vec![vertex(*v)?, vertex(*left)?, vertex(*right)?];
            prepared.point = split_point(soup, reference, *v, *left, *right);
            format!("vertex {v}, between its neighbours {left} (left) and {right} (right)")
        }
        Subject::MirrorImage => {
            prepared.other = Some(mirror_image(soup));
            "the mesh and its mirror image across z = 0, along their common boundary".to_string()
        }
        Subject::FaceAndCorners { face, a, b } => {
            let nf = reference.num_faces();
            if *face as usize >= nf {
                return Err(out_of_range(E::Face, *face, nf));
            }
            prepared.vertices = vec![vertex(*a)?, vertex(*b)?];
            let c = corners_of(reference, FaceId(*face));
            prepared.point = centroid(c.iter().map(|&v| at(v)));
            let words = c.iter().map(|v| format!("v{v}")).collect::<Vec<_>>();
            prepared.corners = Some(c);
            format!(
                "face {face} ({}), by a new edge from v{a} to v{b}",
                words.join(", ")
            )
        }
        Subject::WholeMesh => "every vertex of the mesh".to_string(),
        Subject::Edges([e, f]) => {
            let ne = reference.num_edges();
            let mut ends = Vec::new();
            for id in [*e, *f] {
                if id as usize >= ne {
                    return Err(out_of_range(E::Edge, id, ne));
                }
                ends.push(reference.edge_vertices(EdgeId(id)).map(|v| v.0));
            }
            prepared.ends = Some(ends[0]);
            prepared.second.0 = Some(ends[1]);
            prepared.vertices = vec![ends[0][0], ends[0][1], ends[1][0], ends[1][1]];
            format!(
                "edges {e} (v{} - v{}) and {f} (v{} - v{}), the second sewn onto the first",
                ends[0][0], ends[0][1], ends[1][0], ends[1][1]
            )
        }
        Subject::Faces([f, g]) => {
            let nf = reference.num_faces();
            let mut words = Vec::new();
            let mut both = Vec::new();
            for id in [*f, *g] {
                if id as usize >= nf {
                    return Err(out_of_range(E::Face, id, nf));
                }
                let c = corners_of(reference, FaceId(id));
                words.push(format!(
                    "face {id} ({})",
                    c.iter()
                        .map(|v| format!("v{v}"))
                        .collect::<Vec<_>>()
                        .join(", ")
                ));
                both.push(c);
            }
            prepared.vertices = both.concat();
            prepared.second.1 = Some(both.pop().expect("two faces"));
            prepared.corners = both.pop();
            format!(
                "{} and {}, both removed and their boundaries sewn together",
                words[0], words[1]
            )
        }
    };
    Ok(prepared)
}

/// Where the new vertex of a split of `v` between `left` and `right` goes: halfway from `v`
/// to the centroid of the faces that move to it, which the split is tried on another index
/// half-edge of `soup` to find (so the picture shows no triangle turned over); `v`'s own
/// position when the split is refused (nothing is drawn then).
fn split_point(
    soup: &PolygonSoup,
    reference: &IndexHalfEdge,
    v: u32,
    left: u32,
    right: u32,
) -> DVec3 {
    let here = reference.position(VertexId(v));
    let Ok(mut probe) = IndexHalfEdge::from_soup(soup) else {
        return here;
    };
    let Ok(new) = probe.split_vertex(VertexId(v), here, VertexId(left), VertexId(right)) else {
        return here;
    };
    let mut moved = Vec::new();
    probe.vertex_faces(new, |f| {
        moved.push(centroid(
            corners_of(&probe, f)
                .into_iter()
                .map(|c| probe.position(VertexId(c))),
        ))
    });
    (here + centroid(moved)) / 2.0
}

/// The structure's id of the edge between `a` and `b`.
pub fn edge_between<M: MeshTopology>(m: &M, a: u32, b: u32) -> Option<EdgeId> {
    let mut found = None;
    m.vertex_edges(VertexId(a), |e| {
        let [x, y] = m.edge_vertices(e).map(|v| v.0);
        if (x, y) == (a, b) || (x, y) == (b, a) {
            found.get_or_insert(e);
        }
    });
    found
}

/// The structure's id of the face with `corners` in this cyclic order.
fn face_with_corners<M: MeshTopology>(m: &M, corners: &[u32]) -> Option<FaceId> {
    let mut found = None;
    m.vertex_faces(VertexId(corners[0]), |f| {
        let c = corners_of(m, f);
        let same = c.len() == corners.len()
            && (0..c.len()).any(|r| (0..c.len()).all(|i| c[(i + r) % c.len()] == corners[i]));
        if same {
            found.get_or_insert(f);
        }
    });
    found
}

impl Prepared {
    /// The subject found in `m`, in its ids (`None` if `m` does not have it: a structure built
    /// from the same mesh always does).
    pub fn target<M: MeshTopology>(&self, m: &M) -> Option<Target> {
        let edge = match self.ends {
            Some([a, b]) => Some(edge_between(m, a, b)?),
            None => None,
        };
        let face = match &self.corners {
            Some(c) => Some(face_with_corners(m, c)?),
            None => None,
        };
        let second = (
            match self.second.0 {
                Some([a, b]) => Some(edge_between(m, a, b)?),
                None => None,
            },
            match &self.second.1 {
                Some(c) => Some(face_with_corners(m, c)?),
                None => None,
            },
        );
        Some(Target {
            vertices: self.vertices.iter().map(|&v| VertexId(v)).collect(),
            edge,
            face,
            second,
            point: self.point,
            other: self.other.clone(),
        })
    }
}

/// One structure's explained edit.
#[derive(Clone, Debug)]
pub struct Explained {
    /// The structure's name.
    pub structure: &'static str,
    /// Its edge id or face id of the subject, where the structure's differs from the
    /// numbering of [`Subject`] (for the heading).
    pub own_id: Option<String>,
    /// The records that changed, old → new, one line each (`  key.field: old -> new`,
    /// `+ key: new`, `- key: old`), as `explain --op` prints them.
    pub changes: Vec<String>,
    /// The mesh before the edit (after its setup), the subject marked.
    pub before: EditPicture,
    /// The mesh after it, what it made marked.
    pub after: EditPicture,
}

/// Does `op` on `prepared`'s subject in a structure `M` built from `soup`: `Err` with the
/// structure's refusal ([`Error::EditRefused`]) when it refuses (an operation it does not
/// offer too: [`Refusal::NotImplemented`]), or when the result fails `validate()`.
pub fn explain_on<M: MeshEdit + 'static>(
    soup: &PolygonSoup,
    op: EditOp,
    prepared: &Prepared,
) -> Result<Explained> {
    if !M::supports(op) {
        return Err(Error::EditRefused {
            structure: M::NAME,
            op,
            reason: Refusal::NotImplemented,
        });
    }
    let spec = edit::<M>(op);
    let mut m = M::from_soup(soup)?;
    let target = prepared.target(&m).ok_or_else(|| {
        Error::Unsupported(format!(
            "{} has no {} after building the mesh",
            M::NAME,
            prepared.description
        ))
    })?;
    if let Some((_, setup)) = spec.setup {
        setup(&mut m, &target)?;
    }
    let own_id = match (&prepared.subject, target.edge, target.face) {
        (Subject::Edge(e), Some(id), _) if id.0 != *e => Some(format!("its edge id {}", id.0)),
        (Subject::Face(f), _, Some(id)) if id.0 != *f => Some(format!("its face id {}", id.0)),
        _ => None,
    };
    let before_records = records(&m);
    let before = picture(&m, marked_subject(prepared));
    (spec.call)(&mut m, &target)?;
    m.validate()?;
    let after_records = records(&m);
    let made = marked_made(&before, &m, prepared);
    let after = picture(&m, made);
    Ok(Explained {
        structure: M::NAME,
        own_id,
        changes: diff(&before_records, &after_records),
        before,
        after,
    })
}

/// Vertices and edges (by their ends) drawn marked.
type Marks = (Vec<u32>, Vec<[u32; 2]>);

/// What a picture before the edit marks: the subject's vertices and edges.
fn marked_subject(p: &Prepared) -> Marks {
    match (&p.subject, &p.ends, &p.corners) {
        (_, Some(ends), _) => (ends.to_vec(), vec![*ends]),
        (_, _, Some(c)) => (
            c.clone(),
            (0..c.len()).map(|i| [c[i], c[(i + 1) % c.len()]]).collect(),
        ),
        (
            Subject::VertexAndNeighbours {
                vertex,
                left,
                right,
            },
            _,
            _,
        ) => (vec![*vertex], vec![[*vertex, *left], [*vertex, *right]]),
        _ => (p.vertices.clone(), Vec::new()),
    }
}

/// What a picture after the edit marks: the edges and vertices it made, or, where it made
/// none (a collapse, a deletion), the subject's vertices that are left.
fn marked_made<M: MeshEdit>(before: &EditPicture, m: &M, p: &Prepared) -> Marks {
    let old: HashSet<[u32; 2]> = edges_of(&before.faces).into_iter().collect();
    let now = picture(m, (Vec::new(), Vec::new()));
    let edges: Vec<[u32; 2]> = edges_of(&now.faces)
        .into_iter()
        .filter(|e| !old.contains(e))
        .collect();
    let mut vertices: Vec<u32> = (before.vertices.len()..now.vertices.len())
        .map(|v| v as u32)
        .filter(|&v| now.vertices[v as usize].is_some())
        .collect();
    if edges.is_empty() && vertices.is_empty() {
        vertices = p
            .vertices
            .iter()
            .copied()
            .filter(|&v| now.vertices.get(v as usize).is_some_and(Option::is_some))
            .collect();
    }
    (vertices, edges)
}

/// The undirected edges of `faces`, each `[smaller, larger]`, in order of first appearance.
fn edges_of(faces: &[Vec<u32>]) -> Vec<[u32; 2]> {
    let mut seen = HashSet::new();
    let mut out = Vec::new();
    for f in faces {
        for i in 0..f.len() {
            let (a, b) = (f[i], f[(i + 1) % f.len()]);
            let e = [a.min(b), a.max(b)];
            if seen.insert(e) {
                out.push(e);
            }
        }
    }
    out
}

/// The live vertices and faces of `m`, with `marks`.
fn picture<M: MeshEdit>(m: &M, (marked_vertices, marked_edges): Marks) -> EditPicture {
    let vertices = (0..m.num_vertices())
        .map(VertexId::new)
        .map(|v| {
            (!m.is_deleted_vertex(v)).then(|| {
                let p = m.position(v);
                [p.x, p.y, p.z]
            })
        })
        .collect();
    let faces = (0..m.num_faces())
        .map(FaceId::new)
        .filter(|&f| !m.is_deleted_face(f))
        .map(|f| corners_of(m, f))
        .collect();
    EditPicture {
        vertices,
        faces,
        marked_vertices,
        marked_edges,
    }
}

/// What [`choose`] found: the first subject on which the edit succeeds, and the first on
/// which it is refused, with the refusal.
#[derive(Clone, Debug, Default)]
pub struct Choice {
    /// The first subject where the edit succeeds.
    pub success: Option<Subject>,
    /// The first subject where it is refused, and the structure's error.
    pub refused: Option<(Subject, String)>,
}

/// Subjects [`choose`] tries at most: a large mesh is not edited element by element.
pub const TRIED: usize = 64;

/// The vertices among which [`choose`] looks for corners of a new face, pairs to weld and
/// neighbours of a split.
const TRIED_VERTICES: u32 = 12;

/// The edges among which [`choose`] looks for pairs to weld.
const TRIED_EDGES: usize = 12;

/// The subjects of `kind` that [`choose`] tries on `m`, in order, at most [`TRIED`] of a kind
/// that has one per element (vertices, edges, faces); combinations of the first
/// [`TRIED_VERTICES`] vertices for the kinds that take several.
fn candidates(kind: SubjectKind, m: &IndexHalfEdge) -> Vec<Subject> {
    let first = |n: usize| 0..(n.min(TRIED) as u32);
    let few = (m.num_vertices() as u32).min(TRIED_VERTICES);
    match kind {
        SubjectKind::Nothing => vec![Subject::Nothing],
        SubjectKind::MirrorImage => vec![Subject::MirrorImage],
        SubjectKind::WholeMesh => vec![Subject::WholeMesh],
        SubjectKind::TwoEdges => {
            let few = m.num_edges().min(TRIED_EDGES) as u32;
            (0..few)
                .flat_map(|e| (0..few).filter(move |&f| f != e).map(move |f| [e, f]))
                .map(Subject::Edges)
                .collect()
        }
        SubjectKind::TwoFaces => {
            let n = m.num_faces() as u32;
            // Face 0 with each other face, farthest first (a weld of faces needs faces apart),
            // then the nearest (which names a refusal).
            let centre = |f: u32| {
                centroid(
                    corners_of(m, FaceId(f))
                        .into_iter()
                        .map(|v| m.position(VertexId(v))),
                )
            };
            let mut others: Vec<u32> = (1..n).collect();
            others.sort_by(|&a, &b| {
                centre(b)
                    .distance_squared(centre(0))
                    .total_cmp(&centre(a).distance_squared(centre(0)))
            });
            let mut out: Vec<Subject> = others
                .iter()
                .take(TRIED / 2)
                .map(|&g| Subject::Faces([0, g]))
                .collect();
            out.extend(
                others
                    .iter()
                    .rev()
                    .take(TRIED / 2)
                    .map(|&g| Subject::Faces([0, g])),
            );
            out
        }
        SubjectKind::FaceAndCorners => first(m.num_faces())
            .flat_map(|f| {
                let c = corners_of(m, FaceId(f));
                let pairs: Vec<(u32, u32)> = c
                    .iter()
                    .enumerate()
                    .flat_map(|(i, &a)| c[i + 1..].iter().map(move |&b| (a, b)))
                    .collect();
                pairs
                    .into_iter()
                    .map(move |(a, b)| Subject::FaceAndCorners { face: f, a, b })
            })
            .collect(),
        SubjectKind::Vertex => first(m.num_vertices()).map(Subject::Vertex).collect(),
        SubjectKind::Edge => first(m.num_edges()).map(Subject::Edge).collect(),
        SubjectKind::Face => first(m.num_faces()).map(Subject::Face).collect(),
        SubjectKind::TwoVertices => (0..few)
            .flat_map(|a| (0..few).filter(move |&b| b != a).map(move |b| (a, b)))
            .map(|(a, b)| Subject::Vertices(vec![a, b]))
            .collect(),
        SubjectKind::Corners => (0..few)
            .flat_map(|a| (0..few).map(move |b| (a, b)))
            .flat_map(|(a, b)| (0..few).map(move |c| [a, b, c]))
            .filter(|[a, b, c]| a != b && b != c && a != c)
            .map(|c| Subject::Vertices(c.to_vec()))
            .collect(),
        SubjectKind::VertexAndNeighbours => (0..few)
            .flat_map(|v| {
                let mut ring = Vec::new();
                m.vertex_vertices(VertexId(v), |w| ring.push(w.0));
                let pairs: Vec<(u32, u32)> = ring
                    .iter()
                    .flat_map(|&l| ring.iter().filter(move |&&r| r != l).map(move |&r| (l, r)))
                    .collect();
                pairs
                    .into_iter()
                    .map(move |(left, right)| Subject::VertexAndNeighbours {
                        vertex: v,
                        left,
                        right,
                    })
            })
            .collect(),
    }
}

/// The first subject of `soup` on which `op` succeeds and the first on which it is refused,
/// tried on the index half-edge (among its first [`TRIED`] vertices, edges or faces, or the
/// combinations of its first few vertices for the operations that take several): every
/// editable structure refuses what it refuses (the editing suite holds them to one model),
/// with the same reason on the cases `explain`'s tests name. A subject whose setup is refused
/// (a vertex that cannot be deleted, before a garbage collection) is skipped.
pub fn choose(soup: &PolygonSoup, op: EditOp) -> Choice {
    let mut choice = Choice::default();
    let (Ok(reference), Ok(mut m)) = (
        IndexHalfEdge::from_soup(soup),
        IndexHalfEdge::from_soup(soup),
    ) else {
        return choice;
    };
    let spec = edit::<IndexHalfEdge>(op);
    for subject in candidates(spec.kind, &reference) {
        let Ok(prepared) = prepare(op, subject.clone(), soup, &reference) else {
            continue;
        };
        let Some(target) = prepared.target(&m) else {
            continue;
        };
        // A refused edit changes nothing (what `MeshEdit` promises), so `m` is built again
        // only after an edit, or a setup, that was done.
        let mut changed = false;
        if let Some((_, setup)) = spec.setup {
            if setup(&mut m, &target).is_err() {
                continue;
            }
            changed = true;
        }
        match (spec.call)(&mut m, &target) {
            Ok(()) => {
                changed = true;
                choice.success.get_or_insert(subject);
            }
            Err(e) => {
                choice.refused.get_or_insert((subject, e.to_string()));
            }
        }
        if changed {
            match IndexHalfEdge::from_soup(soup) {
                Ok(fresh) => m = fresh,
                Err(_) => break,
            }
        }
        if choice.success.is_some() && choice.refused.is_some() {
            break;
        }
    }
    choice
}

/// The mesh an edit is shown on by default: the open tetrahedron (the CHE thesis chapter's
/// Figure 4.10), or, where `op` succeeds nowhere on it, the canonical `grid` (a 3x2
/// triangulated grid), or, where it succeeds on no triangle (an edge inserted as a face's
/// diagonal), the canonical `quad-strip` (three quads in a row). Each comes with its label and
/// its [`Choice`]; the second is `None` on the tetrahedron and the tetrahedron's choice on the
/// others (which names a refusal there).
pub struct DefaultCase {
    /// The mesh.
    pub soup: PolygonSoup,
    /// The mesh in words, and the `--mesh` that names it.
    pub label: &'static str,
    /// The `--mesh` that names it (`None` for the open tetrahedron, the default).
    pub mesh_flag: Option<&'static str>,
    /// The elements found on it.
    pub choice: Choice,
    /// Where the default moved to the grid: what was found on the tetrahedron.
    pub on_tetrahedron: Option<Choice>,
}

/// The label of the open tetrahedron.
pub const TETRAHEDRON: &str =
    "the open tetrahedron of the CHE thesis chapter's Figure 4.10 (--mesh open-tetrahedron)";
/// The label of the canonical grid.
pub const GRID: &str = "the canonical mesh `grid` (a 3x2 triangulated grid: --mesh grid)";
/// The label of the canonical quad strip.
pub const QUAD_STRIP: &str =
    "the canonical mesh `quad-strip` (three quads in a row: --mesh quad-strip)";

/// The label of the torus the welds of faces are shown on.
pub const TORUS: &str = "a torus of 128 triangles (--mesh torus:128)";

/// Builds one of the meshes [`default_case`] tries.
type MakeMesh = fn() -> PolygonSoup;

/// [`DefaultCase`] of `op`: the first of the open tetrahedron, `grid`, `quad-strip` and a
/// torus of 128 triangles (a weld of two faces needs faces apart on a closed mesh) on which
/// `op` succeeds, or the last.
pub fn default_case(op: EditOp) -> DefaultCase {
    let soup = meshes::open_tetrahedron();
    let choice = choose(&soup, op);
    if choice.success.is_some() {
        return DefaultCase {
            soup,
            label: TETRAHEDRON,
            mesh_flag: None,
            choice,
            on_tetrahedron: None,
        };
    }
    let others: [(MakeMesh, &'static str, &'static str); 3] = [
        (|| meshes::grid(3, 2, true), GRID, "grid"),
        (|| meshes::quad_strip(3), QUAD_STRIP, "quad-strip"),
        (|| meshes::torus_with_triangles(128), TORUS, "torus:128"),
    ];
    let mut case = None;
    for (make, label, flag) in others {
        let other = make();
        let found = choose(&other, op);
        let done = found.success.is_some();
        case = Some(DefaultCase {
            choice: found,
            soup: other,
            label,
            mesh_flag: Some(flag),
            on_tetrahedron: Some(choice.clone()),
        });
        if done {
            break;
        }
    }
    case.expect("three meshes tried")
}

/// The operations the report's teaching section draws, each on the index half-edge, the
/// winged-edge and the CHE's level 2 ([`teaching_edits`]).
pub const TAUGHT: [EditOp; 4] = [
    EditOp::FlipEdge,
    EditOp::SplitEdge,
    EditOp::CollapseEdge,
    EditOp::SplitVertex,
];

/// The teaching section's edits: each operation of [`TAUGHT`] on its default element and
/// mesh ([`default_case`]) on the index half-edge, the winged-edge and the CHE's level 2. An
/// edit that cannot be shown is left out (none is on these structures; the report's test
/// checks that all twelve are there).
pub fn teaching_edits() -> Vec<TeachingEdit> {
    let mut out = Vec::new();
    for op in TAUGHT {
        let case = default_case(op);
        let (Some(subject), Ok(reference)) = (
            case.choice.success.clone(),
            IndexHalfEdge::from_soup(&case.soup),
        ) else {
            continue;
        };
        let Ok(prepared) = prepare(op, subject, &case.soup, &reference) else {
            continue;
        };
        let explained = [
            explain_on::<IndexHalfEdge>(&case.soup, op, &prepared),
            explain_on::<topolab_structures::WingedEdge>(&case.soup, op, &prepared),
            explain_on::<topolab_structures::CheL2>(&case.soup, op, &prepared),
        ];
        for e in explained.into_iter().flatten() {
            out.push(TeachingEdit {
                op,
                structure: e.structure.to_string(),
                mesh: case.label.to_string(),
                subject: prepared.description.clone(),
                changes: e.changes,
                before: e.before,
                after: e.after,
            });
        }
    }
    out
}
