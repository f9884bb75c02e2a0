//! The two changing workloads of the Surface_mesh benchmark (Sieger & Botsch, IMR 2011), on
//! any [`MeshEdit`] structure, as the protocol (pmp-library's
//! `benchmarks/SurfaceMeshPerformance.h`) runs them:
//!
//! - [`sqrt3_step`]: one step of √3 subdivision (Kobbelt): new positions of the old interior
//!   vertices (weight α = (4 − 2 cos(2π/n)) / 9 for valence n), every old face split at its
//!   centroid, then every old edge flipped where the flip is allowed (boundary edges are not);
//! - [`collapse_test`]: every face split at the origin, every new vertex collapsed back into
//!   the end of its half-edge, then the deleted elements collected. The mesh comes back as it
//!   was (faces possibly renumbered).
//!
//! New vertex of face `f` (in both): vertex `n0 + f`, as in every library that appends.

use crate::core::edit::{EditOp, MeshEdit};
use crate::core::error::{Error, Result};
use crate::core::ids::{FaceId, VertexId};
use crate::core::soup::PolygonSoup;
use crate::core::topology::MeshTopology;
use glam::DVec3;
use std::f64::consts::TAU;

/// The face list and positions of `m` as a soup, ids as the structure's (after
/// [`MeshEdit::garbage_collection`], when it marks deletions): what an edited mesh is written as.
pub fn to_soup<M: MeshTopology>(m: &M) -> PolygonSoup {
    let positions = (0..m.num_vertices())
        .map(|v| m.position(VertexId::new(v)))
        .collect();
    let mut soup = PolygonSoup::with_capacity(0, m.num_faces(), 3 * m.num_faces());
    soup.positions = positions;
    let mut face = Vec::new();
    for f in 0..m.num_faces() {
        face.clear();
        m.face_vertices(FaceId::new(f), |v| face.push(v.0));
        soup.push_face(&face);
    }
    soup
}

/// A changing workload.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Changing {
    /// One step of √3 subdivision ([`sqrt3_step`]).
    Sqrt3,
    /// The collapse test ([`collapse_test`]).
    Collapse,
}

impl Changing {
    /// Both workloads.
    pub const ALL: [Changing; 2] = [Changing::Sqrt3, Changing::Collapse];

    /// The kebab-case name.
    pub const fn name(self) -> &'static str {
        match self {
            Changing::Sqrt3 => "sqrt3",
            Changing::Collapse => "collapse-test",
        }
    }

    /// The editing operations the workload does, with how many per face of the mesh it
    /// starts from (what its declared costs are made of).
    pub const fn operations(self) -> &'static [(EditOp, f64)] {
        match self {
            Changing::Sqrt3 => &[(EditOp::SplitFace, 1.0), (EditOp::FlipEdge, 1.5)],
            Changing::Collapse => &[
                (EditOp::SplitFace, 1.0),
                (EditOp::CollapseEdge, 1.0),
                (EditOp::GarbageCollection, 0.0),
            ],
        }
    }

    /// Runs the workload on `m`.
    pub fn run<M: MeshEdit>(self, m: &mut M) -> Result<()> {
        match self {
            Changing::Sqrt3 => sqrt3_step(m),
            Changing::Collapse => collapse_test(m),
        }
    }
}

/// One step of √3 subdivision (see the module docs). Polygons are split into fans as the
/// protocol does; the CLI refuses them before (√3 is a triangle scheme).
///
/// Refused with [`Error::Unsupported`], before any change, on a structure whose edge ids do
/// not survive the face splits ([`MeshEdit::STABLE_EDGE_IDS`]): the flips would hit other
/// edges than the old ones.
pub fn sqrt3_step<M: MeshEdit>(m: &mut M) -> Result<()> {
    if !M::STABLE_EDGE_IDS {
        return Err(Error::Unsupported(format!(
            "{}: √3 subdivision flips the old edges by id, and this structure's edge ids change when faces are split",
            M::NAME
        )));
    }
    let (nv, ne, nf) = (m.num_vertices(), m.num_edges(), m.num_faces());
    m.reserve(nf, 3 * nf, 2 * nf);
    // New positions of the old interior vertices.
    let mut moved: Vec<DVec3> = Vec::with_capacity(nv);
    for v in 0..nv {
        let v = VertexId::new(v);
        let p = m.position(v);
        if m.is_boundary_vertex(v) {
            moved.push(p);
            continue;
        }
        let (mut sum, mut n) = (DVec3::ZERO, 0usize);
        m.vertex_vertices(v, |w| {
            sum += m.position(w);
            n += 1;
        });
        if n == 0 {
            moved.push(p);
            continue;
        }
        let n = n as f64;
        let alpha = (4.0 - 2.0 * (TAU / n).cos()) / 9.0;
        moved.push((1.0 - alpha) * p + alpha / n * sum);
    }
    for f in 0..nf {
        let f = FaceId::new(f);
        let (mut c, mut k) = (DVec3::ZERO, 0usize);
        m.face_vertices(f, |v| {
            c += m.position(v);
            k += 1;
        });
        m.split_face(f, c / k as f64)?;
    }
    for (v, p) in moved.into_iter().enumerate() {
        let v = VertexId::new(v);
        if !m.is_boundary_vertex(v) {
            m.set_position(v, p)?;
        }
    }
    // The old edges are those between two old vertices (every new edge has a new end), found
    // after the splits: a structure whose edge ids are half-edge ids of triangles (the CHE)
    // moves an old edge to a new triangle when it splits a face, so ids taken before would
    // name other edges. Flipping one old edge rewrites only its own two triangles.
    let mut old = Vec::with_capacity(ne);
    m.for_each_edge(|e| {
        let [a, b] = m.edge_vertices(e);
        if a.index() < nv && b.index() < nv {
            old.push(e);
        }
    });
    for e in old {
        match m.flip_edge(e) {
            Ok(()) | Err(Error::EditRefused { .. }) => {}
            Err(e) => return Err(e),
        }
    }
    Ok(())
}

