//! The measuring machinery every study and both runs share, lowest first: the checksum every
//! kernel folds its answers into ([`checksum`]), the clock and its statistics ([`timing`]),
//! the machine and its physical limits ([`machine`], [`probe`]), the operator catalogue and
//! the timed kernels ([`catalogue`], [`kernels`]), what measuring a structure on a mesh is made
//! of ([`measure`]) and the rounds every cell is measured in ([`rounds`]), a sweep cell's speed
//! limit ([`speed_limit`]), the fitted exponents ([`fit`]), the memory meter over the counting
//! allocator ([`counting`]), the machine's memory as runs plan with it ([`memory`]), the `cargo bench` groups ([`bench`](mod@bench)), how long each
//! part of a run took ([`phases`]) and how the outside libraries were built and used
//! ([`baselines`]).

pub mod baselines;
pub mod bench;
pub mod catalogue;
pub mod cells;
pub mod checksum;
pub mod counting;
pub mod fit;
pub mod kernels;
pub mod machine;
pub mod measure;
pub mod memory;
pub mod phases;
pub mod probe;
pub mod rounds;
pub mod speed_limit;
pub mod timing;
