//! "Meshes": a thumbnail of every mesh of the run.

use crate::format::esc;
use crate::report::section::{Needs, Page, Real, Section};
use crate::results::Results;
use std::fmt::Write;

fn meshes(h: &mut String, r: &Results) {
    h.push_str("<h2>Meshes</h2><div class=thumbs>");
    for m in &r.meshes {
        let _ = write!(
            h,
            "<figure>{}<figcaption>{}{}<br>{} vertices, {} faces</figcaption></figure>",
            m.thumbnail_svg,
            esc(&m.name),
            crate::page::repaired::mark(m),
            m.vertices,
            m.faces
        );
    }
    h.push_str("</div>");
}

/// Thumbnails of the meshes.
pub struct Meshes;

impl Section for Meshes {
    fn name(&self) -> &'static str {
        "meshes"
    }

    fn needs(&self) -> Needs {
        Needs {
            generated: true,
            real: Real::Read,
            ..Needs::NOTHING
        }
    }

    fn render(&self, h: &mut String, page: &Page) {
        meshes(h, page.r);
    }
}
