//! What an edit reads, described per family of structures in its source's field names (the
//! lecture on polygon-mesh data structures for the half-edges, the edge list and the vertex
//! list, the lecture on 3D convex hulls for the winged-edge, the CHE thesis chapter for the
//! CHE): the words `explain --op` prints before the records and the counts, for anything that
//! teaches an edit.

use std::any::TypeId;
use topolab_structures::{
    CheL0, CheL1, CheL2, CheL3, EdgeList, EditOp, IndexHalfEdge, PointerHalfEdge, VertexList,
    WingedEdge,
};

/// The families whose edits read differently, for the reads described ([`reads`]).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Family {
    /// The index and pointer half-edges.
    HalfEdge,
    /// The CHE levels 0–3.
    Che,
    /// The winged-edge (the face rewrite over its edge records).
    WingedEdge,
    /// The edge list (the face rewrite over its edges and polygons).
    EdgeList,
    /// The vertex list (the face rewrite over its faces' corners).
    VertexList,
    /// An editable structure with no description here (its records are still listed).
    Other,
}

impl Family {
    /// The family of structure `M`, by its type.
    pub fn of<M: 'static>() -> Family {
        let is = |t: TypeId| TypeId::of::<M>() == t;
        if is(TypeId::of::<IndexHalfEdge>()) || is(TypeId::of::<PointerHalfEdge>()) {
            Family::HalfEdge
        } else if [
            TypeId::of::<CheL0>(),
            TypeId::of::<CheL1>(),
            TypeId::of::<CheL2>(),
            TypeId::of::<CheL3>(),
        ]
        .into_iter()
        .any(is)
        {
            Family::Che
        } else if is(TypeId::of::<WingedEdge>()) {
            Family::WingedEdge
        } else if is(TypeId::of::<EdgeList>()) {
            Family::EdgeList
        } else if is(TypeId::of::<VertexList>()) {
            Family::VertexList
        } else {
            Family::Other
        }
    }
}

/// What `op` reads in a structure of `family`: a flip, an edge split and a collapse described
/// op by op; the others as the neighbourhood the operation reads (`neighbourhood`, the
/// [`Edit`](super::Edit)'s) and, where it reads one through the structure's relations
/// (`local`), how the family reads and rewrites it.
pub fn reads(family: Family, op: EditOp, neighbourhood: &str, local: bool) -> String {
    if let Some(text) = reads_of_three(family, op) {
        return text.to_string();
    }
    if !local {
        return neighbourhood.to_string();
    }
    format!("{neighbourhood}; {}", family_reads(family, op))
}

/// How a family reads a neighbourhood and writes its change, for the operations
/// [`reads_of_three`] does not describe one by one.
fn family_reads(family: Family, op: EditOp) -> &'static str {
    match (family, op) {
        (Family::Che, EditOp::WeldVertices) => {
            "the corners of the second vertex are renamed in a copy of V[], and the level's containers are built again from it (O[], VH[], EH, CH[] from V[]), refused before anything is replaced"
        }
        (Family::HalfEdge, _) => {
            "read by rotating around each vertex (the next of a half-edge's twin, from the vertex's edge field) and walking each face's cycle through next; the half-edges' next, prev, vert and face and the vertices' and faces' edge fields it relinks are written in place, new records appended, deleted ones marked until garbage collection"
        }
        (Family::Che, _) => {
            "read through the level's relations: from VH[] around the fan by O[] at levels 2-3, by scans of V[] at levels 0-1 (level 0 finds an opposite by a scan of V[], Algorithm 8); then V[] of the triangles is rewritten (a removed triangle's slot taken by the last one), O[] of their outer half-edges and VH[] of their corners repaired, EH from a scan of O[] (levels 2-3), CH[] relabelled when the boundary is touched (level 3)"
        }
        (Family::WingedEdge, _) => {
            "read through the winged-edge's queries (a vertex's fan from its av through the wings, a face's cycle through the wings of its edges); then the faces are rewritten: edge records appended or re-pointed with their wings, the last edge and face records moving into freed slots"
        }
        (Family::EdgeList, _) => {
            "read through the edge list's queries, each a scan of all of E; then the polygons P are rewritten, new edges appended, the last edge and polygon moving into freed slots"
        }
        (Family::VertexList, _) => {
            "read through the vertex list's queries, each a scan of all faces; then the faces' corners are rewritten, new faces appended, the last face moving into a freed slot"
        }
        (Family::Other, _) => {
            "not described for this structure: the records it writes are listed below"
        }
    }
}

