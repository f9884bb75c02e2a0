//! `topolab decimate`: decimation by quadric error
//! ([`topolab_structures::algorithms::decimate`], after OpenMesh's `DecimaterT` with
//! `ModQuadricT`: area-weighted face quadrics, half-edge collapses onto an end vertex, the
//! link condition through [`topolab_structures::MeshEdit`]'s collapse test) on any structure
//! the decimation suite enrols ([`decimating_structures`]: the editable ones that collapse
//! edges and split vertices), to a face count, and the result written. `--strategy` chooses
//! how candidates are kept ([`Strategy`]): `lazy`, the default, because its normal-flipping
//! test keeps flat regions from decimating into zero-area triangles, which `topolab check`
//! would report in the file written; `eager` runs OpenMesh's Decimater step for step, as the
//! report compares it with OpenMesh's own. Both break ties by vertex ids
//! ([`topolab_structures::algorithms::decimate::Ties::Ids`]), so every structure gives the
//! same mesh (the report's eager rows keep OpenMesh's order of ties instead).
//!
//! Two modes: `--faces N` or `--ratio R` write the decimated mesh to the file `--out` (its
//! deleted elements collected, in the structure's order); `--levels 50%,10%` decimates once
//! through each level and writes into the folder `--out` the levels of detail and the
//! collapse record that `topolab reconstruct` steps back through ([`write_levels`]; the
//! files and their format: `docs/level-of-detail.md`).
//!
//! Refused before any work, nothing written (exit 2): a bad `--ratio` or `--levels`, a
//! `--structure` outside the decimation suite, an unknown `--strategy`, an unwritable output,
//! a mesh past `u32` ids or the available memory. Refused once read, nothing written (exit
//! 1): polygons (the decimater collapses triangles), input the structure cannot store
//! (non-manifold, inconsistently oriented), and a target below what the topology allows
//! ([`minimum_faces`]: per closed component of genus g, `2 (V − 2 + 2g)` faces with V
//! Heawood's fewest vertices, 4 faces for a sphere, 14 for a torus; one per component with a
//! boundary, whose vertices stay). The outputs are written atomically
//! ([`crate::output::write_mesh`], [`crate::output::write_files_together`]).

use crate::input::{load_mesh, refuse_empty, Failure};
use crate::output::{check_folder, check_mesh_out, write_files_together, write_mesh, Fill};
use crate::registry::{self, EditVisitor};
use std::path::{Path, PathBuf};
use std::time::Instant;
use topolab_structures::algorithms::changing::to_soup;
use topolab_structures::algorithms::decimate::record::{fingerprint, Counts, Level, Record};
use topolab_structures::algorithms::decimate::{
    canonical_input, decimate, decimate_levels, live_soup, minimum_faces, Decimation, Strategy,
};
use topolab_structures::io::write_obj;
use topolab_structures::summary::plural;
use topolab_structures::{EditOp, IndexHalfEdge, MeshEdit, MeshTopology, PolygonSoup};

