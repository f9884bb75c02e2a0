//! `topolab info`: counts, boundary curves, Euler characteristic and genus of a mesh, computed
//! through a structure.

use super::info_text::summary_lines;
use crate::input::{
    invalid_mesh_hint, is_che_file, load_mesh, refuse_empty, unknown_structure, Failure,
};
use crate::registry::{self, StructureVisitor};
use std::fmt::Write as _;
use std::path::Path;
use topolab_structures::summary::{summarize, Summary};
use topolab_structures::{Error, MeshTopology, PolygonSoup};

/// Takes the mesh: the structure is built from it consumed ([`MeshTopology::from_soup_owned`]:
/// a CHE takes its arrays, another structure drops it once built), before the summary's work.
struct InfoVisit(PolygonSoup);
impl StructureVisitor for InfoVisit {
    type Output = Result<Summary, Error>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        let m = M::from_soup_owned(self.0)?;
        Ok(summarize(&m))
    }
}

/// What `info` computes on a mesh: the structure's summary, or why it cannot store the mesh.
/// `None` for an unknown structure.
fn summary_of(structure: &str, soup: PolygonSoup) -> Option<Result<Summary, Error>> {
    registry::visit(structure, InfoVisit(soup))
}

/// The structure `info` answers through when `--structure` does not name one: it answers every
/// query in O(k).
pub const DEFAULT_STRUCTURE: &str = "index-half-edge";

/// The text of `topolab info MESH [--structure NAME] [--json]`. A `.che` file is described
/// as the level its containers hold (`info_che`), whatever `--structure` says (a note on
/// stderr says so when it names another).
pub fn info(spec: &str, structure: &str, json: bool) -> Result<String, Failure> {
    info_through(spec, Some(structure), json)
}

/// [`info`] with the structure as the command line gave it: `None` for the default.
pub fn info_through(spec: &str, structure: Option<&str>, json: bool) -> Result<String, Failure> {
    if is_che_file(Path::new(spec)) {
        return super::info_che::che_info(spec, structure, json);
    }
    let structure = structure.unwrap_or(DEFAULT_STRUCTURE);
    if !registry::NAMES.contains(&structure) {
        return Err(unknown_structure(structure));
    }
    // The mesh is counted exactly (its soup), and again in the work's peak measured on the
    // sample, whose copy the work takes: an estimate above the peak by the soup, as the mesh
    // generated (a quad grid's faces and corners) may weigh more an element than the sample's.
    let soup = load_mesh(spec, |sample| {
        summary_of(structure, sample.clone());
        0
    })?;
    refuse_empty(spec, &soup)?;
    let summary = summary_of(structure, soup).ok_or_else(|| unknown_structure(structure))?;
    let summary = summary.map_err(|e| Failure {
        message: format!(
            "{structure} cannot store {spec}: {e}{}",
            invalid_mesh_hint(spec, &e)
        ),
        code: 1,
    })?;
    if json {
        let mut v = serde_json::to_value(&summary).expect("serialisable");
        v["mesh"] = spec.into();
        return Ok(serde_json::to_string_pretty(&v).expect("serialisable") + "\n");
    }
    let mut out = String::new();
    let _ = writeln!(out, "mesh:                 {spec}");
    let _ = writeln!(out, "structure:            {}", summary.structure);
    summary_lines(&mut out, &summary);
    Ok(out)
}
