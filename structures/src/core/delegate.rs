//! [`delegate_topology!`](crate::delegate_topology): [`MeshTopology`](crate::MeshTopology)
//! for a newtype over a structure, every query forwarded to the structure inside, in the
//! manner of petgraph's `delegate_impl`. A structure that adds something of its own (its own
//! editing operations, a different name in the report) starts from it instead of writing the
//! queries again.

/// Implements [`MeshTopology`](crate::MeshTopology) for the tuple struct `$outer($inner)`:
/// its name is `$name`, its costs, capabilities and every query are `$inner`'s, called on
/// field `.0`. The native kernels and the separate construction stay the defaults (none): the
/// harness times the lab's generic kernels on it.
///
/// ```
/// use topolab_structures::{IndexHalfEdge, MeshTopology};
/// struct Renamed(IndexHalfEdge);
/// topolab_structures::delegate_topology!(Renamed(IndexHalfEdge), "renamed-half-edge");
/// let m = Renamed::from_soup(&topolab_structures::meshes::closed_tetrahedron()).unwrap();
/// assert_eq!((Renamed::NAME, m.num_faces()), ("renamed-half-edge", 4));
/// ```
#[macro_export]
macro_rules! delegate_topology {
    ($outer:ident($inner:ty), $name:literal) => {
        impl $crate::core::topology::MeshTopology for $outer {
            const NAME: &'static str = $name;
            const FAMILY: $crate::core::family::Family =
                <$inner as $crate::core::topology::MeshTopology>::FAMILY;
            fn capabilities() -> $crate::core::topology::Capabilities {
                <$inner as $crate::core::topology::MeshTopology>::capabilities()
            }
            fn cost(op: $crate::core::topology::Operator) -> $crate::core::topology::Cost {
                <$inner as $crate::core::topology::MeshTopology>::cost(op)
            }
            fn from_soup(
                soup: &$crate::core::soup::PolygonSoup,
            ) -> $crate::core::error::Result<Self> {
                <$inner as $crate::core::topology::MeshTopology>::from_soup(soup).map($outer)
            }
            fn from_soup_owned(
                soup: $crate::core::soup::PolygonSoup,
            ) -> $crate::core::error::Result<Self> {
                <$inner as $crate::core::topology::MeshTopology>::from_soup_owned(soup).map($outer)
            }
            #[inline]
            fn num_vertices(&self) -> usize {
                self.0.num_vertices()
            }
            #[inline]
            fn num_edges(&self) -> usize {
                self.0.num_edges()
            }
            #[inline]
            fn num_faces(&self) -> usize {
                self.0.num_faces()
            }
            #[inline]
            fn num_boundary_edges(&self) -> usize {
                self.0.num_boundary_edges()
            }
            fn for_each_edge(&self, f: impl FnMut($crate::core::ids::EdgeId)) {
                self.0.for_each_edge(f)
            }
            #[inline]
            fn position(&self, v: $crate::core::ids::VertexId) -> $crate::glam::DVec3 {
                self.0.position(v)
            }
            #[inline]
            fn vertex_vertices(
                &self,
                v: $crate::core::ids::VertexId,
                f: impl FnMut($crate::core::ids::VertexId),
            ) {
                self.0.vertex_vertices(v, f)
            }
            #[inline]
            fn vertex_edges(
                &self,
                v: $crate::core::ids::VertexId,
                f: impl FnMut($crate::core::ids::EdgeId),
            ) {
                self.0.vertex_edges(v, f)
            }
            #[inline]
            fn vertex_faces(
                &self,
                v: $crate::core::ids::VertexId,
                f: impl FnMut($crate::core::ids::FaceId),
            ) {
                self.0.vertex_faces(v, f)
            }
            #[inline]
            fn edge_vertices(
                &self,
                e: $crate::core::ids::EdgeId,
            ) -> [$crate::core::ids::VertexId; 2] {
                self.0.edge_vertices(e)
            }
            #[inline]
            fn edge_edges(
                &self,
                e: $crate::core::ids::EdgeId,
                f: impl FnMut($crate::core::ids::EdgeId),
            ) {
                self.0.edge_edges(e, f)
            }
            #[inline]
            fn edge_faces(
                &self,
                e: $crate::core::ids::EdgeId,
                f: impl FnMut($crate::core::ids::FaceId),
            ) {
                self.0.edge_faces(e, f)
            }
            #[inline]
            fn face_vertices(
                &self,
                face: $crate::core::ids::FaceId,
                f: impl FnMut($crate::core::ids::VertexId),
            ) {
                self.0.face_vertices(face, f)
            }
            #[inline]
            fn face_edges(
                &self,
                face: $crate::core::ids::FaceId,
                f: impl FnMut($crate::core::ids::EdgeId),
            ) {
                self.0.face_edges(face, f)
            }
            #[inline]
            fn face_faces(
                &self,
                face: $crate::core::ids::FaceId,
                f: impl FnMut($crate::core::ids::FaceId),
            ) {
                self.0.face_faces(face, f)
            }
            #[inline]
            fn is_boundary_vertex(&self, v: $crate::core::ids::VertexId) -> bool {
                self.0.is_boundary_vertex(v)
            }
            #[inline]
            fn is_boundary_edge(&self, e: $crate::core::ids::EdgeId) -> bool {
                self.0.is_boundary_edge(e)
            }
            fn boundary_curves(&self, out: &mut $crate::core::topology::BoundaryCurves) {
                self.0.boundary_curves(out)
            }
            #[inline]
            fn edge_successor(
                &self,
                e: $crate::core::ids::EdgeId,
                face: $crate::core::ids::FaceId,
            ) -> Option<$crate::core::ids::EdgeId> {
                self.0.edge_successor(e, face)
            }
            #[inline]
            fn edge_predecessor(
                &self,
                e: $crate::core::ids::EdgeId,
                face: $crate::core::ids::FaceId,
            ) -> Option<$crate::core::ids::EdgeId> {
                self.0.edge_predecessor(e, face)
            }
            fn validate(&self) -> $crate::core::error::Result<()> {
                self.0.validate()
            }
            fn heap_bytes(&self) -> usize {
                self.0.heap_bytes()
            }
            fn explain(&self, w: &mut dyn std::fmt::Write) -> std::fmt::Result {
                self.0.explain(w)
            }
            fn input_checks() -> Option<$crate::core::topology::InputChecks> {
                <$inner as $crate::core::topology::MeshTopology>::input_checks()
            }
            fn access(
                op: $crate::core::topology::Operator,
            ) -> Option<$crate::core::access::Access> {
                <$inner as $crate::core::topology::MeshTopology>::access(op)
            }
        }
    };
}
