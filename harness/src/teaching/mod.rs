//! What the lab shows a student, in one home that `topolab explain`, the report's teaching
//! section (and any later explorer) call, so that each shows the same records: a query traced
//! read by read on a structure's containers ([`trace`]), and an edit explained, the records it
//! writes old → new with a picture before and after ([`edits`]).

pub mod edits;
pub mod trace;
