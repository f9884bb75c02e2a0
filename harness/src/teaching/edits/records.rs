//! A structure's records, for the old → new listing of an edit ([`records`], [`diff`]): one
//! `(key, fields)` pair per record, the fields written `name = value, ...` where the
//! structure's source names them, so that a change prints per field. The CHE levels' are
//! their containers entry by entry (`G[v]`, `V[he]`, `O[he]`, `VH[v]`, `EH ∋ he`, `CH[k-1]`, the
//! names of the CHE thesis chapter); every other structure's are its
//! [`MeshTopology::explain`] lines read as records ([`explained_records`]).
//!
//! The texts come in three forms, each a family's:
//! - `key: fields` lines (the half-edges' `HE_vert`, `HE_face`, `HE_edge` records, the vertex
//!   list's vertices and faces, the winged-edge's vertices and faces);
//! - `KEY = (a, b, ...)` lines (the edge list's `V`, `E` and `P` of the lecture on
//!   polygon-mesh data structures; an edge `E = (start, end, left, right)` gets those names,
//!   the lecture's "start vertex, end vertex, left polygon, right polygon");
//! - a table whose header row names the columns (the winged-edge's edge records with their
//!   wings, in the names of the lecture on 3D convex hulls: `v1 v2 fccw fcw pccw nccw pcw
//!   ncw`), each row one record keyed by its first column.
//!
//! A position `(x, y, z)` followed by named fields (the winged-edge's `v: (x, y, z)  av = e`)
//! is split into `x = …, y = …, z = …` and those fields.

use super::st::che::CheLevel;
use super::st::{CheL0, CheL1, CheL2, CheL3, EdgeId, FaceId, MeshEdit, MeshTopology, VertexId};
use glam::DVec3;
use std::any::Any;
use std::collections::HashMap;
use std::fmt::Write;

/// The field names of the edge list's edge record `E = (start, end, left, right)`.
const EDGE_LIST_EDGE: [&str; 4] = ["start", "end", "left", "right"];

/// The records of `m`'s explain text, in order.
pub fn explained_records<M: MeshTopology>(m: &M) -> Vec<(String, String)> {
    let mut text = String::new();
    let _ = m.explain(&mut text);
    records_of_text(&text)
}

/// The records of an explain text (see the module docs).
pub fn records_of_text(text: &str) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = Vec::new();
    let mut columns: Option<Vec<&str>> = None;
    for line in text.lines() {
        let trimmed = line.trim();
        if let Some((key, value)) = trimmed.split_once(": ") {
            columns = None;
            if !key.is_empty() && !key.contains(' ') {
                out.push((key.to_string(), with_position(value.trim())));
            }
            continue;
        }
        if let Some((key, value)) = trimmed.split_once(" = (") {
            columns = None;
            if !key.is_empty() && !key.contains(' ') && value.ends_with(')') {
                let value = format!("({value}");
                out.push((key.to_string(), named_edge(key, value)));
            }
            continue;
        }
        let cells: Vec<&str> = trimmed.split_whitespace().collect();
        match &columns {
            Some(names)
                if cells.len() == names.len()
                    && is_id(cells[0])
                    && cells[0].starts_with(names[0]) =>
            {
                let fields: Vec<String> = names[1..]
                    .iter()
                    .zip(&cells[1..])
                    .map(|(n, c)| format!("{n} = {c}"))
                    .collect();
                out.push((cells[0].to_string(), fields.join(", ")));
            }
            // A header: one letter naming the key column (the rows' ids start with it),
            // then the column names.
            _ if cells.len() > 2
                && cells[0].len() == 1
                && cells[0].chars().all(|c| c.is_ascii_alphabetic())
                && cells.iter().all(|c| !c.contains('=')) =>
            {
                columns = Some(cells);
            }
            _ => columns = None,
        }
    }
    out
}

/// `e12`, `E3`, `f0`, `v7`: a letter and digits.
fn is_id(cell: &str) -> bool {
    let mut chars = cell.chars();
    chars.next().is_some_and(|c| c.is_ascii_alphabetic())
        && cell.len() > 1
        && chars.all(|c| c.is_ascii_digit())
}

/// An edge list edge `E3 = (a, b, P0, N)` with the lecture's field names; anything else as it
/// is.
fn named_edge(key: &str, value: String) -> String {
    let is_edge = key
        .strip_prefix('E')
        .is_some_and(|n| n.parse::<u32>().is_ok());
    let inner = &value[1..value.len() - 1];
    let parts: Vec<&str> = inner.split(", ").collect();
    if is_edge && parts.len() == EDGE_LIST_EDGE.len() {
        EDGE_LIST_EDGE
            .iter()
            .zip(parts)
            .map(|(n, p)| format!("{n} = {p}"))
            .collect::<Vec<_>>()
            .join(", ")
    } else {
        value
    }
}

