//! `topolab explain NAME --op flip|split|collapse --edge E [--mesh M]`: one edit on one
//! structure (or, for `che`, on the four CHE levels), with the records it writes, old → new,
//! in the field names of the structure's source (the lecture on polygon-mesh data structures
//! for the half-edges, the edge list and the vertex list, the lecture on 3D convex hulls for
//! the winged-edge's record, the CHE thesis chapter for the CHE's containers), and what it
//! reads. Every structure the registry marks `[editable]` is explained
//! ([`editable`]); the reads are described per family ([`Family`]). The C++ baselines edit
//! too, but their records live inside the C++ library, out of this command's reach: asked for
//! one, it says so, as a usage error.
//!
//! Edges are numbered as `--trace` numbers them: the mesh's edges in order of first
//! appearance (the index half-edge's edge ids), so `--edge E` is the same edge on every
//! structure. `collapse` collapses the edge's first vertex into its second; `split` splits it
//! at its midpoint. A refused edit exits with code 1 and the structure's reason.
//!
//! The records are each structure's [`MeshTopology::explain`] lines read as records
//! ([`super::explain_records`]), except for the CHE levels, whose containers are listed entry
//! by entry (`V[he]`, `O[he]`, `VH[v]`, `EH ∋ he`, `CH[k-1]`). The reads are described, not
//! counted: the edit code reads its containers directly, not through the counted accessors
//! `--trace` uses.

use super::explain_records::explained_records;
use crate::input::{mesh_or_tetrahedron, Failure};
use crate::registry::{
    missing_baseline, peer_crate, visit_editable, EditVisitor, CPP_BASELINES, NAMES,
};
use std::any::{Any, TypeId};
use std::collections::HashMap;
use std::fmt::Write;
use topolab_structures::che::CheLevel;
use topolab_structures::meshes;
use topolab_structures::{
    CheL0, CheL1, CheL2, CheL3, EdgeId, EdgeList, IndexHalfEdge, MeshEdit, MeshTopology,
    PointerHalfEdge, PolygonSoup, VertexId, VertexList, WingedEdge,
};

/// The edits `--op` explains.
#[derive(Copy, Clone, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ExplainOp {
    /// Flip the edge between its two triangles.
    Flip,
    /// Split the edge at its midpoint.
    Split,
    /// Collapse the edge's first vertex into its second.
    Collapse,
}

/// The structures `--op` can explain: every one the registry marks `[editable]` (that
/// [`visit_editable`] reaches) but the C++ baselines ([`CPP_BASELINES`]) and the Rust
/// crates ([`peer_crate`]), whose records live inside their library and cannot be listed, in
/// the registry's order.
pub fn editable() -> Vec<&'static str> {
    struct Probe;
    impl EditVisitor for Probe {
        type Output = ();
        fn visit<M: MeshEdit + 'static>(self) {}
    }
    NAMES
        .iter()
        .copied()
        .filter(|name| !CPP_BASELINES.contains(name) && peer_crate(name).is_none())
        .filter(|name| visit_editable(name, Probe).is_some())
        .collect()
}

/// The families whose edits read differently, for the reads `--op` describes.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Family {
    /// The index and pointer half-edges.
    HalfEdge,
    /// The CHE levels 0–3.
    Che,
    /// The winged-edge (the face rewrite over its edge records).
    WingedEdge,
    /// The edge list (the face rewrite over its edges and polygons).
    EdgeList,
    /// The vertex list (the face rewrite over its faces' corners).
    VertexList,
    /// An editable structure this command has no description for (its records are still
    /// printed).
    Other,
}

