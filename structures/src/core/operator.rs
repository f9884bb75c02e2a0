//! The vocabulary of queries: the kinds of [`Element`], the [`Operator`]s every structure
//! answers (and the [`Input`] each takes), and the theoretical [`Cost`] a structure declares for
//! each. Plain enums that every other part of the crate names, so they sit below the trait
//! ([`crate::core::topology`]) and the workloads ([`crate::core::workload`]) that use them.
//!
//! Relations follow the notation `Rpq` of the CHE thesis chapter: given a p-simplex, the
//! q-simplices around it (0 = vertex, 1 = edge, 2 = face).

/// A kind of mesh element.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Element {
    /// A vertex (0-simplex).
    Vertex,
    /// An edge (1-simplex).
    Edge,
    /// A face (2-cell).
    Face,
    /// The whole mesh.
    Mesh,
}

impl Element {
    /// The lower-case name, as in messages ("vertex", "edge", "face", "mesh").
    pub const fn name(self) -> &'static str {
        match self {
            Element::Vertex => "vertex",
            Element::Edge => "edge",
            Element::Face => "face",
            Element::Mesh => "mesh",
        }
    }
}

/// What one query of an [`Operator`] is given ([`Operator::input`]): the element whose
/// neighbourhood it asks about, which is also what a sweep of the operator walks over.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum Input {
    /// A vertex.
    Vertex,
    /// An edge.
    Edge,
    /// A face.
    Face,
    /// An edge and a face it bounds (successor, predecessor). Every (edge, face) pair of a
    /// mesh is one edge of one face, so a sweep walks the faces and each face's edges.
    EdgeOfFace,
    /// Nothing: the question is about the whole mesh (boundary curves).
    Mesh,
}

impl Input {
    /// The elements a query is given, in argument order.
    pub const fn elements(self) -> &'static [Element] {
        match self {
            Input::Vertex => &[Element::Vertex],
            Input::Edge => &[Element::Edge],
            Input::Face => &[Element::Face],
            Input::EdgeOfFace => &[Element::Edge, Element::Face],
            Input::Mesh => &[Element::Mesh],
        }
    }
}

/// Every operator a structure answers, in catalogue order.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Operator {
    /// R00: vertex → neighbour vertices.
    R00,
    /// R01: vertex → incident edges.
    R01,
    /// R02: vertex → incident faces.
    R02,
    /// R10: edge → its two vertices.
    R10,
    /// R11: edge → the other edges of its incident faces (the edge star).
    R11,
    /// R12: edge → its one or two faces.
    R12,
    /// R20: face → its vertices in order.
    R20,
    /// R21: face → its edges in order.
    R21,
    /// R22: face → the faces across its edges.
    R22,
    /// Is a vertex on the boundary?
    BoundaryVertex,
    /// Is an edge on the boundary?
    BoundaryEdge,
    /// All boundary curves as closed loops of edges.
    BoundaryCurves,
    /// The edge after a given edge in a given face (the successor of the lecture on
    /// polygon-mesh data structures).
    EdgeSuccessor,
    /// The edge before a given edge in a given face (the lecture's predecessor).
    EdgePredecessor,
}

impl Operator {
    /// All operators, in catalogue order.
    pub const ALL: [Operator; 14] = [
        Operator::R00,
        Operator::R01,
        Operator::R02,
        Operator::R10,
        Operator::R11,
        Operator::R12,
        Operator::R20,
        Operator::R21,
        Operator::R22,
        Operator::BoundaryVertex,
        Operator::BoundaryEdge,
        Operator::BoundaryCurves,
        Operator::EdgeSuccessor,
        Operator::EdgePredecessor,
    ];

    /// The kebab-case name used in the CLI, JSON and report.
    pub const fn name(self) -> &'static str {
        match self {
            Operator::R00 => "r00",
            Operator::R01 => "r01",
            Operator::R02 => "r02",
            Operator::R10 => "r10",
            Operator::R11 => "r11",
            Operator::R12 => "r12",
            Operator::R20 => "r20",
            Operator::R21 => "r21",
            Operator::R22 => "r22",
            Operator::BoundaryVertex => "boundary-vertex",
            Operator::BoundaryEdge => "boundary-edge",
            Operator::BoundaryCurves => "boundary-curves",
            Operator::EdgeSuccessor => "edge-successor",
            Operator::EdgePredecessor => "edge-predecessor",
        }
    }

    /// The operator of a kebab-case name.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|op| op.name() == name)
    }

    /// What one query of the operator is given (the lab's one answer to "which element does
    /// this operator take?").
    pub const fn input(self) -> Input {
        match self {
            Operator::R00 | Operator::R01 | Operator::R02 | Operator::BoundaryVertex => {
                Input::Vertex
            }
            Operator::R10 | Operator::R11 | Operator::R12 | Operator::BoundaryEdge => Input::Edge,
            Operator::R20 | Operator::R21 | Operator::R22 => Input::Face,
            Operator::EdgeSuccessor | Operator::EdgePredecessor => Input::EdgeOfFace,
            Operator::BoundaryCurves => Input::Mesh,
        }
    }
}

/// A theoretical cost, as the tables of the lecture on polygon-mesh data structures and
/// Table 4.1 of the CHE thesis chapter state it.
///
/// `n0`, `n1`, `n2` are the numbers of vertices, edges and faces; `k` the size of the local
/// neighbourhood (valence of a vertex, corners of a face); `∂n1` the boundary edges.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Cost {
    /// O(1).
    Constant,
    /// O(log n): a binary search.
    Log,
    /// O(k): proportional to the local neighbourhood (deg v, or the k of a k-gon).
    Local,
    /// O(k²): a local search for each of the k local elements (e.g. each neighbour of one
    /// vertex looked for in the ring of another, as a collapse's link condition does).
    LocalSquared,
    /// O(∂n1): proportional to the boundary.
    Boundary,
    /// O(n): a scan of one of the element lists.
    Linear,
    /// O(k·n): a scan for each of the k local elements.
    LocalTimesLinear,
    /// O(n²): a scan for each element of a scan.
    Quadratic,
}

impl Cost {
    /// How the cost reads in the lecture's notation.
    pub const fn notation(self) -> &'static str {
        match self {
            Cost::Constant => "O(1)",
            Cost::Log => "O(log n)",
            Cost::Local => "O(k)",
            Cost::LocalSquared => "O(k²)",
            Cost::Boundary => "O(∂n1)",
            Cost::Linear => "O(n)",
            Cost::LocalTimesLinear => "O(k·n)",
            Cost::Quadratic => "O(n²)",
        }
    }

    /// The exponent of time per query against mesh size this cost predicts on meshes of
    /// bounded valence (0 for O(1), O(k), O(log n) (≈0); 1 for scans). Boundary: the
    /// generated meshes' boundaries grow like √n, so 0.5.
    pub const fn expected_exponent(self) -> f64 {
        match self {
            Cost::Constant | Cost::Log | Cost::Local | Cost::LocalSquared => 0.0,
            Cost::Boundary => 0.5,
            Cost::Linear | Cost::LocalTimesLinear => 1.0,
            Cost::Quadratic => 2.0,
        }
    }
}
