//! `topolab check FILE`: the lecture's consistency checks on a mesh file as written, every
//! problem reported (not only the first). Exit code 0 when clean, 1 when problems were found,
//! 2 when the file cannot be read.

use crate::input::{input_file, is_che_file, Failure};
use crate::limits;
use std::fmt::Write as _;
use std::path::PathBuf;
use topolab_structures::che::CheFile;
use topolab_structures::checks::{self, Options, Report};
use topolab_structures::io::echo;
use topolab_structures::io::RawSoup;
use topolab_structures::meshes::MeshSize;
use topolab_structures::summary::shown;
use topolab_structures::PolygonSoup;

/// Components listed one by one in the text report (JSON lists them all).
const LISTED_COMPONENTS: usize = 10;

/// Arguments of `topolab check`.
#[derive(clap::Args, Debug)]
pub struct CheckArgs {
    /// The mesh file (.obj, .off, .ply, .stl), or a .che file (the CHE's containers: its
    /// checksum, every id's range and the level's invariants are verified).
    pub file: PathBuf,
    /// Print the findings and summary as JSON.
    #[arg(long)]
    pub json: bool,
    /// Distance under which positions are equal (duplicate vertices) and a face counts as
    /// flat to a line (degenerate).
    #[arg(long, default_value_t = Options::default().tolerance, value_parser = tolerance)]
    pub tolerance: f64,
    /// Largest distance of a corner from its face's plane, relative to the face's size.
    #[arg(long, default_value_t = Options::default().planarity_tolerance, value_parser = tolerance)]
    pub planarity_tolerance: f64,
}

/// A tolerance: a finite number, at least 0. NaN would make every comparison false (no
/// duplicate, every face planar: a clean report of a broken file), and a negative or infinite
/// one means nothing.
fn tolerance(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(t) if t.is_finite() && t >= 0.0 => Ok(t),
        Ok(_) => Err("a tolerance is a finite number, at least 0".into()),
        Err(e) => Err(e.to_string()),
    }
}

/// Reads the file as written, refusing first what is not a regular file, or what would not fit
/// in memory: reading it ([`limits::read_mesh_bytes`]), then the mesh and the checks on it,
/// measured on two samples and scaled by elements ([`limits::elements`]): the sample mesh of
/// [`limits::sample_mesh`] (one component, each vertex shared) and as many separate triangles
/// (a component, three vertices and a grid cell of their own each), whose bytes per element
/// are the larger of the two.
fn read(args: &CheckArgs, options: &Options) -> Result<RawSoup, Failure> {
    let name = args.file.display().to_string();
    let bytes = input_file(&args.file)?;
    limits::admit(
        &format!("reading {name}"),
        limits::read_mesh_bytes(&args.file, bytes),
    )?;
    let raw = topolab_structures::io::read_raw(&args.file).map_err(|e| Failure {
        message: format!("cannot read {name}: {e}"),
        code: 2,
    })?;
    crate::input::warn_skipped(&name, &raw.skipped);
    let elements = limits::elements(&MeshSize::of(&raw.soup));
    let samples = [limits::sample_mesh(), limits::separate_triangles()];
    let sample_elements = |s: &PolygonSoup| limits::elements(&MeshSize::of(s));
    if elements > samples.iter().map(sample_elements).min().unwrap_or(0) {
        let work = samples
            .into_iter()
            .map(|soup| {
                let n = sample_elements(&soup);
                let sample = RawSoup {
                    soup,
                    ..RawSoup::default()
                };
                // The checks take the mesh read, as they take the sample here.
                let ((), peak) = limits::peak_of(|| {
                    checks::check_owned(sample, options);
                });
                limits::scale(peak, n, elements)
            })
            .max()
            .unwrap_or(0);
        // The mesh stays alive during the checks: counted with them.
        let soup = MeshSize::of(&raw.soup).soup_bytes();
        limits::admit(&format!("checking {name}"), soup.saturating_add(work))?;
    }
    Ok(raw)
}

/// The report on `args.file` (a mesh file, not a `.che` file), read and checked after the
/// refusals of what is not a file or would not fit in memory: what `topolab check` prints.
pub fn report(args: &CheckArgs) -> Result<Report, Failure> {
    let options = Options {
        tolerance: args.tolerance,
        planarity_tolerance: args.planarity_tolerance,
        ..Options::default()
    };
    let raw = read(args, &options)?;
    Ok(checks::check_owned(raw, &options))
}

/// Runs the check, prints the report; returns the exit code.
pub fn run(args: CheckArgs) -> u8 {
    if is_che_file(&args.file) {
        return run_che(&args);
    }
    let report = match report(&args) {
        Ok(report) => report,
        Err(e) => {
            crate::output::say(&e.message);
            return e.code;
        }
    };
    let name = args.file.display().to_string();
    let printed = if args.json {
        let mut v = serde_json::to_value(&report).expect("serialisable");
        v["file"] = name.clone().into();
        v["clean"] = report.is_clean().into();
        let json = serde_json::to_string_pretty(&v).expect("serialisable") + "\n";
        crate::output::print(&json)
    } else {
        crate::output::print(&text(&name, &report))
    };
    if let Err(e) = printed {
        crate::output::say(&e.message);
        return e.code;
    }
    if report.is_clean() {
        0
    } else {
        // The findings are on stdout; the reason for exit code 1 goes with the other refusals.
        crate::output::say(&format!(
            "{}: {} problems found",
            echo::path(&args.file),
            report.total()
        ));
        1
    }
}

