//! The access models of the four CHE levels ([`MeshTopology::access`]): what the relations of
//! `che_topology!` and each level's [`CheLevel`](super::CheLevel) hooks read from `V[]`,
//! `O[]` and `VH[]` (4 bytes per element each). `next`, `prev` and `triangle` are arithmetic on
//! the half-edge id and read nothing.
//!
//! Where a query's reads grow with the valence without answers to count them by (a level-1
//! boundary test walks the whole fan twice), the model takes the valence 6 of the lab's
//! generated meshes. The level-0 boundary curves (a scan for each half-edge, O(n2²)) have no
//! model: their reads grow with the mesh, not per query.
//!
//! [`MeshTopology::access`]: crate::MeshTopology::access

use crate::core::access::{Access, Container, Read, Step, Unit};
use crate::core::topology::Operator;

const V: Container = Container::new("V", Unit::Corner, 4.0);
const O: Container = Container::new("O", Unit::Corner, 4.0);
const VH: Container = Container::new("VH", Unit::Vertex, 4.0);

/// What the vertex star's half a load per answer assumes.
const TWO_ENDS: &str = "an interior star is walked from both ends at once (two chains, each half the valence long); a boundary star from its VH[] end only, one load per answer";
/// What the boundary curves of levels 1 and 2 leave out.
const WRITTEN_CURVES: &str = "each boundary half-edge is also checked against the curves already written (O(∂n1²) reads of the output)";

/// `V[he]` and `V[next(he)]`: R10, and the end vertices of the edge the successor and
/// predecessor are asked about, then `V[]` of the face's half-edges until the edge is found
/// (two of three on average).
const ENDS: f64 = 8.0;
const FIND_IN_FACE: f64 = ENDS + 16.0;

/// What `op` reads at CHE level `level` (0 to 3).
pub(crate) fn model(level: u8, op: Operator) -> Option<Access> {
    match level {
        0 => level0(op),
        1 => level1(op),
        _ => level2(level, op),
    }
}

/// Level 0: `V[]` only; the twin of a half-edge is a scan for it (Algorithm 8), stopping
/// halfway on average; the vertex star a whole scan (Algorithm 5).
fn level0(op: Operator) -> Option<Access> {
    Some(match op {
        Operator::R00 | Operator::R01 | Operator::R02 | Operator::BoundaryVertex => Access::new(
            const { &[Read::scan(V, 1.0), Read::new(V, 0.0, 8.0)] },
            0.0,
            0.0,
        ),
        Operator::R10 => Access::new(const { &[Read::new(V, ENDS, 0.0)] }, 0.0, 0.0),
        Operator::R11 | Operator::R12 | Operator::BoundaryEdge => Access::new(
            const { &[Read::new(V, ENDS, 0.0), Read::scan(V, 0.5)] },
            0.0,
            0.0,
        ),
        Operator::R20 => Access::new(const { &[Read::new(V, 0.0, 4.0)] }, 0.0, 0.0),
        // Edge ids are half-edge ids: nothing to read.
        Operator::R21 => Access::new(const { &[] }, 0.0, 0.0),
        // Algorithm 9: one scan of `V[]` against the triangle's three edges.
        Operator::R22 => Access::new(
            const { &[Read::new(V, 24.0, 0.0), Read::scan(V, 1.0)] },
            0.0,
            0.0,
        ),
        Operator::BoundaryCurves => return None,
        Operator::EdgeSuccessor | Operator::EdgePredecessor => {
            Access::new(const { &[Read::new(V, FIND_IN_FACE, 0.0)] }, 0.0, 0.0)
        }
    })
}

/// The relations levels 1 to 3 answer alike through `O[]` (edge ids are `min(he, O[he])`).
fn with_opposites(op: Operator) -> Option<Access> {
    Some(match op {
        Operator::R10 => Access::new(const { &[Read::new(V, ENDS, 0.0)] }, 0.0, 0.0),
        // O[he]; the edges of next and prev on both sides: O[] of each.
        Operator::R11 => Access::new(const { &[Read::new(O, 20.0, 0.0)] }, 1.0, 0.0),
        Operator::R12 | Operator::BoundaryEdge => {
            Access::new(const { &[Read::new(O, 4.0, 0.0)] }, 0.0, 0.0)
        }
        Operator::R20 => Access::new(const { &[Read::new(V, 0.0, 4.0)] }, 0.0, 0.0),
        Operator::R21 => Access::new(const { &[Read::new(O, 0.0, 4.0)] }, 0.0, 0.0),
        Operator::R22 => Access::new(const { &[Read::new(O, 12.0, 0.0)] }, 0.0, 0.0),
        Operator::EdgeSuccessor | Operator::EdgePredecessor => Access::new(
            const { &[Read::new(V, FIND_IN_FACE, 0.0), Read::new(O, 4.0, 0.0)] },
            1.0,
            0.0,
        ),
        _ => return None,
    })
}

