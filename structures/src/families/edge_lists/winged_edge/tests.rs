//! The winged-edge's own tests: the polygon-mesh lecture's example records, incremental
//! construction and removal, refusals and `validate`.

use super::*;
use crate::core::error::Error;
use crate::core::soup::PolygonSoup;
use crate::core::topology::MeshTopology;
use crate::meshes;
use crate::testing::conformance::compare;

fn ids(vs: &[u32]) -> Vec<VertexId> {
    vs.iter().map(|&v| VertexId(v)).collect()
}

/// The closed tetrahedron's four corners, without faces.
fn four_vertices() -> WingedEdge {
    let mut m = WingedEdge::new();
    for p in &meshes::closed_tetrahedron().positions {
        m.add_vertex(*p);
    }
    m
}

#[test]
fn records_match_the_lectures_example() {
    // The polygon-mesh lecture's P1 = (E5, E4, E1) and P2 = (E2, E4, E3) over V1..V4, 0-based.
    let soup = PolygonSoup::from_polygons(
        vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y],
        &[[0u32, 3, 1], [2, 1, 3]],
    );
    let m = WingedEdge::from_soup(&soup).unwrap();
    // Our edges by first appearance: e0 = E5, e1 = E4, e2 = E1, e3 = E2, e4 = E3.
    let (e, f) = (EdgeId, FaceId);
    // E4 = (4, 2, P1, P2, 5, 1, 2, 3).
    assert_eq!(
        m.edges[1],
        EdgeRecord {
            v1: VertexId(3),
            v2: VertexId(1),
            fccw: f(0),
            fcw: f(1),
            pccw: e(0),
            nccw: e(2),
            pcw: e(3),
            ncw: e(4),
        }
    );
    // E1 = (2, 1, P1, N, 4, 5, N, N).
    assert_eq!(
        m.edges[2],
        EdgeRecord {
            v1: VertexId(1),
            v2: VertexId(0),
            fccw: f(0),
            pccw: e(1),
            nccw: e(0),
            ..EdgeRecord::REMOVED
        }
    );
    m.validate().unwrap();
}

#[test]
fn faces_added_one_by_one_make_the_closed_tetrahedron() {
    let soup = meshes::closed_tetrahedron();
    let mut m = four_vertices();
    // (edges, boundary edges) after each face.
    let expected = [(3, 3), (5, 4), (6, 3), (6, 0)];
    for (j, face) in soup.faces().enumerate() {
        let added = m.add_face(&ids(face)).unwrap();
        assert_eq!(added, FaceId::new(j));
        m.validate()
            .unwrap_or_else(|e| panic!("after face {j}: {e}"));
        assert_eq!((m.num_edges(), m.num_boundary_edges()), expected[j]);
        // Every answer matches the oracle of the faces added so far.
        compare(&m, &soup.with_faces(|g| g <= j)).unwrap();
    }
}

#[test]
fn removing_faces_leaves_tombstones_that_compact_closes() {
    let soup = meshes::closed_tetrahedron();
    let mut m = WingedEdge::from_soup(&soup).unwrap();
    // Without the base it is the open tetrahedron.
    m.remove_face(FaceId(3)).unwrap();
    m.validate().unwrap();
    compare(&m, &meshes::open_tetrahedron()).unwrap();
    // Removing face 0 removes edge {0, 1}, its only edge without another face.
    m.remove_face(FaceId(0)).unwrap();
    m.validate().unwrap();
    assert!(!m.is_face_live(FaceId(0)));
    assert_eq!(
        (m.num_faces(), m.num_edges(), m.face_slots(), m.edge_slots()),
        (2, 5, 4, 6)
    );
    assert_eq!(m.live_faces().collect::<Vec<_>>(), [FaceId(1), FaceId(2)]);
    let err = m.remove_face(FaceId(0)).unwrap_err();
    assert_eq!(err.kind(), "unsupported");
    let renumbering = m.compact();
    m.validate().unwrap();
    assert_eq!((m.face_slots(), m.edge_slots()), (2, 5));
    assert_eq!(renumbering.face(FaceId(0)), None);
    assert_eq!(renumbering.face(FaceId(2)), Some(FaceId(1)));
    assert_eq!(renumbering.edge(EdgeId(0)), None);
    compare(&m, &soup.with_faces(|j| j == 1 || j == 2)).unwrap();
    // Removing every face leaves isolated vertices and no edges.
    m.remove_face(FaceId(0)).unwrap();
    m.remove_face(FaceId(1)).unwrap();
    m.validate().unwrap();
    assert_eq!((m.num_faces(), m.num_edges()), (0, 0));
    assert!(m.av.iter().all(|e| !e.is_valid()));
}

