//! The element an operation acts on by default ([`choose`]), the default mesh of each
//! operation ([`default_case`]) and the report's teaching edits.

use super::explained::explain_on;
use super::operations::centroid;
use super::operations::edit;
use super::prepare::{corners_of, prepare};
use super::refusals::refused_text;
use super::subject::{Subject, SubjectKind};
use crate::teaching::edits::picture::TeachingEdit;
use topolab_structures::meshes;
use topolab_structures::{
    EditOp, Error, FaceId, IndexHalfEdge, MeshEdit, MeshTopology, PolygonSoup, Refusal, VertexId,
};

/// What [`choose`] found: the first subject on which the edit succeeds, and the first on
/// which it is refused, with the refusal.
#[derive(Clone, Debug, Default)]
pub struct Choice {
    /// The first subject where the edit succeeds.
    pub success: Option<Subject>,
    /// The first subject where it is refused, and the structure's error.
    pub refused: Option<(Subject, String)>,
}

/// Subjects [`choose`] tries at most: a large mesh is not edited element by element.
pub const TRIED: usize = 64;

/// The vertices among which [`choose`] looks for corners of a new face, pairs to weld and
/// neighbours of a split.
pub(super) const TRIED_VERTICES: u32 = 12;

/// The edges among which [`choose`] looks for pairs to weld.
pub(super) const TRIED_EDGES: usize = 12;

/// The subjects of `kind` that [`choose`] tries on `m`, in order, at most [`TRIED`] of a kind
/// that has one per element (vertices, edges, faces); combinations of the first
/// [`TRIED_VERTICES`] vertices for the kinds that take several.
pub(super) fn candidates(kind: SubjectKind, m: &IndexHalfEdge) -> Vec<Subject> {
    let first = |n: usize| 0..(n.min(TRIED) as u32);
    let few = (m.num_vertices() as u32).min(TRIED_VERTICES);
    match kind {
        SubjectKind::Nothing => vec![Subject::Nothing],
        SubjectKind::MirrorImage => vec![Subject::MirrorImage],
        SubjectKind::WholeMesh => vec![Subject::WholeMesh],
        SubjectKind::TwoEdges => {
            let few = m.num_edges().min(TRIED_EDGES) as u32;
            (0..few)
                .flat_map(|e| (0..few).filter(move |&f| f != e).map(move |f| [e, f]))
                .map(Subject::Edges)
                .collect()
        }
        SubjectKind::TwoFaces => {
            let n = m.num_faces() as u32;
            // Face 0 with each other face, farthest first (a weld of faces needs faces apart),
            // then the nearest (which names a refusal).
            let centre = |f: u32| {
                centroid(
                    corners_of(m, FaceId(f))
                        .into_iter()
                        .map(|v| m.position(VertexId(v))),
                )
            };
            let mut others: Vec<u32> = (1..n).collect();
            others.sort_by(|&a, &b| {
                centre(b)
                    .distance_squared(centre(0))
                    .total_cmp(&centre(a).distance_squared(centre(0)))
            });
            let mut out: Vec<Subject> = others
                .iter()
                .take(TRIED / 2)
                .map(|&g| Subject::Faces([0, g]))
                .collect();
            out.extend(
                others
                    .iter()
                    .rev()
                    .take(TRIED / 2)
                    .map(|&g| Subject::Faces([0, g])),
            );
            out
        }
        SubjectKind::FaceAndCorners => first(m.num_faces())
            .flat_map(|f| {
                let c = corners_of(m, FaceId(f));
                let pairs: Vec<(u32, u32)> = c
                    .iter()
                    .enumerate()
                    .flat_map(|(i, &a)| c[i + 1..].iter().map(move |&b| (a, b)))
                    .collect();
                pairs
                    .into_iter()
                    .map(move |(a, b)| Subject::FaceAndCorners { face: f, a, b })
            })
            .collect(),
        // A selection's default is a vertex's; `--edge` or `--face` selects those instead.
        SubjectKind::Vertex | SubjectKind::Selected => {
            first(m.num_vertices()).map(Subject::Vertex).collect()
        }
        SubjectKind::Edge => first(m.num_edges()).map(Subject::Edge).collect(),
        SubjectKind::Face => first(m.num_faces()).map(Subject::Face).collect(),
        SubjectKind::TwoVertices => (0..few)
            .flat_map(|a| (0..few).filter(move |&b| b != a).map(move |b| (a, b)))
            .map(|(a, b)| Subject::Vertices(vec![a, b]))
            .collect(),
        SubjectKind::Corners => (0..few)
            .flat_map(|a| (0..few).map(move |b| (a, b)))
            .flat_map(|(a, b)| (0..few).map(move |c| [a, b, c]))
            .filter(|[a, b, c]| a != b && b != c && a != c)
            .map(|c| Subject::Vertices(c.to_vec()))
            .collect(),
        SubjectKind::VertexAndNeighbours => (0..few)
            .flat_map(|v| {
                let mut ring = Vec::new();
                m.vertex_vertices(VertexId(v), |w| ring.push(w.0));
                let pairs: Vec<(u32, u32)> = ring
                    .iter()
                    .flat_map(|&l| ring.iter().filter(move |&&r| r != l).map(move |&r| (l, r)))
                    .collect();
                pairs
                    .into_iter()
                    .map(move |(left, right)| Subject::VertexAndNeighbours {
                        vertex: v,
                        left,
                        right,
                    })
            })
            .collect(),
    }
}

