//! "The lecture's operations, measured": the operations the lecture on polygon-mesh data
//! structures asks of a structure (select, insert, delete, rotate and scale vertices, edges
//! and faces, and smoothing; [`MEASURED`]) timed one by one on every editable structure of
//! the run and on explicit storage, on the run's small tori, beside the cost each structure
//! declares (`MeshEdit::edit_cost`). It shows the lecture's contrast: explicit storage must
//! find every copy of a position to move a vertex (O(n)), the vertex list, the edge lists and
//! the half-edges change a position in place (O(1)).
//!
//! Each sample builds a fresh mesh and prepares it (finding the element by its vertices,
//! deleting the edge an insertion puts back: not timed), times the operation alone (a moved
//! vertex: [`SET_POSITION_BATCH`] moves, timed together, since one is below the clock's
//! resolution), then, not timed, collects garbage and takes a checksum of the mesh (counts,
//! faces by their vertices, positions by their bits). The median over the samples is shown
//! per operation. The checksums of all samples, summed, must agree between structures; a
//! disagreement stops the report, as in the changing section.
//!
//! An operation a structure does not offer (`MeshEdit::supports`) shows `—` with that reason;
//! one whose declared cost predicts more than [`CELL_MAX_SECONDS`] for its samples (a tenth
//! of it in a quick run, at 1 ns per element read) is skipped with the estimate. Only tori of
//! at most [`MAX_FACES`] faces are measured: every sample is a fresh build, and the O(n)
//! operations show their slope on small meshes already. The cap, the sample counts and the
//! skip by estimate are what bound the section's time (its phase in `results.json` records it).

use crate::measuring::checksum::mix;
use crate::measuring::phases::Phase;
use crate::measuring::timing::median;
use crate::page::skips::{self, Skip};
use crate::report::run::{Case, ReportError, Run};
use crate::report::section::{Needs, Page, Section};
use crate::results::{EditOpOutcome, EditOpRow};
use crate::studies::changing::mesh_checksum;
use crate::teaching::edits::edge_between;
use std::fmt::Write;
use std::time::Instant;
use topolab_registry::{self as registry, EditVisitor};
use topolab_structures::algorithms::select::{
    rotate_selection, scale_selection, select_vertices_in, smooth_step, Aabb,
};
use topolab_structures::glam::{DQuat, DVec3};
use topolab_structures::{Cost, EditOp, FaceId, MeshEdit, MeshTopology, PolygonSoup, VertexId};

/// The operations measured, in the order of the lecture's list: moving and selecting
/// vertices, rotating and scaling a selection, smoothing, inserting and deleting edges,
/// faces and vertices.
pub const MEASURED: [EditOp; 10] = [
    EditOp::SetPosition,
    EditOp::Select,
    EditOp::RotateSelection,
    EditOp::ScaleSelection,
    EditOp::Smooth,
    EditOp::InsertEdge,
    EditOp::DeleteEdge,
    EditOp::AddFace,
    EditOp::DeleteFace,
    EditOp::DeleteVertex,
];

/// Tori larger than this (faces) are not measured: every sample is a fresh build.
pub const MAX_FACES: usize = 4_000;

/// A cell (operation, structure, mesh) is skipped where its declared cost predicts more than
/// this for all its samples (a tenth of it in a quick run).
pub const CELL_MAX_SECONDS: f64 = 1.0;

/// The time the estimate assumes per element an operation reads (optimistic, so that
/// nothing is skipped that would have fitted).
const SECONDS_PER_ELEMENT: f64 = 1e-9;

/// Vertices moved per sample of [`EditOp::SetPosition`], timed together.
pub const SET_POSITION_BATCH: usize = 64;

/// Samples per cell.
fn samples(quick: bool) -> usize {
    if quick {
        7
    } else {
        15
    }
}

