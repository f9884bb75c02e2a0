//! What one query of an operator reads from memory, as a structure declares it beside its costs
//! ([`MeshTopology::access`](crate::MeshTopology::access)): the bytes it reads from each of
//! its containers, and the dependent loads on its longest chain: loads whose address comes from
//! a load of the same query, each waiting for the one before (each step of a fan walk is one).
//! A query's first loads, whose addresses follow from the element asked about, are not counted:
//! the processor issues them while the queries before are still running. The report turns the
//! model into the limit of a sweep: the bytes at the machine's bandwidth, the chain at its load
//! latency.
//!
//! Amounts are per query and per answer (the answers a query reports: the k of an O(k)
//! relation), so one model serves every mesh. They count what the structure's code reads for a
//! triangle mesh, the meshes the report measures; a container read whole by each query (a scan)
//! is declared as such. The model names the work a step of the chain does between its loads
//! ([`Step`]: `h ^ 1`, the CHE's `prev`), which the report times as a chase of its own beside
//! the limit; other arithmetic, branches and the harness's checksum are not in the model (the
//! harness adds the reads of the edge keys its checksum asks for; see the report).

/// How a container's size follows the mesh: one element per vertex, edge, face, corner (a
/// face's side: the CHE's half-edges, three per triangle) or half-edge (two per edge, the
/// boundary's included: the half-edge structures').
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Unit {
    /// One per vertex.
    Vertex,
    /// One per edge.
    Edge,
    /// One per face.
    Face,
    /// One per corner of a face (the sum of the faces' sizes).
    Corner,
    /// Two per edge.
    HalfEdge,
}

/// A container: an array, or the records of one kind.
#[derive(Copy, Clone, Debug, PartialEq, serde::Serialize)]
pub struct Container {
    /// Its name, as the structure's docs name it (`O`, `next`, `HE_edge`).
    pub name: &'static str,
    /// What it has one element of.
    pub per: Unit,
    /// Bytes per element, as laid out in memory (a record allocated on its own counts the
    /// allocator's block, not only its fields).
    pub bytes: f64,
}

impl Container {
    /// A container of `bytes` per `per`.
    pub const fn new(name: &'static str, per: Unit, bytes: f64) -> Self {
        Self { name, per, bytes }
    }
}

/// What one query reads from one container.
#[derive(Copy, Clone, Debug, PartialEq, serde::Serialize)]
pub struct Read {
    /// The container.
    pub container: Container,
    /// Bytes read once per query.
    pub per_query: f64,
    /// Bytes read per answer the query reports.
    pub per_answer: f64,
    /// Times the query reads the whole container (a scan; 0.5 for a scan that stops halfway on
    /// average).
    pub scans: f64,
    /// The records its bytes land in, once per query and per answer, when each read takes only
    /// part of a record (a field or two of a 16-byte halfedge). `None`: the bytes read are whole
    /// records, as in an array of one field. The cache brings whole lines, so a sweep fetches
    /// every byte of the records it visits: its bandwidth bound counts these records' bytes,
    /// not only the bytes read ([`Read::fetched`]).
    pub records: Option<[f64; 2]>,
}

impl Read {
    /// `per_query` bytes of `container` once per query and `per_answer` per answer.
    pub const fn new(container: Container, per_query: f64, per_answer: f64) -> Self {
        Self {
            container,
            per_query,
            per_answer,
            scans: 0.0,
            records: None,
        }
    }

    /// The same reads, landing in `per_query` records once per query and `per_answer` per
    /// answer, each read in part (see [`Read::records`]).
    pub const fn in_records(self, per_query: f64, per_answer: f64) -> Self {
        Self {
            records: Some([per_query, per_answer]),
            ..self
        }
    }

    /// The bytes a cache brings in for these reads, once per query and per answer: the bytes
    /// read, or the whole records they land in when that is more.
    pub fn fetched(&self) -> [f64; 2] {
        let [q, a] = self.records.unwrap_or([0.0, 0.0]);
        let b = self.container.bytes;
        [self.per_query.max(q * b), self.per_answer.max(a * b)]
    }

    /// `scans` times the whole `container` per query.
    pub const fn scan(container: Container, scans: f64) -> Self {
        Self {
            container,
            per_query: 0.0,
            per_answer: 0.0,
            scans,
            records: None,
        }
    }
}

/// The work a step of the chain does between one dependent load and the address of the next,
/// as the structure's code computes it: the probe times a chase of each kind
/// (`topolab_harness::measuring::probe`), so a chain's steps are priced as measured, arithmetic included.
#[derive(
    Copy, Clone, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "kebab-case")]
