//! Every subcommand, run as the binary with the arguments a person mistypes or a script gets
//! wrong: huge, zero, negative and non-numeric counts, missing and unwritable paths,
//! directories and devices where files go. Each run must end within [`TIME_LIMIT`] (a guard
//! against hangs, not a speed test) with exit code 1 or 2, no panic and no signal, and say
//! what is wrong in one line on stderr.
//!
//! The subcommands and their arguments come from clap's definition of the command line: a new
//! subcommand without a [`baseline`] fails the test, and every argument of every subcommand is
//! given each of [`GENERIC`]'s values. Those runs see no available memory
//! (`TOPOLAB_AVAILABLE_MEMORY=0`): an argument that happens to be valid (`abc` is a fine output
//! folder) must then stop at the memory check instead of starting a long run. The [`curated`]
//! cases run with the machine's real memory; their huge counts need hundreds of GB.

use clap::CommandFactory;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};
use topolab::cli::Cli;
use topolab_structures::MeshTopology;

/// The longest a refused run may take.
const TIME_LIMIT: Duration = Duration::from_secs(10);

/// Values every argument is given (to options as `--name=VALUE`, so `-1` is a value; to
/// positionals after `--`).
const GENERIC: &[&str] = &[
    "-1",
    "abc",
    "99999999999999999999999",
    "",
    "/dev/zero",
    "@DIR",
];

/// A valid, small invocation of each subcommand: argument id and the tokens that give it. The
/// generic runs replace one argument's tokens. `@DIR` is a scratch folder, `@FILE` a valid
/// mesh file in it.
fn baseline(subcommand: &str) -> Option<Vec<(&'static str, Vec<&'static str>)>> {
    Some(match subcommand {
        "list" => vec![],
        "info" => vec![("mesh", vec!["torus"])],
        "check" => vec![("file", vec!["@FILE"])],
        "explain" => vec![("name", vec!["che"])],
        "report" => vec![
            ("quick", vec!["--quick"]),
            ("sizes", vec!["--sizes", "1000"]),
            ("structures", vec!["--structures", "che-l0"]),
            ("meshes", vec!["--meshes", "torus"]),
            ("out", vec!["--out", "@DIR/report"]),
        ],
        "refine" => vec![
            ("mesh", vec!["torus"]),
            ("levels", vec!["--levels", "1"]),
            ("out", vec!["--out", "@DIR/refined.obj"]),
        ],
        "hull" => vec![("random", vec!["--random", "10"])],
        "repair" => vec![
            ("file", vec!["@FILE"]),
            ("out", vec!["--out", "@DIR/repaired.obj"]),
        ],
        "compare" => vec![("old", vec!["@FILE"]), ("new", vec!["@FILE"])],
        "subdivide" => vec![
            ("mesh", vec!["torus"]),
            ("scheme", vec!["--scheme", "sqrt3"]),
            ("levels", vec!["--levels", "1"]),
            ("out", vec!["--out", "@DIR/sqrt3.obj"]),
        ],
        "decimate" => vec![
            ("mesh", vec!["torus"]),
            ("faces", vec!["--faces", "20"]),
            ("out", vec!["--out", "@DIR/decimated.obj"]),
        ],
        "convert" => vec![("mesh", vec!["torus"]), ("out", vec!["@DIR/converted.stl"])],
        "reconstruct" => vec![
            ("dir", vec!["@DIR/lod"]),
            ("out", vec!["--out", "@DIR/rebuilt.obj"]),
        ],
        "scale" => vec![
            ("max_triangles", vec!["--max-triangles", "1000"]),
            ("structures", vec!["--structures", "che-l2"]),
            ("mapped_triangles", vec!["--mapped-triangles", "0"]),
            ("out", vec!["--out", "@DIR/scale"]),
        ],
        "scale-cell" => vec![
            ("structure", vec!["--structure", "che-l2"]),
            ("triangles", vec!["--triangles", "1000"]),
        ],
        "scale-mapped" => vec![("file", vec!["@DIR/truncated.che"])],
        _ => return None,
    })
}

