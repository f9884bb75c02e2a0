//! The outside libraries' convex hulls as plain results, whatever this build compiled in:
//! [`HullLibrary::hull`] runs one (Qhull's `qhull i Qt`, CGAL's `convex_hull_3`) once and
//! returns its clock and what it built. The harness times and checks them beside the lab's
//! hulls (its `hull::outside`).

use glam::DVec3;

/// An outside library that builds convex hulls.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum HullLibrary {
    /// Qhull, in-process (the `qhull` module).
    Qhull,
    /// `CGAL::convex_hull_3` (the `cgal::hull` module).
    CgalConvexHull3,
}

/// What an outside library's hull built, once.
#[derive(Clone, Debug, PartialEq)]
pub struct OutsideHull {
    /// The library's own clock around the hull's construction, seconds (read inside the shim,
    /// so the FFI is not timed).
    pub seconds: f64,
    /// Vertices of the hull.
    pub vertices: usize,
    /// Input indices of the hull's vertices, increasing, when the library returns them
    /// (Qhull's; CGAL's shim returns counts only).
    pub vertex_ids: Option<Vec<u32>>,
    /// Every face a triangle and no border: a closed triangulated surface.
    pub closed_triangles: bool,
}

impl HullLibrary {
    /// Every outside hull library, in the order of the report's rows.
    pub const ALL: [HullLibrary; 2] = [HullLibrary::Qhull, HullLibrary::CgalConvexHull3];

    /// Its name in the hull benchmark's rows.
    pub const fn name(self) -> &'static str {
        match self {
            HullLibrary::Qhull => "qhull",
            HullLibrary::CgalConvexHull3 => "cgal-convex-hull-3",
        }
    }

    /// Whether this build compiled it in ([`crate::HAS_QHULL`], [`crate::HAS_CGAL`]).
    pub const fn compiled_in(self) -> bool {
        match self {
            HullLibrary::Qhull => crate::HAS_QHULL,
            HullLibrary::CgalConvexHull3 => crate::HAS_CGAL,
        }
    }

    /// The convex hull of `points` by this library, once; an error (the library's, or that it
    /// is not compiled in: [`crate::QHULL_MISSING`], [`crate::CGAL_MISSING`]).
    pub fn hull(self, points: &[DVec3]) -> Result<OutsideHull, String> {
        match self {
            HullLibrary::Qhull => qhull(points),
            HullLibrary::CgalConvexHull3 => cgal(points),
        }
    }
}

#[cfg(has_qhull)]
fn qhull(points: &[DVec3]) -> Result<OutsideHull, String> {
    let hull = crate::qhull::convex_hull(points).map_err(|e| e.to_string())?;
    let h = hull.vertices.len();
    Ok(OutsideHull {
        seconds: hull.seconds,
        vertices: h,
        // A closed triangulated surface of h vertices has 2h - 4 triangles.
        closed_triangles: hull.facets + 4 == 2 * h,
        vertex_ids: Some(hull.vertices),
    })
}

#[cfg(not(has_qhull))]
fn qhull(_: &[DVec3]) -> Result<OutsideHull, String> {
    Err(crate::QHULL_MISSING.into())
}

#[cfg(has_cgal)]
fn cgal(points: &[DVec3]) -> Result<OutsideHull, String> {
    let hull = crate::cgal::hull::convex_hull_3(points, 1).map_err(|e| e.to_string())?;
    Ok(OutsideHull {
        seconds: hull.seconds,
        vertices: hull.vertices,
        vertex_ids: None,
        closed_triangles: hull.closed_triangles,
    })
}

#[cfg(not(has_cgal))]
fn cgal(_: &[DVec3]) -> Result<OutsideHull, String> {
    Err(crate::CGAL_MISSING.into())
}
