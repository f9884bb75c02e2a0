//! The sections of the report page, one file each, and the one list they are run and shown
//! in ([`SECTIONS`]): `--sections` names, the phases of their measurements in `results.json`
//! and the page's order all come from it. A new section is a new file here and one line in
//! the list (with its `mod` line).

use crate::report::section::Section;

pub mod changing;
pub mod chooser;
pub mod construction;
pub mod decimate;
pub mod edit_ops;
pub mod hull;
pub mod libigl;
pub mod memory;
pub mod meshes;
pub mod orderings;
pub mod plots;
pub mod real_at_scale;
pub mod real_meshes;
pub mod sweeps;
pub mod table_4_1;
pub mod targets;
pub mod teaching;
pub mod workloads;

/// Every section, in page order.
pub static SECTIONS: &[&dyn Section] = &[
    &chooser::Chooser,
    &table_4_1::Table41,
    &plots::Plots,
    &sweeps::Sweeps,
    &workloads::Workloads,
    &memory::Memory,
    &construction::Construction,
    &orderings::Orderings,
    &real_meshes::RealMeshes,
    &real_at_scale::RealAtScale,
    &libigl::Libigl,
    &hull::Hull,
    &changing::ChangingMeshes,
    &edit_ops::EditOps,
    &decimate::Decimate,
    &teaching::Teaching,
    &meshes::Meshes,
    &targets::Targets,
];

/// The section called `name`.
pub fn by_name(name: &str) -> Option<&'static dyn Section> {
    SECTIONS.iter().copied().find(|s| s.name() == name)
}

/// The names of every section, in page order.
pub fn names() -> Vec<&'static str> {
    SECTIONS.iter().map(|s| s.name()).collect()
}