/// The report for people: findings grouped by kind (the first few of each), then the summary.
fn text(name: &str, report: &Report) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "file: {name}");
    if report.is_clean() {
        let _ = writeln!(out, "no problems found");
    }
    for kind in checks::FindingKind::ALL {
        let count = report.count(kind);
        if count == 0 {
            continue;
        }
        let _ = writeln!(out, "{} ({count}):", kind.name());
        let kept = report.findings.iter().filter(|f| f.kind == kind);
        let mut listed = 0;
        for f in kept {
            let _ = writeln!(out, "  {}", f.message);
            listed += 1;
        }
        if count > listed {
            let _ = writeln!(out, "  ... and {} more", count - listed);
        }
    }
    let cut = report.summary.near_duplicates_not_exhaustive;
    if cut > 0 {
        let _ = writeln!(
            out,
            "note: {cut} vertices lie among more than {} distinct positions within twice the tolerance of each other; each was compared with {} of them, so near duplicates among them may be missed",
            checks::NEAR_DUPLICATES_COMPARED,
            checks::NEAR_DUPLICATES_COMPARED
        );
    }
    let s = &report.summary;
    let _ = writeln!(out, "summary:");
    let _ = writeln!(
        out,
        "  vertices {}, faces {} ({} usable), edges {}, boundary edges {}, boundary curves {}",
        s.vertices,
        s.faces,
        s.usable_faces,
        s.edges,
        s.boundary_edges,
        shown(s.boundary_curves, s.boundary_curves_undefined)
    );
    let _ = writeln!(
        out,
        "  euler characteristic {}, components {}",
        s.euler_characteristic,
        s.components.len()
    );
    for (i, c) in s.components.iter().enumerate().take(LISTED_COMPONENTS) {
        let genus = c.genus.map_or("undefined".to_string(), |g| g.to_string());
        let _ = writeln!(
            out,
            "  component {i}: {} faces, {} vertices, {} edges, {} boundary curves, χ {}, {}, {}, genus {genus}",
            c.faces,
            c.vertices,
            c.edges,
            c.boundary_curves
                .map_or("undefined".to_string(), |n| n.to_string()),
            c.euler_characteristic,
            if c.manifold { "manifold" } else { "non-manifold" },
            if c.orientable { "orientable" } else { "non-orientable" },
        );
    }
    if s.components.len() > LISTED_COMPONENTS {
        let _ = writeln!(
            out,
            "  ... and {} more components (`--json` lists them all)",
            s.components.len() - LISTED_COMPONENTS
        );
    }
    out
}

/// `topolab check FILE.che`: maps the file (a bad header or length: exit code 2), then reads
/// it all ([`CheFile::check`]): the checksum, the range of every id, the header's edge count
/// and the level's invariants, those of the structure's `validate()` (exit code 1 for the
/// first problem found, 0 when there is none). The tolerances do not apply: a `.che` file
/// stores a structure that was built, not a face list to inspect.
fn run_che(args: &CheckArgs) -> u8 {
    let name = args.file.display().to_string();
    let file = match CheFile::open(&args.file) {
        Ok(file) => file,
        Err(e) => {
            // The error names the file.
            crate::output::say(&e.to_string());
            return 2;
        }
    };
    let h = file.header();
    let checked = file.check();
    let printed = if args.json {
        let v = serde_json::json!({
            "file": name,
            "format": "che",
            "level": h.level,
            "vertices": h.vertices,
            "edges": h.edges,
            "faces": h.triangles,
            "bytes": file.file_bytes(),
            "clean": checked.is_ok(),
            "problem": checked.as_ref().err().map(|e| serde_json::json!({
                "kind": e.kind(),
                "message": e.to_string(),
            })),
        });
        crate::output::print(&(serde_json::to_string_pretty(&v).expect("serialisable") + "\n"))
    } else {
        let mut out = String::new();
        let _ = writeln!(out, "file: {name}");
        let _ = writeln!(
            out,
            "CHE level {} (che-l{}): {} vertices, {} edges, {} triangles, {} bytes",
            h.level,
            h.level,
            h.vertices,
            h.edges,
            h.triangles,
            file.file_bytes()
        );
        match &checked {
            Ok(()) => {
                let _ = writeln!(
                    out,
                    "checksum, id ranges, edge count and the level's invariants (validate()): ok"
                );
                let _ = writeln!(out, "no problems found");
            }
            Err(e) => {
                let _ = writeln!(out, "problem: {e}");
            }
        }
        crate::output::print(&out)
    };
    if let Err(e) = printed {
        crate::output::say(&e.message);
        return e.code;
    }
    match checked {
        Ok(()) => 0,
        Err(e) => {
            crate::output::say(&e.to_string());
            1
        }
    }
}
