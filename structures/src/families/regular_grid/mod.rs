//! # Regular grid (and, beside it, the height field)
//!
//! The lecture's *regelmäßige Struktur*: a rectangular, uniform grid whose topology is given
//! by the number of points in x and y, and whose geometry by the origin and the cell lengths.
//! Nothing is stored per element: every operator is arithmetic on the vertex number
//! `v = j·(nx+1) + i`. It represents exactly the grids of [`crate::testing::meshes::grid`] (quads, or
//! each cell split into the triangles `(a, b, c)`, `(a, c, d)`); anything else is refused with
//! [`crate::Error::NotAGrid`] naming the reason. Positions are answered by the formula
//! `origin + (i·dx, j·dy, 0)`; an input is accepted when each vertex lies there up to
//! rounding (1e-9 of the grid's extent), so a generator's `origin + i·dx` need not round as ours.
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

pub use height_field::{HeightField, Positions};

use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::soup::PolygonSoup;
use crate::core::topology::{BoundaryCurves, Capabilities, Cost, MeshTopology, Operator};
use glam::DVec3;
use std::fmt::Write;

/// The topology of a grid: everything the operators compute from.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct GridShape {
    /// Cells along x.
    pub nx: u32,
    /// Cells along y.
    pub ny: u32,
    /// Each cell is two triangles `(a, b, c)`, `(a, c, d)` instead of the quad `(a, b, c, d)`.
    pub triangulated: bool,
}

/// Up to four ids (a face's corners or edges), without allocating.
#[derive(Copy, Clone, Debug)]
struct Ring {
    /// The ids; only the first `len` count.
    ids: [u32; 4],
    /// How many.
    len: usize,
}

impl Ring {
    fn new(ids: &[u32]) -> Self {
        let mut ring = Self {
            ids: [0; 4],
            len: ids.len(),
        };
        ring.ids[..ids.len()].copy_from_slice(ids);
        ring
    }
    fn as_slice(&self) -> &[u32] {
        &self.ids[..self.len]
    }
}

/// Which cell side an edge lies on; the lower triangle `(a, b, c)` has the bottom and right
/// sides, the upper `(a, c, d)` the top and left ones (both have the diagonal).
#[derive(Copy, Clone)]
enum Side {
    Bottom,
    Right,
    Top,
    Left,
}

/// An edge decoded from its id.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum EdgeKind {
    /// `(i, j)-(i+1, j)`.
    Horizontal,
    /// `(i, j)-(i, j+1)`.
    Vertical,
    /// `(i, j)-(i+1, j+1)`, in triangulated grids.
    Diagonal,
}

