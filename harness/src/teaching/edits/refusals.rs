//! What a refusal teaches ([`witness`]): the test that failed, by the name `docs/editing.md`
//! defines it by, and the element that shows it. Computed from the mesh before the edit, by
//! pure functions of its faces, never from the structure that refused: the collapse tests of
//! [`topolab_structures::core::link`] on the index half-edge built from the mesh, and, for a
//! refusal of the result's faces, the face list the edit would leave checked as a soup (the
//! check every structure's construction makes). So every structure's refusal of one edit is
//! explained by the same element.

use super::prepare::Prepared;
use super::subject::Subject;
use topolab_structures::core::link::{
    collapse_failure_at, edge_link, faces_around, link_violations, ring_shared, third_corners,
    CollapseFailure, LinkVertex,
};
use topolab_structures::core::rewrite::merged_corners;
use topolab_structures::{
    EditOp, Error, IndexHalfEdge, MeshTopology, PolygonSoup, Refusal, VertexId,
};

/// The test that refused `op` on `prepared`'s subject of `soup` with `reason`, by its name in
/// `docs/editing.md`, and the element that shows it, in one sentence; `None` for a refusal
/// that names no test of its own (a boundary edge, an edge that exists, ...), or where the
/// mesh does not show `reason` (a structure's refusal the lab's tests would not explain).
pub fn witness(
    soup: &PolygonSoup,
    op: EditOp,
    prepared: &Prepared,
    reason: Refusal,
) -> Option<String> {
    match reason {
        Refusal::LinkCondition | Refusal::TetrahedronTest if op == EditOp::CollapseEdge => {
            collapse(soup, prepared, reason)
        }
        Refusal::BadFace | Refusal::NonManifoldEdge | Refusal::NonManifoldVertex
            if op == EditOp::AddFace =>
        {
            new_face_witness(soup, &prepared.vertices, reason)
        }
        Refusal::BadFace | Refusal::NonManifoldEdge | Refusal::NonManifoldVertex => {
            let (faces, what) = result_faces(soup, op, prepared)?;
            faces_witness(soup, &faces, what, reason)
        }
        _ => None,
    }
}

/// The error of a refused edit in words, followed by its [`witness`] where it has one: what
/// `explain --op` prints for a refusal, on the element asked for and on the one it names by
/// default.
pub fn refused_text(error: &Error, soup: &PolygonSoup, op: EditOp, prepared: &Prepared) -> String {
    match error {
        Error::EditRefused { reason, .. } => match witness(soup, op, prepared, *reason) {
            Some(w) => format!("{error}; test and element: {w}"),
            None => error.to_string(),
        },
        _ => error.to_string(),
    }
}

/// [`witness`] of a refused face addition on `soup`, for any list of corners (the command
/// line asks for three at least; the call takes any).
pub fn new_face_witness(soup: &PolygonSoup, corners: &[u32], reason: Refusal) -> Option<String> {
    let mut faces: Vec<Vec<u32>> = soup.faces().map(<[u32]>::to_vec).collect();
    faces.push(corners.to_vec());
    faces_witness(soup, &faces, Made::NewFace, reason)
}

fn v(x: VertexId) -> String {
    format!("v{}", x.0)
}

fn set(vs: &[LinkVertex]) -> String {
    let names: Vec<String> = vs.iter().map(LinkVertex::to_string).collect();
    format!("{{{}}}", names.join(", "))
}

