//! What the lab does with the structures: the 3D convex [`hull`] built on the winged-edge,
//! the consistency [`checks`] of a file as written and its topological [`summary`], the
//! [`repair`] of what the checks find in a mesh's topology, mesh refinement, uniform
//! ([`refine`]) and adaptive by longest-edge bisection on any editable structure
//! ([`adaptive`]), the changing workloads of the Surface_mesh benchmark on any editable
//! structure ([`changing`]), the selection, rotation, scaling and smoothing of vertices
//! ([`select`]), decimation by quadric error and its reconstruction
//! ([`decimate`]), the declared cost of a step of each refinement and thinning
//! ([`schemes`]), element renumbering ([`ordering`]), and the union-find they share.

pub mod adaptive;
pub mod changing;
pub mod checks;
pub mod decimate;
pub mod hull;
pub mod ordering;
pub mod refine;
pub mod repair;
pub mod schemes;
pub mod select;
pub mod summary;
pub(crate) mod union_find;
pub mod weld;
