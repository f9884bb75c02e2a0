//! The `.che` file: the containers of a Compact Half-Edge (the CHE thesis chapter's `G`, `V`,
//! `O`, `VH`, `EH`, `CH`, as many as its level has) laid out to be memory-mapped.
//! `docs/che-format.md` describes it byte by byte; in short:
//!
//! - a 64-byte header: magic, byte-order mark, format version, level, the counts (vertices,
//!   triangles, edges, boundary curves) and a checksum;
//! - then each container the level has, in the order `G`, `V`, `O`, `VH`, `EH`, `CH`, each
//!   starting at a multiple of 64 bytes and padded with zeros to the next one; all numbers
//!   little-endian. Every offset follows from the counts ([`Layout`]), so the header needs no
//!   offset table, and the file's length is exactly the layout's.
//!
//! This module reads and writes the bytes only, in safe code: [`Header::parse`] and
//! [`Layout::of_file`] check a file's first bytes and its length (O(1): opening a file of any
//! size reads its header only), [`checksum`] reads it all. The CHE over the mapped containers
//! is [`crate::che::mapped`].

use crate::core::error::{Error, Result};
use crate::core::soup::PolygonSoup;
use glam::DVec3;
use std::io::Write;
use std::path::{Path, PathBuf};

use crate::core::che_format::CHECKSUM_AT;
pub use crate::core::che_format::{
    CheFileProblem, Container, ALIGNMENT, BYTE_ORDER_MARK, HEADER_BYTES, MAGIC, VERSION,
};

impl CheFileProblem {
    /// The [`Error`] for this problem in `path`.
    pub fn at(self, path: &Path) -> Error {
        Error::CheFile {
            path: path.to_path_buf(),
            problem: self,
        }
    }
}

/// A `.che` header (the first [`HEADER_BYTES`] bytes).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Header {
    /// The CHE level, 0 to 3.
    pub level: u8,
    /// `n0`, the vertices (`G[]` and `VH[]` entries).
    pub vertices: u64,
    /// `n2`, the triangles (`V[]` and `O[]` hold `3·n2` entries).
    pub triangles: u64,
    /// `n1`, the edges (`EH` entries from level 2; stated at every level).
    pub edges: u64,
    /// The boundary curves (`CH[]` entries); 0 below level 3, which do not store them.
    pub curves: u64,
    /// [`checksum`] of the whole file.
    pub checksum: u64,
}

fn u32_at(bytes: &[u8], at: usize) -> u32 {
    u32::from_le_bytes(bytes[at..at + 4].try_into().expect("4 bytes"))
}

fn u64_at(bytes: &[u8], at: usize) -> u64 {
    u64::from_le_bytes(bytes[at..at + 8].try_into().expect("8 bytes"))
}

impl Header {
    /// Reads a header from the first bytes of a file: refuses a short file, another magic,
    /// another byte order or version, a level outside 0–3 and reserved bytes that are not zero.
    /// The counts are checked by [`Layout::of`].
    pub fn parse(bytes: &[u8]) -> Result<Self, CheFileProblem> {
        if (bytes.len() as u64) < HEADER_BYTES {
            return Err(CheFileProblem::Short {
                bytes: bytes.len() as u64,
            });
        }
        if bytes[..8] != MAGIC {
            return Err(CheFileProblem::WrongMagic);
        }
        match u32_at(bytes, 8) {
            BYTE_ORDER_MARK => {}
            m if m == BYTE_ORDER_MARK.swap_bytes() => return Err(CheFileProblem::BigEndian),
            found => return Err(CheFileProblem::BadByteOrderMark { found }),
        }
        let version = u32_at(bytes, 12);
        if version != VERSION {
            return Err(CheFileProblem::UnknownVersion { found: version });
        }
        let level = u32_at(bytes, 16);
        if level > 3 {
            return Err(CheFileProblem::UnknownLevel { found: level });
        }
        if u32_at(bytes, 20) != 0 {
            return Err(CheFileProblem::ReservedNotZero { at: 20 });
        }
        Ok(Header {
            level: level as u8,
            vertices: u64_at(bytes, 24),
            triangles: u64_at(bytes, 32),
            edges: u64_at(bytes, 40),
            curves: u64_at(bytes, 48),
            checksum: u64_at(bytes, CHECKSUM_AT),
        })
    }

