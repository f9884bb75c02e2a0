//! The `topolab` command line: parsed here (clap), run by [`crate::commands`]. Each command
//! returns an exit code: 0 success, 1 when the input was read but a structure refused it (or
//! problems were found), 2 when the input cannot be read or the request cannot fit (ids past
//! u32, more memory than is available, an output that cannot be written: see
//! [`crate::limits`] and [`crate::output`]), checked before the work starts.

use crate::commands;
use clap::error::ErrorKind;
use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;

/// A lab of mesh data structures: build, query, explain and measure them side by side.
#[derive(Parser, Debug)]
#[command(name = "topolab", version, about)]
pub struct Cli {
    /// Run even when the estimated memory of the request exceeds what the system has available
    /// (counts past u32 ids are refused whatever this says).
    #[arg(long, global = true)]
    pub allow_memory: bool,
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// List the structures, the operators and each structure's theoretical cost per operator.
    List {
        /// Print JSON instead of a table.
        #[arg(long)]
        json: bool,
        /// Add each editing operation's counted reads on every structure, on tori of about
        /// 128 and 2,000 faces, beside the declared costs (a few seconds).
        #[arg(long)]
        counted: bool,
    },
    /// Counts, boundary curves, Euler characteristic and genus of a mesh, computed through a structure.
    Info {
        /// A mesh file (.obj, .off, .ply, .stl) or a built-in mesh (see `topolab info --help`):
        /// a canonical mesh name such as `open-tetrahedron`, or `torus:N`, `sphere:N`,
        /// `grid:N`, `quad-grid:N`, `mixed:N`, `genus:G:N`, `holes:K:N`, `surface:G:K:N`
        /// for about N faces.
        mesh: String,
        /// The structure that answers the queries (`index-half-edge` by default: it answers
        /// every query in O(k); the scanning structures such as `vertex-list` take O(n²) on
        /// the boundary curves, minutes on a 100k-face mesh). A .che file is answered by the
        /// level it holds, whatever this says.
        #[arg(long)]
        structure: Option<String>,
        /// Print JSON.
        #[arg(long)]
        json: bool,
    },
    /// The consistency checks of the lecture on polygon-mesh data structures on a mesh file: every
    /// problem, with the elements it concerns. Exit code 0 when clean, 1 when problems were found,
    /// 2 when unreadable.
    Check(commands::check::CheckArgs),
    /// Repair what `topolab check` finds in a mesh's topology: drop duplicate faces, split
    /// non-manifold edges and vertices, orient each orientable component, drop unused vertices;
    /// write the result and say what changed and what remains. Exit code 0 when nothing of
    /// that remains, 1 when something does (a non-orientable component), 2 when unreadable.
    Repair(commands::repair::RepairArgs),
    /// For teaching: what a structure stores for the CHE thesis chapter's open tetrahedron
    /// (Figure 4.10).
    Explain {
        /// The structure (see `topolab list`), or `che` for the four CHE levels side by side.
        name: String,
        /// Explain this mesh (a file or built-in mesh) instead of the open tetrahedron.
        #[arg(long)]
        mesh: Option<String>,
        /// Print every container read of one query of this operator (`r00` ... `r22`,
        /// `boundary-vertex`, ...; see `topolab list`), then the answer and the number of reads.
        /// `explain che --trace r00 --vertex N` follows Algorithm 7 at each level.
        #[arg(long)]
        trace: Option<String>,
        /// The vertex `--trace` asks about, or the vertex `--op` edits (`delete-vertex`,
        /// `split-vertex` with `--vertices L,R`, `garbage-collection` after deleting it).
        #[arg(long)]
        vertex: Option<u32>,
        /// The edge `--trace` or `--op` asks about, numbered as the mesh's edges in order of
        /// first appearance (the edge list's ids) on every structure.
        #[arg(long)]
        edge: Option<u32>,
        /// The face `--trace` asks about, or the face `--op` edits (`delete-face`,
        /// `split-face`).
        #[arg(long)]
        face: Option<u32>,
        /// With `--op`, comma-separated vertices: the corners of `add-face`, the two of
        /// `weld-vertices` (the second merged into the first), or the left and right
        /// neighbours of `split-vertex --vertex V`.
        #[arg(long, value_delimiter = ',', requires = "op")]
        vertices: Vec<u32>,
        /// With `--op weld-edges`: the two boundary edges, comma-separated (the second sewn
        /// onto the first).
        #[arg(long, value_delimiter = ',', requires = "op")]
        edges: Vec<u32>,
        /// With `--op weld-faces`: the two faces, comma-separated (both removed, their
        /// boundaries sewn together).
        #[arg(long, value_delimiter = ',', requires = "op")]
        faces: Vec<u32>,
        /// With `--trace` or `--op`: more structures side by side, comma-separated (with
        /// `--op`, each explained, all counted side by side, and the same edit counted on
        /// tori of growing size).
        #[arg(long, value_delimiter = ',')]
        structures: Vec<String>,
        /// Do one edit (any editing operation, by its name; `flip`, `split` and `collapse` for
        /// the three edge operations) on the element `--edge`, `--face`, `--vertex`,
        /// `--vertices`, `--edges` or `--faces` names, as the operation needs, and print the records it writes,
        /// old -> new, and what it reads (`collapse-edge`: the edge's first vertex into its
        /// second). A refused edit exits with code 1 and the reason. Without an element, the
        /// first on which the edit succeeds (on the open tetrahedron, or, where none does, on
        /// the canonical `grid`, the `quad-strip` or a torus), named, with one where it is
        /// refused and why.
        /// `explain che --op ...` edits the four CHE levels.
        #[arg(long, value_enum, conflicts_with = "trace")]
        op: Option<commands::explain_edit::ExplainOp>,
    },
    /// Measure every operator on every structure and write results.json and index.html.
    Report(commands::report::ReportArgs),
    /// Compare two report runs (their results.json): every cell measured in both, new/old,
    /// flagged when outside both runs' spread, the largest change first; text and an HTML page.
    /// Exit code 0 (it informs), 2 when a file is not a topolab results.json of a known format.
    Compare(commands::compare::CompareArgs),
    /// Refine a triangle mesh and write it: uniformly, `--levels N` of subdivision (each level:
    /// 4 triangles per triangle), or adaptively, `--max-edge L` (every edge longer than L split,
    /// inside `--region` if given, by longest-edge bisection on an editable structure).
    Refine(commands::refine::RefineArgs),
    /// The 3D convex hull of a point file or random points, by one of the algorithms of the
    /// lecture on 3D convex hulls.
    Hull(commands::hull::HullArgs),
    /// Subdivide a mesh N times and write it: `sqrt3` (√3 through the editing operations,
    /// 3 triangles per triangle and level), `midpoint` or `loop` (4 per level).
    Subdivide {
        /// A triangle mesh file (.obj, .off, .ply, .stl) or a built-in mesh (see `topolab info --help`).
        mesh: String,
        /// `sqrt3`, `midpoint` or `loop`.
        #[arg(long)]
        scheme: String,
        /// Number of levels.
        #[arg(long, default_value_t = 1)]
        levels: usize,
        /// The output file (.obj, .off or .stl).
        #[arg(long)]
        out: PathBuf,
    },
    /// Convert a mesh between the formats the lab reads (.obj, .off, .ply, .stl) and writes
    /// (.obj, .off, .ply, binary .stl), or to the CHE's containers as a memory-mappable .che
    /// file. A mesh the written file would not hold as it is (an empty mesh; in STL, coordinates
    /// beyond float or corners float cannot tell apart) is refused with exit code 1.
    Convert {
        /// A mesh file or a built-in mesh (see `topolab info --help`).
        mesh: String,
        /// The output file; its extension gives the format unless `--to` names it.
        out: PathBuf,
        /// The output format: `obj`, `off`, `ply` (binary little-endian unless `--ascii`),
        /// `stl` (binary) or `che` (docs/che-format.md).
        #[arg(long)]
        to: Option<String>,
        /// With `--to che`: the CHE level whose containers the file holds, 0 to 3 (default 2).
        #[arg(long)]
        level: Option<u8>,
        /// Write PLY as ASCII instead of binary little-endian.
        #[arg(long)]
        ascii: bool,
    },
    /// Decimate a triangle mesh by quadric error (as OpenMesh's Decimater with ModQuadric) to
    /// `--faces N` or `--ratio R` of its faces and write it; or through `--levels 50%,10%`,
    /// writing every level of detail and the collapse record into a folder.
    Decimate(commands::decimate::DecimateArgs),
    /// The largest mesh each structure holds on this machine: tori from 1k triangles up four
    /// times larger each step, each structure built and measured in a process of its own until
    /// the memory would not hold the next size (shown refused, with the estimate); then the CHE
    /// from a memory-mapped .che file, in memory and in a memory cgroup smaller than the file.
    /// Writes results.json and index.html (docs/scale.md).
    Scale(commands::scale::ScaleArgs),
    /// The scale run's worker: one structure on one torus, measured, as JSON.
    #[command(hide = true)]
    ScaleCell {
        /// The structure.
        #[arg(long)]
        structure: String,
        /// Triangles of the torus.
        #[arg(long)]
        triangles: u64,
    },
    /// The scale run's worker: a level-2 .che file opened and swept, as JSON.
    #[command(hide = true)]
    ScaleMapped {
        /// The .che file.
        file: PathBuf,
        /// Join the cgroup whose `cgroup.procs` this is first.
        #[arg(long)]
        cgroup_procs: Option<PathBuf>,
    },
    /// Rebuild a level of detail, by default the original, from the folder `decimate --levels`
    /// wrote: its coarsest mesh and its collapse record, undone by vertex splits.
    Reconstruct(commands::reconstruct::ReconstructArgs),
}

