//! The CHE over memory-mapped containers: a `.che` file ([`crate::che::file`],
//! `docs/che-format.md`) opened in place, so a mesh larger than memory is queried through the
//! page cache, with the same relations as the owned levels.
//!
//! - [`CheFile`]: a `.che` file of any level (0–3), mapped. Opening it reads the header only
//!   and checks the file's length against the counts: O(1), milliseconds at any size.
//!   [`CheFile::check`] reads everything: the checksum, every id's range, the header's edge
//!   count, and the level's invariants (the owned levels' `validate()`, the same functions).
//! - [`MappedChe`] (`MappedCheL1`, `MappedCheL2`, `MappedCheL3`): levels 1–3 as a
//!   [`MeshTopology`] structure, read-only. Its relations are the owned
//!   levels' own: the `che_topology!` macro over the same [`CheLevel`] hooks, Algorithm 6 and
//!   Algorithm 7's walk, and after a verification the timed two-ended walk (`Fan`). Level 0
//!   (its algorithms are methods of the owned [`CheL0`]) is checked and
//!   described as a file, not mapped as a structure.
//!
//! ## Which reads are checked
//!
//! Checking that every id is in range is a pass over the file, which `open` must not make.
//! So a just-opened [`MappedChe`] reads its containers **with bounds checks** (the
//! relations that default to [`CheLevel::vertex_star`]: Algorithm 6 at level 1, Algorithm 7
//! from `VH[v]` at levels 2 and 3): an id out of range in a corrupt file panics there instead
//! of reading outside the mapping, and a corrupt `O[]` may make a walk answer wrongly or not
//! end. [`MappedChe::verify`] runs the whole [`CheFile::check`] once, O(n); from then on levels 2
//! and 3 answer R00–R02 and the boundary test by the owned level 2's unchecked walk, whose
//! soundness needs exactly what the check established (`ranges_hold`). Validating lazily (a
//! range check at each read) was not chosen: it would put a check on every step of the walk,
//! the cost the unchecked walk exists to avoid, and a relation could still only panic on a
//! bad id, since the trait's queries return no error.
//!
//! So: `open` then query is safe on any file and right on a sound one; `open`, `verify`, then
//! query is fast and right. A file changed by another process while mapped is outside both:
//! see the `map` module's docs (the user's responsibility, as for every `memmap2` mapping).

mod map;

use super::build::{
    edge_map_by_scan, every_vertex_one_fan, opposites_and_vertex_half_edges, refusal,
};
use super::fan::Fan;
use super::level0::check_start_vertices;
use super::level1::{check_opposites, level1_cost, vertex_star_algorithm_6};
use super::level2::{check_cells, level2_cost};
use super::level3::{check_curves, level3_cost};
use super::{
    by_star, che_topology, fan_walk_algorithm_7, next, opposite_of, printed, walk_boundary_curve,
    CheLevel, StarRead,
};
use super::{CheL0, CheL1, CheL2, CheL3};
use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
use crate::core::reads::{self, read};
use crate::core::soup::PolygonSoup;
use crate::core::topology::{BoundaryCurves, MeshTopology};
use crate::families::che::file::{checksum, write_mesh, CheFileProblem, Container, Header};
use glam::DVec3;
use map::Mapping;
use std::path::{Path, PathBuf};

/// A `.che` file of any level, mapped read-only; see the [module docs](self).
pub struct CheFile {
    map: Mapping,
    path: PathBuf,
}

impl std::fmt::Debug for CheFile {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CheFile")
            .field("path", &self.path)
            .field("header", &self.header())
            .finish()
    }
}

/// The structure names of the four owned levels, by level.
const OWNED_NAMES: [&str; 4] = [CheL0::NAME, CheL1::NAME, CheL2::NAME, CheL3::NAME];

/// An entry out of its range: (index, value).
type Outside = (u64, i64);

/// The first entry of `xs` whose value `allowed` refuses, as (index, value).
fn first_outside<T: Copy + Into<i64>>(xs: &[T], allowed: impl Fn(i64) -> bool) -> Option<Outside> {
    xs.iter()
        .map(|&x| x.into())
        .enumerate()
        .find(|&(_, x)| !allowed(x))
        .map(|(i, x)| (i as u64, x))
}

