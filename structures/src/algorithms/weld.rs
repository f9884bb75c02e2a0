//! Welding, the lecture on polygon-mesh data structures' "weld vertices, edges, faces" and
//! "weld whole meshes" (*Ecken, Kanten, Faces … verschweißen*, *Ganze Netze verschweißen*);
//! the lecture names the operations, not a method, so what follows is the lab's choice.
//! [`weld_meshes`] appends mesh B to mesh A and merges each boundary vertex
//! of B with the boundary vertex of A at the same place (within a tolerance), where the
//! boundary curves run against each other, so that the two surfaces share the edges along
//! which they meet. Vertex welding inside one mesh is [`MeshEdit::weld_vertices`].
//! [`weld_edges`] sews two boundary edges of one mesh into one edge (the ends of a strip into
//! a ring); [`weld_faces`] removes two faces of one mesh and sews their boundaries together
//! (two facing faces become a tunnel, a handle).
//!
//! The result is built from the welded face list ([`MeshTopology::from_soup`]), O(n + m) for
//! every structure: appending B costs O(m) anyway, and a structure's own `add_face` could not
//! take B's faces one at a time in an arbitrary order (a face that meets the rest at a vertex
//! only would make it non-manifold until its neighbours come). A's vertices keep their ids,
//! B's unmatched vertices follow in their order; A's faces come first, then B's.
//!
//! [`weld_edges`] and [`weld_faces`] are rebuilds too, O(n) for every structure: the welded
//! face list is built again, the vertices welded away leave and the others keep their order
//! (ids move down past the ones that left, deleted slots are collected, as a garbage
//! collection would); a welded vertex keeps the position of the first edge's (face's) corner.
//! They are refused (op [`EditOp::WeldEdges`], [`EditOp::WeldFaces`]), nothing changed, where
//! an id names nothing, or two vertices no edge joins ([`Refusal::NoSuchElement`]), both name the same element
//! ([`Refusal::SameElement`]), an edge is not on the boundary ([`Refusal::InteriorEdge`]), the
//! faces differ in their number of corners or share a corner ([`Refusal::FaceMismatch`]), or
//! the result is not an oriented manifold (as below); and by a structure that does not offer
//! them ([`Refusal::NotImplemented`]).
//!
//! Refused with [`Error::EditRefused`] (op [`EditOp::WeldMeshes`]), nothing built:
//! - no boundary vertex of B lies within the tolerance of one of A ([`Refusal::NothingToWeld`]);
//! - a boundary edge of B lands on one of A that runs the same way: one of the two meshes
//!   would have to be turned over ([`Refusal::Orientation`]);
//! - the welded faces are not an oriented manifold (curves that touch at a vertex only, an
//!   edge that would get three faces): [`Refusal::NonManifoldVertex`] or
//!   [`Refusal::NonManifoldEdge`].

use crate::core::edit::{offered, refuse, EditOp, MeshEdit, Refusal};
use crate::core::error::{Error, Result};
use crate::core::ids::{FaceId, VertexId};
use crate::core::soup::PolygonSoup;
use crate::core::topology::MeshTopology;
use glam::DVec3;
use std::collections::{HashMap, HashSet};

fn refuse_weld<M: MeshTopology>(reason: Refusal) -> Error {
    refuse::<M>(EditOp::WeldMeshes, reason)
}

/// `M` built from the welded `soup`, or `op` refused with the reason the build gives.
fn rebuilt<M: MeshEdit>(op: EditOp, soup: &PolygonSoup) -> Result<M> {
    M::from_soup(soup).map_err(|e| match e {
        Error::NonManifoldEdge { .. } => refuse::<M>(op, Refusal::NonManifoldEdge),
        Error::InconsistentOrientation { .. } => refuse::<M>(op, Refusal::Orientation),
        Error::NonManifoldVertex { .. } => refuse::<M>(op, Refusal::NonManifoldVertex),
        Error::RepeatedVertex { .. } => refuse::<M>(op, Refusal::BadFace),
        other => other,
    })
}

/// `m` with its faces `faces` (vertex ids of `m`) and vertex `v` renamed `rename[v]` where
/// given: the vertices renamed and the deleted ones leave, the rest keep their order.
fn rebuilt_renamed<M: MeshEdit>(
    op: EditOp,
    m: &M,
    faces: Vec<Vec<u32>>,
    rename: &HashMap<u32, u32>,
) -> Result<M> {
    let mut id = vec![u32::MAX; m.num_vertices()];
    let mut positions = Vec::with_capacity(m.num_vertices());
    for v in (0..m.num_vertices()).map(VertexId::new) {
        if !m.is_deleted_vertex(v) && !rename.contains_key(&v.0) {
            id[v.index()] = positions.len() as u32;
            positions.push(m.position(v));
        }
    }
    let faces: Vec<Vec<u32>> = faces
        .into_iter()
        .map(|f| {
            f.into_iter()
                .map(|v| id[*rename.get(&v).unwrap_or(&v) as usize])
                .collect()
        })
        .collect();
    rebuilt(op, &PolygonSoup::from_polygons(positions, &faces))
}

