//! Each step on a small hand-made mesh with its problem, each checked by the consistency checks
//! on the output; and random meshes with every problem at once.

use super::*;
use crate::algorithms::checks::{self, FindingKind, Options};
use crate::io::RawSoup;
use crate::meshes;
use glam::DVec3;
use proptest::prelude::*;

/// The kinds of finding the repair removes.
const REPAIRED: [FindingKind; 5] = [
    FindingKind::DuplicateFace,
    FindingKind::NonManifoldEdge,
    FindingKind::NonManifoldVertex,
    FindingKind::InconsistentOrientation,
    FindingKind::UnusedVertex,
];

/// The kinds `topolab check` finds on `soup`, each once.
fn kinds(soup: &PolygonSoup) -> Vec<FindingKind> {
    let raw = RawSoup {
        soup: soup.clone(),
        ..RawSoup::default()
    };
    let mut kinds: Vec<FindingKind> = checks::check(&raw, &Options::default())
        .findings
        .iter()
        .map(|f| f.kind)
        .collect();
    kinds.dedup();
    kinds
}

/// Asserts that each face of `out` is the face `kept[j]` of `input` at the same positions,
/// as the same cycle in either direction (a repair moves no point and changes no face's shape).
fn same_geometry(input: &PolygonSoup, out: &PolygonSoup, kept: &[usize]) {
    assert_eq!(out.num_faces(), kept.len());
    for (j, &k) in kept.iter().enumerate() {
        let at = |s: &PolygonSoup, f: &[u32]| -> Vec<[u64; 3]> {
            f.iter()
                .map(|&v| s.positions[v as usize].to_array().map(f64::to_bits))
                .collect()
        };
        let (a, b) = (at(input, input.face(k)), at(out, out.face(j)));
        // The same cycle, in either direction, from any corner.
        let mut reversed = a.clone();
        reversed.reverse();
        let cycle =
            |c: &[[u64; 3]]| (0..c.len()).any(|r| b.iter().eq(c[r..].iter().chain(&c[..r])));
        let b = if cycle(&a) || cycle(&reversed) {
            a.clone()
        } else {
            b
        };
        assert_eq!(
            a, b,
            "output face {j} is not input face {k} at the same places"
        );
    }
}

/// Three triangles sharing the edge (0, 1): a book of three pages, a non-manifold edge.
fn book() -> PolygonSoup {
    PolygonSoup::from_polygons(
        vec![
            DVec3::ZERO,
            DVec3::X,
            DVec3::new(0.5, 1.0, 0.0),
            DVec3::new(0.5, -1.0, 0.0),
            DVec3::new(0.5, 0.0, 1.0),
        ],
        &[[0u32, 1, 2], [1, 0, 3], [0, 1, 4]],
    )
}

/// A Möbius strip of `n` quads (n >= 3): no orientation makes it consistent.
fn mobius(n: u32) -> PolygonSoup {
    let mut s = PolygonSoup::new();
    for i in 0..n {
        let t = i as f64 / n as f64 * std::f64::consts::TAU;
        let (c, w) = (DVec3::new(t.cos(), t.sin(), 0.0) * 3.0, (t / 2.0).cos());
        let up = DVec3::new(t.cos() * (t / 2.0).sin(), t.sin() * (t / 2.0).sin(), w);
        s.push_vertex(c + up);
        s.push_vertex(c - up);
    }
    for i in 0..n {
        let (a, b) = (2 * i, 2 * i + 1);
        // The last quad joins the first pair the other way round: the half twist.
        let (c, d) = if i + 1 == n {
            (1, 0)
        } else {
            (2 * i + 2, 2 * i + 3)
        };
        s.push_face(&[a, b, d, c]);
    }
    s
}

fn all() -> Vec<Step> {
    Step::ALL.to_vec()
}

