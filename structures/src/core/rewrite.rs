//! The editing operations of [`MeshEdit`] written once over one primitive, [`FaceRewrite`]:
//! replace a few faces by a few others, for the structures whose records are faces and edges
//! rather than half-edges (the winged-edge, the edge list, the vertex list). The procedure is
//! the lab's own: the lecture on polygon-mesh data structures lists the operations a structure
//! must offer and gives these structures' query costs, but describes no way of carrying an
//! edit out; the operations and their checks are those of pmp-library and OpenMesh. An
//! operation reads the neighbourhood it changes through the structure's own queries, checks
//! that the result is an oriented manifold, and rewrites the faces of that neighbourhood. Each
//! operation costs what its queries cost in that structure plus the rewrite: O(k) where the
//! queries are local (the winged-edge), O(n) where a neighbour is found by a scan (the vertex
//! list).
//!
//! Every operation checks first and refuses with [`Error::EditRefused`](crate::Error::EditRefused) before its first
//! write, so a refused edit changes nothing. The checks are those of the half-edge libraries
//! (pmp-library's `is_collapse_ok` with the tetrahedron test of OpenMesh's Decimater for a
//! collapse, no existing edge for a flip as in pmp-library's `is_flip_ok`), and the
//! manifold check of a rewrite is local: only the vertices of the faces removed or added can
//! change their fans, so for each the faces around it after the rewrite must meet every
//! directed edge at most once (no edge with three faces, none run twice the same way) and form
//! one fan.
//!
//! Deletion: faces (and the edges a structure stores) leave at once, the last one moving into
//! the freed slot ([`Deletion::LastMoves`]); a deleted vertex keeps its slot, marked, until
//! [`MeshEdit::garbage_collection`], because vertex ids are what callers (and the changing
//! workloads) hold across edits.

use crate::core::edit::{EditOp, Refusal};
use crate::core::error::Result;
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::link::check_collapse;
pub use crate::core::link::Star;
use crate::core::neighbourhood::{
    adjacent, corners, face_with, faces_at, neighbours, refuse, sides_of,
};
use crate::core::topology::MeshTopology;
use glam::DVec3;

#[allow(unused_imports)]
use crate::core::edit::{Deletion, MeshEdit};

/// The primitive under the operations of this module: what a structure without half-edges
/// offers to be edited.
pub trait FaceRewrite: MeshTopology {
    /// Appends an unused vertex at `p`; refused with [`Error::TooLarge`](crate::Error::TooLarge) when ids run out.
    fn push_vertex(&mut self, p: DVec3) -> Result<VertexId>;
    /// Moves vertex `v` (a live vertex).
    fn write_position(&mut self, v: VertexId, p: DVec3);
    /// Is `e` an edge id of the current mesh?
    fn is_edge(&self, e: EdgeId) -> bool;
    /// Is vertex `v` marked deleted?
    fn vertex_deleted(&self, v: VertexId) -> bool;
    /// Marks vertex `v` (which has no faces left) deleted.
    fn mark_vertex_deleted(&mut self, v: VertexId);
    /// Replaces the faces `old` by the faces `new` (corners counter-clockwise), which the
    /// caller has checked make an oriented manifold. The first new faces take the ids of the
    /// old ones in order, the others are appended; old ids left over are freed, the last face
    /// moving into each. An edge the structure stores keeps its id while some face still has
    /// it (an edge that leaves and one that comes in the same rewrite may share a slot).
    fn rewrite(&mut self, old: &[FaceId], new: &[Vec<VertexId>]);
    /// Removes the marked vertices, keeping the order of the others, and renumbers the faces'
    /// corners.
    fn collect_vertices(&mut self);
    /// Reserves room for more vertices, edges and faces.
    fn reserve_room(&mut self, vertices: usize, edges: usize, faces: usize);
}

