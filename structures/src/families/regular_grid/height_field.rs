//! # Height field
//!
//! The *gemischte Struktur* (mixed structure) of the lecture on polygon-mesh data structures: the
//! regular grid's implicit topology (every operator is the same arithmetic, shared through
//! [`Grid`]) with explicit geometry, one stored position per vertex, "e.g. the simulation of a
//! flag". It accepts the grids of [`crate::meshes::grid`] with any positions: heights,
//! perturbations, a waving flag.
//!
//! | stores | bytes |
//! |---|---|
//! | shape: `nx`, `ny` cells, quads or triangles | 12 |
//! | `positions[v]`: x, y, z | 24 per vertex |
//!
//! Costs: as [`crate::RegularGrid`] (all O(1), boundary curves O(∂n1)); only `position` reads
//! memory. The lecture notes what it cannot do: no adaptive refinement, since the topology is
//! fixed by the counts.

use super::{Grid, GridGeometry, GridShape};
use crate::core::ids::VertexId;
use glam::DVec3;
use std::fmt::Write;

/// The height field's geometry: every vertex position, stored.
#[derive(Clone, Debug, PartialEq)]
pub struct Positions {
    /// `positions[v]`: the coordinates of vertex v.
    positions: Vec<DVec3>,
}

/// The lecture's mixed structure: implicit grid topology, explicit positions.
pub type HeightField = Grid<Positions>;

impl GridGeometry for Positions {
    const NAME: &'static str = "height-field";

    fn from_positions(positions: &[DVec3], _shape: GridShape) -> Result<Self, String> {
        Ok(Self {
            positions: positions.to_vec(),
        })
    }
    #[inline]
    fn position(&self, _shape: GridShape, v: VertexId) -> DVec3 {
        self.positions[v.index()]
    }
    fn heap_bytes(&self) -> usize {
        self.positions.capacity() * std::mem::size_of::<DVec3>()
    }
    fn validate(&self, shape: GridShape) -> Result<(), String> {
        if self.positions.len() != shape.num_vertices() {
            return Err(format!(
                "{} positions for the {} vertices of a {}x{} grid",
                self.positions.len(),
                shape.num_vertices(),
                shape.nx,
                shape.ny
            ));
        }
        match self.positions.iter().position(|p| !p.is_finite()) {
            Some(v) => Err(format!("vertex {v} has a non-finite position")),
            None => Ok(()),
        }
    }
    fn describe(&self, _shape: GridShape, w: &mut dyn Write) -> std::fmt::Result {
        writeln!(w, "geometry (explicit): one stored position per vertex")?;
        for (v, p) in self.positions.iter().enumerate() {
            writeln!(w, "  v{v}: ({:.3}, {:.3}, {:.3})", p.x, p.y, p.z)?;
        }
        Ok(())
    }
}
