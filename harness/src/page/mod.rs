//! The drawing every page of the crate shares (the report's, compare's, the scale run's): the
//! log-log plots ([`plot`]), bar charts, figures and thumbnails ([`svg`], [`thumbnail`]), how
//! a repaired mesh is marked ([`repaired`]), the skipped work grouped for the notes
//! ([`skips`]), and the run's findings in Markdown ([`findings`]).

pub mod findings;
pub mod plot;
pub mod repaired;
pub mod skips;
pub mod svg;
pub mod thumbnail;