/// Hand-written cases, run with the real available memory: the arguments after `topolab`.
fn curated() -> Vec<Vec<&'static str>> {
    vec![
        // The five cases of the issue that asked for all this.
        vec![
            "refine",
            "torus:1000",
            "--levels",
            "20",
            "--out",
            "@DIR/x.off",
        ],
        vec!["hull", "--random", "10000000000", "--shape", "ball"],
        vec!["report", "--out", "/proc/nope"],
        vec!["info", "torus:99999999999"],
        // The scale run past the ids' limit, its workers on a huge torus and a bad file.
        vec![
            "scale",
            "--max-triangles",
            "2000000000",
            "--out",
            "@DIR/scale",
        ],
        vec![
            "scale-cell",
            "--structure",
            "che-l2",
            "--triangles",
            "99999999999",
        ],
        vec!["scale-mapped", "@DIR/truncated.che"],
        vec![
            "scale-mapped",
            "@DIR/truncated.che",
            "--cgroup-procs",
            "@DIR/taken",
        ],
        vec!["hull", "@DIR/far.obj"],
        // Huge counts: past u32 ids, or hundreds of GB.
        vec!["info", "torus:1073741824"],
        vec!["info", "quad-grid:1073741824"],
        vec!["info", "genus:2000000:1000"],
        vec!["explain", "index-half-edge", "--mesh", "torus:1073741824"],
        vec![
            "explain",
            "che",
            "--mesh",
            "torus:1073741824",
            "--trace",
            "r00",
            "--vertex",
            "0",
        ],
        vec!["explain", "che", "--trace", "r00", "--vertex", "4294967295"],
        // explain --op: an unknown operation, elements past the mesh's count, the wrong kind
        // of element for the operation.
        vec!["explain", "che", "--op", "twist"],
        vec![
            "explain",
            "che",
            "--op",
            "split-face",
            "--face",
            "4294967295",
        ],
        vec!["explain", "che", "--op", "flip-edge", "--edge", "6"],
        vec![
            "explain",
            "winged-edge",
            "--op",
            "weld-vertices",
            "--vertices",
            "0,99",
        ],
        vec![
            "explain",
            "index-half-edge",
            "--op",
            "split-vertex",
            "--vertex",
            "99",
            "--vertices",
            "0,1",
        ],
        vec![
            "explain",
            "vertex-list",
            "--op",
            "delete-vertex",
            "--face",
            "0",
        ],
        vec![
            "explain",
            "edge-list",
            "--op",
            "add-face",
            "--vertices",
            "0,1",
        ],
        vec![
            "explain",
            "che",
            "--op",
            "garbage-collection",
            "--vertices",
            "0,1",
        ],
        vec!["explain", "che", "--op", "add-vertex", "--edge", "0"],
        vec!["explain", "che", "--vertices", "0,1"],
        vec!["hull", "--random", "4294967295"],
        vec!["hull", "--random", "4000000000"],
        vec![
            "refine",
            "torus:1073741824",
            "--levels",
            "1",
            "--out",
            "@DIR/x.obj",
        ],
        vec![
            "subdivide",
            "torus:1000",
            "--scheme",
            "sqrt3",
            "--levels",
            "30",
            "--out",
            "@DIR/x.off",
        ],
        vec![
            "subdivide",
            "torus:100000000",
            "--scheme",
            "sqrt3",
            "--levels",
            "3",
            "--out",
            "@DIR/x.off",
        ],
        vec![
            "decimate",
            "torus:1073741824",
            "--ratio",
            "0.1",
            "--out",
            "@DIR/x.off",
        ],
        vec!["convert", "torus:1073741824", "@DIR/x.stl"],
        // A point cloud has nothing STL can hold; coordinates of 1e300 none a float can.
        vec!["convert", "@DIR/far.obj", "@DIR/x.stl"],
        // The input as the output (issue 52: `convert x.off x.off --to che` replaced its source).
        vec!["convert", "@DIR/far.obj", "@DIR/far.obj"],
        vec!["convert", "@DIR/tet.off", "@DIR/tet.off", "--to", "che"],
        // Past u32 after two levels; the input alone (17 GB) might fit: refused ungenerated.
        vec![
            "refine",
            "torus:600000000",
            "--levels",
            "2",
            "--out",
            "@DIR/x.obj",
        ],
        vec![
            "refine",
            "torus",
            "--levels",
            "99999999999",
            "--out",
            "@DIR/x.obj",
        ],
        vec!["report", "--sizes", "5000000000", "--out", "@DIR/r"],
        vec![
            "report",
            "--sizes",
            "1073741824,1073741823",
            "--out",
            "@DIR/r",
        ],
        vec!["report", "--probe-mb", "99999", "--out", "@DIR/r"],
        vec!["--allow-memory", "info", "torus:99999999999"],
        // Zero counts.
        vec!["hull", "--random", "0"],
        vec!["report", "--sizes", "0", "--out", "@DIR/r"],
        vec!["report", "--probe-mb", "0", "--out", "@DIR/r"],
        // Missing and unwritable paths, directories and devices as files.
        vec!["info", "/proc/nope"],
        vec!["info", "@DIR"],
        vec!["info", "/dev/null"],
        vec!["check", "/proc/nope"],
        vec!["check", "@DIR"],
        vec!["check", "/dev/zero"],
        vec!["hull", "/dev/zero"],
        vec!["hull", "@DIR"],
        vec!["explain", "che", "--mesh", "/dev/null"],
        vec![
            "refine",
            "/dev/zero",
            "--levels",
            "1",
            "--out",
            "@DIR/x.obj",
        ],
        vec![
            "refine",
            "torus",
            "--levels",
            "1",
            "--out",
            "/proc/nope.obj",
        ],
        vec!["refine", "torus", "--levels", "1", "--out", "/dev/null"],
        vec!["refine", "torus", "--levels", "1", "--out", "/dev/full"],
        vec!["refine", "torus", "--levels", "1", "--out", "@DIR"],
        vec![
            "refine",
            "torus",
            "--levels",
            "1",
            "--out",
            "@DIR/taken.obj",
        ],
        vec![
            "refine",
            "torus",
            "--levels",
            "1",
            "--out",
            "@DIR/none/x.obj",
        ],
        // Adaptive refinement: a length no edge ends at, a region that is no box, a grid that
        // cannot refine locally, an output it cannot write.
        vec!["refine", "torus", "--max-edge", "0", "--out", "@DIR/x.obj"],
        vec![
            "refine",
            "torus",
            "--max-edge",
            "1e-300",
            "--out",
            "@DIR/x.obj",
        ],
        vec![
            "refine",
            "torus",
            "--max-edge",
            "inf",
            "--out",
            "@DIR/x.obj",
        ],
        vec![
            "refine",
            "torus",
            "--max-edge",
            "0.5",
            "--region",
            "1,1,1,-1,-1,-1",
            "--out",
            "@DIR/x.obj",
        ],
        vec![
            "refine",
            "torus",
            "--max-edge",
            "0.5",
            "--structure",
            "regular-grid",
            "--out",
            "@DIR/x.obj",
        ],
        vec!["refine", "torus", "--max-edge", "0.5", "--out", "/dev/full"],
        vec!["hull", "--random", "10", "--out", "/proc/nope.obj"],
        vec!["hull", "--random", "10", "--out", "/dev/full"],
        vec!["hull", "--random", "10", "--out", "@DIR/taken.obj"],
        vec!["report", "--out", "/dev/null"],
        vec!["report", "--out", "@FILE"],
        vec!["report", "--out", "@DIR/taken"],
        vec!["report", "--out", "@FILE/below"],
        vec!["report", "--sections", "nope", "--out", "@DIR/r"],
        vec!["repair", "/dev/zero", "--out", "@DIR/x.obj"],
        vec!["repair", "@DIR", "--out", "@DIR/x.obj"],
        vec!["repair", "@FILE", "--out", "/proc/nope.obj"],
        vec!["repair", "@FILE", "--out", "/dev/full"],
        vec!["repair", "@FILE", "--out", "@DIR/taken.obj"],
        vec!["repair", "@FILE", "--out", "@DIR/x.dxf"],
        // A point cloud: no face to repair (dropping its unused vertices would leave nothing).
        vec!["repair", "@DIR/far.obj", "--out", "@DIR/x.obj"],
        vec!["repair", "torus:1073741824", "--out", "@DIR/x.obj"],
        vec!["compare", "@FILE", "@FILE"],
        vec!["compare", "/proc/nope", "@FILE"],
        vec!["compare", "@FILE", "/dev/zero"],
        vec!["compare", "@DIR", "@FILE"],
        vec!["compare", "@FILE", "@FILE", "--out", "/dev/null"],
        vec!["compare", "@FILE", "@FILE", "--out", "@FILE"],
        // .che files (docs/che-format.md): bad files, and conversions that cannot be written.
        vec!["info", "@DIR/truncated.che"],
        vec!["check", "@DIR/truncated.che"],
        vec!["info", "@DIR/magic.che"],
        vec!["check", "@DIR/magic.che"],
        vec!["info", "@DIR/level9.che"],
        vec!["check", "@DIR/level9.che"],
        vec!["convert", "quad-grid:20", "--to", "che", "@DIR/x.che"],
        vec![
            "convert",
            "torus",
            "--to",
            "che",
            "--level",
            "9",
            "@DIR/x.che",
        ],
        vec!["convert", "torus", "--to", "che", "/proc/nope.che"],
        vec!["convert", "torus", "--to", "che", "/dev/full"],
        vec!["convert", "torus", "--to", "che", "@DIR/taken.obj"],
        // Levels of detail: bad levels, levels with another target, outputs that are no
        // folder or cannot be made.
        vec!["decimate", "torus", "--levels", "", "--out", "@DIR/l"],
        vec!["decimate", "torus", "--levels", "0%", "--out", "@DIR/l"],
        vec!["decimate", "torus", "--levels", "100%", "--out", "@DIR/l"],
        vec!["decimate", "torus", "--levels", "150%", "--out", "@DIR/l"],
        vec![
            "decimate", "torus", "--levels", "10%,50%", "--out", "@DIR/l",
        ],
        vec!["decimate", "torus", "--levels", "half", "--out", "@DIR/l"],
        vec![
            "decimate", "torus", "--levels", "50%", "--faces", "10", "--out", "@DIR/l",
        ],
        vec![
            "decimate", "torus", "--levels", "50%", "--ratio", "0.5", "--out", "@DIR/l",
        ],
        vec![
            "decimate",
            "torus:600",
            "--levels",
            "50%,1%",
            "--out",
            "@DIR/l",
        ],
        vec!["decimate", "torus:600", "--levels", "50%", "--out", "@FILE"],
        vec![
            "decimate",
            "torus:600",
            "--levels",
            "50%",
            "--out",
            "/proc/nope",
        ],
        vec![
            "decimate",
            "torus:1073741824",
            "--levels",
            "50%",
            "--out",
            "@DIR/l",
        ],
        // A folder missing, or not a folder; a record missing, cut short, of another
        // version, with ids past the original's vertices, or not of this coarse mesh.
        vec!["reconstruct", "@DIR/none", "--out", "@DIR/x.obj"],
        vec!["reconstruct", "@FILE", "--out", "@DIR/x.obj"],
        vec!["reconstruct", "@DIR", "--out", "@DIR/x.obj"],
        vec!["reconstruct", "@DIR/lod-truncated", "--out", "@DIR/x.obj"],
        vec!["reconstruct", "@DIR/lod-version", "--out", "@DIR/x.obj"],
        vec!["reconstruct", "@DIR/lod-ids", "--out", "@DIR/x.obj"],
        vec!["reconstruct", "@DIR/lod-mismatch", "--out", "@DIR/x.obj"],
        vec!["reconstruct", "@DIR/lod-garbage", "--out", "@DIR/x.obj"],
        // --to below the coarse mesh's faces, above the original's; outputs that cannot be
        // written.
        vec![
            "reconstruct",
            "@DIR/lod",
            "--to",
            "0",
            "--out",
            "@DIR/x.obj",
        ],
        vec![
            "reconstruct",
            "@DIR/lod",
            "--to",
            "99999",
            "--out",
            "@DIR/x.obj",
        ],
        vec!["reconstruct", "@DIR/lod", "--out", "/dev/full"],
        vec!["reconstruct", "@DIR/lod", "--out", "/proc/nope.obj"],
        vec!["reconstruct", "@DIR/lod", "--out", "@DIR/taken.obj"],
        vec!["reconstruct", "@DIR/lod", "--out", "@DIR/x.dxf"],
        vec![
            "reconstruct",
            "@DIR/lod",
            "--structure",
            "lox-half-edge",
            "--out",
            "@DIR/x.obj",
        ],
    ]
}

