//! Repairs what the consistency [`checks`](crate::checks) find in a mesh's topology, so that
//! the structures that need an oriented manifold can store it: the validity rules of the
//! lecture on polygon-mesh data structures (an edge borders one or two facets, facets around a
//! vertex form one fan, neighbouring facets are oriented alike, nothing is redundant) made
//! true by changing the face list, never the positions.
//!
//! The steps, each optional ([`Step`]), run in this order:
//!
//! | step | removes the finding | how |
//! |---|---|---|
//! | [`Step::DuplicateFaces`] | `duplicate-face` | a face with the vertex set of an earlier face is dropped (the first is kept) |
//! | [`Step::SplitEdges`] | `non-manifold-edge` | every end point of an edge of more than two faces gets one vertex per fan, the fans cut at such edges |
//! | [`Step::SplitVertices`] | `non-manifold-vertex` | every other vertex whose faces form more than one fan gets one vertex per fan |
//! | [`Step::Orient`] | `inconsistent-orientation` | each orientable component is oriented like the majority of its faces |
//! | [`Step::UnusedVertices`] | `unused-vertex` | vertices no face uses are dropped, the others renumbered in order |
//!
//! Splitting comes before orienting: faces that met only at a non-manifold edge impose no
//! orientation on each other once apart. A split gives a vertex's second and later fans new
//! vertices, appended after the input's, at the vertex's position: the copies are
//! `duplicate-vertices` for `topolab check`, as expected (a vertex that is two points of the
//! surface). A component that no choice of orientations makes consistent (a Möbius strip) is
//! left as it is and stays a `non-orientable` finding. Faces that the readers refuse (missing
//! or repeated vertices, fewer than three corners) are not repaired: the input is a checked
//! [`PolygonSoup`].
//!
//! Every step is an edge analysis (see [`Connectivity`](crate::Connectivity): by sorting for
//! the soups that need repair), a sort or a union-find over corners: O(c log c) for c corners.

mod duplicate_faces;
mod orient;
mod split;
mod unused_vertices;

use crate::core::soup::PolygonSoup;

/// One step of the repair, in the order they run.
#[derive(Copy, Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Step {
    /// Drop faces with the vertex set of an earlier face.
    DuplicateFaces,
    /// Split the end points of non-manifold edges into one vertex per fan.
    SplitEdges,
    /// Split the other non-manifold vertices into one vertex per fan.
    SplitVertices,
    /// Orient each orientable component consistently.
    Orient,
    /// Drop vertices no face uses.
    UnusedVertices,
}

impl Step {
    /// Every step, in the order they run.
    pub const ALL: [Step; 5] = [
        Step::DuplicateFaces,
        Step::SplitEdges,
        Step::SplitVertices,
        Step::Orient,
        Step::UnusedVertices,
    ];

    /// The kebab-case name of the command line.
    pub fn name(self) -> &'static str {
        match self {
            Step::DuplicateFaces => "duplicate-faces",
            Step::SplitEdges => "split-edges",
            Step::SplitVertices => "split-vertices",
            Step::Orient => "orient",
            Step::UnusedVertices => "unused-vertices",
        }
    }

    /// The step called `name`.
    pub fn from_name(name: &str) -> Option<Step> {
        Step::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// A vertex a split gave new vertices to.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Split {
    /// The vertex, numbered as in the input.
    pub vertex: u32,
    /// The fans its faces formed: the vertex keeps the first, each other one a new vertex.
    pub fans: u32,
}

/// What a repair changed, step by step (empty for a step that was not run or found nothing).
#[derive(Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct RepairLog {
    /// The faces dropped as duplicates of an earlier face (ids of the input).
    pub duplicate_faces: Vec<u32>,
    /// Edges of more than two faces found (split when [`Step::SplitEdges`] ran).
    pub non_manifold_edges: usize,
    /// Vertices split into one vertex per fan, at the end points of non-manifold edges.
    pub edge_splits: Vec<Split>,
    /// The other non-manifold vertices split into one vertex per fan.
    pub vertex_splits: Vec<Split>,
    /// Faces whose corner order was reversed.
    pub flipped_faces: usize,
    /// Components in which faces were flipped.
    pub oriented_components: usize,
    /// One face (the smallest id, of the output) of each component left non-orientable.
    pub non_orientable: Vec<u32>,
    /// Vertices no face used, dropped.
    pub unused_vertices: usize,
}