/// Sews boundary edge `g` of `m` onto boundary edge `e`, each named by its two ends (edge ids
/// are each structure's own): with `e` run a → b and `g` run c → d by their faces, c becomes b
/// and d becomes a, so that the two faces run the welded edge in opposite directions (see the
/// module docs for the ids and the refusals). Two edges that share an end are zipped from it;
/// the ends of a strip, welded, make a ring.
pub fn weld_edges<M: MeshEdit>(m: &M, e: [VertexId; 2], g: [VertexId; 2]) -> Result<M> {
    let op = EditOp::WeldEdges;
    offered::<M>(op)?;
    let live = |v: VertexId| v.index() < m.num_vertices() && !m.is_deleted_vertex(v);
    let joined = |[a, b]: [VertexId; 2]| {
        let mut found = false;
        if live(a) && live(b) {
            m.vertex_vertices(a, |w| found |= w == b);
        }
        found
    };
    if !joined(e) || !joined(g) {
        return Err(refuse::<M>(op, Refusal::NoSuchElement));
    }
    let unordered = |[a, b]: [VertexId; 2]| (a.0.min(b.0), a.0.max(b.0));
    if unordered(e) == unordered(g) {
        return Err(refuse::<M>(op, Refusal::SameElement));
    }
    let faces = faces_of(m);
    let sides = boundary_sides(&faces);
    let side_of = |e: [VertexId; 2]| {
        sides
            .iter()
            .copied()
            .find(|&(p, q)| (p.min(q), p.max(q)) == unordered(e))
            .ok_or_else(|| refuse::<M>(op, Refusal::InteriorEdge))
    };
    let ((a, b), (c, d)) = (side_of(e)?, side_of(g)?);
    let rename: HashMap<u32, u32> = [(c, b), (d, a)]
        .into_iter()
        .filter(|(from, to)| from != to)
        .collect();
    rebuilt_renamed(op, m, faces, &rename)
}

/// Removes faces `f` and `g` of `m` and sews their boundaries together: corner i of `f`
/// meets corner r − i of `g` (counter-clockwise, mod k: facing faces run opposite ways), with
/// r the turn that brings the paired corners closest (the least sum of squared distances; the
/// first such). See the module docs for the ids and the refusals.
pub fn weld_faces<M: MeshEdit>(m: &M, f: FaceId, g: FaceId) -> Result<M> {
    let op = EditOp::WeldFaces;
    offered::<M>(op)?;
    let live = |f: FaceId| f.index() < m.num_faces() && !m.is_deleted_face(f);
    if !live(f) || !live(g) {
        return Err(refuse::<M>(op, Refusal::NoSuchElement));
    }
    if f == g {
        return Err(refuse::<M>(op, Refusal::SameElement));
    }
    let corners = |f: FaceId| {
        let mut c = Vec::new();
        m.face_vertices(f, |v| c.push(v.0));
        c
    };
    let (cf, cg) = (corners(f), corners(g));
    let k = cf.len();
    if cg.len() != k || cf.iter().any(|v| cg.contains(v)) {
        return Err(refuse::<M>(op, Refusal::FaceMismatch));
    }
    let at = |v: u32| m.position(VertexId(v));
    let paired = |r: usize, i: usize| cg[(r + k - i) % k];
    let spread = |r: usize| -> f64 {
        (0..k)
            .map(|i| at(cf[i]).distance_squared(at(paired(r, i))))
            .sum()
    };
    let r = (0..k)
        .min_by(|&x, &y| spread(x).total_cmp(&spread(y)))
        .unwrap_or(0);
    let rename: HashMap<u32, u32> = (0..k).map(|i| (paired(r, i), cf[i])).collect();
    let faces: Vec<Vec<u32>> = (0..m.num_faces())
        .map(FaceId::new)
        .filter(|&h| h != f && h != g && !m.is_deleted_face(h))
        .map(corners)
        .collect();
    rebuilt_renamed(op, m, faces, &rename)
}

/// The live faces of `m` as vertex lists (deleted faces skipped; vertex ids as the structure's).
fn faces_of<M: MeshEdit>(m: &M) -> Vec<Vec<u32>> {
    (0..m.num_faces())
        .map(FaceId::new)
        .filter(|&f| !m.is_deleted_face(f))
        .map(|f| {
            let mut face = Vec::with_capacity(4);
            m.face_vertices(f, |v| face.push(v.0));
            face
        })
        .collect()
}

