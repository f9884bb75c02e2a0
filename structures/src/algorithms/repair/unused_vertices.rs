//! Drops vertices no face uses (the `unused-vertex` finding), keeping the others in order.

use super::RepairLog;
use crate::core::soup::PolygonSoup;

/// Drops from `soup` its unused vertices, the others renumbered in their order, in place;
/// their count goes to `log.unused_vertices`.
pub(super) fn drop_unused(soup: &mut PolygonSoup, log: &mut RepairLog) {
    let mut used = vec![false; soup.num_vertices()];
    for &v in soup.indices() {
        used[v as usize] = true;
    }
    log.unused_vertices = used.iter().filter(|u| !**u).count();
    if log.unused_vertices == 0 {
        return;
    }
    // Each vertex's new id, its position moved down to it.
    let mut new_id = vec![u32::MAX; soup.num_vertices()];
    let mut kept = 0;
    for v in 0..soup.num_vertices() {
        if used[v] {
            soup.positions[kept] = soup.positions[v];
            new_id[v] = kept as u32;
            kept += 1;
        }
    }
    soup.positions.truncate(kept);
    for v in soup.indices_mut() {
        *v = new_id[*v as usize];
    }
}