    /// The header's bytes.
    pub fn to_bytes(&self) -> [u8; HEADER_BYTES as usize] {
        let mut b = [0u8; HEADER_BYTES as usize];
        b[..8].copy_from_slice(&MAGIC);
        b[8..12].copy_from_slice(&BYTE_ORDER_MARK.to_le_bytes());
        b[12..16].copy_from_slice(&VERSION.to_le_bytes());
        b[16..20].copy_from_slice(&u32::from(self.level).to_le_bytes());
        b[24..32].copy_from_slice(&self.vertices.to_le_bytes());
        b[32..40].copy_from_slice(&self.triangles.to_le_bytes());
        b[40..48].copy_from_slice(&self.edges.to_le_bytes());
        b[48..56].copy_from_slice(&self.curves.to_le_bytes());
        b[56..64].copy_from_slice(&self.checksum.to_le_bytes());
        b
    }

    /// `3·n2`, the half-edges.
    pub fn half_edges(&self) -> u64 {
        self.triangles.saturating_mul(3)
    }

    /// How many elements `c` holds at this level (0 for a container the level does not store).
    pub fn count(&self, c: Container) -> u64 {
        if self.level < c.first_level() {
            return 0;
        }
        match c {
            Container::G | Container::VH => self.vertices,
            Container::V | Container::O => self.half_edges(),
            Container::EH => self.edges,
            Container::CH => self.curves,
        }
    }
}

/// Where one container lies in the file.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Section {
    /// The byte offset of its first element, a multiple of [`ALIGNMENT`].
    pub offset: u64,
    /// Its elements.
    pub len: u64,
}

/// The offsets of a file's containers, derived from its header's counts.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Layout {
    /// The header.
    pub header: Header,
    sections: [Option<Section>; 6],
    /// The file's length: the last container's end, padded to [`ALIGNMENT`].
    pub file_bytes: u64,
}

/// `x` rounded up to a multiple of [`ALIGNMENT`], `None` past `u64`.
fn aligned(x: u64) -> Option<u64> {
    x.checked_next_multiple_of(ALIGNMENT)
}

impl Layout {
    /// The layout of `header`'s counts: refuses counts no CHE can have (more half-edges or
    /// vertices than `i32` numbers, more edges than half-edges, curves below level 3 or more
    /// curves than half-edges).
    pub fn of(header: Header) -> Result<Self, CheFileProblem> {
        let limit = i32::MAX as u64;
        let impossible = |reason: String| Err(CheFileProblem::ImpossibleCounts { reason });
        if header.vertices > limit {
            return impossible(format!(
                "{} vertices, more than i32 numbers",
                header.vertices
            ));
        }
        if header.triangles > limit / 3 {
            return impossible(format!(
                "{} triangles, more half-edges than i32 numbers",
                header.triangles
            ));
        }
        if header.edges > header.half_edges() {
            return impossible(format!(
                "{} edges for {} half-edges",
                header.edges,
                header.half_edges()
            ));
        }
        if header.level < 3 && header.curves != 0 {
            return impossible(format!(
                "{} boundary curves stored at level {}, which has no CH[]",
                header.curves, header.level
            ));
        }
        if header.curves > header.half_edges() {
            return impossible(format!(
                "{} boundary curves for {} half-edges",
                header.curves,
                header.half_edges()
            ));
        }
        // Below these limits every product and sum fits u64 many times over.
        let mut sections = [None; 6];
        let mut at = HEADER_BYTES;
        for c in Container::ALL {
            if header.level < c.first_level() {
                continue;
            }
            let len = header.count(c);
            sections[c.index()] = Some(Section { offset: at, len });
            at = aligned(at + len * c.element_bytes()).expect("bounded counts");
        }
        Ok(Layout {
            header,
            sections,
            file_bytes: at,
        })
    }