/// The vertex compaction every [`FaceRewrite::collect_vertices`] shares: takes the marks out
/// of `deleted` (shorter than `count` where later vertices were never marked) and returns
/// them, one per vertex, with the old-to-new id map (deleted vertices map to
/// `VertexId::INVALID`); `None`, the marks cleared, when nothing was marked.
pub(crate) fn compact_vertices(
    deleted: &mut Vec<bool>,
    count: usize,
) -> Option<(Vec<bool>, Vec<VertexId>)> {
    let mut marks = std::mem::take(deleted);
    if !marks.iter().any(|&d| d) {
        return None;
    }
    marks.resize(count, false);
    let mut next = 0;
    let map = marks
        .iter()
        .map(|&gone| {
            if gone {
                VertexId::INVALID
            } else {
                next += 1;
                VertexId(next - 1)
            }
        })
        .collect();
    Some((marks, map))
}

/// Keeps the entries of a per-vertex container whose vertex `marks` does not mark deleted.
pub(crate) fn retain_unmarked<T>(per_vertex: &mut Vec<T>, marks: &[bool]) {
    let mut i = 0;
    per_vertex.retain(|_| {
        i += 1;
        !marks[i - 1]
    });
}

fn live<M: FaceRewrite>(m: &M, v: VertexId) -> bool {
    v.index() < m.num_vertices() && !m.vertex_deleted(v)
}

/// Would the faces around each vertex of `check` make one fan, every directed edge once,
/// after `old` is replaced by `new`? (See the module docs.) `Err` names the refusal: an edge
/// with three faces or run twice the same way ([`Refusal::NonManifoldEdge`]), a vertex with
/// several fans ([`Refusal::NonManifoldVertex`]). Public so that a structure edited by a
/// library (the Rust crates of `topolab-peers`) checks an edit with the lab's test before the
/// library sees it.
pub fn check_result<M: MeshTopology>(
    m: &M,
    old: &[FaceId],
    new: &[Vec<VertexId>],
    check: &[VertexId],
) -> std::result::Result<(), Refusal> {
    let mut seen: Vec<VertexId> = Vec::with_capacity(check.len());
    for &v in check {
        if seen.contains(&v) {
            continue;
        }
        seen.push(v);
        let mut around: Vec<Vec<VertexId>> = faces_at(m, v)
            .into_iter()
            .filter(|f| !old.contains(f))
            .map(|f| corners(m, f))
            .collect();
        around.extend(new.iter().filter(|f| f.contains(&v)).cloned());
        // Per face, the corner after v (out) and before v (in).
        let sides: Vec<(VertexId, VertexId)> = around
            .iter()
            .map(|c| {
                let k = c.len();
                let i = c.iter().position(|&x| x == v).expect("v is a corner");
                (c[(i + 1) % k], c[(i + k - 1) % k])
            })
            .collect();
        for (i, &(out, inn)) in sides.iter().enumerate() {
            if sides[..i].iter().any(|&(o, n)| o == out || n == inn) {
                return Err(Refusal::NonManifoldEdge);
            }
        }
        // One fan: faces linked where one's out is the other's in; union by relabelling.
        let mut fan: Vec<usize> = (0..sides.len()).collect();
        for i in 0..sides.len() {
            for j in 0..sides.len() {
                if sides[i].0 == sides[j].1 && fan[i] != fan[j] {
                    let (from, to) = (fan[j], fan[i]);
                    for x in fan.iter_mut().filter(|x| **x == from) {
                        *x = to;
                    }
                }
            }
        }
        if fan.iter().any(|&x| x != fan[0]) {
            return Err(Refusal::NonManifoldVertex);
        }
    }
    Ok(())
}

fn all_corners(m: &impl MeshTopology, faces: &[FaceId], new: &[Vec<VertexId>]) -> Vec<VertexId> {
    let mut out: Vec<VertexId> = faces.iter().flat_map(|&f| corners(m, f)).collect();
    out.extend(new.iter().flatten().copied());
    out
}

