//! The one error type of `topolab-structures`.
//!
//! Readers, soup checks, structure construction and `validate()` all answer with [`Error`].
//! Every variant names the offending element (face, vertex, edge by its end vertices) or the
//! place in the file (line or byte offset), so a user can find the problem.

use std::path::PathBuf;

/// A file format the lab reads or writes.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Format {
    /// Wavefront OBJ.
    Obj,
    /// Object File Format.
    Off,
    /// Stanford polygon file format (ASCII or binary).
    Ply,
    /// STL, ASCII or binary (triangles with their corners' positions, welded on reading).
    Stl,
}

impl std::fmt::Display for Format {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Format::Obj => "OBJ",
            Format::Off => "OFF",
            Format::Ply => "PLY",
            Format::Stl => "STL",
        })
    }
}

/// Where in a file a problem was found.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Location {
    /// 1-based line of a text file.
    Line(usize),
    /// Byte offset in a binary file (or binary body).
    Byte(u64),
}

impl std::fmt::Display for Location {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Location::Line(l) => write!(f, "line {l}"),
            Location::Byte(b) => write!(f, "byte {b}"),
        }
    }
}

/// How the ids in an error are numbered: from 0 as the lab numbers elements, or from 1 as an
/// OBJ file numbers its vertices (and, by the order of its `f` statements, its faces), so that
/// a message about a file names its elements as the file does.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub enum Numbering {
    /// From 0: the lab's ids (and OFF's, PLY's, STL's).
    #[default]
    FromZero,
    /// From 1: OBJ's.
    FromOne,
}

impl Numbering {
    /// The first id: 0 or 1.
    pub fn first(self) -> u32 {
        match self {
            Numbering::FromZero => 0,
            Numbering::FromOne => 1,
        }
    }
}

impl std::fmt::Display for Numbering {
    /// Nothing for the lab's numbering; a note for a file's own.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Numbering::FromZero => Ok(()),
            Numbering::FromOne => f.write_str(" (numbered from 1, as in the file)"),
        }
    }
}

