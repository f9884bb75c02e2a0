//! A [`Subject`] checked against the mesh and found in the reference structure: the
//! [`Prepared`] edit, with the point a new vertex goes to.

use super::operations::{centroid, kind_of, Target};
use super::st::{
    EdgeId, EditOp, Error, FaceId, IndexHalfEdge, MeshEdit, MeshTopology, PolygonSoup, Result,
    VertexId,
};
use super::subject::{Subject, SubjectKind};
use glam::DVec3;

/// A [`Subject`] with what every structure needs to find it and do the edit, found once on
/// the index half-edge (the reference whose numbering [`Subject`] uses).
#[derive(Clone, Debug)]
pub struct Prepared {
    /// The element.
    pub subject: Subject,
    /// The vertices (see [`Target::vertices`]).
    pub(super) vertices: Vec<u32>,
    /// The edge's ends, for an edge.
    pub(super) ends: Option<[u32; 2]>,
    /// The face's corners, for a face.
    pub(super) corners: Option<Vec<u32>>,
    /// The second edge's ends and the second face's corners, for a weld of two.
    pub(super) second: (Option<[u32; 2]>, Option<Vec<u32>>),
    /// See [`Target::point`].
    pub(super) point: DVec3,
    /// See [`Target::other`].
    pub(super) other: Option<PolygonSoup>,
    /// The element in words ("edge 1 (v1 - v3)", "face 2 (v2, v0, v3)").
    pub description: String,
}

/// Does `op` select around its element (select, and rotate or scale a selection)?
fn selects(op: EditOp) -> bool {
    matches!(
        op,
        EditOp::Select | EditOp::RotateSelection | EditOp::ScaleSelection
    )
}

pub(super) fn out_of_range(element: super::st::Element, id: u32, count: usize) -> Error {
    Error::ElementOutOfRange {
        structure: "the mesh",
        element,
        id,
        count: count as u32,
    }
}

pub(super) fn corners_of<M: MeshTopology>(m: &M, f: FaceId) -> Vec<u32> {
    let mut c = Vec::new();
    m.face_vertices(f, |v| c.push(v.0));
    c
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
    use super::st::Element as E;
    let kind = kind_of(op);
    let selected = matches!(
        subject.kind(),
        SubjectKind::Vertex | SubjectKind::Edge | SubjectKind::Face
    );
    if subject.kind() != kind && !(kind == SubjectKind::Selected && selected) {
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
                _ if selects(op) => format!(
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
            let selection = if selects(op) {
                " (the selection: the edges with both ends in its bounding box)"
            } else {
                ""
            };
            format!("edge {e} (v{a} - v{b}){selection}")
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
            let selection = if selects(op) {
                " (the selection: the faces with every corner in its bounding box)"
            } else {
                ""
            };
            format!("face {f} ({}){selection}", words.join(", "))
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
pub(super) fn split_point(
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
pub(super) fn face_with_corners<M: MeshTopology>(m: &M, corners: &[u32]) -> Option<FaceId> {
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
            selection: None,
        })
    }
}
