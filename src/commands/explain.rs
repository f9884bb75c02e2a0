//! `topolab explain`: what a structure stores for the CHE chapter's open tetrahedron (or a
//! mesh given), record by record; `explain che` shows the four CHE levels
//! ([`super::explain_che`]); `--trace` prints the reads of one query ([`super::explain_trace`]).

use super::explain_che;
use super::explain_trace::{explain_trace, TraceRequest};
use super::list::Row;
use crate::input::{mesh_or_tetrahedron, unknown_structure, Failure};
use crate::limits;
use crate::registry::{self, StructureVisitor};
use topolab_harness::reads::trace::Query;
use topolab_structures::{Error, MeshTopology, PolygonSoup};

/// The text of `topolab explain NAME [--mesh M] [--trace OP --vertex N]`: the CHE levels for
/// `che`, one structure's records otherwise; with `--trace`, the reads of one query ([`run_traced`]).
pub fn run(
    name: &str,
    mesh: Option<&str>,
    trace: Option<&str>,
    vertex: Option<u32>,
) -> Result<String, Failure> {
    run_traced(
        name,
        mesh,
        trace.map(|op| TraceRequest {
            op: op.to_string(),
            query: Query {
                vertex,
                ..Query::default()
            },
            structures: Vec::new(),
        }),
    )
}

/// [`run`] with a whole trace request (`--trace OP --vertex N | --edge E | --face F
/// --structures a,b`, [`explain_trace`]).
pub fn run_traced(
    name: &str,
    mesh: Option<&str>,
    trace: Option<TraceRequest>,
) -> Result<String, Failure> {
    let Some(request) = trace else {
        return if name == explain_che::NAME {
            explain_che::explain_che(mesh, None, None)
        } else {
            explain(name, mesh)
        };
    };
    let star = matches!(request.op.as_str(), "r00" | "r01" | "r02");
    if name == explain_che::NAME {
        // The CHE's own trace of each level's vertex-star algorithm (Algorithm 7's order).
        if star && request.structures.is_empty() && request.query.vertex.is_some() {
            return explain_che::explain_che(mesh, Some(&request.op), request.query.vertex);
        }
        return explain_trace(&["che-l0", "che-l1", "che-l2", "che-l3"], mesh, &request);
    }
    explain_trace(&[name], mesh, &request)
}

/// The structure's records after a heading, in one string (no copy of the long part).
struct ExplainVisit<'a>(&'a PolygonSoup, String);
impl StructureVisitor for ExplainVisit<'_> {
    type Output = Result<String, Error>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        let m = M::from_soup(self.0)?;
        let mut out = self.1;
        m.explain(&mut out)
            .expect("writing to a String cannot fail");
        Ok(out)
    }
}

fn explain(name: &str, mesh: Option<&str>) -> Result<String, Failure> {
    let grids_only = registry::visit(name, Row)
        .ok_or_else(|| unknown_structure(name))?
        .capabilities
        .grids_only;
    let (soup, label) = mesh_or_tetrahedron(mesh, grids_only, |sample| {
        let text = registry::visit(name, ExplainVisit(sample, String::new()));
        let text = text.and_then(Result::ok).unwrap_or_default();
        limits::growing_text(&text)
    })?;
    registry::visit(name, ExplainVisit(&soup, format!("{name} for {label}\n\n")))
        .ok_or_else(|| unknown_structure(name))?
        .map(|text| text + &super::explain_costs::edit_costs(name))
        .map_err(|e| Failure {
            message: format!("{name} cannot store {label}: {e}"),
            code: 1,
        })
}