impl Family {
    /// The family of structure `M`, by its type.
    pub fn of<M: 'static>() -> Family {
        let is = |t: TypeId| TypeId::of::<M>() == t;
        if is(TypeId::of::<IndexHalfEdge>()) || is(TypeId::of::<PointerHalfEdge>()) {
            Family::HalfEdge
        } else if [
            TypeId::of::<CheL0>(),
            TypeId::of::<CheL1>(),
            TypeId::of::<CheL2>(),
            TypeId::of::<CheL3>(),
        ]
        .into_iter()
        .any(is)
        {
            Family::Che
        } else if is(TypeId::of::<WingedEdge>()) {
            Family::WingedEdge
        } else if is(TypeId::of::<EdgeList>()) {
            Family::EdgeList
        } else if is(TypeId::of::<VertexList>()) {
            Family::VertexList
        } else {
            Family::Other
        }
    }
}

/// One structure's explanation, for [`visit`].
struct Explain<'a> {
    soup: &'a PolygonSoup,
    label: &'a str,
    op: ExplainOp,
    edge: u32,
    ends: [u32; 2],
}

impl EditVisitor for Explain<'_> {
    type Output = Result<String, Failure>;
    fn visit<M: MeshEdit + 'static>(self) -> Self::Output {
        self.run::<M>()
    }
}

/// The text of `topolab explain NAME --op OP [--edge E] [--mesh M]`: without `--edge`, the
/// first edge on which the edit succeeds, among the first 64, tried on the index half-edge.
pub fn run(
    name: &str,
    mesh: Option<&str>,
    op: ExplainOp,
    edge: Option<u32>,
) -> Result<String, Failure> {
    let editable = editable();
    let names: Vec<&str> = if name == super::explain_che::NAME {
        [CheL0::NAME, CheL1::NAME, CheL2::NAME, CheL3::NAME]
            .into_iter()
            .filter(|n| editable.contains(n))
            .collect()
    } else if editable.contains(&name) {
        vec![name]
    } else if CPP_BASELINES.contains(&name) {
        let absent = missing_baseline(name)
            .map(|why| format!(" (and it is not in this build: {why})"))
            .unwrap_or_default();
        return Err(Failure::usage(format!(
            "--op: {name} edits through its C++ library's own Euler operations, and its records live inside that library, which --op cannot list{absent}; `topolab list` and `topolab explain {name}` show its declared edit costs. The structures whose records --op shows: che (its four levels), {}",
            editable.join(", ")
        )));
    } else if let Some((krate, _)) = peer_crate(name) {
        return Err(Failure::usage(format!(
            "--op: {name} edits through the crate {krate}'s own calls, and its records live inside that crate, which --op cannot list; `topolab list` shows the operations it offers and their declared costs. The structures whose records --op shows: che (its four levels), {}",
            editable.join(", ")
        )));
    } else {
        return Err(Failure::usage(format!(
            "--op: {name:?} cannot edit (or is not a structure); the editable structures: che (its four levels), {}",
            editable.join(", ")
        )));
    };
    let (mut soup, mut label) = mesh_or_tetrahedron(mesh, false, |s| {
        400 * (s.num_corners() + s.num_vertices()) as u64
    })?;
    let mut reference = IndexHalfEdge::from_soup(&soup).map_err(|e| Failure {
        message: format!("{label} is not an oriented manifold mesh: {e}"),
        code: 1,
    })?;
    let mut preface = String::new();
    let edge = match edge {
        Some(edge) => edge,
        None => {
            let mut choice = chosen_edge(&soup, op);
            // No such edit on the default mesh (no flip and no collapse succeeds on the open
            // tetrahedron): the canonical grid, where each does.
            if choice.success.is_none() && mesh.is_none() {
                let refused_here = choice.refused.clone();
                soup = meshes::canonical()
                    .into_iter()
                    .find(|m| m.name == "grid")
                    .expect("the canonical grid")
                    .soup;
                reference = IndexHalfEdge::from_soup(&soup).expect("a grid is a manifold");
                let why = refused_here
                    .map(|(e, why)| format!(" (edge {e}: {why})"))
                    .unwrap_or_default();
                let _ = writeln!(
                    preface,
                    "no {} succeeds on the open tetrahedron{why}: the canonical mesh `grid` instead",
                    op_name(op)
                );
                label = "the canonical mesh `grid` (a 3x2 triangulated grid: --mesh grid)".into();
                choice = chosen_edge(&soup, op);
            }
            let Some(edge) = choice.success else {
                return Err(Failure {
                    message: format!(
                        "no {} succeeds on the first {TRIED_EDGES} edges of {label}{}; name one with --edge",
                        op_name(op),
                        choice
                            .refused
                            .map(|(e, why)| format!(" (edge {e}: {why})"))
                            .unwrap_or_default()
                    ),
                    code: 1,
                });
            };
            let _ = writeln!(
                preface,
                "no --edge given: edge {edge} is the first edge of {label} on which {} succeeds{}",
                op_name(op),
                choice
                    .refused
                    .map(|(e, why)| format!("; it is refused on edge {e} ({why}): try --edge {e}"))
                    .unwrap_or_default()
            );
            edge
        }
    };
    if edge as usize >= reference.num_edges() {
        return Err(Failure::usage(format!(
            "--edge {edge}: {label} has {} edges (0 to {})",
            reference.num_edges(),
            reference.num_edges().saturating_sub(1)
        )));
    }
    let ends = reference.edge_vertices(EdgeId(edge)).map(|v| v.0);
    let mut out = preface;
    for n in names {
        let e = Explain {
            soup: &soup,
            label: &label,
            op,
            edge,
            ends,
        };
        out += &visit_editable(n, e).expect("an editable structure")?;
    }
    Ok(out)
}