/// Everything that can go wrong in `topolab-structures`.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// The operating system refused to read or write a file.
    #[error("cannot access {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// What the OS said.
        #[source]
        source: std::io::Error,
    },
    /// The file name does not tell which format to read.
    #[error("cannot tell the format of {path}: expected an .obj, .off, .ply or .stl file")]
    UnknownFormat {
        /// The file.
        path: PathBuf,
    },
    /// A token or line that the format does not allow.
    #[error("{format} {location}: {message}")]
    Syntax {
        /// The format being read.
        format: Format,
        /// Where.
        location: Location,
        /// What was expected and what was found.
        message: String,
    },
    /// The file ended before the elements its header announced.
    #[error("{format} {location}: file ends early: {message}")]
    Truncated {
        /// The format being read.
        format: Format,
        /// Where the file ended.
        location: Location,
        /// What was still expected.
        message: String,
    },
    /// A header announces more elements than the file could hold; nothing was allocated.
    #[error("{format}: header announces {announced} {what}, but the file has room for at most {possible}")]
    ImplausibleHeader {
        /// The format being read.
        format: Format,
        /// "vertices" or "faces".
        what: &'static str,
        /// What the header says.
        announced: u64,
        /// The most the remaining bytes could hold.
        possible: u64,
    },
    /// A mesh with more elements than `u32` handles can address.
    #[error("{what}: {count} elements do not fit u32 handles")]
    TooLarge {
        /// Which element kind.
        what: &'static str,
        /// How many there are.
        count: u64,
    },
    /// A face refers to a vertex that does not exist (or a negative / overflowing index).
    #[error("face {face} refers to vertex {index}, but there are {vertices} vertices{numbering}")]
    IndexOutOfRange {
        /// The face (input order, numbered as `numbering` says).
        face: usize,
        /// The index as written (relative indices resolved), numbered as `numbering` says.
        index: i64,
        /// How many vertices exist.
        vertices: usize,
        /// How `face` and `index` are numbered.
        numbering: Numbering,
    },
    /// A coordinate is NaN or infinite.
    #[error("vertex {vertex} has a non-finite coordinate {value}{numbering}")]
    NonFiniteCoordinate {
        /// The vertex.
        vertex: usize,
        /// The offending value.
        value: f64,
        /// How `vertex` is numbered.
        numbering: Numbering,
    },
    /// A coordinate outside the range in which the convex hull's exact predicates stay exact:
    /// their products of three coordinate differences would overflow (or underflow) a double.
    #[error("point {vertex} has the coordinate {value:e}, outside the range the hull's exact predicates handle: 0, or a magnitude from {min:e} to {max:e} (2^-250 to 2^250); scale the points")]
    CoordinateOutOfRange {
        /// The point (vertex) with the coordinate.
        vertex: usize,
        /// The offending value.
        value: f64,
        /// The smallest magnitude accepted besides 0.
        min: f64,
        /// The largest magnitude accepted.
        max: f64,
    },
    /// A face with fewer than three corners.
    #[error("face {face} has {corners} corners; a face needs at least 3{numbering}")]
    TooFewCorners {
        /// The face.
        face: usize,
        /// How many corners it has.
        corners: usize,
        /// How `face` is numbered.
        numbering: Numbering,
    },
    /// A face that uses one vertex twice.
    #[error("face {face} uses vertex {vertex} more than once{numbering}")]
    RepeatedVertex {
        /// The face.
        face: usize,
        /// The repeated vertex.
        vertex: u32,
        /// How `face` and `vertex` are numbered.
        numbering: Numbering,
    },
    /// An edge with more than two incident faces.
    #[error("edge ({a}, {b}) is shared by {} faces {faces:?}; a manifold edge has one or two", faces.len())]
    NonManifoldEdge {
        /// One end vertex.
        a: u32,
        /// The other end vertex.
        b: u32,
        /// Every face that uses the edge.
        faces: Vec<u32>,
    },
    /// Two faces use their shared edge in the same direction: their orientations disagree.
    #[error("faces {f} and {g} both traverse edge ({a} -> {b}): inconsistent orientation")]
    InconsistentOrientation {
        /// Start vertex of the edge in both faces.
        a: u32,
        /// End vertex.
        b: u32,
        /// One face.
        f: u32,
        /// The other face.
        g: u32,
    },
    /// A vertex whose faces form more than one fan (e.g. two cones touching at their tips).
    #[error("vertex {vertex} is non-manifold: its faces form {fans} separate fans")]
    NonManifoldVertex {
        /// The vertex.
        vertex: u32,
        /// How many fans its star falls into.
        fans: usize,
    },
    /// A triangle-only structure was given a polygon with more corners.
    #[error("{structure} stores triangles only, but face {face} has {corners} corners")]
    NotTriangles {
        /// The structure that refused.
        structure: &'static str,
        /// The first offending face.
        face: usize,
        /// Its number of corners.
        corners: usize,
    },
    /// Two vertices at the same position, which a structure that identifies vertices by
    /// their coordinates (explicit storage) cannot tell apart.
    #[error(
        "{structure} identifies vertices by position, but vertices {first} and {second} coincide"
    )]
    CoincidentVertices {
        /// The structure that refused.
        structure: &'static str,
        /// The first vertex.
        first: u32,
        /// The vertex at the same position.
        second: u32,
    },
    /// The regular grid (and its height field) represent grid meshes only.
    #[error("{structure} represents grid meshes only: {reason}")]
    NotAGrid {
        /// The structure that refused.
        structure: &'static str,
        /// Why this soup is not one of its grids.
        reason: String,
    },
    /// Points whose convex hull is not a solid: fewer than four distinct points, or all of
    /// them on one line or one plane (the 3D hull algorithms need four points not in a plane).
    #[error("the {distinct} distinct points span only dimension {dimension}; a 3D convex hull needs four points not in one plane")]
    DegeneratePoints {
        /// How many distinct positions there are.
        distinct: usize,
        /// The dimension of their affine hull (0: one point, 1: a line, 2: a plane).
        dimension: u8,
    },
    /// A parameter of an algorithm outside the values it accepts (an adaptive refinement's
    /// `max_edge` that is not a positive finite length, a region whose minimum exceeds its
    /// maximum); nothing was done.
    #[error("{parameter} = {value}: it must be {expected}")]
    InvalidParameter {
        /// The parameter, as the algorithm names it.
        parameter: &'static str,
        /// The value given, as text (a number or a box).
        value: String,
        /// What it must be.
        expected: &'static str,
    },
    /// An algorithm would make more elements than the budget its caller gave (the most `u32`
    /// ids number, or the available memory holds); it stopped before passing it.
    #[error("{what} would pass the limit of {limit}")]
    BudgetExceeded {
        /// What would pass the limit ("faces").
        what: &'static str,
        /// The limit.
        limit: u64,
    },
    /// A structure's `validate()` found a broken invariant.
    #[error("{structure}: invariant broken: {message}")]
    Invariant {
        /// The structure.
        structure: &'static str,
        /// Which invariant and where.
        message: String,
    },
    /// A request outside what the structure or mesh offers (e.g. an unknown structure name).
    #[error("{0}")]
    Unsupported(String),
    /// A query about an element the structure does not have: an id past its count.
    #[error("{structure} has no {} {id} (it has {count}, numbered from 0)", element.name())]
    ElementOutOfRange {
        /// The structure asked.
        structure: &'static str,
        /// The kind of element.
        element: crate::core::operator::Element,
        /// The id asked about.
        id: u32,
        /// How many elements of that kind the structure has.
        count: u32,
    },
    /// An edit ([`crate::MeshEdit`]) that cannot be done on this mesh; nothing was changed.
    #[error("{structure} refuses {op}: {reason}")]
    EditRefused {
        /// The structure that refused.
        structure: &'static str,
        /// The operation.
        op: crate::core::edit_op::EditOp,
        /// Why.
        reason: crate::core::edit_op::Refusal,
    },
    /// A `.che` file (the CHE's containers, [`crate::che::file`]) that cannot be mapped or
    /// whose check failed.
    #[error("{path}: {problem}")]
    CheFile {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        problem: crate::core::che_format::CheFileProblem,
    },
    /// A vertex of so many faces that a library whose construction searches a vertex's
    /// half-edges for each face it adds there (OpenMesh, CGAL, lox) would take time quadratic
    /// in them to build the mesh ([`Connectivity::check_star_sizes`](crate::Connectivity::check_star_sizes)).
    /// Refused before the library sees the mesh.
    #[error("vertex {vertex} has {faces} faces in {fans} fans; the library searches a vertex's half-edges for each face it adds there, about {steps} steps for this mesh (its vertices' face counts squared), more than the {budget} the lab lets it take (16 a corner and 2^24)")]
    StarTooLarge {
        /// The vertex with the most faces.
        vertex: u32,
        /// Its faces (corners).
        faces: usize,
        /// The fans they form.
        fans: usize,
        /// The vertices' face counts, squared and summed.
        steps: u64,
        /// The most steps allowed.
        budget: u64,
    },
    /// A mesh a format cannot hold as it is: written, the file would not read back as this
    /// mesh (an empty mesh, a coordinate STL's `float` cannot hold, corners STL's welding would
    /// join into one vertex). Nothing was written.
    #[error("cannot write it as {format}: {reason}")]
    NotWritable {
        /// The format asked for.
        format: Format,
        /// Why the file would not read back.
        reason: String,
    },
    /// A library behind FFI (a C++ baseline) failed inside one of its calls: its exception was
    /// caught at the boundary and reported as a status code.
    #[error("{library} failed in {call}: {reason}")]
    Foreign {
        /// The library (e.g. "OpenMesh").
        library: &'static str,
        /// The C function of the shim that failed.
        call: &'static str,
        /// What the shim reported (out of memory, an exception, an unknown code).
        reason: &'static str,
    },
}

