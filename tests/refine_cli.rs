//! `topolab refine`: writes the refined mesh, and refuses bad input with the right exit code.

use topolab::refine::refine;

#[test]
fn refine_writes_four_to_the_level_times_the_faces() {
    let dir = std::env::temp_dir().join(format!("topolab-refine-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("torus.off");
    let text = refine("torus", 2, "loop", &out).unwrap();
    assert!(text.contains("384 faces"), "{text}");
    let written = std::fs::read_to_string(&out).unwrap();
    // The canonical torus has 4 x 3 vertices and 24 triangles: 16 x 24 faces after 2 levels.
    let mut header = written.lines().nth(1).unwrap().split_whitespace();
    assert_eq!(header.nth(1), Some("384"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_schemes_polygons_and_formats_are_refused() {
    let out = std::env::temp_dir().join("never-written.obj");
    assert_eq!(refine("torus", 1, "butterfly", &out).unwrap_err().code, 2);
    assert_eq!(
        refine("quad-cube", 1, "midpoint", &out).unwrap_err().code,
        1
    );
    let ply = std::env::temp_dir().join("never-written.ply");
    assert_eq!(refine("torus", 1, "midpoint", &ply).unwrap_err().code, 2);
    assert_eq!(
        refine("no-such-mesh", 1, "midpoint", &out)
            .unwrap_err()
            .code,
        2
    );
    assert!(!out.exists());
}
