//! What the structures are checked against and tested on: the naive [`oracle`] built from the
//! face list, the shared [`conformance`](mod@conformance) suite that compares every operator
//! with it, the [`editing`] suite of random edit sequences against a naive model with its
//! [`weld`] tests, the [`differential`] test of `topolab info`, the [`decimating`] suite
//! (decimation, then reconstruction by vertex splits), and the [`growth`] of a test's time
//! with its input's size. The meshes they run on are [`crate::meshes`].

pub mod conformance;
pub mod decimating;
pub mod differential;
pub mod editing;
pub mod growth;
pub mod oracle;
pub mod weld;

/// The property-testing crate the [`conformance!`](macro@crate::conformance) macro expands to,
/// re-exported so that a crate outside the lab running the suite needs no `proptest`
/// dependency of its own (nor one of the same version).
#[doc(hidden)]
pub use proptest;
