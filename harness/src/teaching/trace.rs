//! One query on one structure, read by read, in the counting build of the structures.
//!
//! Edges are asked for and answered in the soup's numbering (edge `E` is the `E`-th edge in
//! order of first appearance, [`Connectivity`]'s, the edge list's and the half-edge's), so that
//! one `--edge E` means the same edge on every structure; each structure's own edge id is
//! found by the edge's end vertices, outside the trace.

use std::collections::HashMap;
use std::fmt::Write as _;
use topolab_structures_counted::core::reads::{self, Event};
use topolab_structures_counted::registry::{self, StructureVisitor};
use topolab_structures_counted::{
    BoundaryCurves, Connectivity, Cost, EdgeId, FaceId, Input, MeshTopology, Operator, PolygonSoup,
    VertexId,
};

/// The element a query asks about, in the soup's numbering.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct Query {
    /// The vertex (R00, R01, R02, boundary vertex).
    pub vertex: Option<u32>,
    /// The edge, numbered as the soup's edges (R10, R11, R12, boundary edge, successor,
    /// predecessor).
    pub edge: Option<u32>,
    /// The face (R20, R21, R22, successor, predecessor).
    pub face: Option<u32>,
}

/// Why a query cannot be traced.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TraceError {
    /// Not a structure of the lab (or a baseline, whose reads happen inside its library).
    UnknownStructure(String),
    /// The query lacks the element its operator takes, or names one the mesh does not have.
    BadQuery(String),
    /// The structure cannot store the mesh.
    Refused(String),
}

impl std::fmt::Display for TraceError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            TraceError::UnknownStructure(m) | TraceError::BadQuery(m) | TraceError::Refused(m) => {
                f.write_str(m)
            }
        }
    }
}

/// The reads of one query on one structure.
#[derive(Clone, Debug)]
pub struct Trace {
    /// The structure.
    pub structure: &'static str,
    /// The operator.
    pub op: Operator,
    /// Its declared cost in the structure.
    pub cost: Cost,
    /// Every read (and grid arithmetic), in order.
    pub events: Vec<Event>,
    /// Container reads among the events.
    pub reads: u64,
    /// The answer, edges in the soup's numbering.
    pub answer: String,
    /// The query's edge as the structure numbers it, if it takes one and the ids differ.
    pub own_edge: Option<u32>,
}

impl Trace {
    /// The trace as `topolab explain --trace` prints it.
    pub fn text(&self) -> String {
        let mut out = format!(
            "== {} ({}: {}) ==\n",
            self.structure,
            self.op.name(),
            self.cost.notation()
        );
        if let Some(e) = self.own_edge {
            let _ = writeln!(
                out,
                "  (the edge asked about is e{e} in this structure's ids)"
            );
        }
        let mut n = 0;
        for event in &self.events {
            match event {
                Event::Read {
                    container,
                    index,
                    value,
                } => {
                    n += 1;
                    let _ = writeln!(out, "  {n:>3}. read {container}[{index}] = {value}");
                }
                Event::Computed { what, value } => {
                    let _ = writeln!(out, "       compute {what} = {value}");
                }
            }
        }
        if self.events.is_empty() {
            out.push_str("       (nothing read)\n");
        }
        let _ = writeln!(
            out,
            "  answer: {}\n  {} container reads",
            self.answer, self.reads
        );
        out
    }
}

/// The soup's edges: end vertices by edge, and edge by sorted end vertices.
pub struct SoupEdges {
    /// `ends[E]`: the end vertices of soup edge E, as its first face traverses it.
    pub ends: Vec<[u32; 2]>,
    by_ends: HashMap<(u32, u32), u32>,
}