/// What a flip, an edge split and a collapse read in a structure of `family`, in its
/// source's field names, described op by op.
fn reads_of_three(family: Family, op: EditOp) -> Option<&'static str> {
    Some(match (family, op) {
        (Family::Che, EditOp::FlipEdge) => {
            "V[h], V[next(h)], V[prev(h)] (the corners a, b, x), O[h] = g (level 0: Algorithm 8's scan of V[]), V[prev(g)] (the corner y); the star of x to check that edge x-y is new (from VH[x] around by O[prev(h)] at levels 2-3, a scan of V[] at levels 0-1); then O[] of the two triangles' 6 half-edges (their outer opposites) and the fans of the 4 corners for VH[]; EH from a scan of O[] (levels 2-3)"
        }
        (Family::Che, EditOp::SplitEdge) => {
            "V[] of the edge's one or two triangles, O[h] (level 0: a scan of V[]), O[] of their outer half-edges, the fans of their corners for VH[]; EH from a scan of O[] (levels 2-3); O[] labels of the whole mesh when the edge is on the boundary (level 3, Algorithm 4)"
        }
        (Family::Che, EditOp::CollapseEdge) => {
            "the stars of both ends and of the two opposite corners (the link condition and OpenMesh's tetrahedron test: from VH[] and O[] at levels 2-3, scans of V[] at levels 0-1), V[] and O[] of the star of the removed vertex, the last triangles (moved into the removed ones' slots); EH from a scan of O[] (levels 2-3); O[] labels of the whole mesh when the boundary is touched (level 3, Algorithm 4)"
        }
        (Family::HalfEdge, EditOp::FlipEdge) => {
            "the edge's two half-edges and their next, prev, vert and face; the corners' rotation (next of twin) to check that the new edge is not there; the vertices' and faces' edge fields it repoints"
        }
        (Family::HalfEdge, EditOp::SplitEdge) => {
            "the edge's half-edges and their next, prev, vert and face, and the face records of its triangles"
        }
        (Family::HalfEdge, EditOp::CollapseEdge) => {
            "the rotations around both ends and the two opposite corners (the link condition and OpenMesh's tetrahedron test), then every half-edge leaving the removed vertex (its vert) and the next/prev/face of the two removed triangles"
        }
        (Family::WingedEdge, EditOp::FlipEdge) => {
            "the edge record (v1, v2, fccw, fcw) and its two triangles' cycles through the wings (pccw, nccw in fccw; pcw, ncw in fcw); the fan of the far corner from its av through the wings, to check that the new edge is not there; the fans of the four corners for the rewrite's manifold check; then the two faces are rewritten, the edge record in place, the wings of the four outer edges re-pointed"
        }
        (Family::WingedEdge, EditOp::SplitEdge) => {
            "the edge record (v1, v2, fccw, fcw) and the cycles of its one or two triangles through the wings; the fans of their corners from av for the rewrite's manifold check; then the triangles are rewritten in two, the new edge records appended and the outer edges' wings re-pointed"
        }
        (Family::WingedEdge, EditOp::CollapseEdge) => {
            "the fans of both ends and of the two far corners from av through the wings (the link condition and OpenMesh's tetrahedron test), the cycles of the faces around the removed vertex; then those faces are rewritten around the kept vertex, the edges of the two removed triangles leave (the last edge and face records moving into their slots) and the wings around them are re-pointed"
        }
        (Family::EdgeList, EditOp::FlipEdge) => {
            "the edge E = (start, end, left, right), its two polygons P (lists of edge indices) and their edges' start and end; a scan of all of E for the far corner's edges (is the new edge there?) and for each corner's fan; then the two polygons are rewritten, the edge in place, and a scan of E finds the edges they share with the rest"
        }
        (Family::EdgeList, EditOp::SplitEdge) => {
            "the edge E = (start, end, left, right), its one or two polygons P and their edges' ends; a scan of all of E for each corner's fan and for the edges the new polygons share with the rest; then the polygons are rewritten and the new edges appended"
        }
        (Family::EdgeList, EditOp::CollapseEdge) => {
            "a scan of all of E per vertex of the link condition and OpenMesh's tetrahedron test (the rings of both ends and of the two far corners), the polygons around the removed vertex; then they are rewritten around the kept vertex, the edges and polygons of the two removed triangles leave (the last ones moving into their slots)"
        }
        (Family::VertexList, EditOp::FlipEdge) => {
            "a scan of all faces (lists of vertex indices) for the two that hold the edge, and for the far corner's neighbours (is the new edge there?); the faces around each of the four corners, a scan each; then the two faces' corners are rewritten in place"
        }
        (Family::VertexList, EditOp::SplitEdge) => {
            "a scan of all faces for the one or two that hold the edge, and for the faces around each corner; then each triangle's corners are rewritten and one new triangle appended per side"
        }
        (Family::VertexList, EditOp::CollapseEdge) => {
            "a scan of all faces per vertex of the link condition and OpenMesh's tetrahedron test (the rings of both ends and of the two far corners), then the faces around the removed vertex; they are rewritten around the kept vertex and the two removed triangles leave (the last faces moving into their slots)"
        }
        _ => return None,
    })
}