/// Options of `topolab decimate`.
#[derive(clap::Args, Debug, Clone)]
#[command(group = clap::ArgGroup::new("target").required(true).args(["faces", "ratio", "levels"]))]
pub struct DecimateArgs {
    /// A triangle mesh file (.obj, .off, .ply, .stl) or a built-in mesh (see `topolab info --help`).
    pub mesh: String,
    /// Decimate to at most this many faces.
    #[arg(long)]
    pub faces: Option<usize>,
    /// Decimate to this fraction of the faces (0 < R ≤ 1).
    #[arg(long)]
    pub ratio: Option<f64>,
    /// Levels of detail: percentages of the faces, strictly decreasing, each above 0% and
    /// below 100% (`50%,10%`). The mesh is decimated once through each, and `--out` is a
    /// folder that receives every level, the coarsest as `coarse.obj`, the original in the
    /// same canonical form, and the collapse record `topolab reconstruct` steps back through.
    #[arg(long, value_parser = parse_levels)]
    pub levels: Option<Levels>,
    /// The output file (.obj, .off or .stl); with `--levels`, a folder (created if missing).
    #[arg(long)]
    pub out: PathBuf,
    /// The structure that decimates: one the decimation suite enrols (an editable structure
    /// that collapses edges and splits vertices; see `topolab list`).
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

/// The levels of `--levels`: percentages of the input's faces, strictly decreasing, each in
/// (0%, 100%).
#[derive(Clone, Debug, PartialEq)]
pub struct Levels(pub Vec<f64>);

/// `--levels`' parser.
pub fn parse_levels(text: &str) -> Result<Levels, String> {
    let mut levels = Vec::new();
    for word in text.split(',') {
        let word = word.trim();
        let Some(number) = word.strip_suffix('%') else {
            return Err(format!(
                "{word:?}: each level is a percentage of the faces, such as 50%"
            ));
        };
        let p: f64 = number
            .parse()
            .map_err(|_| format!("{word:?} is not a percentage, such as 50%"))?;
        if !(p > 0.0 && p < 100.0) {
            return Err(format!(
                "{word}: a level keeps more than 0% and less than 100% of the faces"
            ));
        }
        if let Some(&last) = levels.last() {
            if p >= last {
                return Err(format!(
                    "{word} after {last}%: the levels must decrease strictly, finest first"
                ));
            }
        }
        levels.push(p);
    }
    Ok(Levels(levels))
}

/// The files `decimate --levels` writes into its folder, and `reconstruct` reads.
pub mod files {
    /// The coarsest level, which `topolab reconstruct` starts from.
    pub const COARSE: &str = "coarse.obj";
    /// The collapse record.
    pub const RECORD: &str = "collapses.txt";
    /// The input, in the canonical form every file of the folder has.
    pub const ORIGINAL: &str = "original.obj";

    /// The file of level `i` (from 1, finest first).
    pub fn level(i: usize) -> String {
        format!("level-{i}.obj")
    }

    /// Every file the folder gets for `levels` levels, in the order written.
    pub fn all(levels: usize) -> Vec<String> {
        let mut names = vec![ORIGINAL.to_string()];
        names.extend((1..=levels).map(level));
        names.extend([COARSE.to_string(), RECORD.to_string()]);
        names
    }
}

/// Does `M` offer what decimation and its undoing need: the edge collapse and the vertex split?
struct Decimates;
impl EditVisitor for Decimates {
    type Output = bool;
    fn visit<M: MeshEdit + 'static>(self) -> bool {
        M::supports(EditOp::CollapseEdge) && M::supports(EditOp::SplitVertex)
    }
}

/// The structures `--structure` takes, here and in `topolab reconstruct`: the editable ones
/// of this build that collapse edges and split vertices. Exactly the ones the decimation
/// suite enrols (`structures/tests/decimating.rs` every editable lab structure,
/// `baselines/tests/decimating.rs` OpenMesh and CGAL's two when compiled in); the Rust crates
/// of `topolab-peers` offer no vertex split, so what they decimate could not be undone.
pub fn decimating_structures() -> Vec<&'static str> {
    registry::NAMES
        .iter()
        .copied()
        .filter(|&name| registry::visit_editable(name, Decimates) == Some(true))
        .collect()
}

/// Refuses a `--structure` outside [`decimating_structures`], saying which it takes and why.
pub fn check_structure(name: &str) -> Result<(), Failure> {
    let accepted = decimating_structures();
    if accepted.contains(&name) {
        return Ok(());
    }
    let why = if !registry::NAMES.contains(&name) {
        return Err(crate::input::unknown_structure(name));
    } else if registry::visit_editable(name, Decimates).is_some() {
        "it does not offer both the edge collapse a decimation makes and the vertex split that undoes it (not offered: a missing feature)"
    } else {
        "it has no editing operations"
    };
    Err(Failure::usage(format!(
        "--structure {name}: {why}; decimation and reconstruction run on the structures the decimation suite enrols, those that collapse edges and split vertices: {}",
        accepted.join(", ")
    )))
}