impl SoupEdges {
    /// The edges of `soup` (`None` if it is not an oriented manifold: no structure stores it).
    pub fn of(soup: &PolygonSoup) -> Option<Self> {
        let conn: Connectivity = soup.connectivity().ok()?;
        let corner_face = &conn.corner_face;
        let ends: Vec<[u32; 2]> = conn
            .edge_corners
            .iter()
            .map(|&[c, _]| {
                let c = c as usize;
                let n = soup.next_corner(c, corner_face[c] as usize);
                [soup.indices()[c], soup.indices()[n]]
            })
            .collect();
        let by_ends = ends
            .iter()
            .enumerate()
            .map(|(e, &[a, b])| (key(a, b), e as u32))
            .collect();
        Some(Self { ends, by_ends })
    }

    /// The soup edge joining `a` and `b`.
    pub fn find(&self, a: VertexId, b: VertexId) -> Option<u32> {
        self.by_ends.get(&key(a.0, b.0)).copied()
    }
}

fn key(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// Runs one query of `op` on `m` inside a sink of reads; `answer` receives it as text.
/// Shared by [`trace`] and [`count`](crate::studies::reads), so the two cannot differ.
pub(crate) fn run<M: MeshTopology>(
    m: &M,
    op: Operator,
    v: VertexId,
    e: EdgeId,
    f: FaceId,
    curves: &mut BoundaryCurves,
    answer: &mut Vec<Answer>,
) {
    match op {
        Operator::R00 => m.vertex_vertices(v, |x| answer.push(Answer::Vertex(x))),
        Operator::R01 => m.vertex_edges(v, |x| answer.push(Answer::Edge(x))),
        Operator::R02 => m.vertex_faces(v, |x| answer.push(Answer::Face(x))),
        Operator::R10 => answer.extend(m.edge_vertices(e).map(Answer::Vertex)),
        Operator::R11 => m.edge_edges(e, |x| answer.push(Answer::Edge(x))),
        Operator::R12 => m.edge_faces(e, |x| answer.push(Answer::Face(x))),
        Operator::R20 => m.face_vertices(f, |x| answer.push(Answer::Vertex(x))),
        Operator::R21 => m.face_edges(f, |x| answer.push(Answer::Edge(x))),
        Operator::R22 => m.face_faces(f, |x| answer.push(Answer::Face(x))),
        Operator::BoundaryVertex => answer.push(Answer::Bool(m.is_boundary_vertex(v))),
        Operator::BoundaryEdge => answer.push(Answer::Bool(m.is_boundary_edge(e))),
        Operator::BoundaryCurves => {
            m.boundary_curves(curves);
            answer.extend(curves.edges.iter().map(|&x| Answer::Edge(x)));
        }
        Operator::EdgeSuccessor => {
            answer.push(m.edge_successor(e, f).map_or(Answer::None, Answer::Edge))
        }
        Operator::EdgePredecessor => {
            answer.push(m.edge_predecessor(e, f).map_or(Answer::None, Answer::Edge))
        }
    }
}

/// One answer of a query, in the structure's ids.
#[derive(Copy, Clone, Debug, PartialEq)]
pub(crate) enum Answer {
    Vertex(VertexId),
    Edge(EdgeId),
    Face(FaceId),
    Bool(bool),
    None,
}

/// Checks that `q` gives what `op` takes, within the mesh's counts.
fn check(op: Operator, q: Query, soup: &PolygonSoup, edges: &SoupEdges) -> Result<(), TraceError> {
    let need = |what: &str, x: Option<u32>, n: usize| match x {
        None => Err(TraceError::BadQuery(format!(
            "--trace {} needs --{what} N",
            op.name()
        ))),
        Some(x) if x as usize >= n => Err(TraceError::BadQuery(format!(
            "--{what} {x}: the mesh has {n} {} (0 to {})",
            if what == "vertex" {
                "vertices".to_string()
            } else {
                format!("{what}s")
            },
            n as i64 - 1
        ))),
        Some(_) => Ok(()),
    };
    match op.input() {
        Input::Vertex => need("vertex", q.vertex, soup.num_vertices()),
        Input::Edge => need("edge", q.edge, edges.ends.len()),
        Input::Face => need("face", q.face, soup.num_faces()),
        Input::EdgeOfFace => {
            need("edge", q.edge, edges.ends.len())?;
            need("face", q.face, soup.num_faces())
        }
        Input::Mesh => Ok(()),
    }
}

struct TraceVisit<'a> {
    soup: &'a PolygonSoup,
    edges: &'a SoupEdges,
    op: Operator,
    query: Query,
}