#[test]
fn inconsistent_orientation_is_made_consistent_by_the_majority() {
    let sphere = meshes::sphere(6, 8);
    assert!(kinds(&sphere).is_empty());
    let flipped: Vec<usize> = (0..sphere.num_faces()).filter(|j| j % 5 == 0).collect();
    let mut faces: Vec<Vec<u32>> = sphere.faces().map(|f| f.to_vec()).collect();
    for &j in &flipped {
        faces[j].reverse();
    }
    let shuffled = PolygonSoup::from_polygons(sphere.positions.clone(), &faces);
    assert!(kinds(&shuffled).contains(&FindingKind::InconsistentOrientation));
    let r = repair(shuffled.clone(), &all());
    assert_eq!(kinds(&r.soup), [], "{:?}", r.log);
    // The minority was flipped back: the sphere as generated.
    assert_eq!(r.soup, sphere);
    assert_eq!(r.log.flipped_faces, flipped.len());
    assert_eq!(r.log.oriented_components, 1);
    // Without the step, the problem stays.
    let steps: Vec<Step> = all().into_iter().filter(|&s| s != Step::Orient).collect();
    let kept = repair(shuffled.clone(), &steps);
    assert_eq!(kept.soup, shuffled);
    assert_eq!(kinds(&kept.soup), [FindingKind::InconsistentOrientation]);
}

#[test]
fn duplicate_faces_are_dropped_keeping_the_first() {
    let mut soup = meshes::closed_tetrahedron();
    let first = soup.face(1).to_vec();
    // The same vertex set, reversed and rotated.
    soup.push_face(&[first[1], first[0], first[2]]);
    soup.push_face(&first);
    assert!(kinds(&soup).contains(&FindingKind::DuplicateFace));
    let r = repair(soup.clone(), &all());
    assert_eq!(r.log.duplicate_faces, [4, 5]);
    assert_eq!(r.soup, meshes::closed_tetrahedron());
    assert_eq!(kinds(&r.soup), []);
    let only = repair(soup.clone(), &[Step::DuplicateFaces]);
    assert_eq!(only.soup, meshes::closed_tetrahedron());
}

#[test]
fn a_non_manifold_edge_is_split_at_its_end_points() {
    let soup = book();
    assert!(kinds(&soup).contains(&FindingKind::NonManifoldEdge));
    let r = repair(soup.clone(), &all());
    assert_eq!(r.log.non_manifold_edges, 1);
    // Each end point: three pages, three fans (the edge is a cut): two new vertices each.
    assert_eq!(
        r.log.edge_splits,
        [Split { vertex: 0, fans: 3 }, Split { vertex: 1, fans: 3 }]
    );
    assert_eq!(r.log.new_vertices(), 4);
    assert_eq!(r.soup.num_vertices(), 9);
    same_geometry(&soup, &r.soup, &[0, 1, 2]);
    // What remains: the copies at one position, by design.
    assert_eq!(kinds(&r.soup), [FindingKind::DuplicateVertices]);
    // Splitting vertices alone leaves the edge's end points as they are.
    let vertices_only = repair(soup.clone(), &[Step::SplitVertices]);
    assert_eq!(vertices_only.soup, soup);
    assert!(kinds(&vertices_only.soup).contains(&FindingKind::NonManifoldEdge));
}

#[test]
fn a_fin_on_a_closed_surface_leaves_the_surface_closed() {
    // A fin on an edge of a closed tetrahedron: the two faces of the surface stay joined
    // around both end points, the fin gets vertices of its own.
    let mut soup = meshes::closed_tetrahedron();
    let (a, b) = (soup.face(0)[0], soup.face(0)[1]);
    let tip = soup.push_vertex(DVec3::new(5.0, 5.0, 5.0)).0;
    soup.push_face(&[a, b, tip]);
    let r = repair(soup.clone(), &all());
    assert_eq!(r.log.new_vertices(), 2);
    assert_eq!(kinds(&r.soup), [FindingKind::DuplicateVertices]);
    let check = checks::check(
        &RawSoup {
            soup: r.soup.clone(),
            ..RawSoup::default()
        },
        &Options::default(),
    );
    let mut closed: Vec<Option<u32>> = check
        .summary
        .components
        .iter()
        .map(|c| c.boundary_curves)
        .collect();
    closed.sort_unstable();
    assert_eq!(
        closed,
        [Some(0), Some(1)],
        "the tetrahedron closed, the fin a triangle"
    );
}

#[test]
fn a_non_manifold_vertex_gets_one_vertex_per_fan() {
    let soup = meshes::bowtie();
    assert_eq!(kinds(&soup), [FindingKind::NonManifoldVertex]);
    let r = repair(soup.clone(), &all());
    assert_eq!(r.log.vertex_splits, [Split { vertex: 0, fans: 2 }]);
    assert_eq!(r.soup.num_vertices(), 6);
    assert_eq!(r.soup.positions[5], soup.positions[0]);
    same_geometry(&soup, &r.soup, &[0, 1]);
    assert_eq!(kinds(&r.soup), [FindingKind::DuplicateVertices]);
    let edges_only = repair(soup.clone(), &[Step::SplitEdges]);
    assert_eq!(edges_only.soup, soup);
}