/// [`choose_on`] the index half-edge, the reference whose numbering subjects use: every
/// editable structure refuses what it refuses (the editing suite holds them to one model),
/// with the same reason on the cases `explain`'s tests name.
pub fn choose(soup: &PolygonSoup, op: EditOp) -> Choice {
    choose_on::<IndexHalfEdge>(soup, op)
}

/// The first subject of `soup` on which `op` succeeds in structure `M` and the first on
/// which `M` refuses it (among the first [`TRIED`] vertices, edges or faces, or the
/// combinations of the first few vertices for the operations that take several), so that a
/// refusal shown is the refusal of the structure asked about. A subject whose setup is refused
/// (a vertex that cannot be deleted, before a garbage collection) is skipped, and so is an
/// edit `M` does not offer there ([`Refusal::NotImplemented`]): a missing feature, not a
/// refusal.
pub fn choose_on<M: MeshEdit>(soup: &PolygonSoup, op: EditOp) -> Choice {
    let mut choice = Choice::default();
    let (Ok(reference), Ok(mut m)) = (IndexHalfEdge::from_soup(soup), M::from_soup(soup)) else {
        return choice;
    };
    let spec = edit::<M>(op);
    for subject in candidates(spec.kind, &reference) {
        let Ok(prepared) = prepare(op, subject.clone(), soup, &reference) else {
            continue;
        };
        let Some(mut target) = prepared.target(&m) else {
            continue;
        };
        // A refused edit changes nothing (what `MeshEdit` promises), so `m` is built again
        // only after an edit, or a setup, that was done.
        let mut changed = false;
        if let Some((_, setup)) = spec.setup {
            if setup(&mut m, &mut target).is_err() {
                continue;
            }
            changed = true;
        }
        match (spec.call)(&mut m, &target) {
            Ok(()) => {
                changed = true;
                choice.success.get_or_insert(subject);
            }
            Err(Error::EditRefused {
                reason: Refusal::NotImplemented,
                ..
            }) => {}
            Err(e) => {
                if choice.refused.is_none() {
                    let why = refused_text(&e, soup, op, &prepared);
                    choice.refused = Some((subject, why));
                }
            }
        }
        if changed {
            match M::from_soup(soup) {
                Ok(fresh) => m = fresh,
                Err(_) => break,
            }
        }
        if choice.success.is_some() && choice.refused.is_some() {
            break;
        }
    }
    choice
}

/// The mesh an edit is shown on by default: the open tetrahedron (the CHE thesis chapter's
/// Figure 4.10), or, where `op` succeeds nowhere on it, the canonical `grid` (a 3x2
/// triangulated grid), or, where it succeeds on no triangle (an edge inserted as a face's
/// diagonal), the canonical `quad-strip` (three quads in a row). Each comes with its label and
/// its [`Choice`]; the second is `None` on the tetrahedron and the tetrahedron's choice on the
/// others (which names a refusal there).
pub struct DefaultCase {
    /// The mesh.
    pub soup: PolygonSoup,
    /// The mesh in words, and the `--mesh` that names it.
    pub label: &'static str,
    /// The `--mesh` that names it (`None` for the open tetrahedron, the default).
    pub mesh_flag: Option<&'static str>,
    /// The elements found on it.
    pub choice: Choice,
    /// Where the default moved to the grid: what was found on the tetrahedron.
    pub on_tetrahedron: Option<Choice>,
}

