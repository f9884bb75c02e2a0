//! `topolab repair FILE --out FILE`: repairs what `topolab check` finds in a mesh's topology
//! (duplicate faces, non-manifold edges and vertices, inconsistent orientation, unused
//! vertices; [`topolab_structures::repair`]), writes the result, prints what changed, then runs
//! the checks on the output and says what remains. Exit code 0 when none of those problems
//! remains, 1 when one does (a non-orientable component, or the problem of a skipped step; the
//! output is written all the same), 2 when the file cannot be read or the output written.

use crate::input::{load_mesh, refuse_empty, Failure};
use crate::output::{check_mesh_out, write_mesh};
use std::fmt::Write as _;
use std::path::PathBuf;
use topolab_structures::checks::{self, FindingKind, Options, Report};
use topolab_structures::io::RawSoup;
use topolab_structures::repair::{repair, Repaired, Step};
use topolab_structures::PolygonSoup;

/// The findings of `topolab check` that repair is about: those it removes, and the one it
/// cannot (a non-orientable component).
const TOPOLOGICAL: [FindingKind; 6] = [
    FindingKind::DuplicateFace,
    FindingKind::NonManifoldEdge,
    FindingKind::NonManifoldVertex,
    FindingKind::InconsistentOrientation,
    FindingKind::NonOrientable,
    FindingKind::UnusedVertex,
];

/// Arguments of `topolab repair`.
#[derive(clap::Args, Debug)]
pub struct RepairArgs {
    /// The mesh file (.obj, .off, .ply, .stl).
    pub file: String,
    /// The repaired mesh (.obj, .off or .stl).
    #[arg(long)]
    pub out: PathBuf,
    /// Steps not to run, comma separated: duplicate-faces, split-edges, split-vertices,
    /// orient, unused-vertices (by default all run, in that order).
    #[arg(long, value_delimiter = ',', value_parser = step)]
    pub skip: Vec<Step>,
}

/// A step by name; an unknown one lists the known.
fn step(name: &str) -> Result<Step, String> {
    Step::from_name(name).ok_or_else(|| {
        let names: Vec<&str> = Step::ALL.iter().map(|s| s.name()).collect();
        format!("unknown step; known: {}", names.join(", "))
    })
}

/// The work measured on the sample mesh before a large input is read: the repair, which takes
/// the mesh and changes it in place, then the checks on its output, which take the repaired
/// mesh.
fn work(soup: PolygonSoup, steps: &[Step]) -> u64 {
    let repaired = repair(soup, steps);
    check_output(repaired.soup);
    0
}

/// The checks on the repaired mesh, which they take (their edge analysis runs in its arrays).
fn check_output(soup: PolygonSoup) -> Report {
    let raw = RawSoup {
        soup,
        ..RawSoup::default()
    };
    checks::check_owned(raw, &Options::default())
}

/// Runs the repair, prints what changed and what remains; returns the exit code.
pub fn run(args: RepairArgs) -> u8 {
    match repair_file(&args) {
        Ok((text, remaining)) => {
            if let Err(e) = crate::output::print(&text) {
                crate::output::say(&e.message);
                return e.code;
            }
            if remaining == 0 {
                return 0;
            }
            crate::output::say(&format!(
                "{}: {remaining} problems remain (see above)",
                args.out.display()
            ));
            1
        }
        Err(e) => {
            crate::output::say(&e.message);
            e.code
        }
    }
}

/// The repair of `args.file` into `args.out`: the text to print and how many topological
/// problems remain in the output.
pub fn repair_file(args: &RepairArgs) -> Result<(String, usize), Failure> {
    let steps: Vec<Step> = Step::ALL
        .into_iter()
        .filter(|s| !args.skip.contains(s))
        .collect();
    // An output that cannot be written is refused before the input is read.
    check_mesh_out(&args.out, &args.file)?;
    // The mesh is counted (its soup) besides the work's peak on the sample's copy: the mesh
    // twice, which covers what the sample does not show, a mesh of more components an element
    // than the sample's one (separate triangles, each a component the checks report).
    let soup = load_mesh(&args.file, |s| work(s.clone(), &steps))?;
    refuse_empty(&args.file, &soup)?;
    if soup.num_faces() == 0 {
        return Err(Failure {
            message: format!(
                "{} has no faces (a point cloud): nothing to repair",
                args.file
            ),
            code: 1,
        });
    }
    let mut text = String::new();
    let _ = writeln!(
        text,
        "{}: {} vertices, {} faces",
        args.file,
        soup.num_vertices(),
        soup.num_faces()
    );
    let Repaired { soup: out, log } = repair(soup, &steps);
    write_mesh(&args.out, &out)?;
    let lines = log.lines();
    if lines.is_empty() {
        let _ = writeln!(text, "  nothing to repair");
    }
    for line in lines {
        let _ = writeln!(text, "  {line}");
    }
    let _ = writeln!(
        text,
        "wrote {}: {} vertices, {} faces",
        args.out.display(),
        out.num_vertices(),
        out.num_faces()
    );
    let new = log.new_vertices();
    if new > 0 {
        let _ = writeln!(
            text,
            "expected: the {new} new vertices are at the positions of the vertices they were split from (one point, two places on the surface): `topolab check` lists them as duplicate-vertices"
        );
    }
    let report = check_output(out);
    let count = |k: FindingKind| report.count(k);
    let remaining: Vec<String> = TOPOLOGICAL
        .iter()
        .map(|&k| (k, count(k)))
        .filter(|(_, n)| *n > 0)
        .map(|(k, n)| format!("{} ({n})", k.name()))
        .collect();
    if remaining.is_empty() {
        let _ = writeln!(
            text,
            "check of the output: no duplicate face, non-manifold edge or vertex, inconsistent orientation, non-orientable component or unused vertex"
        );
    } else {
        let _ = writeln!(
            text,
            "check of the output: remaining {}",
            remaining.join(", ")
        );
    }
    let other: usize = FindingKind::ALL
        .into_iter()
        .filter(|k| !TOPOLOGICAL.contains(k) && *k != FindingKind::DuplicateVertices)
        .map(count)
        .sum();
    if other > 0 {
        let _ = writeln!(
            text,
            "not repaired: {other} other findings (geometry, polygons): see `topolab check {}`",
            args.out.display()
        );
    }
    let remaining = TOPOLOGICAL.iter().map(|&k| count(k)).sum();
    Ok((text, remaining))
}
