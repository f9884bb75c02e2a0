//! `topolab reconstruct`: a level of detail rebuilt from the folder `topolab decimate
//! --levels` wrote, its coarsest mesh and its collapse record alone
//! ([`topolab_structures::algorithms::decimate::record`]): the record read and checked, the
//! coarse mesh checked against it (counts and fingerprint), built as `--structure`, and the
//! collapses undone by vertex splits, the last first
//! ([`reconstruct_from`]), up to the first state with at least `--to` faces (every split adds
//! two), by default the original. The state is written in the canonical form of
//! [`live_soup`]: its vertices in increasing original id, each face rotated to start at its
//! smallest vertex, faces sorted; the form of every file in the folder, so that the original
//! rebuilt is byte for byte the folder's `original.obj` (as OBJ: every position written as the
//! shortest decimal that reads back as the same `f64`), and a level's face count rebuilds
//! that level's file. A rebuilt state that is one of the record's levels, or the original, is
//! checked against the record's fingerprint before it is written.
//!
//! Refused, nothing written: with exit 2 a `--structure` outside the decimation suite, an
//! unwritable output, a missing folder, record or coarse mesh, a record that does not read or
//! does not hold together (another version, cut short, ids past the original's vertices, a
//! vertex removed twice), a `--to` below the coarse mesh's faces or above the original's, a
//! request past `u32` ids or the available memory; with exit 1 a coarse mesh that is not the
//! one the record was made with, or collapses the structure cannot undo on it.

use crate::commands::decimate::{check_structure, files};
use crate::input::{input_file, load_mesh, Failure};
use crate::limits;
use crate::output::{check_mesh_out, write_mesh};
use crate::registry::{self, EditVisitor};
use std::path::{Path, PathBuf};
use std::time::Instant;
use topolab_structures::algorithms::changing::to_soup;
use topolab_structures::algorithms::decimate::record::{Record, RecordError};
use topolab_structures::algorithms::decimate::{live_soup, reconstruct_from};
use topolab_structures::meshes::MeshSize;
use topolab_structures::{IndexHalfEdge, MeshEdit, MeshTopology, PolygonSoup};

/// Options of `topolab reconstruct`.
#[derive(clap::Args, Debug, Clone)]
pub struct ReconstructArgs {
    /// A folder written by `topolab decimate --levels` (its `coarse.obj` and `collapses.txt`
    /// are read).
    pub dir: PathBuf,
    /// Rebuild the first state with at least this many faces, going from the coarse mesh
    /// towards the original (each vertex split adds two faces); by default the original.
    #[arg(long)]
    pub to: Option<usize>,
    /// The output file (.obj, .off or .stl; .stl stores positions as f32).
    #[arg(long)]
    pub out: PathBuf,
    /// The structure that rebuilds: one the decimation suite enrols (see `topolab decimate
    /// --help`).
    #[arg(long, default_value = "index-half-edge")]
    pub structure: String,
}

/// `what` cannot be read (exit 2).
fn unreadable(what: &Path, why: impl std::fmt::Display) -> Failure {
    Failure::usage(format!("cannot read {}: {why}", what.display()))
}

/// Reads and checks the record of `dir`.
fn read_record(dir: &Path) -> Result<Record, Failure> {
    let path = dir.join(files::RECORD);
    let bytes = input_file(&path)?;
    limits::admit(
        &format!("reading {}", path.display()),
        limits::read_bytes(bytes),
    )?;
    let text = std::fs::read_to_string(&path).map_err(|e| unreadable(&path, e))?;
    Record::parse(&text).map_err(|e| unreadable(&path, e))
}