/// The level-of-detail folders of the scratch folder `dir`: `lod`, written by `topolab
/// decimate --levels` (600 faces to 300 and 60), and copies with one thing wrong each.
fn level_of_detail_folders(dir: &Path) {
    let lod = dir.join("lod");
    let made = Command::new(env!("CARGO_BIN_EXE_topolab"))
        .args(["decimate", "torus:600", "--levels", "50%,10%", "--out"])
        .arg(&lod)
        .output()
        .expect("the binary runs");
    assert!(made.status.success(), "{made:?}");
    let record = std::fs::read_to_string(lod.join("collapses.txt")).unwrap();
    let coarse = std::fs::read_to_string(lod.join("coarse.obj")).unwrap();
    // The first collapse's line, its vertex ids past the original's 300-odd vertices.
    let first = record.find("\n# from").unwrap() + 1;
    let first = first + record[first..].find('\n').unwrap() + 1;
    let end = first + record[first..].find('\n').unwrap();
    let ids = format!("{}999999 0 1 2 0 0 0 0{}", &record[..first], &record[end..]);
    let mismatch = coarse.replacen("v ", "v 9 9 9\n# was: ", 1);
    for (name, record, coarse) in [
        (
            "lod-truncated",
            record[..record.len() / 2].to_string(),
            coarse.clone(),
        ),
        (
            "lod-version",
            record.replacen("topolab-collapses 1", "topolab-collapses 2", 1),
            coarse.clone(),
        ),
        ("lod-ids", ids, coarse.clone()),
        ("lod-mismatch", record.clone(), mismatch),
        (
            "lod-garbage",
            "\u{0}\u{1}\u{fffd}".to_string(),
            coarse.clone(),
        ),
    ] {
        std::fs::create_dir_all(dir.join(name)).unwrap();
        std::fs::write(dir.join(name).join("collapses.txt"), record).unwrap();
        std::fs::write(dir.join(name).join("coarse.obj"), coarse).unwrap();
    }
}

