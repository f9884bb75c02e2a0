//! The lecture on polygon-mesh data structures' "select, rotate, scale vertices, edges and
//! faces" (*Ecken, Kanten, Faces auswählen, rotieren, skalieren*) and its smoothing, over
//! [`MeshEdit`]: the lecture names the operations, not a method, so what follows is the lab's
//! choice.
//!
//! - **Select** ([`select_vertices`], [`select_edges`], [`select_faces`], and the box
//!   variants [`select_vertices_in`], [`select_edges_in`], [`select_faces_in`]): one scan of
//!   the vertices (edges, faces), keeping those whose position (both of whose ends, all of
//!   whose corners) a predicate accepts, as a typed, sorted set ([`VertexSelection`],
//!   [`EdgeSelection`], [`FaceSelection`]). O(n) on every structure; written over
//!   [`MeshEdit`] rather than the queries alone because a structure that marks deletions
//!   ([`Deletion::Marked`](crate::core::edit::Deletion::Marked)) keeps deleted slots, which a
//!   selection must skip.
//! - **Rotate, scale** ([`rotate_selection`], [`scale_selection`]): the positions of a vertex
//!   selection transformed about a centre and written back through
//!   [`MeshEdit::set_positions`], O(k) for k selected vertices where a position is stored once,
//!   O(n) in explicit storage, which must find every corner holding a moved position (the
//!   lecture's point: there "geometry cannot be changed independently of topology"). An edge
//!   or face selection is moved as the set of its ends or corners ([`EdgeSelection::vertices`],
//!   [`FaceSelection::vertices`]).
//! - **Smooth** ([`smooth_step`]): one step of uniform Laplacian smoothing, the rule of the
//!   lab's smoothing workload (an interior vertex moves to the mean of its neighbours, a
//!   boundary vertex stays) with the result written back. The neighbours are summed in
//!   increasing id order ([`laplacian_mean`]), so that every structure computes the same bits.
//!
//! An operation the structure does not offer ([`MeshEdit::supports`]) is refused with
//! [`Refusal::NotImplemented`], nothing changed; so is a selection holding a vertex that does
//! not exist ([`Refusal::NoSuchElement`]).

use crate::core::edit::{offered, EditOp, MeshEdit, Refusal};
use crate::core::error::{Error, Result};
use crate::core::ids::{EdgeId, FaceId, VertexId};
use glam::{DQuat, DVec3};

/// An axis-aligned box, bounds included.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Aabb {
    /// The lowest corner.
    pub min: DVec3,
    /// The highest corner.
    pub max: DVec3,
}

impl Aabb {
    /// Is `p` inside (or on) the box?
    pub fn contains(&self, p: DVec3) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }
}

/// Vertices chosen by a selection: ids sorted, each once.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct VertexSelection(Vec<VertexId>);

