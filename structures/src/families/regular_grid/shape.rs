//! The topology of a grid as arithmetic: the numbering of vertices, edges and faces (see the
//! module docs) and every relation computed from it.

use crate::core::reads::computed;
use crate::core::soup::PolygonSoup;

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
pub(super) struct Ring {
    /// The ids; only the first `len` count.
    ids: [u32; 4],
    /// How many.
    len: usize,
}

impl Ring {
    pub(super) fn new(ids: &[u32]) -> Self {
        let mut ring = Self {
            ids: [0; 4],
            len: ids.len(),
        };
        ring.ids[..ids.len()].copy_from_slice(ids);
        ring
    }
    pub(super) fn as_slice(&self) -> &[u32] {
        &self.ids[..self.len]
    }
}

/// Which cell side an edge lies on; the lower triangle `(a, b, c)` has the bottom and right
/// sides, the upper `(a, c, d)` the top and left ones (both have the diagonal).
#[derive(Copy, Clone)]
pub(super) enum Side {
    Bottom,
    Right,
    Top,
    Left,
}

/// An edge decoded from its id.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(super) enum EdgeKind {
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
    pub(super) fn width(&self) -> u32 {
        self.nx + 1
    }
    pub(super) fn num_vertices(&self) -> usize {
        (self.nx as usize + 1) * (self.ny as usize + 1)
    }
    pub(super) fn faces_per_cell(&self) -> u32 {
        if self.triangulated {
            2
        } else {
            1
        }
    }
    pub(super) fn num_faces(&self) -> usize {
        self.nx as usize * self.ny as usize * self.faces_per_cell() as usize
    }
    pub(super) fn num_horizontal(&self) -> u32 {
        self.nx * (self.ny + 1)
    }
    pub(super) fn num_vertical(&self) -> u32 {
        (self.nx + 1) * self.ny
    }
    pub(super) fn num_edges(&self) -> usize {
        let diagonals = if self.triangulated {
            self.nx as usize * self.ny as usize
        } else {
            0
        };
        self.num_horizontal() as usize + self.num_vertical() as usize + diagonals
    }
    #[inline]
    pub(super) fn vertex(&self, i: u32, j: u32) -> u32 {
        j * self.width() + i
    }
    #[inline]
    pub(super) fn coords(&self, v: u32) -> (u32, u32) {
        computed!("column i = v % (nx + 1)", v % self.width());
        computed!("row j = v / (nx + 1)", v / self.width());
        (v % self.width(), v / self.width())
    }
    #[inline]
    pub(super) fn horizontal(&self, i: u32, j: u32) -> u32 {
        j * self.nx + i
    }
    #[inline]
    pub(super) fn vertical(&self, i: u32, j: u32) -> u32 {
        self.num_horizontal() + j * self.width() + i
    }
    #[inline]
    pub(super) fn diagonal(&self, i: u32, j: u32) -> u32 {
        self.num_horizontal() + self.num_vertical() + j * self.nx + i
    }
    #[inline]
    pub(super) fn edge(&self, e: u32) -> (EdgeKind, u32, u32) {
        let (nh, nv) = (self.num_horizontal(), self.num_vertical());
        computed!(
            "kind of e (0 horizontal, 1 vertical, 2 diagonal)",
            (e >= nh) as u32 + (e >= nh + nv) as u32
        );
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
    pub(super) fn face_of(&self, i: u32, j: u32, side: Side) -> u32 {
        let cell = j * self.nx + i;
        match (self.triangulated, side) {
            (false, _) => cell,
            (true, Side::Bottom | Side::Right) => 2 * cell,
            (true, Side::Top | Side::Left) => 2 * cell + 1,
        }
    }
    /// Cell `(i, j)` of face `f`, and whether it is the upper triangle.
    #[inline]
    pub(super) fn face_cell(&self, f: u32) -> (u32, u32, bool) {
        let per = self.faces_per_cell();
        let cell = f / per;
        computed!("cell = f / faces per cell", cell);
        computed!("column i = cell % nx", cell % self.nx);
        computed!("row j = cell / nx", cell / self.nx);
        (cell % self.nx, cell / self.nx, f % per == 1)
    }
    pub(super) fn face_corners(&self, f: u32) -> Ring {
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
    pub(super) fn face_edges(&self, f: u32) -> Ring {
        let (i, j, upper) = self.face_cell(f);
        let (bottom, right) = (self.horizontal(i, j), self.vertical(i + 1, j));
        let (top, left) = (self.horizontal(i, j + 1), self.vertical(i, j));
        match (self.triangulated, upper) {
            (false, _) => Ring::new(&[bottom, right, top, left]),
            (true, false) => Ring::new(&[bottom, right, self.diagonal(i, j)]),
            (true, true) => Ring::new(&[self.diagonal(i, j), top, left]),
        }
    }
    pub(super) fn edge_ends(&self, e: u32) -> [u32; 2] {
        let (kind, i, j) = self.edge(e);
        let a = self.vertex(i, j);
        match kind {
            EdgeKind::Horizontal => [a, a + 1],
            EdgeKind::Vertical => [a, a + self.width()],
            EdgeKind::Diagonal => [a, a + self.width() + 1],
        }
    }
    pub(super) fn edge_faces(&self, e: u32) -> [Option<u32>; 2] {
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
    pub(super) fn vertex_edges(&self, v: u32, mut f: impl FnMut(u32, u32)) {
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
    pub(super) fn vertex_faces(&self, v: u32, mut f: impl FnMut(u32)) {
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
    pub(super) fn is_boundary_vertex(&self, v: u32) -> bool {
        let (i, j) = self.coords(v);
        i == 0 || j == 0 || i == self.nx || j == self.ny
    }

    /// The shape of `soup` if it is one of [`crate::meshes::grid`]'s grids, else why not.
    /// Linear: every face is compared with the grid's face of the same number.
    pub(super) fn of_soup(soup: &PolygonSoup) -> std::result::Result<Self, String> {
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
