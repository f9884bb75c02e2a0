//! `topolab explain NAME --op OP`: a refusal names the test that failed and the element that
//! shows it (docs/editing.md, "Why an edit is refused"). Each element is checked against a
//! computation of this file's own, from the mesh's face list (rings, third corners, links with
//! the boundary coned off to ω, fans), not against the program's code; every structure that
//! refuses an edit must name the same element.

use std::collections::BTreeSet;
use topolab::commands::explain_edit::{self, Asked, Counting};
use topolab_harness::teaching::edits::refusals::new_face_witness;
use topolab_structures::meshes::canonical_by_name;
use topolab_structures::{
    EditOp, Error, IndexHalfEdge, MeshEdit, MeshTopology, PolygonSoup, Refusal, VertexId,
};
// The structures that offer the topological edits these tests refuse or count: explicit
// storage (`[moves]`) offers none of them.
use topolab_structures::registry::editable_names;

/// ω, the vertex the boundary is coned off to, among this file's link vertices.
const OMEGA: u32 = u32::MAX;

/// `explain NAME --op OP` on `mesh`: the text, or the refusal's message.
fn explain(name: &str, mesh: &str, op: EditOp, asked: &Asked) -> Result<String, String> {
    explain_edit::run(name, Some(mesh), op, asked, &Counting::default()).map_err(|f| f.message)
}

fn faces(mesh: &str) -> Vec<Vec<u32>> {
    let soup = canonical_by_name(mesh).expect("a canonical mesh").soup;
    soup.faces().map(<[u32]>::to_vec).collect()
}

/// The directed sides of `faces`.
fn sides(faces: &[Vec<u32>]) -> BTreeSet<(u32, u32)> {
    faces
        .iter()
        .flat_map(|f| (0..f.len()).map(move |i| (f[i], f[(i + 1) % f.len()])))
        .collect()
}

fn ring(faces: &[Vec<u32>], v: u32) -> BTreeSet<u32> {
    sides(faces)
        .into_iter()
        .filter_map(|(a, b)| (a == v).then_some(b).or((b == v).then_some(a)))
        .collect()
}

/// The third corner of the triangle running a → b.
fn third(faces: &[Vec<u32>], a: u32, b: u32) -> Option<u32> {
    faces.iter().find_map(|f| {
        (0..3)
            .find(|&i| f[i] == a && f[(i + 1) % 3] == b)
            .map(|i| f[(i + 2) % 3])
    })
}

fn is_boundary(faces: &[Vec<u32>], a: u32, b: u32) -> bool {
    let s = sides(faces);
    s.contains(&(a, b)) != s.contains(&(b, a))
}

type Link = (BTreeSet<u32>, BTreeSet<(u32, u32)>);