    /// [`Header::parse`] and [`Layout::of`] for a file whose length is `file_bytes` and whose
    /// first bytes are `start` (at least the header, if the file has it), then refuses a
    /// length other than the layout's. O(1): only the header is read.
    pub fn of_file(start: &[u8], file_bytes: u64) -> Result<Self, CheFileProblem> {
        let layout = Layout::of(Header::parse(start)?)?;
        if layout.file_bytes != file_bytes {
            return Err(CheFileProblem::LengthMismatch {
                expected: layout.file_bytes,
                actual: file_bytes,
            });
        }
        Ok(layout)
    }

    /// Where container `c` lies, `None` if the level does not store it.
    pub fn section(&self, c: Container) -> Option<Section> {
        self.sections[c.index()]
    }
}

/// The file's checksum: every 8-byte little-endian word `w` of the file in order, with the
/// header's checksum field read as 0, folded as `h = (h ^ w) · 0x100000001B3` (wrapping),
/// from `h = 0xCBF29CE484222325` (FNV-1a's constants, a word at a time). Each step is a
/// bijection of `h` for a given word, so a change confined to one word always changes the
/// result. Not cryptographic. A `.che` file's length is a multiple of 8 ([`ALIGNMENT`]).
pub fn checksum(bytes: &[u8]) -> u64 {
    let mut h = Checksum::new();
    h.feed(bytes);
    h.finish()
}

/// [`checksum`] fed piece by piece (the writer hashes the file as it lays it out).
struct Checksum {
    h: u64,
    /// Bytes fed so far.
    at: u64,
    /// The bytes of an unfinished word.
    pending: [u8; 8],
    pending_len: usize,
}

impl Checksum {
    const START: u64 = 0xCBF2_9CE4_8422_2325;
    const PRIME: u64 = 0x0000_0100_0000_01B3;

    fn new() -> Self {
        Self {
            h: Self::START,
            at: 0,
            pending: [0; 8],
            pending_len: 0,
        }
    }

    #[inline]
    fn word(&mut self, w: u64) {
        // The word at byte 56 is the checksum field itself, read as 0.
        let w = if self.at == CHECKSUM_AT as u64 { 0 } else { w };
        self.h = (self.h ^ w).wrapping_mul(Self::PRIME);
        self.at += 8;
    }

    fn feed(&mut self, mut bytes: &[u8]) {
        while self.pending_len > 0 && !bytes.is_empty() {
            self.pending[self.pending_len] = bytes[0];
            self.pending_len += 1;
            bytes = &bytes[1..];
            if self.pending_len == 8 {
                self.pending_len = 0;
                self.word(u64::from_le_bytes(self.pending));
            }
        }
        let mut words = bytes.chunks_exact(8);
        for w in &mut words {
            self.word(u64::from_le_bytes(w.try_into().expect("8 bytes")));
        }
        for &b in words.remainder() {
            self.pending[self.pending_len] = b;
            self.pending_len += 1;
        }
    }

    fn finish(mut self) -> u64 {
        if self.pending_len > 0 {
            self.pending[self.pending_len..].fill(0);
            self.pending_len = 0;
            self.word(u64::from_le_bytes(self.pending));
        }
        self.h
    }
}

/// A container's elements as little-endian bytes.
trait LittleEndian {
    /// How many elements.
    fn count(&self) -> usize;
    /// Appends the bytes of elements `range` to `out`.
    fn put(&self, range: std::ops::Range<usize>, out: &mut Vec<u8>);
}

impl LittleEndian for &[DVec3] {
    fn count(&self) -> usize {
        self.len()
    }
    fn put(&self, range: std::ops::Range<usize>, out: &mut Vec<u8>) {
        for p in &self[range] {
            for x in p.to_array() {
                out.extend_from_slice(&x.to_le_bytes());
            }
        }
    }
}