/// The elements one operation of cost `c` reads on a mesh of `n` elements (valence k ≈ 6;
/// for a rotation or a scaling, k is the selection's size, a few dozen here).
fn reads(op: EditOp, c: Cost, n: f64) -> f64 {
    let k = match op {
        EditOp::RotateSelection | EditOp::ScaleSelection => 40.0,
        _ => 6.0,
    };
    match c {
        Cost::Constant | Cost::Log | Cost::Boundary => 6.0,
        Cost::Local => k,
        Cost::LocalSquared => k * k,
        Cost::Linear => n,
        Cost::LocalTimesLinear => k * n,
        Cost::Quadratic => n * n,
    }
}

/// The operation a sample of `op` does before the clock starts, if any: an insertion puts
/// back what a deletion took.
fn preparation(op: EditOp) -> Option<EditOp> {
    match op {
        EditOp::InsertEdge => Some(EditOp::DeleteEdge),
        EditOp::AddFace => Some(EditOp::DeleteFace),
        _ => None,
    }
}

/// The elements of each sample: per sample a vertex and an edge (a → b, a side of a face of
/// the soup), spread over the mesh.
struct Targets {
    vertices: Vec<u32>,
    sides: Vec<(u32, u32)>,
    /// Half the width of a selection box, per axis (a tenth of the mesh's extent).
    half_box: DVec3,
}

impl Targets {
    fn of(soup: &PolygonSoup, samples: usize) -> Self {
        let (nv, nf) = (soup.num_vertices().max(1), soup.num_faces().max(1));
        let faces: Vec<&[u32]> = soup.faces().collect();
        let sides = (0..samples)
            .map(|i| {
                let f = faces[(i * nf / samples + i) % nf];
                (f[0], f[1])
            })
            .collect();
        let (lo, hi) = soup.positions.iter().fold(
            (DVec3::splat(f64::MAX), DVec3::splat(f64::MIN)),
            |(lo, hi), &p| (lo.min(p), hi.max(p)),
        );
        Self {
            vertices: (0..samples)
                .map(|i| ((i * nv / samples) % nv) as u32)
                .collect(),
            sides,
            half_box: (hi - lo) * 0.05,
        }
    }
}

/// The face of `m` holding the directed side a → b.
fn face_left<M: MeshTopology>(m: &M, a: u32, b: u32) -> Option<(FaceId, Vec<VertexId>)> {
    let mut found = None;
    m.vertex_faces(VertexId(a), |f| {
        let mut c = Vec::new();
        m.face_vertices(f, |v| c.push(v));
        let k = c.len();
        if (0..k).any(|i| c[i].0 == a && c[(i + 1) % k].0 == b) {
            found = Some((f, c));
        }
    });
    found
}

/// A face of `m` with both `a` and `b` among its corners.
fn face_with_both<M: MeshTopology>(m: &M, a: u32, b: u32) -> Option<FaceId> {
    let mut found = None;
    m.vertex_faces(VertexId(a), |f| {
        let mut has = false;
        m.face_vertices(f, |v| has |= v.0 == b);
        if has {
            found = Some(f);
        }
    });
    found
}

/// The positions of the live vertices, by their bits (-0 as +0), in a sum that does not
/// depend on order.
fn positions_checksum<M: MeshEdit>(m: &M) -> u64 {
    (0..m.num_vertices())
        .map(VertexId::new)
        .filter(|&v| !m.is_deleted_vertex(v))
        .map(|v| {
            let p = m.position(v).to_array().map(|x| (x + 0.0).to_bits());
            mix(mix(mix(v.0 as u64, p[0]), p[1]), p[2])
        })
        .fold(0u64, u64::wrapping_add)
}

/// The mesh after a sample: garbage collected (not timed), then counts, faces and positions.
fn finish<M: MeshEdit>(m: &mut M) -> u64 {
    m.garbage_collection();
    let c = mesh_checksum(m);
    let counts = mix(mix(c.vertices as u64, c.edges as u64), c.faces as u64);
    mix(mix(counts, c.face_hash), positions_checksum(m))
}

