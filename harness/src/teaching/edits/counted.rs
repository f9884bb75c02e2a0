//! Edits counted: the same call table ([`edit`](super::edit)), preparation and records as the
//! explained edits, compiled a second time over the counting build of the structures
//! (`topolab-structures-counted`), so that an edit's container reads are counted as a query's
//! are (`explain --trace`), and its writes are the elements of its records that changed.
//!
//! What the counts are, exactly:
//! - **reads**: the container reads the edit makes through the structure's counted accessors
//!   (every query primitive, and the searches the face-rewriting structures run through
//!   them); the element the edit acts on is found before the count starts, as a caller that
//!   holds its id would have it. A read the edit code makes straight from a container,
//!   without an accessor, is not in the count (so a count is at most what the edit reads).
//! - **writes**: the fields of the structure's records that changed, as `explain --op` lists
//!   them old → new (a record added or removed counts its fields), so a write of the value a
//!   field already held is not counted.
//!
//! Both are the same for every structure: what differs between two structures' counts is
//! their design, which is what [`growth`] shows: the same edit on tori of growing size.

// The twin modules are the explained edits' own files, compiled a second time over the other
// crate on purpose (as `topolab-structures-counted` compiles the structures' sources); the
// counting uses part of them.
#![allow(dead_code, clippy::duplicate_mod)]

// The subjects are the same in both builds (ids in the mesh's numbering): one type, no twin.
use super::subject::{self, Subject};
use crate::teaching::trace::counted_soup;
use topolab_structures_counted as st;
use topolab_structures_counted::core::reads;
use topolab_structures_counted::registry::{visit_editable, EditVisitor};
use topolab_structures_counted::{IndexHalfEdge, MeshEdit, MeshTopology, PolygonSoup};

#[path = "operations.rs"]
mod operations;
#[path = "prepare.rs"]
mod prepare;
#[path = "records.rs"]
mod records;

/// The tori of the growth table, triangles: about 128, 2,000 and 32,000, each 16 times the last.
pub const GROWTH_FACES: [usize; 3] = [128, 2_000, 32_000];

/// One edit on one structure, counted.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CountedEdit {
    /// The structure.
    pub structure: &'static str,
    /// Its declared cost of the operation, in the notation of the queries' costs.
    pub cost: String,
    /// Does that cost grow with the mesh (a scan: O(n), O(k·n), O(n²))?
    pub scans: bool,
    /// Container reads through the structure's counted accessors.
    pub reads: u64,
    /// Elements of its records that changed (fields, a list's entries).
    pub writes: u64,
    /// The structure's refusal, when it refused (nothing then changed).
    pub refused: Option<String>,
}

/// Why an edit cannot be counted on a structure.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CountError {
    /// Not one of the lab's editable structures (the baselines and the crates edit inside
    /// their libraries, out of the counting build's reach).
    NotCounted(String),
    /// The mesh, or the element on it, does not take the edit (not an oriented manifold, an
    /// element of the wrong kind or past the mesh's count, a structure that cannot store it).
    Mesh(String),
    /// The structure does not offer the operation (a missing feature, not a refusal).
    NotOffered(String),
}

impl std::fmt::Display for CountError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CountError::NotCounted(m) | CountError::Mesh(m) | CountError::NotOffered(m) => {
                f.write_str(m)
            }
        }
    }
}

/// The lab's structures that implement `MeshEdit`, in registry order: those whose edits the
/// counting build counts (the baselines and the Rust crates edit inside their libraries) and
/// `explain --op` lists record by record.
pub fn counted_structures() -> Vec<&'static str> {
    struct Probe;
    impl EditVisitor for Probe {
        type Output = ();
        fn visit<M: MeshEdit + 'static>(self) {}
    }
    st::registry::NAMES
        .iter()
        .copied()
        .filter(|n| visit_editable(n, Probe).is_some())
        .collect()
}

/// The counting build's operation of the timed build's `op` (the same enum, compiled twice).
fn counted_op(op: topolab_structures::EditOp) -> st::EditOp {
    st::EditOp::ALL
        .iter()
        .copied()
        .find(|o| o.name() == op.name())
        .expect("both builds have every operation")
}

/// One edit to count on any structure: the mesh in the counting build, the operation, and its
/// element found once on the reference (every structure then finds it by its ends or corners).
pub struct EditCase {
    soup: PolygonSoup,
    op: st::EditOp,
    prepared: prepare::Prepared,
    /// The mesh's faces.
    pub faces: usize,
}

impl EditCase {
    /// `op` on `subject` of `soup`; an error when the mesh or the element does not take it.
    pub fn new(
        soup: &topolab_structures::PolygonSoup,
        op: topolab_structures::EditOp,
        subject: &Subject,
    ) -> Result<EditCase, CountError> {
        let soup = counted_soup(soup);
        let op = counted_op(op);
        let reference = IndexHalfEdge::from_soup(&soup)
            .map_err(|e| CountError::Mesh(format!("not an oriented manifold mesh: {e}")))?;
        let prepared = prepare::prepare(op, subject.clone(), &soup, &reference)
            .map_err(|e| CountError::Mesh(e.to_string()))?;
        Ok(EditCase {
            faces: soup.num_faces(),
            soup,
            op,
            prepared,
        })
    }

