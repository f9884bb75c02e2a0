//! The changing workloads of the Surface_mesh benchmark (√3 subdivision and the collapse test;
//! see `topolab_structures::algorithms::changing`) on CGAL's two structures, each run whole
//! in C++ through CGAL's own Euler operations, as CGAL's `Surface_mesh/benchmark` runs them
//! (`cgal/edit_surface_mesh.cpp`, `cgal/edit_polyhedron.cpp`): `add_center_vertex` /
//! `create_center_vertex`, `flip_edge`, `collapse_edge`, and `collect_garbage` for the
//! `Surface_mesh` (a `Polyhedron_3` erases at once; its ids are given again in list order).

use super::{ffi::RawMesh, status, Cgal, PolyhedronClass, SurfaceMeshClass};
use topolab_structures::algorithms::changing::Changing;
use topolab_structures::Result;

extern "C" {
    fn topolab_cgal_sm_changing(mesh: *mut RawMesh, workload: i32) -> i32;
    fn topolab_cgal_polyhedron_changing(mesh: *mut RawMesh, workload: i32) -> i32;
}

/// The shim's workload code.
const fn code(workload: Changing) -> i32 {
    match workload {
        Changing::Sqrt3 => 0,
        Changing::Collapse => 1,
    }
}

impl<S: super::CgalStructure> Cgal<S> {
    /// Reads the element counts from the mesh again.
    pub(super) fn refresh_counts(&mut self) -> Result<()> {
        let mut summary = [0u32; 3];
        // SAFETY: `raw` is live; `summary` has the 3 slots the shim fills.
        status("topolab_cgal_summary", unsafe {
            super::ffi::topolab_cgal_summary(self.raw.as_ptr(), summary.as_mut_ptr())
        })?;
        [self.vertices, self.edges, self.faces] = summary;
        Ok(())
    }
}

impl Cgal<SurfaceMeshClass> {
    /// Runs a changing workload in place, in one C++ call, as CGAL's Surface_mesh benchmark
    /// does (see `cgal/edit_surface_mesh.cpp`); the counts are read again afterwards.
    pub fn native_changing(&mut self, workload: Changing) -> Result<()> {
        // SAFETY: `raw` is a live Surface_mesh, exclusively borrowed; the shim checks the code.
        let code = unsafe { topolab_cgal_sm_changing(self.raw.as_ptr(), code(workload)) };
        let done = status("topolab_cgal_sm_changing", code);
        self.refresh_counts()?;
        done
    }
}

impl Cgal<PolyhedronClass> {
    /// Runs a changing workload in place, in one C++ call, through `Polyhedron_3`'s Euler
    /// operations (see `cgal/edit_polyhedron.cpp`); the counts are read again afterwards.
    pub fn native_changing(&mut self, workload: Changing) -> Result<()> {
        // SAFETY: `raw` is a live Polyhedron_3, exclusively borrowed; the shim checks the code.
        let code = unsafe { topolab_cgal_polyhedron_changing(self.raw.as_ptr(), code(workload)) };
        let done = status("topolab_cgal_polyhedron_changing", code);
        self.refresh_counts()?;
        done
    }
}
