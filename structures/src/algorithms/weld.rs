//! Welding whole meshes, the lecture on polygon-mesh data structures' "weld meshes" (*Netze
//! verschweißen*): [`weld_meshes`] appends mesh B to mesh A and merges each boundary vertex
//! of B with the boundary vertex of A at the same place (within a tolerance), where the
//! boundary curves run against each other, so that the two surfaces share the edges along
//! which they meet. Vertex welding inside one mesh is [`MeshEdit::weld_vertices`].
//!
//! The result is built from the welded face list ([`MeshTopology::from_soup`]), O(n + m) for
//! every structure: appending B costs O(m) anyway, and a structure's own `add_face` could not
//! take B's faces one at a time in an arbitrary order (a face that meets the rest at a vertex
//! only would make it non-manifold until its neighbours come). A's vertices keep their ids,
//! B's unmatched vertices follow in their order; A's faces come first, then B's.
//!
//! Refused with [`Error::EditRefused`] (op [`EditOp::WeldMeshes`]), nothing built:
//! - no boundary vertex of B lies within the tolerance of one of A ([`Refusal::NothingToWeld`]);
//! - a boundary edge of B lands on one of A that runs the same way: one of the two meshes
//!   would have to be turned over ([`Refusal::Orientation`]);
//! - the welded faces are not an oriented manifold (curves that touch at a vertex only, an
//!   edge that would get three faces): [`Refusal::NonManifoldVertex`] or
//!   [`Refusal::NonManifoldEdge`].

use crate::core::edit::{EditOp, MeshEdit, Refusal};
use crate::core::error::{Error, Result};
use crate::core::ids::{FaceId, VertexId};
use crate::core::soup::PolygonSoup;
use crate::core::topology::MeshTopology;
use glam::DVec3;
use std::collections::{HashMap, HashSet};

fn refuse<M: MeshTopology>(reason: Refusal) -> Error {
    Error::EditRefused {
        structure: M::NAME,
        op: EditOp::WeldMeshes,
        reason,
    }
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
        return Err(refuse::<M>(Refusal::NothingToWeld));
    }
    // Where a boundary side of B lands on one of A, they must run against each other.
    let a_sides: HashSet<(u32, u32)> = ba.iter().copied().collect();
    for &(u, v) in &bb {
        if let (Some(&x), Some(&y)) = (matched.get(&u), matched.get(&v)) {
            if a_sides.contains(&(x, y)) {
                return Err(refuse::<M>(Refusal::Orientation));
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
    M::from_soup(&soup).map_err(|e| match e {
        Error::NonManifoldEdge { .. } => refuse::<M>(Refusal::NonManifoldEdge),
        Error::InconsistentOrientation { .. } => refuse::<M>(Refusal::Orientation),
        Error::NonManifoldVertex { .. } => refuse::<M>(Refusal::NonManifoldVertex),
        Error::RepeatedVertex { .. } => refuse::<M>(Refusal::BadFace),
        other => other,
    })
}