/// Runs `topolab reconstruct`.
pub fn run(args: &ReconstructArgs) -> Result<String, Failure> {
    check_structure(&args.structure)?;
    // The folder's coarse mesh is an input too.
    let coarse = args.dir.join(files::COARSE);
    check_mesh_out(&args.out, &coarse.to_string_lossy())?;
    match std::fs::metadata(&args.dir) {
        Err(e) => return Err(unreadable(&args.dir, e)),
        Ok(m) if !m.is_dir() => {
            return Err(unreadable(
                &args.dir,
                "it is not a folder (give the folder `topolab decimate --levels` wrote)",
            ))
        }
        Ok(_) => {}
    }
    let record = read_record(&args.dir)?;
    let (coarse_faces, original_faces) = (record.coarse.faces, record.original.faces);
    let faces = args.to.unwrap_or(original_faces);
    let keep = record.keep_for(faces).ok_or_else(|| {
        Failure::usage(format!(
            "--to {faces}: the record goes from {coarse_faces} faces (the coarse mesh) to {original_faces} (the original); ask for a count between them"
        ))
    })?;
    let size = MeshSize {
        vertices: record.original.vertices as u64,
        faces: record.original.faces as u64,
        corners: 3 * record.original.faces as u64,
    };
    let what = format!("reconstructing {}", args.dir.display());
    limits::mesh_within_u32(&what, &size)?;
    // The work, measured on the sample mesh and scaled to the original's corners: the
    // structure and the soups of the rebuilt mesh.
    let sample = limits::sample_mesh();
    let (_, peak) = limits::peak_of(|| {
        if let Ok(m) = IndexHalfEdge::from_soup(&sample) {
            let identity: Vec<u32> = (0..sample.num_vertices() as u32).collect();
            drop((live_soup(&m, &identity), to_soup(&m)));
        }
    });
    limits::admit(
        &what,
        limits::scale(peak, sample.num_corners() as u64, size.corners),
    )?;
    let coarse_path = args.dir.join(files::COARSE);
    input_file(&coarse_path)?;
    let spec = coarse_path.display().to_string();
    let coarse = load_mesh(&spec, |_| 0)?;
    record.coarse.check(&spec, &coarse).map_err(|e| Failure {
        message: e.to_string(),
        code: 1,
    })?;
    let started = Instant::now();
    let rebuilt = registry::visit_editable(
        &args.structure,
        Rebuild {
            coarse: &coarse,
            record: &record,
            keep,
        },
    )
    .expect("check_structure admitted an editable structure")
    .map_err(|message| Failure { message, code: 1 })?;
    let mismatch = |e: RecordError| Failure {
        message: e.to_string(),
        code: 1,
    };
    if keep == 0 {
        record
            .original
            .check("the original rebuilt", &rebuilt)
            .map_err(mismatch)?;
    } else if let Some(level) = record.level_keeping(keep) {
        let counts = topolab_structures::algorithms::decimate::record::Counts {
            vertices: rebuilt.num_vertices(),
            faces: level.faces,
            fingerprint: level.fingerprint,
        };
        counts
            .check("the level rebuilt", &rebuilt)
            .map_err(mismatch)?;
    }
    write_mesh(&args.out, &rebuilt)?;
    let state = match (keep, record.level_keeping(keep)) {
        (0, _) => "the original".to_string(),
        (_, Some(_)) => {
            let i = record
                .levels
                .iter()
                .position(|l| l.collapses == keep)
                .expect("a level keeps them");
            format!("level {}", i + 1)
        }
        _ => format!("the state after {keep} collapses"),
    };
    Ok(format!(
        "{}: {coarse_faces} faces rebuilt to {} ({state}) by {} vertex splits on {}: {} vertices, written to {} ({:.2} s)\n",
        args.dir.display(),
        rebuilt.num_faces(),
        record.collapses.len() - keep,
        args.structure,
        rebuilt.num_vertices(),
        args.out.display(),
        started.elapsed().as_secs_f64()
    ))
}

/// The rebuilding on the structure `--structure` names: the state keeping the first `keep`
/// collapses, canonical, or why the coarse mesh and the record do not go together.
struct Rebuild<'a> {
    coarse: &'a PolygonSoup,
    record: &'a Record,
    keep: usize,
}

impl EditVisitor for Rebuild<'_> {
    type Output = Result<PolygonSoup, String>;
    fn visit<M: MeshEdit + 'static>(self) -> Result<PolygonSoup, String> {
        let mut m = M::from_soup(self.coarse)
            .map_err(|e| format!("cannot build the coarse mesh as {}: {e}", M::NAME))?;
        let r = reconstruct_from(
            &mut m,
            &self.record.collapses,
            self.keep,
            self.record.coarse_ids(),
        )
        .map_err(|e| format!("the record does not match the coarse mesh: {e}"))?;
        Ok(live_soup(&m, &r.original))
    }
}
