//! The scale run: the largest mesh each structure holds on this machine, measured, and the
//! CHE read from memory-mapped files, in memory and beyond it (docs/scale.md). The `topolab`
//! program is its front (`topolab scale`: the options, their checks, the files written); what
//! only the program has comes from its [`ScaleHost`]: the counting allocator, what the memory
//! admits, and the command lines of the workers, which are the program itself.
//!
//! The run climbs the ladder of sizes ([`LADDER`]: tori of 1k to 1.024 billion triangles, four
//! times larger each step) structure by structure. Before each size it asks the host whether
//! the size fits: the estimated peak ([`estimate`]: the peak per triangle the previous size
//! measured, or for the first a build of the sample mesh under the counting allocator, scaled)
//! against the memory available at that moment. A size that does not fit is shown refused
//! with its estimate, and the structure stops there; a size that fits runs in a worker process
//! of its own ([`cell`]), so the kernel's count of its memory is that build's alone and a build
//! that still runs out ends that process, not the run. Then the `.che` part ([`mapped`]).
//! Everything lands in [`ScaleResults`], which the front writes as `results.json` and
//! `index.html` ([`page`](super::page)).

pub mod cell;
mod group;
pub mod mapped;

use super::{Check, Entrant, Measure, Outcome, ScaleCell, ScaleResults, FORMAT, LADDER};
use crate::measuring::memory::{self, human};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;
use topolab_alloc::CountingAllocator;
use topolab_registry::{self as registry, StructureVisitor};
use topolab_structures::meshes;
use topolab_structures::{MeshTopology, PolygonSoup};

/// The structures of the default run: every structure of the course that holds a large mesh
/// (the CHE levels, the two half-edges, the winged-edge, the vertex list) and the C++
/// baselines, in report order. The others are named with `--structures`.
pub const DEFAULT_STRUCTURES: [&str; 11] = [
    "vertex-list",
    "winged-edge",
    "pointer-half-edge",
    "index-half-edge",
    "che-l0",
    "che-l1",
    "che-l2",
    "che-l3",
    "openmesh",
    "cgal-surface-mesh",
    "cgal-polyhedron",
];

/// What the program running the scale run provides.
pub trait ScaleHost {
    /// The process's counting allocator: the first size's estimate is a build of the sample
    /// mesh measured under it.
    fn allocator(&self) -> &CountingAllocator;
    /// The memory available, when `bytes` exceed it and the run may not go past it: the reason
    /// to refuse a size. `None`: go on.
    fn exceeds_available(&self, bytes: u64) -> Option<u64>;
    /// The worker that measures `structure` on a torus of `triangles` and prints its
    /// [`Measure`] as JSON, the run having admitted the cell by its own estimate.
    fn cell_worker(&self, structure: &str, triangles: u64) -> std::io::Result<Command>;
    /// The worker that writes a torus of `triangles` as a level-2 `.che` file at `file`.
    fn convert_worker(&self, triangles: u64, file: &Path) -> std::io::Result<Command>;
    /// The worker that sweeps the `.che` file `file` ([`mapped::sweep`]), having joined the
    /// cgroup whose `cgroup.procs` is `cgroup_procs` first, and prints its
    /// [`MappedRun`](super::MappedRun) as JSON.
    fn sweep_worker(&self, file: &Path, cgroup_procs: Option<&Path>) -> std::io::Result<Command>;
}

/// A scale run, as its front checked it.
#[derive(Clone, Debug)]
pub struct ScaleRequest {
    /// The structures, known to this build, each once, in the order they climb.
    pub structures: Vec<String>,
    /// Each structure's estimate for the smallest size and what it comes from ([`estimate`]
    /// with no previous size), which the front admitted the run by.
    pub first_estimates: Vec<(u64, String)>,
    /// The largest size, triangles.
    pub max_triangles: u64,
    /// Triangles of the torus of the `.che` part; 0: no `.che` part.
    pub mapped_triangles: u64,
    /// The folder of the `.che` part's file, deleted after.
    pub scratch: PathBuf,
    /// Size of each of the memory probe's two arrays, MiB.
    pub probe_mb: u64,
    /// The command line, for the results.
    pub command: String,
}

/// What a scale run found: its results, and the disagreements between answers among their
/// notes (each kernel's checksum against the first structure's at each size, and the `.che`
/// file's sweep against the in-memory CHE's): a run with any failed.
pub struct ScaleOutcome {
    /// The results, for `results.json` and the page.
    pub results: ScaleResults,
    /// The notes that say two answers disagree.
    pub disagreements: Vec<String>,
}

