//! The editing suite: random sequences of [`MeshEdit`] operations on a structure, each
//! applied as well to a naive [`Model`] (a face list edited by hand), with every refusal
//! checked against the model (which says whether an edit must be refused, not for which
//! [`Refusal`](crate::Refusal)) and, after every edit, `validate()`, the live faces
//! compared with the model's, and, when nothing is marked deleted, every relation compared
//! with the [`Oracle`](crate::testing::oracle::Oracle) rebuilt from the structure's face list
//! ([`compare`](crate::testing::conformance::compare)). An operation the structure does not implement ([`MeshEdit::supports`])
//! must be refused with [`Refusal::NotImplemented`](crate::Refusal::NotImplemented), nothing
//! changed. The [`edit_conformance!`](macro@crate::edit_conformance) macro enrols a
//! structure in one line, one that implements a subset of the operations too.
//!
//! The operations on positions ([`crate::algorithms::select`]) are drawn too: a box
//! selection (compared with the model's vertices and faces in the box), its rotation or
//! scaling, and a smoothing step, each applied to the model's positions by hand. The point
//! transforms themselves ([`rotate_point`](crate::algorithms::select::rotate_point), [`scale_point`](crate::algorithms::select::scale_point), [`laplacian_mean`](crate::algorithms::select::laplacian_mean)) are shared
//! with the model so that positions compare bit for bit, and tested on their own in that
//! module. A structure that tells vertices apart by their coordinates
//! (`capabilities().distinct_positions`, explicit storage) must refuse a move that would put
//! two vertices at one position, which the model then refuses too.

mod check;
mod edit;
mod expect;
mod macros;
mod model;

pub use edit::{drawn, Edit};
pub use model::{start_mesh, Model};

use crate::core::edit::{EditOp, MeshEdit};
pub use crate::testing::oracle::canonical_face;
use check::{run_tally, Tally};
use std::collections::BTreeMap;

/// Runs `steps` random edits of `seed` on `M`; `Err` describes the first disagreement.
/// Returns how many of the drawn edits succeeded and how many were refused (an operation `M`
/// does not implement, refused as [`Refusal::NotImplemented`](crate::Refusal::NotImplemented), among them).
///
/// An edit of an operation `M` implements ([`MeshEdit::supports`], see [`Edit::op`]) must be
/// done exactly when the model allows it; one of an operation it does not implement must be
/// refused with [`Refusal::NotImplemented`](crate::Refusal::NotImplemented) whatever the model says, and change nothing. A
/// structure of triangles only (`M::capabilities().triangles_only`) is also asked to add
/// faces of four corners, which it must refuse. Beside the drawn edits, from a stream of
/// their own, vertices are moved (`set_position`, refused where there is no such vertex)
/// and faces that do not exist split (refused).
pub fn run<M: MeshEdit>(seed: u64, steps: usize) -> Result<(usize, usize), String> {
    run_with::<M>(seed, steps, false)
}

/// [`run`], except that on a start mesh with polygons an edit the model allows may be refused
/// with [`Refusal::NotImplemented`](crate::Refusal::NotImplemented) (and must then change nothing): for a library whose
/// polygon kernel lacks the triangle operations (OpenMesh's PolyMesh has no flip, 2-to-4
/// split or vertex split).
pub fn run_with<M: MeshEdit>(
    seed: u64,
    steps: usize,
    not_implemented_on_polygons: bool,
) -> Result<(usize, usize), String> {
    run_tally::<M>(seed, steps, not_implemented_on_polygons).map(|t| (t.done, t.refused))
}

