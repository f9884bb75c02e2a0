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
    // A format the lab does not write (PLY it does).
    let ply = std::env::temp_dir().join("never-written.dxf");
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

mod adaptive {
    //! `topolab refine --max-edge`: adaptive refinement by longest-edge bisection.

    use clap::Parser;
    use std::path::{Path, PathBuf};
    use topolab::cli::Cli;
    use topolab::commands::refine::{run, RefineArgs};
    use topolab::commands::refine_adaptive::adaptive;
    use topolab_structures::algorithms::checks;
    use topolab_structures::io::read_raw;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("topolab-adaptive-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(name);
        let _ = std::fs::remove_file(&path);
        path
    }

    /// The file written is a mesh `topolab check` finds nothing in; its face count.
    fn clean_faces(path: &Path) -> usize {
        let raw = read_raw(path).unwrap();
        let report = checks::check(&raw, &checks::Options::default());
        assert!(report.findings.is_empty(), "{:?}", report.findings);
        raw.soup.num_faces()
    }

    #[test]
    fn writes_a_clean_refined_mesh_on_editable_structures() {
        // The canonical torus (24 triangles, edges of about 1.4 to 2): every edge longer than
        // 0.5 split, on the default structure and two others; all make the same faces.
        let mut counts = Vec::new();
        for structure in ["index-half-edge", "winged-edge", "che-l3"] {
            let out = scratch(&format!("torus-{structure}.obj"));
            let text = adaptive("torus", 0.5, None, structure, &out).unwrap();
            assert!(
                text.contains("edges split") && text.contains("24 faces before"),
                "{text}"
            );
            counts.push(clean_faces(&out));
        }
        assert!(counts[0] > 4 * 24, "{counts:?}");
        assert!(counts.iter().all(|&c| c == counts[0]), "{counts:?}");
        // A box around part of the torus refines less.
        let out = scratch("torus-region.off");
        let text = adaptive("torus", 0.5, Some("0,-2,-1,2,2,1"), "index-half-edge", &out).unwrap();
        assert!(text.contains("both ends in"), "{text}");
        let local = clean_faces(&out);
        assert!(local > 24 && local < counts[0], "{local} of {}", counts[0]);
    }

    #[test]
    fn a_regular_grid_cannot_refine_locally() {
        let out = scratch("never-grid.obj");
        for structure in ["regular-grid", "height-field"] {
            let failure = adaptive("grid:8", 0.1, None, structure, &out).unwrap_err();
            assert_eq!(failure.code, 1, "{}", failure.message);
            assert!(
                failure.message.contains("cannot refine locally")
                    && failure.message.contains("implicit in (i, j)"),
                "{}",
                failure.message
            );
        }
        let failure = adaptive("torus", 0.1, None, "explicit", &out).unwrap_err();
        assert_eq!(failure.code, 1, "{}", failure.message);
        // It implements MeshEdit for its moves only: the split is not offered, said so, and
        // the structures that offer it named.
        assert!(
            failure.message.contains("does not offer split-edge")
                && failure.message.contains("not offered")
                && failure.message.contains("index-half-edge"),
            "{}",
            failure.message
        );
        let failure = adaptive("torus", 0.1, None, "no-such", &out).unwrap_err();
        assert_eq!(failure.code, 2, "{}", failure.message);
        assert!(!out.exists());
    }

