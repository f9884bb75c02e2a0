//! `topolab refine`: writes the refined mesh, and refuses bad input with the right exit code.

use topolab::commands::refine::refine;

#[test]
fn refine_writes_four_to_the_level_times_the_faces() {
    let dir = std::env::temp_dir().join(format!("topolab-refine-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("torus.off");
    let text = refine("torus", 2, "loop", "input", &out).unwrap();
    assert!(text.contains("384 faces"), "{text}");
    let written = std::fs::read_to_string(&out).unwrap();
    // The canonical torus has 4 x 3 vertices and 24 triangles: 16 x 24 faces after 2 levels.
    let mut header = written.lines().nth(1).unwrap().split_whitespace();
    assert_eq!(header.nth(1), Some("384"));
    // Renumbered: the same counts, another vertex order.
    let bfs = dir.join("torus-bfs.off");
    let text = refine("torus", 2, "loop", "bfs", &bfs).unwrap();
    assert!(text.contains("bfs order"), "{text}");
    let reordered = std::fs::read_to_string(&bfs).unwrap();
    assert_eq!(reordered.lines().nth(1), written.lines().nth(1));
    assert_ne!(reordered, written);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_schemes_polygons_orders_and_formats_are_refused() {
    let out = std::env::temp_dir().join("never-written.obj");
    let ply = std::env::temp_dir().join("never-written.ply");
    for stale in [&out, &ply] {
        let _ = std::fs::remove_file(stale);
    }
    // (mesh, scheme, order, output, expected exit code)
    let cases = [
        ("torus", "butterfly", "input", &out, 2),
        ("quad-cube", "midpoint", "input", &out, 1),
        ("torus", "midpoint", "input", &ply, 2),
        ("no-such-mesh", "midpoint", "input", &out, 2),
        ("torus", "midpoint", "spiral", &out, 2),
    ];
    for (mesh, scheme, order, path, code) in cases {
        let failure = refine(mesh, 1, scheme, order, path).unwrap_err();
        assert_eq!(
            failure.code, code,
            "{mesh} {scheme} {order}: {}",
            failure.message
        );
    }
    assert!(!out.exists() && !ply.exists());
}

#[test]
fn levels_past_what_u32_ids_number_are_refused_before_refining() {
    let out = std::env::temp_dir().join("never-written-levels.obj");
    let _ = std::fs::remove_file(&out);
    // 18 triangles: 14 levels make 3 · 18 · 4^14 = 14.5G corners (13 levels: 3.6G, which u32
    // numbers); usize::MAX levels overflow any count. Both used to refine level by level
    // until memory ran out.
    for levels in [14, usize::MAX] {
        let failure = refine("torus:10", levels, "midpoint", "input", &out).unwrap_err();
        assert_eq!(failure.code, 2, "{levels}: {}", failure.message);
        assert!(failure.message.contains("u32"), "{}", failure.message);
    }
    // A count that fits is refined as before.
    let text = refine("torus:10", 1, "midpoint", "input", &out).unwrap();
    assert!(text.contains("72 faces"), "{text}");
    assert!(out.exists());
    std::fs::remove_file(&out).unwrap();
}