/// Runs a parsed command line; returns the process exit code.
pub fn run(cli: Cli) -> u8 {
    crate::limits::set_allow_memory(cli.allow_memory);
    let result = match cli.command {
        Command::List { json, counted } => commands::list::list(json, counted),
        Command::Info {
            mesh,
            structure,
            json,
        } => commands::info::info_through(&mesh, structure.as_deref(), json),
        Command::Explain {
            name,
            mesh,
            edge,
            face,
            vertex,
            vertices,
            edges,
            faces,
            structures,
            op: Some(op),
            ..
        } => commands::explain_edit::run(
            &name,
            mesh.as_deref(),
            op.0,
            &commands::explain_edit::Asked {
                edge,
                face,
                vertex,
                vertices,
                edges,
                faces,
            },
            &commands::explain_edit::Counting {
                // The comparison mode: the same edit on tori of growing size too.
                growth: !structures.is_empty(),
                beside: structures,
            },
        ),
        Command::Explain {
            trace: None,
            structures,
            ..
        } if !structures.is_empty() => Err(crate::failure::Failure::usage(format!(
            "--structures {}: names the structures shown beside NAME's with --trace OP or --op OP, and neither was given",
            structures.join(",")
        ))),
        Command::Explain {
            name,
            mesh,
            trace,
            vertex,
            edge,
            face,
            structures,
            op: None,
            ..
        } => commands::explain::run_traced(
            &name,
            mesh.as_deref(),
            trace.map(|op| commands::explain_trace::TraceRequest {
                op,
                query: topolab_harness::teaching::trace::Query { vertex, edge, face },
                structures,
            }),
        ),
        Command::Report(args) => {
            let command = std::env::args().collect::<Vec<_>>().join(" ");
            commands::report::report(&args, command)
        }
        Command::Refine(args) => commands::refine::run(&args),
        Command::Check(args) => return commands::check::run(args),
        Command::Repair(args) => return commands::repair::run(args),
        Command::Hull(args) => commands::hull::hull(&args),
        Command::Compare(args) => commands::compare::compare(&args),
        Command::Subdivide {
            mesh,
            scheme,
            levels,
            out,
        } => commands::subdivide::subdivide(&mesh, &scheme, levels, &out),
        Command::Convert {
            mesh,
            out,
            to,
            level,
            ascii,
        } => commands::convert::convert(&mesh, &out, to.as_deref(), level, ascii),
        Command::Decimate(args) => commands::decimate::run(&args),
        Command::Reconstruct(args) => commands::reconstruct::run(&args),
        Command::Scale(args) => {
            let command = std::env::args().collect::<Vec<_>>().join(" ");
            commands::scale::scale(&args, command)
        }
        Command::ScaleCell {
            structure,
            triangles,
        } => commands::scale::cell(&structure, triangles),
        Command::ScaleMapped { file, cgroup_procs } => {
            commands::scale::sweep(&file, cgroup_procs.as_deref())
        }
    };
    match result {
        Ok(text) => match crate::output::print(&text) {
            Ok(()) => 0,
            Err(e) => {
                crate::output::say(&e.message);
                e.code
            }
        },
        Err(e) => {
            crate::output::say(&e.message);
            e.code
        }
    }
}

