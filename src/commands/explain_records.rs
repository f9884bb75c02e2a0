//! A structure's records read from its [`MeshTopology::explain`] text, for `explain --op`'s
//! old → new listing: one `(key, fields)` pair per record, the fields written `name = value,
//! ...` where the structure's source names them, so that a change prints per field.
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

use topolab_structures::MeshTopology;

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
}