#[test]
fn a_removed_face_can_be_added_again() {
    let mut m = WingedEdge::from_soup(&meshes::closed_tetrahedron()).unwrap();
    m.remove_face(FaceId(1)).unwrap();
    assert_eq!(m.add_face(&ids(&[1, 2, 3])).unwrap(), FaceId(4));
    m.validate().unwrap();
    assert_eq!((m.num_faces(), m.num_boundary_edges()), (4, 0));
}

#[test]
fn refused_faces_leave_the_structure_unchanged() {
    let mut m = four_vertices();
    m.add_face(&ids(&[0, 1, 3])).unwrap();
    let before = m.clone();
    let cases: [(&[u32], &str); 5] = [
        (&[0, 1], "too-few-corners"),
        (&[0, 1, 7], "index-out-of-range"),
        (&[0, 2, 0], "repeated-vertex"),
        // Runs 0 -> 1 like face 0.
        (&[0, 1, 2], "inconsistent-orientation"),
        (&[1, 0, 2], "ok"),
    ];
    for (face, kind) in cases {
        match m.add_face(&ids(face)) {
            Err(e) => {
                assert_eq!(e.kind(), kind, "{face:?}: {e}");
                assert_eq!(m.edges, before.edges);
                assert_eq!(m.af, before.af);
                m.validate().unwrap();
            }
            Ok(_) => assert_eq!(kind, "ok", "{face:?} was accepted"),
        }
    }
    // Edge {0, 1} now has two faces: a third is refused.
    let err = m.add_face(&ids(&[0, 1, 2])).unwrap_err();
    assert_eq!(err.kind(), "non-manifold-edge", "{err}");
}

/// The bowtie's vertices with its two triangles, which meet at v0 only: two fans there.
fn two_fans_at_v0() -> WingedEdge {
    let mut m = WingedEdge::new();
    for p in &meshes::bowtie().positions {
        m.add_vertex(*p);
    }
    m.add_face(&ids(&[0, 2, 1])).unwrap();
    m.add_face(&ids(&[0, 3, 4])).unwrap();
    m
}

/// A compacted copy (dense ids), to compare with an oracle.
fn compacted(m: &WingedEdge) -> WingedEdge {
    let mut dense = m.clone();
    dense.compact();
    dense
}

#[test]
fn a_vertex_with_two_fans_is_reported_until_a_face_joins_them() {
    let mut m = two_fans_at_v0();
    let err = m.validate().unwrap_err();
    assert!(
        matches!(err, Error::NonManifoldVertex { vertex: 0, fans: 2 }),
        "{err}"
    );
    // The face between the two fans uses edges of both: the index finds them.
    m.add_face(&ids(&[0, 1, 3])).unwrap();
    m.validate().unwrap();
    let mut faces = Vec::new();
    m.vertex_faces(VertexId(0), |f| faces.push(f.0));
    faces.sort_unstable();
    assert_eq!(faces, [0, 1, 2]);
    assert_eq!(m.num_edges(), 7);
}

/// `validate()` in the middle of incremental work: fine, or a vertex with several fans
/// (which add_face and remove_face may leave), never a broken wing. When fine, every answer
/// matches the oracle of the live faces.
fn check_intermediate(m: &WingedEdge, soup: &PolygonSoup, live: &[bool], step: &str) {
    match m.validate() {
        Ok(()) => {
            compare(&compacted(m), &soup.with_faces(|j| live[j]))
                .unwrap_or_else(|e| panic!("{step}: {e}"));
        }
        Err(Error::NonManifoldVertex { .. }) => {}
        Err(e) => panic!("{step}: {e}"),
    }
}

