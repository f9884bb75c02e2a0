//! One edit explained: the records an editing operation ([`EditOp`](topolab_structures::EditOp)) writes in a structure,
//! old → new, and a picture of the mesh before and after it. `topolab explain NAME --op OP`
//! prints it; the report's teaching section draws it ([`crate::teaching::edits::picture::TeachingEdit`]).
//! Both go through this module, so the lines the report shows are the lines the command
//! prints.
//!
//! [`edit`] is the one place that knows each operation: what it acts on ([`SubjectKind`]),
//! what it reads of that neighbourhood, an edit done before it where it needs one (garbage
//! collection collects what a vertex deletion marked), and the call. It is an exhaustive
//! `match` on [`EditOp`](topolab_structures::EditOp), so an operation added to the enum is a compile error there until it
//! is given its arm, and one arm is all it needs: the command line, the default element
//! ([`choose`]) and the records follow from it.
//!
//! Elements are numbered the same on every structure ([`Subject`]): vertices and faces as the
//! mesh's (a built structure keeps the soup's vertex ids; a face is found in each structure by
//! its corners), edges as the index half-edge numbers them (the mesh's edges in order of first
//! appearance, which `--trace` uses too; an edge is found in each structure by its ends).

mod choose;
pub mod counted;
pub mod described;
mod explained;
mod operations;
pub mod picture;
mod prepare;
pub mod records;
pub mod refusals;
mod subject;

pub use choose::{
    choose, choose_on, default_case, default_case_on, teaching_edits, Choice, DefaultCase, GRID,
    QUAD_STRIP, TAUGHT, TETRAHEDRON, TORUS, TRIED,
};
pub use explained::{explain_on, Explained};
pub use operations::{edit, kind_of, Call, Edit, Target};
pub use prepare::{edge_between, mirror_image, prepare, Prepared};
pub use subject::{Subject, SubjectKind};

/// The structures' crate the edits here act on: the timed build. The same call table, subjects
/// and records are compiled a second time over the counting build in [`counted`].
use topolab_structures as st;
