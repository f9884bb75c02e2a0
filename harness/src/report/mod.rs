//! The report: the run from its request to its files ([`pipeline`]), what a run is asked for
//! and what a section measures with ([`run`]), what a section is ([`section`]), the sections in
//! their one list ([`sections`]), what a run measures for the sections it shows
//! ([`selection`]), the meshes it repairs and refines ([`repair`], [`refined`]), its clock and
//! budgets ([`clock`]), and the page: its shell ([`page`]), the formatting its sections share
//! ([`crate::format`], shared with every page of the crate), the look-ups of cells they share
//! (`cells`) and how sure a cell is (`sure`).

pub(crate) mod cells;
pub mod clock;
pub mod listed;
pub mod page;
pub mod pipeline;
pub mod reads;
pub mod refined;
pub mod repair;
pub mod run;
pub mod section;
pub mod sections;
pub mod selection;
pub(crate) mod sure;
