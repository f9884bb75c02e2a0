//! Drops faces with the vertex set of an earlier face: the `duplicate-face` finding of the
//! checks (topological duplicates, whatever their orientation or starting corner).

use super::RepairLog;
use crate::core::soup::PolygonSoup;

/// Drops from `soup` the faces whose vertex set an earlier face has; the dropped faces' ids go
/// to `log.duplicate_faces`. Faces are sorted by their sorted vertex lists (O(c log c)); of
/// equal keys the first in input order stays.
pub(super) fn drop_duplicates(soup: &mut PolygonSoup, log: &mut RepairLog) {
    // Each face's vertices sorted, in one buffer with the soup's offsets.
    let mut keys: Vec<u32> = soup.indices().to_vec();
    for j in 0..soup.num_faces() {
        let range = soup.face_start(j)..soup.face_start(j + 1);
        keys[range].sort_unstable();
    }
    let key = |j: u32| &keys[soup.face_start(j as usize)..soup.face_start(j as usize + 1)];
    let mut order: Vec<u32> = (0..soup.num_faces() as u32).collect();
    // Stable: among equal keys, input order, so the first face is the one kept.
    order.sort_by(|&a, &b| key(a).cmp(key(b)));
    let mut duplicate = vec![false; soup.num_faces()];
    for w in order.windows(2) {
        if key(w[0]) == key(w[1]) {
            duplicate[w[1] as usize] = true;
        }
    }
    drop((order, keys));
    log.duplicate_faces = (0..soup.num_faces() as u32)
        .filter(|&j| duplicate[j as usize])
        .collect();
    if !log.duplicate_faces.is_empty() {
        soup.retain_faces(|j| !duplicate[j]);
    }
}
