//! Real meshes at scale for the report: two meshes of `bench-data/cache/` refined by Loop
//! subdivision to the sizes where the structures differ most, measured like the tori (every
//! operator, sampled and swept, the workloads, construction and memory; family `refined`).
//!
//! Refinement appends each new vertex after the old ones, as real tools do, so a refined mesh
//! keeps the input order a subdivided scan really has: far from the ideal the generated tori
//! have. The element-order section runs on the smallest of them too.

use crate::report::run::ReportError;
use topolab_structures::refine::{subdivide_levels, Scheme};
use topolab_structures::summary::plural;
use topolab_structures::PolygonSoup;

/// One refined mesh: the file stem in `bench-data/cache/` and the Loop levels.
#[derive(Copy, Clone, Debug)]
pub struct Refined {
    /// File stem of the source mesh.
    pub source: &'static str,
    /// Loop subdivision levels (each multiplies the triangles by four).
    pub levels: usize,
    /// Measured light: construction, memory and the vertex 1-ring sweep only (the full
    /// report's time budget, see [`crate::report::clock`]).
    pub light: bool,
}

impl Refined {
    /// Its name in the report: `SOURCE-loopLEVELS`.
    pub fn name(&self) -> String {
        format!("{}-loop{}", self.source, self.levels)
    }
}

/// Whether the refined mesh `name` of the full report is measured light ([`Refined::light`]).
pub fn light(name: &str) -> bool {
    FULL.iter().any(|r| r.light && r.name() == name)
}

/// The full report's refined meshes: CGAL's bunny (75,408 triangles) to 1.2M and the armadillo
/// (52,000) to 3.3M. Measured alone on the 2-core machine (see `docs/report.md`), these two took
/// about what the tori of 256k and 1M take together; the armadillo is now measured light
/// (construction, memory, the 1-ring sweep: the numbers a 3.3M mesh adds to the 1.2M bunny's),
/// which saves about 45 of its 140 s alone.
pub const FULL: [Refined; 2] = [
    Refined {
        source: "bunny00",
        levels: 2,
        light: false,
    },
    Refined {
        source: "armadillo",
        levels: 3,
        light: true,
    },
];

/// `--quick`: the npm bunny (3,720 triangles) one level up, 15k: the section is shown, small.
pub const QUICK: [Refined; 1] = [Refined {
    source: "npm-bunny",
    levels: 1,
    light: false,
}];

/// The refined meshes, smallest first (so the skip-by-estimate of the larger extrapolates from
/// the smaller), named `SOURCE-loopLEVELS`. A source that is missing or cannot be read or
/// refined is left out with a note; the report goes on. Each is admitted before it is refined
/// (`admit`: its triangles, checked as a torus of as many with two builds of the largest
/// structure: within u32 ids and the memory there is).
pub fn refined_meshes(
    list: &[Refined],
    admit: &dyn Fn(usize) -> Result<(), ReportError>,
    notes: &mut Vec<String>,
) -> Result<Vec<(String, PolygonSoup)>, ReportError> {
    let dir = std::path::Path::new("bench-data/cache");
    let mut out: Vec<(String, PolygonSoup)> = Vec::new();
    for r in list {
        let found = std::fs::read_dir(dir).ok().and_then(|d| {
            d.filter_map(|e| e.ok().map(|e| e.path())).find(|p| {
                p.file_stem().and_then(|s| s.to_str()) == Some(r.source)
                    && topolab_structures::io::format_of(p).is_ok()
            })
        });
        let Some(path) = found else {
            notes.push(format!(
                "{}: not refined, bench-data/cache/ has no such mesh (run `make data`)",
                r.source
            ));
            continue;
        };
        let soup = match topolab_structures::io::read(&path) {
            Ok(s) => s,
            Err(e) => {
                notes.push(format!("{}: not refined: {e}", path.display()));
                continue;
            }
        };
        // Checked before refining: 4^levels times the faces.
        admit(soup.num_faces().saturating_mul(1 << (2 * r.levels)))?;
        eprintln!(
            "topolab report: refining {} by {} Loop level{}",
            r.source,
            r.levels,
            plural(r.levels)
        );
        match subdivide_levels(soup, Scheme::Loop, r.levels, |_, _| {}) {
            Ok(s) => out.push((r.name(), s)),
            Err(e) => notes.push(format!("{}: not refined: {e}", path.display())),
        }
    }
    out.sort_by_key(|m| m.1.num_faces());
    Ok(out)
}
