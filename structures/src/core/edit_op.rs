//! The editing operations of [`MeshEdit`](crate::core::edit::MeshEdit) by name ([`EditOp`],
//! for their declared costs) and the reasons an edit is refused ([`Refusal`]): named below the
//! trait and the errors, which both speak of them.

/// One editing operation of [`MeshEdit`](crate::core::edit::MeshEdit), for its declared cost.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum EditOp {
    /// Add an unused vertex.
    AddVertex,
    /// Add a face on existing vertices.
    AddFace,
    /// Delete a face (its edges that border nothing else go with it).
    DeleteFace,
    /// Delete a vertex and every face around it.
    DeleteVertex,
    /// Flip the edge between two triangles to join their other two corners.
    FlipEdge,
    /// Split an edge (and its one or two triangles) at a new vertex.
    SplitEdge,
    /// Split a face into a fan of triangles around a new vertex.
    SplitFace,
    /// Collapse an edge into one of its end vertices, with the link condition checked.
    CollapseEdge,
    /// Split a vertex into an edge and two triangles: the inverse of a collapse.
    SplitVertex,
    /// Compact the slots of deleted elements.
    GarbageCollection,
    /// Merge two vertices into one ([`MeshEdit::weld_vertices`](crate::core::edit::MeshEdit::weld_vertices)).
    WeldVertices,
    /// Append a mesh and weld it along matching boundary curves
    /// ([`weld_meshes`](crate::algorithms::weld::weld_meshes)): a rebuild, O(n) everywhere.
    WeldMeshes,
}

impl EditOp {
    /// Every operation, in the order above.
    pub const ALL: [EditOp; 12] = [
        EditOp::AddVertex,
        EditOp::AddFace,
        EditOp::DeleteFace,
        EditOp::DeleteVertex,
        EditOp::FlipEdge,
        EditOp::SplitEdge,
        EditOp::SplitFace,
        EditOp::CollapseEdge,
        EditOp::SplitVertex,
        EditOp::GarbageCollection,
        EditOp::WeldVertices,
        EditOp::WeldMeshes,
    ];

    /// The kebab-case name.
    pub const fn name(self) -> &'static str {
        match self {
            EditOp::AddVertex => "add-vertex",
            EditOp::AddFace => "add-face",
            EditOp::DeleteFace => "delete-face",
            EditOp::DeleteVertex => "delete-vertex",
            EditOp::FlipEdge => "flip-edge",
            EditOp::SplitEdge => "split-edge",
            EditOp::SplitFace => "split-face",
            EditOp::CollapseEdge => "collapse-edge",
            EditOp::SplitVertex => "split-vertex",
            EditOp::GarbageCollection => "garbage-collection",
            EditOp::WeldVertices => "weld-vertices",
            EditOp::WeldMeshes => "weld-meshes",
        }
    }
}

impl std::fmt::Display for EditOp {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// Why an edit was refused (nothing was changed).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum Refusal {
    /// An id that is out of range or names a deleted element.
    NoSuchElement,
    /// A weld of a vertex to itself: both ids name the same vertex.
    SameVertex,
    /// A face with fewer than three corners or a repeated vertex.
    BadFace,
    /// The result would have an edge with more than two faces.
    NonManifoldEdge,
    /// The result would have a vertex whose faces form several fans.
    NonManifoldVertex,
    /// The operation needs triangles (flip, edge split, collapse) and a face is not one.
    NotTriangles,
    /// A flip of a boundary edge (it has one triangle).
    BoundaryEdge,
    /// The edge a flip or a split would create exists already.
    EdgeExists,
    /// The vertices asked for are not neighbours as the operation needs.
    NotNeighbours,
    /// A collapse that fails the link condition (the one-rings of the two vertices share a
    /// vertex that is not on a triangle of the edge), or that would join two boundaries
    /// through an interior edge or close a boundary triangle: the result would not be a
    /// manifold.
    LinkCondition,
    /// Boundary curves to weld run the same way where they meet: the result would not be
    /// oriented.
    Orientation,
    /// No boundary vertex of one mesh coincides with one of the other (within the tolerance).
    NothingToWeld,
    /// A case this structure does not implement yet (named in its docs).
    NotImplemented,
}

impl Refusal {
    /// What the refusal means, for messages.
    pub const fn message(self) -> &'static str {
        match self {
            Refusal::NoSuchElement => "an id is out of range or names a deleted element",
            Refusal::SameVertex => "both ids name the same vertex: a vertex cannot be welded to itself",
            Refusal::BadFace => "a face needs at least three distinct vertices",
            Refusal::NonManifoldEdge => "an edge would have more than two faces",
            Refusal::NonManifoldVertex => "a vertex's faces would form several fans",
            Refusal::NotTriangles => "the faces around the edge must be triangles",
            Refusal::BoundaryEdge => "a boundary edge has one triangle and cannot be flipped",
            Refusal::EdgeExists => "the edge it would create exists already",
            Refusal::NotNeighbours => "the vertices are not neighbours as required",
            Refusal::LinkCondition => {
                "the link condition fails: the result would not be a manifold"
            }
            Refusal::Orientation => {
                "the boundary curves run the same way where they meet: the result would not be oriented"
            }
            Refusal::NothingToWeld => "no boundary vertices coincide within the tolerance",
            Refusal::NotImplemented => "this case is not implemented by this structure",
        }
    }
}

impl std::fmt::Display for Refusal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.message())
    }
}
