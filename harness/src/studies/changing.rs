//! The changing workloads of the Surface_mesh benchmark (Sieger & Botsch, IMR 2011) in the
//! report: one step of √3 subdivision and the collapse test
//! (`topolab_structures::algorithms::changing`), timed on every editable structure and on
//! OpenMesh (natively, the whole loop in C++), with the resulting meshes compared by a
//! [`MeshChecksum`]: counts plus a hash of the face list that does not depend on how faces
//! are numbered or where each face's cycle starts. Structures that disagree stop the report.

pub use crate::measuring::checksum::{mesh_checksum, MeshChecksum};
use crate::measuring::timing::interval::Interval;
use crate::measuring::timing::median;
use crate::measuring::timing::meter::MemoryMeter;
use crate::measuring::timing::turns::Stopwatch;
use topolab_structures::algorithms::changing::Changing;
use topolab_structures::Result;

/// One timed workload on one structure and mesh.
#[derive(Clone, Debug, serde::Serialize)]
pub struct ChangingRow {
    /// The workload (`sqrt3` or `collapse-test`).
    pub workload: Changing,
    /// The mesh it started from.
    pub mesh: String,
    /// Its faces.
    pub faces: usize,
    /// The structure.
    pub structure: String,
    /// Median seconds of the rounds (the workload only: each run starts from a fresh build,
    /// not timed), in the measuring thread's CPU time.
    pub seconds: f64,
    /// Runs: one a round.
    pub runs: usize,
    /// Nanoseconds per face of the input, median.
    pub ns_per_face: f64,
    /// The interval of that median ([`Interval::of_median`]), ns per face.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ns_per_face_ci: Option<[f64; 2]>,
    /// Seconds of each round, in round order (every structure of the mesh ran in every
    /// round, so round `i` of two rows was taken in turns).
    pub round_seconds: Vec<f64>,
    /// The resulting mesh.
    pub result: MeshChecksum,
    /// The costs the structure declares for the operations the workload does ([`declared`]);
    /// empty for a baseline run natively.
    pub declared: String,
}

impl ChangingRow {
    /// The row of `structure`'s `rounds` of `workload` on `mesh` of `faces` faces.
    pub fn of(
        workload: Changing,
        (mesh, faces): (&str, usize),
        structure: &str,
        rounds: &Rounds,
        declared: String,
    ) -> Self {
        let per_face = 1e9 / faces.max(1) as f64;
        let seconds = rounds.median();
        ChangingRow {
            workload,
            mesh: mesh.into(),
            faces,
            structure: structure.into(),
            seconds,
            runs: rounds.seconds.len(),
            ns_per_face: seconds * per_face,
            ns_per_face_ci: rounds
                .interval()
                .map(|i| [i.low * per_face, i.high * per_face]),
            round_seconds: rounds.seconds.clone(),
            result: rounds.result,
            declared,
        }
    }
}

/// The costs `M` declares for the operations of `workload`, as the report shows them
/// (`split-face O(k), flip-edge O(k)`).
pub fn declared<M: topolab_structures::MeshEdit>(workload: Changing) -> String {
    declared_operations::<M>(workload.operations(), &[])
}

/// The costs `M` declares for `operations` and `queries` (each with how many per face of the
/// input), as the report shows them (`split-edge O(1), r01 O(k)`).
pub fn declared_operations<M: topolab_structures::MeshEdit>(
    operations: &[(topolab_structures::EditOp, f64)],
    queries: &[(topolab_structures::Operator, f64)],
) -> String {
    operations
        .iter()
        .map(|&(op, _)| format!("{op} {}", M::edit_cost(op).notation()))
        .chain(
            queries
                .iter()
                .map(|&(q, _)| format!("{} {}", q.name(), M::cost(q).notation())),
        )
        .collect::<Vec<_>>()
        .join(", ")
}

/// The changing section's local refinement: what it asked of each torus and how each
/// structure did.
#[derive(Clone, Debug, Default, serde::Serialize)]
pub struct LocalRefinement {
    /// Per torus, the request and what it gave.
    pub cases: Vec<LocalRefinementCase>,
    /// Per torus and structure, the time.
    pub rows: Vec<LocalRefinementRow>,
}

/// Adaptive refinement timed on one structure and torus (the changing section's local
/// refinement table).
#[derive(Clone, Debug, serde::Serialize)]
pub struct LocalRefinementRow {
    /// The torus it started from.
    pub mesh: String,
    /// The structure.
    pub structure: String,
    /// Median seconds of the rounds (the refinement only: each run starts from a fresh build,
    /// not timed), in the measuring thread's CPU time.
    pub seconds: f64,
    /// Runs: one a round.
    pub runs: usize,
    /// Nanoseconds per edge split, median.
    pub ns_per_split: f64,
    /// The interval of that median ([`Interval::of_median`]), ns per split.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ns_per_split_ci: Option<[f64; 2]>,
    /// The refined mesh, the same on every structure (the refinement does not depend on it).
    pub result: MeshChecksum,
    /// The costs the structure declares for the operations the refinement does.
    pub declared: String,
}