/// Which test of the collapse failed and its element, then what the full link condition says.
fn collapse(soup: &PolygonSoup, prepared: &Prepared, reason: Refusal) -> Option<String> {
    let [a, b] = prepared.ends?;
    let m = IndexHalfEdge::from_soup(soup).ok()?;
    let (v0, v1) = (VertexId(a), VertexId(b));
    let failure = collapse_failure_at(&m, v0, v1)?;
    if failure.refusal() != reason {
        return None;
    }
    let (vl, vr) = third_corners(&faces_around(&m, v0), v0, v1);
    let corner = |c: Option<VertexId>| c.map_or_else(|| "none".to_string(), v);
    let thirds = format!("vl = {}, vr = {}", corner(vl), corner(vr));
    let mut ring0 = Vec::new();
    m.vertex_vertices(v0, |w| ring0.push(w));
    ring0.sort_unstable();
    let shared = ring_shared(&m, &ring0, v1, vl, vr);
    let valence = |x: VertexId| {
        let mut n = 0;
        m.vertex_vertices(x, |_| n += 1);
        n
    };
    let test = match failure {
        CollapseFailure::VertexRing { .. } => format!(
            "the link condition in its vertex-ring form fails: the one-rings of {} and {} share {} besides the third corners ({thirds})",
            v(v0),
            v(v1),
            shared.iter().copied().map(v).collect::<Vec<_>>().join(" and ")
        ),
        CollapseFailure::Tetrahedron { vl, vr } => format!(
            "OpenMesh's tetrahedron test fails: vl = {} and vr = {} are neighbours, of valences {} and {}; the link condition in its vertex-ring form passes (the one-rings of {} and {} share only vl and vr)",
            v(vl),
            v(vr),
            valence(vl),
            valence(vr),
            v(v0),
            v(v1)
        ),
        CollapseFailure::TriangleWithTwoBoundaryEdges { corner } => format!(
            "pmp-library's boundary rule \"a triangle with two boundary edges\" fails: the triangle ({}, {}, {}) has its edges {} - {} and {} - {} on the boundary, so the collapse would leave an edge without faces ({thirds})",
            v(v0), v(v1), v(corner), v(v1), v(corner), v(corner), v(v0)
        ),
        CollapseFailure::SameThirdCorner { corner: Some(c) } => format!(
            "pmp-library's rule \"distinct third corners\" fails: the edge's two triangles share their third corner, vl = vr = {}",
            v(c)
        ),
        CollapseFailure::SameThirdCorner { corner: None } => {
            "pmp-library's rule \"distinct third corners\" fails: the edge has no triangle".to_string()
        }
        CollapseFailure::InteriorEdgeBetweenBoundaryVertices => format!(
            "pmp-library's boundary rule \"an interior edge between boundary vertices\" fails: {} and {} are both on the boundary, but the edge between them has two triangles ({thirds}), so the collapse would pinch the boundary",
            v(v0),
            v(v1)
        ),
    };
    let (extra, lab) = (link_violations(&m, v0, v1), edge_link(&m, v0, v1));
    let links = format!("Lk({}) ∩ Lk({})", v(v0), v(v1));
    let edge = format!("Lk({}{}) = {}", v(v0), v(v1), set(&lab.vertices));
    let full = if extra.is_empty() {
        format!("the full link condition (Dey et al.) holds: {links} = {edge}")
    } else {
        let mut what: Vec<String> = extra
            .vertices
            .iter()
            .map(|x| format!("vertex {x}"))
            .collect();
        what.extend(extra.edges.iter().map(|[x, y]| format!("edge {x} - {y}")));
        format!(
            "the full link condition (Dey et al.) fails: {links} has {} beyond {edge}",
            what.join(", ")
        )
    };
    Some(format!("{test}; {full}"))
}

/// What the result is called in the sentence: the faces an edit makes.
#[derive(Copy, Clone)]
enum Made {
    /// A face added.
    NewFace,
    /// Two faces merged by deleting their edge.
    Merged,
    /// The faces left.
    Left,
    /// The faces of a weld of vertex `from` into vertex `into`, each where it was.
    Welded {
        /// The vertex kept.
        into: u32,
        /// The vertex welded into it.
        from: u32,
    },
}