/// `(x, y, z)  name = value` as `x = x, y = y, z = z, name = value`; anything else as it is.
fn with_position(value: &str) -> String {
    let Some(rest) = value.strip_prefix('(') else {
        return value.to_string();
    };
    let Some((inner, tail)) = rest.split_once(')') else {
        return value.to_string();
    };
    let coords: Vec<&str> = inner.split(", ").collect();
    let tail = tail.trim();
    if coords.len() != 3
        || !tail.contains(" = ")
        || coords.iter().any(|c| c.parse::<f64>().is_err())
    {
        return value.to_string();
    }
    format!(
        "x = {}, y = {}, z = {}, {tail}",
        coords[0], coords[1], coords[2]
    )
}

/// A structure's records as `(key, value)`, in order, with a record per vertex marked deleted
/// (until garbage collection).
pub fn records<M: MeshEdit + 'static>(m: &M) -> Vec<(String, String)> {
    let any: &dyn Any = m;
    let mut out = if let Some(c) = any.downcast_ref::<CheL0>() {
        che_records(c.geometry(), c.start_vertices(), None, None, None, None)
    } else if let Some(c) = any.downcast_ref::<CheL1>() {
        che_records(
            c.geometry(),
            c.start_vertices(),
            Some(c.opposite()),
            None,
            None,
            None,
        )
    } else if let Some(c) = any.downcast_ref::<CheL2>() {
        che_records(
            c.geometry(),
            c.start_vertices(),
            Some(c.level1().opposite()),
            Some(c.vertex_half_edge()),
            Some(c.edge_map()),
            None,
        )
    } else if let Some(c) = any.downcast_ref::<CheL3>() {
        let l2 = c.level2();
        che_records(
            c.geometry(),
            c.start_vertices(),
            Some(l2.level1().opposite()),
            Some(l2.vertex_half_edge()),
            Some(l2.edge_map()),
            Some(c.curve_half_edge()),
        )
    } else {
        explained_records(m)
    };
    // A deleted element that keeps its slot (until garbage collection) gets a record of its
    // own, so that a deletion shows as one; an edge's two half-edges go with it.
    let marked = "yes (marked until garbage collection)";
    for v in 0..m.num_vertices() {
        if m.is_deleted_vertex(VertexId::new(v)) {
            out.push((format!("v{v}.deleted"), marked.to_string()));
        }
    }
    for e in 0..m.num_edges() {
        if m.is_deleted_edge(EdgeId::new(e)) {
            out.push((
                format!("e{e}.deleted"),
                format!(
                    "{marked}, with its half-edges h{} and h{}",
                    2 * e,
                    2 * e + 1
                ),
            ));
        }
    }
    for f in 0..m.num_faces() {
        if m.is_deleted_face(FaceId::new(f)) {
            out.push((format!("f{f}.deleted"), marked.to_string()));
        }
    }
    out
}

/// The CHE's containers entry by entry.
fn che_records(
    g: &[DVec3],
    v: &[u32],
    o: Option<&[i32]>,
    vh: Option<&[i32]>,
    eh: Option<&[u32]>,
    ch: Option<&[u32]>,
) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = g
        .iter()
        .enumerate()
        .map(|(x, p)| {
            (
                format!("G[{x}]"),
                format!("x = {:.3}, y = {:.3}, z = {:.3}", p.x, p.y, p.z),
            )
        })
        .collect();
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

/// Records by their keys.
fn by_key(list: &[(String, String)]) -> HashMap<&str, &str> {
    list.iter().map(|(k, v)| (k.as_str(), v.as_str())).collect()
}

/// `name = value` fields of a record, if it is written so.
fn fields(value: &str) -> Option<Vec<(&str, &str)>> {
    let value = value.split("  (").next().unwrap_or(value);
    value
        .split(", ")
        .map(|f| f.split_once(" = "))
        .collect::<Option<Vec<_>>>()
}

/// The records that changed (`  key.field: old -> new` per field where both are written in
/// fields, `  key: old -> new` otherwise), were removed (`- key: old`) or were added
/// (`+ key: new`), one line each; `  (no record changed)` alone when none did.
pub fn diff(before: &[(String, String)], after: &[(String, String)]) -> Vec<String> {
    let (old_index, new_index) = (by_key(before), by_key(after));
    let mut w = String::new();
    for (key, old) in before {
        match new_index.get(key.as_str()) {
            Some(new) if new == old => {}
            Some(new) => match (fields(old), fields(new)) {
                // Per field, where the fields differ (a change in the comment after them
                // alone prints as a whole).
                (Some(f), Some(g)) if f.len() == g.len() && f != g => {
                    for ((name, x), (_, y)) in f.iter().zip(&g) {
                        if x != y {
                            let _ = writeln!(w, "  {key}.{name}: {x} -> {y}");
                        }
                    }
                }
                _ => {
                    let _ = writeln!(w, "  {key}: {old} -> {new}");
                }
            },
            None => {
                let _ = writeln!(w, "- {key}: {old}");
            }
        }
    }
    for (key, new) in after {
        if !old_index.contains_key(key.as_str()) {
            let _ = writeln!(w, "+ {key}: {new}");
        }
    }
    let lines: Vec<String> = w.lines().map(str::to_string).collect();
    if lines.is_empty() {
        vec!["  (no record changed)".to_string()]
    } else {
        lines
    }
}