/// Runs the scale run: the memory probe, every structure up the ladder, the `.che` part.
pub fn run(req: &ScaleRequest, host: &dyn ScaleHost) -> ScaleOutcome {
    let started = Instant::now();
    // The build's facts as the run starts (its commit is the binary's, not a later edit's).
    let machine = crate::measuring::machine::facts(&topolab_baselines::openmesh_description());
    let memory_available = memory::available().unwrap_or(0);
    eprintln!(
        "scale: {} structures, sizes up to {} triangles, {} available; the memory probe first (alone)",
        req.structures.len(),
        req.max_triangles,
        human(memory_available)
    );
    let probe_mb = req.probe_mb as usize;
    let probe = crate::measuring::probe::measure(probe_mb, probe_mb).levels;
    let sizes: Vec<u64> = LADDER
        .iter()
        .copied()
        .filter(|&n| n <= req.max_triangles)
        .collect();
    let mut cells = Vec::new();
    let climbers = req
        .structures
        .iter()
        .zip(req.first_estimates.iter().cloned());
    for (i, (name, first)) in climbers.enumerate() {
        let place = (i + 1, req.structures.len());
        climb(host, name, first, &sizes, &mut cells, place);
    }
    let mut disagreements = disagreements(&cells);
    let mut notes = disagreements.clone();
    let mut mapped = Vec::new();
    if req.mapped_triangles > 0 {
        match mapped::run(host, req.mapped_triangles, &req.scratch, &cells) {
            Ok(part) => {
                mapped = part.runs;
                notes.extend(part.notes);
                disagreements.extend(part.disagreements.iter().cloned());
                notes.extend(part.disagreements);
            }
            Err(why) => notes.push(format!("the .che part did not run: {why}")),
        }
    }
    let results = ScaleResults {
        format: FORMAT.into(),
        command: req.command.clone(),
        machine,
        memory_total: crate::measuring::machine::meminfo("MemTotal").unwrap_or(0),
        memory_available,
        structures: req
            .structures
            .iter()
            .map(|name| Entrant {
                name: name.clone(),
                family: registry::visit(name, FamilyOf)
                    .unwrap_or(topolab_structures::Family::Outside),
            })
            .collect(),
        probe,
        max_triangles: req.max_triangles,
        scale: cells,
        mapped,
        seconds: started.elapsed().as_secs_f64(),
        notes,
    };
    ScaleOutcome {
        results,
        disagreements,
    }
}

/// What the run found, a line per structure: the largest size it measured.
pub fn summary(results: &ScaleResults) -> String {
    let mut text = String::new();
    for e in &results.structures {
        let rows = super::page::measured(results, &e.name);
        let largest = rows.last().map_or("nothing".to_string(), |(_, m)| {
            format!(
                "{} triangles, {:.1} bytes/triangle resident",
                m.faces,
                m.resident_bytes as f64 / m.faces.max(1) as f64
            )
        });
        text.push_str(&format!("{:<20} largest measured: {largest}\n", e.name));
    }
    text
}

/// A structure's family.
struct FamilyOf;
impl StructureVisitor for FamilyOf {
    type Output = topolab_structures::Family;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        M::FAMILY
    }
}

/// The peak heap of building a structure, measured by the limits module on its sample.
struct SampleBuild<'a>(&'a PolygonSoup);
impl StructureVisitor for SampleBuild<'_> {
    type Output = ();
    fn visit<M: MeshTopology>(self) {
        drop(std::hint::black_box(M::from_soup(self.0)));
    }
}

/// The estimated peak of the cell (`structure`, `triangles`) and what it comes from: what
/// `previous` measured, its program's memory plus the rest of its peak scaled by triangles;
/// for the first size, the torus's soup plus the structure's build on the limits module's
/// sample, scaled by corners.
pub fn estimate(
    allocator: &CountingAllocator,
    structure: &str,
    triangles: u64,
    previous: Option<(u64, &Measure)>,
) -> (u64, String) {
    let size = meshes::parse_spec(&format!("torus:{triangles}"))
        .map(|s| s.size())
        .expect("the ladder's tori are valid specs");
    if let Some((_, m)) = previous {
        let grows = m.peak_bytes.saturating_sub(m.start_bytes);
        let bytes = m
            .start_bytes
            .saturating_add(memory::scale(grows, m.faces, size.faces));
        return (
            bytes,
            format!(
                "{:.1} bytes per triangle at its peak, measured at {} triangles, and the program's {}",
                grows as f64 / m.faces.max(1) as f64,
                m.faces,
                human(m.start_bytes)
            ),
        );
    }
    let sample = memory::sample_mesh();
    let (_, peak) = allocator.measure(|| registry::visit(structure, SampleBuild(&sample)));
    let peak = peak as u64;
    let bytes = size.soup_bytes().saturating_add(memory::scale(
        peak,
        sample.num_corners() as u64,
        size.corners,
    ));
    (bytes, "the soup, and a sample's build scaled".into())
}

