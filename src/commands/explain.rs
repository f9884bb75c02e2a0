//! `topolab explain`: what a structure stores for the CHE chapter's open tetrahedron (or a
//! mesh given), record by record; `explain che` shows the four CHE levels
//! ([`super::explain_che`]); `--trace` prints the reads of one query ([`super::explain_trace`]).

use super::explain_che;
use super::explain_trace::{explain_trace, TraceRequest};
use super::list::Row;
use crate::input::{is_che_file, mesh_or_tetrahedron, unknown_structure, Failure};
use crate::limits;
use crate::registry::{self, StructureVisitor};
use std::path::Path;
use topolab_harness::teaching::trace::Query;
use topolab_structures::che::{CheFile, MappedChe};
use topolab_structures::{CheL3, Error, MeshTopology, PolygonSoup};

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
    if let Some(path) = mesh.filter(|m| is_che_file(Path::new(m))) {
        if let Some(request) = trace {
            return Err(Failure::usage(format!(
                "--trace {} reads a mesh: {path} is a .che file, which `explain {name} --mesh {path}` explains record by record (the trace of a .che file's mesh: `--mesh` its source mesh)",
                request.op
            )));
        }
        return explain_che_file(name, path);
    }
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

/// `explain che-lN --mesh FILE.che` (or `explain che --mesh FILE.che`): the records of the
/// file's level, read through the memory-mapped containers after the file is verified (one
/// pass, as `topolab check` reads it). A level-0 file is described by `info`, not mapped.
fn explain_che_file(name: &str, path: &str) -> Result<String, Failure> {
    let bad_file = |e: Error| Failure::usage(format!("{path}: {e}"));
    let file = CheFile::open(Path::new(path)).map_err(bad_file)?;
    let level = file.level();
    let structure = format!("che-l{level}");
    if name != explain_che::NAME && name != structure {
        return Err(Failure::usage(format!(
            "{path} holds the containers of CHE level {level}: `explain {structure} --mesh {path}` (or `explain che --mesh {path}`) explains it"
        )));
    }
    if level == 0 {
        return Err(Failure::usage(format!(
            "{path} is a level-0 file, described (`topolab info {path}`) and checked (`topolab check {path}`) but not mapped as a structure: its relations scan"
        )));
    }
    // The text: bytes per triangle of the explanation of the limits module's sample, scaled.
    let sample = limits::sample_mesh();
    let mut text = String::new();
    CheL3::from_soup(&sample)
        .expect("the sample is a manifold triangle mesh")
        .explain(&mut text)
        .expect("writing to a String cannot fail");
    let bytes = limits::scale(
        text.len() as u64 + limits::growing_text(&text),
        sample.num_faces() as u64,
        file.header().triangles,
    );
    limits::admit(&format!("explain {name} --mesh {path}"), bytes)?;
    let mut out = format!("{structure} for {path}\n\n");
    match level {
        1 => explain_mapped::<1>(file, path, &mut out),
        2 => explain_mapped::<2>(file, path, &mut out),
        _ => explain_mapped::<3>(file, path, &mut out),
    }?;
    Ok(out)
}

/// The records of a mapped level, verified first.
fn explain_mapped<const L: u8>(file: CheFile, path: &str, out: &mut String) -> Result<(), Failure>
where
    MappedChe<L>: MeshTopology,
{
    let mut m =
        MappedChe::<L>::from_file(file).map_err(|e| Failure::usage(format!("{path}: {e}")))?;
    m.verify().map_err(|e| Failure {
        message: format!("{path} does not verify: {e} (`topolab check {path}` lists it)"),
        code: 1,
    })?;
    m.explain(out).expect("writing to a String cannot fail");
    Ok(())
}
