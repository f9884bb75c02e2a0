//! # topolab-harness
//!
//! The operator catalogue (what each operator takes and answers), the kernels that time it on
//! any structure (in the report and in the `cargo bench` groups of [`bench`](mod@bench)),
//! [`timing`] (medians, contenders taking turns, the memory meter), complexity fits, the machine
//! probe, the [`results`] schema, the HTML [`report`] and its sections, the
//! [`targets`] measured in turns, and [`compare`](mod@compare): two runs side by side.
#![deny(missing_docs)]
#![forbid(unsafe_code)]

pub mod baselines;
pub mod bench;
pub mod catalogue;
pub mod changing;
pub mod checksum;
pub mod compare;
pub mod counting;
pub mod decimate;
pub mod edit_explain;
pub mod findings;
pub mod fit;
pub mod format;
pub mod hull;
pub mod kernels;
pub mod limit;
pub mod machine;
pub mod measure;
pub mod phases;
pub mod plot;
pub mod probe;
pub mod reads;
pub mod repaired;
pub mod report;
pub mod results;
pub mod rounds;
pub mod scale;
pub mod skips;
pub mod svg;
pub mod targets;
pub mod thumbnail;
pub mod timing;
