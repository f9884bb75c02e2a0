//! `topolab explain`: what a structure stores for the CHE chapter's open tetrahedron (or a
//! mesh given), record by record; `explain che` shows the four CHE levels
//! ([`super::explain_che`]).

use super::explain_che;
use super::list::Row;
use crate::input::{mesh_or_tetrahedron, unknown_structure, Failure};
use crate::registry::{self, StructureVisitor};
use topolab_structures::{Error, MeshTopology, PolygonSoup};

/// The text of `topolab explain NAME [--mesh M] [--trace OP --vertex N]`: the CHE levels for
/// `che`, one structure's records otherwise (`--trace` is for `che` only).
pub fn run(
    name: &str,
    mesh: Option<&str>,
    trace: Option<&str>,
    vertex: Option<u32>,
) -> Result<String, Failure> {
    if name == explain_che::NAME {
        return explain_che::explain_che(mesh, trace, vertex);
    }
    match trace {
        Some(_) => Err(Failure::usage(format!(
            "--trace works with `explain {}` only",
            explain_che::NAME
        ))),
        None => explain(name, mesh),
    }
}

struct ExplainVisit<'a>(&'a PolygonSoup);
impl StructureVisitor for ExplainVisit<'_> {
    type Output = Result<String, Error>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        let m = M::from_soup(self.0)?;
        let mut out = String::new();
        m.explain(&mut out)
            .expect("writing to a String cannot fail");
        Ok(out)
    }
}

fn explain(name: &str, mesh: Option<&str>) -> Result<String, Failure> {
    let grids_only = registry::visit(name, Row).is_some_and(|r| r.capabilities.grids_only);
    let (soup, label) = mesh_or_tetrahedron(mesh, grids_only)?;
    let text = registry::visit(name, ExplainVisit(&soup))
        .ok_or_else(|| unknown_structure(name))?
        .map_err(|e| Failure {
            message: format!("{name} cannot store {label}: {e}"),
            code: 1,
        })?;
    Ok(format!("{name} for {label}\n\n{text}"))
}
