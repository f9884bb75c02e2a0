//! Deterministic generators of grids, tori, spheres, surfaces of any genus and boundary,
//! mixed polygons and random meshes, of any size.

use crate::core::soup::PolygonSoup;
use glam::DVec3;
use rand::seq::SliceRandom;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::TAU;

/// An open `nx` × `ny` grid in the z = 0 plane with unit cells: `(nx+1)(ny+1)` vertices,
/// vertex `(i, j)` is `j (nx+1) + i` at `(i, j, 0)`. Cells row by row; each cell is a quad
/// `(a, b, c, d)` or, `triangulated`, the triangles `(a, b, c)` and `(a, c, d)`.
pub fn grid(nx: usize, ny: usize, triangulated: bool) -> PolygonSoup {
    let (per, corners) = if triangulated { (2, 6) } else { (1, 4) };
    let mut s = PolygonSoup::with_capacity((nx + 1) * (ny + 1), nx * ny * per, nx * ny * corners);
    push_grid_vertices(&mut s, nx, ny);
    let w = (nx + 1) as u32;
    for j in 0..ny as u32 {
        for i in 0..nx as u32 {
            let a = j * w + i;
            let (b, c, d) = (a + 1, a + w + 1, a + w);
            if triangulated {
                s.push_face(&[a, b, c]);
                s.push_face(&[a, c, d]);
            } else {
                s.push_face(&[a, b, c, d]);
            }
        }
    }
    s
}

/// Adds the vertices of an `nx` × `ny` cell grid in the z = 0 plane, row by row: vertex
/// `(i, j)` at `(i, j, 0)`.
fn push_grid_vertices(s: &mut PolygonSoup, nx: usize, ny: usize) {
    for j in 0..=ny {
        for i in 0..=nx {
            s.push_vertex(DVec3::new(i as f64, j as f64, 0.0));
        }
    }
}

/// A closed triangulated torus of `nu` × `nv` vertices (`2 nu nv` triangles), ordered ring by ring.
///
/// # Panics
/// If `nu < 3` or `nv < 3`.
pub fn torus(nu: usize, nv: usize) -> PolygonSoup {
    assert!(nu >= 3 && nv >= 3, "a torus needs at least 3 x 3 vertices");
    let (r_big, r_small) = (1.0, 0.35);
    let mut s = PolygonSoup::with_capacity(nu * nv, 2 * nu * nv, 6 * nu * nv);
    for i in 0..nu {
        let u = TAU * i as f64 / nu as f64;
        for j in 0..nv {
            let v = TAU * j as f64 / nv as f64;
            let r = r_big + r_small * v.cos();
            s.push_vertex(DVec3::new(r * u.cos(), r * u.sin(), r_small * v.sin()));
        }
    }
    let id = |i: usize, j: usize| ((i % nu) * nv + (j % nv)) as u32;
    for i in 0..nu {
        for j in 0..nv {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            s.push_face(&[a, b, c]);
            s.push_face(&[a, c, d]);
        }
    }
    s
}

/// A torus with about `triangles` triangles (at least 18), rings about three times the tube.
pub fn torus_with_triangles(triangles: usize) -> PolygonSoup {
    let (nu, nv) = torus_sides(triangles);
    torus(nu, nv)
}

/// The `(nu, nv)` of [`torus_with_triangles`].
pub(super) fn torus_sides(triangles: usize) -> (usize, usize) {
    let cells = (triangles / 2).max(9) as f64;
    let nv = ((cells / 3.0).sqrt().round() as usize).max(3);
    let nu = ((cells / nv as f64).round() as usize).max(3);
    (nu, nv)
}

/// A closed UV sphere: `rings` ≥ 2 latitude bands, `segments` ≥ 3 longitudes, two poles;
/// `2 segments (rings - 1)` triangles.
pub fn sphere(rings: usize, segments: usize) -> PolygonSoup {
    assert!(
        rings >= 2 && segments >= 3,
        "a sphere needs 2 rings and 3 segments"
    );
    let faces = 2 * segments * (rings - 1);
    let mut s = PolygonSoup::with_capacity(2 + (rings - 1) * segments, faces, 3 * faces);
    s.push_vertex(DVec3::Z);
    for r in 1..rings {
        let theta = std::f64::consts::PI * r as f64 / rings as f64;
        for k in 0..segments {
            let phi = TAU * k as f64 / segments as f64;
            s.push_vertex(DVec3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            ));
        }
    }
    let south = s.push_vertex(-DVec3::Z).0;
    let ring = |r: usize, k: usize| (1 + (r - 1) * segments + k % segments) as u32;
    for k in 0..segments {
        s.push_face(&[0, ring(1, k), ring(1, k + 1)]);
    }
    for r in 1..rings - 1 {
        for k in 0..segments {
            let (a, b, c, d) = (
                ring(r, k),
                ring(r + 1, k),
                ring(r + 1, k + 1),
                ring(r, k + 1),
            );
            s.push_face(&[a, b, c]);
            s.push_face(&[a, c, d]);
        }
    }
    for k in 0..segments {
        s.push_face(&[south, ring(rings - 1, k + 1), ring(rings - 1, k)]);
    }
    s
}