/// [`MeshEdit::add_face`] over [`FaceRewrite`].
pub fn add_face<M: FaceRewrite>(m: &mut M, vertices: &[VertexId]) -> Result<FaceId> {
    let op = EditOp::AddFace;
    let distinct = (1..vertices.len()).all(|i| !vertices[..i].contains(&vertices[i]));
    if vertices.len() < 3 || !distinct {
        return Err(refuse::<M>(op, Refusal::BadFace));
    }
    if !vertices.iter().all(|&v| live(m, v)) {
        return Err(refuse::<M>(op, Refusal::NoSuchElement));
    }
    let new = [vertices.to_vec()];
    check_result(m, &[], &new, vertices).map_err(|r| refuse::<M>(op, r))?;
    m.rewrite(&[], &new);
    Ok(FaceId::new(m.num_faces() - 1))
}

/// [`MeshEdit::delete_face`] over [`FaceRewrite`].
pub fn delete_face<M: FaceRewrite>(m: &mut M, f: FaceId) -> Result<()> {
    let op = EditOp::DeleteFace;
    if f.index() >= m.num_faces() {
        return Err(refuse::<M>(op, Refusal::NoSuchElement));
    }
    let c = corners(m, f);
    check_result(m, &[f], &[], &c).map_err(|r| refuse::<M>(op, r))?;
    m.rewrite(&[f], &[]);
    Ok(())
}

/// [`MeshEdit::delete_vertex`] over [`FaceRewrite`].
pub fn delete_vertex<M: FaceRewrite>(m: &mut M, v: VertexId) -> Result<()> {
    let op = EditOp::DeleteVertex;
    if !live(m, v) {
        return Err(refuse::<M>(op, Refusal::NoSuchElement));
    }
    let old = faces_at(m, v);
    let check: Vec<VertexId> = all_corners(m, &old, &[])
        .into_iter()
        .filter(|&w| w != v)
        .collect();
    check_result(m, &old, &[], &check).map_err(|r| refuse::<M>(op, r))?;
    m.rewrite(&old, &[]);
    m.mark_vertex_deleted(v);
    Ok(())
}

/// The lab's checks of a flip of edge `e` = {a, b} (an edge of the mesh, `a`, `b` as
/// `edge_vertices` gives them): two faces ([`Refusal::BoundaryEdge`]), both triangles
/// ([`Refusal::NotTriangles`]), their third corners distinct and not yet joined
/// ([`Refusal::EdgeExists`]). Returns the faces running a → b and b → a and their third
/// corners. Public so that a structure edited by a library (the Rust crates of
/// `topolab-peers`) checks a flip with the lab's test before the library sees it.
pub fn check_flip<M: MeshTopology>(m: &M, e: EdgeId) -> Result<([FaceId; 2], [VertexId; 2])> {
    let op = EditOp::FlipEdge;
    let [a, b] = m.edge_vertices(e);
    let [Some((f1, c1, i1)), Some((f2, c2, i2))] = sides_of(m, e, a, b) else {
        return Err(refuse::<M>(op, Refusal::BoundaryEdge));
    };
    if c1.len() != 3 || c2.len() != 3 {
        return Err(refuse::<M>(op, Refusal::NotTriangles));
    }
    let (x, y) = (c1[(i1 + 2) % 3], c2[(i2 + 2) % 3]);
    if x == y || adjacent(m, x, y) {
        return Err(refuse::<M>(op, Refusal::EdgeExists));
    }
    Ok(([f1, f2], [x, y]))
}

/// [`MeshEdit::flip_edge`] over [`FaceRewrite`].
pub fn flip_edge<M: FaceRewrite>(m: &mut M, e: EdgeId) -> Result<()> {
    if !m.is_edge(e) {
        return Err(refuse::<M>(EditOp::FlipEdge, Refusal::NoSuchElement));
    }
    let ([f1, f2], [x, y]) = check_flip(m, e)?;
    let [a, b] = m.edge_vertices(e);
    m.rewrite(&[f1, f2], &[vec![a, y, x], vec![b, x, y]]);
    Ok(())
}

/// One face of an edge: the face, its corners, and the corner where it leaves the end it
/// runs from.
pub type Side = (FaceId, Vec<VertexId>, usize);

