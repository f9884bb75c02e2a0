//! What the kernel says about this process's memory, read from `/proc/self` (Linux; zeros
//! elsewhere): resident bytes now and at their highest, and page faults so far. The scale run
//! measures memory this way, not by the counting allocator, so nothing counts inside a timed
//! region and the C++ baselines' memory is seen exactly like the lab's.

/// Resident memory of this process, bytes.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct Resident {
    /// Resident now (`VmRSS`).
    pub now: u64,
    /// The highest resident so far (`VmHWM`).
    pub peak: u64,
}

/// Reads [`Resident`] from `/proc/self/status`.
pub fn resident() -> Resident {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    let kib = |key: &str| -> u64 {
        status
            .lines()
            .find_map(|l| l.strip_prefix(key))
            .and_then(|rest| rest.split_whitespace().next())
            .and_then(|n| n.parse::<u64>().ok())
            .map_or(0, |k| k * 1024)
    };
    Resident {
        now: kib("VmRSS:"),
        peak: kib("VmHWM:"),
    }
}

/// Page faults of this process so far.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Faults {
    /// Minor faults: a page mapped without reading the disk (fresh memory, or a file's page
    /// already in the page cache).
    pub minor: u64,
    /// Major faults: a page read from the disk.
    pub major: u64,
}

impl Faults {
    /// The faults between `earlier` and `self`.
    pub fn since(self, earlier: Faults) -> Faults {
        Faults {
            minor: self.minor.saturating_sub(earlier.minor),
            major: self.major.saturating_sub(earlier.major),
        }
    }
}

/// Reads [`Faults`] from `/proc/self/stat` (fields 10 and 12, counted after the command
/// name, which may hold spaces and ends at the last `)`).
pub fn faults() -> Faults {
    let stat = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
    let fields: Vec<&str> = stat
        .rsplit_once(')')
        .map_or("", |(_, rest)| rest)
        .split_whitespace()
        .collect();
    // After the name: state is field 3, so field k is fields[k - 3].
    let field = |k: usize| fields.get(k - 3).and_then(|f| f.parse().ok()).unwrap_or(0);
    Faults {
        minor: field(10),
        major: field(12),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn touching_fresh_memory_shows_as_resident_and_as_minor_faults() {
        if !std::path::Path::new("/proc/self/stat").exists() {
            return;
        }
        let (before, faults_before) = (resident(), faults());
        let mut block = vec![0u8; 64 << 20];
        for i in (0..block.len()).step_by(4096) {
            block[i] = 1;
        }
        std::hint::black_box(&block);
        let (after, faulted) = (resident(), faults().since(faults_before));
        assert!(after.now >= before.now + (32 << 20), "{before:?} {after:?}");
        assert!(after.peak >= after.now);
        // 16,384 pages of 4 kB, or 32 huge pages of 2 MB.
        assert!(faulted.minor >= 16, "{faulted:?}");
    }
}
