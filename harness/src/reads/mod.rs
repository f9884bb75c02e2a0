//! Reads per query: every container read of a query, traced for teaching and counted as a
//! measurement, through the counting build of the structures (`topolab-structures-counted`,
//! see `topolab_structures::core::reads`), which the timed code never links into its kernels.
//!
//! - [`trace`]: one query on one structure, read by read (`topolab explain NAME --trace`, the
//!   report's teaching section);
//! - [`count`]: the mean reads per query of every operator on every structure and mesh size,
//!   with exponents fitted against the mesh size and compared with the declared costs (the
//!   report's "reads per query" table);
//! - [`section`]: that table and the teaching section of the report.

pub mod count;
pub mod section;
pub mod trace;
