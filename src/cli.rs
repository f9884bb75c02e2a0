//! The `topolab` commands. Each returns an exit code: 0 success, 1 when the input was read
//! but a structure refused it (or problems were found), 2 when the input cannot be read.

use crate::registry::{self, StructureVisitor};
use clap::{Parser, Subcommand};
use std::fmt::Write as _;
use std::path::PathBuf;
use topolab_structures::summary::{summarize, Summary};
use topolab_structures::{meshes, Capabilities, Error, MeshTopology, Operator, PolygonSoup};

/// A lab of mesh data structures: build, query, explain and measure them side by side.
#[derive(Parser, Debug)]
#[command(name = "topolab", version, about)]
pub struct Cli {
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
    },
    /// Counts, boundary curves, Euler characteristic and genus of a mesh, computed through a structure.
    Info {
        /// A mesh file (.obj, .off, .ply) or a built-in mesh (see `topolab info --help`):
        /// a canonical mesh name such as `open-tetrahedron`, or `torus:N`, `sphere:N`,
        /// `grid:N`, `quad-grid:N`, `mixed:N`, `genus:G:N`, `holes:K:N`, `surface:G:K:N`
        /// for about N faces.
        mesh: String,
        /// The structure that answers the queries (`index-half-edge` by default: it answers
        /// every query in O(k); the scanning structures such as `vertex-list` take O(n²) on
        /// the boundary curves, minutes on a 100k-face mesh).
        #[arg(long, default_value = "index-half-edge")]
        structure: String,
        /// Print JSON.
        #[arg(long)]
        json: bool,
    },
    /// The lecture's consistency checks on a mesh file: every problem, with the elements it
    /// concerns. Exit code 0 when clean, 1 when problems were found, 2 when unreadable.
    Check(crate::check::CheckArgs),
    /// For teaching: what a structure stores for the CHE chapter's open tetrahedron (Figure 4.10).
    Explain {
        /// The structure (see `topolab list`), or `che` for the four CHE levels side by side.
        name: String,
        /// Explain this mesh (a file or built-in mesh) instead of the open tetrahedron.
        #[arg(long)]
        mesh: Option<String>,
        /// With `explain che`: print the steps of this relation's algorithm at each level
        /// (`r00`, `r01` or `r02`: the vertex star) instead of the containers.
        #[arg(long, requires = "vertex")]
        trace: Option<String>,
        /// The vertex whose star `--trace` follows.
        #[arg(long)]
        vertex: Option<u32>,
    },
    /// Measure every operator on every structure and write results.json and index.html.
    Report(crate::report::ReportArgs),
    /// Subdivide a triangle mesh N times (each level: 4 triangles per triangle) and write it.
    Refine {
        /// A triangle mesh file (.obj, .off, .ply) or a built-in mesh (see `topolab info --help`).
        mesh: String,
        /// Number of levels.
        #[arg(long)]
        levels: usize,
        /// Where new vertices go: `midpoint` (same shape) or `loop` (smooth).
        #[arg(long, default_value = "midpoint")]
        scheme: String,
        /// The output file (.obj or .off).
        #[arg(long)]
        out: PathBuf,
        /// Renumber the result: `input` (as refined: new vertices appended), `random`,
        /// `random:SEED`, `morton`, `hilbert` or `bfs` (see `topolab_structures::ordering`).
        #[arg(long, default_value = "input")]
        order: String,
    },
    /// The 3D convex hull of a point file or random points, by one of seed 004's algorithms.
    Hull(crate::hull::HullArgs),
}

/// Runs a parsed command line; returns the process exit code.
pub fn run(cli: Cli) -> u8 {
    let result = match cli.command {
        Command::List { json } => list(json),
        Command::Info {
            mesh,
            structure,
            json,
        } => info(&mesh, &structure, json),
        Command::Explain {
            name,
            mesh,
            trace,
            vertex,
        } if name == crate::explain_che::NAME => {
            crate::explain_che::explain_che(mesh.as_deref(), trace.as_deref(), vertex)
        }
        Command::Explain {
            name, mesh, trace, ..
        } => match trace {
            Some(_) => Err(Failure::usage(format!(
                "--trace works with `explain {}` only",
                crate::explain_che::NAME
            ))),
            None => explain(&name, mesh.as_deref()),
        },
        Command::Report(args) => {
            let command = std::env::args().collect::<Vec<_>>().join(" ");
            crate::report::report(&args, command)
        }
        Command::Refine {
            mesh,
            levels,
            scheme,
            out,
            order,
        } => crate::refine::refine(&mesh, levels, &scheme, &order, &out),
        Command::Check(args) => return crate::check::run(args),
        Command::Hull(args) => crate::hull::hull(&args),
    };
    match result {
        Ok(text) => {
            print!("{text}");
            0
        }
        Err(e) => {
            eprintln!("topolab: {}", e.message);
            e.code
        }
    }
}