macro_rules! little_endian_ids {
    ($($t:ty),*) => {$(
        impl LittleEndian for &[$t] {
            fn count(&self) -> usize {
                self.len()
            }
            fn put(&self, range: std::ops::Range<usize>, out: &mut Vec<u8>) {
                for x in &self[range] {
                    out.extend_from_slice(&x.to_le_bytes());
                }
            }
        }
    )*};
}
little_endian_ids!(u32, i32);

/// The containers of one CHE level, borrowed, to write as a `.che` file.
#[derive(Copy, Clone, Debug)]
pub struct Containers<'a> {
    /// The level, 0 to 3.
    pub level: u8,
    /// `G[]`.
    pub g: &'a [DVec3],
    /// `V[]`.
    pub v: &'a [u32],
    /// `O[]` (level 1 on; empty below).
    pub o: &'a [i32],
    /// `VH[]` (level 2 on; empty below).
    pub vh: &'a [i32],
    /// `EH` (level 2 on; empty below).
    pub eh: &'a [u32],
    /// `CH[]` (level 3; empty below).
    pub ch: &'a [u32],
    /// The number of edges, stated in the header at every level (`EH`'s length from level 2).
    pub edges: u64,
}

impl<'a> Containers<'a> {
    /// The containers of an owned level 0 (its edges counted by sorting, O(n log n)).
    pub fn level0(m: &'a crate::families::che::CheL0) -> Self {
        use crate::core::topology::MeshTopology;
        Self::geometry_and_corners(m, m.num_edges() as u64)
    }

    /// `G[]` and `V[]` of `m` and nothing else, with `edges` for the header: what every level
    /// starts from (the higher levels count their edges from `O[]` or `EH`, without the
    /// sort level 0 needs, which took a copy of every half-edge).
    fn geometry_and_corners(m: &'a crate::families::che::CheL0, edges: u64) -> Self {
        Self {
            level: 0,
            g: m.geometry(),
            v: crate::families::che::CheLevel::start_vertices(m),
            o: &[],
            vh: &[],
            eh: &[],
            ch: &[],
            edges,
        }
    }

    /// The containers of an owned level 1.
    pub fn level1(m: &'a crate::families::che::CheL1) -> Self {
        let o = m.opposite();
        let edges = o
            .iter()
            .enumerate()
            .filter(|&(he, &x)| x < 0 || (he as i64) < i64::from(x))
            .count() as u64;
        Self {
            level: 1,
            o,
            ..Self::geometry_and_corners(m.level0(), edges)
        }
    }

    /// The containers of an owned level 2.
    pub fn level2(m: &'a crate::families::che::CheL2) -> Self {
        Self {
            level: 2,
            vh: m.vertex_half_edge(),
            eh: m.edge_map(),
            edges: m.edge_map().len() as u64,
            ..Self::level1(m.level1())
        }
    }

    /// The containers of an owned level 3 (`O[]` with its curve labels).
    pub fn level3(m: &'a crate::families::che::CheL3) -> Self {
        Self {
            level: 3,
            ch: m.curve_half_edge(),
            ..Self::level2(m.level2())
        }
    }

    /// The header of these containers, its checksum not yet computed (0); refuses counts no
    /// `.che` file can state ([`Layout::of`]) or containers of the wrong lengths.
    fn header(&self) -> Result<Header, CheFileProblem> {
        let header = Header {
            level: self.level,
            vertices: self.g.len() as u64,
            triangles: (self.v.len() / 3) as u64,
            edges: self.edges,
            curves: self.ch.len() as u64,
            checksum: 0,
        };
        let layout = Layout::of(header)?;
        let lengths = [
            self.g.len(),
            self.v.len(),
            self.o.len(),
            self.vh.len(),
            self.eh.len(),
            self.ch.len(),
        ];
        for (c, len) in Container::ALL.into_iter().zip(lengths) {
            let expected = layout.section(c).map_or(0, |s| s.len);
            if len as u64 != expected {
                return Err(CheFileProblem::CountMismatch {
                    what: c.name(),
                    stated: expected,
                    found: len as u64,
                });
            }
        }
        Ok(header)
    }

