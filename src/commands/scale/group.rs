//! A memory cgroup of its own for one worker process: the scale run sweeps a `.che` file
//! larger than the memory the sweeping process may use. The limit is the kernel's, on the
//! process's resident memory and the page cache it brings in together, so the file's pages
//! cannot all stay: what the process reads comes back from the disk. (`ulimit -v` would not
//! show this: it counts the mapping's address space, and refuses to map a file larger than
//! the limit at all.)
//!
//! Made under the cgroup this process belongs to (`/proc/self/cgroup`): cgroup v1's `memory`
//! controller (`memory.limit_in_bytes`, `memory.max_usage_in_bytes`) or cgroup v2
//! (`memory.max`, `memory.peak`). Creating one needs the right to write there (root, or a
//! delegated subtree); where that is refused, the run says so and sweeps without the limit.

use std::path::{Path, PathBuf};

/// Which cgroup interface the group is made with.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum Version {
    /// cgroup v1, the `memory` controller's hierarchy.
    V1,
    /// cgroup v2, the unified hierarchy.
    V2,
}

/// A memory cgroup, removed when dropped.
pub(super) struct MemoryGroup {
    dir: PathBuf,
    version: Version,
}

/// The folder of this process's own cgroup for memory, and its interface.
fn own_group() -> Option<(PathBuf, Version)> {
    let groups = std::fs::read_to_string("/proc/self/cgroup").ok()?;
    for line in groups.lines() {
        let mut parts = line.splitn(3, ':');
        let (_, controllers, path) = (parts.next()?, parts.next()?, parts.next()?);
        let path = path.trim_start_matches('/');
        if controllers.split(',').any(|c| c == "memory") {
            let dir = Path::new("/sys/fs/cgroup/memory").join(path);
            if dir.join("memory.limit_in_bytes").exists() {
                return Some((dir, Version::V1));
            }
        }
    }
    let v2 = groups.lines().find_map(|l| l.strip_prefix("0::"))?;
    let dir = Path::new("/sys/fs/cgroup").join(v2.trim_start_matches('/'));
    dir.join("cgroup.controllers")
        .exists()
        .then_some((dir, Version::V2))
}

impl MemoryGroup {
    /// A new group under this process's own, limited to `limit` bytes; why not, where the
    /// system does not allow it.
    pub(super) fn create(limit: u64) -> Result<Self, String> {
        let (parent, version) =
            own_group().ok_or("no memory cgroup found for this process (/proc/self/cgroup)")?;
        let dir = parent.join(format!("topolab-scale-{}", std::process::id()));
        std::fs::create_dir(&dir)
            .map_err(|e| format!("cannot create the memory cgroup {}: {e}", dir.display()))?;
        let group = MemoryGroup { dir, version };
        let file = match version {
            Version::V1 => "memory.limit_in_bytes",
            Version::V2 => "memory.max",
        };
        std::fs::write(group.dir.join(file), limit.to_string())
            .map_err(|e| format!("cannot set {file} of {}: {e}", group.dir.display()))?;
        Ok(group)
    }

    /// The file a process writes its id into to join the group.
    pub(super) fn procs(&self) -> PathBuf {
        self.dir.join("cgroup.procs")
    }

    /// The most memory the group was charged, bytes (resident memory and page cache).
    pub(super) fn peak(&self) -> Option<u64> {
        let file = match self.version {
            Version::V1 => "memory.max_usage_in_bytes",
            Version::V2 => "memory.peak",
        };
        std::fs::read_to_string(self.dir.join(file))
            .ok()?
            .trim()
            .parse()
            .ok()
    }

    /// How the limit was set, for the page.
    pub(super) fn how(&self) -> String {
        match self.version {
            Version::V1 => "cgroup v1, memory.limit_in_bytes".into(),
            Version::V2 => "cgroup v2, memory.max".into(),
        }
    }
}

impl Drop for MemoryGroup {
    fn drop(&mut self) {
        // The group's last process has been waited for; its removal from the group may lag
        // behind its exit by a moment.
        for _ in 0..50 {
            if std::fs::remove_dir(&self.dir).is_ok() {
                return;
            }
            std::thread::sleep(std::time::Duration::from_millis(20));
        }
        eprintln!(
            "topolab: could not remove the memory cgroup {}",
            self.dir.display()
        );
    }
}
