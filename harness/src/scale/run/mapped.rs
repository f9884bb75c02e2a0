//! The scale run's `.che` part: a torus written as a level-2 `.che` file by the host's convert
//! worker, then opened and swept by its sweep worker ([`sweep`]) twice:
//! with the machine's memory, and in a memory cgroup whose limit is a quarter of the file
//! (the `group` module), so the file cannot stay resident and every sweep reads it from the
//! disk. Each sweep's result is compared with the in-memory CHE's on the same torus.

use super::group::MemoryGroup;
use super::{ended, ScaleHost};
use crate::measuring::kernels::{self, Queries};
use crate::measuring::memory::human;
use crate::scale::proc::faults;
use crate::scale::{time_kernel_runs, Check, MappedRun, Outcome, ScaleCell, Timing};
use std::path::{Path, PathBuf};
use std::time::Instant;
use topolab_structures::che::{CheFile, MappedCheL2};
use topolab_structures::io::echo;
use topolab_structures::{BoundaryCurves, MeshTopology, Operator};

/// Seconds the later sweeps may take, beyond their fewest runs.
const LATER_BUDGET_S: f64 = 2.0;

/// The fewest later sweeps, however long each takes: their median is the warm figure the
/// 256M target reads, and one run of a sweep of 128M vertices varied by half.
const LATER_RUNS: usize = 3;

/// Fills of the page cache in the run without a memory limit, each followed by the later
/// sweeps: the warm time changed by nearly 2× from one fill to the next on the project's
/// machine (docs/scale.md), so one fill is not a measurement of it.
const FILLS: usize = 3;

/// The limit of the cgroup run, as a fraction of the file: a quarter.
const LIMIT_DIVISOR: u64 = 4;

/// The smallest limit the cgroup run is made with: the sweeping process's own memory (its
/// program, about 10 MB resident, and its list of every vertex, 4 bytes each) must fit well
/// below it, or the kernel ends the process instead of dropping the file's pages.
const MIN_LIMIT: u64 = 128 << 20;

/// Removes the file when dropped (the run's `.che` file is scratch).
struct Scratch(PathBuf);
impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

/// What the `.che` part found.
pub(super) struct MappedPart {
    /// The sweeps: without a memory limit, then within one when it could be made.
    pub runs: Vec<MappedRun>,
    /// What the reader should know (why a limited run could not be made).
    pub notes: Vec<String>,
    /// A sweep's answer that disagrees with the in-memory CHE's.
    pub disagreements: Vec<String>,
}

/// Writes a torus of `triangles` as a level-2 `.che` file under `scratch`, sweeps it without
/// and with a memory limit below its size. An error when the file cannot be written.
pub(super) fn run(
    host: &dyn ScaleHost,
    triangles: u64,
    scratch: &Path,
    cells: &[ScaleCell],
) -> Result<MappedPart, String> {
    let file = Scratch(scratch.join(format!("topolab-scale-{}.che", std::process::id())));
    eprintln!(
        "scale: .che part: converting torus:{triangles} to {}",
        file.0.display()
    );
    let t = Instant::now();
    let out = host
        .convert_worker(triangles, &file.0)
        .and_then(|mut worker| worker.output())
        .map_err(|e| format!("cannot start the conversion: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "the conversion: {}",
            ended(out.status, &out.stderr)
        ));
    }
    let convert_s = t.elapsed().as_secs_f64();
    let in_memory_check = cells
        .iter()
        .filter(|c| c.triangles == triangles)
        .find_map(|c| match &c.outcome {
            Outcome::Measured(m) => m.r00_sweep.map(|t| t.check),
            _ => None,
        });
    let mut runs = Vec::new();
    let mut notes = Vec::new();
    let mut disagreements = Vec::new();
    let mut free = sweep_in_child(host, &file.0, None)?;
    free.limit_how = "none".into();
    runs.push(free);
    let file_bytes = runs[0].file_bytes;
    let limit = file_bytes / LIMIT_DIVISOR;
    if limit < MIN_LIMIT {
        notes.push(format!(
            "the .che file was not swept beyond memory: at {}, a quarter of it is below the {} the sweeping process needs for itself (its program and its list of vertices); --mapped-triangles 16000000 or more makes a file large enough",
            human(file_bytes),
            human(MIN_LIMIT)
        ));
    } else {
        match MemoryGroup::create(limit) {
            Ok(group) => {
                eprintln!(
                    "scale: .che part: sweeping in a memory cgroup limited to {}",
                    human(limit)
                );
                match sweep_in_child(host, &file.0, Some(&group.procs())) {
                    Ok(mut limited) => {
                        limited.memory_limit = Some(limit);
                        limited.limit_how = group.how();
                        limited.group_peak_bytes = group.peak();
                        runs.push(limited);
                    }
                    Err(why) => notes.push(format!(
                        "the .che file's sweep in a memory cgroup of {} failed: {why}",
                        human(limit)
                    )),
                }
            }
            Err(why) => notes.push(format!(
                "the .che file was not swept beyond memory: {why} (a memory cgroup needs root or a delegated cgroup)"
            )),
        }
    }
    for r in &mut runs {
        r.convert_s = convert_s;
        r.in_memory_check = in_memory_check;
        if let Some(c) = in_memory_check {
            let mut sweeps = std::iter::once(&r.first_sweep).chain(r.fills());
            if let Some(t) = sweeps.find(|t| !c.agrees(t.check)) {
                disagreements.push(format!(
                    "the .che file's R00 sweep and the in-memory CHE's disagree ({:?} against {c:?})",
                    t.check
                ));
            }
        }
    }
    Ok(MappedPart {
        runs,
        notes,
        disagreements,
    })
}

