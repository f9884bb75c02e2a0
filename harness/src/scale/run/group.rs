//! A memory cgroup of its own for one worker process: the scale run sweeps a `.che` file
//! larger than the memory the sweeping process may use. The limit is the kernel's, on the
//! process's resident memory and the page cache it brings in together, so the file's pages
//! cannot all stay: what the process reads comes back from the disk. (`ulimit -v` would not
//! show this: it counts the mapping's address space, and refuses to map a file larger than
//! the limit at all.)
//!
//! Made under the cgroup this process belongs to ([`memory_cgroup`]): cgroup v1's `memory`
//! controller (`memory.limit_in_bytes`, `memory.max_usage_in_bytes`) or cgroup v2
//! (`memory.max`, `memory.peak`). Creating one needs the right to write there (root, or a
//! delegated subtree); where that is refused, the run says so and sweeps without the limit.

use crate::measuring::memory::{memory_cgroup, CgroupVersion};
use std::path::PathBuf;

/// A memory cgroup, removed when dropped.
pub(super) struct MemoryGroup {
    dir: PathBuf,
    version: CgroupVersion,
}

impl MemoryGroup {
    /// A new group under this process's own, limited to `limit` bytes; why not, where the
    /// system does not allow it.
    pub(super) fn create(limit: u64) -> Result<Self, String> {
        let (parent, version) =
            memory_cgroup().ok_or("no memory cgroup found for this process (/proc/self/cgroup)")?;
        let dir = parent.join(format!("topolab-scale-{}", std::process::id()));
        std::fs::create_dir(&dir)
            .map_err(|e| format!("cannot create the memory cgroup {}: {e}", dir.display()))?;
        let group = MemoryGroup { dir, version };
        let file = match version {
            CgroupVersion::V1 => "memory.limit_in_bytes",
            CgroupVersion::V2 => "memory.max",
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
            CgroupVersion::V1 => "memory.max_usage_in_bytes",
            CgroupVersion::V2 => "memory.peak",
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
            CgroupVersion::V1 => "cgroup v1, memory.limit_in_bytes".into(),
            CgroupVersion::V2 => "cgroup v2, memory.max".into(),
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