/// What clap's parse errors become: `--help` and `--version` (and `topolab` alone, which shows
/// the help) print as clap prints them; a bad command line is one line on stderr, like every
/// other refusal, with exit code 2.
pub fn usage_error(e: clap::Error) -> ExitCode {
    if !e.use_stderr() || e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
        e.exit()
    }
    crate::output::say(&one_line(&e.to_string()));
    ExitCode::from(2)
}

/// Clap's error text on one line: the message before the first blank line (the usage and tips
/// follow it), without its `error: ` prefix, lines joined, and a pointer to `--help`.
fn one_line(text: &str) -> String {
    let message = text.split("\n\n").next().unwrap_or(text);
    let message = message.strip_prefix("error: ").unwrap_or(message);
    let words: Vec<&str> = message.split_whitespace().collect();
    format!("{} (see --help)", words.join(" "))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parse_errors_are_one_line() {
        for args in [
            &["topolab", "refine", "torus"][..],
            &[
                "topolab", "refine", "torus", "--levels", "abc", "--out", "x.obj",
            ],
            &["topolab", "nope"],
            &["topolab", "list", "--json=yes"],
        ] {
            let e = Cli::try_parse_from(args).unwrap_err();
            let line = one_line(&e.to_string());
            assert!(!line.contains('\n') && !line.starts_with("error"), "{line}");
            assert!(line.len() > "(see --help)".len() + 5, "{args:?}: {line}");
        }
        let e = Cli::try_parse_from(["topolab", "refine", "torus"]).unwrap_err();
        assert!(one_line(&e.to_string()).contains("--levels <LEVELS>"));
    }
}