/// The directed sides of `faces` that no face runs the other way: the boundary, each side as
/// its face runs it.
fn boundary_sides(faces: &[Vec<u32>]) -> Vec<(u32, u32)> {
    let sides = |f: &Vec<u32>| {
        let k = f.len();
        (0..k)
            .map(move |i| (f[i], f[(i + 1) % k]))
            .collect::<Vec<_>>()
    };
    let all: HashSet<(u32, u32)> = faces.iter().flat_map(sides).collect();
    faces
        .iter()
        .flat_map(sides)
        .filter(|&(a, b)| !all.contains(&(b, a)))
        .collect()
}

/// Finds, for a point, the nearest of a set of points within `tolerance`: a grid of cells of
/// that size (exact positions when the tolerance is 0).
struct Nearby {
    cell: f64,
    cells: HashMap<[i64; 3], Vec<(DVec3, u32)>>,
}

impl Nearby {
    fn new(tolerance: f64) -> Self {
        Self {
            cell: tolerance,
            cells: HashMap::new(),
        }
    }
    fn key(&self, p: DVec3) -> [i64; 3] {
        if self.cell > 0.0 {
            (p / self.cell).floor().as_i64vec3().to_array()
        } else {
            [
                p.x.to_bits() as i64,
                p.y.to_bits() as i64,
                p.z.to_bits() as i64,
            ]
        }
    }
    fn insert(&mut self, p: DVec3, id: u32) {
        let k = self.key(p);
        self.cells.entry(k).or_default().push((p, id));
    }
    fn nearest(&self, p: DVec3) -> Option<u32> {
        let k = self.key(p);
        let reach = if self.cell > 0.0 { 1 } else { 0 };
        let mut best: Option<(f64, u32)> = None;
        for dx in -reach..=reach {
            for dy in -reach..=reach {
                for dz in -reach..=reach {
                    let Some(cell) = self.cells.get(&[k[0] + dx, k[1] + dy, k[2] + dz]) else {
                        continue;
                    };
                    for &(q, id) in cell {
                        let d = p.distance(q);
                        if d <= self.cell && best.is_none_or(|(bd, _)| d < bd) {
                            best = Some((d, id));
                        }
                    }
                }
            }
        }
        best.map(|(_, id)| id)
    }
}

/// Welds mesh `b` to mesh `a` along their coinciding boundary curves (see the module docs);
/// `tolerance` is the largest distance at which two boundary vertices are the same (≥ 0).
pub fn weld_meshes<M: MeshEdit>(a: &M, b: &M, tolerance: f64) -> Result<M> {
    if !(tolerance >= 0.0 && tolerance.is_finite()) {
        return Err(Error::Unsupported(format!(
            "weld tolerance must be a finite distance ≥ 0, not {tolerance}"
        )));
    }
    let (fa, fb) = (faces_of(a), faces_of(b));
    let (ba, bb) = (boundary_sides(&fa), boundary_sides(&fb));
    let mut near = Nearby::new(tolerance);
    let mut on_boundary: Vec<u32> = ba.iter().map(|&(x, _)| x).collect();
    on_boundary.sort_unstable();
    on_boundary.dedup();
    for &v in &on_boundary {
        near.insert(a.position(VertexId(v)), v);
    }
    // B's boundary vertices → A's.
    let mut matched: HashMap<u32, u32> = HashMap::new();
    for &(v, _) in &bb {
        if let Some(w) = near.nearest(b.position(VertexId(v))) {
            matched.insert(v, w);
        }
    }
    if matched.is_empty() {
        return Err(refuse_weld::<M>(Refusal::NothingToWeld));
    }
    // Where a boundary side of B lands on one of A, they must run against each other.
    let a_sides: HashSet<(u32, u32)> = ba.iter().copied().collect();
    for &(u, v) in &bb {
        if let (Some(&x), Some(&y)) = (matched.get(&u), matched.get(&v)) {
            if a_sides.contains(&(x, y)) {
                return Err(refuse_weld::<M>(Refusal::Orientation));
            }
        }
    }
    // The welded face list: A's vertices, then B's unmatched ones.
    let mut positions: Vec<DVec3> = (0..a.num_vertices())
        .map(|v| a.position(VertexId::new(v)))
        .collect();
    let mut map = vec![u32::MAX; b.num_vertices()];
    for (v, slot) in map.iter_mut().enumerate() {
        *slot = match matched.get(&(v as u32)) {
            Some(&w) => w,
            None => {
                positions.push(b.position(VertexId::new(v)));
                (positions.len() - 1) as u32
            }
        };
    }
    let mut faces = fa;
    faces.extend(
        fb.into_iter()
            .map(|f| f.into_iter().map(|v| map[v as usize]).collect()),
    );
    let soup = PolygonSoup::from_polygons(positions, &faces);
    rebuilt(EditOp::WeldMeshes, &soup)
}
