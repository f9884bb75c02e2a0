//! The lecture on polygon-mesh data structures lists refinement and thinning (*Verfeinerung,
//! Ausdünnung*) beside the editing operations. The lab runs them as algorithms over
//! [`MeshEdit`]: √3 subdivision ([`changing::sqrt3_step`](super::changing::sqrt3_step)),
//! adaptive longest-edge bisection ([`adaptive`](super::adaptive)) and decimation by quadric
//! error ([`decimate`](super::decimate)). Each step of one costs what its operations cost on
//! the structure, plus the algorithm's own work (a heap). [`Scheme::declared`] states that
//! cost per step from the structure's declared costs, as the module docs of each algorithm
//! describe the step:
//!
//! | scheme | one step | what it asks of the structure |
//! |---|---|---|
//! | √3 subdivision | a face | its split at the centroid, and 1.5 edge flips |
//! | adaptive bisection | an edge split | the edge found from its ends (the vertex-edge query), its split, up to four edges pushed on a heap (O(log n)) |
//! | decimation | an edge collapse | the collapse (with its test), the faces around the kept vertex (its quadric), O(k) heap keys updated (O(log n) each) |

use crate::core::edit::{EditOp, MeshEdit};
use crate::core::operator::{Cost, Operator};

/// A refinement or thinning algorithm of the lab.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Scheme {
    /// One step of √3 subdivision, per face of the input.
    Sqrt3,
    /// Adaptive longest-edge bisection, per split.
    AdaptiveBisection,
    /// Decimation by quadric error, per collapse.
    Decimation,
}

/// The algorithm's own work per step, beside the structure's operations.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum Heap {
    /// None.
    None,
    /// A few pushes: O(log n).
    Pushes,
    /// O(k) keys updated: O(k log n).
    Keys,
}

impl Scheme {
    /// Every scheme, refinement first.
    pub const ALL: [Scheme; 3] = [Scheme::Sqrt3, Scheme::AdaptiveBisection, Scheme::Decimation];

    /// How `topolab list` names the scheme's row.
    pub const fn name(self) -> &'static str {
        match self {
            Scheme::Sqrt3 => "√3 (a face)",
            Scheme::AdaptiveBisection => "bisection (a split)",
            Scheme::Decimation => "decimation (a collapse)",
        }
    }

    /// The editing operations a step does.
    pub const fn operations(self) -> &'static [EditOp] {
        match self {
            Scheme::Sqrt3 => &[EditOp::SplitFace, EditOp::FlipEdge],
            Scheme::AdaptiveBisection => &[EditOp::SplitEdge],
            Scheme::Decimation => &[EditOp::CollapseEdge],
        }
    }

    /// The queries a step asks beside them.
    const fn queries(self) -> &'static [Operator] {
        match self {
            Scheme::Sqrt3 => &[],
            Scheme::AdaptiveBisection => &[Operator::R01],
            Scheme::Decimation => &[Operator::R02],
        }
    }

    const fn heap(self) -> Heap {
        match self {
            Scheme::Sqrt3 => Heap::None,
            Scheme::AdaptiveBisection => Heap::Pushes,
            Scheme::Decimation => Heap::Keys,
        }
    }

    /// Does `M` run the scheme (it offers every operation of a step; √3 also needs edge ids
    /// that survive the face splits, since it flips the old edges by id)?
    pub fn runs_on<M: MeshEdit>(self) -> bool {
        self.operations().iter().all(|&op| M::supports(op))
            && (self != Scheme::Sqrt3 || M::STABLE_EDGE_IDS)
    }

    /// The declared cost of one step on `M`, in the lecture's notation (`None` where `M` does
    /// not run it): a scan in any part dominates; otherwise the largest local part and the
    /// heap's logarithm, which do not compare, are written side by side (`O(k + log n)`).
    pub fn declared<M: MeshEdit>(self) -> Option<String> {
        if !self.runs_on::<M>() {
            return None;
        }
        let parts: Vec<Cost> = (self.operations().iter())
            .map(|&op| M::edit_cost(op))
            .chain(self.queries().iter().map(|&q| M::cost(q)))
            .collect();
        Some(dominant(&parts, self.heap()))
    }
}

/// The rank of a cost that grows with the mesh (a scan), highest last; `None` for a local one.
fn scan_rank(c: Cost) -> Option<u8> {
    match c {
        Cost::Boundary => Some(0),
        Cost::Linear => Some(1),
        Cost::LocalTimesLinear => Some(2),
        Cost::Quadratic => Some(3),
        Cost::Constant | Cost::Log | Cost::Local | Cost::LocalSquared => None,
    }
}

/// The cost that dominates `parts` and the heap's work (see [`Scheme::declared`]).
fn dominant(parts: &[Cost], heap: Heap) -> String {
    if let Some(scan) = parts.iter().copied().max_by_key(|&c| scan_rank(c)) {
        if scan_rank(scan).is_some() {
            return scan.notation().to_string();
        }
    }
    let local = if parts.contains(&Cost::LocalSquared) {
        Some("k²")
    } else if parts.contains(&Cost::Local) || heap == Heap::Keys {
        Some("k")
    } else {
        None
    };
    let log = match heap {
        Heap::None if parts.contains(&Cost::Log) => Some("log n"),
        Heap::None => None,
        Heap::Pushes => Some("log n"),
        Heap::Keys => Some("k log n"),
    };
    match (local, log) {
        (None, None) => "O(1)".to_string(),
        (Some(l), None) => format!("O({l})"),
        (None, Some(g)) => format!("O({g})"),
        // O(k) heap keys at O(log n) dominate the O(k) parts: k log n alone.
        (Some("k"), Some("k log n")) => "O(k log n)".to_string(),
        (Some(l), Some(g)) => format!("O({l} + {g})"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_scan_dominates_and_local_parts_meet_the_heap_side_by_side() {
        assert_eq!(dominant(&[Cost::Local, Cost::Linear], Heap::Keys), "O(n)");
        assert_eq!(
            dominant(&[Cost::Quadratic, Cost::LocalTimesLinear], Heap::None),
            "O(n²)"
        );
        assert_eq!(
            dominant(&[Cost::Constant, Cost::Local], Heap::Pushes),
            "O(k + log n)"
        );
        assert_eq!(
            dominant(&[Cost::LocalSquared], Heap::Keys),
            "O(k² + k log n)"
        );
        assert_eq!(dominant(&[Cost::Local], Heap::Keys), "O(k log n)");
        assert_eq!(dominant(&[Cost::Constant], Heap::None), "O(1)");
        assert_eq!(
            dominant(&[Cost::Constant, Cost::Log], Heap::None),
            "O(log n)"
        );
    }
}
