//! What an operation acts on ([`SubjectKind`]) and the element the user names ([`Subject`]),
//! numbered the same on every structure.

/// What an editing operation acts on, and how `explain --op` asks for it.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum SubjectKind {
    /// Nothing of the mesh: the operation adds a vertex (at a point it is given).
    Nothing,
    /// A vertex (`--vertex V`).
    Vertex,
    /// An edge (`--edge E`).
    Edge,
    /// A face (`--face F`).
    Face,
    /// The corners of a new face, counter-clockwise (`--vertices A,B,C`).
    Corners,
    /// Two vertices (`--vertices A,B`).
    TwoVertices,
    /// A vertex and two of its neighbours (`--vertex V --vertices L,R`).
    VertexAndNeighbours,
    /// A second mesh: the mesh's mirror image across the plane z = 0, turned so that it is
    /// oriented the other way (no element to name: `--mesh` chooses the mesh).
    MirrorImage,
    /// A face and two of its corners that are not neighbours in it (`--face F --vertices A,B`).
    FaceAndCorners,
    /// The whole mesh: every vertex (no element to name).
    WholeMesh,
    /// Two edges (`--edges E,F`).
    TwoEdges,
    /// Two faces (`--faces F,G`).
    TwoFaces,
    /// A vertex, an edge or a face (`--vertex V`, `--edge E` or `--face F`): a selection made
    /// around it selects elements of its kind.
    Selected,
}

impl SubjectKind {
    /// Does this kind name no element (the operation has one subject on a mesh)?
    pub const fn is_single(self) -> bool {
        matches!(
            self,
            SubjectKind::Nothing | SubjectKind::MirrorImage | SubjectKind::WholeMesh
        )
    }
}

impl SubjectKind {
    /// How the command line names this kind of element, for messages.
    pub const fn flags(self) -> &'static str {
        match self {
            SubjectKind::Nothing => "no element",
            SubjectKind::Vertex => "--vertex V",
            SubjectKind::Edge => "--edge E",
            SubjectKind::Face => "--face F",
            SubjectKind::Corners => "--vertices A,B,C (three or more corners)",
            SubjectKind::TwoVertices => "--vertices A,B",
            SubjectKind::VertexAndNeighbours => "--vertex V --vertices L,R",
            SubjectKind::MirrorImage => {
                "no element (the mesh of --mesh is welded to its mirror image)"
            }
            SubjectKind::FaceAndCorners => {
                "--face F --vertices A,B (two corners of the face that are not neighbours in it)"
            }
            SubjectKind::WholeMesh => "no element (every vertex of the mesh of --mesh)",
            SubjectKind::TwoEdges => "--edges E,F (two boundary edges)",
            SubjectKind::TwoFaces => "--faces F,G",
            SubjectKind::Selected => {
                "--vertex V, --edge E or --face F (the selection: elements of its kind around it)"
            }
        }
    }
}

/// The element an edit is done to, in the numbering of the module docs.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Subject {
    /// Nothing of the mesh ([`SubjectKind::Nothing`]).
    Nothing,
    /// A vertex.
    Vertex(u32),
    /// An edge.
    Edge(u32),
    /// A face.
    Face(u32),
    /// The corners of a new face ([`SubjectKind::Corners`]) or two vertices
    /// ([`SubjectKind::TwoVertices`]).
    Vertices(Vec<u32>),
    /// A vertex and two of its neighbours ([`SubjectKind::VertexAndNeighbours`]).
    VertexAndNeighbours {
        /// The vertex.
        vertex: u32,
        /// The neighbour on the left of the new edge.
        left: u32,
        /// The neighbour on its right.
        right: u32,
    },
    /// The mesh's mirror image ([`SubjectKind::MirrorImage`]).
    MirrorImage,
    /// A face and two of its corners ([`SubjectKind::FaceAndCorners`]).
    FaceAndCorners {
        /// The face.
        face: u32,
        /// The corner the new edge starts at.
        a: u32,
        /// The corner it ends at.
        b: u32,
    },
    /// The whole mesh ([`SubjectKind::WholeMesh`]).
    WholeMesh,
    /// Two edges ([`SubjectKind::TwoEdges`]).
    Edges([u32; 2]),
    /// Two faces ([`SubjectKind::TwoFaces`]).
    Faces([u32; 2]),
}

impl Subject {
    /// The kind of element this is.
    pub fn kind(&self) -> SubjectKind {
        match self {
            Subject::Nothing => SubjectKind::Nothing,
            Subject::Vertex(_) => SubjectKind::Vertex,
            Subject::Edge(_) => SubjectKind::Edge,
            Subject::Face(_) => SubjectKind::Face,
            Subject::Vertices(v) if v.len() == 2 => SubjectKind::TwoVertices,
            Subject::Vertices(_) => SubjectKind::Corners,
            Subject::VertexAndNeighbours { .. } => SubjectKind::VertexAndNeighbours,
            Subject::MirrorImage => SubjectKind::MirrorImage,
            Subject::FaceAndCorners { .. } => SubjectKind::FaceAndCorners,
            Subject::WholeMesh => SubjectKind::WholeMesh,
            Subject::Edges(_) => SubjectKind::TwoEdges,
            Subject::Faces(_) => SubjectKind::TwoFaces,
        }
    }
}