impl CheFile {
    /// Maps `path` and checks its header and length ([`crate::che::file::Layout::of_file`]);
    /// reads nothing else. Every malformed header or length is an [`Error::CheFile`].
    pub fn open(path: &Path) -> Result<Self> {
        Ok(Self {
            map: Mapping::open(path)?,
            path: path.to_path_buf(),
        })
    }

    /// The file's path.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The header.
    pub fn header(&self) -> Header {
        self.map.layout().header
    }

    /// The CHE level, 0 to 3.
    pub fn level(&self) -> u8 {
        self.header().level
    }

    /// The file's length in bytes.
    pub fn file_bytes(&self) -> u64 {
        self.map.layout().file_bytes
    }

    /// `G[]`: the vertex positions.
    pub fn geometry(&self) -> &[DVec3] {
        self.map.g()
    }

    /// `V[]`: the start vertex of each half-edge.
    pub fn start_vertices(&self) -> &[u32] {
        self.map.v()
    }

    /// `O[]` (empty at level 0).
    pub fn opposite(&self) -> &[i32] {
        self.map.o()
    }

    /// `VH[]` (empty below level 2).
    pub fn vertex_half_edge(&self) -> &[i32] {
        self.map.vh()
    }

    /// `EH` (empty below level 2).
    pub fn edge_map(&self) -> &[u32] {
        self.map.eh()
    }

    /// `CH[]` (empty below level 3).
    pub fn curve_half_edge(&self) -> &[u32] {
        self.map.ch()
    }

    /// Reads the whole file: the checksum, the range of every id, the header's edge count,
    /// then the level's invariants (those of the owned level's `validate()`). O(n), plus
    /// O(n log n) for the edge count of level 0.
    pub fn check(&self) -> Result<()> {
        let problem = |p: CheFileProblem| p.at(&self.path);
        let stored = self.header().checksum;
        let computed = checksum(self.map.bytes());
        if computed != stored {
            return Err(problem(CheFileProblem::ChecksumMismatch {
                stored,
                computed,
            }));
        }
        self.check_ids().map_err(problem)?;
        let structure = OWNED_NAMES[self.level() as usize];
        self.check_corners(structure)?;
        self.check_edge_count().map_err(problem)?;
        self.check_structure(structure)
    }

    /// What building any level from `G[]` and `V[]` refuses, whatever the level stores: a
    /// coordinate that is not finite, a triangle that repeats a vertex, an edge of more than
    /// two triangles or two that traverse it the same way, a vertex of several fans (the
    /// shared edge analysis names it, as for a mesh file); and from level 1 on, an `O[]` other
    /// than the pairing `V[]` makes (boundary half-edges negative). So a level-0 file, which
    /// stores no `O[]` to contradict a corrupt `V[]`, is refused for what a level-1 file of the
    /// same triangles would be. O(n), the construction's own passes; a refusal copies `G[]` and
    /// `V[]` for the analysis.
    fn check_corners(&self, structure: &'static str) -> Result<()> {
        let (g, v) = (self.geometry(), self.start_vertices());
        let refuse = || {
            refusal(
                &PolygonSoup::from_triangles(g.to_vec(), v.to_vec()),
                structure,
            )
        };
        if !g.iter().all(|p| p.is_finite()) {
            return Err(refuse());
        }
        let paired = opposites_and_vertex_half_edges(v, g.len());
        let Some((o, _)) = paired.filter(|(o, vh)| every_vertex_one_fan(o, vh)) else {
            return Err(refuse());
        };
        if self.level() == 0 {
            return Ok(());
        }
        let stored = self.opposite();
        let differs = (0..o.len()).find(|&he| match o[he] {
            twin if twin >= 0 => stored[he] != twin,
            _ => stored[he] >= 0,
        });
        match differs {
            Some(he) => Err(Error::invariant(
                structure,
                format!(
                    "O[{he}] = {}, but V[] makes half-edge {he} {}",
                    stored[he],
                    match o[he] {
                        twin if twin >= 0 => format!("the opposite of half-edge {twin}"),
                        _ => "a boundary half-edge".to_string(),
                    }
                ),
            )),
            None => Ok(()),
        }
    }

