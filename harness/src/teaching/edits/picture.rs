//! What the report keeps of an edit explained ([`super::explain_on`]): the records it wrote,
//! one line each as `topolab explain NAME --op OP` prints them, and the mesh drawn before and
//! after.

/// One edit on one structure for the teaching section: the records it wrote, as
/// `topolab explain NAME --op OP` prints them, and the mesh before and after.
#[derive(Clone, Debug, serde::Serialize)]
pub struct TeachingEdit {
    /// The operation.
    pub op: topolab_structures::EditOp,
    /// The structure.
    pub structure: String,
    /// The mesh, in words.
    pub mesh: String,
    /// The element edited, in words ("edge 1 (v1 - v3)").
    pub subject: String,
    /// The records that changed, one line each (`  key.field: old -> new`, `+ key: new`,
    /// `- key: old`).
    pub changes: Vec<String>,
    /// The mesh before the edit, the element marked.
    pub before: EditPicture,
    /// The mesh after it, what the edit made marked.
    pub after: EditPicture,
}

/// A small mesh to draw: its vertices (`None` where deleted), its faces and what is marked.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct EditPicture {
    /// Each vertex's position, `None` for a deleted vertex.
    pub vertices: Vec<Option<[f64; 3]>>,
    /// The live faces, each its corners counter-clockwise.
    pub faces: Vec<Vec<u32>>,
    /// The vertices drawn marked.
    pub marked_vertices: Vec<u32>,
    /// The edges drawn marked, by their ends.
    pub marked_edges: Vec<[u32; 2]>,
}