#[test]
fn unused_vertices_are_dropped_and_the_rest_keep_their_order() {
    let mut soup = meshes::open_tetrahedron();
    let positions = soup.positions.clone();
    soup.positions.insert(1, DVec3::splat(9.0));
    soup.positions.push(DVec3::splat(8.0));
    let faces: Vec<Vec<u32>> = soup
        .faces()
        .map(|f| f.iter().map(|&v| if v >= 1 { v + 1 } else { v }).collect())
        .collect();
    let soup = PolygonSoup::from_polygons(soup.positions.clone(), &faces);
    assert_eq!(kinds(&soup), [FindingKind::UnusedVertex]);
    let r = repair(soup.clone(), &all());
    assert_eq!(r.log.unused_vertices, 2);
    assert_eq!(r.soup.positions, positions);
    assert_eq!(r.soup, meshes::open_tetrahedron());
}

#[test]
fn a_mobius_strip_stays_non_orientable_and_untouched() {
    let strip = mobius(8);
    assert!(kinds(&strip).contains(&FindingKind::NonOrientable));
    let r = repair(strip.clone(), &all());
    assert_eq!(r.log.non_orientable, [0]);
    assert_eq!(r.log.flipped_faces, 0);
    assert_eq!(r.soup, strip);
    assert!(r.log.lines().iter().any(|l| l.contains("non-orientable")));
}

#[test]
fn a_clean_mesh_is_left_as_it_is() {
    for soup in [meshes::torus(8, 6), meshes::grid(4, 3, false)] {
        let r = repair(soup.clone(), &all());
        assert!(r.log.is_empty(), "{:?}", r.log);
        assert!(r.log.lines().is_empty());
        assert_eq!(r.soup, soup);
    }
}

#[test]
fn step_names_round_trip() {
    for s in Step::ALL {
        assert_eq!(Step::from_name(s.name()), Some(s));
    }
    assert_eq!(Step::from_name("nope"), None);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Random grid pieces (non-manifold and unused vertices by construction) with faces
    /// flipped, repeated, and fins glued on edges: the output has none of the problems the
    /// repair removes, and every face is still where it was.
    #[test]
    fn random_broken_meshes_come_out_clean(seed in any::<u64>(), flips in any::<u64>(), extra in 0usize..4) {
        let base = meshes::random_mesh(seed, meshes::RandomMeshParams::default());
        prop_assume!(base.num_faces() > 0);
        let mut faces: Vec<Vec<u32>> = base.faces().map(|f| f.to_vec()).collect();
        for (j, f) in faces.iter_mut().enumerate() {
            if flips >> (j % 64) & 1 == 1 {
                f.reverse();
            }
        }
        let mut positions = base.positions.clone();
        let n = faces.len();
        for k in 0..extra {
            let f = faces[(k * 7 + seed as usize % n) % n].clone();
            // A duplicate of a face, and a fin on its first edge.
            faces.push(f.iter().rev().copied().collect());
            positions.push(DVec3::new(k as f64, 0.5, 2.0));
            faces.push(vec![f[0], f[1], positions.len() as u32 - 1]);
        }
        let soup = PolygonSoup::from_polygons(positions, &faces);
        let r = repair(soup.clone(), &all());
        let left: Vec<FindingKind> = kinds(&r.soup).into_iter().filter(|k| REPAIRED.contains(k)).collect();
        prop_assert!(left.is_empty(), "{:?} left after {:?}", left, r.log);
        prop_assert!(r.log.non_orientable.is_empty());
        let kept: Vec<usize> = (0..soup.num_faces()).filter(|j| !r.log.duplicate_faces.contains(&(*j as u32))).collect();
        same_geometry(&soup, &r.soup, &kept);
        // What a structure that needs an oriented manifold asks for.
        let conn = r.soup.connectivity();
        prop_assert!(conn.is_ok(), "{:?}", conn.err());
        prop_assert!(conn.unwrap().check_vertex_fans(&r.soup).is_ok());
    }
}