    /// Every id of every container in the range its level allows.
    fn check_ids(&self) -> Result<(), CheFileProblem> {
        let h = self.header();
        let (vertices, half_edges) = (h.vertices as i64, h.half_edges() as i64);
        let curves = h.curves as i64;
        let is_half_edge = move |x: i64| (0..half_edges).contains(&x);
        let level = h.level;
        let boundary = move |x: i64| {
            if level == 3 {
                (-curves..0).contains(&x)
            } else {
                x == -1
            }
        };
        let half_edge_range = format!("a half-edge, 0 to {}", half_edges - 1);
        let checks: [(Container, Option<Outside>, String); 6] = [
            (
                Container::V,
                first_outside(self.start_vertices(), |x| (0..vertices).contains(&x)),
                format!("a vertex, 0 to {}", vertices - 1),
            ),
            (
                Container::O,
                first_outside(self.opposite(), |x| is_half_edge(x) || boundary(x)),
                if level == 3 {
                    format!("{half_edge_range}, or -1 to -{curves} for a boundary curve")
                } else {
                    format!("{half_edge_range}, or -1 on the boundary")
                },
            ),
            (
                Container::VH,
                first_outside(self.vertex_half_edge(), |x| is_half_edge(x) || x == -1),
                format!("{half_edge_range}, or -1 for an unused vertex"),
            ),
            (
                Container::EH,
                first_outside(self.edge_map(), is_half_edge),
                half_edge_range.clone(),
            ),
            (
                Container::CH,
                first_outside(self.curve_half_edge(), is_half_edge),
                half_edge_range,
            ),
            (Container::G, None, String::new()),
        ];
        for (container, outside, allowed) in checks {
            if let Some((index, value)) = outside {
                return Err(CheFileProblem::IdOutOfRange {
                    container,
                    index,
                    value,
                    allowed,
                });
            }
        }
        Ok(())
    }

    /// The header's edges are the containers' (levels 0 and 1, which store no `EH`; from level
    /// 2 on, `EH`'s length is the count and the level's check compares `EH` with `O[]`).
    fn check_edge_count(&self) -> Result<(), CheFileProblem> {
        let (v, o) = (self.start_vertices(), self.opposite());
        let found = match self.level() {
            0 => {
                let mut pairs: Vec<u64> = (0..v.len() as u32)
                    .map(|he| {
                        let (a, b) = (v[he as usize], v[next(HalfEdgeId(he)).index()]);
                        (u64::from(a.min(b)) << 32) | u64::from(a.max(b))
                    })
                    .collect();
                pairs.sort_unstable();
                pairs.dedup();
                pairs.len() as u64
            }
            1 => edge_map_by_scan(o).len() as u64,
            _ => return Ok(()),
        };
        let stated = self.header().edges;
        if found != stated {
            return Err(CheFileProblem::CountMismatch {
                what: "edges",
                stated,
                found,
            });
        }
        Ok(())
    }

    /// The level's invariants, by the owned levels' checks, reported as `structure`'s.
    fn check_structure(&self, structure: &'static str) -> Result<()> {
        let (n0, v, o) = (
            self.geometry().len(),
            self.start_vertices(),
            self.opposite(),
        );
        let (vh, eh) = (self.vertex_half_edge(), self.edge_map());
        match self.level() {
            0 => check_start_vertices(n0, v, structure),
            1 => check_opposites(n0, v, o, structure),
            2 => check_cells(n0, v, o, vh, eh, structure),
            _ => check_cells(n0, v, o, vh, eh, structure)
                .and_then(|()| check_curves(o, self.curve_half_edge(), structure)),
        }
    }
}

/// A CHE of level `L` (1 to 3) over a mapped `.che` file; see the [module docs](self).
#[derive(Debug)]
pub struct MappedChe<const L: u8> {
    file: CheFile,
    /// [`CheFile::check`] passed: the unchecked walk may be used (levels 2 and 3).
    verified: bool,
}

/// CHE level 1 over a mapped `.che` file.
pub type MappedCheL1 = MappedChe<1>;
/// CHE level 2 over a mapped `.che` file.
pub type MappedCheL2 = MappedChe<2>;
/// CHE level 3 over a mapped `.che` file.
pub type MappedCheL3 = MappedChe<3>;

che_topology!(MappedChe<1>, "che-l1-mapped", level1_cost);
che_topology!(MappedChe<2>, "che-l2-mapped", level2_cost);
che_topology!(MappedChe<3>, "che-l3-mapped", level3_cost);

impl<const L: u8> MappedChe<L> {
    /// Maps the `.che` file `path` ([`CheFile::open`], O(1)); refuses a file of another level.
    /// Its ids are not checked yet: see [`MappedChe::verify`].
    pub fn open(path: &Path) -> Result<Self> {
        Self::from_file(CheFile::open(path)?)
    }

