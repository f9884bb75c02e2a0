//! Reconstruction: the collapses of a [`decimate`](super::decimate) replayed backwards with
//! [`MeshEdit::split_vertex`], each the exact inverse of its collapse (the split puts the
//! removed vertex back at its recorded position with the two triangles (`from`, `to`, `left`)
//! and (`to`, `from`, `right`), and moves back the fan of `from` between `left` and `right`).
//!
//! The id mapping: a structure that appends (every [`MeshEdit`] does) gives each re-created
//! vertex a new id, `num_vertices()` before its split; [`Reconstruction::original`] maps every
//! vertex id of the rebuilt mesh to the id the vertex had before the decimation. Faces are
//! compared as a set (each rotated to start at its smallest vertex), since face ids are not
//! recorded. [`reconstruct_from`] starts from a mesh numbered otherwise (the coarse mesh read
//! from a file) and may stop at any number of collapses; [`live_soup`] writes a state in the
//! canonical form the level-of-detail files share.

use super::Collapses;
use crate::core::edit::MeshEdit;
use crate::core::error::{Error, Result};
use crate::core::ids::{FaceId, VertexId};
use crate::core::soup::PolygonSoup;

/// What [`reconstruct`] rebuilt.
#[derive(Clone, Debug, Default)]
pub struct Reconstruction {
    /// Per vertex id of the rebuilt mesh, the id it had before the decimation (the identity
    /// for vertices the decimation kept; [`u32::MAX`] for deleted slots).
    pub original: Vec<u32>,
}

/// Undoes `collapses` on `m` (the decimated mesh, not garbage-collected) by vertex splits, the
/// last collapse first.
pub fn reconstruct<M: MeshEdit>(m: &mut M, collapses: &Collapses) -> Result<Reconstruction> {
    let identity = (0..m.num_vertices() as u32).collect();
    reconstruct_from(m, collapses, 0, identity)
}

/// Undoes the collapses of `collapses` after the first `keep` on `m`, the last first, and
/// says which original vertex each vertex of the result is: `m` is the mesh after all of
/// them, numbered its own way, and `live_of[o]` is the id in `m` of original vertex `o`
/// ([`u32::MAX`] for a vertex a collapse removed). [`reconstruct`] is this with `keep` 0 on
/// the decimated mesh itself (its ids are the original ones); `topolab reconstruct` starts
/// from the coarse mesh read from a file, whose vertices are the survivors in increasing
/// original id. The result is the mesh after the first `keep` collapses.
pub fn reconstruct_from<M: MeshEdit>(
    m: &mut M,
    collapses: &Collapses,
    keep: usize,
    live_of: Vec<u32>,
) -> Result<Reconstruction> {
    let n = collapses.len();
    let keep = keep.min(n);
    let splits = n - keep;
    m.reserve(splits, 3 * splits, 2 * splits);
    let mut original = vec![u32::MAX; m.num_vertices()];
    for (o, &v) in live_of.iter().enumerate() {
        if let Some(slot) = original.get_mut(v as usize) {
            *slot = o as u32;
        }
    }
    // A vertex removed by a later collapse was re-created (with a new id) before an earlier
    // collapse that names it is undone: `current` follows each original id to its live one.
    let mut current = live_of;
    for i in (keep..n).rev() {
        let id = |v: u32| -> Result<VertexId> {
            match current.get(v as usize) {
                Some(&live) if live != u32::MAX => Ok(VertexId(live)),
                _ => Err(Error::InvalidParameter {
                    parameter: "collapse record",
                    value: format!("collapse {i} names vertex {v}"),
                    expected: "a record whose collapses name vertices present when undone",
                }),
            }
        };
        let new = m.split_vertex(
            id(collapses.to[i])?,
            collapses.position[i],
            id(collapses.left[i])?,
            id(collapses.right[i])?,
        )?;
        debug_assert_eq!(new.index(), original.len(), "split vertices are appended");
        original.push(collapses.from[i]);
        let from = collapses.from[i] as usize;
        if from >= current.len() {
            current.resize(from + 1, u32::MAX);
        }
        current[from] = new.0;
    }
    for (v, o) in original.iter_mut().enumerate() {
        if m.is_deleted_vertex(VertexId::new(v)) {
            *o = u32::MAX;
        }
    }
    Ok(Reconstruction { original })
}