/// The lab's checks of a split of edge `e` (an edge of the mesh): at least one face
/// ([`Refusal::NoSuchElement`]), triangles ([`Refusal::NotTriangles`]), and two faces that do
/// not share their third corner (the new edge to it would have four faces:
/// [`Refusal::EdgeExists`]). Returns the edge's faces. Public as [`check_flip`] is.
pub fn check_split_edge<M: MeshTopology>(m: &M, e: EdgeId) -> Result<Vec<Side>> {
    let op = EditOp::SplitEdge;
    let [a, b] = m.edge_vertices(e);
    let sides: Vec<Side> = sides_of(m, e, a, b).into_iter().flatten().collect();
    if sides.is_empty() {
        return Err(refuse::<M>(op, Refusal::NoSuchElement));
    }
    if sides.iter().any(|(_, c, _)| c.len() != 3) {
        return Err(refuse::<M>(op, Refusal::NotTriangles));
    }
    if sides.len() == 2 && sides[0].1[(sides[0].2 + 2) % 3] == sides[1].1[(sides[1].2 + 2) % 3] {
        return Err(refuse::<M>(op, Refusal::EdgeExists));
    }
    Ok(sides)
}

/// [`MeshEdit::split_edge`] over [`FaceRewrite`].
pub fn split_edge<M: FaceRewrite>(m: &mut M, e: EdgeId, p: DVec3) -> Result<VertexId> {
    if !m.is_edge(e) {
        return Err(refuse::<M>(EditOp::SplitEdge, Refusal::NoSuchElement));
    }
    let sides = check_split_edge(m, e)?;
    let n = m.push_vertex(p)?;
    let old: Vec<FaceId> = sides.iter().map(|s| s.0).collect();
    let mut first = Vec::new();
    let mut second = Vec::new();
    for (_, c, i) in &sides {
        let (s, t, o) = (c[*i], c[(i + 1) % 3], c[(i + 2) % 3]);
        first.push(vec![s, n, o]);
        second.push(vec![n, t, o]);
    }
    first.extend(second);
    m.rewrite(&old, &first);
    Ok(n)
}

/// [`MeshEdit::split_face`] over [`FaceRewrite`].
pub fn split_face<M: FaceRewrite>(m: &mut M, f: FaceId, p: DVec3) -> Result<VertexId> {
    if f.index() >= m.num_faces() {
        return Err(refuse::<M>(EditOp::SplitFace, Refusal::NoSuchElement));
    }
    let c = corners(m, f);
    let n = m.push_vertex(p)?;
    let k = c.len();
    let new: Vec<Vec<VertexId>> = (0..k).map(|i| vec![c[i], c[(i + 1) % k], n]).collect();
    m.rewrite(&[f], &new);
    Ok(n)
}

/// [`MeshEdit::collapse_edge`] over [`FaceRewrite`]: [`check_collapse`], then the faces
/// around `from` rewritten around `to`.
pub fn collapse_edge<M: FaceRewrite + MeshEdit>(
    m: &mut M,
    from: VertexId,
    to: VertexId,
) -> Result<()> {
    let (around, faces) = check_collapse(m, from, to, |v| m.is_deleted_vertex(v))?;
    let mut old = Vec::new();
    let mut new = Vec::new();
    let mut gone = Vec::new();
    for (f, c) in around.iter().zip(&faces) {
        if c.contains(&to) {
            gone.push(*f);
        } else {
            old.push(*f);
            new.push(c.iter().map(|&v| if v == from { to } else { v }).collect());
        }
    }
    old.extend(gone);
    m.rewrite(&old, &new);
    m.mark_vertex_deleted(from);
    Ok(())
}

