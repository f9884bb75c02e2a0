//! `topolab explain NAME --op OP` for the moves, the lecture's contrast of structures by
//! their operations: explicit storage finds every copy of a moved position, a structure that
//! stores it once writes it once; and a selection made of vertices, edges or faces.

mod common;

use common::run::{changed, topolab};

#[test]
fn explicit_storage_moves_a_vertex_by_finding_every_copy_of_it() {
    // Its moves run through explain as `list` gives them: every corner holding the moved
    // position is written, and the corners are all read (compared), so the count grows with
    // the mesh, where the index half-edge writes one record whatever the size.
    let out = topolab(&[
        "explain",
        "explicit",
        "--op",
        "set-position",
        "--vertex",
        "3",
        "--mesh",
        "open-tetrahedron",
        "--structures",
        "index-half-edge",
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // Vertex 3 of the open tetrahedron is a corner of its three faces: three records change.
    let soup = topolab_structures::meshes::open_tetrahedron();
    let copies = soup.indices().iter().filter(|&&v| v == 3).count();
    let corner_records = changed(&stdout)
        .iter()
        .filter(|l| l.starts_with('P'))
        .count();
    assert_eq!(corner_records, copies, "{stdout}");
    let growth: Vec<&str> = stdout
        .lines()
        .skip_while(|l| !l.contains("tori of growing size"))
        .filter(|l| {
            l.trim_start().starts_with("explicit") || l.trim_start().starts_with("index-half-edge")
        })
        .collect();
    assert_eq!(growth.len(), 2, "{stdout}");
    let reads = |line: &str| -> Vec<u64> {
        line.split_whitespace()
            .skip(1)
            .filter_map(|w| w.parse().ok())
            .step_by(2)
            .collect()
    };
    let (explicit, half_edge) = (reads(growth[0]), reads(growth[1]));
    assert_eq!(explicit.len(), 3, "{stdout}");
    // 16 times the faces each step: at least 8 times the reads, where a search is linear.
    assert!(
        explicit[1] >= 8 * explicit[0].max(1) && explicit[2] >= 8 * explicit[1],
        "{stdout}"
    );
    assert_eq!(half_edge[0], half_edge[2], "{stdout}");
}

#[test]
fn a_selection_is_made_of_vertices_edges_or_faces_and_a_face_set_moves_as_its_corners() {
    let soup = topolab_structures::meshes::open_tetrahedron();
    let face = 2u32;
    let mut corners: Vec<u32> = soup.faces().nth(face as usize).unwrap().to_vec();
    corners.sort_unstable();
    for (op, flag, id, kind) in [
        ("select", "--edge", "1", "edges"),
        ("select", "--face", "2", "faces"),
        ("rotate-selection", "--face", "2", "faces"),
        ("scale-selection", "--edge", "1", "edges"),
    ] {
        let out = topolab(&[
            "explain",
            "index-half-edge",
            "--op",
            op,
            flag,
            id,
            "--mesh",
            "open-tetrahedron",
        ]);
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert_eq!(out.status.code(), Some(0), "{op} {flag}: {stdout}{out:?}");
        assert!(
            stdout.contains(&format!("(the selection: the {kind} with")),
            "{op} {flag}: {stdout}"
        );
        if op == "rotate-selection" {
            // The selected face's corners move, and only they: the face set moves as the set
            // of its corners.
            let mut moved: Vec<u32> = changed(&stdout)
                .iter()
                .filter_map(|l| l.strip_prefix('v')?.split('.').next()?.parse().ok())
                .collect();
            moved.sort_unstable();
            moved.dedup();
            assert_eq!(moved, corners, "{stdout}");
        }
    }
    // Two elements, or corners, are not a selection's element.
    let out = topolab(&[
        "explain",
        "index-half-edge",
        "--op",
        "select",
        "--vertices",
        "1,2",
    ]);
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("--vertex V, --edge E or --face F"),
        "{out:?}"
    );
}