/// The outcome of one run.
struct Run {
    code: Option<i32>,
    stderr: String,
    took: Duration,
}

/// Runs the binary with `args` (`@DIR`, `@FILE` substituted), killed after [`TIME_LIMIT`].
fn run(args: &[String], dir: &Path, no_memory: bool) -> Run {
    let substituted: Vec<String> = args
        .iter()
        .map(|a| {
            a.replace("@FILE", &dir.join("tet.off").display().to_string())
                .replace("@DIR", &dir.display().to_string())
        })
        .collect();
    let mut command = Command::new(env!("CARGO_BIN_EXE_topolab"));
    command
        .args(&substituted)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .env_remove("RUST_BACKTRACE");
    if no_memory {
        command.env("TOPOLAB_AVAILABLE_MEMORY", "0");
    } else {
        command.env_remove("TOPOLAB_AVAILABLE_MEMORY");
    }
    let start = Instant::now();
    let mut child = command.spawn().expect("the binary runs");
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > TIME_LIMIT {
            child.kill().unwrap();
            child.wait().unwrap();
            panic!("topolab {substituted:?} still ran after {TIME_LIMIT:?}");
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let took = start.elapsed();
    let mut stderr = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut stderr).unwrap();
    Run {
        code: status.code(),
        stderr,
        took,
    }
}