impl GridShape {
    /// Vertices per row.
    #[inline]
    fn width(&self) -> u32 {
        self.nx + 1
    }
    fn num_vertices(&self) -> usize {
        (self.nx as usize + 1) * (self.ny as usize + 1)
    }
    fn faces_per_cell(&self) -> u32 {
        if self.triangulated {
            2
        } else {
            1
        }
    }
    fn num_faces(&self) -> usize {
        self.nx as usize * self.ny as usize * self.faces_per_cell() as usize
    }
    fn num_horizontal(&self) -> u32 {
        self.nx * (self.ny + 1)
    }
    fn num_vertical(&self) -> u32 {
        (self.nx + 1) * self.ny
    }
    fn num_edges(&self) -> usize {
        let diagonals = if self.triangulated {
            self.nx as usize * self.ny as usize
        } else {
            0
        };
        self.num_horizontal() as usize + self.num_vertical() as usize + diagonals
    }
    #[inline]
    fn vertex(&self, i: u32, j: u32) -> u32 {
        j * self.width() + i
    }
    #[inline]
    fn coords(&self, v: u32) -> (u32, u32) {
        (v % self.width(), v / self.width())
    }
    #[inline]
    fn horizontal(&self, i: u32, j: u32) -> u32 {
        j * self.nx + i
    }
    #[inline]
    fn vertical(&self, i: u32, j: u32) -> u32 {
        self.num_horizontal() + j * self.width() + i
    }
    #[inline]
    fn diagonal(&self, i: u32, j: u32) -> u32 {
        self.num_horizontal() + self.num_vertical() + j * self.nx + i
    }
    #[inline]
    fn edge(&self, e: u32) -> (EdgeKind, u32, u32) {
        let (nh, nv) = (self.num_horizontal(), self.num_vertical());
        if e < nh {
            (EdgeKind::Horizontal, e % self.nx, e / self.nx)
        } else if e < nh + nv {
            let r = e - nh;
            (EdgeKind::Vertical, r % self.width(), r / self.width())
        } else {
            let r = e - nh - nv;
            (EdgeKind::Diagonal, r % self.nx, r / self.nx)
        }
    }
    /// The face of cell `(i, j)` that has the given side.
    #[inline]
    fn face_of(&self, i: u32, j: u32, side: Side) -> u32 {
        let cell = j * self.nx + i;
        match (self.triangulated, side) {
            (false, _) => cell,
            (true, Side::Bottom | Side::Right) => 2 * cell,
            (true, Side::Top | Side::Left) => 2 * cell + 1,
        }
    }
    /// Cell `(i, j)` of face `f`, and whether it is the upper triangle.
    #[inline]
    fn face_cell(&self, f: u32) -> (u32, u32, bool) {
        let per = self.faces_per_cell();
        let cell = f / per;
        (cell % self.nx, cell / self.nx, f % per == 1)
    }
    fn face_corners(&self, f: u32) -> Ring {
        let (i, j, upper) = self.face_cell(f);
        let a = self.vertex(i, j);
        let (b, c, d) = (a + 1, a + self.width() + 1, a + self.width());
        match (self.triangulated, upper) {
            (false, _) => Ring::new(&[a, b, c, d]),
            (true, false) => Ring::new(&[a, b, c]),
            (true, true) => Ring::new(&[a, c, d]),
        }
    }
    /// Edge `k` joins corner `k` and `k + 1` of [`GridShape::face_corners`].
    fn face_edges(&self, f: u32) -> Ring {
        let (i, j, upper) = self.face_cell(f);
        let (bottom, right) = (self.horizontal(i, j), self.vertical(i + 1, j));
        let (top, left) = (self.horizontal(i, j + 1), self.vertical(i, j));
        match (self.triangulated, upper) {
            (false, _) => Ring::new(&[bottom, right, top, left]),
            (true, false) => Ring::new(&[bottom, right, self.diagonal(i, j)]),
            (true, true) => Ring::new(&[self.diagonal(i, j), top, left]),
        }
    }
    fn edge_ends(&self, e: u32) -> [u32; 2] {
        let (kind, i, j) = self.edge(e);
        let a = self.vertex(i, j);
        match kind {
            EdgeKind::Horizontal => [a, a + 1],
            EdgeKind::Vertical => [a, a + self.width()],
            EdgeKind::Diagonal => [a, a + self.width() + 1],
        }
    }
    fn edge_faces(&self, e: u32) -> [Option<u32>; 2] {
        let (kind, i, j) = self.edge(e);
        match kind {
            EdgeKind::Horizontal => [
                (j > 0).then(|| self.face_of(i, j - 1, Side::Top)),
                (j < self.ny).then(|| self.face_of(i, j, Side::Bottom)),
            ],
            EdgeKind::Vertical => [
                (i > 0).then(|| self.face_of(i - 1, j, Side::Right)),
                (i < self.nx).then(|| self.face_of(i, j, Side::Left)),
            ],
            EdgeKind::Diagonal => [
                Some(self.face_of(i, j, Side::Bottom)),
                Some(self.face_of(i, j, Side::Top)),
            ],
        }
    }
    /// The edges around vertex `v`, each with its other end.
    #[inline]
    fn vertex_edges(&self, v: u32, mut f: impl FnMut(u32, u32)) {
        let (i, j) = self.coords(v);
        let w = self.width();
        if i > 0 {
            f(self.horizontal(i - 1, j), v - 1);
        }
        if i < self.nx {
            f(self.horizontal(i, j), v + 1);
        }
        if j > 0 {
            f(self.vertical(i, j - 1), v - w);
        }
        if j < self.ny {
            f(self.vertical(i, j), v + w);
        }
        if self.triangulated {
            if i < self.nx && j < self.ny {
                f(self.diagonal(i, j), v + w + 1);
            }
            if i > 0 && j > 0 {
                f(self.diagonal(i - 1, j - 1), v - w - 1);
            }
        }
    }
    /// The faces around vertex `v`: the faces of the (up to four) cells touching it that have
    /// `v` as a corner.
    #[inline]
    fn vertex_faces(&self, v: u32, mut f: impl FnMut(u32)) {
        let (i, j) = self.coords(v);
        // (cell offset, corner of that cell v is): a lower-left cell has v as corner c, etc.
        for (di, dj) in [(1, 1), (0, 1), (1, 0), (0, 0)] {
            let (Some(ci), Some(cj)) = (i.checked_sub(di), j.checked_sub(dj)) else {
                continue;
            };
            if ci >= self.nx || cj >= self.ny {
                continue;
            }
            if !self.triangulated {
                f(self.face_of(ci, cj, Side::Bottom));
                continue;
            }
            // Corner a (0, 0) and c (1, 1) are in both triangles, b (1, 0) only in the lower,
            // d (0, 1) only in the upper.
            if di == dj || (di, dj) == (1, 0) {
                f(self.face_of(ci, cj, Side::Bottom));
            }
            if di == dj || (di, dj) == (0, 1) {
                f(self.face_of(ci, cj, Side::Top));
            }
        }
    }
    fn is_boundary_vertex(&self, v: u32) -> bool {
        let (i, j) = self.coords(v);
        i == 0 || j == 0 || i == self.nx || j == self.ny
    }

