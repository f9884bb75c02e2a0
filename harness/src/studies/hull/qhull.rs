//! Running the Qhull reference (`python/qhull_reference.py`, SciPy's `ConvexHull`) on a
//! point set, for the tests: the correctness reference of the lab's hulls and of the
//! in-process Qhull (the report's times come from the latter). Needs the workspace's `.venv`
//! with SciPy (`.ci/install-deps`, or `python3 -m venv .venv && .venv/bin/pip install scipy
//! numpy`).

use glam::DVec3;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};
use topolab_structures::io::write_obj;
use topolab_structures::PolygonSoup;

/// What Qhull answered.
#[derive(Clone, Debug, serde::Deserialize)]
pub struct QhullRun {
    /// Input indices of the hull vertices, sorted.
    pub vertices: Vec<u32>,
    /// Enclosed volume.
    pub volume: f64,
    /// Triangles Qhull reports.
    pub simplices: usize,
    /// Best time of the `ConvexHull` call alone, seconds (SciPy's output arrays, volume and
    /// area included; a fresh process, so the first call is cold).
    pub seconds: f64,
}

/// The workspace's Python with SciPy, if there is one: `root/.venv/bin/python` that can
/// import `scipy.spatial`.
pub fn python(root: &Path) -> Option<PathBuf> {
    let python = root.join(".venv/bin/python");
    let works = Command::new(&python)
        .args(["-c", "import scipy.spatial, numpy"])
        .output()
        .is_ok_and(|o| o.status.success());
    works.then_some(python)
}

/// Runs Qhull on `points` with `python` (see [`python`]), timing `repeat` calls; the points
/// go through a temporary OBJ file of `v` lines (exact: Rust prints the shortest decimal that
/// reads back to the same double). `root` is the workspace root (for the script). Calls may
/// run in parallel: each has its own temporary folder.
pub fn run(
    python: &Path,
    root: &Path,
    points: &[DVec3],
    repeat: usize,
) -> Result<QhullRun, String> {
    // Tests call this from parallel threads of one process: the process id alone is not unique.
    static CALLS: AtomicUsize = AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("topolab-qhull-{}-{call}", std::process::id()));
    std::fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
    let (input, output) = (dir.join("points.obj"), dir.join("qhull.json"));
    let soup = PolygonSoup::from_polygons(points.to_vec(), &[] as &[[u32; 3]]);
    let mut file =
        std::io::BufWriter::new(std::fs::File::create(&input).map_err(|e| e.to_string())?);
    write_obj(&mut file, &soup).map_err(|e| e.to_string())?;
    drop(file);
    let status = Command::new(python)
        .arg(root.join("python/qhull_reference.py"))
        .arg(&input)
        .arg("--out")
        .arg(&output)
        .arg("--repeat")
        .arg(repeat.to_string())
        .output();
    let text = match status {
        Ok(s) if s.status.success() => std::fs::read_to_string(&output).map_err(|e| e.to_string()),
        Ok(s) => Err(String::from_utf8_lossy(&s.stderr).into_owned()),
        Err(e) => Err(e.to_string()),
    };
    let _ = std::fs::remove_dir_all(&dir);
    let text = text?;
    serde_json::from_str(&text).map_err(|e| e.to_string())
}