/// What kind of random mesh [`random_mesh`] makes.
#[derive(Copy, Clone, Debug)]
pub struct RandomMeshParams {
    /// Only triangles (otherwise a mix of triangles and quads).
    pub triangles_only: bool,
    /// Largest grid side.
    pub max_side: usize,
    /// Probability of keeping each cell (holes make boundaries, and non-manifold vertices).
    pub keep: f64,
}

impl Default for RandomMeshParams {
    fn default() -> Self {
        Self {
            triangles_only: false,
            max_side: 7,
            keep: 0.8,
        }
    }
}

/// A random mesh from `seed`: a random subset of a grid's cells (each cell a quad or two
/// triangles), with vertices relabelled and faces shuffled at random. Unused vertices stay,
/// and cells touching only at a corner make non-manifold vertices: both are intended.
pub fn random_mesh(seed: u64, params: RandomMeshParams) -> PolygonSoup {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let nx = rng.random_range(1..=params.max_side);
    let ny = rng.random_range(1..=params.max_side);
    let w = (nx + 1) as u32;
    let mut s = PolygonSoup::new();
    for j in 0..=ny {
        for i in 0..=nx {
            let jitter = DVec3::new(
                rng.random::<f64>(),
                rng.random::<f64>(),
                rng.random::<f64>(),
            );
            s.push_vertex(DVec3::new(i as f64, j as f64, 0.0) + 0.2 * jitter);
        }
    }
    for j in 0..ny as u32 {
        for i in 0..nx as u32 {
            if !rng.random_bool(params.keep) {
                continue;
            }
            let a = j * w + i;
            let (b, c, d) = (a + 1, a + w + 1, a + w);
            if params.triangles_only || rng.random_bool(0.5) {
                if rng.random_bool(0.5) {
                    s.push_face(&[a, b, c]);
                    s.push_face(&[a, c, d]);
                } else {
                    s.push_face(&[a, b, d]);
                    s.push_face(&[b, c, d]);
                }
            } else {
                s.push_face(&[a, b, c, d]);
            }
        }
    }
    if s.num_faces() == 0 {
        s.push_face(&[0, 1, w + 1]);
    }
    let mut perm: Vec<u32> = (0..s.num_vertices() as u32).collect();
    perm.shuffle(&mut rng);
    let mut order: Vec<u32> = (0..s.num_faces() as u32).collect();
    order.shuffle(&mut rng);
    s.relabel_vertices(&perm).reorder_faces(&order)
}