#[test]
fn faces_added_and_removed_in_random_orders_keep_every_invariant() {
    use rand::seq::SliceRandom;
    use rand::SeedableRng;
    for seed in 0..4u64 {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let mut order: Vec<u32> = (0..meshes::torus(5, 4).num_faces() as u32).collect();
        order.shuffle(&mut rng);
        // Face j of `soup` is the j-th face added.
        let soup = meshes::torus(5, 4).reorder_faces(&order);
        let mut m = WingedEdge::new();
        soup.positions.iter().for_each(|&p| {
            m.add_vertex(p);
        });
        let mut live = vec![false; soup.num_faces()];
        for (j, face) in soup.faces().enumerate() {
            m.add_face(&ids(face)).unwrap();
            live[j] = true;
            check_intermediate(&m, &soup, &live, &format!("seed {seed}, add {j}"));
        }
        m.validate().unwrap();
        compare(&m, &soup).unwrap();
        let mut removal: Vec<usize> = (0..soup.num_faces()).collect();
        removal.shuffle(&mut rng);
        for j in removal {
            m.remove_face(FaceId::new(j)).unwrap();
            live[j] = false;
            check_intermediate(&m, &soup, &live, &format!("seed {seed}, remove {j}"));
        }
        assert_eq!((m.num_faces(), m.num_edges()), (0, 0));
        assert!(m.av.iter().all(|e| !e.is_valid()));
    }
}

#[test]
fn validate_reports_a_wing_that_does_not_point_back() {
    let mut m = WingedEdge::from_soup(&meshes::closed_tetrahedron()).unwrap();
    m.edges[0].nccw = m.edges[0].pccw;
    let err = m.validate().unwrap_err();
    assert_eq!(err.kind(), "invariant", "{err}");
    let mut m = WingedEdge::from_soup(&meshes::open_tetrahedron()).unwrap();
    m.av[3] = EdgeId(0); // edge 0 joins v0 and v1
    assert_eq!(m.validate().unwrap_err().kind(), "invariant");
    let mut m = WingedEdge::from_soup(&meshes::open_tetrahedron()).unwrap();
    m.live_faces = 4;
    assert_eq!(m.validate().unwrap_err().kind(), "invariant");
}

#[test]
fn heap_bytes_are_the_documented_bytes_per_element() {
    let soup = meshes::torus(6, 5);
    let m = WingedEdge::from_soup(&soup).unwrap();
    let (n0, n1, n2) = (m.num_vertices(), m.num_edges(), m.num_faces());
    assert_eq!(m.heap_bytes(), 28 * n0 + 32 * n1 + 4 * n2);
    // 66 bytes per triangle on a closed triangle mesh, as the module docs say.
    assert_eq!(m.heap_bytes(), 66 * n2);
}

#[test]
fn explain_prints_the_hull_lectures_fields_for_the_open_tetrahedron() {
    let m = WingedEdge::from_soup(&meshes::open_tetrahedron()).unwrap();
    let mut text = String::new();
    m.explain(&mut text).unwrap();
    for field in [
        "v1", "v2", "fccw", "fcw", "pccw", "nccw", "pcw", "ncw", "av = ", "af = ",
    ] {
        assert!(text.contains(field), "{field} missing:\n{text}");
    }
    // Edge 0 runs v0 -> v1 in face 0 = (0, 1, 3), on the boundary: no cw side.
    let row = text
        .lines()
        .find(|l| l.trim_start().starts_with("e0 "))
        .unwrap();
    let fields: Vec<&str> = row.split_whitespace().collect();
    assert_eq!(fields, ["e0", "v0", "v1", "f0", "-", "e2", "e1", "-", "-"]);
}

#[test]
fn a_vertex_that_loses_one_fan_keeps_an_edge_of_its_other_fan() {
    let mut m = two_fans_at_v0();
    // av(0) is an edge of face 0, whose two edges at v0 go with it: v0's edge handle must
    // come from the other fan (from v0's ring in the index, no search).
    assert!(m.edge(m.av[0]).fccw == FaceId(0));
    m.remove_face(FaceId(0)).unwrap();
    m.validate().unwrap();
    let mut faces = Vec::new();
    m.vertex_faces(VertexId(0), |f| faces.push(f.0));
    assert_eq!(faces, [1]);
    let left = PolygonSoup::from_polygons(meshes::bowtie().positions, &[[0u32, 3, 4]]);
    compare(&compacted(&m), &left).unwrap();
}