/// Runs the host's sweep worker on `file` (in the cgroup whose `cgroup.procs` is `group`).
fn sweep_in_child(
    host: &dyn ScaleHost,
    file: &Path,
    group: Option<&Path>,
) -> Result<MappedRun, String> {
    let out = host
        .sweep_worker(file, group)
        .and_then(|mut worker| worker.output())
        .map_err(|e| format!("cannot start the sweep: {e}"))?;
    if !out.status.success() {
        return Err(format!("the sweep: {}", ended(out.status, &out.stderr)));
    }
    serde_json::from_slice(&out.stdout)
        .map_err(|e| format!("the sweep printed no measurement ({e})"))
}

/// Drops `file`'s pages from the page cache (those no mapping holds).
fn drop_pages(file: &Path) -> Result<(), String> {
    let cached = std::fs::File::open(file).map_err(|e| failure(file, "cannot open", e))?;
    topolab_alloc::drop_file_cache(&cached)
        .map_err(|e| failure(file, "cannot drop its pages from the page cache", e))
}

fn open_level2(file: &Path) -> Result<MappedCheL2, String> {
    MappedCheL2::open(file).map_err(|e| failure(file, "cannot open as CHE level 2", e))
}

fn verify(m: &mut MappedCheL2, file: &Path) -> Result<(), String> {
    m.verify().map_err(|e| failure(file, "does not verify", e))
}

/// The verified walk's R00 sweeps over `every` vertex: at least [`LATER_RUNS`], until
/// [`LATER_BUDGET_S`] have gone by.
fn warm_sweeps(m: &MappedCheL2, every: &Queries, curves: &mut BoundaryCurves) -> Timing {
    time_kernel_runs(m.num_vertices() as u64, LATER_BUDGET_S, LATER_RUNS, || {
        Check::Exact(kernels::run(m, Operator::R00, every, curves))
    })
}

fn failure(file: &Path, what: &str, e: impl std::fmt::Display) -> String {
    format!("{}: {what}: {e}", echo::path(file))
}

/// The sweep worker's measurement (`topolab scale-mapped FILE [--cgroup-procs PATH]`): joins
/// the cgroup when given, drops the file's pages from the page cache, opens it three times,
/// sweeps R00 once before verifying (the bounds-checked reads, from the disk), verifies it,
/// then sweeps again, three times at least and until two seconds have gone by (the
/// verified walk); without a cgroup, fills the page cache twice more (unmapped, pages dropped,
/// opened and verified again) and sweeps after each. Only
/// level-2 files.
pub fn sweep(file: &Path, cgroup_procs: Option<&Path>) -> Result<MappedRun, String> {
    if let Some(procs) = cgroup_procs {
        // Only an existing `cgroup.procs` file: never a file of another name, never created.
        if procs.file_name() != Some(std::ffi::OsStr::new("cgroup.procs")) {
            return Err(format!(
                "--cgroup-procs {}: not a cgroup's cgroup.procs file",
                echo::path(procs)
            ));
        }
        std::fs::OpenOptions::new()
            .write(true)
            .open(procs)
            .and_then(|mut f| {
                std::io::Write::write_all(&mut f, std::process::id().to_string().as_bytes())
            })
            .map_err(|e| failure(procs, "cannot join the cgroup", e))?;
    }
    drop_pages(file)?;
    let mut open_ms = Vec::new();
    for _ in 0..3 {
        let t = Instant::now();
        let opened = CheFile::open(file).map_err(|e| failure(file, "cannot open", e))?;
        open_ms.push(t.elapsed().as_secs_f64() * 1e3);
        drop(opened);
    }
    let mut m = open_level2(file)?;
    let vertices = m.num_vertices() as u64;
    let every = Queries::every_vertex(&m);
    let mut curves = BoundaryCurves::default();
    let before = faults();
    let t = Instant::now();
    let first = kernels::run(&m, Operator::R00, &every, &mut curves);
    let ns = t.elapsed().as_secs_f64() * 1e9 / vertices.max(1) as f64;
    let first_faults = faults().since(before);
    let first_sweep = Timing {
        ns,
        min: ns,
        max: ns,
        reps: 1,
        check: Check::Exact(first),
    };
    let t = Instant::now();
    verify(&mut m, file)?;
    let verify_ms = t.elapsed().as_secs_f64() * 1e3;
    let before = faults();
    let later_sweeps = warm_sweeps(&m, &every, &mut curves);
    let later_faults = faults().since(before);
    // Each further fill: unmapped first (the kernel does not drop pages that are mapped), then
    // the verification reads the file into the page cache again.
    let mut refills = Vec::new();
    if cgroup_procs.is_none() {
        for _ in 1..FILLS {
            drop(m);
            drop_pages(file)?;
            m = open_level2(file)?;
            verify(&mut m, file)?;
            refills.push(warm_sweeps(&m, &every, &mut curves));
        }
    }
    let run = MappedRun {
        triangles: m.num_faces() as u64,
        level: 2,
        file_bytes: m.file().file_bytes(),
        convert_s: 0.0,
        open_ms,
        verify_ms,
        memory_limit: None,
        limit_how: String::new(),
        first_sweep,
        first_faults,
        later_sweeps,
        later_faults,
        refills,
        group_peak_bytes: None,
        in_memory_check: None,
    };
    Ok(run)
}