/// [`MeshEdit::split_vertex`] over [`FaceRewrite`].
pub fn split_vertex<M: FaceRewrite>(
    m: &mut M,
    v: VertexId,
    p: DVec3,
    left: VertexId,
    right: VertexId,
) -> Result<VertexId> {
    let op = EditOp::SplitVertex;
    let no = |r| Err(refuse::<M>(op, r));
    if [v, left, right].iter().any(|&x| !live(m, x)) {
        return no(Refusal::NoSuchElement);
    }
    if left == right || left == v || right == v {
        return no(Refusal::NotNeighbours);
    }
    let ring = neighbours(m, v);
    if !ring.contains(&left) || !ring.contains(&right) {
        return no(Refusal::NotNeighbours);
    }
    // From the face running v → left, clockwise to the one running right → v: they move. Both
    // are neighbours (checked above), so a face missing on the way is the boundary inside the
    // moving fan: the inverse of a boundary collapse, not implemented, as in the half-edges.
    let Some((mut f, mut c, _)) = face_with(m, v, left) else {
        return no(Refusal::NotImplemented);
    };
    let mut moved: Vec<(FaceId, Vec<VertexId>)> = Vec::new();
    loop {
        if moved.iter().any(|(g, _)| *g == f) {
            return no(Refusal::NotNeighbours);
        }
        let k = c.len();
        let i = c.iter().position(|&x| x == v).expect("around v");
        let before = c[(i + k - 1) % k];
        moved.push((f, c));
        if before == right {
            break;
        }
        let Some((g, d, _)) = face_with(m, v, before) else {
            return no(Refusal::NotImplemented);
        };
        (f, c) = (g, d);
    }
    let n = m.push_vertex(p)?;
    let old: Vec<FaceId> = moved.iter().map(|(f, _)| *f).collect();
    let mut new: Vec<Vec<VertexId>> = moved
        .into_iter()
        .map(|(_, c)| c.into_iter().map(|x| if x == v { n } else { x }).collect())
        .collect();
    new.push(vec![n, v, left]);
    new.push(vec![v, n, right]);
    m.rewrite(&old, &new);
    Ok(n)
}

/// [`MeshEdit::weld_vertices`] over [`FaceRewrite`]: the faces around `b` rewritten around
/// `a`, refused when a face would have both or the result would not be a manifold.
pub fn weld_vertices<M: FaceRewrite>(m: &mut M, a: VertexId, b: VertexId) -> Result<()> {
    let op = EditOp::WeldVertices;
    if !live(m, a) || !live(m, b) {
        return Err(refuse::<M>(op, Refusal::NoSuchElement));
    }
    if a == b {
        return Err(refuse::<M>(op, Refusal::SameVertex));
    }
    let old = faces_at(m, b);
    let mut new = Vec::with_capacity(old.len());
    for &f in &old {
        let c = corners(m, f);
        if c.contains(&a) {
            return Err(refuse::<M>(op, Refusal::BadFace));
        }
        new.push(c.into_iter().map(|x| if x == b { a } else { x }).collect());
    }
    let check = all_corners(m, &old, &new);
    let check: Vec<VertexId> = check.into_iter().filter(|&x| x != b).collect();
    check_result(m, &old, &new, &check).map_err(|r| refuse::<M>(op, r))?;
    m.rewrite(&old, &new);
    m.mark_vertex_deleted(b);
    Ok(())
}

/// The two polygons of face `f` (corners `c`) split by the diagonal from `a` to `b`: the
/// corners from `a` to `b`, then those from `b` to `a`; `None` unless `a` and `b` are corners
/// of `c` that are not neighbours in it. Public so that every structure's insertion (and the
/// editing suite's model) splits a face the same way.
pub fn diagonal_split(
    c: &[VertexId],
    a: VertexId,
    b: VertexId,
) -> Option<(Vec<VertexId>, Vec<VertexId>)> {
    let k = c.len();
    let i = c.iter().position(|&x| x == a)?;
    let j = c.iter().position(|&x| x == b)?;
    if i == j || (i + 1) % k == j || (j + 1) % k == i {
        return None;
    }
    let run = |from: usize, to: usize| {
        let len = (to + k - from) % k + 1;
        (0..len).map(|t| c[(from + t) % k]).collect::<Vec<_>>()
    };
    Some((run(i, j), run(j, i)))
}