impl Explain<'_> {
    fn run<M: MeshEdit + 'static>(self) -> Result<String, Failure> {
        let mut m = M::from_soup(self.soup).map_err(|e| Failure {
            message: format!("{} cannot store {}: {e}", M::NAME, self.label),
            code: 1,
        })?;
        let [a, b] = self.ends;
        let id = edge_between(&m, a, b).expect("the edge is in every structure");
        let before = records(&m);
        let what = op_name(self.op);
        let done = apply(&mut m, self.op, id, [VertexId(a), VertexId(b)]);
        let mut out = String::new();
        let w = &mut out;
        let _ = writeln!(
            w,
            "{}: {what} of edge {} (v{a} - v{b}; the structure's edge id {}) on {}",
            M::NAME,
            self.edge,
            id.0,
            self.label
        );
        if let Err(e) = done {
            return Err(Failure {
                message: format!("{e} (edge {} = v{a} - v{b} on {})", self.edge, self.label),
                code: 1,
            });
        }
        m.validate().map_err(|e| Failure {
            message: format!("{} is invalid after {what}: {e}", M::NAME),
            code: 1,
        })?;
        let _ = writeln!(w, "reads: {}", reads(Family::of::<M>(), self.op));
        let _ = writeln!(
            w,
            "  (described, not counted: the edit code reads its records directly, not through the counted accessors of --trace)"
        );
        let _ = writeln!(w, "writes (old -> new; + added, - removed):");
        diff(w, &before, &records(&m));
        let _ = writeln!(w);
        Ok(out)
    }
}

/// The name of an edit as `explain` prints it.
fn op_name(op: ExplainOp) -> &'static str {
    match op {
        ExplainOp::Flip => "flip-edge",
        ExplainOp::Split => "split-edge",
        ExplainOp::Collapse => "collapse-edge",
    }
}

/// Does `op` on edge `id` of `m`, the edge from `a` to `b`: a flip, a split at its midpoint,
/// or the collapse of `a` into `b`. A refused edit changes nothing (what `MeshEdit` promises).
fn apply<M: MeshEdit>(
    m: &mut M,
    op: ExplainOp,
    id: EdgeId,
    [a, b]: [VertexId; 2],
) -> topolab_structures::Result<()> {
    match op {
        ExplainOp::Flip => m.flip_edge(id),
        ExplainOp::Split => {
            let p = (m.position(a) + m.position(b)) / 2.0;
            m.split_edge(id, p).map(drop)
        }
        ExplainOp::Collapse => m.collapse_edge(a, b),
    }
}

