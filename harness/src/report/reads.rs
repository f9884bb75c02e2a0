//! The report's "reads per query" table (Table 4.1 counted instead of timed, beside the
//! timed exponents) and its teaching section (one query traced on several structures, drawn
//! on Figure 4.10); see [`super`].

use crate::format::esc;
use crate::measuring::kernels::Kernel;
use crate::results::Results;
use crate::studies::reads::{ReadsRow, Verdict};
use crate::teaching::trace::{self, counted_soup, Query, SoupEdges};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use topolab_structures_counted::core::reads::Event;
use topolab_structures_counted::Operator;

/// How far the timed exponent may be from the counted one before the cell says the memory
/// hierarchy is speaking (the timed table's own tolerance, [`crate::measuring::fit::agrees`]).
const TIME_VS_READS: f64 = 0.4;

/// Appends the "reads per query" table of `r.reads`.
pub fn table(h: &mut String, r: &Results) {
    if r.reads.is_empty() {
        return;
    }
    let mut names: Vec<&str> = Vec::new();
    for row in &r.reads {
        if !names.contains(&row.structure.as_str()) {
            names.push(&row.structure);
        }
    }
    h.push_str("<h2>Table 4.1, counted: reads per query</h2><div class=read><b>How to read it.</b> The same table as above with the clock replaced by a count: the mean number of container reads one query makes (an id of an index array, a position, a record of the winged-edge, a field of a pointer record), counted by a build of the structures whose every container read goes through a counting accessor (the timed build compiles that accessor to a plain index). In every cell: the declared cost, the exponent <i>e</i> fitted to the reads against mesh size, the reads per query at the largest size counted, and the exponent fitted to the time (from the table above, same kernel of sampled queries, same family). Counts have no noise and no cache, so <i>e</i> must be the declared cost's: green when it is (within 0.15), red when not (a finding about the code, explained below the table). <b>Where time and reads disagree</b> (orange, ⚑) the reads follow the declared cost and the time does not: the memory hierarchy is speaking (a query that reads the same number of elements takes longer on a bigger mesh because they come from further away). Grey: nothing read (the grids compute their answers) or too few sizes within the counting budget.</div>");
    h.push_str("<table class=t41><tr><th>operator</th>");
    for n in &names {
        let _ = write!(h, "<th>{}</th>", esc(n));
    }
    h.push_str("</tr>");
    let mut findings = Vec::new();
    for op in Operator::ALL {
        let _ = write!(h, "<tr><td class=l>{}</td>", op.name());
        for n in &names {
            let Some(row) = r
                .reads
                .iter()
                .find(|x| x.structure == *n && x.operator == op)
            else {
                h.push_str("<td></td>");
                continue;
            };
            let timed = r
                .fits
                .iter()
                .find(|f| {
                    f.structure == *n
                        && f.operator.name() == op.name()
                        && f.kernel == Kernel::Sampled
                        && f.family == row.family
                })
                .map(|f| f.exponent);
            let last = row.points.last();
            let hierarchy = row.verdict == Verdict::Matches
                && timed
                    .zip(row.exponent)
                    .is_some_and(|(t, e)| (t - e).abs() > TIME_VS_READS);
            let class = match row.verdict {
                Verdict::Matches if hierarchy => "warn",
                Verdict::Matches => "ok",
                Verdict::Differs => "bad",
                Verdict::NoReads | Verdict::TooFew => "skip",
            };
            if row.verdict == Verdict::Differs {
                findings.push(row);
            }
            let _ = write!(
                h,
                "<td class={class}>{}<br>{}<br>{}<br>{}{}</td>",
                row.cost.notation(),
                match (row.verdict, row.exponent) {
                    (Verdict::NoReads, _) => "no reads".to_string(),
                    (_, Some(e)) => format!("reads e = {e:.2}"),
                    (_, None) => "too few sizes".to_string(),
                },
                last.map(|&(faces, mean, _)| format!("{mean:.1} @ {faces}"))
                    .unwrap_or_default(),
                timed
                    .map(|t| format!("time e = {t:.2}"))
                    .unwrap_or_default(),
                if hierarchy { " ⚑" } else { "" }
            );
        }
        h.push_str("</tr>");
    }
    h.push_str("</table>");
    if !findings.is_empty() {
        h.push_str("<div class=read><b>Reads against declared costs.</b><ul>");
        for row in findings {
            let _ = write!(
                h,
                "<li>{} {}: declared {}, reads grow with exponent {:.2} ({}). {}</li>",
                esc(&row.structure),
                row.operator.name(),
                row.cost.notation(),
                row.exponent.unwrap_or(f64::NAN),
                row.points
                    .iter()
                    .map(|&(n, m, _)| format!("{m:.0} reads at {n} faces"))
                    .collect::<Vec<_>>()
                    .join(", "),
                finding(row)
            );
        }
        h.push_str("</ul></div>");
    }
}

