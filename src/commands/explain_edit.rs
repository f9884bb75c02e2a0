//! `topolab explain NAME --op OP [--edge E | --face F | --vertex V | --vertices A,B,...]
//! [--face F --vertices A,B] [--mesh M]`: one edit on one structure (or, for `che`, on the four CHE levels), with the
//! records it writes, old → new, in the field names of the structure's source (the lecture on
//! polygon-mesh data structures for the half-edges, the edge list and the vertex list, the
//! lecture on 3D convex hulls for the winged-edge's record, the CHE thesis chapter for the
//! CHE's containers), and what it reads. Every structure the registry marks `[editable]` is
//! explained ([`editable`]); the reads are described per family ([`Family`]). The C++
//! baselines and the Rust crates edit too, but their records live inside their library, out of
//! this command's reach: asked for one, it says so, as a usage error.
//!
//! `--op` takes every [`EditOp`] by its name ([`ExplainOp`], from [`EditOp::ALL`]), and
//! `flip`, `split` and `collapse` for `flip-edge`, `split-edge` and `collapse-edge`. What an
//! operation acts on, and so which of `--edge`, `--face`, `--vertex` and `--vertices` it
//! takes, is [`topolab_harness::teaching::edits::edit`]'s, which also does the edit and lists the
//! records ([`topolab_harness::teaching::edits::explain_on`]): the report's teaching section shows
//! the same lines. Elements are numbered the same on every structure: vertices and faces as the
//! mesh's, edges as `--trace` numbers them (the mesh's edges in order of first appearance, the
//! index half-edge's edge ids). `collapse-edge` collapses the edge's first vertex into its
//! second; `split-edge` splits it at its midpoint, `split-face` at its centroid;
//! `split-vertex V` between neighbours `L,R` puts the new vertex inside the faces that move;
//! `garbage-collection` is shown after the deletion of `--vertex V` (not explained);
//! `weld-meshes` welds the mesh to its mirror image across z = 0; `set-position V` moves the
//! vertex halfway to the mesh's centroid; `select V` selects in the box around the vertex that
//! reaches halfway to its nearest neighbour (nothing is written), and `rotate-selection V` and
//! `scale-selection V` turn that selection by 30 degrees about the x axis, or scale it by 1/2,
//! about the centroid of the vertex's neighbours; `insert-edge` takes a face and two of its
//! corners (`--face F --vertices A,B`); `smooth` is one step of uniform Laplacian smoothing of
//! the whole mesh; `weld-edges` sews the second of two boundary edges (`--edges E,F`) onto the
//! first, `weld-faces` removes two faces (`--faces F,G`) and sews their boundaries together.
//!
//! Without an element, the first one on which the edit succeeds (tried on the structure asked
//! about, its level 0 for `che`: on the open tetrahedron or, where none succeeds there, on the
//! canonical `grid`, where none succeeds on triangles, on the canonical `quad-strip`, and where
//! none succeeds on an open mesh, on a torus of 128 triangles), named, with one where that
//! structure refuses it and why. A refused edit exits with code 1 and the structure's reason
//! ([`topolab_structures::Refusal`]), followed, where the mesh shows it, by the test that
//! failed and the element that shows it (`test and element: ...`,
//! [`topolab_harness::teaching::edits::refusals::witness`], the same for every structure); an
//! operation the structure does not offer exits with code 1 too, said to be not offered (a
//! missing feature, not a refusal). An element past the mesh's count, or of the wrong kind for
//! the operation, is a usage error (code 2).
//!
//! The records are each structure's [`MeshTopology::explain`] lines read as records, except
//! for the CHE levels, whose containers are listed entry by entry
//! ([`topolab_harness::teaching::edits::records`]). The reads are described per family, then
//! counted ([`topolab_harness::teaching::edits::counted`]): every structure explained, and those `--structures` adds, side by
//! side, with the same edit on tori of growing size.

use super::explain_counted as counted;
use crate::input::{mesh_or_tetrahedron, Failure};
use crate::registry::{
    missing_baseline, offers, peer_crate, visit_editable, EditVisitor, CPP_BASELINES,
};
use std::fmt::Write;
use std::sync::LazyLock;
use topolab_harness::teaching::edits::counted::counted_structures;
use topolab_harness::teaching::edits::described::{reads, Family};
use topolab_harness::teaching::edits::refusals::witness;
use topolab_harness::teaching::edits::{
    choose_on, default_case_on, edit, explain_on, kind_of, prepare, Choice, DefaultCase, Prepared,
    Subject, SubjectKind,
};
use topolab_structures::{
    CheL0, CheL1, CheL2, CheL3, EditOp, Error, IndexHalfEdge, MeshEdit, MeshTopology, PolygonSoup,
};