/// Does `op` succeed on `edge` of `m` ([`apply`])? `Err` with the refusal.
fn try_op(m: &mut IndexHalfEdge, op: ExplainOp, edge: u32) -> Result<(), String> {
    let ends = m.edge_vertices(EdgeId(edge));
    apply(m, op, EdgeId(edge), ends).map_err(|e| e.to_string())
}

/// What [`chosen_edge`] found: the first edge where the edit succeeds, and the first where
/// it is refused, with the reason.
struct Choice {
    success: Option<u32>,
    refused: Option<(u32, String)>,
}

/// Edges [`chosen_edge`] tries at most: a large mesh is not edited edge by edge.
const TRIED_EDGES: u32 = 64;

/// The first edge of `soup` (in the edge numbering `--edge` uses) on which `op` succeeds, and
/// the first on which it is refused, among its first [`TRIED_EDGES`], tried on the index
/// half-edge: every editable structure refuses what it refuses (the editing suite holds them
/// to one model). Refused edits leave the structure as it was, so it is built again only after
/// an edit that was done.
fn chosen_edge(soup: &PolygonSoup, op: ExplainOp) -> Choice {
    let mut choice = Choice {
        success: None,
        refused: None,
    };
    let Ok(mut m) = IndexHalfEdge::from_soup(soup) else {
        return choice;
    };
    for e in 0..(m.num_edges() as u32).min(TRIED_EDGES) {
        match try_op(&mut m, op, e) {
            Ok(()) => {
                choice.success.get_or_insert(e);
                match IndexHalfEdge::from_soup(soup) {
                    Ok(fresh) => m = fresh,
                    Err(_) => break,
                }
            }
            Err(why) => {
                choice.refused.get_or_insert((e, why));
            }
        }
        if choice.success.is_some() && choice.refused.is_some() {
            break;
        }
    }
    choice
}

/// The structure's id of the edge between `a` and `b`.
fn edge_between<M: MeshTopology>(m: &M, a: u32, b: u32) -> Option<EdgeId> {
    let mut found = None;
    m.vertex_edges(VertexId(a), |e| {
        let [x, y] = m.edge_vertices(e).map(|v| v.0);
        if (x, y) == (a, b) || (x, y) == (b, a) {
            found.get_or_insert(e);
        }
    });
    found
}