/// Level 1: the vertex star scans `V[]` for a first half-edge (halfway on average), turns back
/// to the boundary (all the way round at an interior vertex) and walks the fan: two `O[]` loads
/// per answer on the chain.
fn level1(op: Operator) -> Option<Access> {
    match op {
        Operator::R00 => Some(level1_star(
            const {
                &[
                    Read::scan(V, 0.5),
                    Read::new(V, 0.0, 4.0),
                    Read::new(O, 0.0, 8.0),
                ]
            },
        )),
        Operator::R01 => Some(level1_star(
            const { &[Read::scan(V, 0.5), Read::new(O, 0.0, 12.0)] },
        )),
        Operator::R02 => Some(level1_star(
            const { &[Read::scan(V, 0.5), Read::new(O, 0.0, 8.0)] },
        )),
        // The whole star walked for one answer: 2 · 6 `O[]` loads at valence 6.
        Operator::BoundaryVertex => Some(Access::new(
            const { &[Read::scan(V, 0.5), Read::new(O, 48.0, 0.0)] },
            12.0,
            0.0,
        )),
        Operator::BoundaryCurves => Some(boundary_walk_after_scan()),
        _ => with_opposites(op),
    }
}

/// A level-1 vertex star reading `reads`: two `O[]` loads per answer on the chain, each step
/// a CHE corner step (`next(O[h])` back to the boundary, then `O[prev(h)]`).
const fn level1_star(reads: &'static [Read]) -> Access {
    Access::new(reads, 0.0, 2.0).stepping(Step::Corner)
}

/// The boundary curves of levels 1 and 2 (§4.6): a scan of `O[]` for boundary half-edges, then
/// each curve walked by turning around its vertices (about three `O[]` loads a step on the
/// generated grids' boundaries).
fn boundary_walk_after_scan() -> Access {
    Access::new(
        const { &[Read::scan(O, 1.0), Read::new(O, 0.0, 12.0)] },
        0.0,
        3.0,
    )
    .noting(WRITTEN_CURVES)
}

/// Levels 2 and 3: the vertex star starts at `VH[v]` and is walked from both ends at once
/// (`Fan::spokes`): each spoke's `O[e]` load is a step of one of two
/// independent chains, so half a dependent load per answer; each neighbour is `V[e]` (R00),
/// each edge `min(e, O[e])` (R01) and each triangle `e / 3` (R02) of the half-edge `e` the
/// walk just read `O[e]` of.
fn level2(level: u8, op: Operator) -> Option<Access> {
    Some(match op {
        Operator::R00 => Access::new(
            const {
                &[
                    Read::new(VH, 4.0, 0.0),
                    Read::new(V, 0.0, 4.0),
                    Read::new(O, 0.0, 4.0),
                ]
            },
            0.0,
            0.5,
        )
        .stepping(Step::Corner)
        .noting(TWO_ENDS),
        Operator::R01 | Operator::R02 => Access::new(
            const { &[Read::new(VH, 4.0, 0.0), Read::new(O, 0.0, 4.0)] },
            0.0,
            0.5,
        )
        .stepping(Step::Corner)
        .noting(TWO_ENDS),
        // O[VH[v]] < 0.
        Operator::BoundaryVertex => Access::new(
            const { &[Read::new(VH, 4.0, 0.0), Read::new(O, 4.0, 0.0)] },
            1.0,
            0.0,
        ),
        // Level 3 (Algorithm 10): each curve from its half-edge in `CH[]`, no scan.
        Operator::BoundaryCurves if level >= 3 => {
            Access::new(const { &[Read::new(O, 0.0, 12.0)] }, 0.0, 3.0)
        }
        Operator::BoundaryCurves => boundary_walk_after_scan(),
        _ => return with_opposites(op),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_level_models_its_local_relations_and_level_0_scans() {
        for level in 0..4 {
            for op in [Operator::R10, Operator::R20, Operator::EdgeSuccessor] {
                let a = model(level, op).expect("O(1) at every level");
                assert!(a.reads.iter().all(|r| r.scans == 0.0), "{level} {op:?}");
            }
        }
        // The vertex star scans V[] below level 2 and starts at VH[] from level 2 on.
        for level in 0..2 {
            let a = model(level, Operator::R00).unwrap();
            assert!(a.reads.iter().any(|r| r.scans > 0.0 && r.container == V));
        }
        for level in 2..4 {
            let a = model(level, Operator::R00).unwrap();
            assert!(a.reads.iter().all(|r| r.scans == 0.0));
            assert!(a.reads.iter().any(|r| r.container == VH));
        }
        // Only level 3 walks its boundary curves without scanning O[].
        let scans = |level| {
            model(level, Operator::BoundaryCurves)
                .unwrap()
                .reads
                .iter()
                .any(|r| r.scans > 0.0)
        };
        assert!(scans(1) && scans(2) && !scans(3));
        assert_eq!(model(0, Operator::BoundaryCurves), None);
    }
}