/// What every refused run must look like; the problem, if not.
fn judge(args: &[String], r: &Run) -> Option<String> {
    let lines: Vec<&str> = r.stderr.lines().filter(|l| !l.trim().is_empty()).collect();
    let fault = if r.code.is_none() {
        "killed by a signal (abort?)"
    } else if !matches!(r.code, Some(1 | 2)) {
        "exit code not 1 or 2"
    } else if r.stderr.contains("panicked") || r.stderr.contains("RUST_BACKTRACE") {
        "panicked"
    } else if lines.len() != 1 || !lines[0].starts_with("topolab: ") {
        "not one line `topolab: ...` on stderr"
    } else {
        return None;
    };
    Some(format!(
        "topolab {args:?}: {fault} (exit {:?}, {:?}): {}",
        r.code, r.took, r.stderr
    ))
}

/// A scratch folder for test `name`: mesh files, and directories where files go.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("topolab-{name}-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("taken.obj")).unwrap();
    std::fs::create_dir_all(dir.join("taken/results.json")).unwrap();
    // Coordinates past what the hull's exact predicates handle.
    std::fs::write(
        dir.join("far.obj"),
        "v 1e300 0 0\nv 0 1e300 0\nv 0 0 1e300\nv -1e300 -1e300 -1e300\n",
    )
    .unwrap();
    che_files(&dir);
    std::fs::write(
        dir.join("tet.off"),
        "OFF\n4 3 0\n0 0 0\n1 0 0\n0.5 0.8 0\n0.5 0.3 0.8\n3 0 1 3\n3 1 2 3\n3 2 0 3\n",
    )
    .unwrap();
    level_of_detail_folders(&dir);
    dir
}

/// The bad `.che` files of the curated cases: a valid file cut short, one with another magic,
/// one whose header says level 9.
fn che_files(dir: &Path) {
    use topolab_structures::che::file::Containers;
    let tet = topolab_structures::meshes::open_tetrahedron();
    let che = topolab_structures::CheL2::from_soup(&tet).unwrap();
    let good = Containers::level2(&che).to_bytes().unwrap();
    std::fs::write(dir.join("truncated.che"), &good[..good.len() - 64]).unwrap();
    let mut magic = good.clone();
    magic[..8].copy_from_slice(b"OFF\n4 3 ");
    std::fs::write(dir.join("magic.che"), magic).unwrap();
    let mut level9 = good;
    level9[16] = 9;
    std::fs::write(dir.join("level9.che"), level9).unwrap();
}