/// The corners of the polygon that merges face `first` (running a → b at corner `i`) and
/// face `second` (running b → a at corner `j`) across the edge {a, b}: `first`'s corners from
/// b round to a, then `second`'s strictly between a and b, whether or not one repeats (what
/// `explain` shows of a refused deletion).
pub fn merged_corners<T>(first: &[T], i: usize, second: &[T], j: usize) -> Vec<T>
where
    T: Copy,
{
    let (k1, k2) = (first.len(), second.len());
    // first[i] = a, first[i + 1] = b; second[j] = b, second[j + 1] = a.
    let mut out: Vec<T> = (1..=k1).map(|t| first[(i + t) % k1]).collect();
    out.extend((2..k2).map(|t| second[(j + t) % k2]));
    out
}

/// [`merged_corners`], `None` when a corner would repeat.
pub fn merged_polygon(
    first: &[VertexId],
    i: usize,
    second: &[VertexId],
    j: usize,
) -> Option<Vec<VertexId>> {
    let out = merged_corners(first, i, second, j);
    let distinct = (1..out.len()).all(|t| !out[..t].contains(&out[t]));
    distinct.then_some(out)
}

/// [`MeshEdit::insert_edge`] over [`FaceRewrite`]: no manifold check is needed, since the
/// two polygons replace `f` in the fans of its corners and both new sides are new edges.
pub fn insert_edge<M: FaceRewrite>(
    m: &mut M,
    f: FaceId,
    a: VertexId,
    b: VertexId,
) -> Result<FaceId> {
    let op = EditOp::InsertEdge;
    if f.index() >= m.num_faces() || !live(m, a) || !live(m, b) {
        return Err(refuse::<M>(op, Refusal::NoSuchElement));
    }
    let c = corners(m, f);
    let Some((one, two)) = diagonal_split(&c, a, b) else {
        return Err(refuse::<M>(op, Refusal::NotDiagonal));
    };
    if adjacent(m, a, b) {
        return Err(refuse::<M>(op, Refusal::EdgeExists));
    }
    m.rewrite(&[f], &[one, two]);
    Ok(FaceId::new(m.num_faces() - 1))
}

/// [`MeshEdit::delete_edge`] over [`FaceRewrite`]: the edge's two faces rewritten as one.
/// No manifold check is needed once the merged polygon's corners are distinct: it takes the
/// place of two neighbouring faces in the fans of its corners.
pub fn delete_edge<M: FaceRewrite>(m: &mut M, e: EdgeId) -> Result<()> {
    let op = EditOp::DeleteEdge;
    if !m.is_edge(e) {
        return Err(refuse::<M>(op, Refusal::NoSuchElement));
    }
    let [a, b] = m.edge_vertices(e);
    let [Some((f1, c1, i1)), Some((f2, c2, i2))] = sides_of(m, e, a, b) else {
        return Err(refuse::<M>(op, Refusal::BoundaryEdge));
    };
    if f1 == f2 {
        return Err(refuse::<M>(op, Refusal::BadFace));
    }
    let Some(merged) = merged_polygon(&c1, i1, &c2, i2) else {
        return Err(refuse::<M>(op, Refusal::BadFace));
    };
    m.rewrite(&[f1, f2], &[merged]);
    Ok(())
}

/// [`MeshEdit::set_position`] over [`FaceRewrite`].
pub fn set_position<M: FaceRewrite>(m: &mut M, v: VertexId, p: DVec3) -> Result<()> {
    if !live(m, v) {
        return Err(refuse::<M>(EditOp::SetPosition, Refusal::NoSuchElement));
    }
    m.write_position(v, p);
    Ok(())
}

