//! The `.che` format's constants, its containers by name and the problems a file can have:
//! what [`crate::core::error::Error::CheFile`] carries. The reading and writing, which build
//! the CHE levels, are the CHE's own ([`crate::che::file`]); these definitions stand here, below
//! every structure, so that the crate's one error type names them without depending on the CHE.

/// The first 8 bytes of every `.che` file: `0x89 'C' 'H' 'E' '\r' '\n' 0x1A '\n'`. As PNG's
/// signature does, the first byte is not ASCII and the line endings and end-of-file character
/// after the name show a file that went through a text-mode transfer.
pub const MAGIC: [u8; 8] = [0x89, b'C', b'H', b'E', b'\r', b'\n', 0x1A, b'\n'];

/// The format version this build reads and writes.
pub const VERSION: u32 = 1;

/// The byte-order mark at byte 8, a `u32` written little-endian: bytes `0D 0C 0B 0A`.
pub const BYTE_ORDER_MARK: u32 = 0x0A0B_0C0D;

/// The header's length, and so the offset of the first container.
pub const HEADER_BYTES: u64 = 64;

/// Every container starts at a multiple of this many bytes (a cache line, and a multiple of
/// every element's alignment).
pub const ALIGNMENT: u64 = 64;

/// Where the checksum is stored in the header (a `u64`).
pub(crate) const CHECKSUM_AT: usize = 56;

/// A container of the CHE, in file order.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Container {
    /// `G[v]`: the position of each vertex, three `f64` (24 bytes).
    G,
    /// `V[he]`: the start vertex of each half-edge, `u32`.
    V,
    /// `O[he]`: the opposite half-edge, `i32`, negative on the boundary (level 1 on).
    O,
    /// `VH[v]`: a half-edge leaving each vertex, `i32`, `-1` for an unused vertex (level 2 on).
    VH,
    /// `EH`: each edge's smaller half-edge, in increasing order, `u32` (level 2 on).
    EH,
    /// `CH[k-1]`: a half-edge of boundary curve k, `u32` (level 3).
    CH,
}

impl Container {
    /// Every container, in file order.
    pub const ALL: [Container; 6] = [
        Container::G,
        Container::V,
        Container::O,
        Container::VH,
        Container::EH,
        Container::CH,
    ];

    /// The chapter's name (`"G"`, `"V"`, ...).
    pub const fn name(self) -> &'static str {
        match self {
            Container::G => "G",
            Container::V => "V",
            Container::O => "O",
            Container::VH => "VH",
            Container::EH => "EH",
            Container::CH => "CH",
        }
    }

    /// Bytes per element.
    pub const fn element_bytes(self) -> u64 {
        match self {
            Container::G => 24,
            _ => 4,
        }
    }

    /// The lowest CHE level that stores it.
    pub const fn first_level(self) -> u8 {
        match self {
            Container::G | Container::V => 0,
            Container::O => 1,
            Container::VH | Container::EH => 2,
            Container::CH => 3,
        }
    }

    pub(crate) fn index(self) -> usize {
        self as usize
    }
}

impl std::fmt::Display for Container {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}[]", self.name())
    }
}

/// Why a `.che` file was refused: each a typed case of [`crate::core::error::Error::CheFile`].
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum CheFileProblem {
    /// Fewer bytes than the header.
    #[error("{bytes} bytes, shorter than the {HEADER_BYTES}-byte header")]
    Short {
        /// The file's length.
        bytes: u64,
    },
    /// The first 8 bytes are not [`MAGIC`].
    #[error("not a .che file: its first bytes are not the .che magic")]
    WrongMagic,
    /// The byte-order mark reads as big-endian.
    #[error("written big-endian; the format is little-endian")]
    BigEndian,
    /// The byte-order mark is neither order.
    #[error("byte-order mark {found:#010x} is not {BYTE_ORDER_MARK:#010x}")]
    BadByteOrderMark {
        /// What bytes 8–11 hold, read little-endian.
        found: u32,
    },
    /// A format version this build does not read.
    #[error("format version {found}; this build reads version {VERSION}")]
    UnknownVersion {
        /// The version in the header.
        found: u32,
    },
    /// A level other than 0–3.
    #[error("CHE level {found}; the levels are 0 to 3")]
    UnknownLevel {
        /// The level in the header.
        found: u32,
    },
    /// A header field that must be zero is not.
    #[error("reserved header bytes {at}..{} are not zero", at + 4)]
    ReservedNotZero {
        /// Its offset.
        at: usize,
    },
    /// Counts no CHE can have: more half-edges or vertices than `i32` numbers, more edges than
    /// half-edges, boundary curves below level 3.
    #[error("impossible counts: {reason}")]
    ImpossibleCounts {
        /// Which count and why.
        reason: String,
    },
    /// The file's length is not what its counts lay out.
    #[error("{actual} bytes, but its counts lay out {expected} bytes")]
    LengthMismatch {
        /// What the counts lay out ([`Layout::file_bytes`](crate::che::file::Layout::file_bytes)).
        expected: u64,
        /// The file's length.
        actual: u64,
    },
    /// The mapped bytes do not start at an address aligned for the containers (never on the
    /// systems the lab runs on: mappings start at a page boundary).
    #[error("mapped at an address not aligned to {ALIGNMENT} bytes")]
    Misaligned,
    /// This machine is big-endian; the containers are mapped as they are stored.
    #[error("mapping a .che file needs a little-endian machine")]
    BigEndianMachine,
    /// The checksum of the file's bytes is not the one in its header.
    #[error("checksum mismatch: the header says {stored:#018x}, the bytes give {computed:#018x}")]
    ChecksumMismatch {
        /// The header's.
        stored: u64,
        /// The file's bytes'.
        computed: u64,
    },
    /// A container holds an id outside the range its level allows.
    #[error("{container}[{index}] = {value} is out of range ({allowed})")]
    IdOutOfRange {
        /// The container.
        container: Container,
        /// The entry.
        index: u64,
        /// Its value.
        value: i64,
        /// What it may be.
        allowed: String,
    },
    /// A header count that the containers contradict (checked by `check`: the edges of levels
    /// 0 and 1, which store no `EH`).
    #[error("the header says {what} {stated}, the containers give {found}")]
    CountMismatch {
        /// Which count.
        what: &'static str,
        /// The header's.
        stated: u64,
        /// The containers'.
        found: u64,
    },
    /// The file is a `.che` of another level than the one asked for.
    #[error("a level-{found} CHE, not level {expected}")]
    WrongLevel {
        /// The level asked for.
        expected: u8,
        /// The file's.
        found: u8,
    },
}