/// The generic cases of one subcommand: each argument (but `help`) given each [`GENERIC`]
/// value in its baseline; a flag given a value. Arguments that conflict with the one under
/// test leave the baseline.
fn generic_cases(sub: &clap::Command) -> Vec<Vec<String>> {
    let name = sub.get_name();
    let base = baseline(name).unwrap_or_else(|| {
        panic!("the subcommand `{name}` has no baseline in tests/adversarial.rs: add one")
    });
    let mut cases = Vec::new();
    for arg in sub.get_arguments() {
        let id = arg.get_id().as_str();
        if id == "help" || id == "version" {
            continue;
        }
        let conflicts: Vec<String> = sub
            .get_arg_conflicts_with(arg)
            .iter()
            .map(|a| a.get_id().to_string())
            .collect();
        let takes_value = arg.get_action().takes_values();
        let values: &[&str] = if takes_value { GENERIC } else { &["yes"] };
        for value in values {
            let mut args = vec![name.to_string()];
            let mut positional = Vec::new();
            for (other, tokens) in &base {
                if *other == id || conflicts.iter().any(|c| c == other) {
                    continue;
                }
                let tokens = tokens.iter().map(|t| t.to_string());
                if sub
                    .get_arguments()
                    .any(|a| a.get_id() == *other && a.is_positional())
                {
                    positional.extend(tokens);
                } else {
                    args.extend(tokens);
                }
            }
            match arg.get_long() {
                Some(long) => args.push(format!("--{long}={value}")),
                None => positional.push(value.to_string()),
            }
            if !positional.is_empty() {
                args.push("--".into());
                args.extend(positional);
            }
            cases.push(args);
        }
    }
    cases
}

#[test]
fn every_subcommand_refuses_adversarial_arguments_quickly_in_one_line() {
    let dir = scratch("adversarial");
    let cli = Cli::command();
    let mut failures = Vec::new();
    let mut runs = 0;
    for sub in cli.get_subcommands() {
        for args in generic_cases(sub) {
            runs += 1;
            failures.extend(judge(&args, &run(&args, &dir, true)));
        }
    }
    let mut covered: Vec<&str> = Vec::new();
    for case in curated() {
        let args: Vec<String> = case.iter().map(|s| s.to_string()).collect();
        covered.extend(case.iter().find(|a| !a.starts_with('-')));
        runs += 1;
        failures.extend(judge(&args, &run(&args, &dir, false)));
    }
    for sub in cli.get_subcommands() {
        if sub.get_name() != "list" {
            assert!(
                covered.contains(&sub.get_name()),
                "no curated case for `{}`",
                sub.get_name()
            );
        }
    }
    // Nothing was written: only the scratch files are there.
    let mut left: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    left.sort();
    assert_eq!(
        left,
        [
            "far.obj",
            "level9.che",
            "lod",
            "lod-garbage",
            "lod-ids",
            "lod-mismatch",
            "lod-truncated",
            "lod-version",
            "magic.che",
            "taken",
            "taken.obj",
            "tet.off",
            "truncated.che",
        ]
    );
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(
        failures.is_empty(),
        "{} of {runs} runs failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn allow_memory_lifts_the_memory_check_only() {
    let dir = scratch("allow-memory");
    let args = |a: &[&str]| a.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    // With no memory available a 20k-triangle torus is refused, with --allow-memory it runs.
    let refused = run(&args(&["info", "torus:20000"]), &dir, true);
    assert_eq!(refused.code, Some(2), "{}", refused.stderr);
    assert!(
        refused.stderr.contains("--allow-memory"),
        "{}",
        refused.stderr
    );
    let allowed = run(
        &args(&["--allow-memory", "info", "torus:20000"]),
        &dir,
        true,
    );
    assert_eq!(allowed.code, Some(0), "{}", allowed.stderr);
    // The id limit holds whatever the flag says.
    let ids = run(
        &args(&["info", "torus:99999999999", "--allow-memory"]),
        &dir,
        true,
    );
    assert_eq!(ids.code, Some(2), "{}", ids.stderr);
    assert!(ids.stderr.contains("too large"), "{}", ids.stderr);
    std::fs::remove_dir_all(&dir).unwrap();
}
