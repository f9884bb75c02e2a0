//! [`MeshTopology`](crate::MeshTopology) for the four levels, written once over their
//! [`CheLevel`] hooks (the `che_topology!` macro each level invokes).

use super::{half_edge, half_edges_of, next, prev, CheLevel};
use crate::core::ids::{EdgeId, FaceId, HalfEdgeId};
use crate::core::reads::read;

/// The edge after (`forward`) or before `e` in triangle `t`, found among `t`'s three
/// half-edges by `e`'s end vertices: O(1) at every level.
fn neighbour_in_face<L: CheLevel>(
    level: &L,
    e: EdgeId,
    t: FaceId,
    forward: bool,
) -> Option<HalfEdgeId> {
    let v = level.start_vertices();
    let ends = |h: HalfEdgeId| (read!("V", v, h.index()), read!("V", v, next(h).index()));
    let (a, b) = ends(half_edge(e));
    half_edges_of(t)
        .find(|&h| {
            let (c, d) = ends(h);
            (c, d) == (a, b) || (c, d) == (b, a)
        })
        .map(|h| if forward { next(h) } else { prev(h) })
}

/// Implements [`crate::MeshTopology`] for a level from its [`CheLevel`] hooks: one body for
/// the relations of all four levels, so they differ only where the chapter's algorithms do.
macro_rules! che_topology {
    ($ty:ty, $name:literal, $cost:path) => {
        impl $crate::core::topology::MeshTopology for $ty {
            const NAME: &'static str = $name;
            const FAMILY: $crate::Family = $crate::Family::Che;

            fn capabilities() -> $crate::core::topology::Capabilities {
                $crate::core::topology::Capabilities {
                    triangles_only: true,
                    ..$crate::core::topology::Capabilities::POLYGONS
                }
            }
            fn cost(op: $crate::core::topology::Operator) -> $crate::core::topology::Cost {
                $cost(op)
            }
            fn from_soup(
                soup: &$crate::core::soup::PolygonSoup,
            ) -> $crate::core::error::Result<Self> {
                Self::build(soup)
            }
            fn from_soup_owned(
                soup: $crate::core::soup::PolygonSoup,
            ) -> $crate::core::error::Result<Self> {
                Self::build_owned(soup)
            }
            #[inline]
            fn num_vertices(&self) -> usize {
                self.geometry().len()
            }
            #[inline]
            fn num_edges(&self) -> usize {
                $crate::families::che::CheLevel::edge_count(self)
            }
            #[inline]
            fn num_faces(&self) -> usize {
                self.start_vertices().len() / 3
            }
            fn for_each_edge(&self, f: impl FnMut($crate::core::ids::EdgeId)) {
                $crate::families::che::CheLevel::each_edge(self, f)
            }
            #[inline]
            fn position(&self, v: $crate::core::ids::VertexId) -> glam::DVec3 {
                self.geometry()[v.index()]
            }
            #[inline]
            fn vertex_vertices(
                &self,
                v: $crate::core::ids::VertexId,
                f: impl FnMut($crate::core::ids::VertexId),
            ) {
                $crate::families::che::CheLevel::neighbours(self, v, f)
            }
            #[inline]
            fn vertex_edges(
                &self,
                v: $crate::core::ids::VertexId,
                f: impl FnMut($crate::core::ids::EdgeId),
            ) {
                $crate::families::che::CheLevel::spoke_edges(self, v, f)
            }
            #[inline]
            fn vertex_faces(
                &self,
                v: $crate::core::ids::VertexId,
                f: impl FnMut($crate::core::ids::FaceId),
            ) {
                $crate::families::che::CheLevel::star_triangles(self, v, f)
            }
            #[inline]
            fn edge_vertices(
                &self,
                e: $crate::core::ids::EdgeId,
            ) -> [$crate::core::ids::VertexId; 2] {
                let vs = self.start_vertices();
                let he = $crate::families::che::half_edge(e);
                [
                    $crate::core::ids::VertexId($crate::core::reads::read!("V", vs, he.index())),
                    $crate::core::ids::VertexId($crate::core::reads::read!(
                        "V",
                        vs,
                        $crate::families::che::next(he).index()
                    )),
                ]
            }
            #[inline]
            fn edge_edges(
                &self,
                e: $crate::core::ids::EdgeId,
                mut f: impl FnMut($crate::core::ids::EdgeId),
            ) {
                let mut sides = |h: $crate::core::ids::HalfEdgeId| {
                    f(self.edge_of($crate::families::che::next(h)));
                    f(self.edge_of($crate::families::che::prev(h)));
                };
                let he = $crate::families::che::half_edge(e);
                sides(he);
                if let Some(o) = self.twin(he) {
                    sides(o);
                }
            }
            #[inline]
            fn edge_faces(
                &self,
                e: $crate::core::ids::EdgeId,
                mut f: impl FnMut($crate::core::ids::FaceId),
            ) {
                let he = $crate::families::che::half_edge(e);
                f($crate::families::che::triangle(he));
                if let Some(o) = self.twin(he) {
                    f($crate::families::che::triangle(o));
                }
            }
            #[inline]
            fn face_vertices(
                &self,
                face: $crate::core::ids::FaceId,
                mut f: impl FnMut($crate::core::ids::VertexId),
            ) {
                for he in $crate::families::che::half_edges_of(face) {
                    f($crate::core::ids::VertexId($crate::core::reads::read!(
                        "V",
                        self.start_vertices(),
                        he.index()
                    )));
                }
            }
            #[inline]
            fn face_edges(
                &self,
                face: $crate::core::ids::FaceId,
                mut f: impl FnMut($crate::core::ids::EdgeId),
            ) {
                for he in $crate::families::che::half_edges_of(face) {
                    f(self.edge_of(he));
                }
            }
            #[inline]
            fn face_faces(
                &self,
                face: $crate::core::ids::FaceId,
                f: impl FnMut($crate::core::ids::FaceId),
            ) {
                $crate::families::che::CheLevel::triangles_across(self, face, f)
            }
            #[inline]
            fn is_boundary_vertex(&self, v: $crate::core::ids::VertexId) -> bool {
                $crate::families::che::CheLevel::vertex_on_boundary(self, v)
            }
            #[inline]
            fn is_boundary_edge(&self, e: $crate::core::ids::EdgeId) -> bool {
                self.twin($crate::families::che::half_edge(e)).is_none()
            }
            #[inline]
            fn boundary_curves(&self, out: &mut $crate::core::topology::BoundaryCurves) {
                $crate::families::che::CheLevel::walk_boundary_curves(self, out)
            }
            #[inline]
            fn edge_successor(
                &self,
                e: $crate::core::ids::EdgeId,
                face: $crate::core::ids::FaceId,
            ) -> Option<$crate::core::ids::EdgeId> {
                $crate::families::che::topology::successor(self, e, face, true)
            }
            #[inline]
            fn edge_predecessor(
                &self,
                e: $crate::core::ids::EdgeId,
                face: $crate::core::ids::FaceId,
            ) -> Option<$crate::core::ids::EdgeId> {
                $crate::families::che::topology::successor(self, e, face, false)
            }
            fn validate(&self) -> $crate::core::error::Result<()> {
                self.check_containers()
            }
            fn heap_bytes(&self) -> usize {
                self.container_bytes()
            }
            fn explain(&self, w: &mut dyn std::fmt::Write) -> std::fmt::Result {
                self.print_containers(w)
            }
            fn access(
                op: $crate::core::topology::Operator,
            ) -> Option<$crate::core::access::Access> {
                $crate::families::che::access::model(
                    <$ty as $crate::families::che::CheLevel>::LEVEL,
                    op,
                )
            }
        }
    };
}
pub(crate) use che_topology;

/// Successor (`forward`) or predecessor of `e` in `face`, as the level names edges.
pub(crate) fn successor<L: CheLevel>(
    level: &L,
    e: EdgeId,
    face: FaceId,
    forward: bool,
) -> Option<EdgeId> {
    neighbour_in_face(level, e, face, forward).map(|h| level.edge_of(h))
}