/// What the edit reads in a structure of `family`, in its source's field names.
fn reads(family: Family, op: ExplainOp) -> &'static str {
    match (family, op) {
        (Family::Che, ExplainOp::Flip) => {
            "V[h], V[next(h)], V[prev(h)] (the corners a, b, x), O[h] = g (level 0: Algorithm 8's scan of V[]), V[prev(g)] (the corner y); the star of x to check that edge x-y is new (from VH[x] around by O[prev(h)] at levels 2-3, a scan of V[] at levels 0-1); then O[] of the two triangles' 6 half-edges (their outer opposites) and the fans of the 4 corners for VH[]; EH from a scan of O[] (levels 2-3)"
        }
        (Family::Che, ExplainOp::Split) => {
            "V[] of the edge's one or two triangles, O[h] (level 0: a scan of V[]), O[] of their outer half-edges, the fans of their corners for VH[]; EH from a scan of O[] (levels 2-3); O[] labels of the whole mesh when the edge is on the boundary (level 3, Algorithm 4)"
        }
        (Family::Che, ExplainOp::Collapse) => {
            "the stars of both ends and of the two opposite corners (the link condition and OpenMesh's tetrahedron test: from VH[] and O[] at levels 2-3, scans of V[] at levels 0-1), V[] and O[] of the star of the removed vertex, the last triangles (moved into the removed ones' slots); EH from a scan of O[] (levels 2-3); O[] labels of the whole mesh when the boundary is touched (level 3, Algorithm 4)"
        }
        (Family::HalfEdge, ExplainOp::Flip) => {
            "the edge's two half-edges and their next, prev, vert and face; the corners' rotation (next of twin) to check that the new edge is not there; the vertices' and faces' edge fields it repoints"
        }
        (Family::HalfEdge, ExplainOp::Split) => {
            "the edge's half-edges and their next, prev, vert and face, and the face records of its triangles"
        }
        (Family::HalfEdge, ExplainOp::Collapse) => {
            "the rotations around both ends and the two opposite corners (the link condition and OpenMesh's tetrahedron test), then every half-edge leaving the removed vertex (its vert) and the next/prev/face of the two removed triangles"
        }
        (Family::WingedEdge, ExplainOp::Flip) => {
            "the edge record (v1, v2, fccw, fcw) and its two triangles' cycles through the wings (pccw, nccw in fccw; pcw, ncw in fcw); the fan of the far corner from its av through the wings, to check that the new edge is not there; the fans of the four corners for the rewrite's manifold check; then the two faces are rewritten, the edge record in place, the wings of the four outer edges re-pointed"
        }
        (Family::WingedEdge, ExplainOp::Split) => {
            "the edge record (v1, v2, fccw, fcw) and the cycles of its one or two triangles through the wings; the fans of their corners from av for the rewrite's manifold check; then the triangles are rewritten in two, the new edge records appended and the outer edges' wings re-pointed"
        }
        (Family::WingedEdge, ExplainOp::Collapse) => {
            "the fans of both ends and of the two far corners from av through the wings (the link condition and OpenMesh's tetrahedron test), the cycles of the faces around the removed vertex; then those faces are rewritten around the kept vertex, the edges of the two removed triangles leave (the last edge and face records moving into their slots) and the wings around them are re-pointed"
        }
        (Family::EdgeList, ExplainOp::Flip) => {
            "the edge E = (start, end, left, right), its two polygons P (lists of edge indices) and their edges' start and end; a scan of all of E for the far corner's edges (is the new edge there?) and for each corner's fan; then the two polygons are rewritten, the edge in place, and a scan of E finds the edges they share with the rest"
        }
        (Family::EdgeList, ExplainOp::Split) => {
            "the edge E = (start, end, left, right), its one or two polygons P and their edges' ends; a scan of all of E for each corner's fan and for the edges the new polygons share with the rest; then the polygons are rewritten and the new edges appended"
        }
        (Family::EdgeList, ExplainOp::Collapse) => {
            "a scan of all of E per vertex of the link condition and OpenMesh's tetrahedron test (the rings of both ends and of the two far corners), the polygons around the removed vertex; then they are rewritten around the kept vertex, the edges and polygons of the two removed triangles leave (the last ones moving into their slots)"
        }
        (Family::VertexList, ExplainOp::Flip) => {
            "a scan of all faces (lists of vertex indices) for the two that hold the edge, and for the far corner's neighbours (is the new edge there?); the faces around each of the four corners, a scan each; then the two faces' corners are rewritten in place"
        }
        (Family::VertexList, ExplainOp::Split) => {
            "a scan of all faces for the one or two that hold the edge, and for the faces around each corner; then each triangle's corners are rewritten and one new triangle appended per side"
        }
        (Family::VertexList, ExplainOp::Collapse) => {
            "a scan of all faces per vertex of the link condition and OpenMesh's tetrahedron test (the rings of both ends and of the two far corners), then the faces around the removed vertex; they are rewritten around the kept vertex and the two removed triangles leave (the last faces moving into their slots)"
        }
        (Family::Other, _) => {
            "not described for this structure: the records it writes are listed below"
        }
    }
}