/// What a row whose reads do not follow its declared cost says about the code.
fn finding(row: &ReadsRow) -> &'static str {
    match (row.structure.as_str(), row.operator) {
        ("edge-list" | "winged-edge", Operator::BoundaryCurves) => "One scan of the edges finds the boundary edges (the declared O(n1)), then each curve is walked by turning around its vertices with successor queries, several per boundary edge: O(∂n1) ≈ √n with a large constant, which outweighs the scan on small meshes; the reads approach O(n) as the mesh grows.",
        _ => "Not yet explained: compare the trace of one query (`topolab explain NAME --trace OP`) at two sizes.",
    }
}

/// The query the teaching section traces, and the structures it puts side by side.
const TAUGHT: (Operator, u32, &[&str]) = (
    Operator::R00,
    3,
    &["vertex-list", "index-half-edge", "che-l2"],
);

/// Appends the teaching section: R00 of the apex traced on Figure 4.10, one picture per structure
/// with the elements each read touched numbered in order, and the trace beside it.
pub fn teaching(h: &mut String) {
    let (op, v, names) = TAUGHT;
    let soup = counted_soup(&topolab_structures::meshes::open_tetrahedron());
    let Some(edges) = SoupEdges::of(&soup) else {
        return;
    };
    let _ = write!(h, "<h2>Teaching: one query, read by read</h2><div class=read>The 1-ring of the apex v{v} of Figure 4.10 (R00), asked of {} structures. Each picture numbers the elements whose records a read touched, in the order read (a number on a vertex: a per-vertex container such as <code>VH</code> or <code>HE_vert.edge</code>; on a face: <code>offsets</code>; beside a side of a triangle: a per-corner or per-half-edge container such as <code>corners</code>, <code>V</code>, <code>O</code>, <code>next</code>). The vertex list scans every face; the half-edge and the CHE turn around the vertex in O(k). <code>topolab explain NAME --trace r00 --vertex {v}</code> prints the same traces, from the same code.</div><div class=teach>", names.len());
    for name in names {
        let Ok(t) = trace::trace(
            name,
            &soup,
            op,
            Query {
                vertex: Some(v),
                ..Query::default()
            },
        ) else {
            continue;
        };
        let _ = write!(
            h,
            "<div><h3>{} — {} reads</h3>{}<pre>{}</pre></div>",
            esc(name),
            t.reads,
            drawing(&t.events, &soup, &edges),
            esc(&t.text())
        );
    }
    h.push_str("</div>");
}

/// Where a read of `container[index]` sits on the figure.
enum Place {
    Vertex(u32),
    Face(u32),
    /// Corner c (a CHE half-edge, a vertex-list slot): the side of face c / 3 leaving corner c % 3.
    Corner(u32),
    /// The edge of soup edge E.
    Edge(u32),
    /// A half-edge of the half-edge structures: h / 2 is its edge, h % 2 its side.
    HalfEdge(u32),
}

fn place(container: &str, index: u32) -> Option<Place> {
    Some(match container {
        "HE_vert.edge" | "av" | "VH" | "positions" | "lookup" => Place::Vertex(index),
        "HE_face.edge" | "af" | "face_offsets" | "offsets" => Place::Face(index),
        "V" | "O" | "corners" | "face_edges" => Place::Corner(index),
        "E" | "edge_start" | "edge_end" | "edge_left" | "edge_right" => Place::Edge(index),
        "next" | "prev" | "vert" | "face" | "pair" => Place::HalfEdge(index),
        _ => return None,
    })
}

