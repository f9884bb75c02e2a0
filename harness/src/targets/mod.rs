//! The Targets table: the project's performance targets, each a ratio measured with the two
//! sides taking turns: which targets and who takes turns ([`plan`](mod@plan)), the rounds of two
//! structures ([`rounds`]) and of a structure with the probe ([`probe`](mod@probe)), the ratios
//! they measure ([`measured`](mod@measured)) and the texts that explain a missed one ([`text`]);
//! the table itself is drawn with the report's sections.
//!
//! The size sweep times structures one after another, so on a shared machine a change of load
//! between two structures shows up in their ratio (one structure's own runs of one sweep have
//! ranged over more than a factor of two in a single report). Here each target's two
//! structures are built once on the largest torus of the run and then run A, B, A, B, … for
//! [`ROUNDS`] rounds, after one warm-up round; every
//! round gives one ratio, the table shows their median and their spread (the smallest and the
//! largest), and a load change hits both sides of a round alike. A target against a limit
//! (the vertex 1-ring sweep of the half-edge family against its access model, see
//! [`crate::measuring::speed_limit`]) takes turns with the probe ([`with_probe`]: its read, its chases and its
//! checksum arithmetic) and divides each round of the sweep by the limit of that round, so the
//! limit follows the machine from round to round. A row held to a limit whose chain steps do
//! arithmetic also shows the sweep against its chain at its own step's latency
//! ([`measured_chain`]).
//!
//! The runs are the size sweep's own: the harness kernels ([`crate::measuring::kernels::run`],
//! [`crate::measuring::kernels::run_workload`]), and a baseline's own loops for every run of a baseline
//! ([`topolab_structures::NativeKernels`]). Every run is timed in the measuring thread's CPU
//! time ([`Stopwatch`]), as the size sweep times construction: time slices given to other
//! processes do not count. Every run's answer must agree with the first run's; a disagreement
//! fails the report.

pub mod group;
pub mod measured;
pub mod plan;
pub mod probe;
pub mod rounds;
pub mod swept;
#[cfg(test)]
mod tests;
pub mod text;

pub use crate::measuring::timing::turns::{take_turns, Answer, Run, Spread, Stopwatch};
pub use measured::{measured, measured_chain};
pub use plan::{
    plan, Against, Cell, Group, Target, Turns, CHANGING_ROUNDS, PROBE, PROBE_CHECKSUM, PROBE_LOAD,
    PROBE_STEP, ROUNDS, TARGETS,
};
pub use probe::{with_probe, ChaseTurns, ProbeTurns};
pub use rounds::{build, pair, turns, Built};
pub use text::sequential;