    /// The CHE of level `L` over `file`; refuses a file of another level.
    pub fn from_file(file: CheFile) -> Result<Self> {
        if !(1..=3).contains(&L) {
            return Err(Error::Unsupported(format!(
                "a mapped CHE has level 1, 2 or 3, not {L} (a level-0 file is checked and described as a CheFile)"
            )));
        }
        if file.level() != L {
            let problem = CheFileProblem::WrongLevel {
                expected: L,
                found: file.level(),
            };
            return Err(problem.at(file.path()));
        }
        Ok(Self {
            file,
            verified: false,
        })
    }

    /// Runs [`CheFile::check`] (O(n)); once it passes, levels 2 and 3 answer by the unchecked
    /// walk (see the module docs).
    pub fn verify(&mut self) -> Result<()> {
        self.file.check()?;
        self.verified = true;
        Ok(())
    }

    /// Has [`MappedChe::verify`] passed?
    pub fn is_verified(&self) -> bool {
        self.verified
    }

    /// The mapped file.
    pub fn file(&self) -> &CheFile {
        &self.file
    }

    /// `G[]`: the vertex positions.
    #[inline]
    pub fn geometry(&self) -> &[DVec3] {
        self.file.geometry()
    }

    /// `O[]`: the opposite of each half-edge, negative on the boundary.
    #[inline]
    pub fn opposite(&self) -> &[i32] {
        self.file.opposite()
    }

    /// `VH[]` (empty at level 1).
    pub fn vertex_half_edge(&self) -> &[i32] {
        self.file.vertex_half_edge()
    }

    /// `EH` (empty at level 1).
    pub fn edge_map(&self) -> &[u32] {
        self.file.edge_map()
    }

    /// `CH[]` (empty below level 3).
    pub fn curve_half_edge(&self) -> &[u32] {
        self.file.curve_half_edge()
    }

    /// The unchecked walk over `V[]`, `O[]` and `VH[]`, once the file is verified (levels 2
    /// and 3); `None` before.
    #[inline(always)]
    #[allow(unsafe_code)]
    fn fan(&self) -> Option<Fan<'_>> {
        (L >= 2 && self.verified).then(|| {
            let (v, o, vh) = (
                self.file.start_vertices(),
                self.opposite(),
                self.vertex_half_edge(),
            );
            // SAFETY: `verified` is set only after `CheFile::check` passed, which for levels 2
            // and 3 includes `check_cells` and so `ranges_hold(v, o, vh)`; the mapping is
            // read-only, so the arrays are as checked (a file changed by another process is
            // the user's responsibility: see the `map` module's docs).
            unsafe { Fan::new_unchecked(v, o, vh) }
        })
    }

    /// [`Self::build`]: the mapped level keeps no array of the soup's to take.
    fn build_owned(soup: PolygonSoup) -> Result<Self> {
        Self::build(&soup)
    }

    /// Builds the owned level `L` from `soup`, writes it to a temporary `.che` file, maps it,
    /// verifies it and removes the file (the mapping keeps its pages): `from_soup`, for the
    /// conformance suite and the round-trip tests. Real use opens a file: [`MappedChe::open`].
    fn build(soup: &PolygonSoup) -> Result<Self> {
        use std::sync::atomic::{AtomicU64, Ordering};
        static NEXT: AtomicU64 = AtomicU64::new(0);
        let path = std::env::temp_dir().join(format!(
            "topolab-mapped-{}-{}.che",
            std::process::id(),
            NEXT.fetch_add(1, Ordering::Relaxed)
        ));
        write_mesh(soup, L, &path)?;
        let opened = Self::open(&path);
        let _ = std::fs::remove_file(&path);
        let mut m = opened?;
        m.verify()?;
        Ok(m)
    }

    fn check_containers(&self) -> Result<()> {
        self.file.check_structure(OWNED_NAMES[L as usize])
    }

    /// The file's bytes: mapped, not allocated.
    fn container_bytes(&self) -> usize {
        self.file.file_bytes() as usize
    }

    fn print_containers(&self, w: &mut dyn std::fmt::Write) -> std::fmt::Result {
        writeln!(
            w,
            "memory-mapped from {} ({} bytes, {}):",
            self.file.path().display(),
            self.file.file_bytes(),
            if self.verified {
                "verified"
            } else {
                "not verified"
            }
        )?;
        printed::geometry(w, self.geometry())?;
        printed::start_vertices(w, self.file.start_vertices())?;
        printed::opposites(w, self.opposite())?;
        if L >= 2 {
            printed::vertex_half_edges_and_edge_map(w, self.vertex_half_edge(), self.edge_map())?;
        }
        if L >= 3 {
            printed::curves(w, self.curve_half_edge())?;
        }
        Ok(())
    }
}

