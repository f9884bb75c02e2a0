//! [`MeshTopology`] for both grids: every operator is the shape's arithmetic (see the cost
//! table of the module docs); only `position` asks the geometry.

use super::{Grid, GridGeometry, GridShape};
use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, VertexId};
use crate::core::soup::PolygonSoup;
use crate::core::topology::{BoundaryCurves, Capabilities, Cost, MeshTopology, Operator};
use glam::DVec3;
use std::fmt::Write;

impl<G: GridGeometry> MeshTopology for Grid<G> {
    const NAME: &'static str = G::NAME;
    const FAMILY: crate::core::family::Family = crate::core::family::Family::RegularGrid;

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

    #[inline]
    fn num_vertices(&self) -> usize {
        self.shape.num_vertices()
    }
    #[inline]
    fn num_edges(&self) -> usize {
        self.shape.num_edges()
    }
    #[inline]
    fn num_faces(&self) -> usize {
        self.shape.num_faces()
    }
    #[inline]
    fn num_boundary_edges(&self) -> usize {
        2 * (self.shape.nx + self.shape.ny) as usize
    }
    fn for_each_edge(&self, mut f: impl FnMut(EdgeId)) {
        for e in 0..self.shape.num_edges() {
            f(EdgeId::new(e));
        }
    }
    #[inline]
    fn position(&self, v: VertexId) -> DVec3 {
        self.geometry.position(self.shape, v)
    }
    #[inline]
    fn vertex_vertices(&self, v: VertexId, mut f: impl FnMut(VertexId)) {
        self.shape.vertex_edges(v.0, |_, w| f(VertexId(w)));
    }
    #[inline]
    fn vertex_edges(&self, v: VertexId, mut f: impl FnMut(EdgeId)) {
        self.shape.vertex_edges(v.0, |e, _| f(EdgeId(e)));
    }
    #[inline]
    fn vertex_faces(&self, v: VertexId, mut f: impl FnMut(FaceId)) {
        self.shape.vertex_faces(v.0, |g| f(FaceId(g)));
    }
    #[inline]
    fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2] {
        self.shape.edge_ends(e.0).map(VertexId)
    }
    #[inline]
    fn edge_edges(&self, e: EdgeId, mut f: impl FnMut(EdgeId)) {
        for face in self.shape.edge_faces(e.0).into_iter().flatten() {
            for &x in self.shape.face_edges(face).as_slice() {
                if x != e.0 {
                    f(EdgeId(x));
                }
            }
        }
    }
    #[inline]
    fn edge_faces(&self, e: EdgeId, mut f: impl FnMut(FaceId)) {
        for face in self.shape.edge_faces(e.0).into_iter().flatten() {
            f(FaceId(face));
        }
    }
    #[inline]
    fn face_vertices(&self, face: FaceId, mut f: impl FnMut(VertexId)) {
        for &v in self.shape.face_corners(face.0).as_slice() {
            f(VertexId(v));
        }
    }
    #[inline]
    fn face_edges(&self, face: FaceId, mut f: impl FnMut(EdgeId)) {
        for &e in self.shape.face_edges(face.0).as_slice() {
            f(EdgeId(e));
        }
    }
    #[inline]
    fn face_faces(&self, face: FaceId, mut f: impl FnMut(FaceId)) {
        for &e in self.shape.face_edges(face.0).as_slice() {
            for g in self.shape.edge_faces(e).into_iter().flatten() {
                if g != face.0 {
                    f(FaceId(g));
                }
            }
        }
    }
    #[inline]
    fn is_boundary_vertex(&self, v: VertexId) -> bool {
        self.shape.is_boundary_vertex(v.0)
    }
    #[inline]
    fn is_boundary_edge(&self, e: EdgeId) -> bool {
        self.shape.edge_faces(e.0).contains(&None)
    }
    /// One curve around the border: bottom row left to right, right column up, top row
    /// right to left, left column down.
    #[inline]
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
    #[inline]
    fn edge_successor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        let ring = self.shape.face_edges(face.0);
        let edges = ring.as_slice();
        let k = edges.iter().position(|&x| x == e.0)?;
        Some(EdgeId(edges[(k + 1) % edges.len()]))
    }
    #[inline]
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
