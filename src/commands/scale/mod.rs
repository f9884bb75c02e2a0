//! `topolab scale`: the largest mesh each structure holds on this machine, measured, and the
//! CHE read from memory-mapped files, in memory and beyond it (docs/scale.md).
//!
//! The run climbs the ladder of sizes ([`LADDER`]: tori of 1k to 1.024 billion triangles, four
//! times larger each step) structure by structure. Before each size it asks the limits module
//! whether the size fits: the estimated peak (the peak per triangle the previous size
//! measured, or for the first a build of the limits module's sample under the counting
//! allocator, scaled) against the memory available at that moment. A size that does not fit
//! is shown refused with its estimate, and the structure stops there; a size that fits runs
//! in a process of its own ([`cell`]: `topolab scale-cell`), so the kernel's count of its
//! memory is that build's alone and a build that still runs out ends that process, not the
//! run. Then the `.che` part ([`mapped`]). Everything lands in `results.json` (its `scale`
//! list) and `index.html` ([`topolab_harness::scale::page`]).

pub mod cell;
mod group;
pub mod mapped;

use crate::failure::Failure;
use crate::limits;
use crate::registry::{self, StructureVisitor};
use std::io::Write as _;
use std::path::PathBuf;
use std::process::Command;
use std::time::Instant;
use topolab_harness::scale::{
    page, Entrant, Measure, Outcome, ScaleCell, ScaleResults, DEFAULT_MAX_TRIANGLES, FORMAT, LADDER,
};
use topolab_structures::meshes;
use topolab_structures::{MeshTopology, PolygonSoup};

