//! One edit done on one structure: its records old → new and the pictures before and after
//! ([`Explained`]).

use super::operations::edit;
use super::prepare::{corners_of, Prepared};
use super::records::{diff, records};
use super::subject::Subject;
use crate::teaching::edits::picture::EditPicture;
use std::collections::HashSet;
use topolab_structures::{
    Deletion, EditOp, Error, FaceId, MeshEdit, PolygonSoup, Refusal, Result, VertexId,
};

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
    let mut target = prepared.target(&m).ok_or_else(|| {
        Error::Unsupported(format!(
            "{} has no {} after building the mesh",
            M::NAME,
            prepared.description
        ))
    })?;
    if let Some((_, setup)) = spec.setup {
        setup(&mut m, &mut target)?;
    }
    let own_id = match (&prepared.subject, target.edge, target.face) {
        (Subject::Edge(e), Some(id), _) if id.0 != *e => Some(format!("its edge id {}", id.0)),
        (Subject::Face(f), _, Some(id)) if id.0 != *f => Some(format!("its face id {}", id.0)),
        _ => None,
    };
    let before_records = records(&m);
    let before = picture(&m, marked_subject(prepared));
    let faces_before = m.num_faces();
    (spec.call)(&mut m, &target)?;
    m.validate()?;
    let after_records = records(&m);
    let made = marked_made(&before, &m, prepared);
    let after = picture(&m, made);
    let mut changes = diff(&before_records, &after_records);
    changes.extend(compacted::<M>(faces_before, m.num_faces(), target.face));
    Ok(Explained {
        structure: M::NAME,
        own_id,
        changes,
        before,
        after,
    })
}

/// A deletion in a structure that removes faces at once (it does not mark them): the records
/// alone show only the last face moving into the freed slot, so a line says what was deleted,
/// as a marking structure's `f{i}.deleted` record does. `deleted`: the face the edit named, if
/// one.
fn compacted<M: MeshEdit>(before: usize, after: usize, deleted: Option<FaceId>) -> Vec<String> {
    if M::DELETION == Deletion::Marked || after >= before {
        return Vec::new();
    }
    let gone = before - after;
    let how = match M::DELETION {
        Deletion::Compacted => {
            "the triangle arrays are compacted, so the ids of later triangles change"
        }
        _ => "the last face moves into each freed slot",
    };
    match deleted {
        Some(f) if gone == 1 => vec![format!(
            "+ f{}.deleted: yes (removed at once: {how}; the face that was f{} is now f{})",
            f.0,
            before - 1,
            f.0
        )],
        _ if gone == 1 => vec![format!(
            "+ faces.deleted: 1 (removed at once: {how}; id f{after} is gone)"
        )],
        _ => vec![format!(
            "+ faces.deleted: {gone} (removed at once: {how}; ids f{after} to f{} are gone)",
            before - 1
        )],
    }
}

/// Vertices and edges (by their ends) drawn marked.
pub(super) type Marks = (Vec<u32>, Vec<[u32; 2]>);

/// What a picture before the edit marks: the subject's vertices and edges.
pub(super) fn marked_subject(p: &Prepared) -> Marks {
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
pub(super) fn marked_made<M: MeshEdit>(before: &EditPicture, m: &M, p: &Prepared) -> Marks {
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
pub(super) fn edges_of(faces: &[Vec<u32>]) -> Vec<[u32; 2]> {
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
pub(super) fn picture<M: MeshEdit>(m: &M, (marked_vertices, marked_edges): Marks) -> EditPicture {
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