/// One sample of `op` on a fresh `M`: seconds timed, operations timed, checksum.
fn sample<M: MeshEdit>(
    op: EditOp,
    soup: &PolygonSoup,
    t: &Targets,
    i: usize,
) -> Result<(f64, usize, u64), String> {
    let mut m = M::from_soup(soup).map_err(|e| e.to_string())?;
    let missing = |what: &str| format!("sample {i}: no {what} in {}", M::NAME);
    let v = t.vertices[i];
    let (a, b) = t.sides[i];
    let centre = m.position(VertexId(v));
    let around = Aabb {
        min: centre - t.half_box,
        max: centre + t.half_box,
    };
    let err = |e: topolab_structures::Error| e.to_string();
    let (seconds, ops) = match op {
        EditOp::SetPosition => {
            let nv = m.num_vertices();
            let moves: Vec<(VertexId, DVec3)> = (0..SET_POSITION_BATCH.min(nv))
                .map(|j| {
                    let w = VertexId::new((v as usize + j * (nv / SET_POSITION_BATCH).max(1)) % nv);
                    (
                        w,
                        m.position(w) + DVec3::new(1.0, 2.0, 3.0) * 1e-3 * (j + 1) as f64,
                    )
                })
                .collect();
            let start = Instant::now();
            for &(w, p) in &moves {
                m.set_position(w, p).map_err(err)?;
            }
            (start.elapsed().as_secs_f64(), moves.len())
        }
        EditOp::Select => {
            let start = Instant::now();
            let s = select_vertices_in(&m, &around);
            let seconds = start.elapsed().as_secs_f64();
            let picked = s
                .vertices()
                .iter()
                .fold(s.len() as u64, |h, w| h.wrapping_add(mix(w.0 as u64, 1)));
            return Ok((seconds, 1, mix(picked, finish(&mut m))));
        }
        EditOp::RotateSelection | EditOp::ScaleSelection => {
            let s = select_vertices_in(&m, &around);
            let start = Instant::now();
            if op == EditOp::RotateSelection {
                rotate_selection(&mut m, &s, centre, DQuat::from_rotation_z(0.5))
            } else {
                scale_selection(&mut m, &s, centre, DVec3::splat(1.25))
            }
            .map_err(err)?;
            (start.elapsed().as_secs_f64(), 1)
        }
        EditOp::Smooth => {
            let start = Instant::now();
            smooth_step(&mut m).map_err(err)?;
            (start.elapsed().as_secs_f64(), 1)
        }
        EditOp::InsertEdge => {
            let e = edge_between(&m, a, b).ok_or_else(|| missing("edge"))?;
            m.delete_edge(e).map_err(err)?;
            let f = face_with_both(&m, a, b).ok_or_else(|| missing("merged face"))?;
            let start = Instant::now();
            m.insert_edge(f, VertexId(a), VertexId(b)).map_err(err)?;
            (start.elapsed().as_secs_f64(), 1)
        }
        EditOp::DeleteEdge => {
            let e = edge_between(&m, a, b).ok_or_else(|| missing("edge"))?;
            let start = Instant::now();
            m.delete_edge(e).map_err(err)?;
            (start.elapsed().as_secs_f64(), 1)
        }
        EditOp::AddFace => {
            let (f, corners) = face_left(&m, a, b).ok_or_else(|| missing("face"))?;
            m.delete_face(f).map_err(err)?;
            let start = Instant::now();
            m.add_face(&corners).map_err(err)?;
            (start.elapsed().as_secs_f64(), 1)
        }
        EditOp::DeleteFace => {
            let (f, _) = face_left(&m, a, b).ok_or_else(|| missing("face"))?;
            let start = Instant::now();
            m.delete_face(f).map_err(err)?;
            (start.elapsed().as_secs_f64(), 1)
        }
        EditOp::DeleteVertex => {
            let start = Instant::now();
            m.delete_vertex(VertexId(v)).map_err(err)?;
            (start.elapsed().as_secs_f64(), 1)
        }
        other => return Err(format!("{other} is not among the operations measured")),
    };
    Ok((seconds, ops, finish(&mut m)))
}

