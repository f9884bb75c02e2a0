//! The machine's memory as the lab plans with it: what the system can still give
//! ([`available`], under a container's or the process's cgroup limit), the process's memory
//! cgroup ([`memory_cgroup`]), bytes for people ([`human`]), and the sample a command's work is
//! measured on before it runs on a larger mesh ([`sample_mesh`]), its peak scaled to the
//! request ([`scale`]). The `topolab` program's limits and the scale run both plan with these.

use topolab_structures::meshes;
use topolab_structures::PolygonSoup;

/// The mesh a command's work is measured on before it runs on a larger one: a triangulated
/// 45 × 45 grid (4,050 triangles, 12,150 corners), which every structure stores (the grid-only
/// ones included) and which has a boundary, so boundary handling is measured too.
pub fn sample_mesh() -> PolygonSoup {
    meshes::grid(45, 45, true)
}

/// Bytes the system can still give this process: `MemAvailable` of `/proc/meminfo` (what the
/// kernel estimates can be allocated without swapping), lowered to the headroom of the cgroup
/// (v2) mounted at `/sys/fs/cgroup` when that has a limit (`memory.max - memory.current`): in
/// a container, its own cgroup, whose limit the host's `MemAvailable` does not show; or, under
/// cgroup v1, to the headroom of the process's own memory cgroup (`cgroup_v1_headroom`). (On a
/// host, the root cgroup there has no `memory.max`, and a limit on a nested cgroup is not
/// seen.) `None` where neither can be read (not Linux): nothing is
/// refused for memory then. The environment variable `TOPOLAB_AVAILABLE_MEMORY` (bytes), when
/// set, takes the place of all this: to plan for less than the machine has, and for tests.
pub fn available() -> Option<u64> {
    if let Some(bytes) = std::env::var_os("TOPOLAB_AVAILABLE_MEMORY") {
        return bytes.to_str().and_then(|b| b.trim().parse().ok());
    }
    let meminfo = super::machine::meminfo("MemAvailable");
    let read = |file: &str| -> Option<u64> {
        std::fs::read_to_string(format!("/sys/fs/cgroup/{file}"))
            .ok()?
            .trim()
            .parse()
            .ok()
    };
    // "max" (no limit) does not parse: no cgroup headroom then.
    let cgroup = read("memory.max")
        .map(|max| max.saturating_sub(read("memory.current").unwrap_or(0)))
        .or_else(cgroup_v1_headroom);
    match (meminfo, cgroup) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// The headroom of this process's own memory cgroup under cgroup v1 ([`memory_cgroup`]):
/// `memory.limit_in_bytes - memory.usage_in_bytes`. A group without a limit reports a limit
/// near 2^63, which the `MemAvailable` it is compared with makes harmless. `None` where there
/// is no such controller.
fn cgroup_v1_headroom() -> Option<u64> {
    let (dir, CgroupVersion::V1) = memory_cgroup()? else {
        return None;
    };
    let read = |file: &str| -> Option<u64> {
        std::fs::read_to_string(dir.join(file))
            .ok()?
            .trim()
            .parse()
            .ok()
    };
    Some(read("memory.limit_in_bytes")?.saturating_sub(read("memory.usage_in_bytes").unwrap_or(0)))
}

/// Which cgroup interface holds a process's memory limit.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum CgroupVersion {
    /// cgroup v1, the `memory` controller's hierarchy (`memory.limit_in_bytes`).
    V1,
    /// cgroup v2, the unified hierarchy (`memory.max`).
    V2,
}

/// The folder of this process's own memory cgroup (named by `/proc/self/cgroup`) and its
/// interface: the `memory` controller's group under `/sys/fs/cgroup/memory` (v1), else the
/// unified group under `/sys/fs/cgroup` (v2). `None` where there is neither.
pub fn memory_cgroup() -> Option<(std::path::PathBuf, CgroupVersion)> {
    use std::path::Path;
    let groups = std::fs::read_to_string("/proc/self/cgroup").ok()?;
    for line in groups.lines() {
        let mut parts = line.splitn(3, ':');
        let (_, controllers, path) = (parts.next()?, parts.next()?, parts.next()?);
        if controllers.split(',').any(|c| c == "memory") {
            let dir = Path::new("/sys/fs/cgroup/memory").join(path.trim_start_matches('/'));
            if dir.join("memory.limit_in_bytes").exists() {
                return Some((dir, CgroupVersion::V1));
            }
        }
    }
    let v2 = groups.lines().find_map(|l| l.strip_prefix("0::"))?;
    let dir = Path::new("/sys/fs/cgroup").join(v2.trim_start_matches('/'));
    dir.join("cgroup.controllers")
        .exists()
        .then_some((dir, CgroupVersion::V2))
}

/// `bytes` for people: `1.5 GB`, `320.0 MB`, `12.0 kB`, `12 bytes` (powers of 1000).
pub fn human(bytes: u64) -> String {
    let b = bytes as f64;
    match bytes {
        0..1_000 => format!("{bytes} bytes"),
        1_000..1_000_000 => format!("{:.1} kB", b / 1e3),
        1_000_000..1_000_000_000 => format!("{:.1} MB", b / 1e6),
        _ => format!("{:.1} GB", b / 1e9),
    }
}

/// `bytes × elements / sample`, rounded up, saturating.
pub fn scale(bytes: u64, sample: u64, elements: u64) -> u64 {
    let scaled = (bytes as u128 * elements as u128).div_ceil(sample.max(1) as u128);
    u64::try_from(scaled).unwrap_or(u64::MAX)
}
