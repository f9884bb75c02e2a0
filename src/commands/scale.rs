//! `topolab scale`, the front of the harness's scale run ([`topolab_harness::scale::run`]):
//! its options and their checks, the memory the run may start with, the files it writes, and
//! the run's workers, which are this program (`topolab scale-cell`, `topolab scale-mapped`,
//! `topolab convert`): each cell is measured in a process of its own. docs/scale.md says what
//! the run measures and how.

use crate::failure::Failure;
use crate::limits;
use crate::registry;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use topolab_alloc::CountingAllocator;
use topolab_harness::scale::run::{self, ScaleHost, ScaleRequest, DEFAULT_STRUCTURES};
use topolab_harness::scale::{page, MappedRun, ScaleResults, DEFAULT_MAX_TRIANGLES, LADDER};

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
    let request = ScaleRequest {
        structures,
        first_estimates,
        max_triangles,
        mapped_triangles: args
            .mapped_triangles
            .unwrap_or(max_triangles.min(DEFAULT_MAX_TRIANGLES)),
        scratch: args.scratch.clone().unwrap_or_else(std::env::temp_dir),
        probe_mb,
        command,
    };
    let found = run::run(&request, &Program);
    write(&args.out, &found.results)?;
    let text = format!(
        "{}written to {} ({:.0} s)\n",
        run::summary(&found.results),
        args.out.join("index.html").display(),
        found.results.seconds
    );
    if let Some(bad) = found.disagreements.first() {
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
        .map(|s| run::estimate(&crate::ALLOCATOR, s, LADDER[0], None))
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

/// Writes `results.json` and `index.html` into `out`, together.
fn write(out: &Path, r: &ScaleResults) -> Result<(), Failure> {
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

/// This program as the scale run's host: its allocator, its memory admission, itself as the
/// workers.
struct Program;

impl Program {
    /// This program, to run one of its hidden worker commands.
    fn itself() -> std::io::Result<Command> {
        std::env::current_exe().map(Command::new)
    }
}

impl ScaleHost for Program {
    fn allocator(&self) -> &CountingAllocator {
        &crate::ALLOCATOR
    }

    fn exceeds_available(&self, bytes: u64) -> Option<u64> {
        limits::exceeds_available(bytes)
    }

    fn cell_worker(&self, structure: &str, triangles: u64) -> std::io::Result<Command> {
        let mut worker = Self::itself()?;
        // The run admitted the cell by its own estimate: the worker does not check again by
        // the sample's, which errs large.
        worker
            .args(["--allow-memory", "scale-cell", "--structure", structure])
            .arg("--triangles")
            .arg(triangles.to_string());
        Ok(worker)
    }

    fn convert_worker(&self, triangles: u64, file: &Path) -> std::io::Result<Command> {
        let mut worker = Self::itself()?;
        worker
            .args(["convert", &format!("torus:{triangles}")])
            .arg(file)
            .args(["--to", "che", "--level", "2"]);
        Ok(worker)
    }

    fn sweep_worker(&self, file: &Path, cgroup_procs: Option<&Path>) -> std::io::Result<Command> {
        let mut worker = Self::itself()?;
        worker.arg("scale-mapped").arg(file);
        if let Some(procs) = cgroup_procs {
            worker.arg("--cgroup-procs").arg(procs);
        }
        Ok(worker)
    }
}

/// `topolab scale-cell --structure NAME --triangles N` (hidden: the scale run's worker):
/// measures `structure` on a torus of about `triangles` triangles ([`run::cell`]); returns the
/// JSON line the run reads. Exit code 1 when the structure refuses the torus, 2 for an unknown
/// name.
pub fn cell(structure: &str, triangles: u64) -> Result<String, Failure> {
    let triangles = usize::try_from(triangles)
        .ok()
        .filter(|&n| n as u64 <= limits::MAX_TRIANGLES)
        .ok_or_else(|| Failure::usage(format!("--triangles {triangles}: too many for u32 ids")))?;
    if !registry::NAMES.contains(&structure) {
        return Err(crate::input::unknown_structure(structure));
    }
    let what = format!("{structure} on a torus of {triangles} triangles");
    let estimate = run::estimate(&crate::ALLOCATOR, structure, triangles as u64, None);
    limits::admit(&what, estimate.0)?;
    let measure = run::cell::measure(structure, triangles)
        .ok_or_else(|| crate::input::unknown_structure(structure))?
        .map_err(|e| Failure {
            message: format!("{structure} cannot store the torus: {e}"),
            code: 1,
        })?;
    Ok(serde_json::to_string(&measure).expect("a measure serializes") + "\n")
}

/// `topolab scale-mapped FILE [--cgroup-procs PATH]` (hidden: the scale run's worker): the
/// `.che` file's sweeps ([`run::mapped::sweep`]), printed as JSON.
pub fn sweep(file: &Path, cgroup_procs: Option<&Path>) -> Result<String, Failure> {
    let found: MappedRun = run::mapped::sweep(file, cgroup_procs).map_err(Failure::usage)?;
    Ok(serde_json::to_string(&found).expect("a run serializes") + "\n")
}