/// A structure's records as `(key, value)`, in order.
fn records<M: MeshEdit + 'static>(m: &M) -> Vec<(String, String)> {
    let any: &dyn Any = m;
    let mut out = if let Some(c) = any.downcast_ref::<CheL0>() {
        che_records(
            c.geometry().len(),
            c.start_vertices(),
            None,
            None,
            None,
            None,
        )
    } else if let Some(c) = any.downcast_ref::<CheL1>() {
        che_records(
            c.geometry().len(),
            c.start_vertices(),
            Some(c.opposite()),
            None,
            None,
            None,
        )
    } else if let Some(c) = any.downcast_ref::<CheL2>() {
        che_records(
            c.geometry().len(),
            c.start_vertices(),
            Some(c.level1().opposite()),
            Some(c.vertex_half_edge()),
            Some(c.edge_map()),
            None,
        )
    } else if let Some(c) = any.downcast_ref::<CheL3>() {
        let l2 = c.level2();
        che_records(
            c.geometry().len(),
            c.start_vertices(),
            Some(l2.level1().opposite()),
            Some(l2.vertex_half_edge()),
            Some(l2.edge_map()),
            Some(c.curve_half_edge()),
        )
    } else {
        explained_records(m)
    };
    for v in 0..m.num_vertices() {
        if m.is_deleted_vertex(VertexId::new(v)) {
            out.push((
                format!("v{v}.deleted"),
                "yes (marked until garbage collection)".to_string(),
            ));
        }
    }
    out
}

/// The CHE's containers entry by entry.
fn che_records(
    vertices: usize,
    v: &[u32],
    o: Option<&[i32]>,
    vh: Option<&[i32]>,
    eh: Option<&[u32]>,
    ch: Option<&[u32]>,
) -> Vec<(String, String)> {
    let mut out = vec![("G[]".to_string(), format!("{vertices} vertices"))];
    for (he, x) in v.iter().enumerate() {
        out.push((format!("V[{he}]"), x.to_string()));
    }
    for (he, x) in o.into_iter().flatten().enumerate() {
        out.push((format!("O[{he}]"), x.to_string()));
    }
    for (x, he) in vh.into_iter().flatten().enumerate() {
        out.push((format!("VH[{x}]"), he.to_string()));
    }
    for he in eh.into_iter().flatten() {
        out.push((
            format!("EH ∋ {he}"),
            "(an edge's smaller half-edge)".to_string(),
        ));
    }
    for (k, he) in ch.into_iter().flatten().enumerate() {
        out.push((format!("CH[{k}]"), he.to_string()));
    }
    out
}

/// `name = value` fields of a record, if it is written so.
fn fields(value: &str) -> Option<Vec<(&str, &str)>> {
    let value = value.split("  (").next().unwrap_or(value);
    value
        .split(", ")
        .map(|f| f.split_once(" = "))
        .collect::<Option<Vec<_>>>()
}

/// Writes the records that changed, were added or were removed.
fn diff(w: &mut String, before: &[(String, String)], after: &[(String, String)]) {
    let index =
        |list: &[(String, String)]| -> HashMap<String, String> { list.iter().cloned().collect() };
    let (old_index, new_index) = (index(before), index(after));
    let find = |list: &HashMap<String, String>, key: &str| list.get(key).cloned();
    let mut any = false;
    for (key, old) in before {
        match find(&new_index, key) {
            Some(new) if &new == old => {}
            Some(new) => {
                any = true;
                match (fields(old), fields(&new)) {
                    (Some(f), Some(g)) if f.len() == g.len() => {
                        for ((name, x), (_, y)) in f.iter().zip(&g) {
                            if x != y {
                                let _ = writeln!(w, "  {key}.{name}: {x} -> {y}");
                            }
                        }
                    }
                    _ => {
                        let _ = writeln!(w, "  {key}: {old} -> {new}");
                    }
                }
            }
            None => {
                any = true;
                let _ = writeln!(w, "- {key}: {old}");
            }
        }
    }
    for (key, new) in after {
        if find(&old_index, key).is_none() {
            any = true;
            let _ = writeln!(w, "+ {key}: {new}");
        }
    }
    if !any {
        let _ = writeln!(w, "  (no record changed)");
    }
}