    /// Lays the file out into `out`, a piece at a time (the header with `checksum`).
    fn emit(
        &self,
        checksum: u64,
        out: &mut impl FnMut(&[u8]) -> std::io::Result<()>,
    ) -> std::io::Result<()> {
        let header = Header {
            checksum,
            ..self.header().expect("checked by the caller")
        };
        out(&header.to_bytes())?;
        let mut at = HEADER_BYTES;
        let mut buffer: Vec<u8> = Vec::with_capacity(1 << 16);
        let mut section = |values: &dyn LittleEndian| -> std::io::Result<()> {
            for i in (0..values.count()).step_by(1024) {
                buffer.clear();
                values.put(i..(i + 1024).min(values.count()), &mut buffer);
                out(&buffer)?;
                at += buffer.len() as u64;
            }
            let padding = aligned(at).expect("bounded") - at;
            out(&[0u8; ALIGNMENT as usize][..padding as usize])?;
            at += padding;
            Ok(())
        };
        let stored: [(u8, &dyn LittleEndian); 6] = [
            (0, &self.g),
            (0, &self.v),
            (1, &self.o),
            (2, &self.vh),
            (2, &self.eh),
            (3, &self.ch),
        ];
        for (level, values) in stored {
            if self.level >= level {
                section(values)?;
            }
        }
        Ok(())
    }

    /// The whole file in memory (for tests and small meshes; [`Containers::write`] streams).
    pub fn to_bytes(&self) -> Result<Vec<u8>> {
        self.header().map_err(|p| p.at(Path::new("(memory)")))?;
        let mut bytes = Vec::new();
        let mut push = |b: &[u8]| {
            bytes.extend_from_slice(b);
            Ok(())
        };
        self.emit(0, &mut push).expect("writing to memory");
        let sum = checksum(&bytes);
        bytes[CHECKSUM_AT..CHECKSUM_AT + 8].copy_from_slice(&sum.to_le_bytes());
        Ok(bytes)
    }

    /// Writes the `.che` file `path` atomically ([`crate::io::write_atomically`]): the bytes are
    /// laid out twice, once into the checksum and once into the file.
    pub fn write(&self, path: &Path) -> Result<()> {
        self.header().map_err(|p| p.at(path))?;
        let mut sum = Checksum::new();
        let mut hash = |b: &[u8]| {
            sum.feed(b);
            Ok(())
        };
        self.emit(0, &mut hash).expect("hashing does not fail");
        let sum = sum.finish();
        crate::io::write_atomically(path, |w| {
            let mut write = |b: &[u8]| w.write_all(b);
            self.emit(sum, &mut write)
        })
        .map_err(|source| Error::Io {
            path: PathBuf::from(path),
            source,
        })
    }
}

/// Builds the owned CHE of `level` from `soup` and writes it to `path` as a `.che` file
/// ([`Containers::write`], atomically). Refuses a level other than 0–3 and what the level
/// refuses (polygons, non-manifold edges and vertices: the owned levels' typed errors).
pub fn write_mesh(soup: &PolygonSoup, level: u8, path: &Path) -> Result<()> {
    use crate::core::topology::MeshTopology;
    match level {
        0 => Containers::level0(&crate::families::che::CheL0::from_soup(soup)?).write(path),
        1 => Containers::level1(&crate::families::che::CheL1::from_soup(soup)?).write(path),
        2 => Containers::level2(&crate::families::che::CheL2::from_soup(soup)?).write(path),
        3 => Containers::level3(&crate::families::che::CheL3::from_soup(soup)?).write(path),
        _ => Err(Error::InvalidParameter {
            parameter: "level",
            value: level.to_string(),
            expected: "a CHE level: 0, 1, 2 or 3",
        }),
    }
}

