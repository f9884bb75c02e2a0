//! The changing workloads of `topolab report` (√3 subdivision and the collapse test of the
//! Surface_mesh benchmark; see `topolab_harness::changing`): every editable structure among
//! those asked for, and OpenMesh natively, on the closed tori of the run.

use crate::input::Failure;
#[cfg(has_openmesh)]
use crate::openmesh::OpenMesh;
use topolab_harness::changing::{cross_check, mesh_checksum, time, ChangingRow, MeshChecksum};
use topolab_structures::algorithms::changing::Changing;
#[cfg(has_openmesh)]
use topolab_structures::MeshTopology;
use topolab_structures::{
    CheL1, CheL2, CheL3, IndexHalfEdge, MeshEdit, PointerHalfEdge, PolygonSoup,
};

// OpenMesh is built through MeshTopology::from_soup.
#[cfg(has_openmesh)]
const _: fn(&PolygonSoup) -> topolab_structures::Result<OpenMesh> =
    <OpenMesh as MeshTopology>::from_soup;

/// The structures that run the changing workloads: the lab's editable ones, OpenMesh and
/// CGAL's two (the baselines natively).
pub const EDITABLE: [&str; 8] = [
    "index-half-edge",
    "pointer-half-edge",
    "openmesh",
    "cgal-surface-mesh",
    "cgal-polyhedron",
    "che-l1",
    "che-l2",
    "che-l3",
];

/// Tori larger than this (faces) are left out: the workloads triple the mesh.
const MAX_FACES: usize = 4_000_000;

/// The CHE levels run the workloads up to this size only (the 1k torus): each of their edits
/// scans `V[]` (level 1) or rebuilds `EH` (levels 2, 3), O(n), so a workload is O(n²) on them
/// (see their editing module): on the 4k torus a run already takes seconds, some 2000x the
/// index half-edge's. Level 0 scans for every opposite too and is left out.
const CHE_MAX_FACES: usize = 1_500;

fn timed<M: MeshEdit>(
    soup: &PolygonSoup,
    w: Changing,
    runs: usize,
) -> Result<(f64, MeshChecksum), String> {
    time(runs, || M::from_soup(soup), |m| w.run(m), mesh_checksum)
}

#[cfg(has_openmesh)]
fn timed_openmesh(
    soup: &PolygonSoup,
    w: Changing,
    runs: usize,
) -> Result<(f64, MeshChecksum), String> {
    time(
        runs,
        || {
            let mut m = <OpenMesh as MeshTopology>::from_soup(soup)?;
            m.prepare_changing()?;
            Ok(m)
        },
        |m| m.native_changing(w),
        mesh_checksum,
    )
}

/// A CGAL structure's native run (`cgal/edit_*.cpp`), built by CGAL's own construction.
#[cfg(has_cgal)]
fn timed_cgal<S: crate::cgal::CgalStructure>(
    soup: &PolygonSoup,
    runs: usize,
    work: impl FnMut(&mut crate::cgal::Cgal<S>) -> topolab_structures::Result<()>,
) -> Result<(f64, MeshChecksum), String> {
    time(
        runs,
        || crate::cgal::Cgal::<S>::build_native(soup, soup.num_corners() / 2),
        work,
        mesh_checksum,
    )
}

/// Runs both workloads on every torus of `cases` (name, family, soup) for each structure of
/// `names` that can edit; a disagreement between structures is an error.
pub fn measure(
    cases: &[(String, String, PolygonSoup)],
    names: &[String],
    quick: bool,
    notes: &mut Vec<String>,
) -> Result<Vec<ChangingRow>, Failure> {
    let mut rows = Vec::new();
    let editing: Vec<&str> = EDITABLE
        .into_iter()
        .filter(|s| names.iter().any(|n| n == s))
        .collect();
    for (mesh, family, soup) in cases {
        if family != "torus" || editing.is_empty() {
            continue;
        }
        if soup.num_faces() > MAX_FACES {
            notes.push(format!(
                "the changing workloads skipped {mesh}: above {MAX_FACES} faces"
            ));
            continue;
        }
        let runs = if quick || soup.num_faces() >= 1_000_000 {
            3
        } else {
            5
        };
        for w in Changing::ALL {
            for &s in &editing {
                if s.starts_with("che-") && soup.num_faces() > CHE_MAX_FACES {
                    let note = format!("the changing workloads skipped {mesh} on the CHE levels: above {CHE_MAX_FACES} faces, their O(n) edits make a workload O(n²)");
                    if !notes.contains(&note) {
                        notes.push(note);
                    }
                    continue;
                }
                eprintln!("topolab report: {} on {mesh}: {s}", w.name());
                let got = match s {
                    "index-half-edge" => timed::<IndexHalfEdge>(soup, w, runs),
                    "pointer-half-edge" => timed::<PointerHalfEdge>(soup, w, runs),
                    "che-l1" => timed::<CheL1>(soup, w, runs),
                    "che-l2" => timed::<CheL2>(soup, w, runs),
                    "che-l3" => timed::<CheL3>(soup, w, runs),
                    #[cfg(has_cgal)]
                    "cgal-surface-mesh" => {
                        timed_cgal::<crate::cgal::SurfaceMeshClass>(soup, runs, |m| {
                            m.native_changing(w)
                        })
                    }
                    #[cfg(has_cgal)]
                    "cgal-polyhedron" => {
                        timed_cgal::<crate::cgal::PolyhedronClass>(soup, runs, |m| {
                            m.native_changing(w)
                        })
                    }
                    #[cfg(has_openmesh)]
                    _ => timed_openmesh(soup, w, runs),
                    #[cfg(not(has_openmesh))]
                    _ => unreachable!("openmesh is not registered without OpenMesh"),
                };
                let (seconds, result) = got.map_err(|e| Failure {
                    message: format!("{} on {mesh} failed on {s}: {e}", w.name()),
                    code: 1,
                })?;
                rows.push(ChangingRow {
                    workload: w,
                    mesh: mesh.clone(),
                    faces: soup.num_faces(),
                    structure: s.to_string(),
                    seconds,
                    runs,
                    ns_per_face: seconds * 1e9 / soup.num_faces().max(1) as f64,
                    result,
                });
            }
        }
        cross_check(&rows).map_err(|e| Failure {
            message: format!("{e}\nThe report stops: two structures changed a mesh differently."),
            code: 1,
        })?;
    }
    Ok(rows)
}