/// Face runs packed in one array with offsets (face f is `items[offsets[f]..offsets[f + 1]]`):
/// the storage of the vertex list's corners and the edge list's polygons.
pub(crate) mod packed {
    /// Writes face `f`'s run: in place when the length is the same (O(k)), else by shifting
    /// everything after it (O(n)).
    pub(crate) fn set<T: Copy>(items: &mut Vec<T>, offsets: &mut [u32], f: usize, run: &[T]) {
        let (start, end) = (offsets[f] as usize, offsets[f + 1] as usize);
        if end - start == run.len() {
            items[start..end].copy_from_slice(run);
            return;
        }
        items.splice(start..end, run.iter().copied());
        let shift = run.len() as i64 - (end - start) as i64;
        for o in &mut offsets[f + 1..] {
            *o = (*o as i64 + shift) as u32;
        }
    }

    /// Appends a face's run; returns its face index.
    pub(crate) fn push<T: Copy>(items: &mut Vec<T>, offsets: &mut Vec<u32>, run: &[T]) -> usize {
        items.extend_from_slice(run);
        offsets.push(items.len() as u32);
        offsets.len() - 2
    }

    /// Removes face `f`'s run: the last face's run moves into it (O(k) for equal lengths).
    pub(crate) fn remove<T: Copy>(items: &mut Vec<T>, offsets: &mut Vec<u32>, f: usize) {
        let last = offsets.len() - 2;
        if f != last {
            let run: Vec<T> = items[offsets[last] as usize..offsets[last + 1] as usize].to_vec();
            set(items, offsets, f, &run);
        }
        let start = offsets[last] as usize;
        items.truncate(start);
        offsets.pop();
    }
}

/// Implements [`MeshEdit`] for a [`FaceRewrite`] structure with every operation of this
/// module; `$cost` is its `edit_cost` and the optional last argument its `STABLE_EDGE_IDS`.
macro_rules! mesh_edit_by_rewrite {
    ($ty:ty, $cost:expr $(, $stable:expr)?) => {
        impl $crate::core::edit::MeshEdit for $ty {
            const DELETION: $crate::core::edit::Deletion = $crate::core::edit::Deletion::LastMoves;
            $(const STABLE_EDGE_IDS: bool = $stable;)?
            const OFFERS: $crate::core::edit::Offers<Self> = $crate::core::edit::Offers {
                add_vertex: Some($crate::core::rewrite::FaceRewrite::push_vertex),
                add_face: Some($crate::core::rewrite::add_face),
                delete_face: Some($crate::core::rewrite::delete_face),
                delete_vertex: Some($crate::core::rewrite::delete_vertex),
                flip_edge: Some($crate::core::rewrite::flip_edge),
                split_edge: Some($crate::core::rewrite::split_edge),
                split_face: Some($crate::core::rewrite::split_face),
                collapse_edge: Some($crate::core::rewrite::collapse_edge),
                split_vertex: Some($crate::core::rewrite::split_vertex),
                weld_vertices: Some($crate::core::rewrite::weld_vertices),
                insert_edge: Some($crate::core::rewrite::insert_edge),
                delete_edge: Some($crate::core::rewrite::delete_edge),
                rebuilds: true,
            };
            fn edit_cost(op: $crate::core::edit::EditOp) -> $crate::core::topology::Cost {
                ($cost)(op)
            }
            fn set_position(&mut self, v: $crate::core::ids::VertexId, p: glam::DVec3) -> $crate::core::error::Result<()> {
                $crate::core::rewrite::set_position(self, v, p)
            }
            fn is_deleted_vertex(&self, v: $crate::core::ids::VertexId) -> bool {
                $crate::core::rewrite::FaceRewrite::vertex_deleted(self, v)
            }
            fn is_deleted_face(&self, _f: $crate::core::ids::FaceId) -> bool {
                false
            }
            fn garbage_collection(&mut self) {
                $crate::core::rewrite::FaceRewrite::collect_vertices(self)
            }
            fn reserve(&mut self, vertices: usize, edges: usize, faces: usize) {
                $crate::core::rewrite::FaceRewrite::reserve_room(self, vertices, edges, faces)
            }
        }
    };
}
pub(crate) use mesh_edit_by_rewrite;
