//! What every part of the crate speaks: element ids ([`ids`]), the input every structure is
//! built from ([`soup`]), the one trait every structure implements with its operators and
//! declared costs ([`topology`], its vocabulary of operators and costs in [`operator`]), the application workloads named across the lab ([`workload`]),
//! the editing operations beside it ([`edit`], named in [`edit_op`], with what they share about a vertex's surroundings in [`neighbourhood`]), the typed errors ([`error`]) and the geometric attributes
//! computed through the trait ([`attributes`]), the access model a structure may declare for
//! each operator ([`access`]), the family a structure belongs to ([`family`]), the corner
//! arithmetic of triangles stored face by face ([`corners`]) and what a `.che` file is made of
//! and why one is refused ([`che_format`]).

pub mod access;
pub mod attributes;
pub mod che_format;
pub mod corners;
pub mod delegate;
pub mod edit;
pub mod edit_op;
pub mod error;
pub mod family;
pub mod ids;
pub mod link;
pub mod neighbourhood;
pub mod offers;
pub mod operator;
pub mod reads;
pub mod rewrite;
pub mod soup;
pub mod topology;
pub mod workload;
