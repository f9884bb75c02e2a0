//! The memory mapping of a `.che` file and its containers read as typed slices: the unsafe
//! code of the mapped CHE, all of it here (the unchecked walk it may use after a verification
//! is the owned CHE's, in `fan.rs`).
//!
//! Why reading the containers in place is sound:
//!
//! - **Read-only.** The file is opened for reading and mapped read-only (`PROT_READ`): nothing
//!   in this process can write through the mapping.
//! - **Lengths.** [`Layout::of_file`] checks that the mapping's length is exactly the length
//!   the header's counts lay out, and every section lies inside that layout, so each slice
//!   lies inside the mapping.
//! - **Alignment.** Every section starts at a multiple of 64 bytes from the start of the
//!   mapping ([`ALIGNMENT`]), and the mapping's address is checked to be a multiple of 64 too
//!   (it is page-aligned on every system the lab runs on), so each element is aligned for
//!   `u32`, `i32` and `DVec3` (at most 8).
//! - **Values.** `u32`, `i32` and `DVec3` (three `f64`, `#[repr(C)]`, no padding) are valid
//!   for every bit pattern ([`Plain`]), so any bytes read as them are values. Whether they are
//!   a mesh is checked by `check`/`verify`, never assumed by a bounds-checked read.
//! - **Byte order.** The file is little-endian; a big-endian machine is refused.
//!
//! What it cannot guard against, as `memmap2` says of every mapping (`Mmap::map` is `unsafe`
//! for this reason): **another process changing or truncating the file while it is mapped.**
//! The slices would then change under their shared borrows (undefined behaviour in Rust's
//! rules), a truncation ends the process with `SIGBUS` on the next read of a lost page, and a
//! change after `verify` breaks the range promise of the unchecked walk. Not changing a
//! `.che` file while it is open is the user's responsibility; `topolab` only ever replaces one
//! by renaming a new file over it, which leaves an open mapping on the old file's pages.

#![allow(unsafe_code)]

use crate::core::error::{Error, Result};
use crate::families::che::file::{CheFileProblem, Container, Layout, ALIGNMENT, HEADER_BYTES};
use glam::DVec3;
use memmap2::Mmap;
use std::fs::File;
use std::path::Path;

/// Element types that any bytes are a valid value of: no padding, no invalid bit pattern.
///
/// # Safety
///
/// Implement only for such types.
unsafe trait Plain: Copy {}
// SAFETY: integers have no padding and no invalid bit pattern.
unsafe impl Plain for u32 {}
// SAFETY: as for `u32`.
unsafe impl Plain for i32 {}
// SAFETY: `DVec3` is `#[repr(C)]` with three `f64` fields and no padding (size 24, checked
// below); every bit pattern of an `f64` is a value (NaNs included).
unsafe impl Plain for DVec3 {}
const _: () = assert!(std::mem::size_of::<DVec3>() == 24 && std::mem::align_of::<DVec3>() <= 8);

/// A `.che` file mapped read-only, its layout checked against its length.
pub(crate) struct Mapping {
    map: Mmap,
    layout: Layout,
}

impl Mapping {
    /// Maps `path` and checks its header and length (O(1): only the header's bytes are read).
    pub(crate) fn open(path: &Path) -> Result<Self> {
        if cfg!(target_endian = "big") {
            return Err(CheFileProblem::BigEndianMachine.at(path));
        }
        let io = |source| Error::Io {
            path: path.to_path_buf(),
            source,
        };
        let file = File::open(path).map_err(io)?;
        let bytes = file.metadata().map_err(io)?.len();
        if bytes < HEADER_BYTES {
            // Also spares mapping an empty file, which some systems refuse.
            return Err(CheFileProblem::Short { bytes }.at(path));
        }
        // SAFETY: the mapping is read-only and every later read of it goes through `section`,
        // whose bounds and alignment are checked below against the mapping itself (not the
        // length read above). That the file is not changed while mapped is the user's
        // responsibility (see the module docs), as `memmap2` documents for every mapping.
        let map = unsafe { Mmap::map(&file) }.map_err(io)?;
        let layout = Layout::of_file(&map, map.len() as u64).map_err(|p| p.at(path))?;
        if !(map.as_ptr() as usize).is_multiple_of(ALIGNMENT as usize) {
            return Err(CheFileProblem::Misaligned.at(path));
        }
        Ok(Self { map, layout })
    }

    /// The layout (header and offsets).
    pub(crate) fn layout(&self) -> &Layout {
        &self.layout
    }

    /// The whole file's bytes (for the checksum).
    pub(crate) fn bytes(&self) -> &[u8] {
        &self.map
    }

    /// Container `c` as a slice of `T` (empty if the level does not store it).
    fn section<T: Plain>(&self, c: Container) -> &[T] {
        let Some(s) = self.layout.section(c) else {
            return &[];
        };
        assert_eq!(std::mem::size_of::<T>() as u64, c.element_bytes());
        // `Layout::of_file` made the mapping's length the layout's, which contains the section.
        let (start, len) = (s.offset as usize, s.len as usize);
        debug_assert!(start + len * std::mem::size_of::<T>() <= self.map.len());
        // SAFETY: the section lies inside the mapping (its length was checked against the
        // layout in `open`), starts at a multiple of 64 bytes from a mapping address that is
        // a multiple of 64 (checked in `open`), so it is aligned for `T` (alignment at most 8);
        // `T: Plain` makes any bytes valid `T`s; the mapping is read-only and lives as long as
        // `self`, which the returned borrow cannot outlive.
        unsafe { std::slice::from_raw_parts(self.map.as_ptr().add(start).cast::<T>(), len) }
    }

    /// `G[]`.
    pub(crate) fn g(&self) -> &[DVec3] {
        self.section(Container::G)
    }

    /// `V[]`.
    pub(crate) fn v(&self) -> &[u32] {
        self.section(Container::V)
    }

    /// `O[]` (empty at level 0).
    pub(crate) fn o(&self) -> &[i32] {
        self.section(Container::O)
    }

    /// `VH[]` (empty below level 2).
    pub(crate) fn vh(&self) -> &[i32] {
        self.section(Container::VH)
    }

    /// `EH` (empty below level 2).
    pub(crate) fn eh(&self) -> &[u32] {
        self.section(Container::EH)
    }

    /// `CH[]` (empty below level 3).
    pub(crate) fn ch(&self) -> &[u32] {
        self.section(Container::CH)
    }
}
