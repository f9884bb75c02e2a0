//! Meshes to test and measure on: the [canonical](canonical()) tiny meshes (each named for
//! what it exercises), deterministic generators of grids, tori, spheres and random meshes of
//! any size, and the names the command line gives them ([`from_spec`]).

mod canonical;
mod generators;
mod spec;

pub use canonical::*;
pub use generators::*;
pub use spec::{from_spec, parse_spec, MeshSize, MeshSpec, SpecError, MAX_FACES, MAX_SLOTS};
