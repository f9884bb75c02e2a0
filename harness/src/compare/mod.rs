//! Two report runs side by side (`topolab compare OLD NEW`): every cell measured in both, the
//! ratio of the new median to the old, sorted by the size of the change, and flagged only when
//! the cell moved against the rest of the run: its two intervals (each cell's order-statistics
//! interval of its rounds' median; for a file written before cells had one, its fastest–slowest
//! runs) separate once the new run is divided by the run-wide shift, the median of every
//! cell's ratio. The machine itself moves between runs (its drift probe's checksum arithmetic
//! ran 6% slower in the second of two consecutive runs here, and every cell with it), and
//! no cell's interval, taken within one run, can hold that; the shift is said on its own line,
//! with how many cells moved without it taken out. It informs and does not judge.
//!
//! A file is read in two passes: its header first (is it a topolab `results.json`, and of a
//! format this build reads: [`FORMAT_VERSION`]), then its measurements, so that a file of a newer
//! format is refused for its version rather than for a field it renamed.

mod page;

pub use page::{html, text};

use crate::measuring::kernels::Kernel;
use crate::results::{Measurement, Status, Subject, FORMAT_VERSION};
use serde::de::IgnoredAny;
use std::collections::HashMap;

/// Why a file cannot be compared.
#[derive(Debug, Clone, PartialEq)]
pub enum ReadError {
    /// Not a `results.json` of topolab's report (not JSON, or not its fields).
    NotResults(String),
    /// A `results.json` of a format this build does not read.
    Version {
        /// The file's `format_version`.
        found: u64,
    },
}

impl std::fmt::Display for ReadError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ReadError::NotResults(why) => {
                write!(f, "not a topolab results.json (written by `topolab report`): {why}")
            }
            ReadError::Version { found } => write!(
                f,
                "results.json of format version {found}, which this topolab does not read (it reads versions 0 to {FORMAT_VERSION}; version 0 is a file written before results.json had a version): compare it with the topolab that wrote it"
            ),
        }
    }
}

impl std::error::Error for ReadError {}

/// The fields that make a file a `results.json`, checked before the rest is read.
#[derive(serde::Deserialize)]
struct Header {
    format_version: Option<serde_json::Value>,
    machine: Option<IgnoredAny>,
    settings: Option<IgnoredAny>,
    measurements: Option<IgnoredAny>,
}

/// Who ran a run, where and how: what `compare` shows of each.
#[derive(Clone, Debug, Default, PartialEq, serde::Deserialize)]
pub struct RunMachine {
    /// CPU model name.
    #[serde(default)]
    pub cpu: String,
    /// Logical cores.
    #[serde(default)]
    pub cores: usize,
    /// The commit of the build (`-dirty` with uncommitted changes).
    #[serde(default)]
    pub commit: String,
    /// When it ran.
    #[serde(default)]
    pub date: String,
}

#[derive(serde::Deserialize)]
struct RunSettings {
    #[serde(default)]
    command: String,
}

#[derive(serde::Deserialize)]
struct RunMesh {
    name: String,
    #[serde(default)]
    repaired: Option<IgnoredAny>,
}

#[derive(serde::Deserialize)]
struct Body {
    machine: RunMachine,
    settings: RunSettings,
    #[serde(default)]
    meshes: Vec<RunMesh>,
    measurements: Vec<Measurement>,
}

/// One run, as `compare` reads it from its `results.json`.
#[derive(Clone, Debug, PartialEq)]
pub struct Run {
    /// Its format version (0: written before results.json had one).
    pub format_version: u64,
    /// Machine and commit.
    pub machine: RunMachine,
    /// The command that produced it.
    pub command: String,
    /// Its measurements.
    pub measurements: Vec<Measurement>,
    /// The meshes it measured repaired (see `topolab repair`).
    pub repaired: Vec<String>,
}