/// One cell on one structure.
struct Cell<'a> {
    op: EditOp,
    soup: &'a PolygonSoup,
    targets: &'a Targets,
    quick: bool,
}

impl EditVisitor for Cell<'_> {
    type Output = Result<(Cost, EditOpOutcome), String>;
    fn visit<M: MeshEdit + 'static>(self) -> Self::Output {
        let declared = M::edit_cost(self.op);
        if !M::supports(self.op) {
            return Ok((declared, EditOpOutcome::NotOffered));
        }
        if let Some(prep) = preparation(self.op).filter(|&p| !M::supports(p)) {
            return Ok((
                declared,
                EditOpOutcome::Skipped {
                    reason: format!(
                        "its preparation needs {prep}, which the structure does not offer"
                    ),
                    detail: None,
                },
            ));
        }
        let runs = self.targets.vertices.len();
        let per_sample = if self.op == EditOp::SetPosition {
            SET_POSITION_BATCH
        } else {
            1
        };
        let n = 3.0 * self.soup.num_faces() as f64;
        let estimate =
            (runs * per_sample) as f64 * reads(self.op, declared, n) * SECONDS_PER_ELEMENT;
        let max = if self.quick {
            CELL_MAX_SECONDS / 10.0
        } else {
            CELL_MAX_SECONDS
        };
        if estimate > max {
            return Ok((
                declared,
                EditOpOutcome::Skipped {
                    reason: format!(
                        "its declared {} predicts above {max} s for its samples at ≥ 1 ns per element read",
                        declared.notation()
                    ),
                    detail: Some(format!("about {estimate:.1} s")),
                },
            ));
        }
        let mut times = Vec::with_capacity(runs);
        let mut checksum = 0u64;
        let mut ops = 1;
        for i in 0..runs {
            let (seconds, n, sum) = sample::<M>(self.op, self.soup, self.targets, i)?;
            times.push(seconds / n as f64);
            ops = n;
            checksum = checksum.wrapping_add(mix(i as u64, sum));
        }
        times.sort_by(f64::total_cmp);
        Ok((
            declared,
            EditOpOutcome::Measured {
                ns_per_op: median(&times) * 1e9,
                samples: runs,
                ops_per_sample: ops,
                checksum,
            },
        ))
    }
}

/// Is the structure called `name` in the comparison?
pub fn compared(name: &str) -> bool {
    struct Probe;
    impl EditVisitor for Probe {
        type Output = ();
        fn visit<M: MeshEdit + 'static>(self) {}
    }
    registry::visit_editable(name, Probe).is_some()
}

/// Fails, loudly, when two structures gave different meshes for the same samples.
pub fn cross_check(rows: &[EditOpRow]) -> Result<(), String> {
    let sum = |r: &EditOpRow| match r.outcome {
        EditOpOutcome::Measured { checksum, .. } => Some(checksum),
        _ => None,
    };
    for a in rows {
        let Some(x) = sum(a) else { continue };
        if let Some(b) = rows
            .iter()
            .find(|b| b.op == a.op && b.mesh == a.mesh && sum(b).is_some_and(|y| y != x))
        {
            return Err(format!(
                "{} on {}: {} and {} gave different meshes (checksums {x:#x} and {:#x})",
                a.op,
                a.mesh,
                a.structure,
                b.structure,
                sum(b).unwrap_or_default()
            ));
        }
    }
    Ok(())
}