/// One structure up the ladder: each size measured in a process of its own until one is
/// refused (it would not fit) or fails. `first` is the estimate of the smallest size.
fn climb(
    host: &dyn ScaleHost,
    name: &str,
    first: (u64, String),
    sizes: &[u64],
    cells: &mut Vec<ScaleCell>,
    (i, of): (usize, usize),
) {
    let mut previous: Option<(u64, Measure)> = None;
    let mut first = Some(first);
    for &n in sizes {
        let (estimate_bytes, basis) = match (&previous, first.take()) {
            (None, Some(first)) => first,
            _ => estimate(
                host.allocator(),
                name,
                n,
                previous.as_ref().map(|(n, m)| (*n, m)),
            ),
        };
        if let Some(available_bytes) = host.exceeds_available(estimate_bytes) {
            eprintln!(
                "scale [{i}/{of}] {name} at {n} triangles: refused, needs about {}, {} available",
                human(estimate_bytes),
                human(available_bytes)
            );
            cells.push(ScaleCell {
                structure: name.into(),
                triangles: n,
                outcome: Outcome::Refused {
                    estimate_bytes,
                    basis,
                    available_bytes,
                },
            });
            return;
        }
        let t = Instant::now();
        let outcome = run_cell(host, name, n);
        match &outcome {
            Outcome::Measured(m) => eprintln!(
                "scale [{i}/{of}] {name} at {n} triangles: build {:.0} ns/face, {:.1} bytes/triangle, R00 {} ({:.1} s)",
                m.construction_ns_per_face,
                m.resident_bytes as f64 / m.faces.max(1) as f64,
                m.r00_sweep
                    .map_or("scans".to_string(), |t| format!("{:.1} ns/vertex", t.ns)),
                t.elapsed().as_secs_f64()
            ),
            Outcome::Failed { reason } => {
                eprintln!("scale [{i}/{of}] {name} at {n} triangles: failed: {reason}")
            }
            Outcome::Refused { .. } => {}
        }
        let go_on = matches!(outcome, Outcome::Measured(_));
        if let Outcome::Measured(m) = &outcome {
            previous = Some((n, m.clone()));
        }
        cells.push(ScaleCell {
            structure: name.into(),
            triangles: n,
            outcome,
        });
        if !go_on {
            return;
        }
    }
}

/// Runs the host's cell worker for one cell and reads its measurement.
fn run_cell(host: &dyn ScaleHost, name: &str, triangles: u64) -> Outcome {
    let out = host
        .cell_worker(name, triangles)
        .and_then(|mut worker| worker.output());
    let out = match out {
        Ok(out) => out,
        Err(e) => {
            return Outcome::Failed {
                reason: format!("could not start the cell's process: {e}"),
            }
        }
    };
    if out.status.success() {
        return match serde_json::from_slice::<Measure>(&out.stdout) {
            Ok(m) => Outcome::Measured(m),
            Err(e) => Outcome::Failed {
                reason: format!("the cell's process printed no measurement ({e})"),
            },
        };
    }
    Outcome::Failed {
        reason: ended(out.status, &out.stderr),
    }
}

/// Reads one kernel's result from a cell's measurement.
type ResultOf = fn(&Measure) -> Option<Check>;

/// The checksums of the cells, compared at each size: every sampled R00, every R00 sweep,
/// every smoothing must agree with the first structure's; one note per disagreement.
fn disagreements(cells: &[ScaleCell]) -> Vec<String> {
    let mut notes = Vec::new();
    for &n in &LADDER {
        let at: Vec<(&str, &Measure)> = cells
            .iter()
            .filter(|c| c.triangles == n)
            .filter_map(|c| match &c.outcome {
                Outcome::Measured(m) => Some((c.structure.as_str(), m)),
                _ => None,
            })
            .collect();
        let kernels: [(&str, ResultOf); 3] = [
            ("R00 sampled", |m| Some(m.r00_sampled.check)),
            ("R00 sweep", |m| m.r00_sweep.map(|t| t.check)),
            ("smoothing", |m| m.smoothing.map(|t| t.check)),
        ];
        for (kernel, check) in kernels {
            let results: Vec<(&str, _)> = at
                .iter()
                .filter_map(|(s, m)| Some((*s, check(m)?)))
                .collect();
            let Some(&(first, reference)) = results.first() else {
                continue;
            };
            for &(s, c) in &results[1..] {
                if !c.agrees(reference) {
                    notes.push(format!(
                        "{kernel} at {n} triangles: {s}'s result {c:?} and {first}'s {reference:?} disagree"
                    ));
                }
            }
        }
    }
    notes
}

/// How a worker process ended without its measurement: its last line on stderr (the
/// `topolab: ...` refusal), or the signal that ended it (9 from the OOM killer, most often).
fn ended(status: std::process::ExitStatus, stderr: &[u8]) -> String {
    use std::os::unix::process::ExitStatusExt;
    let said = String::from_utf8_lossy(stderr);
    let last = said.lines().rev().find(|l| !l.trim().is_empty());
    match (status.signal(), last) {
        (Some(9), _) => "killed (signal 9: the kernel's out-of-memory killer, most likely)".into(),
        (Some(s), _) => format!("ended by signal {s}"),
        (None, Some(line)) => line.trim_start_matches("topolab: ").to_string(),
        (None, None) => format!("exited with {status}"),
    }
}