/// Runs `topolab decimate`.
pub fn run(args: &DecimateArgs) -> Result<String, Failure> {
    if let Some(r) = args.ratio {
        if !(r > 0.0 && r <= 1.0) {
            return Err(Failure::usage(format!(
                "--ratio {r}: the fraction of faces to keep must be in (0, 1]"
            )));
        }
    }
    check_structure(&args.structure)?;
    match &args.levels {
        Some(levels) => {
            let names = files::all(levels.0.len());
            let names: Vec<&str> = names.iter().map(String::as_str).collect();
            check_folder(&args.out, &names)?;
        }
        None => check_mesh_out(&args.out, &args.mesh)?,
    }
    let spec = args.mesh.as_str();
    // The work measured on the sample mesh (and scaled by corners): the structure, its
    // decimation and the soups written (with levels, each level's and the original's).
    let soup = load_mesh(spec, |s| {
        if let Ok(mut m) = IndexHalfEdge::from_soup(s) {
            let _ = decimate(&mut m, s.num_faces() / 10, args.strategy);
            let kept = args.levels.as_ref().map(|_| canonical_input(s));
            m.garbage_collection();
            drop((to_soup(&m), kept));
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
    registry::visit_editable(&args.structure, Decimater { args, soup: &soup })
        .expect("check_structure admitted an editable structure")
}

/// The run on the structure `--structure` names.
struct Decimater<'a> {
    args: &'a DecimateArgs,
    soup: &'a PolygonSoup,
}

impl EditVisitor for Decimater<'_> {
    type Output = Result<String, Failure>;
    fn visit<M: MeshEdit + 'static>(self) -> Result<String, Failure> {
        match &self.args.levels {
            Some(levels) => write_levels::<M>(self.args, self.soup, levels),
            None => decimate_with::<M>(self.args, self.soup),
        }
    }
}

/// `cannot decimate SPEC: E` (exit 1).
fn refused(spec: &str) -> impl Fn(topolab_structures::Error) -> Failure + '_ {
    move |e| Failure {
        message: format!("cannot decimate {spec}: {e}"),
        code: 1,
    }
}

/// Refuses targets below what `m`'s topology allows ([`minimum_faces`]).
fn check_least<M: MeshEdit>(spec: &str, m: &M, target: usize) -> Result<(), Failure> {
    let least = minimum_faces(m);
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
    Ok(())
}

