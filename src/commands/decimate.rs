//! `topolab decimate`: decimation by quadric error
//! ([`topolab_structures::algorithms::decimate`], after OpenMesh's `DecimaterT` with
//! `ModQuadricT`: area-weighted face quadrics, half-edge collapses onto an end vertex, the
//! link condition through [`topolab_structures::MeshEdit`]'s collapse test) on the index or
//! the pointer half-edge (the editable structures the decimation suite enrols), to a face
//! count, and the result written. `--strategy` chooses how candidates
//! are kept ([`Strategy`]): `lazy`, the default, because its normal-flipping test keeps flat
//! regions from decimating into zero-area triangles, which `topolab check` would report in
//! the file written; `eager` runs OpenMesh's Decimater step for step, as the report compares
//! it with OpenMesh's own.
//!
//! Refused before any work, nothing written (exit 2): a bad `--ratio`, a `--structure` other
//! than those two, an unknown `--strategy`, an unwritable output, a mesh past
//! `u32` ids or the available memory. Refused once read, nothing written (exit 1): polygons (the decimater collapses
//! triangles), input the half-edge cannot store (non-manifold, inconsistently oriented), and
//! a target below what the topology allows
//! ([`minimum_faces`]: per closed component of genus g, `2 (V − 2 + 2g)` faces with V
//! Heawood's fewest vertices, 4 faces for a sphere, 14 for a torus; one per component with a
//! boundary, whose vertices stay). The output is written atomically
//! ([`crate::output::write_mesh`]).

use crate::input::{load_mesh, refuse_empty, Failure};
use crate::output::{check_mesh_out, write_mesh};
use std::path::PathBuf;
use std::time::Instant;
use topolab_structures::algorithms::changing::to_soup;
use topolab_structures::algorithms::decimate::{decimate, minimum_faces, Strategy};
use topolab_structures::{IndexHalfEdge, MeshEdit, MeshTopology, PointerHalfEdge, PolygonSoup};

/// Options of `topolab decimate`.
#[derive(clap::Args, Debug, Clone)]
#[command(group = clap::ArgGroup::new("target").required(true).args(["faces", "ratio"]))]
pub struct DecimateArgs {
    /// A triangle mesh file (.obj, .off, .ply, .stl) or a built-in mesh (see `topolab info --help`).
    pub mesh: String,
    /// Decimate to at most this many faces.
    #[arg(long)]
    pub faces: Option<usize>,
    /// Decimate to this fraction of the faces (0 < R ≤ 1).
    #[arg(long)]
    pub ratio: Option<f64>,
    /// The output file (.obj, .off or .stl).
    #[arg(long)]
    pub out: PathBuf,
    /// The editable structure that decimates: `index-half-edge` or `pointer-half-edge`.
    #[arg(long, default_value = "index-half-edge")]
    pub structure: String,
    /// How candidates are kept: `lazy` (tested for legality when they leave the heap, and a
    /// collapse that would flip or flatten a face skipped, so flat regions keep their area)
    /// or `eager` (OpenMesh's `DecimaterT` with `ModQuadricT` alone, step for step).
    #[arg(long, default_value = "lazy", value_parser = parse_strategy)]
    pub strategy: Strategy,
}

/// `--strategy`'s parser: a [`Strategy`] by its name.
fn parse_strategy(name: &str) -> Result<Strategy, String> {
    Strategy::from_name(name).ok_or_else(|| {
        let names: Vec<&str> = Strategy::ALL.iter().map(|s| s.name()).collect();
        format!("the strategies are {}", names.join(", "))
    })
}

/// The structures `--structure` takes: the editable structures the decimation suite enrols
/// (`structures/tests/decimating.rs`); the decimater is generic over [`MeshEdit`], the others
/// are not tested with it.
const EDITABLE: [&str; 2] = ["index-half-edge", "pointer-half-edge"];

/// Runs `topolab decimate`.
pub fn run(args: &DecimateArgs) -> Result<String, Failure> {
    if let Some(r) = args.ratio {
        if !(r > 0.0 && r <= 1.0) {
            return Err(Failure::usage(format!(
                "--ratio {r}: the fraction of faces to keep must be in (0, 1]"
            )));
        }
    }
    if !EDITABLE.contains(&args.structure.as_str()) {
        return Err(Failure::usage(format!(
            "--structure {}: decimation runs on {} only: the decimater is written over MeshEdit, but of the editable structures only these two are enrolled in the decimation suite, which tests decimation and the reconstruction by vertex splits on them",
            args.structure,
            EDITABLE.join(" and ")
        )));
    }
    check_mesh_out(&args.out)?;
    let spec = args.mesh.as_str();
    // The work measured on the sample mesh (and scaled by corners): the structure, its
    // decimation and the soup written.
    let soup = load_mesh(spec, |s| {
        if let Ok(mut m) = IndexHalfEdge::from_soup(s) {
            let _ = decimate(&mut m, s.num_faces() / 10, args.strategy);
            m.garbage_collection();
            drop(to_soup(&m));
        }
        0
    })?;
    refuse_empty(spec, &soup)?;
    if let Some((face, corners)) = soup.first_non_triangle() {
        return Err(Failure {
            message: format!(
                "cannot decimate {spec}: the decimater collapses triangles, but face {face} has {corners} corners"
            ),
            code: 1,
        });
    }
    match args.structure.as_str() {
        "pointer-half-edge" => decimate_with::<PointerHalfEdge>(args, &soup),
        _ => decimate_with::<IndexHalfEdge>(args, &soup),
    }
}

fn decimate_with<M: MeshEdit>(args: &DecimateArgs, soup: &PolygonSoup) -> Result<String, Failure> {
    let spec = args.mesh.as_str();
    let refused = |e: topolab_structures::Error| Failure {
        message: format!("cannot decimate {spec}: {e}"),
        code: 1,
    };
    let started = Instant::now();
    let mut m = M::from_soup(soup).map_err(refused)?;
    let faces = soup.num_faces();
    let target = match (args.faces, args.ratio) {
        (Some(n), _) => n,
        (None, Some(r)) => (r * faces as f64).round() as usize,
        (None, None) => faces,
    };
    let least = minimum_faces(&m);
    if target < least {
        return Err(Failure {
            message: format!(
                "cannot decimate {spec} to {target} faces: its topology needs at least {least} \
                 (per closed component of genus g, 2 (V - 2 + 2g) faces with V the fewest vertices \
                 that triangulate it: 4 faces for a sphere, 14 for a torus; one per component with \
                 a boundary, whose vertices are kept)"
            ),
            code: 1,
        });
    }
    let d = decimate(&mut m, target, args.strategy).map_err(refused)?;
    m.garbage_collection();
    let result = to_soup(&m);
    drop(m);
    write_mesh(&args.out, &result)?;
    let short = if d.faces_after > target {
        format!(" (no legal collapse left above {target})")
    } else {
        String::new()
    };
    Ok(format!(
        "{spec}: {} faces decimated to {} by {} collapses on {} ({} strategy){short}: {} vertices, written to {} ({:.2} s)\n",
        d.faces_before,
        d.faces_after,
        d.collapses.len(),
        args.structure,
        args.strategy,
        result.num_vertices(),
        args.out.display(),
        started.elapsed().as_secs_f64()
    ))
}