/// How many vertex welds the random sequences of `seeds` did and how many they had refused
/// (each checked as in [`run_with`], with its `not_implemented_on_polygons`): the suite's
/// evidence that welds the model allows are drawn and done, and welds it forbids drawn and
/// refused, not only one of the two.
pub fn weld_counts<M: MeshEdit>(
    seeds: std::ops::Range<u64>,
    steps: usize,
    not_implemented_on_polygons: bool,
) -> Result<(usize, usize), String> {
    let (mut done, mut refused) = (0, 0);
    for seed in seeds {
        let tally = run_tally::<M>(seed, steps, not_implemented_on_polygons)
            .map_err(|msg| format!("seed {seed}: {msg}"))?;
        done += tally.welds;
        refused += tally.welds_refused;
    }
    Ok((done, refused))
}

/// The suite's vertex-weld test, nothing where `M` does not weld: the chosen cases
/// ([`weld_vertex_cases`](crate::testing::weld::weld_vertex_cases)) and the welds done in 200
/// random sequences ([`weld_counts`], with `not_implemented_on_polygons` as in
/// [`run_with`]), enough of each to show that welds are both done and refused. Panics on a
/// disagreement.
pub fn vertex_welds<M: MeshEdit>(not_implemented_on_polygons: bool) {
    if !M::supports(EditOp::WeldVertices) {
        return;
    }
    let cases = crate::testing::weld::weld_vertex_cases::<M>()
        .unwrap_or_else(|msg| panic!("{}: {msg}", M::NAME));
    assert!(cases >= 8, "only {cases} weld cases ran");
    let (done, refused) = weld_counts::<M>(0..200, 40, not_implemented_on_polygons)
        .unwrap_or_else(|msg| panic!("{msg}"));
    assert!(done >= 20, "only {done} random welds done");
    assert!(refused >= 20, "only {refused} random welds refused");
}

/// The count test of a structure that implements a subset of the operations (the
/// `offered_operations` arm of [`edit_conformance!`](macro@crate::edit_conformance)): over
/// the random sequences of 60 seeds, each checked as in [`run`], every operation the
/// sequences draw ([`drawn`]) that `M` implements was done at least 10 times and, but for
/// adding a vertex (which the model never refuses), an edge split (refused only where its two
/// triangles share their third corner), the weld ([`vertex_welds`]) and the operations on
/// positions but the move of one vertex (refused only for a vertex that does not exist, which
/// a box selection never names), refused at least once; every one it does not implement was drawn and refused as not implemented at least
/// 10 times; vertices were moved; and a structure of triangles only that adds faces refused
/// at least 10 faces of four corners the model allows a polygon structure. Panics otherwise.
pub fn offered_operations<M: MeshEdit>() {
    let mut tally = Tally::default();
    for seed in 0..60 {
        let t = run_tally::<M>(seed, 40, false)
            .unwrap_or_else(|msg| panic!("{} on edit seed {seed}: {msg}", M::NAME));
        tally.add(t);
    }
    let count = |by: &BTreeMap<EditOp, usize>, op| by.get(&op).copied().unwrap_or(0);
    for op in drawn() {
        if M::supports(op) {
            let done = count(&tally.done_by, op);
            assert!(done >= 10, "{}: {op} done {done} times: {tally:?}", M::NAME);
            // The operations on positions are refused only for a vertex that does not
            // exist, which the box selections never name.
            let never_refused = [
                EditOp::AddVertex,
                EditOp::SplitEdge,
                EditOp::WeldVertices,
                EditOp::Select,
                EditOp::RotateSelection,
                EditOp::ScaleSelection,
                EditOp::Smooth,
            ];
            if !never_refused.contains(&op) {
                let refused = count(&tally.refused_by, op);
                assert!(refused >= 1, "{}: {op} never refused: {tally:?}", M::NAME);
            }
        } else {
            let refused = count(&tally.not_implemented, op);
            assert!(
                refused >= 10,
                "{}: {op}, not implemented, refused as such {refused} times: {tally:?}",
                M::NAME
            );
        }
    }
    assert!(tally.moved >= 20, "{}: {tally:?}", M::NAME);
    if M::capabilities().triangles_only && M::supports(EditOp::AddFace) {
        assert!(tally.polygons_refused >= 10, "{}: {tally:?}", M::NAME);
    }
}
