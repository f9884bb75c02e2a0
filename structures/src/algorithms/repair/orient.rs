//! Orients each orientable component consistently: two faces that share an edge must traverse
//! it in opposite directions (the lecture's orientation rule), so a face whose neighbour
//! traverses their edge the same way is flipped relative to it.

use super::RepairLog;
use crate::algorithms::union_find::UnionFind;
use crate::core::soup::{Connectivity, PolygonSoup};

/// `soup` with each orientable component (faces joined across edges of exactly two faces)
/// oriented like the majority of its faces (ties: like its smallest face), so that scans and
/// shuffled files keep the orientation most of their faces had. A component with an odd cycle
/// of relative flips (a Möbius strip) is left as it is and listed in `log.non_orientable`.
/// Union-find with parity over faces, as the orientability check runs it.
pub(super) fn orient(soup: &PolygonSoup, log: &mut RepairLog) -> PolygonSoup {
    let nf = soup.num_faces();
    let (conn, _) = Connectivity::analyse(soup, false);
    let mut parity = UnionFind::new(nf);
    let mut contradicted = Vec::new();
    for &[c0, c1] in conn.edge_corners.iter().filter(|e| e[1] != u32::MAX) {
        let (f, g) = (conn.corner_face[c0 as usize], conn.corner_face[c1 as usize]);
        // The same start vertex: both traverse the edge the same way, one must be flipped.
        let flip = soup.indices()[c0 as usize] == soup.indices()[c1 as usize];
        if !parity.union(f, g, flip) {
            contradicted.push(f);
        }
    }
    let side: Vec<(u32, bool)> = (0..nf as u32).map(|f| parity.find(f)).collect();
    let mut non_orientable = vec![false; nf];
    for f in contradicted {
        non_orientable[side[f as usize].0 as usize] = true;
    }
    // Per component root: faces on the root's side and on the other, and its smallest face.
    let mut count = vec![[0usize; 2]; nf];
    let mut smallest = vec![u32::MAX; nf];
    for (f, &(root, flipped)) in side.iter().enumerate() {
        count[root as usize][flipped as usize] += 1;
        smallest[root as usize] = smallest[root as usize].min(f as u32);
    }
    // The side whose faces are flipped, per root: the minority (on a tie, the side the
    // smallest face is not on).
    let flip_side = |root: usize| {
        let [same, other] = count[root];
        match same.cmp(&other) {
            std::cmp::Ordering::Greater => true,
            std::cmp::Ordering::Less => false,
            std::cmp::Ordering::Equal => !side[smallest[root] as usize].1,
        }
    };
    let flips: Vec<bool> = side
        .iter()
        .map(|&(root, s)| !non_orientable[root as usize] && s == flip_side(root as usize))
        .collect();
    for root in (0..nf).filter(|&r| side[r].0 == r as u32) {
        if non_orientable[root] {
            log.non_orientable.push(smallest[root]);
        } else if count[root][flip_side(root) as usize] > 0 {
            log.oriented_components += 1;
        }
    }
    log.non_orientable.sort_unstable();
    log.flipped_faces = flips.iter().filter(|f| **f).count();
    if log.flipped_faces == 0 {
        return soup.clone();
    }
    let mut out = PolygonSoup::with_capacity(soup.num_vertices(), nf, soup.num_corners());
    out.positions = soup.positions.clone();
    let mut face = Vec::new();
    for (j, f) in soup.faces().enumerate() {
        face.clear();
        face.extend_from_slice(f);
        if flips[j] {
            face.reverse();
        }
        out.push_face(&face);
    }
    out
}