/// Every operation of [`MEASURED`] on every compared structure of `names`, on the tori of
/// `cases` of at most [`MAX_FACES`] faces.
fn measure(
    cases: &[Case],
    names: &[String],
    quick: bool,
    notes: &mut Vec<String>,
) -> Result<Vec<EditOpRow>, ReportError> {
    let structures: Vec<&str> = names
        .iter()
        .map(String::as_str)
        .filter(|s| compared(s))
        .collect();
    let mut rows = Vec::new();
    let mut skips = Vec::new();
    for (mesh, family, soup) in cases {
        if family != "torus" || soup.num_faces() > MAX_FACES || structures.is_empty() {
            continue;
        }
        let targets = Targets::of(soup, samples(quick));
        for op in MEASURED {
            for &s in &structures {
                eprintln!("topolab report: {op} on {mesh}: {s}");
                let cell = Cell {
                    op,
                    soup,
                    targets: &targets,
                    quick,
                };
                let (declared, outcome) = registry::visit_editable(s, cell)
                    .unwrap_or_else(|| Err(format!("{s} does not edit")))
                    .map_err(|e| {
                        ReportError::Measurement(format!("{op} on {mesh} failed on {s}: {e}"))
                    })?;
                if let EditOpOutcome::Skipped { reason, detail } = &outcome {
                    skips.push(Skip {
                        what: format!("the measured {op}"),
                        structure: s.to_string(),
                        mesh: mesh.clone(),
                        reason: reason.clone(),
                        detail: detail.clone(),
                    });
                }
                rows.push(EditOpRow {
                    op,
                    mesh: mesh.clone(),
                    faces: soup.num_faces(),
                    structure: s.to_string(),
                    declared,
                    outcome,
                });
            }
        }
        cross_check(&rows).map_err(|e| {
            ReportError::Measurement(format!(
                "{e}\nThe report stops: two structures changed a mesh differently."
            ))
        })?;
    }
    notes.extend(skips::group(&skips));
    Ok(rows)
}

/// The section's HTML: one table per torus, operations as rows, structures as columns.
pub fn render(h: &mut String, rows: &[EditOpRow]) {
    if rows.is_empty() {
        return;
    }
    h.push_str("<h2>The lecture's operations, measured</h2><div class=read><b>How to read it.</b> The operations the lecture on polygon-mesh data structures asks of a structure (select, insert, delete, rotate and scale vertices, edges and faces; smoothing), each timed alone on a fresh copy of the torus (the build and the preparation, such as finding the element by its vertices, not timed), the median of the samples per operation, beside the cost the structure declares for it (<code>topolab list</code>). Explicit storage is the lecture's contrast: it stores a position once per corner, so moving a vertex finds every copy (O(n)); the other structures move it in place. <i>set-position</i> times 64 moves together (one is below the clock's resolution); <i>rotate-selection</i> and <i>scale-selection</i> move the vertices in a box a tenth of the mesh wide; <i>smooth</i> is one step over the whole mesh; <i>insert-edge</i> puts back a diagonal deleted before the clock starts. The meshes after every sample are compared across structures (counts, faces by their vertices, positions by their bits); a disagreement stops the report. <i>—</i>: the structure does not offer the operation (triangle-only structures cannot hold the polygon an edge deletion makes; explicit storage offers moves only); <i>skipped</i>: its declared cost predicts too long (the estimate is in the notes). The algorithms are the lab's choice, described in <code>docs/editing.md</code>.</div>");
    let mut meshes: Vec<(&str, usize)> = Vec::new();
    for r in rows {
        if !meshes.iter().any(|(m, _)| *m == r.mesh) {
            meshes.push((&r.mesh, r.faces));
        }
    }
    for (mesh, faces) in meshes {
        let here: Vec<&EditOpRow> = rows.iter().filter(|r| r.mesh == mesh).collect();
        let mut structures: Vec<&str> = Vec::new();
        for r in &here {
            if !structures.contains(&r.structure.as_str()) {
                structures.push(&r.structure);
            }
        }
        let _ = write!(
            h,
            "<h3>{mesh} ({faces} faces): ns per operation, declared cost below</h3><table><tr><th class=l>operation</th>"
        );
        for s in &structures {
            let _ = write!(h, "<th>{s}</th>");
        }
        h.push_str("</tr>");
        for op in MEASURED {
            let _ = write!(h, "<tr><td class=l>{op}</td>");
            for s in &structures {
                let cell = here.iter().find(|r| r.op == op && r.structure == *s);
                let text = match cell {
                    None => "".to_string(),
                    Some(r) => match &r.outcome {
                        EditOpOutcome::Measured { ns_per_op, .. } => {
                            format!("{ns_per_op:.0}<br><small>{}</small>", r.declared.notation())
                        }
                        EditOpOutcome::NotOffered => "—<br><small>not offered</small>".to_string(),
                        EditOpOutcome::Skipped { reason, .. } => format!(
                            "<span title=\"{reason}\">skipped</span><br><small>{}</small>",
                            r.declared.notation()
                        ),
                    },
                };
                let _ = write!(h, "<td>{text}</td>");
            }
            h.push_str("</tr>");
        }
        h.push_str("</table>");
    }
}