/// An owned CHE level built from a soup it consumed ([`OwnedLevel::build`]), ready to be
/// written ([`OwnedLevel::write`]).
pub enum OwnedLevel {
    /// Level 0.
    L0(crate::families::che::CheL0),
    /// Level 1.
    L1(crate::families::che::CheL1),
    /// Level 2.
    L2(crate::families::che::CheL2),
    /// Level 3.
    L3(crate::families::che::CheL3),
}

impl OwnedLevel {
    /// The CHE of `level` built from `soup`, consumed: its positions and corners become
    /// `G[]` and `V[]` without a copy, so the soup and the structure are never held at once
    /// (the peak is the level's containers and its construction's temporaries). Refuses what
    /// the level's `from_soup` refuses, alike, and a level other than 0–3.
    pub fn build(soup: PolygonSoup, level: u8) -> Result<Self> {
        use crate::core::topology::MeshTopology;
        use crate::families::che::{CheL0, CheL1, CheL2, CheL3};
        Ok(match level {
            0 => Self::L0(CheL0::from_soup_owned(soup)?),
            1 => Self::L1(CheL1::from_soup_owned(soup)?),
            2 => Self::L2(CheL2::from_soup_owned(soup)?),
            3 => Self::L3(CheL3::from_soup_owned(soup)?),
            _ => {
                return Err(Error::InvalidParameter {
                    parameter: "level",
                    value: level.to_string(),
                    expected: "a CHE level: 0, 1, 2 or 3",
                })
            }
        })
    }

    /// Writes the level's containers to `path` ([`Containers::write`], atomically).
    pub fn write(&self, path: &Path) -> Result<()> {
        match self {
            Self::L0(m) => Containers::level0(m),
            Self::L1(m) => Containers::level1(m),
            Self::L2(m) => Containers::level2(m),
            Self::L3(m) => Containers::level3(m),
        }
        .write(path)
    }
}

