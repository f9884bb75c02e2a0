//! The regular grid's geometry: an origin and the cell lengths, nothing per vertex.

use super::{Grid, GridGeometry, GridShape};
use crate::core::ids::VertexId;
use glam::DVec3;
use std::fmt::Write;

/// The lecture's regular structure: implicit topology and geometry; see the module docs.
pub type RegularGrid = Grid<Implicit>;

/// The regular grid's geometry: an origin and the cell lengths, nothing per vertex.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Implicit {
    /// Position of vertex 0.
    origin: DVec3,
    /// Cell length along x.
    dx: f64,
    /// Cell length along y.
    dy: f64,
}

impl Implicit {
    #[inline]
    fn at(&self, i: u32, j: u32) -> DVec3 {
        self.origin + DVec3::new(i as f64 * self.dx, j as f64 * self.dy, 0.0)
    }
}

impl GridGeometry for Implicit {
    const NAME: &'static str = "regular-grid";

    /// The cell sizes are measured over the whole grid (`(x of the last column − x of the
    /// first) / nx`), and every vertex must lie where the formula puts it up to rounding
    /// (1e-9 of the grid's extent), since a generator's `origin + i·dx` and ours may round
    /// differently; positions are then answered by the formula.
    fn from_positions(positions: &[DVec3], shape: GridShape) -> std::result::Result<Self, String> {
        let origin = positions[0];
        let right = positions[shape.nx as usize];
        let top = positions[shape.vertex(0, shape.ny) as usize];
        let geometry = Self {
            origin,
            dx: (right.x - origin.x) / shape.nx as f64,
            dy: (top.y - origin.y) / shape.ny as f64,
        };
        geometry.validate(shape)?;
        let far = geometry.at(shape.nx, shape.ny);
        let tolerance = 1e-9 * (origin.abs().max_element() + (far - origin).abs().max_element());
        for (v, &p) in positions.iter().enumerate() {
            let (i, j) = shape.coords(v as u32);
            let expected = geometry.at(i, j);
            if (p - expected).abs().max_element() > tolerance {
                return Err(format!(
                    "vertex {v} is at {p}, but a regular grid with origin {origin} and cells \
                     {} x {} puts it at {expected} (the height field stores any positions)",
                    geometry.dx, geometry.dy
                ));
            }
        }
        Ok(geometry)
    }
    #[inline]
    fn position(&self, shape: GridShape, v: VertexId) -> DVec3 {
        let (i, j) = shape.coords(v.0);
        self.at(i, j)
    }
    fn heap_bytes(&self) -> usize {
        0
    }
    fn validate(&self, _shape: GridShape) -> std::result::Result<(), String> {
        let finite = self.origin.is_finite() && self.dx.is_finite() && self.dy.is_finite();
        if !finite || self.dx == 0.0 || self.dy == 0.0 {
            return Err(format!(
                "origin {} and cells {} x {} must be finite with non-zero cells",
                self.origin, self.dx, self.dy
            ));
        }
        Ok(())
    }
    fn describe(&self, _shape: GridShape, w: &mut dyn Write) -> std::fmt::Result {
        writeln!(
            w,
            "geometry (implicit): origin {}, cell size dx = {}, dy = {}\n\
             position of vertex (i, j) = origin + (i·dx, j·dy, 0); nothing stored per vertex",
            self.origin, self.dx, self.dy
        )
    }
}