fn decimate_with<M: MeshEdit>(args: &DecimateArgs, soup: &PolygonSoup) -> Result<String, Failure> {
    let spec = args.mesh.as_str();
    let started = Instant::now();
    let mut m = M::from_soup(soup).map_err(refused(spec))?;
    let faces = soup.num_faces();
    let target = match (args.faces, args.ratio) {
        (Some(n), _) => n,
        (None, Some(r)) => (r * faces as f64).round() as usize,
        (None, None) => faces,
    };
    check_least(spec, &m, target)?;
    let d = decimate(&mut m, target, args.strategy).map_err(refused(spec))?;
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

/// `--levels`: decimates `soup` once through each level ([`decimate_levels`]), keeping each
/// level's mesh in the canonical form of [`live_soup`] (the surviving vertices in increasing
/// original id, faces rotated to their smallest vertex and sorted), and writes them, the
/// original in the same form, the coarsest again as [`files::COARSE`] and the [`Record`], all
/// together ([`write_files_together`]).
pub fn write_levels<M: MeshEdit>(
    args: &DecimateArgs,
    soup: &PolygonSoup,
    levels: &Levels,
) -> Result<String, Failure> {
    let spec = args.mesh.as_str();
    let started = Instant::now();
    let mut m = M::from_soup(soup).map_err(refused(spec))?;
    let faces = soup.num_faces();
    let targets: Vec<usize> = levels
        .0
        .iter()
        .map(|p| (p / 100.0 * faces as f64).round() as usize)
        .collect();
    check_least(spec, &m, *targets.last().expect("at least one level"))?;
    // During the decimation the structure's vertex ids are the input's.
    let identity: Vec<u32> = (0..soup.num_vertices() as u32).collect();
    let mut states = Vec::with_capacity(targets.len());
    let d = decimate_levels(&mut m, &targets, args.strategy, |m, _| {
        states.push(live_soup(m, &identity))
    })
    .map_err(refused(spec))?;
    drop(m);
    let original = canonical_input(soup);
    let coarse = states.last().expect("one state per level");
    let record = record_of(&original, &states, &d);
    let mut outputs: Vec<(String, Fill)> = Vec::new();
    outputs.push((
        files::ORIGINAL.into(),
        Box::new(|w| write_obj(w, &original)),
    ));
    for (i, state) in states.iter().enumerate() {
        outputs.push((files::level(i + 1), Box::new(move |w| write_obj(w, state))));
    }
    outputs.push((files::COARSE.into(), Box::new(|w| write_obj(w, coarse))));
    outputs.push((files::RECORD.into(), Box::new(|w| record.write(w))));
    write_files_together(&args.out, outputs)?;
    let mut text = format!(
        "{spec}: {faces} faces decimated through {} level{} by {} collapses on {} ({} strategy), written to {} ({:.2} s):\n",
        targets.len(),
        plural(targets.len()),
        d.collapses.len(),
        args.structure,
        args.strategy,
        args.out.display(),
        started.elapsed().as_secs_f64()
    );
    for (i, ((p, &target), state)) in levels.0.iter().zip(&targets).zip(&states).enumerate() {
        let short = if state.num_faces() > target {
            format!(" (no legal collapse left above {target})")
        } else {
            String::new()
        };
        text += &format!(
            "  {}: {p}%, {} faces, {} vertices{short}\n",
            files::level(i + 1),
            state.num_faces(),
            state.num_vertices()
        );
    }
    text += &format!(
        "  {} (the last level), {} (the input, canonical), {} ({} collapses; `topolab reconstruct {}` rebuilds any level)\n",
        files::COARSE,
        files::ORIGINAL,
        files::RECORD,
        d.collapses.len(),
        Path::new(&args.out).display()
    );
    Ok(text)
}

/// The record of a decimation through levels: `original` canonical, `states` each level's
/// mesh.
fn record_of(original: &PolygonSoup, states: &[PolygonSoup], d: &Decimation) -> Record {
    Record {
        original: Counts::of(original),
        coarse: Counts::of(states.last().expect("one state per level")),
        levels: d
            .levels
            .iter()
            .zip(states)
            .map(|(&collapses, s)| Level {
                faces: s.num_faces(),
                collapses,
                fingerprint: fingerprint(s),
            })
            .collect(),
        collapses: d.collapses.clone(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn levels_are_strictly_decreasing_percentages_inside_the_open_range() {
        assert_eq!(parse_levels("50%,10%"), Ok(Levels(vec![50.0, 10.0])));
        assert_eq!(parse_levels("12.5%"), Ok(Levels(vec![12.5])));
        for (bad, says) in [
            ("", "percentage"),
            ("0%", "more than 0%"),
            ("100%", "less than 100%"),
            ("150%", "less than 100%"),
            ("10%,50%", "decrease strictly"),
            ("50%,50%", "decrease strictly"),
            ("abc%", "not a percentage"),
            ("0.5", "percentage of the faces"),
            ("nan%", "more than 0%"),
            ("50%,", "percentage"),
        ] {
            let e = parse_levels(bad).expect_err(bad);
            assert!(e.contains(says), "{bad}: {e}");
        }
    }

    #[test]
    fn the_decimating_structures_are_the_editable_ones_with_a_vertex_split() {
        let names = decimating_structures();
        for name in topolab_structures::registry::editable_names() {
            assert!(names.contains(&name), "{name}");
        }
        assert_eq!(
            names.contains(&registry::OPENMESH),
            crate::HAS_OPENMESH,
            "{names:?}"
        );
        assert_eq!(
            names.contains(&registry::CGAL_SURFACE_MESH),
            crate::HAS_CGAL,
            "{names:?}"
        );
        assert!(!names.contains(&"explicit"), "{names:?}");
        #[cfg(feature = "peers")]
        assert!(!names.contains(&"lox-half-edge"), "{names:?}");
        assert!(check_structure("regular-grid").is_err());
    }
}