    /// Does the edit in `structure` built from the mesh, counting its reads and writes.
    pub fn count(&self, structure: &str) -> Result<CountedEdit, CountError> {
        let visit = Count {
            soup: &self.soup,
            op: self.op,
            prepared: &self.prepared,
        };
        visit_editable(structure, visit).ok_or_else(|| {
            CountError::NotCounted(format!(
                "{structure} is not one of the lab's editable structures, whose edits the counting build counts"
            ))
        })?
    }
}

/// Does `op` on `subject` in `structure` built from `soup`, counting its reads and writes
/// (one [`EditCase`], counted once).
pub fn count(
    structure: &str,
    soup: &topolab_structures::PolygonSoup,
    op: topolab_structures::EditOp,
    subject: &Subject,
) -> Result<CountedEdit, CountError> {
    EditCase::new(soup, op, subject)?.count(structure)
}

/// The [`EditCase`]s of the growth table: `op` on `subject` on tori of [`GROWTH_FACES`]
/// triangles, the same element ids (which each torus has: its ids start at 0).
pub fn growth(
    op: topolab_structures::EditOp,
    subject: &Subject,
) -> Vec<(usize, Result<EditCase, CountError>)> {
    growth_on(op, subject, &GROWTH_FACES)
}

/// [`growth`] on tori of about `sizes` triangles.
pub fn growth_on(
    op: topolab_structures::EditOp,
    subject: &Subject,
    sizes: &[usize],
) -> Vec<(usize, Result<EditCase, CountError>)> {
    sizes
        .iter()
        .map(|&faces| {
            let torus = topolab_structures::meshes::torus_with_triangles(faces);
            (torus.num_faces(), EditCase::new(&torus, op, subject))
        })
        .collect()
}

/// One structure's counts of an edit on the tori of [`GROWTH_FACES`] ([`growth_of`]).
#[derive(Clone, Debug)]
pub struct Growth {
    /// The structure.
    pub structure: String,
    /// Per torus, its faces and the count (or why there is none).
    pub counts: Vec<(usize, Result<CountedEdit, CountError>)>,
}

impl Growth {
    /// The structure's declared cost of the edit, from its first count.
    pub fn cost(&self) -> Option<&str> {
        self.first().map(|c| c.cost.as_str())
    }
    /// Does that cost grow with the mesh ([`CountedEdit::scans`])?
    pub fn scans(&self) -> bool {
        self.first().is_some_and(|c| c.scans)
    }
    fn first(&self) -> Option<&CountedEdit> {
        self.counts.iter().find_map(|(_, c)| c.as_ref().ok())
    }
}

/// `op` on `subject` counted on every structure of `names` on the tori of about `sizes`
/// triangles (each torus's element prepared once, [`growth_on`]).
pub fn growth_of(
    op: topolab_structures::EditOp,
    subject: &Subject,
    names: &[&str],
    sizes: &[usize],
) -> Vec<Growth> {
    let tori = growth_on(op, subject, sizes);
    names
        .iter()
        .map(|&name| Growth {
            structure: name.to_string(),
            counts: tori
                .iter()
                .map(|(faces, case)| {
                    let found = case
                        .as_ref()
                        .map_err(Clone::clone)
                        .and_then(|c| c.count(name));
                    (*faces, found)
                })
                .collect(),
        })
        .collect()
}

struct Count<'a> {
    soup: &'a PolygonSoup,
    op: st::EditOp,
    prepared: &'a prepare::Prepared,
}

impl EditVisitor for Count<'_> {
    type Output = Result<CountedEdit, CountError>;
    fn visit<M: MeshEdit + 'static>(self) -> Self::Output {
        if !M::supports(self.op) {
            return Err(CountError::NotOffered(format!(
                "{} does not offer {}",
                M::NAME,
                self.op
            )));
        }
        let spec = operations::edit::<M>(self.op);
        let mut m = M::from_soup(self.soup).map_err(|e| CountError::Mesh(e.to_string()))?;
        let mut target = self.prepared.target(&m).ok_or_else(|| {
            CountError::Mesh(format!(
                "{} has no {} after building the mesh",
                M::NAME,
                self.prepared.description
            ))
        })?;
        if let Some((what, setup)) = spec.setup {
            setup(&mut m, &mut target)
                .map_err(|e| CountError::Mesh(format!("{what} before it: {e}")))?;
        }
        let before = records::records(&m);
        let (done, reads) = reads::count(|| (spec.call)(&mut m, &target));
        let after = records::records(&m);
        Ok(CountedEdit {
            structure: M::NAME,
            cost: M::edit_cost(self.op).notation().to_string(),
            scans: M::edit_cost(self.op).expected_exponent() >= 1.0,
            reads,
            writes: records::written(&before, &after),
            refused: done.err().map(|e| e.to_string()),
        })
    }
}