impl<const L: u8> CheLevel for MappedChe<L> {
    const LEVEL: u8 = L;
    const STAR_ALGORITHM: &'static str = if L == 1 {
        CheL1::STAR_ALGORITHM
    } else {
        CheL2::STAR_ALGORITHM
    };

    #[inline]
    fn start_vertices(&self) -> &[u32] {
        self.file.start_vertices()
    }

    /// Algorithm 6 at level 1; Algorithm 7 from `VH[v]` at levels 2 and 3. Bounds-checked.
    #[inline(always)]
    fn vertex_star(
        &self,
        v: VertexId,
        mut trace: impl FnMut(StarRead),
        corner: impl FnMut(HalfEdgeId),
    ) -> Option<HalfEdgeId> {
        let o = self.opposite();
        if L < 2 {
            return vertex_star_algorithm_6(self.start_vertices(), o, v, trace, corner);
        }
        let he = read!("VH", self.vertex_half_edge(), v.index());
        trace(StarRead::VertexHalfEdge { vertex: v, he });
        if he < 0 {
            return None;
        }
        fan_walk_algorithm_7(o, HalfEdgeId(he as u32), trace, corner)
    }

    #[inline(always)]
    fn twin(&self, he: HalfEdgeId) -> Option<HalfEdgeId> {
        opposite_of(self.opposite(), he)
    }

    /// `min(he, O[he])`, as from level 1 on (see the CHE's module docs, "Edge ids").
    #[inline(always)]
    fn edge_of(&self, he: HalfEdgeId) -> EdgeId {
        EdgeId(self.twin(he).map_or(he, |o| o.min(he)).0)
    }

    #[inline(always)]
    fn neighbours(&self, v: VertexId, f: impl FnMut(VertexId)) {
        match self.fan() {
            Some(fan) => fan.neighbours(v, f),
            None => by_star::neighbours(self, v, f),
        }
    }

    #[inline(always)]
    fn spoke_edges(&self, v: VertexId, f: impl FnMut(EdgeId)) {
        match self.fan() {
            Some(fan) => fan.spoke_edges(v, f),
            None => by_star::spoke_edges(self, v, f),
        }
    }

    #[inline(always)]
    fn star_triangles(&self, v: VertexId, f: impl FnMut(FaceId)) {
        match self.fan() {
            Some(fan) => fan.star_triangles(v, f),
            None => by_star::star_triangles(self, v, f),
        }
    }

    /// `O[VH[v]] < 0` from level 2 on (§4.3); the walked star at level 1.
    #[inline(always)]
    fn vertex_on_boundary(&self, v: VertexId) -> bool {
        match self.fan() {
            Some(fan) => fan.on_boundary(v),
            None if L >= 2 => {
                let he = read!("VH", self.vertex_half_edge(), v.index());
                he >= 0 && read!("O", self.opposite(), he as usize) < 0
            }
            None => by_star::vertex_on_boundary(self, v),
        }
    }

    /// `EH` from level 2 on; the half-edges that are the smaller of their pair at level 1.
    fn each_edge(&self, mut f: impl FnMut(EdgeId)) {
        if L >= 2 {
            for &he in self.edge_map() {
                f(EdgeId(he));
            }
        } else {
            by_star::each_edge(self, f)
        }
    }

    #[inline]
    fn edge_count(&self) -> usize {
        if L >= 2 {
            self.edge_map().len()
        } else {
            let mut n = 0;
            by_star::each_edge(self, |_| n += 1);
            n
        }
    }

    /// Algorithm 10 from `CH[]` at level 3; the scan of §4.6 below.
    fn walk_boundary_curves(&self, out: &mut BoundaryCurves) {
        if L >= 3 {
            out.clear();
            for he in reads::each("CH", self.curve_half_edge(), 0) {
                walk_boundary_curve(HalfEdgeId(he), |h| self.twin(h), out);
            }
        } else {
            by_star::boundary_curves(self, out)
        }
    }
}