    /// The shape of `soup` if it is one of [`crate::testing::meshes::grid`]'s grids, else why not.
    /// Linear: every face is compared with the grid's face of the same number.
    fn of_soup(soup: &PolygonSoup) -> std::result::Result<Self, String> {
        if soup.num_faces() == 0 {
            return Err("it has no faces".into());
        }
        let first = soup.face(0);
        let triangulated = match first.len() {
            3 => true,
            4 => false,
            k => {
                return Err(format!(
                    "face 0 has {k} corners; grid cells are quads or two triangles"
                ))
            }
        };
        if first[0] != 0 || first[1] != 1 || first[2] < 3 {
            return Err(format!(
                "face 0 is {first:?}; a grid's first face starts (0, 1, nx + 2, ...)"
            ));
        }
        let width = first[2] - 1;
        let nv = soup.num_vertices() as u64;
        if !nv.is_multiple_of(width as u64) || nv / (width as u64) < 2 {
            return Err(format!(
                "{nv} vertices do not make rows of {width} (as face 0 implies)"
            ));
        }
        let shape = Self {
            nx: width - 1,
            ny: (nv / width as u64 - 1) as u32,
            triangulated,
        };
        if soup.num_faces() != shape.num_faces() {
            return Err(format!(
                "{} faces, but a {}x{} {} grid has {}",
                soup.num_faces(),
                shape.nx,
                shape.ny,
                if triangulated { "triangle" } else { "quad" },
                shape.num_faces()
            ));
        }
        for (f, face) in soup.faces().enumerate() {
            let expected = shape.face_corners(f as u32);
            if face != expected.as_slice() {
                return Err(format!(
                    "face {f} is {face:?}, but face {f} of the {}x{} grid is {:?}",
                    shape.nx,
                    shape.ny,
                    expected.as_slice()
                ));
            }
        }
        Ok(shape)
    }
}

