//! What the subcommands share: reading a mesh named on the command line, and the
//! [`Failure`] a command returns (its message and exit code).

use crate::registry;
use std::path::PathBuf;
use topolab_structures::{meshes, Error, PolygonSoup};

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

/// Refuses a mesh with no vertex and no face (exit code 1): every count of it would be 0 and
/// "manifold" or "genus" would be vacuous; `topolab check` reports it as `empty-mesh`.
pub fn refuse_empty(spec: &str, soup: &PolygonSoup) -> Result<(), Failure> {
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

/// The mesh `explain` shows: the one named, or the open tetrahedron (a 2x2 grid for grid-only
/// structures, which cannot store it); with a label for it.
pub fn mesh_or_tetrahedron(
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
            "the open tetrahedron of the CHE thesis chapter's Figure 4.10 (apex 3, triangle t = (t, t+1 mod 3, 3))".to_string(),
        ),
    })
}

/// The failure for a structure name that is not in this build (OpenMesh says how to get it).
pub fn unknown_structure(name: &str) -> Failure {
    if name == registry::OPENMESH {
        return Failure::usage(format!("{name}: {}", crate::OPENMESH_MISSING));
    }
    Failure::usage(format!(
        "unknown structure {name:?}; known: {}",
        registry::NAMES.join(", ")
    ))
}
