//! What a request needs, checked before the work: every command that generates, reads, refines
//! or measures something large asks here first, and a request that cannot fit is refused with
//! one line and exit code 2 instead of running until the ids overflow or the memory is gone.
//!
//! Two limits:
//! - **ids**: the lab numbers vertices, faces and corners with `u32` ids, so no count may reach
//!   `u32::MAX` ([`within_u32`]). Nothing overrides this: such a mesh cannot be stored.
//! - **memory**: the estimated peak heap of the request against the memory the system has
//!   available ([`available`]: `MemAvailable` of `/proc/meminfo`, or less under a container's
//!   cgroup limit).
//!   `--allow-memory` ([`set_allow_memory`]) overrides this one: the estimate may be pessimistic,
//!   and swap or a smaller real mesh may make it fit.
//!
//! **The estimates.** A mesh's own arrays are counted exactly ([`MeshSize::soup_bytes`]). What
//! a command builds from it (a structure, an edge analysis, the text of `explain`, a hull, a
//! refined level) is *measured*, not guessed: [`peak_of`] runs the command's own work on a
//! small sample ([`sample_mesh`], [`SAMPLE_POINTS`] points for hulls) under the process's
//! counting allocator and scales its peak linearly to the request. So the estimate is the
//! bytes per corner of the structure being built (per point of the hull), as this build
//! allocates them; fixed costs of the sample make it err on the large side for small
//! requests, which are not checked at all (no larger than the sample). The C++ baselines'
//! heap (OpenMesh's, CGAL's) is in that peak too: their `operator new` counts with the same
//! switch ([`crate::alloc`]).
//! Decimation, when it exists, goes through the same checks.

use crate::failure::Failure;
use crate::registry::{self, StructureVisitor};
use std::sync::atomic::{AtomicBool, Ordering};
pub use topolab_harness::measuring::memory::{
    available, human, memory_cgroup, sample_mesh, scale, CgroupVersion,
};
use topolab_structures::meshes::{self, MeshSize};
use topolab_structures::{MeshTopology, PolygonSoup};

/// Set by `--allow-memory`: go on when the estimate exceeds the available memory.
static ALLOW_MEMORY: AtomicBool = AtomicBool::new(false);

/// `--allow-memory`: when `true`, [`admit`] lets requests above the available memory run (the
/// id limit still holds).
pub fn set_allow_memory(allow: bool) {
    ALLOW_MEMORY.store(allow, Ordering::Relaxed);
}

/// Points of the sample a hull's memory is measured on.
pub const SAMPLE_POINTS: usize = 2048;

/// Refuses (exit code 2) a request whose estimated peak heap `bytes` exceeds the available
/// memory, unless `--allow-memory` was given; `what` names the request as the user wrote it.
pub fn admit(what: &str, bytes: u64) -> Result<(), Failure> {
    let Some(free) = exceeds_available(bytes) else {
        return Ok(());
    };
    Err(Failure::usage(format!(
        "{what} needs about {} of memory, more than the {} available; --allow-memory runs it anyway",
        human(bytes),
        human(free)
    )))
}

/// The memory available, when `bytes` exceed it and `--allow-memory` was not given: the reason
/// to refuse a request of `bytes`. `None`: go on (it fits, it is allowed, or nothing can be
/// read).
pub fn exceeds_available(bytes: u64) -> Option<u64> {
    if ALLOW_MEMORY.load(Ordering::Relaxed) {
        return None;
    }
    available().filter(|&free| bytes > free)
}

/// How many elements of `bytes_per_element` bytes each the available memory holds: the cap a
/// command that grows a mesh step by step (adaptive refinement, whose final size is known only
/// as a lower bound) passes to its algorithm. `None` when nothing caps it: `--allow-memory`, or
/// no available memory to read.
pub fn affordable(bytes_per_element: u64) -> Option<u64> {
    if ALLOW_MEMORY.load(Ordering::Relaxed) {
        return None;
    }
    available().map(|free| free / bytes_per_element.max(1))
}

/// The most triangles `u32` ids number: three corner (half-edge) ids per triangle, each below
/// `u32::MAX`, so about 1.43 billion triangles, whatever the structure (the vertices, about
/// half the triangles, stay far below).
pub const MAX_TRIANGLES: u64 = topolab_harness::scale::ID_LIMIT_TRIANGLES;