/// An editing operation as `--op` takes it: every [`EditOp`] by its name, and the names of
/// the first version of `--op` (`flip`, `split`, `collapse`) as aliases.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct ExplainOp(pub EditOp);

/// The values of `--op`, one per [`EditOp`] (from [`EditOp::ALL`]).
static OPS: LazyLock<Vec<ExplainOp>> =
    LazyLock::new(|| EditOp::ALL.iter().copied().map(ExplainOp).collect());

impl clap::ValueEnum for ExplainOp {
    fn value_variants<'a>() -> &'a [Self] {
        &OPS
    }
    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        let value = clap::builder::PossibleValue::new(self.0.name());
        // The first `--op` named the three edge operations by their verb alone.
        Some(match self.0 {
            EditOp::FlipEdge => value.alias("flip"),
            EditOp::SplitEdge => value.alias("split"),
            EditOp::CollapseEdge => value.alias("collapse"),
            _ => value,
        })
    }
}

/// The structures `--op` can explain: the lab's structures that implement `MeshEdit`
/// (`[editable]` or `[moves]` in the registry), in the registry's order; not the C++ baselines
/// nor the Rust crates, whose records live inside their library and cannot be listed
/// ([`counted_structures`], which the counts and the report's teaching section take too).
pub fn editable() -> Vec<&'static str> {
    counted_structures()
}

/// The element asked for on the command line: `--edge`, `--face`, `--vertex`, `--vertices`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Asked {
    /// `--edge E`.
    pub edge: Option<u32>,
    /// `--face F`.
    pub face: Option<u32>,
    /// `--vertex V`.
    pub vertex: Option<u32>,
    /// `--vertices A,B,...`.
    pub vertices: Vec<u32>,
    /// `--edges E,F`.
    pub edges: Vec<u32>,
    /// `--faces F,G`.
    pub faces: Vec<u32>,
}

impl Asked {
    /// Only `--edge E`.
    pub fn edge(e: u32) -> Self {
        Self {
            edge: Some(e),
            ..Self::default()
        }
    }
    /// The flags given, as written.
    fn given(&self) -> Vec<String> {
        let mut out = Vec::new();
        if let Some(e) = self.edge {
            out.push(format!("--edge {e}"));
        }
        if let Some(f) = self.face {
            out.push(format!("--face {f}"));
        }
        if let Some(v) = self.vertex {
            out.push(format!("--vertex {v}"));
        }
        if !self.vertices.is_empty() {
            out.push(format!("--vertices {}", join(&self.vertices)));
        }
        if !self.edges.is_empty() {
            out.push(format!("--edges {}", join(&self.edges)));
        }
        if !self.faces.is_empty() {
            out.push(format!("--faces {}", join(&self.faces)));
        }
        out
    }

    /// The subject asked for, if any, of the kind `op` takes; the wrong flags for it are a
    /// usage error that says which it takes.
    fn subject(&self, op: EditOp) -> Result<Option<Subject>, Failure> {
        let given = self.given();
        if given.is_empty() {
            return Ok(None);
        }
        let kind = kind_of(op);
        let vs = &self.vertices;
        let only = |flag: bool| flag && given.len() == 1;
        let subject = match kind {
            SubjectKind::Vertex if only(self.vertex.is_some()) => self.vertex.map(Subject::Vertex),
            SubjectKind::Edge if only(self.edge.is_some()) => self.edge.map(Subject::Edge),
            SubjectKind::Face if only(self.face.is_some()) => self.face.map(Subject::Face),
            SubjectKind::Selected if given.len() == 1 => (self.vertex.map(Subject::Vertex))
                .or(self.edge.map(Subject::Edge))
                .or(self.face.map(Subject::Face)),
            SubjectKind::Corners if only(vs.len() >= 3) => Some(Subject::Vertices(vs.clone())),
            SubjectKind::TwoVertices if only(vs.len() == 2) => Some(Subject::Vertices(vs.clone())),
            SubjectKind::TwoEdges if only(self.edges.len() == 2) => {
                Some(Subject::Edges([self.edges[0], self.edges[1]]))
            }
            SubjectKind::TwoFaces if only(self.faces.len() == 2) => {
                Some(Subject::Faces([self.faces[0], self.faces[1]]))
            }
            SubjectKind::FaceAndCorners
                if self.face.is_some() && vs.len() == 2 && given.len() == 2 =>
            {
                self.face.map(|face| Subject::FaceAndCorners {
                    face,
                    a: vs[0],
                    b: vs[1],
                })
            }
            SubjectKind::VertexAndNeighbours
                if self.vertex.is_some() && vs.len() == 2 && given.len() == 2 =>
            {
                self.vertex.map(|vertex| Subject::VertexAndNeighbours {
                    vertex,
                    left: vs[0],
                    right: vs[1],
                })
            }
            _ => None,
        };
        subject.map(Some).ok_or_else(|| {
            Failure::usage(format!(
                "--op {op} takes {}, not {}",
                kind.flags(),
                given.join(" ")
            ))
        })
    }
}

