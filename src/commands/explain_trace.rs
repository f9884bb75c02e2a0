//! `topolab explain NAME --trace OP --vertex N | --edge E | --face F [--mesh M]
//! [--structures a,b]`: one query on one or several structures, read by read, with the
//! containers named as the sources name them, then the answer and the number of reads.
//!
//! The reads come from the counting build of the structures
//! (`topolab_harness::teaching::trace`), which the timed code never runs. Edges are numbered as
//! the soup's (the edge list's and the half-edge's ids; see there), so `--edge E` is the same
//! edge on every structure. `explain che --trace r00|r01|r02 --vertex N` keeps the CHE's own
//! trace of Algorithm 7 ([`super::explain_che`]); `explain che --trace OP` otherwise traces
//! the four levels side by side.

use crate::input::{mesh_or_tetrahedron, Failure};
use crate::limits;
use topolab_harness::teaching::trace::{self, counted_soup, Query, TraceError};
use topolab_structures_counted::{Input, Operator};

/// What `--trace` asks.
#[derive(Clone, Debug, Default)]
pub struct TraceRequest {
    /// The operator's name (`r00`, `boundary-edge`, ...).
    pub op: String,
    /// The element asked about.
    pub query: Query,
    /// Structures to put beside the one named.
    pub structures: Vec<String>,
}

/// The text of a trace of `request` on `names` (the structure named first), on `mesh` or the
/// open tetrahedron.
pub fn explain_trace(
    names: &[&str],
    mesh: Option<&str>,
    request: &TraceRequest,
) -> Result<String, Failure> {
    let op = Operator::from_name(&request.op).ok_or_else(|| {
        let known: Vec<&str> = Operator::ALL.iter().map(|o| o.name()).collect();
        Failure::usage(format!(
            "--trace {}: no such operator; known: {}",
            request.op,
            known.join(", ")
        ))
    })?;
    let mut all: Vec<&str> = Vec::new();
    for &n in names.iter().chain(
        request
            .structures
            .iter()
            .map(String::as_str)
            .collect::<Vec<_>>()
            .iter(),
    ) {
        if n.is_empty() || all.contains(&n) {
            continue;
        }
        if !trace::names().contains(&n) {
            return Err(Failure::usage(format!(
                "--trace: no structure {n:?} to trace; the lab's structures: {} (the C++ baselines read inside their library)",
                trace::names().join(", ")
            )));
        }
        all.push(n);
    }
    let grids_only = all
        .iter()
        .all(|n| n.contains("grid") || *n == "height-field");
    // A trace prints a line per read: bounded by the reads of the slowest query asked.
    let (soup, label) = mesh_or_tetrahedron(mesh, grids_only, |sample| {
        let text = all
            .iter()
            .filter_map(|n| trace::trace(n, &counted_soup(sample), op, request.query).ok())
            .map(|t| t.text())
            .collect::<String>();
        limits::growing_text(&text)
    })?;
    let soup = counted_soup(&soup);
    let mut out = format!(
        "{} for {label}, read by read:\n",
        describe(op, request.query)
    );
    for n in all {
        match trace::trace(n, &soup, op, request.query) {
            Ok(t) => {
                out.push('\n');
                out.push_str(&t.text());
            }
            Err(e @ TraceError::Refused(_)) => {
                return Err(Failure {
                    message: e.to_string(),
                    code: 1,
                })
            }
            Err(e) => return Err(Failure::usage(e.to_string())),
        }
    }
    Ok(out)
}

fn describe(op: Operator, q: Query) -> String {
    let mut s = op.name().to_uppercase();
    if let Some(v) = q.vertex.filter(|_| matches!(op.input(), Input::Vertex)) {
        s += &format!(" of v{v}");
    }
    if let Some(e) = q
        .edge
        .filter(|_| matches!(op.input(), Input::Edge | Input::EdgeOfFace))
    {
        s += &format!(" of edge E{e}");
    }
    if let Some(f) = q
        .face
        .filter(|_| matches!(op.input(), Input::Face | Input::EdgeOfFace))
    {
        s += &format!(" in face f{f}");
    }
    s
}