/// Where a grid's vertices are: computed ([`Implicit`]) or stored ([`Positions`]).
pub trait GridGeometry: Sized {
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

/// A grid mesh whose topology is arithmetic; `G` says where its vertices are.
#[derive(Clone, Debug)]
pub struct Grid<G> {
    /// The numbers of cells and the kind of faces.
    shape: GridShape,
    /// Where the vertices are.
    geometry: G,
}

/// The lecture's regular structure: implicit topology and geometry; see the module docs.
pub type RegularGrid = Grid<Implicit>;

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

impl<G: GridGeometry> MeshTopology for Grid<G> {
    const NAME: &'static str = G::NAME;

    fn capabilities() -> Capabilities {
        Capabilities {
            grids_only: true,
            ..Capabilities::POLYGONS
        }
    }

    fn cost(op: Operator) -> Cost {
        match op {
            Operator::BoundaryCurves => Cost::Boundary,
            _ => Cost::Constant,
        }
    }

    fn from_soup(soup: &PolygonSoup) -> Result<Self> {
        soup.check()?;
        let not_a_grid = |reason| Error::NotAGrid {
            structure: G::NAME,
            reason,
        };
        let shape = GridShape::of_soup(soup).map_err(not_a_grid)?;
        let geometry = G::from_positions(&soup.positions, shape).map_err(not_a_grid)?;
        Ok(Self { shape, geometry })
    }

