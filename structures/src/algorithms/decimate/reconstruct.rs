//! Reconstruction: the collapses of a [`decimate`](super::decimate) replayed backwards with
//! [`MeshEdit::split_vertex`], each the exact inverse of its collapse (the split puts the
//! removed vertex back at its recorded position with the two triangles (`from`, `to`, `left`)
//! and (`to`, `from`, `right`), and moves back the fan of `from` between `left` and `right`).
//!
//! The id mapping: a structure that appends (every [`MeshEdit`] does) gives each re-created
//! vertex a new id, `num_vertices()` before its split; [`Reconstruction::original`] maps every
//! vertex id of the rebuilt mesh to the id the vertex had before the decimation. Faces are
//! compared as a set (each rotated to start at its smallest vertex), since face ids are not
//! recorded.

use super::Collapses;
use crate::core::edit::MeshEdit;
use crate::core::error::Result;
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
    let n = collapses.len();
    m.reserve(n, 3 * n, 2 * n);
    let mut original: Vec<u32> = (0..m.num_vertices() as u32).collect();
    // A vertex removed by a later collapse was re-created (with a new id) before an earlier
    // collapse that names it is undone: `current` follows each original id to its live one.
    let mut current: Vec<u32> = original.clone();
    for i in (0..n).rev() {
        let id = |v: u32| VertexId(current[v as usize]);
        let new = m.split_vertex(
            id(collapses.to[i]),
            collapses.position[i],
            id(collapses.left[i]),
            id(collapses.right[i]),
        )?;
        debug_assert_eq!(new.index(), original.len(), "split vertices are appended");
        original.push(collapses.from[i]);
        current[collapses.from[i] as usize] = new.0;
    }
    for (v, o) in original.iter_mut().enumerate() {
        if m.is_deleted_vertex(VertexId::new(v)) {
            *o = u32::MAX;
        }
    }
    Ok(Reconstruction { original })
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
