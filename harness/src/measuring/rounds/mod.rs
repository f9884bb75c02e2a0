//! Measuring in rounds: how every timed cell of the size sweep (and of the element-order
//! comparison) gets a number that holds still, and an interval that says how still.
//!
//! One run of a cell is one draw of everything that moves it besides the structure: where the
//! allocator put its arrays (which cache sets and pages their lines fall in), what the machine
//! was doing at that moment, which queries were drawn. Repeating a run on the same build at the
//! same moment measures none of that; the spread of such repetitions says nothing about the
//! next report. So every cell is measured in *rounds*:
//!
//! - **A fresh build per round.** Each round drops every structure of the mesh and builds each
//!   again, in a fresh random order, timing the builds (the construction cell's rounds; the
//!   first [`COLD_ROUNDS`] also time a build right after the allocator returned its free memory,
//!   the cold build). The round's cells run on these builds.
//! - **Interleaved.** For each cell (operator and kernel, or workload) every structure runs
//!   once per round, in a fresh random order per cell and round (the random interleaving Google
//!   Benchmark added for the same reason), so that a change of load or clock hits the
//!   structures of a round alike and no structure always runs after the same one.
//! - **Sampled queries that are not in cache.** Each round draws its own queries
//!   ([`crate::measuring::kernels::draw_queries`], the same for every structure within the round), cut into
//!   passes of [`PASS`]; a round runs its passes in order until it has spent [`ROUND_NS`], so no
//!   query is asked twice in a round and a pass never finds its records left in cache by an
//!   earlier pass of the same cell.
//! - **A round's value** of a sweep or workload is the median of batches of runs after an
//!   untimed warm-up run ([`WARM_UP_BELOW_NS`]), each batch timed by one reading of the
//!   measuring thread's CPU clock; of a sampled cell, the time of all its passes per query.
//! - **A cell's value** is the median of its rounds, its interval the order-statistics
//!   interval of that median ([`crate::measuring::timing::interval`]): at least 95% from
//!   [`ROUNDS_FOR_LEVEL`](crate::measuring::timing::interval::ROUNDS_FOR_LEVEL) rounds on. While some
//!   cell's interval is wider than [`WIDE`] of its value, the mesh gets another whole round, as
//!   long as the plan's budget for extra rounds lasts: every cell of a mesh has the same rounds,
//!   so two structures' medians are taken over the same moments of the machine (with extra
//!   rounds for some cells only, one run's che-l3 sweep came out 14% above che-l2's, the same
//!   walk).
//!
//! Every answer is compared: a sweep's or workload's with the first structure's on the mesh, a
//! sampled pass's with every other structure's same pass of the same round, a build's face
//! count with the structure's first. A disagreement stops the run.

mod entry;
mod mesh;
mod schedule;

pub use crate::measuring::measure::RoundPlan;
pub use entry::{Contender, Entry, SetUp, Setup};
pub use mesh::{measure_mesh, measure_structure, round_sets, MeshRounds};
pub use schedule::{run_rounds, RoundsRun};

use crate::measuring::cells::Subject;
use crate::measuring::kernels::Kernel;
use crate::measuring::timing::turns::Answer;
use topolab_structures::{Input, Operator, Workload};

/// A cell of the rounds: what is timed and how.
pub type CellKey = (Subject, Kernel);

/// The construction cell.
pub const CONSTRUCTION: CellKey = (Subject::Construction, Kernel::Construction);

/// What one round of a cell answered.
#[derive(Clone, Debug, PartialEq)]
pub enum Said {
    /// A sweep's checksum or a workload's value, the same in every round.
    One(Answer),
    /// A sampled round's checksum of each pass, in order.
    Passes(Vec<u64>),
}

/// Queries of one sampled pass: few enough that a pass of a scanning structure's queries (a
/// scan of the mesh each) stays short on the largest meshes, enough that a pass of constant-time
/// queries is not the clock's resolution.
pub const PASS: usize = 16;

/// Sampled queries drawn per kind and round: a round of the fastest structure's queries (about
/// 50 ns each) fills [`ROUND_NS`] before it runs out of fresh ones.
pub const SAMPLES: usize = 4096;

/// Timed time of one cell in one round, at least: a round's runs are repeated until they took
/// this long.
pub const ROUND_NS: f64 = 1e6;

/// One batch of runs of a sweep or workload, timed by one reading of the clock, lasts at least
/// this long: reading the thread's CPU clock costs a system call.
pub const BATCH_NS: f64 = 2e5;

/// A sampled round looks at the wall clock after this many ns of passes (from the first pass):
/// often enough to stop near [`ROUND_NS`], rarely enough not to time the clock.
pub const PASS_CHECK_NS: f64 = 5e4;

/// A run shorter than this gets an untimed warm-up run before it in each round (its caches as
/// its own last run left them, not as the structure that ran before it did); a longer run is
/// its own warm-up.
pub const WARM_UP_BELOW_NS: f64 = 50e6;

/// Rounds that time a cold build before the warm one, where cold builds are shown (the
/// construction table's largest torus).
pub const COLD_ROUNDS: usize = 3;

/// A cell whose interval is wider than this share of its value asks for extra rounds.
pub const WIDE: f64 = 0.10;

/// Every cell of a structure besides construction, in the sweep's order: each operator's
/// sampled queries then its sweep (boundary curves: the sweep only, one question about the
/// whole mesh), then the workloads; with `light`, the vertex 1-ring sweep only; without
/// `sampled`, no sampled cell.
pub fn cells(light: bool, sampled: bool) -> Vec<CellKey> {
    if light {
        return vec![(Subject::Query(Operator::R00), Kernel::Sweep)];
    }
    let mut out = Vec::new();
    for op in Operator::ALL {
        if sampled && op.input() != Input::Mesh {
            out.push((Subject::Query(op), Kernel::Sampled));
        }
        out.push((Subject::Query(op), Kernel::Sweep));
    }
    out.extend(
        Workload::ALL
            .into_iter()
            .map(|w| (Subject::Workload(w), Kernel::Workload)),
    );
    out
}

/// Whether `op` is about the boundary (its tests and its curves): the operators the report
/// measures on open grids (a closed torus has no boundary).
pub fn boundary(op: Operator) -> bool {
    matches!(
        op,
        Operator::BoundaryVertex | Operator::BoundaryEdge | Operator::BoundaryCurves
    )
}

/// The round settings of `plan`, as `results.json` states them.
pub fn round_settings(
    plan: &crate::measuring::measure::Plan,
) -> crate::measuring::cells::RoundSettings {
    crate::measuring::cells::RoundSettings {
        min_rounds: plan.rounds.min_rounds,
        max_rounds: plan.rounds.max_rounds,
        extra: plan.rounds.extra,
        pass: PASS,
        round_ns: ROUND_NS,
        wide: WIDE,
    }
}