/// The live mesh of `m` as a soup in a canonical form, numbered through `original` (per vertex
/// id of `m`, its original id; [`u32::MAX`] for none): the live vertices in increasing
/// original id, numbered from 0 in that order, and the live faces each rotated to start at
/// its smallest vertex, sorted. Two meshes with the same vertices (by original id, at the
/// same positions) and the same oriented faces give the same soup whatever structure holds
/// them and in whatever order it keeps its faces: what `topolab decimate --levels` writes for
/// each level and `topolab reconstruct` for the state it rebuilds, so that their files compare
/// byte for byte.
pub fn live_soup<M: MeshEdit>(m: &M, original: &[u32]) -> PolygonSoup {
    let mut live: Vec<(u32, u32)> = (0..m.num_vertices())
        .filter(|&v| !m.is_deleted_vertex(VertexId::new(v)) && original[v] != u32::MAX)
        .map(|v| (original[v], v as u32))
        .collect();
    live.sort_unstable();
    let mut number = vec![u32::MAX; m.num_vertices()];
    for (k, &(_, v)) in live.iter().enumerate() {
        number[v as usize] = k as u32;
    }
    let positions = live.iter().map(|&(_, v)| m.position(VertexId(v))).collect();
    let mut faces = Vec::new();
    let mut face = Vec::new();
    for f in 0..m.num_faces() {
        let f = FaceId::new(f);
        if m.is_deleted_face(f) {
            continue;
        }
        face.clear();
        m.face_vertices(f, |v| face.push(number[v.index()]));
        faces.push(canonical(&face));
    }
    faces.sort_unstable();
    PolygonSoup::from_polygons(positions, &faces)
}

/// `soup` in the canonical form of [`live_soup`]: its vertices as they are, its faces each
/// rotated to start at its smallest vertex, sorted. What [`live_soup`] gives for a mesh built
/// from `soup` before any edit.
pub fn canonical_input(soup: &PolygonSoup) -> PolygonSoup {
    let mut faces: Vec<Vec<u32>> = soup.faces().map(canonical).collect();
    faces.sort_unstable();
    PolygonSoup::from_polygons(soup.positions.clone(), &faces)
}

/// Where a rebuilt mesh differs from the original.
#[derive(Clone, Debug, PartialEq)]
pub enum Difference {
    /// Different numbers of live vertices or faces.
    Counts {
        /// (vertices, faces) of the original.
        original: (usize, usize),
        /// (vertices, faces) rebuilt.
        rebuilt: (usize, usize),
    },
    /// A vertex came back at another position.
    Position {
        /// Its original id.
        vertex: u32,
    },
    /// The face lists differ (mapped to the original ids): the first face of the original not
    /// rebuilt, canonical.
    Face(Vec<u32>),
}

impl std::fmt::Display for Difference {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Difference::Counts { original, rebuilt } => write!(
                f,
                "{} vertices and {} faces rebuilt, {} and {} before",
                rebuilt.0, rebuilt.1, original.0, original.1
            ),
            Difference::Position { vertex } => {
                write!(f, "vertex {vertex} came back at another position")
            }
            Difference::Face(face) => write!(f, "face {face:?} did not come back"),
        }
    }
}

/// `f` rotated to start at its smallest vertex.
fn canonical(f: &[u32]) -> Vec<u32> {
    let i = (0..f.len()).min_by_key(|&i| f[i]).unwrap_or(0);
    f[i..].iter().chain(&f[..i]).copied().collect()
}

/// Checks that `m`, rebuilt by [`reconstruct`], is `original` exactly: the same live
/// vertices at bit-identical positions and the same oriented faces, through the id mapping.
pub fn same_mesh<M: MeshEdit>(
    original: &PolygonSoup,
    m: &M,
    rebuilt: &Reconstruction,
) -> std::result::Result<(), Difference> {
    let mut faces = Vec::new();
    let mut face = Vec::new();
    for f in 0..m.num_faces() {
        let f = FaceId::new(f);
        if m.is_deleted_face(f) {
            continue;
        }
        face.clear();
        m.face_vertices(f, |v| face.push(rebuilt.original[v.index()]));
        faces.push(canonical(&face));
    }
    let live = rebuilt.original.iter().filter(|&&o| o != u32::MAX).count();
    if live != original.num_vertices() || faces.len() != original.num_faces() {
        return Err(Difference::Counts {
            original: (original.num_vertices(), original.num_faces()),
            rebuilt: (live, faces.len()),
        });
    }
    for (v, &o) in rebuilt.original.iter().enumerate() {
        if o != u32::MAX
            && (o as usize >= original.num_vertices()
                || m.position(VertexId::new(v)) != original.positions[o as usize])
        {
            return Err(Difference::Position { vertex: o });
        }
    }
    faces.sort_unstable();
    let mut before: Vec<Vec<u32>> = original.faces().map(canonical).collect();
    before.sort_unstable();
    match before.iter().zip(&faces).find(|(a, b)| a != b) {
        Some((a, _)) => Err(Difference::Face(a.clone())),
        None => Ok(()),
    }
}