/// The structures of the default run: every structure of the course that holds a large mesh
/// (the CHE levels, the two half-edges, the winged-edge, the vertex list) and the C++
/// baselines, in report order. The others are named with `--structures`.
const DEFAULT_STRUCTURES: [&str; 11] = [
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

/// Options of `topolab scale`.
#[derive(clap::Args, Debug, Clone)]
pub struct ScaleArgs {
    /// Structures to measure, comma separated (default: the vertex list, the winged-edge, the
    /// two half-edges, the CHE levels 0–3, OpenMesh and CGAL's two, those this build has).
    #[arg(long, value_delimiter = ',')]
    pub structures: Option<Vec<String>>,
    /// The largest size, triangles: the ladder 1k, 4k, 16k, 64k, 250k, 1M, 4M, ... up to it
    /// (default 64000000: under 15 minutes on a 2-core machine).
    #[arg(long, conflicts_with = "full")]
    pub max_triangles: Option<u64>,
    /// Climb the whole ladder, up to 1.024 billion triangles, while the memory admits: the
    /// sizes beyond the default's 15 minutes.
    #[arg(long)]
    pub full: bool,
    /// Triangles of the torus written as a level-2 `.che` file, opened and swept from it, in
    /// memory and in a memory cgroup smaller than the file (default: the largest size of the
    /// run, at most 64000000; 0: no `.che` part).
    #[arg(long)]
    pub mapped_triangles: Option<u64>,
    /// Folder for the `.che` file, deleted after (default: the system's temporary folder).
    #[arg(long)]
    pub scratch: Option<PathBuf>,
    /// Output folder.
    #[arg(long, default_value = "reports/scale-latest")]
    pub out: PathBuf,
    /// Size of each of the memory probe's two arrays, MiB, from 1 to 4096 (default 256).
    #[arg(long, hide = true, value_parser = clap::builder::RangedU64ValueParser::<u64>::new().range(1..=4096))]
    pub probe_mb: Option<u64>,
}

/// The memory probe's arrays by default, MiB each: well past the last cache level.
const PROBE_MB: u64 = 256;

/// The files a run writes into its folder.
const FILES: [&str; 2] = ["results.json", "index.html"];

/// Runs the scale run; returns what it found, a line per structure (exit 1 when two
/// structures' results disagree).
pub fn scale(args: &ScaleArgs, command: String) -> Result<String, Failure> {
    let started = Instant::now();
    let max_triangles = if args.full {
        *LADDER.last().expect("the ladder has sizes")
    } else {
        args.max_triangles.unwrap_or(DEFAULT_MAX_TRIANGLES)
    };
    limits::within_u32(
        &format!("--max-triangles {max_triangles}"),
        &[("corners", 3 * max_triangles as u128)],
    )?;
    if max_triangles < LADDER[0] {
        return Err(Failure::usage(format!(
            "--max-triangles {max_triangles}: the smallest size of the run is {} triangles",
            LADDER[0]
        )));
    }
    let structures = chosen_structures(args.structures.as_deref())?;
    crate::output::check_folder(&args.out, &FILES)?;
    let probe_mb = args.probe_mb.unwrap_or(PROBE_MB);
    let first_estimates = admit_smallest(&structures, probe_mb)?;
    // The build's facts as the run starts (its commit is the binary's, not a later edit's).
    let machine =
        topolab_harness::measuring::machine::facts(&topolab_baselines::openmesh_description());
    let memory_available = limits::available().unwrap_or(0);
    eprintln!(
        "scale: {} structures, sizes up to {max_triangles} triangles, {} available; the memory probe first (alone)",
        structures.len(),
        limits::human(memory_available)
    );
    let probe =
        topolab_harness::measuring::probe::measure(probe_mb as usize, probe_mb as usize).levels;
    let sizes: Vec<u64> = LADDER
        .iter()
        .copied()
        .filter(|&n| n <= max_triangles)
        .collect();
    let mut cells = Vec::new();
    for (i, (name, first)) in structures.iter().zip(first_estimates).enumerate() {
        climb(name, first, &sizes, &mut cells, (i + 1, structures.len()));
    }
    let mut notes = disagreements(&cells);
    let mapped_triangles = args
        .mapped_triangles
        .unwrap_or(max_triangles.min(DEFAULT_MAX_TRIANGLES));
    let mut mapped = Vec::new();
    if mapped_triangles > 0 {
        let scratch = args.scratch.clone().unwrap_or_else(std::env::temp_dir);
        match mapped::run(mapped_triangles, &scratch, &cells) {
            Ok((runs, said)) => {
                mapped = runs;
                notes.extend(said);
            }
            Err(why) => notes.push(format!("the .che part did not run: {why}")),
        }
    }
    let results = ScaleResults {
        format: FORMAT.into(),
        command,
        machine,
        memory_total: topolab_harness::measuring::machine::meminfo("MemTotal").unwrap_or(0),
        memory_available,
        structures: structures
            .iter()
            .map(|name| Entrant {
                name: name.clone(),
                family: registry::visit(name, FamilyOf)
                    .unwrap_or(topolab_structures::Family::Outside),
            })
            .collect(),
        probe,
        max_triangles,
        scale: cells,
        mapped,
        seconds: started.elapsed().as_secs_f64(),
        notes,
    };
    write(&args.out, &results)?;
    let mut text = String::new();
    for e in &results.structures {
        let rows = page::measured(&results, &e.name);
        let largest = rows.last().map_or("nothing".to_string(), |(_, m)| {
            format!(
                "{} triangles, {:.1} bytes/triangle resident",
                m.faces,
                m.resident_bytes as f64 / m.faces.max(1) as f64
            )
        });
        text.push_str(&format!("{:<20} largest measured: {largest}\n", e.name));
    }
    text.push_str(&format!(
        "written to {} ({:.0} s)\n",
        args.out.join("index.html").display(),
        results.seconds
    ));
    if let Some(bad) = results.notes.iter().find(|n| n.contains("disagree")) {
        return Err(Failure {
            message: format!("{text}{bad}"),
            code: 1,
        });
    }
    Ok(text)
}

/// The structures asked for, checked: known to this build, each once. By default, those of
/// [`DEFAULT_STRUCTURES`] this build has.
fn chosen_structures(asked: Option<&[String]>) -> Result<Vec<String>, Failure> {
    let Some(asked) = asked else {
        return Ok(DEFAULT_STRUCTURES
            .iter()
            .filter(|s| registry::NAMES.contains(s))
            .map(|s| s.to_string())
            .collect());
    };
    let mut out: Vec<String> = Vec::new();
    for name in asked {
        if !registry::NAMES.contains(&name.as_str()) {
            return Err(crate::input::unknown_structure(name));
        }
        if out.contains(name) {
            return Err(Failure::usage(format!("--structures names {name} twice")));
        }
        out.push(name.clone());
    }
    if out.is_empty() {
        return Err(Failure::usage("--structures names no structure".into()));
    }
    Ok(out)
}

/// Refuses (exit code 2) a run the memory cannot start: the probe's two arrays, or the smallest
/// size of every structure asked for, above what is available (a structure that alone does
/// not fit is shown refused instead). Returns each structure's estimate for the smallest size,
/// which its climb starts from.
fn admit_smallest(structures: &[String], probe_mb: u64) -> Result<Vec<(u64, String)>, Failure> {
    let first: Vec<(u64, String)> = structures
        .iter()
        .map(|s| estimate(s, LADDER[0], None))
        .collect();
    let smallest = first.iter().map(|(bytes, _)| *bytes).min().unwrap_or(0);
    limits::admit(
        &format!(
            "the scale run (its memory probe, then {} triangles)",
            LADDER[0]
        ),
        smallest.max(2 * (probe_mb << 20)),
    )?;
    Ok(first)
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
pub(crate) fn estimate(
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
            .saturating_add(limits::scale(grows, m.faces, size.faces));
        return (
            bytes,
            format!(
                "{:.1} bytes per triangle at its peak, measured at {} triangles, and the program's {}",
                grows as f64 / m.faces.max(1) as f64,
                m.faces,
                limits::human(m.start_bytes)
            ),
        );
    }
    let sample = limits::sample_mesh();
    let (_, peak) = limits::peak_of(|| registry::visit(structure, SampleBuild(&sample)));
    let bytes = size.soup_bytes().saturating_add(limits::scale(
        peak,
        sample.num_corners() as u64,
        size.corners,
    ));
    (bytes, "the soup, and a sample's build scaled".into())
}

/// One structure up the ladder: each size measured in a process of its own until one is
/// refused (it would not fit) or fails. `first` is the estimate of the smallest size.
fn climb(
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
            _ => estimate(name, n, previous.as_ref().map(|(n, m)| (*n, m))),
        };
        if let Some(available_bytes) = limits::exceeds_available(estimate_bytes) {
            eprintln!(
                "scale [{i}/{of}] {name} at {n} triangles: refused, needs about {}, {} available",
                limits::human(estimate_bytes),
                limits::human(available_bytes)
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
        let outcome = run_cell(name, n);
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

/// Runs `topolab scale-cell` for one cell and reads its measurement.
fn run_cell(name: &str, triangles: u64) -> Outcome {
    let out = std::env::current_exe().and_then(|exe| {
        // The run admitted the cell by its own estimate: the worker does not check again by
        // the sample's, which errs large.
        Command::new(exe)
            .args([
                "--allow-memory",
                "scale-cell",
                "--structure",
                name,
                "--triangles",
            ])
            .arg(triangles.to_string())
            .output()
    });
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
type ResultOf = fn(&Measure) -> Option<topolab_harness::scale::Check>;

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

/// Writes `results.json` and `index.html` into `out`, together.
fn write(out: &std::path::Path, r: &ScaleResults) -> Result<(), Failure> {
    let json = serde_json::to_string_pretty(r).expect("the results serialize");
    let html = page::render(r);
    crate::output::write_files_together(
        out,
        vec![
            (
                FILES[0].into(),
                Box::new(move |w| w.write_all(json.as_bytes())),
            ),
            (
                FILES[1].into(),
                Box::new(move |w| w.write_all(html.as_bytes())),
            ),
        ],
    )
}

/// How a worker process ended without its measurement: its last line on stderr (the
/// `topolab: ...` refusal), or the signal that ended it (9 from the OOM killer, most often).
pub(crate) fn ended(status: std::process::ExitStatus, stderr: &[u8]) -> String {
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
