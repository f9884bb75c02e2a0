//! # Regular grid (and, beside it, the height field)
//!
//! The *regelmäßige Struktur* of the lecture on polygon-mesh data structures: a rectangular,
//! uniform grid whose topology is given by the number of points in x and y, and whose geometry by
//! the origin and the cell lengths. Nothing is stored per element: every operator is arithmetic on
//! the vertex number `v = j·(nx+1) + i`. It represents exactly the grids of
//! [`crate::meshes::grid`] (quads, or each cell split into the triangles `(a, b, c)`, `(a,
//! c, d)`); anything else is refused with [`crate::Error::NotAGrid`] naming the reason. Positions
//! are answered by the formula `origin + (i·dx, j·dy, 0)`; an input is accepted when each vertex
//! lies there up to rounding (1e-9 of the grid's extent), so a generator's `origin + i·dx` need not
//! round as ours.
//!
//! The lecture's *gemischte Struktur* (implicit topology, explicit geometry, "e.g. the
//! simulation of a flag") is [`HeightField`]: the same arithmetic topology with every vertex
//! position stored, so it accepts the same grids with any heights or perturbed positions. The
//! two share everything but the geometry ([`Grid`] over a [`GridGeometry`]).
//!
//! | stores | regular grid | height field |
//! |---|---|---|
//! | shape: `nx`, `ny` cells, quads or triangles | 12 bytes | 12 bytes |
//! | origin (x, y, z), cell size (dx, dy) | 40 bytes | — |
//! | `positions[v]`: x, y, z | — | 24 per vertex |
//! | per face, per edge | nothing | nothing |
//!
//! Numbering (cells row by row, as `meshes::grid` makes them):
//! - vertex `(i, j)`: `j·(nx+1) + i`; cell `(i, j)`: `j·nx + i`, corners `a = (i, j)`,
//!   `b = (i+1, j)`, `c = (i+1, j+1)`, `d = (i, j+1)`;
//! - faces: quads: face = cell; triangles: `2·cell` is `(a, b, c)`, `2·cell + 1` is `(a, c, d)`;
//! - edges: horizontal `(i, j)-(i+1, j)` is `j·nx + i`; vertical `(i, j)-(i, j+1)` is
//!   `nx·(ny+1) + j·(nx+1) + i`; diagonal `a-c` of cell `(i, j)` is
//!   `nx·(ny+1) + (nx+1)·ny + j·nx + i`.
//!
//! | operator | how | cost |
//! |---|---|---|
//! | R00, R01, R02 | the at most 6 edges / 6 faces around `(i, j)`, clipped at the border | O(1) |
//! | R10, R12, boundary vertex, boundary edge | formulas on `(i, j)` | O(1) |
//! | R11, R20, R21, R22, successor, predecessor | the cell's 3 or 4 corners and edges | O(1) |
//! | boundary curves | walk the border: one curve | O(∂n1) |
//!
//! No grid has non-manifold vertices, so the `bowtie` is refused as not a grid; the grids'
//! faces are quads or triangles only, by definition.

mod height_field;
mod implicit;
mod shape;
#[cfg(test)]
mod tests;
mod topology;

pub use height_field::{HeightField, Positions};
pub use implicit::{Implicit, RegularGrid};
pub use shape::GridShape;

/// Why a regular grid and a height field cannot refine locally (the lecture on polygon-mesh
/// data structures: refinement should be possible "lokal und adaptiv", and the structures
/// whose topology is implicit do not allow it), in the words `topolab refine --max-edge` and
/// the report's local-refinement table both give.
pub const NO_LOCAL_REFINEMENT: &str = "a regular grid cannot refine locally: its vertices are \
    implicit in (i, j) (the lecture's regular and mixed structures, topology given by the \
    numbers of points), so splitting an edge would add a vertex that is no grid point and break \
    the grid; only uniform refinement, to a finer grid, keeps it a grid";

use crate::core::ids::VertexId;
use glam::DVec3;
use std::fmt::Write;

/// Where a grid's vertices are: computed ([`Implicit`]) or stored ([`Positions`]).
pub trait GridGeometry: Sized + 'static {
    /// The structure's name.
    const NAME: &'static str;
    /// The geometry of a grid of `shape` with these positions, or why it cannot hold them.
    fn from_positions(positions: &[DVec3], shape: GridShape) -> std::result::Result<Self, String>;
    /// The position of vertex `v`.
    fn position(&self, shape: GridShape, v: VertexId) -> DVec3;
    /// Bytes stored.
    fn heap_bytes(&self) -> usize;
    /// Checks the geometry's invariants.
    fn validate(&self, shape: GridShape) -> std::result::Result<(), String>;
    /// For `explain`: what is stored.
    fn describe(&self, shape: GridShape, w: &mut dyn Write) -> std::fmt::Result;
}

/// A grid mesh whose topology is arithmetic; `G` says where its vertices are.
#[derive(Clone, Debug)]
pub struct Grid<G> {
    /// The numbers of cells and the kind of faces.
    shape: GridShape,
    /// Where the vertices are.
    geometry: G,
}

impl<G> Grid<G> {
    /// The numbers of cells and the kind of faces.
    pub fn shape(&self) -> GridShape {
        self.shape
    }
}

impl<G: GridGeometry> Grid<G> {
    /// Every face's corners and edges agree with the edges' ends and faces (the formulas are
    /// consistent), O(n).
    fn validate_topology(&self) -> std::result::Result<(), String> {
        let s = self.shape;
        if s.nx == 0 || s.ny == 0 {
            return Err(format!("{}x{} cells: a grid has at least one", s.nx, s.ny));
        }
        if s.num_edges() >= u32::MAX as usize {
            return Err(format!("{} edges do not fit u32 ids", s.num_edges()));
        }
        for f in 0..s.num_faces() as u32 {
            let (corners, edges) = (s.face_corners(f), s.face_edges(f));
            let (corners, edges) = (corners.as_slice(), edges.as_slice());
            for (k, &e) in edges.iter().enumerate() {
                let (a, b) = (corners[k], corners[(k + 1) % corners.len()]);
                let mut ends = s.edge_ends(e);
                ends.sort_unstable();
                if ends != [a.min(b), a.max(b)] {
                    return Err(format!("edge e{e} of f{f} does not join v{a} and v{b}"));
                }
                if !s.edge_faces(e).contains(&Some(f)) {
                    return Err(format!("edge e{e} does not list its face f{f}"));
                }
            }
        }
        Ok(())
    }
}
