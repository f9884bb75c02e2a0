//! Which targets the table holds and who takes turns for them: the targets, the cells they
//! time, the groups of structures that run in turns, and the record of one cell's rounds.

use topolab_structures::algorithms::changing::Changing;

/// Timed rounds of the targets the Targets section times itself (against a limit), after one
/// warm-up round, each on a fresh build: with 7 rounds on one build, the median of the che-l2 /
/// index-half-edge R00 target moved by more than its margin from run to run.
pub const ROUNDS: usize = 15;

/// Timed rounds of the changing workloads: each run is a fresh build and a whole workload
/// (about 1.5 s a round for the collapse test on a 1M-triangle torus), so fewer, to keep the
/// report within its time; no warm-up round, since every run starts from a fresh build.
pub const CHANGING_ROUNDS: usize = 3;

pub use crate::results::{Cell, Turns};
pub use crate::studies::hull::bench::HULL_POINTS;

// `Cell` is named in `results.json` (crate::results); how many rounds each cell takes is
// this plan's.
impl Cell {
    /// The rounds a cell is timed: [`ROUNDS`], or [`CHANGING_ROUNDS`] for the changing
    /// workloads and the hull (each run seconds long).
    pub fn rounds(self) -> usize {
        match self {
            Cell::Changing(_) | Cell::Hull => CHANGING_ROUNDS,
            _ => ROUNDS,
        }
    }

    /// Untimed rounds before them: one (the hull's too: hulls are timed warm), but for the
    /// changing workloads, each run from a fresh build.
    pub fn warm_up(self) -> usize {
        match self {
            Cell::Changing(_) => 0,
            _ => 1,
        }
    }

    /// The words the Targets table names it with.
    pub fn text(self) -> String {
        match self {
            Cell::R00Sweep => "vertex 1-ring sweep (r00)".into(),
            Cell::Smoothing => "smoothing".into(),
            Cell::Construction => "construction (warm builds)".into(),
            Cell::Changing(w) => w.name().into(),
            Cell::Hull => "3D convex hull (1M points in a ball)".into(),
        }
    }
}

/// What a target's structure is held against.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Against {
    /// Another structure, in the same rounds.
    Structure(&'static str),
    /// The cell's limit ([`crate::measuring::speed_limit`]).
    Limit,
}

/// One performance target: `structure`'s `cell` at most `goal` times `against`'s.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Target {
    /// What is timed.
    pub cell: Cell,
    /// The structure held to the goal.
    pub structure: &'static str,
    /// What it is compared with.
    pub against: Against,
    /// The largest ratio that meets the target.
    pub goal: f64,
}

const fn versus(cell: Cell, structure: &'static str, against: &'static str, goal: f64) -> Target {
    Target {
        cell,
        structure,
        against: Against::Structure(against),
        goal,
    }
}

const fn limit(structure: &'static str) -> Target {
    Target {
        cell: Cell::R00Sweep,
        structure,
        against: Against::Limit,
        goal: 2.0,
    }
}

/// The targets of the developers' guide, in the table's order. Every half-edge-family sweep is
/// held within 2× its limit. The last four hold the lab's structures against the Rust crates
/// that store the same thing (issue #34): lox's half-edge mesh (the index half-edge's design),
/// lox's directed-edge mesh (a CHE level 1: twin and target per corner) and baby_shark's
/// corner table (the CHE's `O` table); they are measured when the build has the crates (the
/// feature `peers`, on by default).
pub const TARGETS: [Target; 18] = [
    versus(Cell::Construction, "che-l1", "openmesh", 0.3),
    versus(Cell::R00Sweep, "che-l2", "index-half-edge", 1.35),
    versus(Cell::Smoothing, "che-l2", "index-half-edge", 1.2),
    versus(Cell::R00Sweep, "index-half-edge", "openmesh", 0.5),
    // The half-edge family: the two half-edge storages, the CHE levels and OpenMesh.
    limit("index-half-edge"),
    limit("pointer-half-edge"),
    limit("che-l0"),
    limit("che-l1"),
    limit("che-l2"),
    limit("che-l3"),
    limit("openmesh"),
    versus(
        Cell::Changing(Changing::Sqrt3),
        "index-half-edge",
        "openmesh",
        0.7,
    ),
    versus(
        Cell::Changing(Changing::Collapse),
        "index-half-edge",
        "openmesh",
        0.7,
    ),
    versus(Cell::Hull, "randomized", "qhull", 1.5),
    versus(Cell::Construction, "index-half-edge", "lox-half-edge", 1.0),
    versus(Cell::R00Sweep, "index-half-edge", "lox-half-edge", 0.7),
    versus(Cell::Construction, "che-l1", "lox-directed-edge", 1.0),
    versus(Cell::R00Sweep, "che-l2", "baby-shark-corner-table", 0.6),
];

/// One group of structures that take turns on some cells.
#[derive(Clone, Debug, PartialEq)]
pub struct Group {
    /// The structures, in the order of their turns (one or two).
    pub structures: Vec<&'static str>,
    /// The cells they are timed on, one after another.
    pub cells: Vec<Cell>,
}

/// The groups that measure every target whose structures `can` run its cell (in the report:
/// the structure ran and the size sweep measured that cell, not skipped it as too long, such as
/// the vertex 1-ring sweep of a CHE level without a vertex-to-corner map): each pair of
/// structures once with all its cells; a structure held to its limit with the probe's read
/// ([`PROBE`]).
pub fn plan(can: impl Fn(&str, Cell) -> bool) -> Vec<Group> {
    let mut groups: Vec<Group> = Vec::new();
    // The hull's target takes its turns in the hull section, on points, not structures.
    let of_structures = TARGETS.iter().filter(|t| t.cell != Cell::Hull);
    for t in of_structures.filter(|t| can(t.structure, t.cell)) {
        let structures = match t.against {
            Against::Structure(b) if can(b, t.cell) => vec![t.structure, b],
            Against::Structure(_) => continue,
            Against::Limit => vec![t.structure, PROBE],
        };
        match groups.iter_mut().find(|g| g.structures == structures) {
            Some(g) if !g.cells.contains(&t.cell) => g.cells.push(t.cell),
            Some(_) => {}
            None => groups.push(Group {
                structures,
                cells: vec![t.cell],
            }),
        }
    }
    groups
}

/// The name of the probe's turn in the rounds of a target against its limit: a sequential read
/// of the working set whose bandwidth sets the limit's bandwidth bound ([`Reader`](crate::measuring::probe::Reader)).
pub const PROBE: &str = "probe";

/// The third turn of a construction target between one of the lab's structures and an outside
/// one (a C++ baseline, a Rust crate): the lab's structure's own checks of the soup alone
/// (`MeshTopology::input_checks`, where they are a step of their own), which its build
/// includes and the outside one's does not (they run before its clock, as its users would not
/// run them), so that the page shows how much of the ratio they are, in the same rounds.
pub const CHECKS: &str = "lab-checks";

/// The probe's plain chase in the rounds of a target against its limit: ns per dependent load
/// at the latency bound's working set ([`crate::measuring::probe::Chase`]).
pub const PROBE_LOAD: &str = "probe-load";
/// The probe's chase whose steps do the chain's work ([`ChaseTurns::step`](crate::targets::probe::ChaseTurns::step)): ns per step.
pub const PROBE_STEP: &str = "probe-step";
/// The probe's checksum arithmetic ([`crate::measuring::probe::Terms`]): ns per term.
pub const PROBE_CHECKSUM: &str = "probe-checksum";