/// [`write_mesh`] consuming the soup ([`OwnedLevel::build`]): the same file, byte for byte,
/// without holding the soup and the structure at once. What `topolab convert --to che` writes.
pub fn write_mesh_owned(soup: PolygonSoup, level: u8, path: &Path) -> Result<()> {
    OwnedLevel::build(soup, level)?.write(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_soup_consumed_writes_the_same_file_and_refuses_alike() {
        let dir = std::env::temp_dir().join(format!("topolab-che-owned-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        for soup in [crate::meshes::torus(8, 5), crate::meshes::grid(6, 4, true)] {
            for level in 0..=3 {
                let (a, b) = (dir.join("a.che"), dir.join("b.che"));
                write_mesh(&soup, level, &a).unwrap();
                write_mesh_owned(soup.clone(), level, &b).unwrap();
                assert_eq!(
                    std::fs::read(&a).unwrap(),
                    std::fs::read(&b).unwrap(),
                    "level {level}"
                );
            }
        }
        // A non-manifold edge (three triangles on one edge) and a quad: the same refusals.
        let fan = PolygonSoup::from_polygons(
            vec![glam::DVec3::ZERO; 5],
            &[[0u32, 1, 2], [1, 0, 3], [0, 1, 4]],
        );
        let quad = PolygonSoup::from_polygons(vec![glam::DVec3::ZERO; 4], &[[0u32, 1, 2, 3]]);
        for soup in [fan, quad] {
            let path = dir.join("bad.che");
            let a = write_mesh(&soup, 2, &path).unwrap_err().to_string();
            let b = write_mesh_owned(soup, 2, &path).unwrap_err().to_string();
            assert_eq!(a, b);
            assert!(!path.exists());
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    fn header(level: u8) -> Header {
        Header {
            level,
            vertices: 4,
            triangles: 3,
            edges: 6,
            curves: if level == 3 { 1 } else { 0 },
            checksum: 0,
        }
    }

    #[test]
    fn containers_start_at_multiples_of_64_in_file_order() {
        let layout = Layout::of(header(3)).unwrap();
        // G: 4 · 24 = 96 bytes from 64 → 160, padded to 192; V: 9 · 4 = 36 → 228 → 256;
        // O → 320; VH: 16 bytes → 384; EH: 24 bytes → 448; CH: 4 bytes → 512.
        let offsets: Vec<u64> = Container::ALL
            .iter()
            .map(|&c| layout.section(c).unwrap().offset)
            .collect();
        assert_eq!(offsets, [64, 192, 256, 320, 384, 448]);
        assert_eq!(layout.file_bytes, 512);
        let level1 = Layout::of(header(1)).unwrap();
        assert_eq!(level1.section(Container::VH), None);
        assert_eq!(level1.file_bytes, 320);
    }

    #[test]
    fn the_header_reads_back_and_refuses_what_it_does_not_know() {
        let h = Header {
            checksum: 0x1234,
            ..header(2)
        };
        let bytes = h.to_bytes();
        assert_eq!(Header::parse(&bytes), Ok(h));
        assert_eq!(
            Header::parse(&bytes[..63]),
            Err(CheFileProblem::Short { bytes: 63 })
        );
        let mut b = bytes;
        b[1] = b'X';
        assert_eq!(Header::parse(&b), Err(CheFileProblem::WrongMagic));
        let mut b = bytes;
        b[8..12].copy_from_slice(&BYTE_ORDER_MARK.to_be_bytes());
        assert_eq!(Header::parse(&b), Err(CheFileProblem::BigEndian));
        let mut b = bytes;
        b[12] = 2;
        assert_eq!(
            Header::parse(&b),
            Err(CheFileProblem::UnknownVersion { found: 2 })
        );
        let mut b = bytes;
        b[16] = 9;
        assert_eq!(
            Header::parse(&b),
            Err(CheFileProblem::UnknownLevel { found: 9 })
        );
        let mut b = bytes;
        b[21] = 1;
        assert_eq!(
            Header::parse(&b),
            Err(CheFileProblem::ReservedNotZero { at: 20 })
        );
    }

    #[test]
    fn impossible_counts_and_wrong_lengths_are_refused() {
        let too_many = Header {
            triangles: u64::MAX,
            ..header(1)
        };
        assert!(matches!(
            Layout::of(too_many),
            Err(CheFileProblem::ImpossibleCounts { .. })
        ));
        let curves_at_level_2 = Header {
            curves: 1,
            ..header(2)
        };
        assert!(matches!(
            Layout::of(curves_at_level_2),
            Err(CheFileProblem::ImpossibleCounts { .. })
        ));
        let bytes = header(2).to_bytes();
        assert_eq!(
            Layout::of_file(&bytes, 64),
            Err(CheFileProblem::LengthMismatch {
                expected: 448,
                actual: 64
            })
        );
    }

    #[test]
    fn the_checksum_ignores_its_own_field_and_sees_any_one_word() {
        let mut bytes = vec![0u8; 128];
        let base = checksum(&bytes);
        bytes[CHECKSUM_AT] = 7;
        assert_eq!(checksum(&bytes), base, "the checksum field is read as 0");
        bytes[CHECKSUM_AT] = 0;
        for at in (0..128).filter(|at| !(CHECKSUM_AT..CHECKSUM_AT + 8).contains(at)) {
            let mut flipped = bytes.clone();
            flipped[at] ^= 1;
            assert_ne!(checksum(&flipped), base, "byte {at}");
        }
        // Fed piece by piece as in one piece.
        let data: Vec<u8> = (0..200u32).map(|i| (i * 37) as u8).collect();
        let mut h = Checksum::new();
        for piece in data.chunks(13) {
            h.feed(piece);
        }
        assert_eq!(h.finish(), checksum(&data));
    }
}
