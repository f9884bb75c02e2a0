//! Drops vertices no face uses (the `unused-vertex` finding), keeping the others in order.

use super::RepairLog;
use crate::core::soup::PolygonSoup;

/// `soup` without its unused vertices, the others renumbered in their order; their count goes
/// to `log.unused_vertices`.
pub(super) fn drop_unused(soup: &PolygonSoup, log: &mut RepairLog) -> PolygonSoup {
    let mut used = vec![false; soup.num_vertices()];
    for &v in soup.indices() {
        used[v as usize] = true;
    }
    log.unused_vertices = used.iter().filter(|u| !**u).count();
    if log.unused_vertices == 0 {
        return soup.clone();
    }
    let mut new_id = vec![u32::MAX; soup.num_vertices()];
    let mut out = PolygonSoup::with_capacity(
        soup.num_vertices() - log.unused_vertices,
        soup.num_faces(),
        soup.num_corners(),
    );
    for (v, p) in soup.positions.iter().enumerate().filter(|(v, _)| used[*v]) {
        new_id[v] = out.push_vertex(*p).0;
    }
    let mut face = Vec::new();
    for f in soup.faces() {
        face.clear();
        face.extend(f.iter().map(|&v| new_id[v as usize]));
        out.push_face(&face);
    }
    out
}
