//! The text of `info`'s summary, the same whether the mesh came from a file of faces
//! (`info`) or from a `.che` file (`info_che`).

use std::fmt::Write as _;
use topolab_structures::summary::{shown, Summary};

/// The lines of `info`'s text after the mesh and the structure: counts, boundary, components,
/// Euler characteristic, genus, manifoldness.
pub(super) fn summary_lines(out: &mut String, s: &Summary) {
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
}