/// The directed sides a → b of the faces `region` of `soup` whose reverse is not a side of
/// another face of `region`: the border the cone goes over.
fn border_sides(soup: &PolygonSoup, region: &[usize]) -> Vec<(u32, u32)> {
    let sides: Vec<(u32, u32)> = region
        .iter()
        .flat_map(|&f| {
            let c = soup.face(f);
            (0..c.len()).map(move |i| (c[i], c[(i + 1) % c.len()]))
        })
        .collect();
    let mut border: Vec<(u32, u32)> = sides
        .iter()
        .copied()
        .filter(|&(a, b)| !sides.contains(&(b, a)))
        .collect();
    border.sort_unstable();
    border
}

/// The torus with one more vertex, the apex, without edges.
fn torus_and_apex() -> (PolygonSoup, VertexId) {
    let mut soup = meshes::torus(6, 5);
    let apex = soup.push_vertex(DVec3::new(0.0, 0.0, 3.0));
    (soup, apex)
}

#[test]
fn a_cone_replaces_a_disk_of_faces_in_one_step() {
    let (soup, apex) = torus_and_apex();
    // The faces around two neighbouring vertices: a disk with two inner vertices.
    let (v, w) = (7u32, 8u32);
    let region: Vec<usize> = (0..soup.num_faces())
        .filter(|&f| soup.face(f).contains(&v) || soup.face(f).contains(&w))
        .collect();
    for with_index in [false, true] {
        let mut m = if with_index {
            // Built by add_face: the index exists and the cone must keep it right.
            let mut m = WingedEdge::new();
            soup.positions.iter().for_each(|&p| {
                m.add_vertex(p);
            });
            for face in soup.faces() {
                m.add_face(&ids(face)).unwrap();
            }
            m
        } else {
            WingedEdge::from_soup(&soup).unwrap()
        };
        let faces: Vec<FaceId> = region.iter().map(|&f| FaceId::new(f)).collect();
        let mut horizon = Vec::new();
        m.replace_by_cone(&faces, apex, &mut horizon).unwrap();
        m.validate().unwrap();
        // The horizon is the region's border, as one cycle, each edge with its faces.
        let k = horizon.len();
        for (i, h) in horizon.iter().enumerate() {
            assert_eq!(h.b, horizon[(i + 1) % k].a, "cycle at {i}");
            assert!(faces.contains(&h.removed) && !faces.contains(&h.kept));
            let ends = m.edge_vertices(h.edge);
            assert!(ends == [h.a, h.b] || ends == [h.b, h.a], "{h:?}: {ends:?}");
        }
        let mut got: Vec<(u32, u32)> = horizon.iter().map(|h| (h.a.0, h.b.0)).collect();
        got.sort_unstable();
        assert_eq!(got, border_sides(&soup, &region));
        for x in [v, w] {
            assert!(
                !m.av[x as usize].is_valid(),
                "inner vertex v{x} keeps an edge"
            );
        }
        // Every answer matches the oracle of the kept faces and the cone (compaction puts
        // the cone's new slots after the kept faces, in horizon order).
        let mut expected = soup.with_faces(|f| !region.contains(&f));
        for h in &horizon {
            expected.push_face(&[h.a.0, h.b.0, apex.0]);
        }
        compare(&compacted(&m), &expected).unwrap();
        // A second cone reuses the slots the first one freed.
        let (slots, edge_slots) = (m.face_slots(), m.edge_slots());
        let apex2 = m.add_vertex(DVec3::new(0.0, 0.0, -3.0));
        let cone: Vec<FaceId> = horizon.iter().map(|h| h.created).take(2).collect();
        let mut second = Vec::new();
        m.replace_by_cone(&cone, apex2, &mut second).unwrap();
        m.validate().unwrap();
        assert_eq!((m.face_slots(), m.edge_slots()), (slots, edge_slots));
        assert!(second.iter().all(|h| region.contains(&h.created.index())));
        if with_index {
            // The index still finds every edge: a removed face can be added back.
            let f = second[0].created;
            let corners = {
                let mut c = Vec::new();
                m.face_vertices(f, |x| c.push(x));
                c
            };
            m.remove_face(f).unwrap();
            m.add_face(&corners).unwrap();
            m.validate().unwrap();
        }
    }
}