/// The lecture's operations on every structure that implements `MeshEdit` (explicit storage
/// its moves only).
pub struct EditOps;

impl Section for EditOps {
    fn name(&self) -> &'static str {
        "edit-ops"
    }

    fn needs(&self) -> Needs {
        Needs::GENERATED
    }

    fn phase(&self) -> Option<Phase> {
        Some(Phase::new("edit-ops", "the lecture's editing operations"))
    }

    fn measure(&self, run: &mut Run) -> Result<(), ReportError> {
        let (req, r) = (run.request, &mut *run.results);
        r.edit_ops = measure(run.cases, &req.names, req.quick, &mut r.notes)?;
        Ok(())
    }

    fn render(&self, h: &mut String, page: &Page) {
        render(h, &page.r.edit_ops);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::{meshes, ExplicitStorage, IndexHalfEdge, VertexList};

    fn cell<M: MeshEdit + 'static>(op: EditOp, soup: &PolygonSoup) -> EditOpRow {
        let targets = Targets::of(soup, 3);
        let (declared, outcome) = Cell {
            op,
            soup,
            targets: &targets,
            quick: true,
        }
        .visit::<M>()
        .expect("measured");
        EditOpRow {
            op,
            mesh: "torus".into(),
            faces: soup.num_faces(),
            structure: M::NAME.into(),
            declared,
            outcome,
        }
    }

    #[test]
    fn structures_agree_on_every_operation_and_a_different_mesh_is_caught() {
        let soup = meshes::torus(8, 6);
        let mut rows = Vec::new();
        for op in MEASURED {
            rows.push(cell::<IndexHalfEdge>(op, &soup));
            rows.push(cell::<VertexList>(op, &soup));
            rows.push(cell::<ExplicitStorage>(op, &soup));
        }
        cross_check(&rows).expect("the same meshes");
        let measured = |s: &str| {
            rows.iter()
                .filter(|r| r.structure == s && matches!(r.outcome, EditOpOutcome::Measured { .. }))
                .count()
        };
        assert_eq!(measured("index-half-edge"), MEASURED.len());
        // Explicit storage offers the moves, the selection and smoothing only.
        assert_eq!(measured("explicit"), 5);
        let explicit_move = rows
            .iter()
            .find(|r| r.structure == "explicit" && r.op == EditOp::SetPosition)
            .expect("a row");
        assert_eq!(explicit_move.declared, Cost::Linear);
        let mut wrong = rows.clone();
        let i = wrong
            .iter()
            .position(|r| r.structure == "vertex-list" && r.op == EditOp::DeleteEdge)
            .expect("a row");
        if let EditOpOutcome::Measured { checksum, .. } = &mut wrong[i].outcome {
            *checksum ^= 1;
        }
        assert!(cross_check(&wrong).is_err());
        let mut html = String::new();
        render(&mut html, &rows);
        assert_eq!(html.matches("<tr>").count(), 1 + MEASURED.len());
        assert!(html.contains("<th>explicit</th>"));
    }
}