/// A closed surface of genus `genus` with `holes` boundary curves and about `triangles`
/// triangles: a thick plate (two copies of a planar grid, z = ±0.5, joined by a rim of quads cut
/// into triangles) pierced by `genus` square tunnels, with `holes` square openings cut into its
/// top side. Euler characteristic `2 - 2 genus - holes`; every vertex is used and manifold.
///
/// The slots (tunnels, then openings) are laid out on a near-square array of tiles of `t` × `t`
/// cells, each slot the middle half of its tile, so slots never touch each other or the rim.
/// Vertices are numbered top side row by row, then bottom side row by row; faces top, bottom,
/// rim. Linear in the size (one pass per side, capacity reserved), so 16M triangles is fine.
pub fn perforated_plate(genus: usize, holes: usize, triangles: usize) -> PolygonSoup {
    let layout = PlateLayout::new(genus, holes, triangles);
    let PlateLayout { cols, tile, .. } = layout;
    let slots = genus + holes;
    let (nx, ny) = layout.cells();
    // The slot of cell (i, j): its index among all slots, if the cell is inside one.
    let slot_of = |i: usize, j: usize| -> Option<usize> {
        let (lo, hi) = (tile / 4, tile - tile / 4);
        let (u, v) = (i % tile, j % tile);
        let slot = (j / tile) * cols + i / tile;
        (slot < slots && (lo..hi).contains(&u) && (lo..hi).contains(&v)).then_some(slot)
    };
    // Cells of the plate (not in a tunnel), and of its top side (not in a tunnel or an opening).
    let in_plate = |i: usize, j: usize| !matches!(slot_of(i, j), Some(s) if s < genus);
    let in_top = |i: usize, j: usize| slot_of(i, j).is_none();
    let (vertices, faces) = layout.counts();
    let mut s = PolygonSoup::with_capacity(vertices, faces, 3 * faces);
    let top = add_grid_side(&mut s, nx, ny, 0.5, in_top);
    let bottom = add_grid_side(&mut s, nx, ny, -0.5, in_plate);
    let w = nx + 1;
    for j in 0..ny {
        for i in 0..nx {
            if in_top(i, j) {
                let [a, b, c, d] = cell_corners(&top, w, i, j);
                s.push_face(&[a, b, c]);
                s.push_face(&[a, c, d]);
            }
        }
    }
    for j in 0..ny {
        for i in 0..nx {
            if in_plate(i, j) {
                // Seen from below: the reversed cell.
                let [a, b, c, d] = cell_corners(&bottom, w, i, j);
                s.push_face(&[a, c, b]);
                s.push_face(&[a, d, c]);
            }
        }
    }
    // The rim: each side of a plate cell whose neighbour is outside the plate (the outer edge
    // or a tunnel wall) joins top and bottom with a quad cut into two triangles. The cell's
    // counter-clockwise side p -> q is q -> p in the rim, as the orientation requires.
    let outside = |i: isize, j: isize| {
        i < 0 || j < 0 || i >= nx as isize || j >= ny as isize || !in_plate(i as usize, j as usize)
    };
    for j in 0..ny {
        for i in 0..nx {
            if !in_plate(i, j) {
                continue;
            }
            let (ii, jj) = (i as isize, j as isize);
            let corner = |k: usize| {
                let (di, dj) = [(0, 0), (1, 0), (1, 1), (0, 1)][k];
                (j + dj) * w + i + di
            };
            for (k, (di, dj)) in [(0, -1), (1, 0), (0, 1), (-1, 0)].into_iter().enumerate() {
                if outside(ii + di, jj + dj) {
                    let (p, q) = (corner(k), corner((k + 1) % 4));
                    s.push_face(&[top[q], top[p], bottom[p]]);
                    s.push_face(&[top[q], bottom[p], bottom[q]]);
                }
            }
        }
    }
    s
}

/// How [`perforated_plate`] lays a plate out: `cols` × `rows` tiles of `tile` × `tile` cells,
/// slot k (tunnels first, then openings) the middle half of tile k, row by row.
#[derive(Copy, Clone, Debug)]
pub(super) struct PlateLayout {
    genus: usize,
    holes: usize,
    cols: usize,
    rows: usize,
    tile: usize,
}

impl PlateLayout {
    pub(super) fn new(genus: usize, holes: usize, triangles: usize) -> Self {
        let slots = genus + holes;
        let cols = ((slots as f64).sqrt().ceil() as usize).max(1);
        let rows = slots.div_ceil(cols).max(1);
        // Two sides of 2 t² triangles per tile, less a tunnel's t² or an opening's t² / 2.
        let per_t2 = (4 * cols * rows) as f64 - genus as f64 - holes as f64 / 2.0;
        let tile = ((triangles as f64 / per_t2).sqrt().round() as usize).max(4);
        Self {
            genus,
            holes,
            cols,
            rows,
            tile,
        }
    }

    /// The cell grid, `nx` × `ny`.
    fn cells(&self) -> (usize, usize) {
        (self.cols * self.tile, self.rows * self.tile)
    }

    /// The vertices and triangles of the plate, counted without building it: each slot is an
    /// `m` × `m` square of cells (`m = tile - 2 (tile / 4)`) that touches no other slot and not
    /// the rim, so it removes its `(m - 1)²` interior grid vertices and `2 m²` triangles from
    /// each side it cuts (a tunnel both, an opening the top), and a tunnel adds a wall of
    /// `4 m` quads (8 m triangles) to the rim.
    pub(super) fn counts(&self) -> (usize, usize) {
        let (nx, ny) = self.cells();
        let m = self.tile - 2 * (self.tile / 4);
        let (g, h) = (self.genus, self.holes);
        let grid_vertices = (nx + 1) * (ny + 1);
        let vertices = 2 * grid_vertices - (2 * g + h) * (m - 1) * (m - 1);
        let sides = 4 * nx * ny - 2 * (2 * g + h) * m * m;
        let rim = 4 * (nx + ny) + 8 * g * m;
        (vertices, sides + rim)
    }
}