fn join(vs: &[u32]) -> String {
    vs.iter().map(u32::to_string).collect::<Vec<_>>().join(",")
}

/// The command-line flags that ask for `subject` (what "try ..." suggests).
fn flags_of(subject: &Subject) -> String {
    match subject {
        Subject::Nothing | Subject::MirrorImage | Subject::WholeMesh => String::new(),
        Subject::FaceAndCorners { face, a, b } => format!("--face {face} --vertices {a},{b}"),
        Subject::Edges([e, f]) => format!("--edges {e},{f}"),
        Subject::Faces([f, g]) => format!("--faces {f},{g}"),
        Subject::Vertex(v) => format!("--vertex {v}"),
        Subject::Edge(e) => format!("--edge {e}"),
        Subject::Face(f) => format!("--face {f}"),
        Subject::Vertices(vs) => format!("--vertices {}", join(vs)),
        Subject::VertexAndNeighbours {
            vertex,
            left,
            right,
        } => format!("--vertex {vertex} --vertices {left},{right}"),
    }
}

/// One structure's explanation, for [`visit_editable`].
struct Explain<'a> {
    soup: &'a PolygonSoup,
    label: &'a str,
    op: EditOp,
    prepared: &'a Prepared,
}

impl EditVisitor for Explain<'_> {
    type Output = Result<String, Failure>;
    fn visit<M: MeshEdit + 'static>(self) -> Self::Output {
        self.run::<M>()
    }
}

/// The names `--op` explains for `name` (the four levels for `che`), or why it cannot.
fn structures_of(name: &str) -> Result<Vec<&'static str>, Failure> {
    let editable = editable();
    if name == super::explain_che::NAME {
        return Ok([CheL0::NAME, CheL1::NAME, CheL2::NAME, CheL3::NAME]
            .into_iter()
            .filter(|n| editable.contains(n))
            .collect());
    }
    if let Some(&found) = editable.iter().find(|&&n| n == name) {
        return Ok(vec![found]);
    }
    Err(if CPP_BASELINES.contains(&name) {
        let absent = missing_baseline(name)
            .map(|why| format!(" (and it is not in this build: {why})"))
            .unwrap_or_default();
        Failure::usage(format!(
            "--op: {name} edits through its C++ library's own Euler operations, and its records live inside that library, which --op cannot list{absent}; `topolab list` and `topolab explain {name}` show its declared edit costs. The structures whose records --op shows: che (its four levels), {}",
            editable.join(", ")
        ))
    } else if let Some((krate, _)) = peer_crate(name) {
        Failure::usage(format!(
            "--op: {name} edits through the crate {krate}'s own calls, and its records live inside that crate, which --op cannot list; `topolab list` shows the operations it offers and their declared costs. The structures whose records --op shows: che (its four levels), {}",
            editable.join(", ")
        ))
    } else {
        Failure::usage(format!(
            "--op: {name:?} cannot edit (or is not a structure); the editable structures: che (its four levels), {}",
            editable.join(", ")
        ))
    })
}

/// The refusal of a [`Choice`], for the preface: `; it is refused on ... (why): try ...`.
fn refused_hint(choice: &Choice, mesh_flag: &str) -> String {
    choice
        .refused
        .as_ref()
        .map(|(subject, why)| {
            let flags = flags_of(subject);
            if flags.is_empty() {
                format!("; it is refused on {} ({why})", subject_words(subject))
            } else {
                format!(
                    "; it is refused on {} ({why}): try {flags}{mesh_flag}",
                    subject_words(subject)
                )
            }
        })
        .unwrap_or_default()
}

