//! `topolab info`: counts, boundary curves, Euler characteristic and genus of a mesh, computed
//! through a structure.

use crate::input::{invalid_mesh_hint, load_mesh, refuse_empty, unknown_structure, Failure};
use crate::registry::{self, StructureVisitor};
use std::fmt::Write as _;
use topolab_structures::summary::{shown, summarize, Summary};
use topolab_structures::{Error, MeshTopology, PolygonSoup};

struct InfoVisit<'a>(&'a PolygonSoup);
impl StructureVisitor for InfoVisit<'_> {
    type Output = Result<Summary, Error>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        let m = M::from_soup(self.0)?;
        Ok(summarize(&m))
    }
}

/// What `info` computes on a mesh: the structure's summary, or why it cannot store the mesh.
/// `None` for an unknown structure.
fn summary_of(structure: &str, soup: &PolygonSoup) -> Option<Result<Summary, Error>> {
    registry::visit(structure, InfoVisit(soup))
}

/// The text of `topolab info MESH [--structure NAME] [--json]`.
pub fn info(spec: &str, structure: &str, json: bool) -> Result<String, Failure> {
    if !registry::NAMES.contains(&structure) {
        return Err(unknown_structure(structure));
    }
    let soup = load_mesh(spec, |sample| {
        summary_of(structure, sample);
        0
    })?;
    refuse_empty(spec, &soup)?;
    let summary = summary_of(structure, &soup).ok_or_else(|| unknown_structure(structure))?;
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
    let s = &summary;
    let mut out = String::new();
    let _ = writeln!(out, "mesh:                 {spec}");
    let _ = writeln!(out, "structure:            {}", s.structure);
    let _ = writeln!(
        out,
        "vertices:             {} ({} unused)",
        s.vertices, s.unused_vertices
    );
    let _ = writeln!(out, "edges:                {}", s.edges);
    let _ = writeln!(
        out,
        "faces:                {} ({})",
        s.faces,
        if s.triangles_only {
            "triangles"
        } else {
            "polygons"
        }
    );
    let _ = writeln!(out, "boundary edges:       {}", s.boundary_edges);
    let _ = writeln!(
        out,
        "boundary curves:      {}",
        shown(s.boundary_curves, s.boundary_curves_undefined)
    );
    let _ = writeln!(out, "components:           {}", s.components);
    let _ = writeln!(out, "euler characteristic: {}", s.euler_characteristic);
    let _ = writeln!(
        out,
        "genus:                {}",
        shown(s.genus, s.genus_undefined)
    );
    let _ = writeln!(
        out,
        "manifold:             {}",
        if s.non_manifold_vertices == 0 {
            "yes (oriented, every vertex one fan)".to_string()
        } else {
            format!(
                "edges yes, {} non-manifold vertices",
                s.non_manifold_vertices
            )
        }
    );
    Ok(out)
}
