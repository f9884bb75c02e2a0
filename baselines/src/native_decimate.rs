//! The decimaters of the C++ baselines, each run whole in C++ (`openmesh/decimate.cpp`:
//! OpenMesh's `DecimaterT` with `ModQuadricT`; `cgal/decimate.cpp`: CGAL's
//! `Surface_mesh_simplification::edge_collapse` with the Garland–Heckbert plane policies on a
//! `Surface_mesh`), for the report's decimation section: the mesh goes in as arrays, the
//! decimated mesh comes back as arrays with the time of the decimation alone (the thread's CPU
//! time, measured in C++ around the library's calls). The status codes are the shims' (`openmesh/shim.h`, `cgal/shim.h`).

use topolab_structures::{Error, PolygonSoup, Result};

/// A C++ decimater.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum NativeDecimater {
    /// OpenMesh's `DecimaterT` with `ModQuadricT`.
    OpenMesh,
    /// CGAL's `edge_collapse` with `GarlandHeckbert_plane_policies` on a `Surface_mesh`.
    CgalSurfaceMesh,
}

/// What a C++ decimater returned.
#[derive(Clone, Debug)]
pub struct NativeDecimation {
    /// The decimated mesh, compacted.
    pub result: PolygonSoup,
    /// Seconds of the decimation alone, the thread's CPU time measured in C++.
    pub seconds: f64,
}

/// Declares C decimation functions, all with the one signature of [`Decimate`]
/// (`xyz, vertices, triangles, faces, target, out_xyz, out_vertices, out_triangles, out_faces,
/// seconds`), each under its own `cfg`.
macro_rules! decimate_functions {
    ($( $(#[$cfg:meta])* fn $name:ident; )*) => {
        /// One C decimation: the input mesh, the target face count, the output buffers sized by
        /// the caller, the decimation's seconds; returns a status of the C API.
        type Decimate = unsafe extern "C" fn(
            xyz: *const f64,
            vertices: u32,
            triangles: *const u32,
            faces: u32,
            target: u32,
            out_xyz: *mut f64,
            out_vertices: *mut u32,
            out_triangles: *mut u32,
            out_faces: *mut u32,
            seconds: *mut f64,
        ) -> i32;
        $(
            $(#[$cfg])*
            extern "C" {
                fn $name(
                    xyz: *const f64,
                    vertices: u32,
                    triangles: *const u32,
                    faces: u32,
                    target: u32,
                    out_xyz: *mut f64,
                    out_vertices: *mut u32,
                    out_triangles: *mut u32,
                    out_faces: *mut u32,
                    seconds: *mut f64,
                ) -> i32;
            }
        )*
    };
}

decimate_functions! {
    #[cfg(has_openmesh)]
    fn topolab_om_decimate;
    #[cfg(has_cgal_decimate)]
    fn topolab_cgal_decimate;
}

impl NativeDecimater {
    /// Both.
    pub const ALL: [NativeDecimater; 2] =
        [NativeDecimater::OpenMesh, NativeDecimater::CgalSurfaceMesh];

    /// The structure's name in the report (the registry's).
    pub const fn name(self) -> &'static str {
        match self {
            NativeDecimater::OpenMesh => crate::compiled::OPENMESH,
            NativeDecimater::CgalSurfaceMesh => crate::compiled::CGAL_SURFACE_MESH,
        }
    }

    /// The C function, when this build has it.
    fn function(self) -> Option<(Decimate, &'static str, &'static str)> {
        match self {
            #[cfg(has_openmesh)]
            NativeDecimater::OpenMesh => Some((
                topolab_om_decimate as Decimate,
                "OpenMesh",
                "topolab_om_decimate",
            )),
            #[cfg(has_cgal_decimate)]
            NativeDecimater::CgalSurfaceMesh => Some((
                topolab_cgal_decimate as Decimate,
                "CGAL",
                "topolab_cgal_decimate",
            )),
            #[allow(unreachable_patterns)]
            _ => None,
        }
    }

    /// Whether this build has it (CGAL's needs Eigen's headers at build time).
    pub fn available(self) -> bool {
        self.function().is_some()
    }

    /// Decimates the triangle mesh `soup` to `target` faces.
    pub fn decimate(self, soup: &PolygonSoup, target: usize) -> Result<NativeDecimation> {
        let Some((function, library, call)) = self.function() else {
            return Err(Error::Unsupported(format!(
                "{} is not in this build",
                self.name()
            )));
        };
        run(self.name(), function, library, call, soup, target)
    }
}

/// Runs the C decimater `function` (`call` in `library`, reported as `name`) on `soup`.
fn run(
    name: &str,
    function: Decimate,
    library: &'static str,
    call: &'static str,
    soup: &PolygonSoup,
    target: usize,
) -> Result<NativeDecimation> {
    {
        if !soup.is_triangle_mesh() {
            return Err(Error::Unsupported(format!(
                "{name} decimates triangle meshes only"
            )));
        }
        let (nv, nf) = (soup.num_vertices(), soup.num_faces());
        let too_large = |what: &'static str, count: usize| Error::TooLarge {
            what,
            count: count as u64,
        };
        let vertices = u32::try_from(nv).map_err(|_| too_large("vertices", nv))?;
        let faces = u32::try_from(nf).map_err(|_| too_large("faces", nf))?;
        let target = u32::try_from(target.min(nf)).unwrap_or(faces);
        let mut out_xyz = vec![0.0f64; 3 * nv];
        let mut out_triangles = vec![0u32; 3 * nf];
        let (mut out_vertices, mut out_faces, mut seconds) = (0u32, 0u32, 0.0f64);
        // SAFETY: the input arrays hold `vertices` positions (DVec3 is three f64, asserted in
        // `foreign`) and `faces` triangles; the output arrays have room for as many, which a
        // decimation never exceeds; the counts and the time are written before OK returns.
        let code = unsafe {
            function(
                soup.positions.as_ptr().cast::<f64>(),
                vertices,
                soup.indices().as_ptr(),
                faces,
                target,
                out_xyz.as_mut_ptr(),
                &mut out_vertices,
                out_triangles.as_mut_ptr(),
                &mut out_faces,
                &mut seconds,
            )
        };
        #[cfg(any(has_openmesh, has_cgal))]
        crate::foreign::status(library, call, code)?;
        #[cfg(not(any(has_openmesh, has_cgal)))]
        let _ = (library, call, code);
        let positions = out_xyz[..3 * out_vertices as usize]
            .chunks_exact(3)
            .map(|p| glam::DVec3::new(p[0], p[1], p[2]))
            .collect();
        let triangles: Vec<&[u32]> = out_triangles[..3 * out_faces as usize]
            .chunks_exact(3)
            .collect();
        Ok(NativeDecimation {
            result: PolygonSoup::from_polygons(positions, &triangles),
            seconds,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::meshes;

    #[test]
    fn each_available_decimater_reaches_about_the_target_on_a_torus() {
        let soup = meshes::torus(20, 12);
        for d in NativeDecimater::ALL.into_iter().filter(|d| d.available()) {
            let got = d.decimate(&soup, 48).expect("decimates");
            let f = got.result.num_faces();
            assert!((40..=48).contains(&f), "{}: {f} faces", d.name());
            assert!(got.result.check().is_ok(), "{}", d.name());
            assert!(got.seconds >= 0.0);
        }
    }
}
