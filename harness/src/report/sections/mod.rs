//! The sections of the report page drawn here, one file each (the others still live beside
//! what they measure: the chooser, the baselines, the real meshes at scale, the changing
//! workloads, decimation, reads per query).

pub(crate) mod construction;
pub(crate) mod hull;
pub(crate) mod libigl;
pub(crate) mod memory;
pub(crate) mod meshes;
pub(crate) mod orderings;
pub(crate) mod plots;
pub(crate) mod real_meshes;
pub(crate) mod sweeps;
pub(crate) mod table_4_1;
pub(crate) mod targets;
pub(crate) mod teaching;
pub(crate) mod workloads;
