//! "Meshes": a thumbnail of every mesh of the run.

use crate::report::format::esc;
use crate::results::Results;
use std::fmt::Write;

pub(crate) fn meshes(h: &mut String, r: &Results) {
    h.push_str("<h2>Meshes</h2><div class=thumbs>");
    for m in &r.meshes {
        let _ = write!(
            h,
            "<figure>{}<figcaption>{}{}<br>{} vertices, {} faces</figcaption></figure>",
            m.thumbnail_svg,
            esc(&m.name),
            crate::repaired::mark(m),
            m.vertices,
            m.faces
        );
    }
    h.push_str("</div>");
}
