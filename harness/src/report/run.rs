//! What a report run is asked for ([`Request`]: plain data, not a command line's), how it
//! fails ([`ReportError`]), and what a section's own measurement works with ([`Run`]).

use crate::measuring::measure::Plan;
use crate::measuring::rounds::{SetUp, Setup};
use crate::measuring::timing::meter::MemoryMeter;
use crate::results::Results;
use std::path::PathBuf;
use topolab_structures::PolygonSoup;

/// A family of meshes a report run measures (`--meshes`).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum MeshFamily {
    /// Generated closed tori.
    Torus,
    /// Generated open grids (with boundary).
    Grid,
    /// The meshes `make data` fetched into `bench-data/cache/`, when present.
    Real,
    /// Two of them refined by Loop subdivision to 1.2M and 3.3M triangles, measured like the
    /// tori.
    Refined,
}

impl MeshFamily {
    /// Every family, in the order of `--meshes`' default.
    pub const ALL: [MeshFamily; 4] = [
        MeshFamily::Torus,
        MeshFamily::Grid,
        MeshFamily::Real,
        MeshFamily::Refined,
    ];

    /// Its name in `--meshes` and as the family of its meshes in the results.
    pub const fn name(self) -> &'static str {
        match self {
            MeshFamily::Torus => "torus",
            MeshFamily::Grid => "grid",
            MeshFamily::Real => "real",
            MeshFamily::Refined => "refined",
        }
    }

    /// The family called `name`; an unknown one is an error that lists the known.
    pub fn from_name(name: &str) -> Result<Self, ReportError> {
        Self::ALL
            .into_iter()
            .find(|f| f.name() == name)
            .ok_or_else(|| {
                let known: Vec<&str> = Self::ALL.iter().map(|f| f.name()).collect();
                ReportError::Usage(format!(
                    "unknown mesh family {name:?}; known: {}",
                    known.join(", ")
                ))
            })
    }

    /// Whether the lab generates its meshes (tori and grids at every size of the run).
    pub fn generated(self) -> bool {
        matches!(self, MeshFamily::Torus | MeshFamily::Grid)
    }
}

/// A report run, asked for.
#[derive(Clone, Debug)]
pub struct Request {
    /// A smaller, faster run (three sizes up to 16k triangles, short budgets).
    pub quick: bool,
    /// The full measurement, beyond the default's time budget.
    pub full: bool,
    /// Triangle counts of the size sweep, smallest first, each once.
    pub sizes: Vec<usize>,
    /// The structures measured, by name, in the order of the run.
    pub names: Vec<String>,
    /// `--structures` as given (it may name libigl, which is not a structure), `None` for
    /// every structure: the sections with a subject of their own run only when it names it.
    pub structures: Option<Vec<String>>,
    /// The structures of the run that come from outside the lab (every table shows them; the
    /// element-order section measures them beside its few).
    pub added: Vec<String>,
    /// The sections asked for, by name (`None`: every section).
    pub sections: Option<Vec<String>>,
    /// The mesh families, each once.
    pub meshes: Vec<MeshFamily>,
    /// The output folder.
    pub out: PathBuf,
    /// Size of the memory probe's arrays, MiB.
    pub probe_mb: usize,
    /// The command that asked for it, as the page and the results show it.
    pub command: String,
}

/// Why a report run stopped.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ReportError {
    /// The request cannot be run (an unknown name, sizes past what the machine holds).
    Usage(String),
    /// A measurement failed or two answers disagree: the run stops rather than show it.
    Measurement(String),
    /// The report cannot be written.
    Output(String),
}

impl ReportError {
    /// The message, with its context.
    pub fn message(&self) -> &str {
        match self {
            ReportError::Usage(m) | ReportError::Measurement(m) | ReportError::Output(m) => m,
        }
    }
}

impl std::fmt::Display for ReportError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.message())
    }
}

impl std::error::Error for ReportError {}

/// One mesh of the run: its name, its family and its faces.
pub type Case = (String, String, PolygonSoup);

/// The structures of a run, by name, for the sections that measure some of them themselves
/// ([`Listed`](crate::report::listed::Listed) lists those of a list of structures).
pub trait Roster {
    /// The structure called `name` set up on `case` for rounds ([`crate::measuring::rounds`]); `None` for
    /// a name not in the list.
    fn set_up<'a>(&self, name: &str, set_up: SetUp<'a, '_>) -> Option<Result<Setup<'a>, String>>;

    /// The turns of a target's group: the structure called `first` with the one called
    /// `second`, or with the probe (`None` or [`PROBE`](crate::targets::plan::PROBE)); `None`
    /// for a first name not in the list.
    fn targets(
        &self,
        first: &str,
        second: Option<&str>,
        case: &crate::targets::group::Case,
    ) -> Option<Result<Vec<crate::targets::plan::Turns>, String>>;
}

/// What a section's own measurement works with: the request, the run's structures and meshes,
/// the size sweep's plan, the results so far (it adds its rows), and the process's meter.
pub struct Run<'a> {
    /// The request.
    pub request: &'a Request,
    /// Every mesh of the run, in the order measured.
    pub cases: &'a [Case],
    /// The size sweep's plan (budgets and repetitions).
    pub plan: &'a Plan,
    /// The results so far.
    pub results: &'a mut Results,
    /// The structures by name.
    pub structures: &'a dyn Roster,
    /// The process's memory meter and clock.
    pub meter: &'a dyn MemoryMeter,
    /// The version of libigl that answered, when its section ran (for the baselines' rows).
    pub libigl_version: Option<String>,
}
