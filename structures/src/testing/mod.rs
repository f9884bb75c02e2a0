//! What the structures are checked against and tested on: the naive [`oracle`] built from the
//! face list, the shared [`conformance`](mod@conformance) suite that compares every operator
//! with it, and the canonical and generated [`meshes`].

pub mod conformance;
pub mod meshes;
pub mod oracle;