impl StructureVisitor for TraceVisit<'_> {
    type Output = Result<Trace, TraceError>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        let m = M::from_soup(self.soup)
            .map_err(|e| TraceError::Refused(format!("{} cannot store this mesh: {e}", M::NAME)))?;
        // The structure's own edge ids by soup edge, found outside the trace.
        let mut own = vec![EdgeId::INVALID; self.edges.ends.len()];
        let mut soup_edge = HashMap::new();
        m.for_each_edge(|e| {
            let [a, b] = m.edge_vertices(e);
            if let Some(s) = self.edges.find(a, b) {
                own[s as usize] = e;
                soup_edge.insert(e, s);
            }
        });
        let e = self.query.edge.map_or(EdgeId(0), |s| own[s as usize]);
        let v = VertexId(self.query.vertex.unwrap_or(0));
        let f = FaceId(self.query.face.unwrap_or(0));
        let mut curves = BoundaryCurves::default();
        let mut answer = Vec::new();
        let ((), events) = reads::trace(|| run(&m, self.op, v, e, f, &mut curves, &mut answer));
        let reads = events
            .iter()
            .filter(|e| matches!(e, Event::Read { .. }))
            .count() as u64;
        let name = |a: &Answer| match *a {
            Answer::Vertex(x) => format!("v{}", x.0),
            Answer::Edge(x) => match soup_edge.get(&x) {
                Some(&s) => {
                    let [a, b] = self.edges.ends[s as usize];
                    format!("E{s}(v{a}-v{b})")
                }
                None => format!("e{}", x.0),
            },
            Answer::Face(x) => format!("f{}", x.0),
            Answer::Bool(b) => b.to_string(),
            Answer::None => "none (the edge is not one of the face's)".into(),
        };
        let answer = match self.op {
            Operator::BoundaryCurves => (0..curves.len())
                .map(|i| {
                    let names: Vec<String> = curves
                        .curve(i)
                        .iter()
                        .map(|&x| name(&Answer::Edge(x)))
                        .collect();
                    format!("[{}]", names.join(", "))
                })
                .collect::<Vec<_>>()
                .join(" "),
            Operator::BoundaryVertex
            | Operator::BoundaryEdge
            | Operator::EdgeSuccessor
            | Operator::EdgePredecessor => answer.first().map(name).unwrap_or_default(),
            _ => format!(
                "[{}]",
                answer.iter().map(name).collect::<Vec<_>>().join(", ")
            ),
        };
        let own_edge = match self.op.input() {
            Input::Edge | Input::EdgeOfFace => Some(e.0).filter(|&x| Some(x) != self.query.edge),
            _ => None,
        };
        Ok(Trace {
            structure: M::NAME,
            op: self.op,
            cost: M::cost(self.op),
            events,
            reads,
            answer,
            own_edge,
        })
    }
}

/// The names [`trace`] accepts: every structure of the lab (not the C++ baselines).
pub fn names() -> &'static [&'static str] {
    registry::NAMES
}

/// Traces one query of `op` on the structure `name` built from `soup`.
pub fn trace(
    name: &str,
    soup: &PolygonSoup,
    op: Operator,
    query: Query,
) -> Result<Trace, TraceError> {
    let edges = SoupEdges::of(soup).ok_or_else(|| {
        TraceError::Refused("the mesh is not an oriented manifold: no structure stores it".into())
    })?;
    check(op, query, soup, &edges)?;
    registry::visit(
        name,
        TraceVisit {
            soup,
            edges: &edges,
            op,
            query,
        },
    )
    .unwrap_or_else(|| {
        Err(TraceError::UnknownStructure(format!(
            "--trace: no structure {name:?} to trace (the lab's structures: {}; the C++ baselines read inside their library)",
            registry::NAMES.join(", ")
        )))
    })
}

