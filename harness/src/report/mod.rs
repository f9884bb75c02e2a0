//! The report page drawn from [`crate::results::Results`]: its shell ([`page`]), the formatting
//! its sections share ([`format`](mod@format)), the look-ups of cells they share (`cells`) and the sections
//! drawn here (`sections`).

pub(crate) mod cells;
pub mod format;
pub mod page;
pub(crate) mod sections;