impl RepairLog {
    /// New vertices the splits made (one per fan after a vertex's first): each is at the
    /// position of the vertex it was split from, a `duplicate-vertices` finding by design.
    pub fn new_vertices(&self) -> usize {
        self.edge_splits
            .iter()
            .chain(&self.vertex_splits)
            .map(|s| s.fans as usize - 1)
            .sum()
    }

    /// `true` when the repair changed nothing.
    pub fn is_empty(&self) -> bool {
        self.duplicate_faces.is_empty()
            && self.new_vertices() == 0
            && self.flipped_faces == 0
            && self.unused_vertices == 0
    }

    /// One line per change, for people; vertex and face ids as the log gives them.
    pub fn lines(&self) -> Vec<String> {
        let mut out = Vec::new();
        let few = |ids: &mut dyn Iterator<Item = String>| {
            let shown: Vec<String> = ids.take(SHOWN).collect();
            shown.join(", ")
        };
        let more = |n: usize| {
            if n > SHOWN {
                format!(", ... ({n} in all)")
            } else {
                String::new()
            }
        };
        if !self.duplicate_faces.is_empty() {
            let n = self.duplicate_faces.len();
            out.push(format!(
                "dropped {n} duplicate faces (input faces {}{})",
                few(&mut self.duplicate_faces.iter().map(u32::to_string)),
                more(n)
            ));
        }
        for (splits, what) in [
            (
                &self.edge_splits,
                "vertices at the ends of non-manifold edges",
            ),
            (&self.vertex_splits, "non-manifold vertices"),
        ] {
            if splits.is_empty() {
                continue;
            }
            let new: usize = splits.iter().map(|s| s.fans as usize - 1).sum();
            out.push(format!(
                "split {} {what} into one vertex per fan, {new} new vertices (input vertex: fans {}{})",
                splits.len(),
                few(&mut splits.iter().map(|s| format!("{}: {}", s.vertex, s.fans))),
                more(splits.len())
            ));
        }
        if self.non_manifold_edges > 0 && self.edge_splits.is_empty() {
            out.push(format!(
                "left {} non-manifold edges as they were (split-edges not run)",
                self.non_manifold_edges
            ));
        }
        if self.flipped_faces > 0 {
            out.push(format!(
                "flipped {} faces in {} components to orient each consistently",
                self.flipped_faces, self.oriented_components
            ));
        }
        if !self.non_orientable.is_empty() {
            let n = self.non_orientable.len();
            out.push(format!(
                "left {n} non-orientable components as they were (output faces {}{})",
                few(&mut self.non_orientable.iter().map(u32::to_string)),
                more(n)
            ));
        }
        if self.unused_vertices > 0 {
            out.push(format!(
                "dropped {} unused vertices (the others keep their order)",
                self.unused_vertices
            ));
        }
        out
    }
}

/// Ids listed in a line of [`RepairLog::lines`] before "... (N in all)".
const SHOWN: usize = 8;

/// The repaired mesh and what changed.
#[derive(Clone, Debug, PartialEq)]
pub struct Repaired {
    /// The repaired mesh.
    pub soup: PolygonSoup,
    /// What changed.
    pub log: RepairLog,
}

/// Runs `steps` (in [`Step::ALL`] order, whatever order they are given in) on `soup`. Each
/// step changes the soup in place (new vertices of a split are appended), so a repair holds
/// one mesh, and the arrays of the step running.
pub fn repair(mut soup: PolygonSoup, steps: &[Step]) -> Repaired {
    let mut log = RepairLog::default();
    let run = |s: Step| steps.contains(&s);
    if run(Step::DuplicateFaces) {
        duplicate_faces::drop_duplicates(&mut soup, &mut log);
    }
    // Run even with neither split: it counts the non-manifold edges the log says were left.
    split::split(
        &mut soup,
        run(Step::SplitEdges),
        run(Step::SplitVertices),
        &mut log,
    );
    if run(Step::Orient) {
        orient::orient(&mut soup, &mut log);
    }
    if run(Step::UnusedVertices) {
        unused_vertices::drop_unused(&mut soup, &mut log);
    }
    Repaired { soup, log }
}

#[cfg(test)]
mod tests;