/// A subject in words, without the mesh (for the preface).
fn subject_words(subject: &Subject) -> String {
    match subject {
        Subject::Nothing => "no element".to_string(),
        Subject::MirrorImage => "the mirror image".to_string(),
        Subject::WholeMesh => "the whole mesh".to_string(),
        Subject::FaceAndCorners { face, a, b } => format!("face {face} from corner {a} to {b}"),
        Subject::Edges([e, f]) => format!("edges {e} and {f}"),
        Subject::Faces([f, g]) => format!("faces {f} and {g}"),
        Subject::Vertex(v) => format!("vertex {v}"),
        Subject::Edge(e) => format!("edge {e}"),
        Subject::Face(f) => format!("face {f}"),
        Subject::Vertices(vs) if vs.len() == 2 => format!("vertices {} and {}", vs[0], vs[1]),
        Subject::Vertices(vs) => format!("corners {}", join(vs)),
        Subject::VertexAndNeighbours {
            vertex,
            left,
            right,
        } => format!("vertex {vertex} between neighbours {left} and {right}"),
    }
}

/// What `explain --op` counts besides the records: the structures shown beside NAME's
/// (`--structures`), and whether the same edit is counted on tori of growing size.
#[derive(Clone, Debug, Default)]
pub struct Counting {
    /// More structures, each explained and counted beside NAME's.
    pub beside: Vec<String>,
    /// Count the edit on the tori of the growth table too (a few hundred milliseconds per
    /// structure).
    pub growth: bool,
}

/// The text of `topolab explain NAME --op OP [element] [--mesh M]`; see the module docs.
pub fn run(
    name: &str,
    mesh: Option<&str>,
    op: EditOp,
    asked: &Asked,
    counting: &Counting,
) -> Result<String, Failure> {
    let mut names = structures_of(name)?;
    for other in &counting.beside {
        for n in structures_of(other)? {
            if !names.contains(&n) {
                names.push(n);
            }
        }
    }
    // An operation the structure does not offer is a missing feature, said so before any
    // element is chosen, never shown as a refusal of one.
    if let Some(&lacking) = names.iter().find(|n| offers(n, op) == Some(false)) {
        let offering: Vec<&str> = editable()
            .into_iter()
            .filter(|n| offers(n, op) == Some(true))
            .collect();
        return Err(Failure {
            message: format!(
                "{lacking} does not offer {op} (not offered: a missing feature, not a refusal of an element); the structures that offer it: {}",
                offering.join(", ")
            ),
            code: 1,
        });
    }
    let asked_subject = asked.subject(op)?;
    let mut preface = String::new();
    let kind = kind_of(op);
    let single = kind.is_single();
    let (soup, label, subject) = match (mesh, asked_subject) {
        (None, None) => {
            // Chosen on the structure asked about (its first level for `che`), so that a
            // refusal named is its own.
            let case = visit_editable(names[0], DefaultOn(op)).expect("an editable structure");
            if let Some(tetra) = &case.on_tetrahedron {
                let why = tetra
                    .refused
                    .as_ref()
                    .map(|(s, why)| format!(" ({}: {why})", subject_words(s)))
                    .unwrap_or_default();
                let _ = writeln!(
                    preface,
                    "no {op} succeeds on the open tetrahedron{why}: {} instead",
                    case.label
                );
            }
            let mesh_flag = case
                .mesh_flag
                .map(|m| format!(" --mesh {m}"))
                .unwrap_or_default();
            let subject = chosen(&case.choice, op, case.label, kind, &mesh_flag, &mut preface)?;
            (case.soup, case.label.to_string(), subject)
        }
        (_, asked_subject) => {
            let (soup, label) = mesh_or_tetrahedron(mesh, false, |s| {
                400 * (s.num_corners() + s.num_vertices()) as u64
            })?;
            let subject = match asked_subject {
                Some(subject) => subject,
                None if single => {
                    let choice = Choice {
                        success: Some(choose_single(kind)),
                        refused: None,
                    };
                    chosen(&choice, op, &label, kind, "", &mut preface)?
                }
                None => {
                    let choice = visit_editable(names[0], ChooseOn(&soup, op))
                        .expect("an editable structure");
                    chosen(&choice, op, &label, kind, "", &mut preface)?
                }
            };
            (soup, label, subject)
        }
    };
    let reference = IndexHalfEdge::from_soup(&soup).map_err(|e| Failure {
        message: format!("{label} is not an oriented manifold mesh: {e}"),
        code: 1,
    })?;
    let prepared = prepare(op, subject, &soup, &reference)
        .map_err(|e| Failure::usage(format!("--op {op}: {e} ({label})")))?;
    let mut out = preface;
    for &n in &names {
        let e = Explain {
            soup: &soup,
            label: &label,
            op,
            prepared: &prepared,
        };
        out += &visit_editable(n, e).expect("an editable structure")?;
    }
    let case = counted::Case {
        soup: &soup,
        label: &label,
        op,
        subject: &prepared.subject,
        description: &prepared.description,
    };
    out += &counted::table(&names, &case, counting.growth);
    Ok(out)
}