/// Reads a run from the bytes of its `results.json`.
pub fn read(bytes: &[u8]) -> Result<Run, ReadError> {
    let not = |e: serde_json::Error| ReadError::NotResults(e.to_string());
    let header: Header = match serde_json::from_slice(bytes) {
        Ok(h) => h,
        Err(e) if e.is_data() => {
            return Err(ReadError::NotResults(
                "it is JSON, but not an object with the fields of one".into(),
            ))
        }
        Err(e) => return Err(ReadError::NotResults(format!("it is not JSON ({e})"))),
    };
    let missing: Vec<&str> = [
        ("machine", header.machine.is_none()),
        ("settings", header.settings.is_none()),
        ("measurements", header.measurements.is_none()),
    ]
    .into_iter()
    .filter(|f| f.1)
    .map(|f| f.0)
    .collect();
    if !missing.is_empty() {
        return Err(ReadError::NotResults(format!(
            "no {} field",
            missing.join(", no ")
        )));
    }
    let format_version = match header.format_version {
        None => 0,
        Some(v) => v.as_u64().ok_or_else(|| {
            ReadError::NotResults(format!("format_version is {v}, not a whole number"))
        })?,
    };
    if format_version > FORMAT_VERSION as u64 {
        return Err(ReadError::Version {
            found: format_version,
        });
    }
    let body: Body = serde_json::from_slice(bytes).map_err(not)?;
    Ok(Run {
        format_version,
        machine: body.machine,
        command: body.settings.command,
        measurements: body.measurements,
        repaired: body
            .meshes
            .into_iter()
            .filter(|m| m.repaired.is_some())
            .map(|m| m.name)
            .collect(),
    })
}

/// A cell's median and spread, ns per item.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Spread {
    /// The median.
    pub median: f64,
    /// The fastest run (round).
    pub min: f64,
    /// The slowest run (round).
    pub max: f64,
    /// The interval of the median, when the run measured one.
    pub interval: Option<[f64; 2]>,
}

impl Spread {
    fn of(m: &Measurement) -> Option<Spread> {
        let median = m.ns_per_item.filter(|x| x.is_finite() && *x > 0.0)?;
        (m.status == Status::Measured).then(|| Spread {
            median,
            min: m.min_ns_per_item.unwrap_or(median).min(median),
            max: m.max_ns_per_item.unwrap_or(median).max(median),
            interval: m.ns_per_item_ci,
        })
    }

    fn holds(&self, x: f64) -> bool {
        self.min <= x && x <= self.max
    }

    /// Whether `self` and `other` say the cell moved: their intervals separate, or without
    /// intervals, each median lies outside the other's fastest–slowest runs.
    fn moved(&self, other: &Spread) -> bool {
        match (self.interval, other.interval) {
            (Some([a0, a1]), Some([b0, b1])) => a1 < b0 || b1 < a0,
            _ => !self.holds(other.median) && !other.holds(self.median),
        }
    }

    /// This spread with every value divided by `d`.
    fn scaled(&self, d: f64) -> Spread {
        Spread {
            median: self.median / d,
            min: self.min / d,
            max: self.max / d,
            interval: self.interval.map(|[a, b]| [a / d, b / d]),
        }
    }
}

/// One cell measured in both runs.
#[derive(Clone, Debug, PartialEq)]
pub struct Cell {
    /// Structure.
    pub structure: String,
    /// Operator, workload or construction.
    pub operator: Subject,
    /// Kernel.
    pub kernel: Kernel,
    /// Mesh.
    pub mesh: String,
    /// The old run's time.
    pub old: Spread,
    /// The new run's time.
    pub new: Spread,
    /// New median over old median.
    pub ratio: f64,
    /// The two runs' intervals of the median separate once the new run is divided by the
    /// run-wide shift ([`Comparison::shift`]): the cell moved against the
    /// rest of the run.
    pub flagged: bool,
    /// The intervals separate as measured, the shift left in.
    pub moved: bool,
}

/// Two runs compared.
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// The old run, without its measurements.
    pub old: Run,
    /// The new run, without its measurements.
    pub new: Run,
    /// Cells measured in both, the largest change first.
    pub cells: Vec<Cell>,
    /// Cells of the old run that the new one does not have.
    pub only_old: usize,
    /// Cells of the new run that the old one does not have.
    pub only_new: usize,
    /// Cells in both runs but measured in only one or neither (skipped, refused).
    pub not_measured: usize,
    /// Cells of meshes that one run measured repaired and the other as read: different meshes.
    pub repaired_in_one: usize,
    /// The run-wide shift: the median of every cell's new/old ratio (1 with no cell).
    pub shift: f64,
}

