//! # Qhull in-process (through FFI): the report's reference 3D convex hull
//!
//! [Qhull](http://www.qhull.org) through its reentrant C library (`libqhull_r`, Debian's
//! `libqhull-dev`; [`version`] names the one linked) and the C shim `qhull/shim.c`, called the
//! way SciPy's `scipy.spatial.ConvexHull` calls it (`scipy/spatial/_qhull.pyx`): the command
//! [`COMMAND`], `qh_new_qhull` on the points as given, the hull's vertices those of its
//! triangles. SciPy 1.17 (the `.venv`'s) bundles the same Qhull release (`qhull_r` 8.0.2,
//! 2020.2), so the two build the same hull; the tests check it (`baselines/tests/qhull.rs`).
//!
//! [`convex_hull`] runs Qhull once and returns the shim's clock: `qh_new_qhull` (build, merge,
//! triangulate) and the walk that collects the vertex ids, the way the lab's hull algorithms
//! are timed around building their output. Copying the points, the volume (`qh_getarea`) and
//! freeing the hull are outside it, as dropping the lab's hull is. The harness's hull benchmark
//! times it (through [`crate::hulls`]) as it times the lab's: a warm-up run, then the median of
//! its timed runs, one FFI call each (the clock is read inside the shim, so the FFI is not
//! timed).
//!
//! The FFI is a wall: the shim is C, so nothing unwinds; Qhull's errors (the exit code of
//! `qh_new_qhull`, which catches its own `longjmp`, and a `setjmp` of the shim's around
//! `qh_getarea` after it) come back as status codes and become [`QhullError`], with what Qhull
//! wrote to its error file. Qhull calls `exit` only on a misuse, which the shim does not commit
//! (a command not starting with `qhull `, an error raised with no `setjmp` armed), or on an
//! error while it reports another. State:
//! `libqhull_r` keeps all of its state in the `qhT` its caller passes ("All global variables
//! for qhull are in qhT", `libqhull_r.h`), and the shim makes and frees one per call, so there
//! is no process-wide state to set up and threads may call in parallel (`baselines/tests/qhull.rs` does).

use glam::DVec3;
use std::ffi::{c_char, CStr};
use std::fmt;

/// Qhull's command line: SciPy's for `ConvexHull` below five dimensions, mode `i` and the
/// always-required `Qt` (triangulated output), no other option; `TOPOLAB_QHULL_COMMAND` of
/// `qhull/shim.h` (a test reads it there). Qhull's defaults then merge coplanar facets, so the
/// hull's vertices are its extreme points, as the lab's algorithms return them.
pub const COMMAND: &str = "qhull i Qt";

/// The declarations of `qhull/shim.h`.
mod ffi {
    use std::ffi::c_char;

    extern "C" {
        pub fn topolab_qhull_convex_hull(
            xyz: *const f64,
            n: u32,
            seconds: *mut f64,
            vertices: *mut u32,
            vertex_count: *mut u32,
            facet_count: *mut u32,
            volume: *mut f64,
            message: *mut c_char,
            message_capacity: usize,
        ) -> i32;
        pub fn topolab_qhull_version() -> *const c_char;
    }
}

/// Room for Qhull's error message (its messages run to a few hundred bytes; longer ones are
/// cut).
const MESSAGE_CAPACITY: usize = 4096;

/// What Qhull built, once.
#[derive(Clone, Debug, PartialEq)]
pub struct QhullHull {
    /// The shim's clock: `qh_new_qhull` and collecting the vertex ids, seconds.
    pub seconds: f64,
    /// Input indices of the hull's vertices, increasing (sorted after the clock).
    pub vertices: Vec<u32>,
    /// Triangles of the hull (SciPy's `simplices`).
    pub facets: usize,
    /// Qhull's volume of the hull (`qh_getarea`, SciPy's `volume`).
    pub volume: f64,
}

/// Why Qhull refused a point set: its exit codes (`qh_ERRinput` … `qh_ERRdebug` of
/// `libqhull_r.h`).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Failure {
    /// `qh_ERRinput`: input inconsistency (fewer than 4 points, say).
    Input,
    /// `qh_ERRsingular`: singular input (all points on a plane, say).
    Singular,
    /// `qh_ERRprec`: a precision error.
    Precision,
    /// `qh_ERRmem`: Qhull ran out of memory.
    Memory,
    /// `qh_ERRqhull`: an internal error Qhull detected.
    Internal,
    /// `qh_ERRother`: another error.
    Other,
    /// `qh_ERRtopology`: a topology error.
    Topology,
    /// `qh_ERRwide`: a wide facet.
    Wide,
    /// `qh_ERRdebug`: an exit from Qhull's debugging code.
    Debug,
}

impl Failure {
    /// The failure of Qhull's exit code `code`, if it is one (1 to 9).
    fn of(code: i32) -> Option<Failure> {
        use Failure::*;
        Some(match code {
            1 => Input,
            2 => Singular,
            3 => Precision,
            4 => Memory,
            5 => Internal,
            6 => Other,
            7 => Topology,
            8 => Wide,
            9 => Debug,
            _ => return None,
        })
    }
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Failure::Input => "input error",
            Failure::Singular => "singular input",
            Failure::Precision => "precision error",
            Failure::Memory => "out of memory",
            Failure::Internal => "internal error",
            Failure::Other => "other error",
            Failure::Topology => "topology error",
            Failure::Wide => "wide facet",
            Failure::Debug => "debug exit",
        })
    }
}