    #[test]
    fn bad_max_edges_regions_and_inputs_are_refused() {
        let out = scratch("never-bad.obj");
        for max_edge in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let failure = adaptive("torus", max_edge, None, "index-half-edge", &out).unwrap_err();
            assert_eq!(failure.code, 2, "{max_edge}: {}", failure.message);
            assert!(
                failure.message.contains("--max-edge"),
                "{}",
                failure.message
            );
        }
        for region in [
            "0,0,0,1,1",
            "0,0,0,1,1,1,1",
            "a,0,0,1,1,1",
            "1,0,0,0,1,1",
            "0,0,nan,1,1,1",
        ] {
            let failure =
                adaptive("torus", 0.5, Some(region), "index-half-edge", &out).unwrap_err();
            assert_eq!(failure.code, 2, "{region}: {}", failure.message);
            assert!(failure.message.contains("--region"), "{}", failure.message);
        }
        // Polygons: longest-edge bisection splits triangles.
        let failure = adaptive("quad-cube", 0.5, None, "index-half-edge", &out).unwrap_err();
        assert_eq!(failure.code, 1, "{}", failure.message);
        // Edges so short that even the fewest faces pass what u32 ids number.
        let failure = adaptive("torus", 1e-12, None, "index-half-edge", &out).unwrap_err();
        assert_eq!(failure.code, 2, "{}", failure.message);
        assert!(failure.message.contains("u32"), "{}", failure.message);
        assert!(!out.exists());
    }

    #[test]
    fn levels_and_max_edge_are_two_modes() {
        let parse = |args: &[&str]| Cli::try_parse_from(args);
        // One of the two, never both.
        let both = [
            "topolab",
            "refine",
            "torus",
            "--levels",
            "1",
            "--max-edge",
            "0.5",
            "--out",
            "x.obj",
        ];
        let e = parse(&both).unwrap_err().to_string();
        assert!(e.contains("cannot be used with"), "{e}");
        assert!(parse(&["topolab", "refine", "torus", "--out", "x.obj"]).is_err());
        // The uniform options do not go with --max-edge, the adaptive ones not with --levels.
        for mixed in [
            ["--max-edge", "0.5", "--scheme", "loop"],
            ["--levels", "1", "--region", "0,0,0,1,1,1"],
            ["--levels", "1", "--structure", "winged-edge"],
        ] {
            let args = [
                &["topolab", "refine", "torus"][..],
                &mixed,
                &["--out", "x.obj"],
            ]
            .concat();
            assert!(parse(&args).is_err(), "{args:?}");
        }
        // A negative region parses (and is checked by the command).
        let ok = [
            "topolab",
            "refine",
            "torus",
            "--max-edge",
            "0.5",
            "--region",
            "-1,-1,-1,1,1,1",
            "--out",
            "x.obj",
        ];
        assert!(parse(&ok).is_ok());
        assert!(parse(&["topolab", "refine", "torus", "--levels", "1", "--out", "x.obj"]).is_ok());
        // Called directly with both, the command says so too.
        let args = RefineArgs {
            mesh: "torus".into(),
            levels: Some(1),
            max_edge: Some(0.5),
            region: None,
            structure: "index-half-edge".into(),
            scheme: "midpoint".into(),
            out: scratch("never-both.obj"),
            order: "input".into(),
        };
        let failure = run(&args).unwrap_err();
        assert_eq!(failure.code, 2);
        assert!(failure.message.contains("not both"), "{}", failure.message);
    }

    /// `topolab refine` with `args`: its exit code, stdout and stderr.
    fn topolab(args: &[&str]) -> (Option<i32>, String, String) {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_topolab"))
            .args(args)
            .output()
            .expect("run topolab");
        let text = |b: Vec<u8>| String::from_utf8(b).expect("UTF-8");
        (out.status.code(), text(out.stdout), text(out.stderr))
    }

    /// The number written before `word` in `text` (`about 1234 faces predicted`).
    fn number_before(text: &str, word: &str) -> u128 {
        let before = text.split(word).next().expect("the word");
        let number = before.split_whitespace().last().expect("a number");
        number
            .parse()
            .unwrap_or_else(|_| panic!("{number:?} before {word:?} in {text}"))
    }

    #[test]
    fn the_estimate_is_stated_before_the_work_and_is_near_the_result() {
        let out = scratch("estimated.obj");
        let path = out.to_str().unwrap();
        let (code, stdout, stderr) =
            topolab(&["refine", "torus", "--max-edge", "0.05", "--out", path]);
        assert_eq!(code, Some(0), "{stderr}");
        let line = stderr
            .lines()
            .find(|l| l.contains("faces predicted"))
            .unwrap_or_else(|| panic!("no estimate in {stderr:?}"));
        assert!(
            line.contains("--max-edge 0.05 of torus") && line.contains("of memory"),
            "{line}"
        );
        let predicted = number_before(line, " faces predicted") as f64;
        let fewest = number_before(line, ")").max(1) as f64;
        assert!(predicted >= fewest, "{line}");
        let made = clean_faces(&out) as f64;
        assert!(
            made <= 2.0 * predicted && predicted <= 2.0 * made,
            "{made} faces made, {line}"
        );
        assert!(stdout.contains("24 faces before"), "{stdout}");
        // Uniform refinement states its exact count.
        let (code, _, stderr) = topolab(&["refine", "torus", "--levels", "2", "--out", path]);
        assert_eq!(code, Some(0), "{stderr}");
        assert!(stderr.contains("384 faces when done"), "{stderr}");
    }

    #[test]
    fn a_request_predicted_past_the_memory_is_refused_before_the_work() {
        // The canonical torus's 36 edges of about 1.4 to 2 halved down to 1e-4: at least some
        // 2 million faces (the lower bound, which fits), but its area predicts billions, far
        // more than any machine's memory holds.
        let out = scratch("never-predicted.obj");
        let path = out.to_str().unwrap();
        let (code, _, stderr) = topolab(&["refine", "torus", "--max-edge", "1e-4", "--out", path]);
        assert_eq!(code, Some(2), "{stderr}");
        let estimate = stderr
            .lines()
            .find(|l| l.contains("faces predicted"))
            .unwrap_or_else(|| panic!("no estimate in {stderr:?}"));
        assert!(
            number_before(estimate, " faces predicted") > 1_000_000_000,
            "{estimate}"
        );
        assert!(
            stderr.contains("more than the") && stderr.contains("--allow-memory"),
            "{stderr}"
        );
        assert!(!out.exists());
    }
}