/// `soup` (of the timed crate) in the counting build's type: the same vertices and faces.
pub fn counted_soup(soup: &topolab_structures::PolygonSoup) -> PolygonSoup {
    let mut out =
        PolygonSoup::with_capacity(soup.num_vertices(), soup.num_faces(), soup.num_corners());
    for &p in &soup.positions {
        out.push_vertex(p);
    }
    for f in soup.faces() {
        out.push_face(f);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures_counted::meshes;

    fn tetra() -> PolygonSoup {
        meshes::open_tetrahedron()
    }

    #[test]
    fn every_structure_traces_every_operator_on_the_tetrahedron_and_agrees_with_the_oracle() {
        let soup = tetra();
        let q = Query {
            vertex: Some(3),
            edge: Some(1),
            face: Some(0),
        };
        for &name in names() {
            if matches!(name, "regular-grid" | "height-field") {
                continue;
            }
            for op in Operator::ALL {
                let t = trace(name, &soup, op, q).unwrap_or_else(|e| panic!("{name} {op:?}: {e}"));
                let reads = t
                    .events
                    .iter()
                    .filter(|e| matches!(e, Event::Read { .. }))
                    .count() as u64;
                assert_eq!(reads, t.reads);
                // Every structure of the lab reads something to answer, except the grids.
                assert!(
                    t.reads > 0 || op == Operator::R21,
                    "{name} {op:?} read nothing"
                );
            }
        }
        // The answers agree across structures (R00 of the apex: its three neighbours).
        let ring = |name| {
            let t = trace(name, &soup, Operator::R00, q).unwrap();
            let mut a: Vec<String> = t
                .answer
                .trim_matches(['[', ']'])
                .split(", ")
                .map(String::from)
                .collect();
            a.sort();
            a
        };
        assert_eq!(ring("vertex-list"), ["v0", "v1", "v2"]);
        assert_eq!(ring("che-l2"), ring("pointer-half-edge"));
    }

    #[test]
    fn half_edge_rotates_in_k_reads_where_the_vertex_list_scans_every_face() {
        let soup = tetra();
        let q = Query {
            vertex: Some(3),
            ..Query::default()
        };
        let list = trace("vertex-list", &soup, Operator::R00, q).unwrap();
        let he = trace("index-half-edge", &soup, Operator::R00, q).unwrap();
        let che = trace("che-l2", &soup, Operator::R00, q).unwrap();
        // index half-edge: HE_vert.edge, then per neighbour vert[pair] and next[pair].
        assert_eq!(he.reads, 1 + 3 * 2, "{}", he.text());
        // CHE level 2: VH[3], O[VH[3]] (the backward walk's start: an interior star is walked
        // from both ends), then per spoke O[] and V[].
        assert_eq!(che.reads, 1 + 1 + 3 + 3, "{}", che.text());
        assert!(list.reads > he.reads, "{}", list.text());
        assert!(he.text().contains("read HE_vert.edge[3]"), "{}", he.text());
    }

    #[test]
    fn bad_queries_are_typed_errors() {
        let soup = tetra();
        let q = Query::default();
        let bad = |r: Result<Trace, TraceError>| r.unwrap_err();
        assert!(matches!(
            bad(trace("che-l2", &soup, Operator::R00, q)),
            TraceError::BadQuery(_)
        ));
        let far = Query { edge: Some(6), ..q };
        let e = bad(trace("edge-list", &soup, Operator::R10, far));
        assert_eq!(
            e,
            TraceError::BadQuery("--edge 6: the mesh has 6 edges (0 to 5)".into())
        );
        assert!(matches!(
            bad(trace(
                "openmesh",
                &soup,
                Operator::R00,
                Query {
                    vertex: Some(0),
                    ..q
                }
            )),
            TraceError::UnknownStructure(_)
        ));
        assert!(matches!(
            bad(trace(
                "regular-grid",
                &soup,
                Operator::R00,
                Query {
                    vertex: Some(0),
                    ..q
                }
            )),
            TraceError::Refused(_)
        ));
    }
}