/// A failed command: what to tell the user and the exit code.
#[derive(Debug)]
pub struct Failure {
    /// The message, with context.
    pub message: String,
    /// The exit code.
    pub code: u8,
}

impl Failure {
    fn unreadable(what: &str, e: Error) -> Self {
        Self {
            message: format!("cannot read {what}: {e}"),
            code: 2,
        }
    }
    /// A usage error (exit code 2).
    pub fn usage(message: String) -> Self {
        Self { message, code: 2 }
    }
}

/// Loads a mesh named on the command line: a file, or a built-in mesh.
pub fn load_mesh(spec: &str) -> Result<PolygonSoup, Failure> {
    let path = PathBuf::from(spec);
    if path.exists() {
        let soup = topolab_structures::io::read(&path).map_err(|e| Failure::unreadable(spec, e))?;
        return Ok(soup);
    }
    meshes::from_spec(spec).ok_or_else(|| {
        let names: Vec<&str> = meshes::canonical().iter().map(|m| m.name).collect();
        Failure::usage(format!(
            "no file {spec:?}, and it is not a built-in mesh ({}, or torus:N, sphere:N, grid:N, quad-grid:N, mixed:N, genus:G:N, holes:K:N, surface:G:K:N)",
            names.join(", ")
        ))
    })
}

/// The usage error for a structure name this build does not have.
pub(crate) fn unknown_structure(name: &str) -> Failure {
    if name == registry::OPENMESH {
        return Failure::usage(format!("{name}: {}", crate::OPENMESH_MISSING));
    }
    Failure::usage(format!(
        "unknown structure {name:?}; known: {}",
        registry::NAMES.join(", ")
    ))
}

#[derive(serde::Serialize)]
struct StructureRow {
    name: &'static str,
    capabilities: Capabilities,
    costs: Vec<(&'static str, &'static str)>,
}

struct Row;
impl StructureVisitor for Row {
    type Output = StructureRow;
    fn visit<M: MeshTopology>(self) -> StructureRow {
        StructureRow {
            name: M::NAME,
            capabilities: M::capabilities(),
            costs: Operator::ALL
                .iter()
                .map(|&op| (op.name(), M::cost(op).notation()))
                .collect(),
        }
    }
}

fn list(json: bool) -> Result<String, Failure> {
    let rows: Vec<StructureRow> = registry::NAMES
        .iter()
        .map(|n| registry::visit(n, Row).expect("registered"))
        .collect();
    if json {
        let ops: Vec<_> = topolab_harness::catalogue::CATALOGUE.to_vec();
        let v = serde_json::json!({ "structures": rows, "operators": ops });
        return Ok(serde_json::to_string_pretty(&v).expect("serialisable") + "\n");
    }
    let mut out = String::new();
    let _ = writeln!(out, "Structures and the theoretical cost of each operator");
    let _ = writeln!(
        out,
        "(n: elements scanned, k: local size (valence or face size), ∂n1: boundary edges)\n"
    );
    // Columns as wide as the longest structure name (`pointer-half-edge`) plus a gap.
    let width = rows
        .iter()
        .map(|r| r.name.len() + 2)
        .max()
        .unwrap_or(0)
        .max(14);
    let _ = write!(out, "{:<18}", "operator");
    for r in &rows {
        let _ = write!(out, "{:>width$}", r.name);
    }
    out.push('\n');
    for (i, spec) in topolab_harness::catalogue::CATALOGUE.iter().enumerate() {
        let _ = write!(out, "{:<18}", spec.name);
        for r in &rows {
            let _ = write!(out, "{:>width$}", r.costs[i].1);
        }
        out.push('\n');
    }
    out.push('\n');
    for r in &rows {
        let c = r.capabilities;
        let _ = writeln!(
            out,
            "{:<width$} {}{}{}{}",
            r.name,
            if c.triangles_only {
                "triangles only"
            } else {
                "polygons"
            },
            if c.non_manifold_vertices {
                ", non-manifold vertices"
            } else {
                ""
            },
            if c.grids_only {
                ", regular grids only"
            } else {
                ""
            },
            if c.distinct_positions {
                ", distinct positions"
            } else {
                ""
            },
        );
    }
    let _ = writeln!(out, "\noperators:");
    for spec in &topolab_harness::catalogue::CATALOGUE {
        let _ = writeln!(out, "  {:<18}{}", spec.name, spec.about);
    }
    Ok(out)
}

struct InfoVisit<'a>(&'a PolygonSoup);
impl StructureVisitor for InfoVisit<'_> {
    type Output = Result<Summary, Error>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        let m = M::from_soup(self.0)?;
        Ok(summarize(&m))
    }
}