/// Adds the vertices of one side of a plate at height `z`: grid vertex `(i, j)` of an
/// `nx` × `ny` cell grid gets a new vertex when a cell around it is `in_side`. Returns the
/// new id of each grid vertex (`u32::MAX` when unused), indexed `j (nx + 1) + i`.
fn add_grid_side(
    s: &mut PolygonSoup,
    nx: usize,
    ny: usize,
    z: f64,
    in_side: impl Fn(usize, usize) -> bool,
) -> Vec<u32> {
    let mut id = Vec::with_capacity((nx + 1) * (ny + 1));
    for j in 0..=ny {
        for i in 0..=nx {
            let around = [(i, j), (i.wrapping_sub(1), j), (i, j.wrapping_sub(1))];
            let used = around
                .into_iter()
                .chain([(i.wrapping_sub(1), j.wrapping_sub(1))])
                .any(|(a, b)| a < nx && b < ny && in_side(a, b));
            id.push(if used {
                s.push_vertex(DVec3::new(i as f64, j as f64, z)).0
            } else {
                u32::MAX
            });
        }
    }
    id
}

/// The new ids of cell `(i, j)`'s corners, counter-clockwise from `(i, j)`, in a grid of row
/// width `w` vertices.
fn cell_corners(id: &[u32], w: usize, i: usize, j: usize) -> [u32; 4] {
    let a = j * w + i;
    [id[a], id[a + 1], id[a + w + 1], id[a + w]]
}

/// An open grid of about `faces` polygons of sizes 3, 4, 5 and 6: cells are taken in pairs
/// along each row, and pair `(p, j)` becomes, by `(p + j) mod 4`, a hexagon, two quads, a
/// pentagon and a triangle, or a quad and two triangles. One boundary curve; vertices as
/// [`grid`] numbers them.
pub fn mixed_grid(faces: usize) -> PolygonSoup {
    let n = mixed_pairs(faces);
    let (nx, ny) = (2 * n, 2 * n);
    let (f, corners) = mixed_counts(n);
    let mut s = PolygonSoup::with_capacity((nx + 1) * (ny + 1), f, corners);
    push_grid_vertices(&mut s, nx, ny);
    let w = (nx + 1) as u32;
    for j in 0..ny as u32 {
        for p in 0..n as u32 {
            // Bottom row p0 p1 p2, top row q0 q1 q2 of the pair's two cells.
            let p0 = j * w + 2 * p;
            let (p1, p2) = (p0 + 1, p0 + 2);
            let (q0, q1, q2) = (p0 + w, p1 + w, p2 + w);
            match (p + j) % 4 {
                0 => {
                    s.push_face(&[p0, p1, p2, q2, q1, q0]);
                }
                1 => {
                    s.push_face(&[p0, p1, q1, q0]);
                    s.push_face(&[p1, p2, q2, q1]);
                }
                2 => {
                    s.push_face(&[p0, p1, p2, q2, q1]);
                    s.push_face(&[p0, q1, q0]);
                }
                _ => {
                    s.push_face(&[p0, p1, q1, q0]);
                    s.push_face(&[p1, p2, q2]);
                    s.push_face(&[p1, q2, q1]);
                }
            }
        }
    }
    s
}

/// The `n` of [`mixed_grid`]: pairs of cells per row, on a square of 2 n × 2 n cells. On
/// average two faces per pair: 4 n² faces.
pub(super) fn mixed_pairs(faces: usize) -> usize {
    ((faces as f64 / 4.0).sqrt().round() as usize).max(1)
}

/// The faces and corners of [`mixed_grid`] with `n` pairs per row, counted without building
/// it: pair `(p, j)` of kind `(p + j) mod 4` makes 1, 2, 2 or 3 faces of 6, 8, 8 or 10 corners.
pub(super) fn mixed_counts(n: usize) -> (usize, usize) {
    // How many of 0..len are k mod 4, for each k.
    let residues = |len: usize| [0, 1, 2, 3].map(|k| len / 4 + usize::from(k < len % 4));
    let (rows, pairs) = (residues(2 * n), residues(n));
    let (mut faces, mut corners) = (0, 0);
    for (r, &row_count) in rows.iter().enumerate() {
        for (p, &pair_count) in pairs.iter().enumerate() {
            let times = row_count * pair_count;
            let (f, c) = [(1, 6), (2, 8), (2, 8), (3, 10)][(p + r) % 4];
            faces += times * f;
            corners += times * c;
        }
    }
    (faces, corners)
}

/// The same mesh with every position moved by a seeded random offset in
/// `[-amplitude, amplitude]` per coordinate (connectivity unchanged), to break the regularity
/// of generated meshes.
pub fn perturb(soup: &PolygonSoup, amplitude: f64, seed: u64) -> PolygonSoup {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut out = soup.clone();
    for p in &mut out.positions {
        let offset = DVec3::new(
            rng.random_range(-1.0..=1.0),
            rng.random_range(-1.0..=1.0),
            rng.random_range(-1.0..=1.0),
        );
        *p += amplitude * offset;
    }
    out
}