/// The face list `op` would leave, where it is a face-list edit the lab can write out
/// (deleting faces and vertices, welding vertices, deleting an edge; a new face is
/// [`new_face_witness`]'s), with what it makes.
fn result_faces(
    soup: &PolygonSoup,
    op: EditOp,
    prepared: &Prepared,
) -> Option<(Vec<Vec<u32>>, Made)> {
    let mut faces: Vec<Vec<u32>> = soup.faces().map(<[u32]>::to_vec).collect();
    let made = match (op, &prepared.subject) {
        (EditOp::DeleteFace, Subject::Face(f)) => {
            faces.remove(*f as usize);
            Made::Left
        }
        (EditOp::DeleteVertex, Subject::Vertex(x)) => {
            faces.retain(|c| !c.contains(x));
            Made::Left
        }
        (EditOp::WeldVertices, Subject::Vertices(vs)) if vs.len() == 2 => {
            for c in &mut faces {
                for x in c.iter_mut().filter(|x| **x == vs[1]) {
                    *x = vs[0];
                }
            }
            Made::Welded {
                into: vs[0],
                from: vs[1],
            }
        }
        (EditOp::DeleteEdge, Subject::Edge(_)) => {
            let [a, b] = prepared.ends?;
            let runs = |x: u32, y: u32| {
                faces.iter().enumerate().find_map(|(f, c)| {
                    let k = c.len();
                    (0..k)
                        .find(|&i| c[i] == x && c[(i + 1) % k] == y)
                        .map(|i| (f, i))
                })
            };
            let ((f1, i1), (f2, i2)) = (runs(a, b)?, runs(b, a)?);
            if f1 == f2 {
                return None;
            }
            let merged = merged_corners(&faces[f1], i1, &faces[f2], i2);
            faces = faces
                .into_iter()
                .enumerate()
                .filter(|&(f, _)| f != f1 && f != f2)
                .map(|(_, c)| c)
                .collect();
            // The other faces are the mesh's own, valid: what fails is the merged polygon.
            faces.push(merged);
            Made::Merged
        }
        _ => return None,
    };
    Some((faces, made))
}

/// The check of the face list `faces` (on `soup`'s vertices) that fails as `reason` says,
/// in words, with the face, the corner, the edge or the vertex it fails on.
fn faces_witness(
    soup: &PolygonSoup,
    faces: &[Vec<u32>],
    made: Made,
    reason: Refusal,
) -> Option<String> {
    let result = PolygonSoup::from_polygons(soup.positions.clone(), faces);
    let corners = |c: &[u32]| c.iter().map(u32::to_string).collect::<Vec<_>>().join(", ");
    let polygon = |f: usize| match made {
        Made::NewFace => format!("the new face ({})", corners(&faces[f])),
        Made::Merged => format!("the merged polygon ({})", corners(&faces[f])),
        Made::Left => format!("a face ({})", corners(&faces[f])),
        // A weld rewrites faces in place: face f was the mesh's face f.
        Made::Welded { into, from } => format!(
            "the face ({}) with v{from} welded into v{into}, ({}),",
            corners(soup.face(f)),
            corners(&faces[f])
        ),
    };
    let error = match reason {
        Refusal::BadFace => result.check().err()?,
        Refusal::NonManifoldEdge => result.connectivity().err()?,
        _ => result.manifold_connectivity().err()?,
    };
    match (reason, error) {
        (Refusal::BadFace, Error::TooFewCorners { face, corners, .. }) => Some(format!(
            "too few corners: {} would have {corners} corners, and a face needs at least three",
            polygon(face)
        )),
        (Refusal::BadFace, Error::RepeatedVertex { face, vertex, .. }) => {
            let mut distinct = faces[face].clone();
            distinct.sort_unstable();
            distinct.dedup();
            Some(format!(
                "repeated corner: {} has {} distinct corners but corner {vertex} twice",
                polygon(face),
                distinct.len()
            ))
        }
        (Refusal::NonManifoldEdge, Error::NonManifoldEdge { a, b, faces, .. }) => Some(format!(
            "non-manifold edge: edge v{a} - v{b} would have {} faces",
            faces.len()
        )),
        (Refusal::NonManifoldEdge, Error::InconsistentOrientation { a, b, .. }) => Some(format!(
            "non-manifold edge: edge v{a} - v{b} would have two faces running it v{a} -> v{b}"
        )),
        (Refusal::NonManifoldVertex, Error::NonManifoldVertex { vertex, fans }) => Some(format!(
            "several fans: the faces around v{vertex} would form {fans} fans"
        )),
        _ => None,
    }
}
