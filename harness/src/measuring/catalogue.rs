//! The operator catalogue: for every [`Operator`], what it takes, what it answers and which
//! relation of the CHE thesis chapter it is.

pub use topolab_structures::Element;
use topolab_structures::Operator;

/// What an operator takes and answers.
#[derive(Copy, Clone, Debug, serde::Serialize)]
pub struct OperatorSpec {
    /// The operator.
    pub op: Operator,
    /// Its kebab-case name.
    pub name: &'static str,
    /// What a query is given, in argument order ([`Operator::input`]).
    pub input: &'static [Element],
    /// What it answers.
    pub output: Output,
    /// `(p, q)` of the relation Rpq, if it is one.
    pub relation: Option<(u8, u8)>,
    /// One line for a student.
    pub about: &'static str,
}

/// The shape of an operator's answer.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Output {
    /// A variable number of elements of a kind.
    Many(Element),
    /// Exactly two vertices.
    Pair,
    /// Yes or no.
    Flag,
    /// At most one edge.
    MaybeEdge,
    /// Closed loops of edges.
    Loops,
}

const fn spec(
    op: Operator,
    output: Output,
    relation: Option<(u8, u8)>,
    about: &'static str,
) -> OperatorSpec {
    OperatorSpec {
        op,
        name: op.name(),
        input: op.input().elements(),
        output,
        relation,
        about,
    }
}

use Element::*;

/// Every operator, in catalogue order (the order of [`Operator::ALL`]).
pub const CATALOGUE: [OperatorSpec; 14] = [
    spec(
        Operator::R00,
        Output::Many(Vertex),
        Some((0, 0)),
        "the neighbour vertices of a vertex",
    ),
    spec(
        Operator::R01,
        Output::Many(Edge),
        Some((0, 1)),
        "the edges around a vertex",
    ),
    spec(
        Operator::R02,
        Output::Many(Face),
        Some((0, 2)),
        "the faces around a vertex",
    ),
    spec(
        Operator::R10,
        Output::Pair,
        Some((1, 0)),
        "the two vertices of an edge",
    ),
    spec(
        Operator::R11,
        Output::Many(Edge),
        Some((1, 1)),
        "the other edges of an edge's faces",
    ),
    spec(
        Operator::R12,
        Output::Many(Face),
        Some((1, 2)),
        "the one or two faces of an edge",
    ),
    spec(
        Operator::R20,
        Output::Many(Vertex),
        Some((2, 0)),
        "the vertices of a face, in order",
    ),
    spec(
        Operator::R21,
        Output::Many(Edge),
        Some((2, 1)),
        "the edges of a face, in order",
    ),
    spec(
        Operator::R22,
        Output::Many(Face),
        Some((2, 2)),
        "the faces across a face's edges",
    ),
    spec(
        Operator::BoundaryVertex,
        Output::Flag,
        None,
        "is a vertex on the boundary?",
    ),
    spec(
        Operator::BoundaryEdge,
        Output::Flag,
        None,
        "is an edge on the boundary?",
    ),
    spec(
        Operator::BoundaryCurves,
        Output::Loops,
        None,
        "every boundary curve as a loop of edges",
    ),
    spec(
        Operator::EdgeSuccessor,
        Output::MaybeEdge,
        None,
        "the next edge of a face after an edge",
    ),
    spec(
        Operator::EdgePredecessor,
        Output::MaybeEdge,
        None,
        "the edge of a face before an edge",
    ),
];

/// The catalogue entry of `op`.
pub fn spec_of(op: Operator) -> &'static OperatorSpec {
    &CATALOGUE[Operator::ALL
        .iter()
        .position(|&o| o == op)
        .expect("every operator is catalogued")]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn catalogue_follows_operator_order_and_relations_match_names() {
        for (spec, op) in CATALOGUE.iter().zip(Operator::ALL) {
            assert_eq!(spec.op, op);
            if let Some((p, q)) = spec.relation {
                assert_eq!(spec.name, format!("r{p}{q}"));
                // Rpq is asked about a p-simplex.
                assert_eq!(spec.input, &[[Vertex, Edge, Face][p as usize]], "{op:?}");
            }
        }
        assert_eq!(spec_of(Operator::R22).input, &[Face]);
        assert_eq!(spec_of(Operator::EdgeSuccessor).input, &[Edge, Face]);
        assert_eq!(spec_of(Operator::BoundaryCurves).input, &[Mesh]);
    }
}