pub enum Step {
    /// The loaded value is the next address (a pointer, or an index used as it is), or the
    /// model knows no arithmetic between the loads.
    #[default]
    Load,
    /// A half-edge's twin, `h ^ 1`, before the load: `next[h ^ 1]` (the index half-edge,
    /// OpenMesh). CGAL's `Surface_mesh` writes its opposite as a choice, `(h & 1) ? h - 1 :
    /// h + 1`, whose compiled form was not read: it is declared a plain load.
    Twin,
    /// The CHE's `prev(h)` or `next(h)` (a divisibility test and a conditional move,
    /// [`crate::che::prev`], [`crate::che::next`]) between two loads: the forward walk's
    /// `O[prev(h)]`, the backward walk's `O[next(b)]`. The probe times the forward one.
    Corner,
}

impl Step {
    /// Every kind, the plain load first.
    pub const ALL: [Step; 3] = [Step::Load, Step::Twin, Step::Corner];

    /// The address a step loads from, given the value the load before it returned: the
    /// structure's own arithmetic (a bijection on `0..n` for `n` a multiple of 6, so a chase
    /// built through it is one cycle).
    #[inline(always)]
    pub fn address(self, h: u32) -> u32 {
        match self {
            Step::Load => h,
            Step::Twin => h ^ 1,
            Step::Corner => crate::core::corners::prev(crate::core::ids::HalfEdgeId(h)).0,
        }
    }

    /// How the report names it.
    pub fn text(self) -> &'static str {
        match self {
            Step::Load => "a plain load",
            Step::Twin => "h ^ 1, then the load",
            Step::Corner => "the CHE's prev(h), then the load",
        }
    }
}

/// The access model of one operator: see the module docs.
#[derive(Copy, Clone, Debug, PartialEq, serde::Serialize)]
pub struct Access {
    /// What one query reads, container by container.
    pub reads: &'static [Read],
    /// Dependent loads on the query's longest chain (see the module docs), once per query.
    pub chain_per_query: f64,
    /// Dependent loads on the chain per answer (one per step of a fan walk).
    pub chain_per_answer: f64,
    /// The work of each step of the chain (a plain load unless declared).
    pub step: Step,
    /// What the code does that the model leaves out and that bounds it instead, when the
    /// structure knows (shown with the limit).
    pub note: Option<&'static str>,
}

impl Access {
    /// Reads `reads`, with `chain_per_query + chain_per_answer · answers` dependent loads.
    pub const fn new(reads: &'static [Read], chain_per_query: f64, chain_per_answer: f64) -> Self {
        Self {
            reads,
            chain_per_query,
            chain_per_answer,
            step: Step::Load,
            note: None,
        }
    }

    /// The same model whose chain steps each do `step`'s work before their load.
    pub const fn stepping(self, step: Step) -> Self {
        Self { step, ..self }
    }

    /// The same model with `note` (what it leaves out).
    pub const fn noting(self, note: &'static str) -> Self {
        Self {
            note: Some(note),
            ..self
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::core::topology::{MeshTopology, Operator};
    use crate::registry::{visit, StructureVisitor, NAMES};

    /// Per operator with a model: (its declared cost's exponent, whether the model scans).
    struct Models;
    impl StructureVisitor for Models {
        type Output = Vec<(Operator, f64, bool)>;
        fn visit<M: MeshTopology>(self) -> Self::Output {
            Operator::ALL
                .into_iter()
                .filter_map(|op| {
                    let a = M::access(op)?;
                    Some((
                        op,
                        M::cost(op).expected_exponent(),
                        a.reads.iter().any(|r| r.scans > 0.0),
                    ))
                })
                .collect()
        }
    }

    #[test]
    fn a_model_scans_exactly_where_the_declared_cost_grows_with_the_mesh() {
        let mut modelled = Vec::new();
        for &name in NAMES {
            for (op, exponent, scans) in visit(name, Models).expect("registered") {
                // O(n) and beyond read a container whole per query; O(1), O(k) and O(∂n1)
                // read a bounded part of it.
                assert_eq!(exponent >= 1.0, scans, "{name} {op:?}");
                modelled.push(name);
            }
        }
        for name in [
            "index-half-edge",
            "pointer-half-edge",
            "che-l1",
            "che-l2",
            "che-l3",
        ] {
            let ops = modelled.iter().filter(|&&n| n == name).count();
            assert_eq!(ops, Operator::ALL.len(), "{name} models every operator");
        }
    }
}
