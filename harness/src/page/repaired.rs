//! How the page marks a real mesh that the report measured repaired (`topolab repair`): the
//! file as read was refused by the structures that need an oriented manifold, so its rows
//! would say nothing; the repaired mesh is measured in its place.

use crate::results::MeshInfo;

/// The sentence under the real meshes' "How to read it".
pub const HOW_TO_READ: &str = "A mesh marked <i>repaired</i> was refused as read by the structures that need an oriented manifold (inconsistent orientation, non-manifold edges or vertices): its row measures it after <code>topolab repair</code> (duplicate faces dropped, non-manifold edges and vertices split into one vertex per fan, each orientable component oriented, unused vertices dropped). Hover the mark for what changed.";

/// The mark after a mesh's name: empty for a mesh measured as read, else `repaired` with what
/// the repair changed as its hover title.
pub fn mark(mesh: &MeshInfo) -> String {
    let Some(log) = &mesh.repaired else {
        return String::new();
    };
    let title = crate::format::esc(&log.lines().join("; ")).replace('"', "&quot;");
    format!(" <span class=small title=\"{title}\">(repaired)</span>")
}