/// What the changing section asked of one torus for its local refinement, what it gave, and
/// what a structure that can only refine everywhere would need instead.
#[derive(Clone, Debug, serde::Serialize)]
pub struct LocalRefinementCase {
    /// The torus.
    pub mesh: String,
    /// Its faces.
    pub faces: usize,
    /// The longest edge left in the region: half the mean length of the faces' sides.
    pub max_edge: f64,
    /// The region's corners: the quarter of the bounding box with x and y at least the box
    /// centre's.
    pub region: [[f64; 3]; 2],
    /// Edges split (the same on every structure).
    pub splits: u64,
    /// Faces after.
    pub faces_after: usize,
    /// Levels of uniform midpoint refinement (each halves every edge) that bring the torus's
    /// longest edge to `max_edge`: what a structure that cannot refine locally must do.
    pub uniform_levels: u32,
    /// Faces after those levels: `faces · 4^levels`.
    pub uniform_faces: u64,
}

/// One structure's runs of a changing workload, one call a run: each builds a fresh mesh (not
/// timed), times the work on it in the measuring thread's CPU time ([`Stopwatch`]) and answers
/// the seconds and the resulting mesh's [`MeshChecksum`].
pub type Runner<'a> = Box<dyn FnMut(&dyn MemoryMeter) -> Result<(f64, MeshChecksum), String> + 'a>;

/// The [`Runner`] of `work` on meshes from `build`, checked with `check`.
pub fn runner<'a, T: 'a>(
    mut build: impl FnMut() -> Result<T> + 'a,
    mut work: impl FnMut(&mut T) -> Result<()> + 'a,
    check: impl Fn(&T) -> MeshChecksum + 'a,
) -> Runner<'a> {
    Box::new(move |meter| {
        let mut mesh = build().map_err(|e| e.to_string())?;
        let watch = Stopwatch::start(meter);
        work(&mut mesh).map_err(|e| e.to_string())?;
        let seconds = watch.ns() * 1e-9;
        Ok((seconds, check(&mesh)))
    })
}

/// What [`in_rounds`] measured of one structure.
#[derive(Clone, Debug, PartialEq)]
pub struct Rounds {
    /// Seconds of each round, in round order.
    pub seconds: Vec<f64>,
    /// The mesh every run made.
    pub result: MeshChecksum,
}

impl Rounds {
    /// The median seconds.
    pub fn median(&self) -> f64 {
        let mut v = self.seconds.clone();
        v.sort_by(f64::total_cmp);
        median(&v)
    }

    /// The interval of the median, seconds ([`Interval::of_median`]).
    pub fn interval(&self) -> Option<Interval> {
        Interval::of_median(&self.seconds)
    }
}