/// Figure 4.10 (the layout of [`crate::page::svg::figure_4_10`]) with the reads of `events` numbered.
fn drawing(
    events: &[Event],
    soup: &topolab_structures_counted::PolygonSoup,
    edges: &SoupEdges,
) -> String {
    let (w, hgt) = (300.0, 280.0);
    let c = (w / 2.0, hgt / 2.0 + 10.0);
    let r = 115.0;
    let pos = |v: u32| crate::page::svg::figure_4_10_position(c, r, v);
    let faces: Vec<Vec<u32>> = soup.faces().map(|f| f.to_vec()).collect();
    let centroid = |t: usize| {
        let p: Vec<(f64, f64)> = faces[t].iter().map(|&v| pos(v)).collect();
        let n = p.len() as f64;
        (
            p.iter().map(|q| q.0).sum::<f64>() / n,
            p.iter().map(|q| q.1).sum::<f64>() / n,
        )
    };
    let toward = |a: (f64, f64), b: (f64, f64), s: f64| {
        (a.0 * (1.0 - s) + b.0 * s, a.1 * (1.0 - s) + b.1 * s)
    };
    let mut s = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{hgt}" viewBox="0 0 {w} {hgt}" font-family="sans-serif">"#
    );
    for (t, f) in faces.iter().enumerate() {
        let pts: Vec<String> = f
            .iter()
            .map(|&v| {
                let p = pos(v);
                format!("{:.1},{:.1}", p.0, p.1)
            })
            .collect();
        let fill = crate::page::svg::FIGURE_4_10_FILLS[t % 3];
        let _ = write!(
            s,
            r##"<polygon points="{}" fill="{fill}" stroke="#333"/>"##,
            pts.join(" ")
        );
        let g = centroid(t);
        let _ = write!(
            s,
            r##"<text x="{:.1}" y="{:.1}" font-size="11" fill="#555" text-anchor="middle">f{t}</text>"##,
            g.0,
            g.1 + 16.0
        );
    }
    for v in 0..soup.num_vertices() as u32 {
        let (x, y) = pos(v);
        let _ = write!(
            s,
            r##"<circle cx="{x:.1}" cy="{y:.1}" r="9" fill="white" stroke="#333"/><text x="{x:.1}" y="{:.1}" font-size="11" text-anchor="middle">v{v}</text>"##,
            y + 4.0
        );
    }
    // The reads, grouped by the point they are drawn at.
    let mut marks: BTreeMap<(i64, i64), Vec<usize>> = BTreeMap::new();
    let mut n = 0;
    for e in events {
        let Event::Read {
            container, index, ..
        } = e
        else {
            continue;
        };
        n += 1;
        let i = *index as u32;
        let at = match place(container, i) {
            Some(Place::Vertex(v)) if (v as usize) < soup.num_vertices() => {
                toward(pos(v), c, -0.18)
            }
            Some(Place::Face(f)) if (f as usize) < faces.len() => centroid(f as usize),
            Some(Place::Corner(k)) if (k as usize / 3) < faces.len() => {
                let (t, j) = (k as usize / 3, k as usize % 3);
                let f = &faces[t];
                let m = toward(pos(f[j]), pos(f[(j + 1) % f.len()]), 0.5);
                toward(m, centroid(t), 0.3)
            }
            Some(Place::Edge(e)) if (e as usize) < edges.ends.len() => {
                let [a, b] = edges.ends[e as usize];
                toward(pos(a), pos(b), 0.5)
            }
            Some(Place::HalfEdge(h)) if ((h / 2) as usize) < edges.ends.len() => {
                let [a, b] = edges.ends[(h / 2) as usize];
                let m = toward(pos(a), pos(b), 0.5);
                // The first half-edge of an edge runs as its first face does: that face's side.
                let side = toward(m, c, if h % 2 == 0 { 0.12 } else { -0.12 });
                if (a == 3) || (b == 3) {
                    toward(
                        m,
                        pos(if a == 3 { b } else { a }),
                        if h % 2 == 0 { 0.1 } else { -0.1 },
                    )
                } else {
                    side
                }
            }
            _ => continue,
        };
        marks
            .entry(((at.0 * 10.0) as i64, (at.1 * 10.0) as i64))
            .or_default()
            .push(n);
    }
    for ((x, y), order) in &marks {
        let (x, y) = (*x as f64 / 10.0, *y as f64 / 10.0);
        let label = order
            .iter()
            .map(|k| k.to_string())
            .collect::<Vec<_>>()
            .join(",");
        let wdt = 7.0 * label.len() as f64 + 8.0;
        let _ = write!(
            s,
            r##"<rect x="{:.1}" y="{:.1}" width="{wdt:.1}" height="15" rx="7" fill="#b00" opacity="0.85"/><text x="{x:.1}" y="{:.1}" font-size="11" fill="white" text-anchor="middle">{label}</text>"##,
            x - wdt / 2.0,
            y - 8.0,
            y + 3.5
        );
    }
    s.push_str("</svg>");
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_teaching_section_draws_every_read_of_each_trace() {
        let mut h = String::new();
        teaching(&mut h);
        assert_eq!(h.matches("<svg").count(), TAUGHT.2.len(), "{h}");
        // The index half-edge's first read, HE_vert.edge[3], is numbered 1 on the figure.
        assert!(h.contains("read HE_vert.edge[3]"), "{h}");
        assert!(h.contains(">1</text>") || h.contains(">1,"), "{h}");
    }
}
