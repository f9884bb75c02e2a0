//! Input each crate would mis-handle is refused with the lab's typed error before the crate
//! sees it, and nothing panics: tri-mesh pairs a third face on an edge with the wrong
//! half-edge, lox panics on a non-manifold edge or vertex, baby_shark skips such faces or
//! splits such vertices. The conformance suite's meshes have no edge with three faces and no
//! face reversed against its neighbour, so these soups are here.

use glam::DVec3;
use topolab_peers::{BabySharkCornerTable, LoxDirectedEdge, LoxHalfEdge, TriMesh};
use topolab_structures::{MeshTopology, PolygonSoup};

/// Five points, enough for every soup below.
fn soup(faces: &[&[u32]]) -> PolygonSoup {
    let positions = vec![
        DVec3::ZERO,
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::new(0.0, -1.0, 0.0),
        DVec3::new(0.0, 0.0, 1.0),
    ];
    PolygonSoup::from_polygons(positions, faces)
}

/// Each bad soup and the error kind the lab names it with.
fn bad_soups() -> Vec<(&'static str, PolygonSoup, &'static str)> {
    vec![
        (
            "a third face on edge 0-1",
            soup(&[&[0, 1, 2], &[1, 0, 3], &[0, 1, 4]]),
            "non-manifold-edge",
        ),
        (
            "two faces running one way along edge 0-1",
            soup(&[&[0, 1, 2], &[0, 1, 3]]),
            "inconsistent-orientation",
        ),
        (
            "the same face twice",
            soup(&[&[0, 1, 2], &[0, 1, 2]]),
            "inconsistent-orientation",
        ),
        (
            "two fans at vertex 0 (a bowtie)",
            soup(&[&[0, 1, 2], &[0, 3, 4]]),
            "non-manifold-vertex",
        ),
        (
            "a corner past the vertices",
            soup(&[&[0, 1, 7]]),
            "index-out-of-range",
        ),
        (
            "a vertex twice in one face",
            soup(&[&[0, 1, 1]]),
            "repeated-vertex",
        ),
    ]
}

fn refuses_before_the_crate<M: MeshTopology>() {
    for (what, soup, kind) in bad_soups() {
        match M::from_soup(&soup) {
            Ok(_) => panic!("{} built {what}, which it must refuse with {kind}", M::NAME),
            Err(e) => assert_eq!(e.kind(), kind, "{} on {what}: {e}", M::NAME),
        }
    }
}

/// A triangles-only crate refuses a quad by name; lox's half-edge mesh stores it.
fn quad_as_capabilities_say<M: MeshTopology>() {
    let quad = soup(&[&[0, 3, 1, 2]]);
    match (M::capabilities().triangles_only, M::from_soup(&quad)) {
        (true, Err(e)) => assert_eq!(e.kind(), "not-triangles", "{}: {e}", M::NAME),
        (false, Ok(m)) => assert_eq!(m.num_faces(), 1, "{}", M::NAME),
        (true, Ok(_)) => panic!("{} stored a quad", M::NAME),
        (false, Err(e)) => panic!("{} refused a quad: {e}", M::NAME),
    }
}

macro_rules! refusals {
    ($($module:ident => $ty:ty),+ $(,)?) => {
        $(
            mod $module {
                use super::*;

                #[test]
                fn refuses_what_the_crate_would_mishandle() {
                    refuses_before_the_crate::<$ty>();
                }

                #[test]
                fn quads_as_its_capabilities_say() {
                    quad_as_capabilities_say::<$ty>();
                }
            }
        )+
    };
}

refusals! {
    lox_half_edge => LoxHalfEdge,
    lox_directed_edge => LoxDirectedEdge,
    baby_shark_corner_table => BabySharkCornerTable,
    tri_mesh => TriMesh,
}