/// Refuses a mesh with no vertex and no face (exit code 1): every count of it would be 0 and
/// "manifold" or "genus" would be vacuous; `topolab check` reports it as `empty-mesh`.
fn refuse_empty(spec: &str, soup: &PolygonSoup) -> Result<(), Failure> {
    if soup.num_vertices() == 0 && soup.num_faces() == 0 {
        return Err(Failure {
            message: format!(
                "{spec} is an empty mesh: it has no vertices and no faces (`topolab check` reports it as empty-mesh)"
            ),
            code: 1,
        });
    }
    Ok(())
}

fn info(spec: &str, structure: &str, json: bool) -> Result<String, Failure> {
    let soup = load_mesh(spec)?;
    refuse_empty(spec, &soup)?;
    let summary = registry::visit(structure, InfoVisit(&soup))
        .ok_or_else(|| unknown_structure(structure))?
        .map_err(|e| Failure {
            message: format!("{structure} cannot store {spec}: {e}"),
            code: 1,
        })?;
    let non_manifold_vertices = soup
        .connectivity()
        .map(|c| c.vertex_fans(&soup).iter().filter(|&&n| n > 1).count())
        .unwrap_or(0);
    if json {
        let mut v = serde_json::to_value(&summary).expect("serialisable");
        v["mesh"] = spec.into();
        v["non_manifold_vertices"] = non_manifold_vertices.into();
        return Ok(serde_json::to_string_pretty(&v).expect("serialisable") + "\n");
    }
    let s = &summary;
    let mut out = String::new();
    let _ = writeln!(out, "mesh:                 {spec}");
    let _ = writeln!(out, "structure:            {}", s.structure);
    let _ = writeln!(
        out,
        "vertices:             {} ({} unused)",
        s.vertices, s.unused_vertices
    );
    let _ = writeln!(out, "edges:                {}", s.edges);
    let _ = writeln!(
        out,
        "faces:                {} ({})",
        s.faces,
        if s.triangles_only {
            "triangles"
        } else {
            "polygons"
        }
    );
    let _ = writeln!(out, "boundary edges:       {}", s.boundary_edges);
    let _ = writeln!(out, "boundary curves:      {}", s.boundary_curves);
    let _ = writeln!(out, "components:           {}", s.components);
    let _ = writeln!(out, "euler characteristic: {}", s.euler_characteristic);
    match s.genus {
        Some(g) => writeln!(out, "genus:                {g}"),
        None => writeln!(
            out,
            "genus:                undefined ({} components)",
            s.components
        ),
    }
    .ok();
    let _ = writeln!(
        out,
        "manifold:             {}",
        if non_manifold_vertices == 0 {
            "yes (oriented, every vertex one fan)".to_string()
        } else {
            format!("edges yes, {non_manifold_vertices} non-manifold vertices")
        }
    );
    Ok(out)
}

struct ExplainVisit<'a>(&'a PolygonSoup);
impl StructureVisitor for ExplainVisit<'_> {
    type Output = Result<String, Error>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        let m = M::from_soup(self.0)?;
        let mut out = String::new();
        m.explain(&mut out)
            .expect("writing to a String cannot fail");
        Ok(out)
    }
}

/// The mesh `explain` shows: the one named, or the open tetrahedron (a 2x2 grid for grid-only
/// structures, which cannot store it); with a label for it.
pub(crate) fn mesh_or_tetrahedron(
    mesh: Option<&str>,
    grids_only: bool,
) -> Result<(PolygonSoup, String), Failure> {
    Ok(match mesh {
        Some(spec) => {
            let soup = load_mesh(spec)?;
            refuse_empty(spec, &soup)?;
            (soup, spec.to_string())
        }
        // The tetrahedron is not a grid: grid-only structures explain a 2x2 grid instead.
        None if grids_only => (
            meshes::grid(2, 2, true),
            "a 2x2 triangulated grid (the open tetrahedron is not a grid)".to_string(),
        ),
        None => (
            meshes::open_tetrahedron(),
            "the open tetrahedron of the CHE chapter's Figure 4.10 (apex 3, triangle t = (t, t+1 mod 3, 3))".to_string(),
        ),
    })
}

fn explain(name: &str, mesh: Option<&str>) -> Result<String, Failure> {
    let grids_only = registry::visit(name, Row).is_some_and(|r| r.capabilities.grids_only);
    let (soup, label) = mesh_or_tetrahedron(mesh, grids_only)?;
    let text = registry::visit(name, ExplainVisit(&soup))
        .ok_or_else(|| unknown_structure(name))?
        .map_err(|e| Failure {
            message: format!("{name} cannot store {label}: {e}"),
            code: 1,
        })?;
    Ok(format!("{name} for {label}\n\n{text}"))
}
