//! Orients each orientable component consistently: two faces that share an edge must traverse
//! it in opposite directions (the lecture's orientation rule), so a face whose neighbour
//! traverses their edge the same way is flipped relative to it.

use super::RepairLog;
use crate::algorithms::union_find::UnionFind;
use crate::core::soup::{Connectivity, PolygonSoup};

/// Orients, in `soup`, each orientable component (faces joined across edges of exactly two
/// faces) like the majority of its faces (ties: like its smallest face), so that scans and
/// shuffled files keep the orientation most of their faces had. A component with an odd cycle
/// of relative flips (a Möbius strip) is left as it is and listed in `log.non_orientable`.
/// Union-find with parity over faces, as the orientability check runs it.
pub(super) fn orient(soup: &mut PolygonSoup, log: &mut RepairLog) {
    let nf = soup.num_faces();
    let mut contradicted = Vec::new();
    let parity = {
        let (conn, _) = Connectivity::analyse(soup, false);
        // Made once the analysis is, not beside its scratch arrays.
        let mut parity = UnionFind::new(nf);
        for &[c0, c1] in conn.edge_corners.iter().filter(|e| e[1] != u32::MAX) {
            let (f, g) = (conn.corner_face[c0 as usize], conn.corner_face[c1 as usize]);
            // The same start vertex: both traverse the edge the same way, one must be flipped.
            let flip = soup.indices()[c0 as usize] == soup.indices()[c1 as usize];
            if !parity.union(f, g, flip) {
                contradicted.push(f);
            }
        }
        parity
    };
    // Per face its component's root and its side (parity) relative to the root.
    let (root, side) = parity.into_roots();
    let mut non_orientable = vec![false; nf];
    for f in contradicted {
        non_orientable[root[f as usize] as usize] = true;
    }
    // Per component root: faces on the root's side and on the other, and the side of its
    // smallest face (the first met).
    let mut count = vec![[0u32; 2]; nf];
    let mut smallest_side = vec![false; nf];
    for f in 0..nf {
        let r = root[f] as usize;
        if count[r] == [0, 0] {
            smallest_side[r] = side[f];
            if non_orientable[r] {
                log.non_orientable.push(f as u32);
            }
        }
        count[r][side[f] as usize] += 1;
    }
    // The side whose faces are flipped, per root: the minority (on a tie, the side the
    // smallest face is not on).
    let flip_side = |r: usize| {
        let [same, other] = count[r];
        match same.cmp(&other) {
            std::cmp::Ordering::Greater => true,
            std::cmp::Ordering::Less => false,
            std::cmp::Ordering::Equal => !smallest_side[r],
        }
    };
    let flips = |f: usize| {
        let r = root[f] as usize;
        !non_orientable[r] && side[f] == flip_side(r)
    };
    for r in (0..nf).filter(|&r| root[r] == r as u32 && !non_orientable[r]) {
        if count[r][flip_side(r) as usize] > 0 {
            log.oriented_components += 1;
        }
    }
    log.non_orientable.sort_unstable();
    log.flipped_faces = (0..nf).filter(|&f| flips(f)).count();
    for f in (0..nf).filter(|&f| flips(f)) {
        soup.face_mut(f).reverse();
    }
}