#[test]
fn a_region_that_is_not_one_disk_is_refused_and_nothing_changes() {
    let (soup, apex) = torus_and_apex();
    let nv = 5;
    let f = FaceId::new;
    // Faces 0 .. 2nv: the band of cells (0, j) around the tube, an annulus.
    let band: Vec<FaceId> = (0..2 * nv).map(f).collect();
    let cases: Vec<(&str, Vec<FaceId>, VertexId)> = vec![
        ("empty", vec![], apex),
        ("named twice", vec![f(0), f(1), f(0)], apex),
        ("no such face", vec![f(999)], apex),
        ("the apex has edges", vec![f(0)], VertexId(3)),
        ("no such apex", vec![f(0)], VertexId(9999)),
        ("two pieces", vec![f(0), f(20)], apex),
        ("an annulus", band.clone(), apex),
        // The band without one triangle: a strip whose border passes v(0, 0) twice.
        ("pinched", band[1..].to_vec(), apex),
        (
            "the whole mesh",
            (0..soup.num_faces()).map(f).collect(),
            apex,
        ),
    ];
    let mut m = WingedEdge::from_soup(&soup).unwrap();
    let before = m.clone();
    let mut horizon = Vec::new();
    for (what, region, apex) in cases {
        let err = m.replace_by_cone(&region, apex, &mut horizon).unwrap_err();
        assert_eq!(err.kind(), "unsupported", "{what}: {err}");
        assert_eq!(
            (&m.edges, &m.af, &m.av),
            (&before.edges, &before.af, &before.av)
        );
        m.validate().unwrap();
    }
    // An open mesh: a region on its boundary has a border edge without a face outside.
    let mut grid = meshes::grid(3, 3, true);
    let apex = grid.push_vertex(DVec3::Z);
    let mut m = WingedEdge::from_soup(&grid).unwrap();
    let err = m.replace_by_cone(&[f(0)], apex, &mut horizon).unwrap_err();
    assert_eq!(err.kind(), "unsupported", "{err}");
}

#[test]
fn removing_faces_splits_a_fan_and_a_removed_fan_hands_av_to_the_other() {
    // Vertex 4, the centre of the 2 x 2 triangulated grid, has the closed fan
    // f0 f1 f4 f7 f6 f3; removing f1 and f6 leaves the fans {f4, f7} and {f3, f0}.
    let soup = meshes::grid(2, 2, true);
    let centre = VertexId(4);
    let mut m = WingedEdge::from_soup(&soup).unwrap();
    m.remove_face(FaceId(1)).unwrap();
    m.remove_face(FaceId(6)).unwrap();
    let err = m.validate().unwrap_err();
    assert!(
        matches!(err, Error::NonManifoldVertex { vertex: 4, fans: 2 }),
        "{err}"
    );
    // Remove the whole fan av(4) belongs to: av(4) must move to an edge of the other fan,
    // which no removed face has.
    let mut fan = Vec::new();
    m.walk_fan(centre, m.av[4], |_| {}, |f| fan.push(f.0));
    fan.sort_unstable();
    let other: Vec<u32> = [0u32, 3, 4, 7]
        .into_iter()
        .filter(|f| !fan.contains(f))
        .collect();
    assert_eq!((fan.len(), other.len()), (2, 2), "{fan:?}");
    for &f in &fan {
        m.remove_face(FaceId(f)).unwrap();
    }
    m.validate().unwrap();
    let mut faces = Vec::new();
    m.vertex_faces(centre, |f| faces.push(f.0));
    faces.sort_unstable();
    assert_eq!(faces, other);
    let live: Vec<bool> = (0..8u32)
        .map(|f| ![1, 6].contains(&f) && !fan.contains(&f))
        .collect();
    compare(&compacted(&m), &soup.with_faces(|j| live[j])).unwrap();
}
