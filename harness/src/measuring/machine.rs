//! Facts about the machine and build that results must carry: CPU, cores, caches, compiler,
//! the OpenMesh baseline's build, commit, date.

use std::process::Command;

/// A field of `/proc/meminfo` (`MemTotal`, `MemAvailable`, ...), bytes; `None` where it cannot
/// be read (not Linux).
pub fn meminfo(field: &str) -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| {
        l.strip_prefix(field)
            .is_some_and(|rest| rest.starts_with(':'))
    })?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

/// Machine and build facts.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Machine {
    /// CPU model name.
    pub cpu: String,
    /// Logical cores.
    pub cores: usize,
    /// Cache sizes, e.g. `L1d 48K, L2 2048K, L3 ...`.
    pub caches: String,
    /// Total memory.
    pub memory: String,
    /// `rustc --version`.
    pub rustc: String,
    /// The OpenMesh the run measured: its version, where its source came from and how it was
    /// compiled; or why the build has none.
    pub openmesh: String,
    /// `git rev-parse --short HEAD` (plus `-dirty` with uncommitted changes).
    pub commit: String,
    /// UTC date and time of the run.
    pub date: String,
    /// The OS kernel.
    pub os: String,
}

fn run(cmd: &str, args: &[&str]) -> Option<String> {
    let out = Command::new(cmd).args(args).output().ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// The caches of CPU 0 as Linux sysfs describes them: (level, type, size), e.g.
/// `("1", "Data", "32K")`; empty where unreadable.
fn sysfs_caches() -> Vec<(String, String, String)> {
    (0..8)
        .filter_map(|i| {
            let base = format!("/sys/devices/system/cpu/cpu0/cache/index{i}");
            let read = |f: &str| {
                std::fs::read_to_string(format!("{base}/{f}"))
                    .ok()
                    .map(|s| s.trim().to_string())
            };
            Some((read("level")?, read("type")?, read("size")?))
        })
        .collect()
}

/// The data (or unified) caches of CPU 0 by level, with their sizes in bytes, smallest level
/// first (empty where unreadable).
pub fn data_caches() -> Vec<(u8, usize)> {
    let mut out: Vec<(u8, usize)> = sysfs_caches()
        .into_iter()
        .filter(|(_, kind, _)| kind != "Instruction")
        .filter_map(|(level, _, size)| Some((level.parse().ok()?, cache_bytes(&size)?)))
        .collect();
    out.sort_unstable();
    out.dedup_by_key(|c| c.0);
    out
}

/// Bytes of a sysfs cache size such as `32K` or `1M`.
fn cache_bytes(size: &str) -> Option<usize> {
    let (digits, unit) = size.split_at(
        size.find(|c: char| !c.is_ascii_digit())
            .unwrap_or(size.len()),
    );
    let n: usize = digits.parse().ok()?;
    Some(match unit {
        "" => n,
        "K" => n << 10,
        "M" => n << 20,
        "G" => n << 30,
        _ => return None,
    })
}

/// Reads the facts (anything unreadable is "unknown"); `openmesh` is what the build says of its
/// OpenMesh ([`Machine::openmesh`]).
pub fn facts(openmesh: &str) -> Machine {
    let cpuinfo = std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default();
    let cpu = cpuinfo
        .lines()
        .find(|l| l.starts_with("model name"))
        .and_then(|l| l.split(':').nth(1))
        .map(|s| s.trim().to_string())
        .unwrap_or_else(|| "unknown".into());
    let caches: Vec<String> = sysfs_caches()
        .into_iter()
        .map(|(level, kind, size)| {
            let k = match kind.as_str() {
                "Data" => "d",
                "Instruction" => "i",
                _ => "",
            };
            format!("L{level}{k} {size}")
        })
        .collect();
    let memory = meminfo("MemTotal")
        .map(|b| format!("{:.1} GiB", b as f64 / (1u64 << 30) as f64))
        .unwrap_or_else(|| "unknown".into());
    let dirty = run("git", &["status", "--porcelain", "--untracked-files=no"])
        .is_some_and(|s| !s.is_empty());
    let commit = run("git", &["rev-parse", "--short", "HEAD"])
        .map(|c| if dirty { format!("{c}-dirty") } else { c })
        .unwrap_or_else(|| "unknown".into());
    Machine {
        cpu,
        cores: std::thread::available_parallelism()
            .map(|n| n.get())
            .unwrap_or(1),
        caches: if caches.is_empty() {
            "unknown".into()
        } else {
            caches.join(", ")
        },
        memory,
        rustc: run("rustc", &["--version"]).unwrap_or_else(|| "unknown".into()),
        openmesh: openmesh.to_string(),
        commit,
        date: run("date", &["-u", "+%Y-%m-%d %H:%M UTC"]).unwrap_or_else(|| "unknown".into()),
        os: run("uname", &["-sr"]).unwrap_or_else(|| "unknown".into()),
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn cache_sizes_read_as_sysfs_writes_them() {
        assert_eq!(super::cache_bytes("32K"), Some(32 << 10));
        assert_eq!(super::cache_bytes("1024K"), Some(1 << 20));
        assert_eq!(super::cache_bytes("2M"), Some(2 << 20));
        assert_eq!(super::cache_bytes("512"), Some(512));
        assert_eq!(super::cache_bytes("K"), None);
        assert_eq!(super::cache_bytes("3X"), None);
    }
}