/// Runs every runner of `runners` once per round for `rounds` rounds, in a fresh random order
/// each round (seeded by `seed`), as the size sweep's rounds run structures
/// ([`crate::measuring::rounds`]): a change of load hits the structures of a round alike. Every run of a
/// structure must make the mesh its first run made; a failed run names its structure.
pub fn in_rounds(
    runners: &mut [(&str, Runner<'_>)],
    rounds: usize,
    seed: u64,
    meter: &dyn MemoryMeter,
) -> Result<Vec<Rounds>, String> {
    use rand::seq::SliceRandom;
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut out: Vec<Option<Rounds>> = vec![None; runners.len()];
    for round in 1..=rounds.max(1) {
        let mut order: Vec<usize> = (0..runners.len()).collect();
        order.shuffle(&mut rng);
        for i in order {
            let (name, run) = &mut runners[i];
            let (seconds, got) = run(meter).map_err(|e| format!("{name}, round {round}: {e}"))?;
            match &mut out[i] {
                None => {
                    out[i] = Some(Rounds {
                        seconds: vec![seconds],
                        result: got,
                    })
                }
                Some(r) if r.result != got => {
                    return Err(format!(
                        "{name}: two runs gave different meshes: {:?} and {got:?}",
                        r.result
                    ))
                }
                Some(r) => r.seconds.push(seconds),
            }
        }
    }
    Ok(out.into_iter().flatten().collect())
}

/// Fails, loudly, when two structures changed the same mesh into different meshes.
pub fn cross_check(rows: &[ChangingRow]) -> Result<(), String> {
    for a in rows {
        if let Some(b) = rows
            .iter()
            .find(|b| b.workload == a.workload && b.mesh == a.mesh && b.result != a.result)
        {
            return Err(format!(
                "{} on {}: {} made {:?}, {} made {:?}",
                a.workload.name(),
                a.mesh,
                a.structure,
                a.result,
                b.structure,
                b.result
            ));
        }
    }
    Ok(())
}

/// The ratio of `structure`'s time to `base`'s on the largest mesh of `workload`, from the
/// rows of the section (the structures timed one after another).
pub fn ratio(rows: &[ChangingRow], workload: Changing, structure: &str, base: &str) -> Option<f64> {
    let faces = rows
        .iter()
        .filter(|r| r.workload == workload)
        .map(|r| r.faces)
        .max()?;
    let get = |s: &str| {
        rows.iter()
            .find(|r| r.workload == workload && r.faces == faces && r.structure == s)
            .map(|r| r.seconds)
    };
    Some(get(structure)? / get(base)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::algorithms::changing::Changing;
    use topolab_structures::{meshes, IndexHalfEdge, MeshTopology, PointerHalfEdge, PolygonSoup};

    use crate::measuring::timing::meter::Uncounted as NoMeter;

    fn row<M: MeshTopology + topolab_structures::MeshEdit>(
        soup: &PolygonSoup,
        w: Changing,
    ) -> ChangingRow {
        let mut runners = [(
            M::NAME,
            runner(|| M::from_soup(soup), move |m| w.run(m), mesh_checksum),
        )];
        let rounds = in_rounds(&mut runners, 2, 1, &NoMeter).expect("runs");
        let row = ChangingRow::of(
            w,
            ("torus", soup.num_faces()),
            M::NAME,
            &rounds[0],
            declared::<M>(w),
        );
        assert_eq!((row.runs, row.round_seconds.len()), (2, 2));
        row
    }

    #[test]
    fn rounds_run_every_runner_and_a_run_that_changes_its_mesh_fails() {
        let soup = meshes::torus(6, 5);
        let calls = std::cell::Cell::new(0);
        let mut runners: Vec<(&str, Runner)> = vec![
            (
                "a",
                runner(
                    || IndexHalfEdge::from_soup(&soup),
                    |_| Ok(()),
                    mesh_checksum,
                ),
            ),
            (
                "b",
                runner(
                    || IndexHalfEdge::from_soup(&soup),
                    |_| Ok(()),
                    move |m| {
                        calls.set(calls.get() + 1);
                        let mut c = mesh_checksum(m);
                        c.face_hash ^= (calls.get() == 3) as u64;
                        c
                    },
                ),
            ),
        ];
        let err = in_rounds(&mut runners, 4, 7, &NoMeter).unwrap_err();
        assert!(
            err.starts_with("b: two runs gave different meshes"),
            "{err}"
        );
        let rounds = in_rounds(&mut runners[..1], 3, 7, &NoMeter).unwrap();
        assert_eq!(rounds[0].seconds.len(), 3);
        assert!(rounds[0].interval().is_some());
    }

    #[test]
    fn both_half_edges_agree_and_a_different_mesh_is_caught() {
        let soup = meshes::torus(8, 6);
        let mut rows = Vec::new();
        for w in Changing::ALL {
            rows.push(row::<IndexHalfEdge>(&soup, w));
            rows.push(row::<PointerHalfEdge>(&soup, w));
        }
        cross_check(&rows).expect("the same meshes");
        // The collapse test gives the input back.
        let input = mesh_checksum(&IndexHalfEdge::from_soup(&soup).expect("manifold"));
        assert_eq!(rows[2].result, input);
        assert_ne!(rows[0].result, input, "√3 changes the mesh");
        let mut wrong = rows.clone();
        wrong[1].result.face_hash ^= 1;
        assert!(cross_check(&wrong).is_err());
        let mut html = String::new();
        crate::report::sections::changing::render(&mut html, &rows);
        assert_eq!(html.matches("<tr>").count(), 1 + rows.len());
    }

    #[test]
    fn the_face_hash_ignores_numbering_and_start_corner_but_not_orientation() {
        let a = PolygonSoup::from_polygons(vec![glam::DVec3::ZERO; 4], &[[0, 1, 2], [0, 2, 3]]);
        let b = PolygonSoup::from_polygons(vec![glam::DVec3::ZERO; 4], &[[3, 0, 2], [1, 2, 0]]);
        let c = PolygonSoup::from_polygons(vec![glam::DVec3::ZERO; 4], &[[0, 2, 1], [0, 3, 2]]);
        let sum = |s: &PolygonSoup| mesh_checksum(&IndexHalfEdge::from_soup(s).expect("manifold"));
        assert_eq!(sum(&a), sum(&b));
        assert_ne!(sum(&a).face_hash, sum(&c).face_hash);
    }
}