/// [`MAX_TRIANGLES`] as the refusals say it.
const MAX_TRIANGLES_TEXT: &str =
    "a triangle mesh of at most 1.43 billion triangles, three corner ids each";

/// Refuses (exit code 2) counts that `u32` ids cannot number: each must be below `u32::MAX`,
/// the limit [`PolygonSoup::check`] enforces. `counts` pairs a name (`corners`, `points`) with
/// a count (saturated: `u128::MAX` for "more than anything").
pub fn within_u32(what: &str, counts: &[(&str, u128)]) -> Result<(), Failure> {
    match counts.iter().find(|(_, n)| *n >= u32::MAX as u128) {
        None => Ok(()),
        Some((name, n)) => Err(Failure::usage(format!(
            "{what} makes {} {name}, more than u32 ids number (at most {}: {}); no option allows it",
            if *n == u128::MAX {
                "more than 2^128".to_string()
            } else {
                n.to_string()
            },
            u32::MAX - 1,
            MAX_TRIANGLES_TEXT
        ))),
    }
}

/// [`within_u32`] for a mesh's counts.
pub fn mesh_within_u32(what: &str, size: &MeshSize) -> Result<(), Failure> {
    within_u32(
        what,
        &[
            ("vertices", size.vertices.into()),
            ("faces", size.faces.into()),
            ("corners", size.corners.into()),
        ],
    )
}

/// The second sample of the work that a mesh of more vertices an element than
/// [`sample_mesh`] weighs more on (a component, three vertices and a grid cell of their own a
/// face: `check`'s findings, the CHE's containers): 4,050 separate triangles, a unit apart. A
/// command measured on both scales the larger of the two peaks per element.
pub fn separate_triangles() -> PolygonSoup {
    let n = 4050u32;
    let positions = (0..3 * n)
        .map(|i| {
            glam::DVec3::new(
                (i / 3) as f64,
                (i % 3 == 1) as u8 as f64,
                (i % 3 == 2) as u8 as f64,
            )
        })
        .collect();
    let faces: Vec<[u32; 3]> = (0..n).map(|t| [3 * t, 3 * t + 1, 3 * t + 2]).collect();
    PolygonSoup::from_polygons(positions, &faces)
}

/// The peak heap `work` allocates beyond what was allocated when it started, in bytes, as the
/// process's counting allocator ([`crate::ALLOCATOR`]) sees it, C++'s allocations included.
/// `work` must allocate on the calling thread: the allocator counts one thread's bytes.
pub fn peak_of<T>(work: impl FnOnce() -> T) -> (T, u64) {
    let (out, peak) = crate::ALLOCATOR.measure(work);
    (out, peak as u64)
}

/// What a text built by appending may take beyond what a sample of it measured: a `String`
/// doubles its buffer as it grows, so the peak of a text of length L lies between L and 3L (the
/// old buffer and the new one, twice as large, during the last copy), and where in that range
/// depends on how L falls between powers of two. Adding `2 × text.len()` to the sample's
/// measured peak (at least L) makes it cover 3L at any length.
pub fn growing_text(text: &str) -> u64 {
    2 * text.len() as u64
}

/// What a command's measured work is scaled by: the mesh's vertices, faces and corners
/// together. Per corner alone, a file of millions of faces without corners would count as
/// nothing, yet every check keeps something per face.
pub fn elements(size: &MeshSize) -> u64 {
    size.vertices
        .saturating_add(size.faces)
        .saturating_add(size.corners)
}

/// Builds a structure twice at once, as `report` does (the measured build, kept, and a timed
/// rebuild).
struct TwoBuilds<'a>(&'a PolygonSoup);
impl StructureVisitor for TwoBuilds<'_> {
    type Output = ();
    fn visit<M: MeshTopology>(self) {
        let both = (M::from_soup(self.0), M::from_soup(self.0));
        drop(std::hint::black_box(both));
    }
}

