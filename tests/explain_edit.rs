//! `topolab explain NAME --op OP [--edge E | --face F | --vertex V | --vertices A,B]`: the
//! records an edit writes, and a refused edit's exit code and reason, for every editing
//! operation on every structure `--op` explains.

mod common;

use common::run::{changed, topolab};
use topolab::commands::explain_edit::{self, editable, Asked, Counting};
use topolab::failure::Failure;
use topolab_structures::{EditOp, Refusal};

/// `explain NAME --op OP` without the counts on tori of growing size (counted once below).
fn run(name: &str, mesh: Option<&str>, op: EditOp, asked: &Asked) -> Result<String, Failure> {
    explain_edit::run(name, mesh, op, asked, &Counting::default())
}

/// The records marked added (`+ key: ...`) in `text`.
fn added(text: &str) -> Vec<&str> {
    text.lines()
        .filter_map(|l| l.strip_prefix("+ "))
        .filter_map(|l| l.split(": ").next())
        .collect()
}

#[test]
fn a_split_names_the_records_it_adds_and_rewrites() {
    // The open tetrahedron has 4 vertices, 3 triangles and 6 edges: a split adds vertex 4
    // and, splitting an interior edge, two triangles.
    let half_edge =
        run("index-half-edge", None, EditOp::SplitEdge, &Asked::edge(1)).expect("edge 1 splits");
    let new = added(&half_edge);
    assert!(
        new.contains(&"v4") && new.contains(&"f3") && new.contains(&"f4"),
        "{half_edge}"
    );
    assert_eq!(
        new.iter().filter(|k| k.starts_with('h')).count(),
        6,
        "{half_edge}"
    );
    assert!(
        half_edge.contains(".next: "),
        "next links change: {half_edge}"
    );

    let che =
        run("che", None, EditOp::SplitEdge, &Asked::edge(1)).expect("edge 1 splits at every level");
    for level in 0..4 {
        assert!(
            che.contains(&format!("che-l{level}: split-edge of edge 1")),
            "{che}"
        );
    }
    let new = added(&che);
    // Two new triangles: half-edges 9..=14 of V[] at every level, of O[] from level 1 on.
    let count = |prefix: &str| new.iter().filter(|k| k.starts_with(prefix)).count();
    assert_eq!(count("V["), 4 * 6, "{che}");
    assert_eq!(count("O["), 3 * 6, "{che}");
    assert_eq!(
        count("VH["),
        2,
        "the new vertex's VH at levels 2 and 3: {che}"
    );
    assert_eq!(
        count("G[4]"),
        4,
        "the new vertex's position at every level: {che}"
    );
}

#[test]
fn a_collapse_marks_its_vertex_deleted_on_a_torus() {
    for name in editable() {
        if not_offered(name, EditOp::CollapseEdge) {
            continue;
        }
        let text = run(
            name,
            Some("torus:50"),
            EditOp::CollapseEdge,
            &Asked::edge(0),
        )
        .unwrap_or_else(|f| panic!("{name}: {}", f.message));
        assert!(
            text.lines()
                .any(|l| l.starts_with("+ v") && l.contains(".deleted: yes")),
            "{name}: {text}"
        );
    }
}