    fn num_vertices(&self) -> usize {
        self.shape.num_vertices()
    }
    fn num_edges(&self) -> usize {
        self.shape.num_edges()
    }
    fn num_faces(&self) -> usize {
        self.shape.num_faces()
    }
    fn num_boundary_edges(&self) -> usize {
        2 * (self.shape.nx + self.shape.ny) as usize
    }
    fn for_each_edge(&self, mut f: impl FnMut(EdgeId)) {
        for e in 0..self.shape.num_edges() {
            f(EdgeId::new(e));
        }
    }
    fn position(&self, v: VertexId) -> DVec3 {
        self.geometry.position(self.shape, v)
    }
    fn vertex_vertices(&self, v: VertexId, mut f: impl FnMut(VertexId)) {
        self.shape.vertex_edges(v.0, |_, w| f(VertexId(w)));
    }
    fn vertex_edges(&self, v: VertexId, mut f: impl FnMut(EdgeId)) {
        self.shape.vertex_edges(v.0, |e, _| f(EdgeId(e)));
    }
    fn vertex_faces(&self, v: VertexId, mut f: impl FnMut(FaceId)) {
        self.shape.vertex_faces(v.0, |g| f(FaceId(g)));
    }
    fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2] {
        self.shape.edge_ends(e.0).map(VertexId)
    }
    fn edge_edges(&self, e: EdgeId, mut f: impl FnMut(EdgeId)) {
        for face in self.shape.edge_faces(e.0).into_iter().flatten() {
            for &x in self.shape.face_edges(face).as_slice() {
                if x != e.0 {
                    f(EdgeId(x));
                }
            }
        }
    }
    fn edge_faces(&self, e: EdgeId, mut f: impl FnMut(FaceId)) {
        for face in self.shape.edge_faces(e.0).into_iter().flatten() {
            f(FaceId(face));
        }
    }
    fn face_vertices(&self, face: FaceId, mut f: impl FnMut(VertexId)) {
        for &v in self.shape.face_corners(face.0).as_slice() {
            f(VertexId(v));
        }
    }
    fn face_edges(&self, face: FaceId, mut f: impl FnMut(EdgeId)) {
        for &e in self.shape.face_edges(face.0).as_slice() {
            f(EdgeId(e));
        }
    }
    fn face_faces(&self, face: FaceId, mut f: impl FnMut(FaceId)) {
        for &e in self.shape.face_edges(face.0).as_slice() {
            for g in self.shape.edge_faces(e).into_iter().flatten() {
                if g != face.0 {
                    f(FaceId(g));
                }
            }
        }
    }
    fn is_boundary_vertex(&self, v: VertexId) -> bool {
        self.shape.is_boundary_vertex(v.0)
    }
    fn is_boundary_edge(&self, e: EdgeId) -> bool {
        self.shape.edge_faces(e.0).contains(&None)
    }
    /// One curve around the border: bottom row left to right, right column up, top row
    /// right to left, left column down.
    fn boundary_curves(&self, out: &mut BoundaryCurves) {
        out.clear();
        let s = self.shape;
        let mut push = |e: u32| out.edges.push(EdgeId(e));
        (0..s.nx).for_each(|i| push(s.horizontal(i, 0)));
        (0..s.ny).for_each(|j| push(s.vertical(s.nx, j)));
        (0..s.nx).rev().for_each(|i| push(s.horizontal(i, s.ny)));
        (0..s.ny).rev().for_each(|j| push(s.vertical(0, j)));
        out.end_curve();
    }
    fn edge_successor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        let ring = self.shape.face_edges(face.0);
        let edges = ring.as_slice();
        let k = edges.iter().position(|&x| x == e.0)?;
        Some(EdgeId(edges[(k + 1) % edges.len()]))
    }
    fn edge_predecessor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        let ring = self.shape.face_edges(face.0);
        let edges = ring.as_slice();
        let k = edges.iter().position(|&x| x == e.0)?;
        Some(EdgeId(edges[(k + edges.len() - 1) % edges.len()]))
    }

    fn validate(&self) -> Result<()> {
        self.validate_topology()
            .and_then(|()| self.geometry.validate(self.shape))
            .map_err(|message| Error::invariant(G::NAME, message))
    }

    fn heap_bytes(&self) -> usize {
        self.geometry.heap_bytes()
    }

    fn explain(&self, w: &mut dyn Write) -> std::fmt::Result {
        let s = self.shape;
        writeln!(
            w,
            "{}: a {}x{} grid of {}, topology implicit (no record per face or edge)",
            G::NAME,
            s.nx,
            s.ny,
            if s.triangulated {
                "cells split into two triangles"
            } else {
                "quad cells"
            }
        )?;
        self.geometry.describe(s, w)?;
        writeln!(
            w,
            "\nvertex (i, j) = j·(nx+1) + i, here j·{} + i (rows from the bottom):",
            s.width()
        )?;
        for j in (0..=s.ny).rev() {
            let row: Vec<String> = (0..=s.nx)
                .map(|i| format!("v{:<3}", s.vertex(i, j)))
                .collect();
            writeln!(w, "  {}", row.join(" ").trim_end())?;
        }
        writeln!(
            w,
            "\nfaces: cell (i, j) = j·nx + i, corners a = (i, j), b = (i+1, j), c = (i+1, j+1), d = (i, j+1);\n{}",
            if s.triangulated {
                "face 2·cell = (a, b, c), face 2·cell + 1 = (a, c, d)"
            } else {
                "face = cell = (a, b, c, d)"
            }
        )?;
        for f in 0..s.num_faces() as u32 {
            let (i, j, _) = s.face_cell(f);
            writeln!(
                w,
                "  f{f}: cell ({i}, {j}), vertices {:?}, edges {:?}",
                s.face_corners(f).as_slice(),
                s.face_edges(f).as_slice()
            )?;
        }
        writeln!(
            w,
            "\nedges: horizontal (i, j)-(i+1, j) = j·nx + i; vertical (i, j)-(i, j+1) = nx·(ny+1) + j·(nx+1) + i{}",
            if s.triangulated {
                "; diagonal a-c of cell (i, j) = nx·(ny+1) + (nx+1)·ny + j·nx + i"
            } else {
                ""
            }
        )?;
        for e in 0..s.num_edges() as u32 {
            let [a, b] = s.edge_ends(e);
            let (kind, i, j) = s.edge(e);
            writeln!(w, "  e{e}: {kind:?} ({i}, {j}), v{a} - v{b}")?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::conformance::compare;
    use crate::testing::meshes;

    /// The lecture's example: origin (-1, 1), cells 0.2 x 0.2, 10 points... here 10 x 20 cells.
    fn lecture_grid() -> PolygonSoup {
        let mut soup = meshes::grid(10, 20, false);
        for p in &mut soup.positions {
            *p = DVec3::new(-1.0 + p.x * 0.2, 1.0 + p.y * 0.2, 0.0);
        }
        soup
    }

    #[test]
    fn the_lecture_example_answers_its_top_right_corner() {
        let grid = RegularGrid::from_soup(&lecture_grid()).expect("a regular grid");
        assert_eq!(grid.heap_bytes(), 0, "nothing stored per element");
        let top_right = grid.position(VertexId(11 * 21 - 1));
        assert!(
            (top_right - DVec3::new(1.0, 5.0, 0.0)).length() < 1e-12,
            "{top_right}"
        );
        grid.validate().expect("valid");
    }

    #[test]
    fn the_height_field_stores_any_positions_the_regular_grid_refuses_them() {
        let mut soup = meshes::grid(4, 3, true);
        for (v, p) in soup.positions.iter_mut().enumerate() {
            p.z = (v as f64 * 0.7).sin();
            p.x += 0.01 * v as f64;
        }
        let field = HeightField::from_soup(&soup).expect("a grid's topology");
        compare(&field, &soup).expect("every operator matches the oracle");
        assert_eq!(field.heap_bytes(), 20 * 24);
        let err = RegularGrid::from_soup(&soup).expect_err("positions off the formula");
        assert_eq!(err.kind(), "not-a-grid");
        assert!(err.to_string().contains("vertex 1 is at"), "{err}");
    }

    #[test]
    fn refusals_name_the_reason() {
        let reason = |soup: &PolygonSoup| {
            RegularGrid::from_soup(soup)
                .expect_err("refused")
                .to_string()
        };
        assert!(reason(&PolygonSoup::new()).contains("no faces"));
        assert!(reason(&meshes::quad_cube()).contains("face 0 is [0, 2, 3, 1]"));
        assert!(reason(&meshes::mixed_polygons()).contains("face 0 is [0, 1, 2, 3]"));
        let swapped =
            meshes::grid(3, 2, true).reorder_faces(&[0, 1, 2, 3, 5, 4, 6, 7, 8, 9, 10, 11]);
        assert!(
            reason(&swapped)
                .contains("face 4 is [2, 7, 6], but face 4 of the 3x2 grid is [2, 3, 7]"),
            "{}",
            reason(&swapped)
        );
        let mut missing = meshes::grid(2, 2, false);
        missing = missing.with_faces(|f| f != 3);
        assert!(reason(&missing).contains("3 faces, but a 2x2 quad grid has 4"));
    }

    #[test]
    fn validate_catches_inconsistent_shapes_and_geometry() {
        let soup = meshes::grid(2, 2, false);
        let mut grid = RegularGrid::from_soup(&soup).expect("grid");
        grid.shape.nx = 0;
        assert_eq!(grid.validate().map_err(|e| e.kind()), Err("invariant"));
        let mut field = HeightField::from_soup(&soup).expect("grid");
        field.shape.ny = 3;
        let err = field.validate().expect_err("9 positions for 12 vertices");
        assert!(err.to_string().contains("9 positions"), "{err}");
    }

    #[test]
    fn explain_shows_the_implicit_numbering_of_a_2x2_grid() {
        let grid = RegularGrid::from_soup(&meshes::grid(2, 2, true)).expect("grid");
        let mut out = String::new();
        grid.explain(&mut out).expect("string");
        assert!(out.contains("v6   v7   v8"), "{out}");
        assert_eq!(out.matches("\n  e").count(), 16, "{out}");
        assert_eq!(out.matches("\n  f").count(), 8, "{out}");
        assert!(out.contains("f1: cell (0, 0), vertices [0, 4, 3]"), "{out}");
    }
}