/// `topolab report`'s request, checked before the memory probe: every size a triangle count
/// from 1 to [`meshes::MAX_FACES`] that each family generates within `u32` ids, and the memory
/// of the run below what is available. The report holds every generated mesh at once, and
/// measures one structure at a time on each: its peak is the larger of the probe's array
/// (`probe_mb` MiB, freed before the meshes are made) and all the meshes plus two builds of the
/// largest structure on the largest mesh (measured on [`sample_mesh`] and scaled by corners).
/// The real meshes of `bench-data/cache/` (at most 64 MB of file each) and the hull benchmark
/// (at most 1M points, about 0.3 GB) are not counted.
pub fn admit_report(
    sizes: &[usize],
    families: &[&str],
    structures: &[String],
    probe_mb: usize,
) -> Result<(), Failure> {
    let mut meshes_bytes = 0u64;
    let mut largest = 0u64;
    for &size in sizes {
        let bad = || {
            Failure::usage(format!(
                "--sizes {size}: a size is a triangle count from 1 to {} (the generated meshes number their elements with u32 ids)",
                meshes::MAX_FACES
            ))
        };
        if size == 0 {
            return Err(bad());
        }
        for family in families.iter().filter(|f| **f != "real") {
            let spec = meshes::parse_spec(&format!("{family}:{size}")).map_err(|_| bad())?;
            let mesh = spec.size();
            meshes_bytes = meshes_bytes.saturating_add(mesh.soup_bytes());
            largest = largest.max(mesh.corners);
        }
    }
    let sample = sample_mesh();
    let sample_corners = sample.num_corners() as u64;
    let per_structure = structures.iter().map(|name| {
        let (_, peak) = peak_of(|| registry::visit(name, TwoBuilds(&sample)));
        scale(peak, sample_corners, largest)
    });
    let measured = meshes_bytes.saturating_add(per_structure.max().unwrap_or(0));
    let probe = (probe_mb as u64) << 20;
    let largest_size = sizes.iter().max().copied().unwrap_or(0);
    admit(
        &format!(
            "the report ({} sizes up to {largest_size} triangles, {} structures)",
            sizes.len(),
            structures.len()
        ),
        measured.max(probe),
    )
}

/// The estimated peak of reading a file of `file_bytes` bytes that is not a mesh (a collapse
/// record): the file's bytes and what is parsed from them, up to three times as large.
pub fn read_bytes(file_bytes: u64) -> u64 {
    file_bytes.saturating_mul(4)
}

/// The peak of reading the mesh file `path` of `file_bytes` bytes, bounded from its format and
/// its first 64 KiB (its header): [`topolab_structures::io::read_peak_bound`], at most 5 times
/// the file (8 for a binary PLY of one-byte coordinates, read a window at a time). A file whose format is not known by
/// its name counts as the largest.
pub fn read_mesh_bytes(path: &std::path::Path, file_bytes: u64) -> u64 {
    use std::io::Read;
    let mut head = Vec::new();
    let _ = std::fs::File::open(path).and_then(|f| f.take(64 << 10).read_to_end(&mut head));
    match topolab_structures::io::format_of(path) {
        Ok(format) => topolab_structures::io::read_peak_bound(format, &head, file_bytes),
        Err(_) => file_bytes.saturating_mul(9),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_at_u32_max_are_refused_and_below_accepted() {
        assert!(within_u32("x", &[("corners", u32::MAX as u128 - 1)]).is_ok());
        let e = within_u32(
            "--levels 20",
            &[("faces", 1), ("corners", u32::MAX as u128)],
        )
        .unwrap_err();
        assert_eq!(e.code, 2);
        assert!(
            e.message
                .starts_with("--levels 20 makes 4294967295 corners"),
            "{}",
            e.message
        );
        let e = within_u32("x", &[("points", u128::MAX)]).unwrap_err();
        assert!(
            e.message.contains("more than 2^128 points"),
            "{}",
            e.message
        );
    }

    #[test]
    fn the_estimate_is_refused_above_the_available_memory_unless_allowed() {
        let Some(free) = available() else { return };
        assert!(free > 0);
        assert!(admit("small", 1).is_ok());
        let e = admit("torus:N", u64::MAX).unwrap_err();
        assert_eq!(e.code, 2);
        assert!(
            e.message.starts_with("torus:N needs about"),
            "{}",
            e.message
        );
        assert!(e.message.contains("--allow-memory"), "{}", e.message);
    }

    #[test]
    fn scaling_rounds_up_and_saturates() {
        assert_eq!(scale(10, 3, 1), 4);
        assert_eq!(scale(12, 4, 8), 24);
        assert_eq!(scale(u64::MAX, 1, 2), u64::MAX);
        assert_eq!(human(1_500_000_000), "1.5 GB");
        assert_eq!(human(320_000_000), "320.0 MB");
        assert_eq!(human(12), "12 bytes");
    }
}
