//! # topolab-harness
//!
//! Everything that measures and shows, in rooms by concern, each using only the rooms listed
//! before it:
//!
//! | room | what it holds |
//! |---|---|
//! | [`format`](mod@format) | escaping, times and sizes with their units, ratios beside their goals |
//! | [`measuring`] | the checksum, the clock and its intervals, the machine probe, the operator catalogue and the timed kernels, measuring in rounds, speed limits, fits, the memory meter, the `cargo bench` groups |
//! | [`teaching`] | a query traced read by read, an edit explained record by record: what `explain` prints and the report's teaching section draws |
//! | [`studies`] | the changing workloads, decimation, the convex hull, the reads per query counted |
//! | [`results`] | the `results.json` schema: one run's answers |
//! | [`targets`] | the developers' guide's goals, measured in turns and read from a run |
//! | [`page`] | plots, charts, thumbnails, findings: what every page draws with |
//! | [`report`] | the report: its run from the request to the files, and its sections |
//! | [`scale`] | the scale run's page |
//! | [`compare`](mod@compare) | two runs side by side |
#![deny(missing_docs)]
#![forbid(unsafe_code)]

pub mod compare;
pub mod format;
pub mod measuring;
pub mod page;
pub mod report;
pub mod results;
pub mod scale;
pub mod studies;
pub mod targets;
pub mod teaching;
