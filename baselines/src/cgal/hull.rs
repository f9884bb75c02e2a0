//! `CGAL::convex_hull_3` (CGAL's quickhull, with the `Exact_predicates_inexact_constructions_kernel`:
//! exact orientation tests on the input doubles, as the lab's hulls use Shewchuk's `orient3d`)
//! into a `Surface_mesh`, through `cpp/cgal/hull.cpp`: [`convex_hull_3`] for one point set, which the harness's hull
//! benchmark times (through [`crate::hulls`]) beside the lecture's three algorithms and Qhull.

use super::{ffi, status};
use glam::DVec3;
use topolab_structures::Result;

/// What `CGAL::convex_hull_3` built.
#[derive(Clone, Debug, PartialEq)]
pub struct CgalHull {
    /// Best time of the `convex_hull_3` call alone, seconds (input checks, copies and the
    /// volume not included; the clock is read inside the shim).
    pub seconds: f64,
    /// Vertices of the hull.
    pub vertices: usize,
    /// Faces of the hull (triangles).
    pub faces: usize,
    /// Every face a triangle and no border: a closed triangulated surface.
    pub closed_triangles: bool,
    /// The enclosed volume (signed tetrahedra from the origin, as the lab's hulls sum it).
    pub volume: f64,
}

/// The convex hull of `points` by `CGAL::convex_hull_3`, timed over `repeat` runs (at least
/// one). The input is checked first the way the lab's hull algorithms check it
/// ([`topolab_structures::hull::predicates::prepare`]): NaN or infinite coordinates, more
/// points than `u32` counts, and points whose hull is not a solid are the same typed errors.
pub fn convex_hull_3(points: &[DVec3], repeat: u32) -> Result<CgalHull> {
    topolab_structures::hull::predicates::prepare(points)?;
    let (mut seconds, mut counts, mut volume) = (0.0, [0u32; 3], 0.0);
    // SAFETY: `points` are 3 contiguous f64 each (DVec3 is repr(C), size asserted in
    // `foreign`), their count fits u32 (`prepare` checked it); the out-pointers are valid and
    // `counts` has the 3 slots the shim fills.
    let code = unsafe {
        ffi::topolab_cgal_convex_hull(
            points.as_ptr().cast::<f64>(),
            points.len() as u32,
            repeat,
            &mut seconds,
            counts.as_mut_ptr(),
            &mut volume,
        )
    };
    status("topolab_cgal_convex_hull", code)?;
    Ok(CgalHull {
        seconds,
        vertices: counts[0] as usize,
        faces: counts[1] as usize,
        closed_triangles: counts[2] != 0,
        volume,
    })
}