/// The label of the open tetrahedron.
pub const TETRAHEDRON: &str =
    "the open tetrahedron of the CHE thesis chapter's Figure 4.10 (--mesh open-tetrahedron)";
/// The label of the canonical grid.
pub const GRID: &str = "the canonical mesh `grid` (a 3x2 triangulated grid: --mesh grid)";
/// The label of the canonical quad strip.
pub const QUAD_STRIP: &str =
    "the canonical mesh `quad-strip` (three quads in a row: --mesh quad-strip)";

/// The label of the torus the welds of faces are shown on.
pub const TORUS: &str = "a torus of 128 triangles (--mesh torus:128)";

/// Builds one of the meshes [`default_case`] tries.
pub(super) type MakeMesh = fn() -> PolygonSoup;

/// [`DefaultCase`] of `op`: the first of the open tetrahedron, `grid`, `quad-strip` and a
/// torus of 128 triangles (a weld of two faces needs faces apart on a closed mesh) on which
/// `op` succeeds, or the last.
pub fn default_case(op: EditOp) -> DefaultCase {
    default_case_on::<IndexHalfEdge>(op)
}

/// [`default_case`] with the elements chosen on structure `M` ([`choose_on`]).
pub fn default_case_on<M: MeshEdit>(op: EditOp) -> DefaultCase {
    let soup = meshes::open_tetrahedron();
    let choice = choose_on::<M>(&soup, op);
    if choice.success.is_some() {
        return DefaultCase {
            soup,
            label: TETRAHEDRON,
            mesh_flag: None,
            choice,
            on_tetrahedron: None,
        };
    }
    let others: [(MakeMesh, &'static str, &'static str); 3] = [
        (|| meshes::grid(3, 2, true), GRID, "grid"),
        (|| meshes::quad_strip(3), QUAD_STRIP, "quad-strip"),
        (|| meshes::torus_with_triangles(128), TORUS, "torus:128"),
    ];
    let mut case = None;
    for (make, label, flag) in others {
        let other = make();
        let found = choose_on::<M>(&other, op);
        let done = found.success.is_some();
        case = Some(DefaultCase {
            choice: found,
            soup: other,
            label,
            mesh_flag: Some(flag),
            on_tetrahedron: Some(choice.clone()),
        });
        if done {
            break;
        }
    }
    case.expect("three meshes tried")
}

/// The operations the report's teaching section draws, each on the index half-edge, the
/// winged-edge and the CHE's level 2 ([`teaching_edits`]).
pub const TAUGHT: [EditOp; 4] = [
    EditOp::FlipEdge,
    EditOp::SplitEdge,
    EditOp::CollapseEdge,
    EditOp::SplitVertex,
];

/// The teaching section's edits: each operation of [`TAUGHT`] on its default element and
/// mesh ([`default_case`]) on the index half-edge, the winged-edge and the CHE's level 2. An
/// edit that cannot be shown is left out (none is on these structures; the report's test
/// checks that all twelve are there).
pub fn teaching_edits() -> Vec<TeachingEdit> {
    let mut out = Vec::new();
    for op in TAUGHT {
        let case = default_case(op);
        let (Some(subject), Ok(reference)) = (
            case.choice.success.clone(),
            IndexHalfEdge::from_soup(&case.soup),
        ) else {
            continue;
        };
        let Ok(prepared) = prepare(op, subject, &case.soup, &reference) else {
            continue;
        };
        let explained = [
            explain_on::<IndexHalfEdge>(&case.soup, op, &prepared),
            explain_on::<topolab_structures::WingedEdge>(&case.soup, op, &prepared),
            explain_on::<topolab_structures::CheL2>(&case.soup, op, &prepared),
        ];
        for e in explained.into_iter().flatten() {
            out.push(TeachingEdit {
                op,
                structure: e.structure.to_string(),
                mesh: case.label.to_string(),
                subject: prepared.description.clone(),
                changes: e.changes,
                before: e.before,
                after: e.after,
            });
        }
    }
    out
}