impl VertexSelection {
    /// The selection of `vertices` (sorted and deduplicated here).
    pub fn new(mut vertices: Vec<VertexId>) -> Self {
        vertices.sort_unstable();
        vertices.dedup();
        Self(vertices)
    }
    /// The selected vertices, in increasing id order.
    pub fn vertices(&self) -> &[VertexId] {
        &self.0
    }
    /// How many vertices are selected.
    pub fn len(&self) -> usize {
        self.0.len()
    }
    /// Is nothing selected?
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

/// Edges chosen by a selection: ids sorted, each once.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EdgeSelection(Vec<EdgeId>);

impl EdgeSelection {
    /// The selected edges, in increasing id order.
    pub fn edges(&self) -> &[EdgeId] {
        &self.0
    }
    /// How many edges are selected.
    pub fn len(&self) -> usize {
        self.0.len()
    }
    /// Is nothing selected?
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
    /// The ends of the selected edges, to rotate or scale them.
    pub fn vertices<M: MeshEdit>(&self, m: &M) -> VertexSelection {
        VertexSelection::new(self.0.iter().flat_map(|&e| m.edge_vertices(e)).collect())
    }
}

/// Faces chosen by a selection: ids sorted, each once.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FaceSelection(Vec<FaceId>);

impl FaceSelection {
    /// The selected faces, in increasing id order.
    pub fn faces(&self) -> &[FaceId] {
        &self.0
    }
    /// How many faces are selected.
    pub fn len(&self) -> usize {
        self.0.len()
    }
    /// Is nothing selected?
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
    /// The corners of the selected faces, to rotate or scale them.
    pub fn vertices<M: MeshEdit>(&self, m: &M) -> VertexSelection {
        let mut out = Vec::new();
        for &f in &self.0 {
            m.face_vertices(f, |v| out.push(v));
        }
        VertexSelection::new(out)
    }
}

/// The live vertices whose position `keep` accepts: one scan, O(n).
pub fn select_vertices<M: MeshEdit>(m: &M, keep: impl Fn(DVec3) -> bool) -> VertexSelection {
    VertexSelection(
        (0..m.num_vertices())
            .map(VertexId::new)
            .filter(|&v| !m.is_deleted_vertex(v) && keep(m.position(v)))
            .collect(),
    )
}

/// The live vertices inside `b`.
pub fn select_vertices_in<M: MeshEdit>(m: &M, b: &Aabb) -> VertexSelection {
    select_vertices(m, |p| b.contains(p))
}

/// The live edges whose two ends' positions `keep` accepts: one scan of the edges, O(n).
pub fn select_edges<M: MeshEdit>(m: &M, keep: impl Fn(DVec3, DVec3) -> bool) -> EdgeSelection {
    EdgeSelection(
        (0..m.num_edges())
            .map(EdgeId::new)
            .filter(|&e| {
                if m.is_deleted_edge(e) {
                    return false;
                }
                let [a, b] = m.edge_vertices(e);
                keep(m.position(a), m.position(b))
            })
            .collect(),
    )
}

/// The live edges with both ends inside `b`.
pub fn select_edges_in<M: MeshEdit>(m: &M, b: &Aabb) -> EdgeSelection {
    select_edges(m, |p, q| b.contains(p) && b.contains(q))
}

/// The live faces whose corner positions `keep` accepts: one scan of the faces and their
/// corners, O(n).
pub fn select_faces<M: MeshEdit>(m: &M, keep: impl Fn(&[DVec3]) -> bool) -> FaceSelection {
    let mut corners = Vec::with_capacity(8);
    FaceSelection(
        (0..m.num_faces())
            .map(FaceId::new)
            .filter(|&f| {
                if m.is_deleted_face(f) {
                    return false;
                }
                corners.clear();
                m.face_vertices(f, |v| corners.push(m.position(v)));
                keep(&corners)
            })
            .collect(),
    )
}

/// The live faces whose corners are all inside `b`.
pub fn select_faces_in<M: MeshEdit>(m: &M, b: &Aabb) -> FaceSelection {
    select_faces(m, |ps| ps.iter().all(|&p| b.contains(p)))
}

/// `p` rotated by `rotation` about `centre`.
pub fn rotate_point(p: DVec3, centre: DVec3, rotation: DQuat) -> DVec3 {
    centre + rotation * (p - centre)
}

/// `p` scaled by `factors` (per axis) about `centre`.
pub fn scale_point(p: DVec3, centre: DVec3, factors: DVec3) -> DVec3 {
    centre + factors * (p - centre)
}

/// The mean of `points` summed in the order given (the smoothing step gives them in
/// increasing vertex id order); `None` for no points.
pub fn laplacian_mean(points: impl IntoIterator<Item = DVec3>) -> Option<DVec3> {
    let (mut sum, mut k) = (DVec3::ZERO, 0u32);
    for p in points {
        sum += p;
        k += 1;
    }
    (k > 0).then(|| sum / k as f64)
}

/// `set_positions`, its refusal named as `op`'s.
fn write<M: MeshEdit>(m: &mut M, op: EditOp, moves: &[(VertexId, DVec3)]) -> Result<()> {
    m.set_positions(moves).map_err(|e| match e {
        Error::EditRefused {
            structure, reason, ..
        } => Error::EditRefused {
            structure,
            op,
            reason,
        },
        e => e,
    })
}

/// The selection `s` moved by `map`, as `op`.
fn transform<M: MeshEdit>(
    m: &mut M,
    op: EditOp,
    s: &VertexSelection,
    map: impl Fn(DVec3) -> DVec3,
) -> Result<()> {
    offered::<M>(op)?;
    let n = m.num_vertices();
    if s.0
        .iter()
        .any(|&v| v.index() >= n || m.is_deleted_vertex(v))
    {
        return Err(Error::EditRefused {
            structure: M::NAME,
            op,
            reason: Refusal::NoSuchElement,
        });
    }
    let moves: Vec<(VertexId, DVec3)> = s.0.iter().map(|&v| (v, map(m.position(v)))).collect();
    write(m, op, &moves)
}

/// Rotates the vertices of `s` by `rotation` about `centre` ([`EditOp::RotateSelection`]).
pub fn rotate_selection<M: MeshEdit>(
    m: &mut M,
    s: &VertexSelection,
    centre: DVec3,
    rotation: DQuat,
) -> Result<()> {
    transform(m, EditOp::RotateSelection, s, |p| {
        rotate_point(p, centre, rotation)
    })
}

/// Scales the vertices of `s` by `factors` (per axis) about `centre`
/// ([`EditOp::ScaleSelection`]).
pub fn scale_selection<M: MeshEdit>(
    m: &mut M,
    s: &VertexSelection,
    centre: DVec3,
    factors: DVec3,
) -> Result<()> {
    transform(m, EditOp::ScaleSelection, s, |p| {
        scale_point(p, centre, factors)
    })
}

/// One step of uniform Laplacian smoothing ([`EditOp::Smooth`]): every live interior vertex
/// with neighbours moves to the mean of their positions (read before anything moves), summed
/// in increasing id order; boundary vertices stay. Returns how many vertices moved.
pub fn smooth_step<M: MeshEdit>(m: &mut M) -> Result<usize> {
    offered::<M>(EditOp::Smooth)?;
    let mut moves = Vec::new();
    let mut ring: Vec<VertexId> = Vec::with_capacity(8);
    for v in (0..m.num_vertices()).map(VertexId::new) {
        if m.is_deleted_vertex(v) || m.is_boundary_vertex(v) {
            continue;
        }
        ring.clear();
        m.vertex_vertices(v, |w| ring.push(w));
        ring.sort_unstable();
        ring.dedup();
        let Some(p) = laplacian_mean(ring.iter().map(|&w| m.position(w))) else {
            continue;
        };
        if p != m.position(v) {
            moves.push((v, p));
        }
    }
    write(m, EditOp::Smooth, &moves)?;
    Ok(moves.len())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::soup::PolygonSoup;
    use crate::core::topology::MeshTopology;
    use crate::families::half_edge::index::IndexHalfEdge;

    fn quad_grid() -> PolygonSoup {
        // 3 x 3 vertices, 4 quads, one interior vertex (4) at (1, 1).
        let positions = (0..9)
            .map(|i| DVec3::new((i % 3) as f64, (i / 3) as f64, 0.0))
            .collect();
        PolygonSoup::from_polygons(
            positions,
            &[
                vec![0, 1, 4, 3],
                vec![1, 2, 5, 4],
                vec![3, 4, 7, 6],
                vec![4, 5, 8, 7],
            ],
        )
    }

    #[test]
    fn a_box_selects_the_vertices_and_faces_inside_it() {
        let m = IndexHalfEdge::from_soup(&quad_grid()).unwrap();
        let b = Aabb {
            min: DVec3::new(-0.5, -0.5, -1.0),
            max: DVec3::new(1.5, 1.5, 1.0),
        };
        let ids = |s: &[VertexId]| s.iter().map(|v| v.0).collect::<Vec<_>>();
        assert_eq!(ids(select_vertices_in(&m, &b).vertices()), [0, 1, 3, 4]);
        let faces = select_faces_in(&m, &b);
        assert_eq!(faces.len(), 1);
        assert_eq!(ids(faces.vertices(&m).vertices()), [0, 1, 3, 4]);
        // The edges of the one quad inside, each with both ends in the box; not 1 - 2.
        let edges = select_edges_in(&m, &b);
        let mut ends: Vec<[u32; 2]> = edges
            .edges()
            .iter()
            .map(|&e| {
                let [a, b] = m.edge_vertices(e).map(|v| v.0);
                [a.min(b), a.max(b)]
            })
            .collect();
        ends.sort_unstable();
        assert_eq!(ends, [[0, 1], [0, 3], [1, 4], [3, 4]]);
        assert_eq!(ids(edges.vertices(&m).vertices()), [0, 1, 3, 4]);
    }

    #[test]
    fn rotation_and_scale_move_only_the_selection_about_the_centre() {
        let mut m = IndexHalfEdge::from_soup(&quad_grid()).unwrap();
        let s = VertexSelection::new(vec![VertexId(2), VertexId(0)]);
        let quarter = DQuat::from_rotation_z(std::f64::consts::FRAC_PI_2);
        rotate_selection(&mut m, &s, DVec3::ZERO, quarter).unwrap();
        // (2, 0, 0) turned a quarter about z is (0, 2, 0); the origin stays.
        assert!((m.position(VertexId(2)) - DVec3::new(0.0, 2.0, 0.0)).length() < 1e-12);
        assert_eq!(m.position(VertexId(0)), DVec3::ZERO);
        scale_selection(&mut m, &s, DVec3::new(0.0, 1.0, 0.0), DVec3::splat(3.0)).unwrap();
        assert!((m.position(VertexId(2)) - DVec3::new(0.0, 4.0, 0.0)).length() < 1e-12);
        assert_eq!(m.position(VertexId(1)), DVec3::new(1.0, 0.0, 0.0));
        let missing = VertexSelection::new(vec![VertexId(99)]);
        let e = rotate_selection(&mut m, &missing, DVec3::ZERO, quarter).unwrap_err();
        assert!(matches!(
            e,
            Error::EditRefused {
                op: EditOp::RotateSelection,
                reason: Refusal::NoSuchElement,
                ..
            }
        ));
    }

    #[test]
    fn a_smoothing_step_moves_interior_vertices_to_the_mean_of_their_neighbours() {
        let mut soup = quad_grid();
        soup.positions[4] = DVec3::new(1.0, 1.0, 4.0);
        let mut m = IndexHalfEdge::from_soup(&soup).unwrap();
        assert_eq!(smooth_step(&mut m).unwrap(), 1);
        // The neighbours 1, 3, 5, 7 lie in the plane z = 0 around (1, 1).
        assert_eq!(m.position(VertexId(4)), DVec3::new(1.0, 1.0, 0.0));
        assert_eq!(m.position(VertexId(0)), DVec3::ZERO);
        assert_eq!(smooth_step(&mut m).unwrap(), 0);
    }
}