fn pair(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// Lk(v) with the boundary coned off to ω.
fn link(faces: &[Vec<u32>], v: u32) -> Link {
    let (mut vs, mut es) = (BTreeSet::new(), BTreeSet::new());
    for f in faces.iter().filter(|f| f.contains(&v)) {
        let far: Vec<u32> = f.iter().copied().filter(|&w| w != v).collect();
        vs.extend(far.iter().copied());
        es.insert(pair(far[0], far[1]));
    }
    for w in ring(faces, v) {
        if is_boundary(faces, v, w) {
            vs.extend([w, OMEGA]);
            es.insert(pair(w, OMEGA));
        }
    }
    (vs, es)
}

/// What Lk(a) ∩ Lk(b) has beyond Lk(ab), in the words `explain` uses ("vertex v5",
/// "edge v2 - v3", ω as "ω").
fn violations(faces: &[Vec<u32>], a: u32, b: u32) -> Vec<String> {
    let name = |x: u32| {
        if x == OMEGA {
            "ω".to_string()
        } else {
            format!("v{x}")
        }
    };
    let ((va, ea), (vb, eb)) = (link(faces, a), link(faces, b));
    let mut lab: BTreeSet<u32> = [third(faces, a, b), third(faces, b, a)]
        .into_iter()
        .flatten()
        .collect();
    if is_boundary(faces, a, b) {
        lab.insert(OMEGA);
    }
    let mut out: Vec<String> = va
        .intersection(&vb)
        .filter(|x| !lab.contains(x))
        .map(|&x| format!("vertex {}", name(x)))
        .collect();
    out.extend(
        ea.intersection(&eb)
            .map(|&(x, y)| format!("edge {} - {}", name(x), name(y))),
    );
    out
}

/// The ends of edge `e` as the text names them, "edge E (vA - vB)": the edge's numbering is
/// the program's (the index half-edge's order of first appearance), what is checked here is
/// what it says of those ends.
fn ends(text: &str, e: u32) -> (u32, u32) {
    let key = format!("edge {e} (v");
    let at = text.find(&key).unwrap_or_else(|| panic!("{key} in {text}")) + key.len();
    let rest = &text[at..];
    let close = rest.find(')').expect("a closing parenthesis");
    let (a, b) = rest[..close].split_once(" - v").expect("two ends");
    (
        a.parse().expect("a vertex id"),
        b.parse().expect("a vertex id"),
    )
}

/// Every edge of `mesh` collapsed on `name`: checks each refusal's test and element against
/// this file's rings and links, and returns the refused edges with the test named.
fn check_collapses(name: &str, mesh: &str) -> Vec<(u32, &'static str)> {
    let fs = faces(mesh);
    let n_edges = sides(&fs)
        .into_iter()
        .map(|(a, b)| pair(a, b))
        .collect::<BTreeSet<_>>()
        .len() as u32;
    let mut refused = Vec::new();
    for e in 0..n_edges {
        let (text, failed) = match explain(name, mesh, EditOp::CollapseEdge, &Asked::edge(e)) {
            Ok(text) => (text, false),
            Err(message) => (message, true),
        };
        let (a, b) = ends(&text, e);
        let (vl, vr) = (third(&fs, a, b), third(&fs, b, a));
        let shared: Vec<u32> = ring(&fs, a)
            .intersection(&ring(&fs, b))
            .copied()
            .filter(|&w| Some(w) != vl && Some(w) != vr)
            .collect();
        let tetrahedron = match (vl, vr) {
            (Some(l), Some(r)) => {
                ring(&fs, l).contains(&r) && ring(&fs, l).len() == 3 && ring(&fs, r).len() == 3
            }
            _ => false,
        };
        let extra = violations(&fs, a, b);
        let at = format!("{name} {mesh} edge {e} (v{a} - v{b}): {text}");
        if !failed {
            assert!(shared.is_empty() && !tetrahedron, "{at}");
            continue;
        }
        let test = if text.contains("the link condition in its vertex-ring form fails") {
            let names: Vec<String> = shared.iter().map(|w| format!("v{w}")).collect();
            assert!(!shared.is_empty(), "{at}");
            assert!(
                text.contains(&format!(
                    "share {} besides the third corners",
                    names.join(" and ")
                )),
                "{at}"
            );
            assert!(
                !extra.is_empty(),
                "the full form fails where the ring form does: {at}"
            );
            "vertex-ring"
        } else if text.contains("OpenMesh's tetrahedron test fails") {
            let (l, r) = (vl.expect("vl"), vr.expect("vr"));
            assert!(tetrahedron, "{at}");
            assert!(
                text.contains(&format!(
                    "vl = v{l} and vr = v{r} are neighbours, of valences {} and {}",
                    ring(&fs, l).len(),
                    ring(&fs, r).len()
                )),
                "{at}"
            );
            assert!(
                shared.is_empty() && text.contains("vertex-ring form passes"),
                "{at}"
            );
            "tetrahedron"
        } else if text.contains("pmp-library's") {
            let on_boundary = |x: u32| ring(&fs, x).iter().any(|&w| is_boundary(&fs, x, w));
            if text.contains("\"a triangle with two boundary edges\" fails") {
                let x = number_after(&text, &format!("the triangle (v{a}, v{b}, v"));
                assert!(
                    is_boundary(&fs, b, x) && is_boundary(&fs, x, a),
                    "v{x}: {at}"
                );
            } else if text.contains("\"an interior edge between boundary vertices\" fails") {
                assert!(
                    on_boundary(a) && on_boundary(b) && !is_boundary(&fs, a, b),
                    "{at}"
                );
            }
            assert!(
                !extra.is_empty(),
                "the full form fails where a boundary rule does: {at}"
            );
            "boundary"
        } else {
            panic!("no test named: {at}");
        };
        if extra.is_empty() {
            assert!(
                text.contains("the full link condition (Dey et al.) holds"),
                "{at}"
            );
        } else {
            assert!(
                text.contains("the full link condition (Dey et al.) fails"),
                "{at}"
            );
            for x in &extra {
                assert!(text.contains(x.as_str()), "{x}: {at}");
            }
        }
        refused.push((e, test));
    }
    refused
}

#[test]
fn a_refused_collapse_names_its_test_and_element_on_every_structure() {
    for name in editable_names() {
        // The open tetrahedron of the CHE thesis chapter's Figure 4.10: its three boundary
        // edges fail the vertex-ring form (each pair of boundary vertices shares the third
        // one), its three edges to the apex OpenMesh's tetrahedron test (docs/editing.md).
        let open = check_collapses(name, "open-tetrahedron");
        let kinds: BTreeSet<&str> = open.iter().map(|&(_, t)| t).collect();
        assert_eq!(open.len(), 6, "{name}: {open:?}");
        assert_eq!(
            kinds,
            BTreeSet::from(["vertex-ring", "tetrahedron"]),
            "{name}"
        );
        // The closed tetrahedron: every collapse passes the vertex-ring form and fails the
        // full link condition by the edge vl - vr (checked in `check_collapses`).
        let closed = check_collapses(name, "closed-tetrahedron");
        assert_eq!(closed.len(), 6, "{name}: {closed:?}");
        assert!(
            closed.iter().all(|&(_, t)| t == "tetrahedron"),
            "{name}: {closed:?}"
        );
        // The canonical torus: closed, so only the vertex-ring form and the tetrahedron test
        // can refuse, and `check_collapses` holds each edge to them.
        let torus = check_collapses(name, "torus");
        assert!(
            torus.iter().any(|&(e, t)| e == 1 && t == "vertex-ring"),
            "{name}: {torus:?}"
        );
        // pmp-library's boundary rules: the single triangle's every edge has a triangle with
        // two boundary edges; a strip's interior edges join two boundary vertices.
        let mut boundary = 0;
        for mesh in ["single-triangle", "triangle-strip", "grid"] {
            let refused = check_collapses(name, mesh);
            boundary += refused.iter().filter(|&&(_, t)| t == "boundary").count();
        }
        assert!(boundary > 0, "{name}: no boundary rule named");
    }
}

#[test]
fn the_closed_tetrahedron_fails_the_full_link_condition_by_an_edge() {
    // Lk(v0) ∩ Lk(v1) of the closed tetrahedron holds the edge between the two other
    // vertices; Lk(v0v1) has no edge: the full form fails where the vertex-ring form passes.
    let fs = faces("closed-tetrahedron");
    let message = explain(
        "index-half-edge",
        "closed-tetrahedron",
        EditOp::CollapseEdge,
        &Asked::edge(0),
    )
    .expect_err("every collapse of the closed tetrahedron is refused");
    let (a, b) = ends(&message, 0);
    let others: Vec<u32> = (0..4).filter(|&x| x != a && x != b).collect();
    assert_eq!(
        violations(&fs, a, b),
        vec![format!("edge v{} - v{}", others[0], others[1])]
    );
    assert!(
        message.contains(&format!(
            "fails: Lk(v{a}) ∩ Lk(v{b}) has edge v{} - v{}",
            others[0], others[1]
        )),
        "{message}"
    );
    assert!(
        !message.contains("it is not the link condition"),
        "{message}"
    );
}

/// The fans of `v` among `faces`: faces around it joined where they share a side at it.
fn fans(faces: &[Vec<u32>], v: u32) -> usize {
    let around: Vec<&Vec<u32>> = faces.iter().filter(|f| f.contains(&v)).collect();
    let mut parent: Vec<usize> = (0..around.len()).collect();
    fn root(p: &mut [usize], mut x: usize) -> usize {
        while p[x] != x {
            x = p[x];
        }
        x
    }
    let at_v = |f: &Vec<u32>| {
        let k = f.len();
        let i = f.iter().position(|&w| w == v).expect("a corner");
        [f[(i + 1) % k], f[(i + k - 1) % k]]
    };
    for i in 0..around.len() {
        for j in 0..i {
            if at_v(around[i]).iter().any(|w| at_v(around[j]).contains(w)) {
                let (x, y) = (root(&mut parent, i), root(&mut parent, j));
                parent[x] = y;
            }
        }
    }
    (0..around.len())
        .filter(|&i| root(&mut parent, i) == i)
        .count()
}

/// The number after `key` in `text`.
fn number_after(text: &str, key: &str) -> u32 {
    let at = text.find(key).unwrap_or_else(|| panic!("{key} in {text}")) + key.len();
    let digits: String = text[at..]
        .chars()
        .take_while(char::is_ascii_digit)
        .collect();
    digits.parse().expect("a number")
}

#[test]
fn several_fans_names_the_vertex_of_two_fans() {
    // Deleting face 3 of the grid leaves one of its corners with two fans.
    let mut left = faces("grid");
    let gone = left.remove(3);
    for name in editable_names() {
        let Err(message) = explain(
            name,
            "grid",
            EditOp::DeleteFace,
            &Asked {
                face: Some(3),
                ..Asked::default()
            },
        ) else {
            panic!("{name}: deleting face 3 of the grid is refused");
        };
        assert!(
            message.contains(&Refusal::NonManifoldVertex.to_string()),
            "{name}: {message}"
        );
        let v = number_after(&message, "several fans: the faces around v");
        assert!(
            gone.contains(&v),
            "{name}: v{v} is a corner of {gone:?}: {message}"
        );
        let counted = fans(&left, v);
        assert!(counted > 1, "{name}: v{v}: {message}");
        assert!(
            message.contains(&format!("would form {counted} fans")),
            "{name}: {message}"
        );
    }
}

#[test]
fn a_non_manifold_edge_is_named_by_its_vertices() {
    // Face (0, 1, 2) on the open tetrahedron runs each of its sides the way a face of the
    // mesh already does.
    let fs = faces("open-tetrahedron");
    let asked = Asked {
        vertices: vec![0, 1, 2],
        ..Asked::default()
    };
    for name in editable_names() {
        let message = explain(name, "open-tetrahedron", EditOp::AddFace, &asked)
            .expect_err("a second face on the same sides");
        let a = number_after(&message, "non-manifold edge: edge v");
        let b = number_after(&message, &format!("non-manifold edge: edge v{a} - v"));
        let new = [(0, 1), (1, 2), (2, 0)];
        assert!(
            new.contains(&(a, b)) && sides(&fs).contains(&(a, b)),
            "{name}: {message}"
        );
    }
}

/// The polygon that deleting the edge a - b merges: the face running a → b from b round to
/// a, then the face running b → a strictly between a and b.
fn merged(faces: &[Vec<u32>], a: u32, b: u32) -> Vec<u32> {
    let run = |x: u32, y: u32| {
        faces
            .iter()
            .find_map(|f| {
                let k = f.len();
                (0..k)
                    .find(|&i| f[i] == x && f[(i + 1) % k] == y)
                    .map(|i| (f, i))
            })
            .expect("an interior edge")
    };
    let ((f1, i1), (f2, i2)) = (run(a, b), run(b, a));
    let mut out: Vec<u32> = (1..=f1.len()).map(|t| f1[(i1 + t) % f1.len()]).collect();
    out.extend((2..f2.len()).map(|t| f2[(i2 + t) % f2.len()]));
    out
}

#[test]
fn a_merged_polygon_that_repeats_a_corner_is_a_repeated_corner() {
    // The qt.obj: a quad and a triangle on two of its sides, so vertex 3 has valence 2
    // and deleting the edge 3 - 0 merges them into (0, 1, 2, 3, 2): four distinct corners,
    // corner 2 twice, not "fewer than three".
    let dir = std::env::temp_dir().join(format!("topolab-refusals-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a scratch folder");
    let path = dir.join("qt.obj");
    std::fs::write(
        &path,
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nf 1 4 3\n",
    )
    .expect("written");
    let fs = vec![vec![0, 1, 2, 3], vec![0, 3, 2]];
    let mesh = path.to_str().expect("a UTF-8 path");
    let mut explained = 0;
    for name in editable_names() {
        let Err(message) = explain(name, mesh, EditOp::DeleteEdge, &Asked::edge(3)) else {
            panic!("{name}: the deletion of edge 3 succeeded");
        };
        if message.contains("not offer") {
            continue;
        }
        explained += 1;
        let (a, b) = ends(&message, 3);
        let polygon = merged(&fs, a, b);
        let distinct: BTreeSet<u32> = polygon.iter().copied().collect();
        let twice: Vec<u32> = distinct
            .iter()
            .copied()
            .filter(|&v| polygon.iter().filter(|&&w| w == v).count() == 2)
            .collect();
        assert_eq!(polygon, vec![0, 1, 2, 3, 2], "the issue's polygon");
        let shown: Vec<String> = polygon.iter().map(u32::to_string).collect();
        assert!(
            message.contains(&format!(
                "repeated corner: the merged polygon ({}) has {} distinct corners but corner {} twice",
                shown.join(", "),
                distinct.len(),
                twice[0]
            )),
            "{name}: {message}"
        );
        assert!(!message.contains("too few corners:"), "{name}: {message}");
    }
    assert!(explained > 0, "some structure deletes edges");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_weld_of_two_corners_of_a_face_is_a_repeated_corner() {
    // Every two vertices of the open tetrahedron share a face: welding v1 into v0 would give
    // that face v0 twice.
    let fs = faces("open-tetrahedron");
    let face = fs
        .iter()
        .find(|f| f.contains(&0) && f.contains(&1))
        .expect("a face on v0 and v1");
    let welded: Vec<u32> = face.iter().map(|&v| if v == 1 { 0 } else { v }).collect();
    let show = |c: &[u32]| c.iter().map(u32::to_string).collect::<Vec<_>>().join(", ");
    let expected = format!(
        "repeated corner: the face ({}) with v1 welded into v0, ({}), has 2 distinct corners but corner 0 twice",
        show(face),
        show(&welded)
    );
    let asked = Asked {
        vertices: vec![0, 1],
        ..Asked::default()
    };
    let mut explained = 0;
    for name in editable_names() {
        let Err(message) = explain(name, "open-tetrahedron", EditOp::WeldVertices, &asked) else {
            panic!("{name}: the weld succeeded");
        };
        if message.contains("not offer") {
            continue;
        }
        explained += 1;
        assert!(message.contains(&expected), "{name}: {message}");
    }
    assert!(explained > 0, "some structure welds vertices");
}

#[test]
fn a_face_of_two_corners_is_too_few_corners_and_one_of_a_corner_twice_a_repeated_corner() {
    // The command line asks for three corners at least; the call takes any, so the witness of
    // a new face is asked directly, on what the index half-edge refuses.
    let soup: PolygonSoup = canonical_by_name("open-tetrahedron")
        .expect("canonical")
        .soup;
    for corners in [vec![0, 1], vec![0, 1, 1]] {
        let mut m = IndexHalfEdge::from_soup(&soup).expect("builds");
        let ids: Vec<VertexId> = corners.iter().copied().map(VertexId).collect();
        let reason = match m.add_face(&ids) {
            Err(Error::EditRefused { reason, .. }) => reason,
            other => panic!("{corners:?}: {other:?}"),
        };
        assert_eq!(reason, Refusal::BadFace, "{corners:?}");
        let said = new_face_witness(&soup, &corners, reason).expect("a witness");
        let shown: Vec<String> = corners.iter().map(u32::to_string).collect();
        let distinct: BTreeSet<u32> = corners.iter().copied().collect();
        if corners.len() < 3 {
            assert_eq!(
                said,
                format!(
                    "too few corners: the new face ({}) would have {} corners, and a face needs at least three",
                    shown.join(", "),
                    corners.len()
                )
            );
        } else {
            let twice = distinct
                .iter()
                .find(|&&v| corners.iter().filter(|&&w| w == v).count() == 2);
            assert_eq!(
                said,
                format!(
                    "repeated corner: the new face ({}) has {} distinct corners but corner {} twice",
                    shown.join(", "),
                    distinct.len(),
                    twice.expect("a repeated corner")
                )
            );
        }
    }
}

#[test]
fn the_refused_example_named_by_default_names_its_element_too() {
    // Without --edge, the preface names a refused collapse (on the open tetrahedron, where
    // none succeeds, and on the mesh shown instead); the reason it gives carries the test and
    // the element, as a refusal asked for does.
    let text = explain_edit::run(
        "index-half-edge",
        None,
        EditOp::CollapseEdge,
        &Asked::default(),
        &Counting::default(),
    )
    .expect("a collapse succeeds somewhere by default");
    let named: Vec<&str> = text
        .lines()
        .filter(|l| l.contains("refuses collapse-edge"))
        .collect();
    assert!(!named.is_empty(), "a refused edge named: {text}");
    for line in named {
        assert!(
            line.contains("the full link condition (Dey et al.)"),
            "{line}"
        );
    }
}
