//! OpenMesh's own file readers (`OpenMesh::IO::read_mesh`, `openmesh/read.cpp`), for the
//! differential test of the lab's readers on the test files OpenMesh ships with its unit tests
//! (`baselines/tests/openmesh_files.rs`). Not a structure, nothing timed: the soup as OpenMesh
//! reads a file, in its order.

use glam::DVec3;
use std::ffi::{c_void, CString};
use std::os::unix::ffi::OsStrExt;
use std::path::Path;
use topolab_structures::PolygonSoup;

/// `read_mesh` returned `false` (the file is missing, unreadable, or refused by OpenMesh).
const READ_FAILED: i32 = 5;

type ReadVertex = unsafe extern "C" fn(context: *mut c_void, x: f64, y: f64, z: f64);
type ReadFace = unsafe extern "C" fn(context: *mut c_void, corners: *const u32, count: usize);

extern "C" {
    fn topolab_om_read_file(
        path: *const std::ffi::c_char,
        vertex: ReadVertex,
        face: ReadFace,
        context: *mut c_void,
    ) -> i32;
}

/// # Safety
/// `context` is the `&mut PolygonSoup` [`read_file`] passes, alive for the whole call.
unsafe extern "C" fn push_vertex(context: *mut c_void, x: f64, y: f64, z: f64) {
    // SAFETY: see the function's contract.
    let soup = unsafe { &mut *context.cast::<PolygonSoup>() };
    soup.push_vertex(DVec3::new(x, y, z));
}

/// # Safety
/// As [`push_vertex`]; `corners` points at `count` indices, alive for the call.
unsafe extern "C" fn push_face(context: *mut c_void, corners: *const u32, count: usize) {
    // SAFETY: see the function's contract.
    let (soup, corners) = unsafe {
        (
            &mut *context.cast::<PolygonSoup>(),
            std::slice::from_raw_parts(corners, count),
        )
    };
    soup.push_face(corners);
}

/// The vertices and faces OpenMesh's `IO::read_mesh` reads from `path` into a `PolyMesh`
/// (double points, default options), in OpenMesh's order (a face's corners from its
/// `fv_range`, which may start at another corner than the file's); `Err` with the reason when
/// it cannot read the file.
pub fn read_file(path: &Path) -> Result<PolygonSoup, String> {
    let c_path = CString::new(path.as_os_str().as_bytes())
        .map_err(|_| format!("{}: a path with a NUL byte", path.display()))?;
    let mut soup = PolygonSoup::new();
    // SAFETY: the path is NUL-terminated and outlives the call; the callbacks match the C
    // signatures and only touch `soup`, which outlives the call; C++ catches its exceptions.
    let code = unsafe {
        topolab_om_read_file(
            c_path.as_ptr(),
            push_vertex,
            push_face,
            (&mut soup as *mut PolygonSoup).cast(),
        )
    };
    match code {
        READ_FAILED => Err(format!("OpenMesh's read_mesh refused {}", path.display())),
        code => crate::foreign::status("OpenMesh", "topolab_om_read_file", code)
            .map(|()| soup)
            .map_err(|e| e.to_string()),
    }
}
