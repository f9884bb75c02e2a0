//! Input each crate would mis-handle is refused with the lab's typed error before the crate
//! sees it, and nothing panics: tri-mesh pairs a third face on an edge with the wrong
//! half-edge, lox panics on a non-manifold edge or vertex, baby_shark skips such faces or
//! splits such vertices. The conformance suite's meshes have no edge with three faces and no
//! face reversed against its neighbour, so these soups are here.

use glam::DVec3;
use topolab_peers::{BabySharkCornerTable, LoxDirectedEdge, LoxHalfEdge, TriMesh};
use topolab_structures::{meshes, BuildFacts, MeshTopology, PolygonSoup};

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

/// The report times a crate's construction apart from the lab's checks
/// (`SeparateConstruction`); given facts of a soup those checks would refuse, the crate's
/// panic (lox's on a non-manifold edge) is an error, never a panic of the lab.
fn unadmitted_facts_never_panic<M: MeshTopology>() {
    let separate = M::separate_construction().expect("every peer builds apart from the checks");
    for (what, soup, _) in bad_soups() {
        let Ok(facts) = BuildFacts::new(&soup, 0) else {
            continue; // `check` refuses it: no facts to hand over
        };
        let built = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            separate.construction(&facts).and_then(|b| b.finish(&soup))
        }));
        assert!(built.is_ok(), "{} panicked on {what}", M::NAME);
    }
}

/// Admission, the timed construction and the finishing step in a row build what `from_soup`
/// builds, and admission refuses what `from_soup` refuses.
fn separate_construction_is_from_soup<M: MeshTopology>() {
    let separate = M::separate_construction().expect("every peer builds apart from the checks");
    for mesh in meshes::canonical() {
        let soup = &mesh.soup;
        let whole = M::from_soup(soup);
        let parts = separate
            .admit(soup)
            .and_then(|facts| separate.construction(&facts)?.finish(soup));
        match (whole, parts) {
            (Ok(a), Ok(b)) => {
                b.validate().unwrap();
                let counts = |m: &M| [m.num_vertices(), m.num_edges(), m.num_faces()];
                assert_eq!(counts(&a), counts(&b), "{} on {}", M::NAME, mesh.name);
            }
            (Err(a), Err(b)) => assert_eq!(a.kind(), b.kind(), "{} on {}", M::NAME, mesh.name),
            (a, b) => panic!(
                "{} on {}: from_soup {:?}, in parts {:?}",
                M::NAME,
                mesh.name,
                a.err(),
                b.err()
            ),
        }
    }
    for (what, soup, kind) in bad_soups() {
        let refused = separate.admit(&soup).err().map(|e| e.kind());
        assert_eq!(refused, Some(kind), "{} admitted {what}", M::NAME);
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

                #[test]
                fn unadmitted_facts_are_errors_not_panics() {
                    unadmitted_facts_never_panic::<$ty>();
                }

                #[test]
                fn admit_construct_finish_is_from_soup() {
                    separate_construction_is_from_soup::<$ty>();
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
