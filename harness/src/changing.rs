//! The changing workloads of the Surface_mesh benchmark (Sieger & Botsch, IMR 2011) in the
//! report: one step of √3 subdivision and the collapse test
//! (`topolab_structures::algorithms::changing`), timed on every editable structure and on
//! OpenMesh (natively, the whole loop in C++), with the resulting meshes compared by a
//! [`MeshChecksum`]: counts plus a hash of the face list that does not depend on how faces
//! are numbered or where each face's cycle starts. Structures that disagree stop the report.

use crate::checksum::mix;
use crate::timing::median;
use std::time::Instant;
use topolab_structures::algorithms::changing::Changing;
use topolab_structures::{FaceId, MeshTopology, Result};

/// What a changed mesh is compared by.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct MeshChecksum {
    /// Vertices.
    pub vertices: usize,
    /// Edges.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// Σ over faces of the face's vertices folded with [`mix`], each face read from its
    /// smallest vertex on (wrapping sum: face order does not matter, orientation does).
    pub face_hash: u64,
}

/// The [`MeshChecksum`] of `m` (through R20).
pub fn mesh_checksum<M: MeshTopology>(m: &M) -> MeshChecksum {
    let mut face_hash = 0u64;
    let mut face = Vec::new();
    for f in 0..m.num_faces() {
        face.clear();
        m.face_vertices(FaceId::new(f), |v| face.push(v.0));
        let k = face.len();
        let first = (0..k).min_by_key(|&i| face[i]).unwrap_or(0);
        let mut h = k as u64;
        for i in 0..k {
            h = mix(h, face[(first + i) % k] as u64);
        }
        face_hash = face_hash.wrapping_add(h);
    }
    MeshChecksum {
        vertices: m.num_vertices(),
        edges: m.num_edges(),
        faces: m.num_faces(),
        face_hash,
    }
}

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
    /// Median seconds of the runs (the workload only: each run starts from a fresh build,
    /// not timed).
    pub seconds: f64,
    /// Runs.
    pub runs: usize,
    /// Nanoseconds per face of the input, median.
    pub ns_per_face: f64,
    /// The resulting mesh.
    pub result: MeshChecksum,
    /// The costs the structure declares for the operations the workload does ([`declared`]);
    /// empty for a baseline run natively.
    pub declared: String,
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
    /// Median seconds of the runs (the refinement only: each run starts from a fresh build,
    /// not timed).
    pub seconds: f64,
    /// Runs.
    pub runs: usize,
    /// Nanoseconds per edge split, median.
    pub ns_per_split: f64,
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

/// Times `workload` `runs` times: each run builds a fresh mesh with `build` (not timed), runs
/// `work` on it (timed) and checks the result with `check`; every run must give the same
/// result.
pub fn time<T>(
    runs: usize,
    mut build: impl FnMut() -> Result<T>,
    mut work: impl FnMut(&mut T) -> Result<()>,
    check: impl Fn(&T) -> MeshChecksum,
) -> Result<(f64, MeshChecksum), String> {
    let mut times = Vec::with_capacity(runs);
    let mut result: Option<MeshChecksum> = None;
    for _ in 0..runs.max(1) {
        let mut mesh = build().map_err(|e| e.to_string())?;
        let start = Instant::now();
        work(&mut mesh).map_err(|e| e.to_string())?;
        times.push(start.elapsed().as_secs_f64());
        let got = check(&mesh);
        match result {
            Some(r) if r != got => {
                return Err(format!("two runs gave different meshes: {r:?} and {got:?}"))
            }
            _ => result = Some(got),
        }
        drop(mesh);
    }
    times.sort_by(f64::total_cmp);
    Ok((median(&times), result.expect("one run at least")))
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
    use topolab_structures::{meshes, IndexHalfEdge, PointerHalfEdge, PolygonSoup};

    fn row<M: MeshTopology + topolab_structures::MeshEdit>(
        soup: &PolygonSoup,
        w: Changing,
    ) -> ChangingRow {
        let (seconds, result) =
            time(2, || M::from_soup(soup), |m| w.run(m), mesh_checksum).expect("runs");
        ChangingRow {
            workload: w,
            mesh: "torus".into(),
            faces: soup.num_faces(),
            structure: M::NAME.into(),
            seconds,
            runs: 2,
            ns_per_face: seconds * 1e9 / soup.num_faces() as f64,
            result,
            declared: declared::<M>(w),
        }
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
