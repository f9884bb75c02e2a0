//! The conformance suite must catch a structure that answers one relation wrong: a test double
//! that wraps the vertex list and forgets the last face of every R22 answer.

use topolab_structures::testing::conformance::{self, check};
use topolab_structures::*;

struct ForgetfulR22(VertexList);

impl MeshTopology for ForgetfulR22 {
    const NAME: &'static str = "forgetful-r22";
    fn capabilities() -> Capabilities {
        VertexList::capabilities()
    }
    fn cost(op: Operator) -> Cost {
        VertexList::cost(op)
    }
    fn from_soup(soup: &PolygonSoup) -> Result<Self> {
        VertexList::from_soup(soup).map(Self)
    }
    fn num_vertices(&self) -> usize {
        self.0.num_vertices()
    }
    fn num_edges(&self) -> usize {
        self.0.num_edges()
    }
    fn num_faces(&self) -> usize {
        self.0.num_faces()
    }
    fn for_each_edge(&self, f: impl FnMut(EdgeId)) {
        self.0.for_each_edge(f)
    }
    fn position(&self, v: VertexId) -> glam::DVec3 {
        self.0.position(v)
    }
    fn vertex_vertices(&self, v: VertexId, f: impl FnMut(VertexId)) {
        self.0.vertex_vertices(v, f)
    }
    fn vertex_edges(&self, v: VertexId, f: impl FnMut(EdgeId)) {
        self.0.vertex_edges(v, f)
    }
    fn vertex_faces(&self, v: VertexId, f: impl FnMut(FaceId)) {
        self.0.vertex_faces(v, f)
    }
    fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2] {
        self.0.edge_vertices(e)
    }
    fn edge_edges(&self, e: EdgeId, f: impl FnMut(EdgeId)) {
        self.0.edge_edges(e, f)
    }
    fn edge_faces(&self, e: EdgeId, f: impl FnMut(FaceId)) {
        self.0.edge_faces(e, f)
    }
    fn face_vertices(&self, face: FaceId, f: impl FnMut(VertexId)) {
        self.0.face_vertices(face, f)
    }
    fn face_edges(&self, face: FaceId, f: impl FnMut(EdgeId)) {
        self.0.face_edges(face, f)
    }
    fn face_faces(&self, face: FaceId, mut f: impl FnMut(FaceId)) {
        // The bug: every answer but the last.
        let mut all = Vec::new();
        self.0.face_faces(face, |g| all.push(g));
        all.pop();
        all.into_iter().for_each(&mut f);
    }
    fn is_boundary_vertex(&self, v: VertexId) -> bool {
        self.0.is_boundary_vertex(v)
    }
    fn is_boundary_edge(&self, e: EdgeId) -> bool {
        self.0.is_boundary_edge(e)
    }
    fn boundary_curves(&self, out: &mut BoundaryCurves) {
        self.0.boundary_curves(out)
    }
    fn edge_successor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        self.0.edge_successor(e, face)
    }
    fn edge_predecessor(&self, e: EdgeId, face: FaceId) -> Option<EdgeId> {
        self.0.edge_predecessor(e, face)
    }
    fn validate(&self) -> Result<()> {
        self.0.validate()
    }
    fn heap_bytes(&self) -> usize {
        self.0.heap_bytes()
    }
    fn explain(&self, w: &mut dyn std::fmt::Write) -> std::fmt::Result {
        self.0.explain(w)
    }
}

#[test]
fn the_suite_catches_one_wrong_relation() {
    let err = check::<ForgetfulR22>(&meshes::closed_tetrahedron(), false).unwrap_err();
    assert!(err.starts_with("R22(f0)"), "{err}");
    // The same mesh through the real structure conforms: the failure is the double's.
    assert!(check::<VertexList>(&meshes::closed_tetrahedron(), false).is_ok());
}

#[test]
fn the_suite_catches_a_refusal_that_capabilities_do_not_announce() {
    // A structure without non-manifold vertex support must refuse the bowtie; one with it must store it.
    let soup = meshes::bowtie();
    let kinds = conformance::expected_refusals(&soup, Capabilities::POLYGONS, false).unwrap();
    assert_eq!(kinds, ["non-manifold-vertex"]);
    assert!(conformance::expected_refusals(&soup, VertexList::capabilities(), false).is_none());
}