/// [`default_case_on`] the structure visited.
struct DefaultOn(EditOp);
impl EditVisitor for DefaultOn {
    type Output = DefaultCase;
    fn visit<M: MeshEdit + 'static>(self) -> DefaultCase {
        default_case_on::<M>(self.0)
    }
}

/// [`choose_on`] the structure visited.
struct ChooseOn<'a>(&'a PolygonSoup, EditOp);
impl EditVisitor for ChooseOn<'_> {
    type Output = Choice;
    fn visit<M: MeshEdit + 'static>(self) -> Choice {
        choose_on::<M>(self.0, self.1)
    }
}

/// The only subject of an operation that takes no element.
fn choose_single(kind: SubjectKind) -> Subject {
    match kind {
        SubjectKind::MirrorImage => Subject::MirrorImage,
        SubjectKind::WholeMesh => Subject::WholeMesh,
        _ => Subject::Nothing,
    }
}

/// The subject a [`Choice`] found, with the preface that names it and a refused one; a
/// failure (exit code 1) when the edit succeeds on none tried.
fn chosen(
    choice: &Choice,
    op: EditOp,
    label: &str,
    kind: SubjectKind,
    mesh_flag: &str,
    preface: &mut String,
) -> Result<Subject, Failure> {
    let single = kind.is_single();
    let Some(subject) = choice.success.clone() else {
        return Err(Failure {
            message: format!(
                "no {op} succeeds on the elements of {label} tried ({}){}; name one with {}",
                if single {
                    "its only one".to_string()
                } else {
                    format!(
                        "at most {} of them",
                        topolab_harness::teaching::edits::TRIED
                    )
                },
                choice
                    .refused
                    .as_ref()
                    .map(|(s, why)| format!(" ({}: {why})", subject_words(s)))
                    .unwrap_or_default(),
                kind.flags()
            ),
            code: 1,
        });
    };
    if !single {
        let _ = writeln!(
            preface,
            "no element given ({}): {} is the first on {label} on which {op} succeeds{}",
            kind.flags(),
            subject_words(&subject),
            refused_hint(choice, mesh_flag)
        );
    }
    Ok(subject)
}

impl Explain<'_> {
    fn run<M: MeshEdit + 'static>(self) -> Result<String, Failure> {
        let spec = edit::<M>(self.op);
        let op = self.op;
        let what = &self.prepared.description;
        let done = explain_on::<M>(self.soup, op, self.prepared).map_err(|e| {
            // The test that failed and the element that shows it, from the mesh before the
            // edit: the same for every structure that refuses it.
            let taught = match &e {
                Error::EditRefused { reason, .. } => witness(self.soup, op, self.prepared, *reason)
                    .map(|w| format!("\ntest and element: {w}"))
                    .unwrap_or_default(),
                _ => String::new(),
            };
            Failure {
                message: format!("{e} ({what} on {}){taught}", self.label),
                code: 1,
            }
        })?;
        let mut out = String::new();
        let w = &mut out;
        let own = done
            .own_id
            .map(|id| format!("; the structure's {id}"))
            .unwrap_or_default();
        let _ = writeln!(w, "{}: {op} of {what}{own} on {}", M::NAME, self.label);
        if let Some((setup, _)) = spec.setup {
            let _ = writeln!(
                w,
                "first, not explained: {setup} of {what} (what {op} then collects)"
            );
        }
        let _ = writeln!(
            w,
            "reads: {}",
            reads(Family::of::<M>(), op, spec.reads, spec.local)
        );
        let _ = writeln!(w, "writes (old -> new; + added, - removed):");
        for line in &done.changes {
            let _ = writeln!(w, "{line}");
        }
        let _ = writeln!(w);
        Ok(out)
    }
}