/// The elements of a value: the entries of a tuple `(a, b, c)`, the one value otherwise (a
/// comment after two spaces left out).
fn elements(value: &str) -> Vec<&str> {
    let value = value.split("  (").next().unwrap_or(value).trim();
    match value.strip_prefix('(').and_then(|v| v.strip_suffix(')')) {
        Some(inner) => inner.split(", ").collect(),
        None => vec![value],
    }
}

/// The elements of a record: each field's elements ([`elements`]) where it is written in
/// fields, its value's otherwise.
fn record_elements(value: &str) -> Vec<Vec<&str>> {
    match fields(value) {
        Some(f) => f.into_iter().map(|(_, v)| elements(v)).collect(),
        None => vec![elements(value)],
    }
}

/// How many elements the change from `before` to `after` wrote: per record, the fields and
/// tuple entries that differ, position by position (an entry added or removed counts), and
/// every element of a record added or removed. The count `explain --op` gives as an edit's
/// writes: a value written over itself is not seen.
pub fn written(before: &[(String, String)], after: &[(String, String)]) -> u64 {
    let (old_index, new_index) = (by_key(before), by_key(after));
    let size = |v: &str| record_elements(v).iter().map(Vec::len).sum::<usize>() as u64;
    let mut n = 0;
    for (key, old) in before {
        match new_index.get(key.as_str()) {
            Some(new) if new == old => {}
            Some(new) => {
                let (x, y) = (record_elements(old), record_elements(new));
                if x.len() != y.len() {
                    n += size(old).max(size(new));
                    continue;
                }
                for (a, b) in x.iter().zip(&y) {
                    let differ = a.iter().zip(b).filter(|(p, q)| p != q).count();
                    n += (differ + a.len().abs_diff(b.len())) as u64;
                }
            }
            None => n += size(old),
        }
    }
    for (key, new) in after {
        if !old_index.contains_key(key.as_str()) {
            n += size(new);
        }
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_form_becomes_records_with_named_fields() {
        let text = "vertices: 2 (coordinates)\n  v0: (0.000, 1.000, 2.000)  av = e2\n\
            faces: 1\n  f0: (v0, v1, v3)\n  h1: vert = v1, face = null  (edge e0)\n\
            E = (2 edges)\n  E0 = (0, 1, P0, N)\n  P0 = (0, 1, 2)\n\
            edges: 2\n     e    v1   v2   fccw\n    e0    v0   v1     f0\n    e1    v1   v3     -\n\
            all edges of a vertex: rotate\n    e9    v0   v1     f0\n";
        let got = records_of_text(text);
        let find = |k: &str| {
            got.iter()
                .find(|(key, _)| key == k)
                .map(|(_, v)| v.as_str())
        };
        assert_eq!(find("v0"), Some("x = 0.000, y = 1.000, z = 2.000, av = e2"));
        assert_eq!(find("f0"), Some("(v0, v1, v3)"));
        assert_eq!(find("h1"), Some("vert = v1, face = null  (edge e0)"));
        assert_eq!(find("E0"), Some("start = 0, end = 1, left = P0, right = N"));
        assert_eq!(find("P0"), Some("(0, 1, 2)"));
        assert_eq!(find("e1"), Some("v1 = v1, v2 = v3, fccw = -"));
        // A row after the table ended is no record, nor is prose; the counts are records.
        assert_eq!(find("e9"), None);
        assert_eq!(find("E"), Some("(2 edges)"));
        assert_eq!(find("vertices"), Some("2 (coordinates)"));
        assert_eq!(find("edges"), Some("2"));
        assert_eq!(got.len(), 11, "{got:?}");
    }

    #[test]
    fn written_counts_the_fields_and_entries_that_changed() {
        let rec = |k: &str, v: &str| (k.to_string(), v.to_string());
        let before = [
            rec("f0", "(v0, v1, v2)"),
            rec("h1", "vert = v1, face = f0  (edge e0)"),
            rec("v3", "x = 0.0, y = 1.0, z = 2.0"),
            rec("f9", "(v4, v5, v6)"),
        ];
        let after = [
            rec("f0", "(v1, v1, v3)"),
            rec("h1", "vert = v1, face = null  (edge e0)"),
            rec("v3", "x = 0.0, y = 1.0, z = 2.0"),
            rec("f10", "(v4, v5, v6, v7)"),
        ];
        // f0: two entries; h1: one field; f9 removed: three; f10 added: four.
        assert_eq!(written(&before, &after), 2 + 1 + 3 + 4);
        assert_eq!(written(&before, &before), 0);
    }
}