impl Comparison {
    /// The flagged cells.
    pub fn flagged(&self) -> usize {
        self.cells.iter().filter(|c| c.flagged).count()
    }

    /// The cells whose intervals separate with the run-wide shift left in.
    pub fn moved(&self) -> usize {
        self.cells.iter().filter(|c| c.moved).count()
    }

    /// The cells whose medians differ by more than `share` (0.1: 10%): the larger over the
    /// smaller, whichever run it is.
    pub fn differ_by_more_than(&self, share: f64) -> usize {
        self.cells
            .iter()
            .filter(|c| c.ratio.max(1.0 / c.ratio) > 1.0 + share)
            .count()
    }
}

/// Compares `new` with `old` (consumed: their measurements become the cells).
pub fn compare(mut old: Run, mut new: Run) -> Comparison {
    type Key = (String, Subject, Kernel, String);
    let key = |m: &Measurement| (m.structure.clone(), m.operator, m.kernel, m.mesh.clone());
    let old_cells: HashMap<Key, &Measurement> =
        old.measurements.iter().map(|m| (key(m), m)).collect();
    let mut seen = 0;
    let mut cells = Vec::new();
    let (mut only_new, mut not_measured, mut repaired_in_one) = (0, 0, 0);
    for m in &new.measurements {
        let Some(o) = old_cells.get(&key(m)) else {
            only_new += 1;
            continue;
        };
        seen += 1;
        if old.repaired.contains(&m.mesh) != new.repaired.contains(&m.mesh) {
            repaired_in_one += 1;
            continue;
        }
        let (Some(a), Some(b)) = (Spread::of(o), Spread::of(m)) else {
            not_measured += 1;
            continue;
        };
        cells.push(Cell {
            structure: m.structure.clone(),
            operator: m.operator,
            kernel: m.kernel,
            mesh: m.mesh.clone(),
            old: a,
            new: b,
            ratio: b.median / a.median,
            flagged: false,
            moved: a.moved(&b),
        });
    }
    let shift = {
        let mut r: Vec<f64> = cells.iter().map(|c| c.ratio).collect();
        r.sort_by(f64::total_cmp);
        if r.is_empty() {
            1.0
        } else {
            crate::measuring::timing::median(&r)
        }
    };
    for c in &mut cells {
        c.flagged = c.old.moved(&c.new.scaled(shift));
    }
    let only_old = old_cells.len() - seen;
    cells.sort_by(|a, b| {
        b.ratio
            .ln()
            .abs()
            .total_cmp(&a.ratio.ln().abs())
            .then_with(|| {
                (&a.structure, a.operator.name(), a.kernel, &a.mesh).cmp(&(
                    &b.structure,
                    b.operator.name(),
                    b.kernel,
                    &b.mesh,
                ))
            })
    });
    old.measurements = Vec::new();
    new.measurements = Vec::new();
    Comparison {
        old,
        new,
        cells,
        only_old,
        only_new,
        not_measured,
        repaired_in_one,
        shift,
    }
}

/// The text of a `results.json` of `cells` measurements, in the current format: the sample on
/// which `topolab compare` measures the memory of reading one before it reads a large file.
pub fn sample_results(cells: usize) -> String {
    // Each cell on a mesh of its own: every cell of one run has its match in the other.
    let measurements: Vec<serde_json::Value> = (0..cells)
        .map(|i| {
            serde_json::json!({
                "structure": "index-half-edge", "operator": "r00", "kernel": "sweep",
                "mesh": format!("torus-{i}"), "family": "torus", "triangles": 1_000_000,
                "status": "measured", "ns_per_item": 7.25, "min_ns_per_item": 7.0,
                "max_ns_per_item": 9.5, "items": 500_000, "reps": 25,
                "checksum": "13793524636986848482", "bytes": null, "peak_bytes": null,
                "declared_bytes": null, "estimate_ns_per_item": null, "native": false, "note": null
            })
        })
        .collect();
    serde_json::json!({
        "format_version": FORMAT_VERSION,
        "machine": {"cpu": "cpu", "cores": 2, "commit": "0000000", "date": "2026-01-01 00:00 UTC"},
        "settings": {"command": "topolab report"},
        "meshes": [],
        "measurements": measurements,
    })
    .to_string()
}

#[cfg(test)]
mod tests;