impl Error {
    /// A short, stable name of the error kind (used in JSON output and tests).
    pub fn kind(&self) -> &'static str {
        match self {
            Error::Io { .. } => "io",
            Error::UnknownFormat { .. } => "unknown-format",
            Error::Syntax { .. } => "syntax",
            Error::Truncated { .. } => "truncated",
            Error::ImplausibleHeader { .. } => "implausible-header",
            Error::TooLarge { .. } => "too-large",
            Error::IndexOutOfRange { .. } => "index-out-of-range",
            Error::NonFiniteCoordinate { .. } => "non-finite-coordinate",
            Error::CoordinateOutOfRange { .. } => "coordinate-out-of-range",
            Error::TooFewCorners { .. } => "too-few-corners",
            Error::RepeatedVertex { .. } => "repeated-vertex",
            Error::NonManifoldEdge { .. } => "non-manifold-edge",
            Error::InconsistentOrientation { .. } => "inconsistent-orientation",
            Error::NonManifoldVertex { .. } => "non-manifold-vertex",
            Error::NotTriangles { .. } => "not-triangles",
            Error::CoincidentVertices { .. } => "coincident-vertices",
            Error::NotAGrid { .. } => "not-a-grid",
            Error::DegeneratePoints { .. } => "degenerate-points",
            Error::InvalidParameter { .. } => "invalid-parameter",
            Error::BudgetExceeded { .. } => "budget-exceeded",
            Error::Invariant { .. } => "invariant",
            Error::Unsupported(_) => "unsupported",
            Error::ElementOutOfRange { .. } => "element-out-of-range",
            Error::EditRefused { .. } => "edit-refused",
            Error::Foreign { .. } => "foreign",
            Error::NotWritable { .. } => "not-writable",
            Error::StarTooLarge { .. } => "star-too-large",
            Error::CheFile { .. } => "che-file",
        }
    }

    /// `true` for the errors that say the mesh is not an oriented manifold.
    pub fn is_non_manifold(&self) -> bool {
        matches!(
            self,
            Error::NonManifoldEdge { .. }
                | Error::InconsistentOrientation { .. }
                | Error::NonManifoldVertex { .. }
        )
    }

    /// The error with its element ids in `numbering` (they are in the lab's, from 0): what a
    /// reader of a file that numbers from 1 reports. Other errors are returned as they are.
    pub fn numbered(self, numbering: Numbering) -> Self {
        let shift = numbering.first();
        match self {
            Error::IndexOutOfRange {
                face,
                index,
                vertices,
                numbering: Numbering::FromZero,
            } => Error::IndexOutOfRange {
                face: face + shift as usize,
                index: index.saturating_add(shift.into()),
                vertices,
                numbering,
            },
            Error::NonFiniteCoordinate {
                vertex,
                value,
                numbering: Numbering::FromZero,
            } => Error::NonFiniteCoordinate {
                vertex: vertex + shift as usize,
                value,
                numbering,
            },
            Error::TooFewCorners {
                face,
                corners,
                numbering: Numbering::FromZero,
            } => Error::TooFewCorners {
                face: face + shift as usize,
                corners,
                numbering,
            },
            Error::RepeatedVertex {
                face,
                vertex,
                numbering: Numbering::FromZero,
            } => Error::RepeatedVertex {
                face: face + shift as usize,
                vertex: vertex + shift,
                numbering,
            },
            other => other,
        }
    }

    /// Shorthand for an [`Error::Invariant`].
    pub fn invariant(structure: &'static str, message: impl Into<String>) -> Self {
        Error::Invariant {
            structure,
            message: message.into(),
        }
    }
}

/// The result type of this crate.
pub type Result<T, E = Error> = std::result::Result<T, E>;
