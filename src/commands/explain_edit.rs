//! `topolab explain NAME --op flip|split|collapse --edge E [--mesh M]`: one edit on one
//! structure (or, for `che`, on the four CHE levels), with the records it writes, old → new,
//! in the field names of the structure's source (the lecture on polygon-mesh data structures
//! for the half-edges, the CHE thesis chapter for the CHE's containers), and what it reads.
//!
//! Edges are numbered as `--trace` numbers them: the mesh's edges in order of first
//! appearance (the index half-edge's edge ids), so `--edge E` is the same edge on every
//! structure. `collapse` collapses the edge's first vertex into its second; `split` splits it
//! at its midpoint. A refused edit exits with code 1 and the structure's reason.
//!
//! The records are each structure's [`MeshTopology::explain`] lines read as `key: fields`
//! (one record per line), except for the CHE levels, whose containers are listed entry by
//! entry (`V[he]`, `O[he]`, `VH[v]`, `EH ∋ he`, `CH[k-1]`). The reads are described, not
//! counted: the edit code reads its containers directly, not through the counted accessors
//! `--trace` uses.

use crate::input::{mesh_or_tetrahedron, Failure};
use std::any::Any;
use std::collections::HashMap;
use std::fmt::Write;
use topolab_structures::che::CheLevel;
use topolab_structures::{
    CheL0, CheL1, CheL2, CheL3, EdgeId, IndexHalfEdge, MeshEdit, MeshTopology, PointerHalfEdge,
    PolygonSoup, VertexId,
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

/// The structures `--op` can explain: every one that implements [`MeshEdit`].
pub const EDITABLE: [&str; 6] = [
    "index-half-edge",
    "pointer-half-edge",
    "che-l0",
    "che-l1",
    "che-l2",
    "che-l3",
];

/// One structure's explanation, for [`visit`].
struct Explain<'a> {
    soup: &'a PolygonSoup,
    label: &'a str,
    op: ExplainOp,
    edge: u32,
    ends: [u32; 2],
}

/// Runs `e` on the editable structure `name`.
fn visit(name: &str, e: Explain<'_>) -> Option<Result<String, Failure>> {
    Some(match name {
        "index-half-edge" => e.run::<IndexHalfEdge>(),
        "pointer-half-edge" => e.run::<PointerHalfEdge>(),
        "che-l0" => e.run::<CheL0>(),
        "che-l1" => e.run::<CheL1>(),
        "che-l2" => e.run::<CheL2>(),
        "che-l3" => e.run::<CheL3>(),
        _ => return None,
    })
}

/// The text of `topolab explain NAME --op OP --edge E [--mesh M]`.
pub fn run(name: &str, mesh: Option<&str>, op: ExplainOp, edge: u32) -> Result<String, Failure> {
    let names: Vec<&str> = if name == super::explain_che::NAME {
        EDITABLE
            .iter()
            .copied()
            .filter(|n| n.starts_with("che-"))
            .collect()
    } else if EDITABLE.contains(&name) {
        vec![name]
    } else {
        return Err(Failure::usage(format!(
            "--op: {name:?} cannot edit (or is not a structure); the editable structures: che (its four levels), {}",
            EDITABLE.join(", ")
        )));
    };
    let (soup, label) = mesh_or_tetrahedron(mesh, false, |s| {
        400 * (s.num_corners() + s.num_vertices()) as u64
    })?;
    let reference = IndexHalfEdge::from_soup(&soup).map_err(|e| Failure {
        message: format!("{label} is not an oriented manifold mesh: {e}"),
        code: 1,
    })?;
    if edge as usize >= reference.num_edges() {
        return Err(Failure::usage(format!(
            "--edge {edge}: {label} has {} edges (0 to {})",
            reference.num_edges(),
            reference.num_edges().saturating_sub(1)
        )));
    }
    let ends = reference.edge_vertices(EdgeId(edge)).map(|v| v.0);
    let mut out = String::new();
    for n in names {
        let e = Explain {
            soup: &soup,
            label: &label,
            op,
            edge,
            ends,
        };
        out += &visit(n, e).expect("an editable structure")?;
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
        let what = match self.op {
            ExplainOp::Flip => "flip-edge",
            ExplainOp::Split => "split-edge",
            ExplainOp::Collapse => "collapse-edge",
        };
        let done = match self.op {
            ExplainOp::Flip => m.flip_edge(id),
            ExplainOp::Split => {
                let p = (m.position(VertexId(a)) + m.position(VertexId(b))) / 2.0;
                m.split_edge(id, p).map(drop)
            }
            ExplainOp::Collapse => m.collapse_edge(VertexId(a), VertexId(b)),
        };
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
        let _ = writeln!(w, "reads: {}", reads(M::NAME, self.op));
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

/// What the edit reads in structure `name`, in its source's field names.
fn reads(name: &str, op: ExplainOp) -> &'static str {
    let che = name.starts_with("che-");
    match (che, op) {
        (true, ExplainOp::Flip) => {
            "V[h], V[next(h)], V[prev(h)] (the corners a, b, x), O[h] = g (level 0: Algorithm 8's scan of V[]), V[prev(g)] (the corner y); the star of x to check that edge x-y is new (from VH[x] around by O[prev(h)] at levels 2-3, a scan of V[] at levels 0-1); then O[] of the two triangles' 6 half-edges (their outer opposites) and the fans of the 4 corners for VH[]; EH from a scan of O[] (levels 2-3)"
        }
        (true, ExplainOp::Split) => {
            "V[] of the edge's one or two triangles, O[h] (level 0: a scan of V[]), O[] of their outer half-edges, the fans of their corners for VH[]; EH from a scan of O[] (levels 2-3); O[] labels of the whole mesh when the edge is on the boundary (level 3, Algorithm 4)"
        }
        (true, ExplainOp::Collapse) => {
            "the stars of both ends and of the two opposite corners (the link condition: from VH[] and O[] at levels 2-3, scans of V[] at levels 0-1), V[] and O[] of the star of the removed vertex, the last triangles (moved into the removed ones' slots); EH from a scan of O[] (levels 2-3); O[] labels of the whole mesh when the boundary is touched (level 3, Algorithm 4)"
        }
        (false, ExplainOp::Flip) => {
            "the edge's two half-edges and their next, prev, vert and face; the corners' rotation (next of twin) to check that the new edge is not there; the vertices' and faces' edge fields it repoints"
        }
        (false, ExplainOp::Split) => {
            "the edge's half-edges and their next, prev, vert and face, and the face records of its triangles"
        }
        (false, ExplainOp::Collapse) => {
            "the rotations around both ends and the two opposite corners (the link condition), then every half-edge leaving the removed vertex (its vert) and the next/prev/face of the two removed triangles"
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

/// The lines of [`MeshTopology::explain`] that read `key: fields` (one record per line).
fn explained_records<M: MeshTopology>(m: &M) -> Vec<(String, String)> {
    let mut text = String::new();
    let _ = m.explain(&mut text);
    let mut out: Vec<(String, String)> = Vec::new();
    for line in text.lines() {
        let Some((key, value)) = line.trim().split_once(": ") else {
            continue;
        };
        if key.is_empty() || key.contains(' ') {
            continue;
        }
        out.push((key.to_string(), value.trim().to_string()));
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