/// A failure of the shim itself (`qhull/shim.h`'s codes from 100).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum ShimFailure {
    /// `TOPOLAB_QHULL_BAD_ARGUMENT`: a null pointer or too many points (the wrapper checks
    /// both first, so this is a bug of the wrapper).
    BadArgument,
    /// `TOPOLAB_QHULL_OUT_OF_MEMORY`: `malloc` failed in the shim.
    OutOfMemory,
    /// `TOPOLAB_QHULL_LEAK`: Qhull did not free all of its memory.
    Leak,
    /// `TOPOLAB_QHULL_BAD_VERTEX`: a hull vertex that is no input point.
    BadVertex,
    /// A status the shim does not define.
    Unknown(i32),
}

impl fmt::Display for ShimFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ShimFailure::BadArgument => f.write_str("bad argument"),
            ShimFailure::OutOfMemory => f.write_str("out of memory"),
            ShimFailure::Leak => f.write_str("Qhull did not free all of its memory"),
            ShimFailure::BadVertex => f.write_str("a hull vertex that is no input point"),
            ShimFailure::Unknown(code) => write!(f, "unknown status {code}"),
        }
    }
}

/// Why [`convex_hull`] gave no hull.
#[derive(Debug, thiserror::Error)]
pub enum QhullError {
    /// Points the wrapper refuses before Qhull sees them: more than Qhull's `int` counts
    /// ([`topolab_structures::Error::TooLarge`]), a NaN or infinite coordinate
    /// ([`topolab_structures::Error::NonFiniteCoordinate`]; SciPy refuses NaN too).
    #[error(transparent)]
    Points(#[from] topolab_structures::Error),
    /// Qhull refused the points; `message` is what it wrote to its error file.
    #[error("Qhull refused the points ({failure}): {message}")]
    Refused {
        /// Qhull's exit code.
        failure: Failure,
        /// Qhull's message.
        message: String,
    },
    /// The shim failed.
    #[error("the Qhull shim failed ({failure}): {message}")]
    Shim {
        /// How.
        failure: ShimFailure,
        /// What Qhull wrote to its error file, if anything.
        message: String,
    },
}

/// The most points the shim takes: Qhull counts coordinates (3 per point) in an `int`.
pub const MAX_POINTS: usize = i32::MAX as usize / 3;

/// The convex hull of `points` by Qhull, once ([module docs](self)): its vertices, triangles,
/// volume and the shim's time.
pub fn convex_hull(points: &[DVec3]) -> Result<QhullHull, QhullError> {
    if points.len() > MAX_POINTS {
        return Err(topolab_structures::Error::TooLarge {
            what: "points (Qhull counts 3 coordinates per point in an int)",
            count: points.len() as u64,
        }
        .into());
    }
    for (vertex, p) in points.iter().enumerate() {
        if let Some(&value) = p.to_array().iter().find(|c| !c.is_finite()) {
            return Err(topolab_structures::Error::NonFiniteCoordinate {
                vertex,
                value,
                numbering: topolab_structures::Numbering::FromZero,
            }
            .into());
        }
    }
    let mut vertices = vec![0u32; points.len()];
    let mut message = vec![0 as c_char; MESSAGE_CAPACITY];
    let (mut seconds, mut vertex_count, mut facet_count, mut volume) = (0.0, 0u32, 0u32, 0.0);
    // SAFETY: `points` are 3 contiguous f64 each (DVec3 is repr(C) of three f64, asserted
    // below), at most MAX_POINTS of them; `vertices` has room for one id per point, `message`
    // for MESSAGE_CAPACITY bytes; the other out-pointers are valid locals.
    let code = unsafe {
        ffi::topolab_qhull_convex_hull(
            points.as_ptr().cast::<f64>(),
            points.len() as u32,
            &mut seconds,
            vertices.as_mut_ptr(),
            &mut vertex_count,
            &mut facet_count,
            &mut volume,
            message.as_mut_ptr(),
            message.len(),
        )
    };
    if code != 0 {
        // SAFETY: the shim NUL-terminates `message` within its capacity.
        let message = unsafe { CStr::from_ptr(message.as_ptr()) }
            .to_string_lossy()
            .trim()
            .to_string();
        return Err(match Failure::of(code) {
            Some(failure) => QhullError::Refused { failure, message },
            None => QhullError::Shim {
                failure: match code {
                    100 => ShimFailure::BadArgument,
                    101 => ShimFailure::OutOfMemory,
                    102 => ShimFailure::Leak,
                    103 => ShimFailure::BadVertex,
                    other => ShimFailure::Unknown(other),
                },
                message,
            },
        });
    }
    vertices.truncate(vertex_count as usize);
    vertices.sort_unstable();
    Ok(QhullHull {
        seconds,
        vertices,
        facets: facet_count as usize,
        volume,
    })
}

// Points go to C as 3 doubles each, without a copy.
const _: () = assert!(std::mem::size_of::<DVec3>() == 24);

/// Qhull's version string, as the linked library reports it (`qh_version`, e.g.
/// `2020.2.r 2020/08/31`).
pub fn version() -> String {
    // SAFETY: the shim returns Qhull's static, NUL-terminated `qh_version`.
    unsafe { CStr::from_ptr(ffi::topolab_qhull_version()) }
        .to_string_lossy()
        .into_owned()
}

/// How the report says Qhull was run, for its notes and the hull section.
pub fn description() -> String {
    format!(
        "Qhull {} (libqhull_r, in-process through the C shim c/qhull/shim.c), options \"{}\" as SciPy's ConvexHull passes them",
        version(),
        COMMAND.trim_start_matches("qhull ")
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn the_description_names_the_version_and_options() {
        let d = description();
        assert!(d.contains(&version()) && d.contains("\"i Qt\""), "{d}");
    }
}