#[test]
fn a_refused_flip_exits_with_the_reason_and_no_panic() {
    // Every interior edge of the open tetrahedron joins the apex; its flip would create a
    // boundary edge that exists already.
    for name in [
        "index-half-edge",
        "che-l2",
        "che",
        "winged-edge",
        "edge-list",
        "vertex-list",
    ] {
        let out = topolab(&["explain", name, "--op", "flip", "--edge", "1"]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{name}: {stderr}");
        assert!(stderr.contains("refuses flip-edge"), "{name}: {stderr}");
        assert!(
            stderr.contains("the edge it would create exists already"),
            "{stderr}"
        );
        assert!(!stderr.contains("panicked"), "{stderr}");
        assert!(
            out.stdout.is_empty(),
            "{name}: nothing printed before the refusal"
        );
    }
    // A boundary edge (edge 0, v0 - v1) cannot be flipped at all.
    let out = topolab(&["explain", "che-l1", "--op", "flip", "--edge", "0"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("boundary edge"));
}

#[test]
fn bad_requests_are_usage_errors() {
    for args in [
        vec!["explain", "che-l1", "--op", "twist", "--edge", "1"],
        vec!["explain", "che-l1", "--op", "flip", "--edge", "6"],
        // Elements past the open tetrahedron's 4 vertices, 6 edges, 3 faces.
        vec![
            "explain",
            "winged-edge",
            "--op",
            "delete-face",
            "--face",
            "3",
        ],
        vec![
            "explain",
            "winged-edge",
            "--op",
            "delete-vertex",
            "--vertex",
            "4",
        ],
        vec![
            "explain",
            "che",
            "--op",
            "weld-vertices",
            "--vertices",
            "0,4",
        ],
        vec![
            "explain",
            "edge-list",
            "--op",
            "split-vertex",
            "--vertex",
            "0",
            "--vertices",
            "1,9",
        ],
        // The wrong kind of element for the operation.
        vec![
            "explain",
            "vertex-list",
            "--op",
            "delete-face",
            "--edge",
            "1",
        ],
        vec![
            "explain",
            "vertex-list",
            "--op",
            "add-vertex",
            "--vertex",
            "1",
        ],
        vec![
            "explain",
            "che",
            "--op",
            "weld-vertices",
            "--vertices",
            "0,1,2",
        ],
        vec!["explain", "che", "--op", "add-face", "--vertices", "0,1"],
        vec![
            "explain",
            "index-half-edge",
            "--op",
            "split-vertex",
            "--vertex",
            "0",
        ],
        vec![
            "explain",
            "index-half-edge",
            "--op",
            "flip",
            "--edge",
            "1",
            "--face",
            "0",
        ],
        vec![
            "explain",
            "index-half-edge",
            "--op",
            "weld-meshes",
            "--face",
            "0",
        ],
        vec!["explain", "regular-grid", "--op", "split", "--edge", "1"],
        vec![
            "explain", "che-l1", "--op", "flip", "--edge", "1", "--trace", "r00",
        ],
    ] {
        let out = topolab(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(out.stdout.is_empty(), "{args:?}");
    }
    // A wrong kind says what the operation takes; an id past the count, how many there are.
    let out = topolab(&["explain", "che", "--op", "delete-face", "--edge", "1"]);
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("delete-face takes --face F"),
        "{out:?}"
    );
    let out = topolab(&["explain", "che", "--op", "delete-face", "--face", "3"]);
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("no face 3 (it has 3"),
        "{out:?}"
    );
}

#[test]
fn every_editable_structure_of_the_registry_is_explained() {
    let names = editable();
    // The `[editable]` structures and explicit storage, which moves vertices only (`[moves]`).
    let mut expected = topolab_structures::registry::editable_names();
    expected.insert(0, "explicit");
    assert_eq!(names, expected);
    for name in ["winged-edge", "edge-list", "vertex-list"] {
        assert!(names.contains(&name), "{name} is editable: {names:?}");
    }
    // What edits nothing is a usage error naming the editable ones.
    let out = topolab(&["explain", "height-field", "--op", "split", "--edge", "1"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("winged-edge, edge-list") || stderr.contains("edge-list, winged-edge"),
        "{stderr}"
    );
    // A topological edit explicit storage does not offer: not offered, exit 1, naming who does.
    let out = topolab(&["explain", "explicit", "--op", "split", "--edge", "1"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("explicit does not offer split-edge (not offered")
            && stderr.contains("index-half-edge"),
        "{stderr}"
    );
}

#[test]
fn a_split_on_the_face_rewrite_structures_names_their_records() {
    // Splitting interior edge 1 of the open tetrahedron adds one vertex, two triangles and
    // (where edges are stored) three edges, and rewrites the two triangles beside it.
    let count = |keys: &[&str], prefix: char| {
        keys.iter()
            .filter(|k| k.starts_with(prefix) && k[1..].chars().all(|c| c.is_ascii_digit()))
            .count()
    };
    let winged =
        run("winged-edge", None, EditOp::SplitEdge, &Asked::edge(1)).expect("edge 1 splits");
    let new = added(&winged);
    assert_eq!(
        (count(&new, 'v'), count(&new, 'f'), count(&new, 'e')),
        (1, 2, 3),
        "{winged}"
    );
    // The new edge records carry the hull lecture's wings, and old wings are re-pointed.
    for field in [
        "fccw = ", "fcw = ", "pccw = ", "nccw = ", "pcw = ", "ncw = ",
    ] {
        assert!(
            winged
                .lines()
                .any(|l| l.starts_with("+ e") && l.contains(field)),
            "{field}: {winged}"
        );
    }
    assert!(
        changed(&winged)
            .iter()
            .any(|l| l.starts_with('e') && l.contains("cw: ")),
        "{winged}"
    );
    assert!(
        winged.contains("reads: the edge record (v1, v2, fccw, fcw)"),
        "{winged}"
    );

    let edges = run("edge-list", None, EditOp::SplitEdge, &Asked::edge(1)).expect("edge 1 splits");
    let new = added(&edges);
    assert_eq!(
        (count(&new, 'V'), count(&new, 'P'), count(&new, 'E')),
        (1, 2, 3),
        "{edges}"
    );
    assert!(
        edges
            .lines()
            .any(|l| l.starts_with("+ E") && l.contains("start = ") && l.contains("right = ")),
        "the lecture's E = (start, end, left, right): {edges}"
    );
    assert!(
        changed(&edges).iter().any(|l| l.starts_with("E1.end: ")),
        "edge 1 now ends at the new vertex: {edges}"
    );
    assert!(
        changed(&edges).iter().any(|l| l.starts_with('P')),
        "polygons rewritten: {edges}"
    );

    let corners =
        run("vertex-list", None, EditOp::SplitEdge, &Asked::edge(1)).expect("edge 1 splits");
    let new = added(&corners);
    assert_eq!((count(&new, 'v'), count(&new, 'f')), (1, 2), "{corners}");
    assert_eq!(
        changed(&corners)
            .iter()
            .filter(|l| l.starts_with('f') && l.contains(": (v"))
            .count(),
        2,
        "the two triangles beside the edge are rewritten: {corners}"
    );
}

#[test]
fn a_refused_collapse_on_the_face_rewrite_structures_exits_with_its_reason() {
    // On the open tetrahedron, edge 1 = v1 - v3 (a boundary vertex to the apex) passes the link
    // condition in both forms, and its collapse would leave one valid triangle, (2, 0, 3); the
    // third corners v0 and v2 of its two triangles are neighbours of valence 3, so OpenMesh's
    // tetrahedron test refuses it. Edge 0 = v0 - v1, a boundary edge, fails the link condition
    // in its vertex-ring form: the rings of v0 and v1 share v2, which is on no triangle of the
    // edge (the collapse would close the boundary into two triangles on v1, v2, v3).
    for name in ["winged-edge", "edge-list", "vertex-list"] {
        for (edge, reason) in [
            ("1", "OpenMesh's tetrahedron test fails"),
            ("0", "the link condition in its vertex-ring form fails"),
        ] {
            let out = topolab(&["explain", name, "--op", "collapse", "--edge", edge]);
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(1), "{name}, edge {edge}: {stderr}");
            assert!(
                stderr.contains(&format!("{name} refuses collapse-edge")),
                "{stderr}"
            );
            assert!(stderr.contains(reason), "{name}, edge {edge}: {stderr}");
            assert!(
                out.stdout.is_empty(),
                "{name}: nothing printed before the refusal"
            );
        }
    }
}

#[test]
fn an_edit_on_a_cpp_baseline_says_its_records_live_in_the_library() {
    // Built in or not, each baseline is named with why --op cannot show it, as a usage error.
    for name in topolab::registry::CPP_BASELINES {
        let out = topolab(&["explain", name, "--op", "flip", "--edge", "1"]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {stderr}");
        assert!(
            stderr.contains(&format!("{name} edits through its C++ library"))
                && stderr.contains("records live inside that library"),
            "{name}: {stderr}"
        );
        assert!(!stderr.contains("panicked"), "{stderr}");
        assert!(out.stdout.is_empty(), "{name}: nothing printed");
    }
}

/// The cost `topolab list` prints for editing operation `op` in `structure`'s column of its
/// editing table, if the table has that column.
fn listed_edit_cost(list: &str, structure: &str, op: &str) -> Option<String> {
    let table = list
        .split("Editing operations (MeshEdit) and their cost\n")
        .nth(1)?;
    let mut lines = table.lines();
    let column = lines
        .next()?
        .split_whitespace()
        .position(|name| name == structure)?;
    let row = lines.find(|l| l.split_whitespace().next() == Some(op))?;
    row.split_whitespace().nth(column).map(str::to_string)
}

#[cfg(has_openmesh)]
#[test]
fn list_shows_the_edit_costs_of_openmesh_beside_the_others() {
    let out = topolab(&["list"]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    // OpenMesh's own Euler operations: the 2-to-4 split appends, a flip is local.
    assert_eq!(
        listed_edit_cost(&text, "openmesh", "split-edge").as_deref(),
        Some("O(1)"),
        "{text}"
    );
    assert_eq!(
        listed_edit_cost(&text, "openmesh", "flip-edge").as_deref(),
        Some("O(k)"),
        "{text}"
    );
    // The same table as before for the lab's structures (the CHE's weld is a rebuild).
    assert_eq!(
        listed_edit_cost(&text, "che-l3", "weld-vertices").as_deref(),
        Some("O(n)"),
        "{text}"
    );
    let json = topolab(&["list", "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&json.stdout).expect("JSON");
    let editing = v["editing"].as_array().expect("an editing list");
    assert!(
        editing.iter().any(|row| row["name"] == "openmesh"),
        "{editing:?}"
    );
}

#[cfg(not(has_openmesh))]
#[test]
fn skipped_openmesh_edit_costs_in_list_not_compiled_in() {
    common::report_skip("openmesh's edit costs in list", topolab::OPENMESH_MISSING);
    let out = topolab(&["list"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(listed_edit_cost(&text, "openmesh", "split-edge"), None);
}

/// Without `--edge`, each edit succeeds by default on every editable structure: the
/// explanation names the edge it chose (and the mesh, where the open tetrahedron has none:
/// no flip and no collapse succeed there) and an edge where the edit is refused, with its
/// reason, which `--edge` then shows refused with that reason.
#[test]
fn every_edit_succeeds_by_default_and_names_a_refused_edge() {
    for op in ["flip", "split", "collapse"] {
        for name in ["index-half-edge", "winged-edge", "che"] {
            let out = topolab(&["explain", name, "--op", op]);
            let stdout = String::from_utf8_lossy(&out.stdout);
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(0), "{name} {op}: {stderr}");
            assert!(
                stdout.contains("no element given (--edge E): edge "),
                "{stdout}"
            );
            assert!(stdout.contains("writes (old -> new"), "{stdout}");
            let on_grid = stdout.contains("the canonical mesh `grid`");
            assert_eq!(on_grid, op != "split", "{name} {op}: {stdout}");
            // The refused edge it names is refused, with the reason it gave.
            let Some(hint) = stdout.split("try --edge ").nth(1) else {
                continue;
            };
            let refused = hint.split_whitespace().next().unwrap();
            let mesh = if on_grid {
                vec!["--mesh", "grid"]
            } else {
                vec![]
            };
            let mut args = vec!["explain", name, "--op", op, "--edge", refused];
            args.extend(mesh);
            let out = topolab(&args);
            assert_eq!(out.status.code(), Some(1), "{args:?}");
        }
    }
}

/// The Rust crates edit through `MeshEdit` (with the feature `peers`), but their records live
/// inside the crate: `--op` says so, as it does of the C++ baselines, instead of listing
/// nothing.
#[cfg(feature = "peers")]
#[test]
fn a_rust_crate_is_not_explained_by_op_and_says_why() {
    for name in ["tri-mesh", "lox-half-edge"] {
        assert!(!editable().contains(&name), "{name}");
        let failure = run(name, None, EditOp::SplitEdge, &Asked::default()).expect_err(name);
        assert_eq!(failure.code, 2, "{name}: {}", failure.message);
        assert!(
            failure.message.contains("inside that crate"),
            "{}",
            failure.message
        );
    }
}

/// What the heading of `op`'s explanation names, by the kind of element it edits: written per
/// operation (not derived from the code that chooses it), exhaustive so that a new operation
/// is a compile error here until its test says what it should name.
fn named_element(op: EditOp) -> &'static str {
    match op {
        EditOp::AddVertex => "of a new vertex at ",
        EditOp::AddFace => "of the face on vertices ",
        EditOp::DeleteFace | EditOp::SplitFace => "of face ",
        EditOp::DeleteVertex | EditOp::GarbageCollection => "of vertex ",
        EditOp::FlipEdge | EditOp::SplitEdge | EditOp::CollapseEdge => "of edge ",
        EditOp::SplitVertex => ", between its neighbours ",
        EditOp::WeldVertices => "of vertices ",
        EditOp::WeldMeshes => "its mirror image",
        EditOp::WeldEdges => ", the second sewn onto the first",
        EditOp::WeldFaces => ", both removed and their boundaries sewn together",
        EditOp::SetPosition => "moved halfway to the mesh's centroid",
        EditOp::Select | EditOp::RotateSelection | EditOp::ScaleSelection => "(the selection: ",
        EditOp::InsertEdge => ", by a new edge from v",
        EditOp::DeleteEdge => "of edge ",
        EditOp::Smooth => "of every vertex of the mesh",
    }
}

/// Does structure `name` (`che`: its four levels) lack `op`? The CHE stores triangles only, so
/// it has no polygon to split by a diagonal (insert-edge) and cannot hold the polygon merging
/// two triangles makes (delete-edge).
fn not_offered(name: &str, op: EditOp) -> bool {
    // `che` explains the four levels, which offer the same operations.
    let name = if name == "che" { "che-l0" } else { name };
    topolab_registry::offers(name, op) == Some(false)
}

#[test]
fn what_a_structure_offers_comes_from_its_table() {
    // The table the tests above read agrees with the lecture's contrasts: explicit storage
    // moves vertices but inserts nothing, the CHE has no polygon to insert an edge into.
    assert!(not_offered("explicit", EditOp::SplitEdge));
    assert!(!not_offered("explicit", EditOp::SetPosition));
    assert!(not_offered("che", EditOp::InsertEdge));
    assert!(!not_offered("index-half-edge", EditOp::InsertEdge));
}

/// Every operation, by its name, succeeds by default on every structure `--op` explains that
/// offers it (and on the four CHE levels at once), names its element and writes at least one
/// record (but a selection, which writes none); a structure that does not offer it says so.
#[test]
fn every_operation_succeeds_by_default_on_every_structure_and_names_its_element() {
    let mut names = editable();
    names.push("che");
    for op in EditOp::ALL {
        for &name in &names {
            let out = topolab(&["explain", name, "--op", op.name()]);
            let stdout = String::from_utf8_lossy(&out.stdout);
            let stderr = String::from_utf8_lossy(&out.stderr);
            if not_offered(name, op) {
                assert_eq!(out.status.code(), Some(1), "{name} {op}: {stderr}");
                assert!(
                    stderr.contains(&format!("does not offer {op} (not offered")),
                    "{name} {op}: {stderr}"
                );
                continue;
            }
            assert_eq!(out.status.code(), Some(0), "{name} {op}: {stderr}");
            let headings: Vec<&str> = stdout
                .lines()
                .filter(|l| l.contains(&format!(": {op} of ")))
                .collect();
            let expected = if name == "che" { 4 } else { 1 };
            assert_eq!(headings.len(), expected, "{name} {op}: {stdout}");
            for h in headings {
                assert!(h.contains(named_element(op)), "{name} {op}: {h}");
            }
            assert!(stdout.contains("writes (old -> new"), "{stdout}");
            // A selection writes nothing, nor does a garbage collection where nothing was
            // deleted (explicit storage deletes nothing).
            let writes_nothing = op == EditOp::Select
                || (op == EditOp::GarbageCollection && not_offered(name, EditOp::DeleteVertex));
            assert_eq!(
                stdout.contains("(no record changed)"),
                writes_nothing,
                "{name} {op}: {stdout}"
            );
            assert!(!stdout.contains("not described"), "{name} {op}: {stdout}");
        }
    }
}

/// An element asked for with `--edge`, `--face`, `--vertex` or `--vertices` where the edit
/// must be refused, with its typed reason, on every structure. Each case's reason follows
/// from the mesh, not from the code: the open tetrahedron is triangles (t, t+1 mod 3, 3),
/// boundary 0-1-2; the grid's faces are (0,1,5), (0,5,4), (1,2,6), (1,6,5), ... (4 vertices a
/// row).
#[test]
fn a_refused_request_exits_with_its_typed_reason_on_every_structure() {
    let cases: [(&[&str], EditOp, Refusal); 13] = [
        // Edge 0 = v0 - v1 is on the boundary: one triangle.
        (&["--edge", "0"], EditOp::FlipEdge, Refusal::BoundaryEdge),
        // Edge 1 = v1 - v3: its flip would join v0 and v2, a boundary edge already.
        (&["--edge", "1"], EditOp::FlipEdge, Refusal::EdgeExists),
        // The rings of v0 and v1 share v2, on no triangle of the edge (docs/editing.md).
        (
            &["--edge", "0"],
            EditOp::CollapseEdge,
            Refusal::LinkCondition,
        ),
        // v0 and v2, the third corners, are neighbours of valence 3 (docs/editing.md).
        (
            &["--edge", "1"],
            EditOp::CollapseEdge,
            Refusal::TetrahedronTest,
        ),
        // A repeated corner.
        (&["--vertices", "0,1,1"], EditOp::AddFace, Refusal::BadFace),
        // Face (0, 1, 3) runs 0 -> 1 already: a second face running it the same way.
        (
            &["--vertices", "0,1,2"],
            EditOp::AddFace,
            Refusal::NonManifoldEdge,
        ),
        // Every two vertices of the tetrahedron share a face.
        (
            &["--vertices", "0,1"],
            EditOp::WeldVertices,
            Refusal::BadFace,
        ),
        (
            &["--vertices", "2,2"],
            EditOp::WeldVertices,
            Refusal::SameVertex,
        ),
        // Face 3 = (1, 6, 5) lies between (0, 1, 5) and (1, 2, 6) around the boundary vertex
        // 1: without it, v1 has two fans.
        (
            &["--face", "3", "--mesh", "grid"],
            EditOp::DeleteFace,
            Refusal::NonManifoldVertex,
        ),
        // v10 is two rows above v0: not its neighbour.
        (
            &["--vertex", "0", "--vertices", "1,10", "--mesh", "grid"],
            EditOp::SplitVertex,
            Refusal::NotNeighbours,
        ),
        // v2 and v3 are both neighbours of v0, but the fan from v2 round to v3 crosses the
        // boundary edge v2 - v0: the inverse of a boundary collapse, which no structure
        // implements.
        (
            &["--vertex", "0", "--vertices", "2,3"],
            EditOp::SplitVertex,
            Refusal::NotImplemented,
        ),
        // A torus is closed: no boundary vertex to weld to its mirror image.
        (
            &["--mesh", "torus:50"],
            EditOp::WeldMeshes,
            Refusal::NothingToWeld,
        ),
        // The old name of the operation asks the same.
        (
            &["--edge", "0"],
            EditOp::CollapseEdge,
            Refusal::LinkCondition,
        ),
    ];
    let mut names = editable();
    names.push("che");
    for (i, (flags, op, reason)) in cases.iter().enumerate() {
        let op_name = if i == cases.len() - 1 {
            "collapse"
        } else {
            op.name()
        };
        for &name in &names {
            let mut args = vec!["explain", name, "--op", op_name];
            args.extend_from_slice(flags);
            let out = topolab(&args);
            let stderr = String::from_utf8_lossy(&out.stderr);
            let said = if not_offered(name, *op) {
                format!("does not offer {op} (not offered")
            } else {
                format!("refuses {op}: {reason}")
            };
            assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
            assert!(stderr.contains(&said), "{args:?}: {stderr}");
            assert!(
                out.stdout.is_empty(),
                "{args:?}: nothing printed before the refusal"
            );
            // The refusal, and where the mesh shows it, the test and element on a line of
            // their own (tests/explain_refusals.rs checks that line).
            let lines: Vec<&str> = stderr.lines().collect();
            assert!(
                lines.len() == 1
                    || (lines.len() == 2 && lines[1].starts_with("test and element: ")),
                "{args:?}: {stderr}"
            );
        }
    }
}

/// Without an element, the refused one the explanation names (`try --...`) is refused when
/// asked for, on the index half-edge the choice is made on, with the reason it gave.
#[test]
fn the_refused_element_named_by_default_is_refused_with_that_reason() {
    let mut named = 0;
    for op in EditOp::ALL {
        let out = topolab(&["explain", "index-half-edge", "--op", op.name()]);
        let stdout = String::from_utf8_lossy(&out.stdout);
        let Some(hint) = stdout.split("; it is refused on ").nth(1) else {
            continue;
        };
        named += 1;
        let hint = hint.lines().next().unwrap();
        let reason = hint
            .split(&format!("refuses {op}: "))
            .nth(1)
            .and_then(|r| r.split("): try ").next())
            .unwrap_or_else(|| panic!("{op}: {hint}"));
        let flags = hint
            .split("): try ")
            .nth(1)
            .unwrap_or_else(|| panic!("{hint}"));
        let mut args = vec!["explain", "index-half-edge", "--op", op.name()];
        args.extend(flags.split_whitespace());
        let out = topolab(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
        // The reason, and the test and element where it names them, as the refusal asked
        // for prints them.
        for part in reason.split("; test and element: ") {
            assert!(stderr.contains(part), "{args:?}: {part} / {stderr}");
        }
    }
    // Flips, collapses, face additions, vertex splits and vertex welds have a refused element
    // among the first tried; adding a vertex, splitting a face and collecting garbage are
    // never refused on a valid mesh.
    assert!(named >= 5, "{named}");
}

/// Inserting and deleting an edge refused with their reasons on every structure that offers
/// them: on the open tetrahedron (triangles (t, t+1 mod 3, 3)), corners 0 and 1 of face 0 are
/// neighbours in it, so no diagonal joins them; edge 0 = v0 - v1 borders one face only.
#[test]
fn edge_insertion_and_deletion_are_refused_with_their_reasons() {
    let cases: [(&[&str], EditOp, Refusal); 2] = [
        (
            &["--face", "0", "--vertices", "0,1"],
            EditOp::InsertEdge,
            Refusal::NotDiagonal,
        ),
        (&["--edge", "0"], EditOp::DeleteEdge, Refusal::BoundaryEdge),
    ];
    let mut names = editable();
    names.push("che");
    for (flags, op, reason) in cases {
        for &name in &names {
            let mut args = vec!["explain", name, "--op", op.name()];
            args.extend_from_slice(flags);
            let out = topolab(&args);
            let stderr = String::from_utf8_lossy(&out.stderr);
            let said = if not_offered(name, op) {
                format!("does not offer {op} (not offered")
            } else {
                format!("refuses {op}: {reason}")
            };
            assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
            assert!(stderr.contains(&said), "{args:?}: {stderr}");
            assert!(out.stdout.is_empty(), "{args:?}");
        }
    }
}

/// Moving a vertex writes its position and nothing else: the new coordinates appear among the
/// records written, and the faces are untouched.
#[test]
fn set_position_writes_the_vertex_position_only() {
    for name in editable() {
        let out = topolab(&["explain", name, "--op", "set-position", "--vertex", "3"]);
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert_eq!(out.status.code(), Some(0), "{name}: {stdout}");
        let writes = stdout
            .split("writes (old -> new; + added, - removed):\n")
            .nth(1)
            .unwrap();
        let lines: Vec<&str> = writes.lines().take_while(|l| !l.is_empty()).collect();
        assert!(!lines.is_empty(), "{name}: {stdout}");
        assert!(
            lines
                .iter()
                .all(|l| !l.starts_with('+') && !l.starts_with('-')),
            "{name}: nothing added or removed: {lines:?}"
        );
    }
}

/// A deletion shows as one: on every structure the deleted face gets a record of its own (a
/// marking structure's, or a line saying a compacting one removed it at once and which face
/// took its slot); on a structure that marks (the half-edges), the edge that bordered it alone
/// too, as a deleted vertex does.
#[test]
fn a_deleted_face_and_edge_get_records_of_their_own() {
    for name in editable() {
        if not_offered(name, EditOp::DeleteFace) {
            continue;
        }
        let text = run(
            name,
            None,
            EditOp::DeleteFace,
            &Asked {
                face: Some(0),
                ..Asked::default()
            },
        )
        .unwrap_or_else(|f| panic!("{name}: {}", f.message));
        let added = added(&text);
        assert!(added.contains(&"f0.deleted"), "{name}: {text}");
        // The half-edges mark deleted edges too: the edge that bordered only the face.
        let marks_edges = name.ends_with("half-edge");
        assert_eq!(
            added
                .iter()
                .any(|k| k.starts_with('e') && k.ends_with(".deleted")),
            marks_edges,
            "{name}: {text}"
        );
    }
}

/// The refused example named beside a default element is the structure's own refusal: no
/// refusal names another structure, and none is a missing feature (`not offered` is no
/// refusal).
#[test]
fn a_refusal_named_by_default_is_the_structures_own() {
    for name in editable() {
        for op in [
            EditOp::FlipEdge,
            EditOp::CollapseEdge,
            EditOp::SplitVertex,
            EditOp::DeleteEdge,
        ] {
            let Ok(text) = run(name, None, op, &Asked::default()) else {
                continue;
            };
            for line in text.lines().filter(|l| l.contains(" refuses ")) {
                let who = line
                    .split(" refuses ")
                    .next()
                    .and_then(|l| l.rsplit(['(', ' ']).next())
                    .unwrap_or_default();
                assert_eq!(who, name, "{name} {op}: {line}");
                assert!(
                    !line.contains(&Refusal::NotImplemented.to_string()),
                    "{name} {op}: {line}"
                );
            }
        }
    }
}