/// The collapse test (see the module docs).
pub fn collapse_test<M: MeshEdit>(m: &mut M) -> Result<()> {
    let (nv, nf) = (m.num_vertices(), m.num_faces());
    m.reserve(nf, 3 * nf, 2 * nf);
    for f in 0..nf {
        m.split_face(FaceId::new(f), DVec3::ZERO)?;
    }
    for v in nv..m.num_vertices() {
        let v = VertexId::new(v);
        // The end of v's half-edge: the first neighbour its rotation reports.
        let mut first = None;
        m.vertex_vertices(v, |w| {
            first.get_or_insert(w);
        });
        if let Some(w) = first {
            m.collapse_edge(v, w)?;
        }
    }
    m.garbage_collection();
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::ids::EdgeId;
    use crate::families::corner_lists::vertex_list::VertexList;
    use crate::families::edge_lists::edge_list::EdgeList;
    use crate::families::edge_lists::winged_edge::WingedEdge;
    use crate::families::half_edge::index::IndexHalfEdge;
    use crate::families::half_edge::pointer::PointerHalfEdge;
    use crate::meshes;
    use crate::testing::editing::canonical_face;

    fn faces(m: &impl MeshEdit) -> Vec<Vec<u32>> {
        let soup = to_soup(m);
        let mut out: Vec<Vec<u32>> = soup.faces().map(canonical_face).collect();
        out.sort();
        out
    }

    fn both<M: MeshEdit>() {
        for soup in [meshes::torus(6, 5), meshes::grid(4, 3, true)] {
            let mut m = M::from_soup(&soup).expect("manifold");
            let before = faces(&m);
            collapse_test(&mut m).expect("the collapse test runs");
            m.validate().expect("valid");
            assert_eq!(
                faces(&m),
                before,
                "{}: the collapse test gives the mesh back",
                M::NAME
            );

            let mut m = M::from_soup(&soup).expect("manifold");
            let (nv, ne, nf) = (m.num_vertices(), m.num_edges(), m.num_faces());
            if !M::STABLE_EDGE_IDS {
                let err = sqrt3_step(&mut m).expect_err("refused without stable edge ids");
                assert_eq!(err.kind(), "unsupported", "{err}");
                assert_eq!(m.num_faces(), nf, "nothing changed");
                continue;
            }
            sqrt3_step(&mut m).expect("√3 runs");
            m.validate().expect("valid");
            assert_eq!(m.num_faces(), 3 * nf);
            assert_eq!(m.num_vertices(), nv + nf);
            // Every old interior edge was flipped: it no longer joins its old ends.
            let boundary = m.num_boundary_edges();
            let mut kept = 0;
            for e in 0..ne {
                let [a, b] = m.edge_vertices(EdgeId::new(e));
                kept += (a.index() < nv && b.index() < nv) as usize;
            }
            assert_eq!(
                kept, boundary,
                "only the old boundary edges keep their ends"
            );
        }
    }

    /// The face list after `w` on `soup`.
    fn after<M: MeshEdit>(soup: &PolygonSoup, w: Changing) -> Vec<Vec<u32>> {
        let mut m = M::from_soup(soup).expect("manifold");
        w.run(&mut m).expect("runs");
        faces(&m)
    }

    #[test]
    fn every_editable_structure_changes_a_mesh_into_the_same_faces() {
        for soup in [meshes::torus(6, 5), meshes::grid(4, 3, true)] {
            for w in Changing::ALL {
                let want = after::<IndexHalfEdge>(&soup, w);
                assert_eq!(after::<WingedEdge>(&soup, w), want, "winged-edge {w:?}");
                assert_eq!(after::<EdgeList>(&soup, w), want, "edge-list {w:?}");
                if w == Changing::Collapse {
                    assert_eq!(after::<VertexList>(&soup, w), want, "vertex-list {w:?}");
                }
            }
        }
    }

    #[test]
    fn the_collapse_test_restores_the_mesh_and_sqrt3_flips_every_interior_edge() {
        both::<IndexHalfEdge>();
        both::<PointerHalfEdge>();
        both::<WingedEdge>();
        both::<EdgeList>();
        both::<VertexList>();
    }
}
