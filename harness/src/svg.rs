//! SVG drawings of the report: bar charts, mesh thumbnails ([`crate::thumbnail`]) and the CHE
//! thesis chapter's Figure 4.10 (the log-log plots are [`crate::plot`]'s). Everything is
//! inline SVG with real `<text>`, no fonts or network.

use crate::plot::Style;
use std::fmt::Write;
use topolab_structures::PolygonSoup;

/// Horizontal bars: (label, style (its colour fills the bar), value, optional second value
/// drawn as a tick).
pub fn bars(title: &str, unit: &str, rows: &[(String, Style, f64, Option<f64>)]) -> String {
    let max = rows
        .iter()
        .map(|r| r.2.max(r.3.unwrap_or(0.0)))
        .fold(0.0, f64::max)
        .max(1e-9);
    let (w, row_h, left, right) = (560.0, 22.0, 150.0, 110.0);
    let h = 36.0 + row_h * rows.len() as f64;
    let mut s = String::new();
    let _ = write!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif"><text x="{}" y="18" font-size="15" text-anchor="middle">{title}</text>"#,
        w / 2.0
    );
    for (i, (label, style, v, tick)) in rows.iter().enumerate() {
        let y = 30.0 + i as f64 * row_h;
        let bw = (w - left - right) * v / max;
        let _ = write!(
            s,
            r#"<text x="{}" y="{}" font-size="12" text-anchor="end">{label}</text><rect x="{left}" y="{}" width="{bw:.1}" height="{}" fill="{}"/><text x="{}" y="{}" font-size="12">{} {unit}</text>"#,
            left - 6.0,
            y + 14.0,
            y + 3.0,
            row_h - 6.0,
            style.hex(),
            left + bw + 4.0,
            y + 14.0,
            trim_num(*v)
        );
        if let Some(t) = tick {
            let tx = left + (w - left - right) * t / max;
            let _ = write!(
                s,
                r#"<line x1="{tx:.1}" x2="{tx:.1}" y1="{}" y2="{}" stroke="black" stroke-width="2"><title>containers: {} {unit}</title></line>"#,
                y + 1.0,
                y + row_h - 1.0,
                trim_num(*t)
            );
        }
    }
    s.push_str("</svg>");
    s
}

fn trim_num(v: f64) -> String {
    if v >= 100.0 {
        format!("{v:.0}")
    } else if v >= 10.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.2}")
    }
}

/// A shaded orthographic thumbnail of a mesh, at every size (see [`crate::thumbnail`]).
pub fn thumbnail(soup: &PolygonSoup, size: f64) -> String {
    crate::thumbnail::thumbnail(soup, size)
}

/// Where vertex `v` of Figure 4.10 sits in its unfolded drawing around `center`: apex 3 in the
/// middle, vertices 0, 1, 2 on a circle of `radius` counter-clockwise from the top. Shared by
/// every drawing of the figure (the teaching sections' read-by-read pictures too), so they all
/// show the same layout.
pub fn figure_4_10_position(center: (f64, f64), radius: f64, v: u32) -> (f64, f64) {
    if v == 3 {
        center
    } else {
        let a = std::f64::consts::FRAC_PI_2 + std::f64::consts::TAU * v as f64 / 3.0;
        (center.0 + radius * a.cos(), center.1 - radius * a.sin())
    }
}

/// The fill of triangle t (mod 3) in every drawing of Figure 4.10.
pub const FIGURE_4_10_FILLS: [&str; 3] = ["#dbe9f6", "#fde2c8", "#d8f0d2"];

/// The CHE thesis chapter's Figure 4.10, unfolded: the open tetrahedron (apex 3 in the middle,
/// triangle t = (t, t+1 mod 3, 3)) with vertex numbers and the half-edge numbers 3t + i, each
/// drawn inside its triangle next to the edge it starts.
pub fn figure_4_10() -> String {
    let soup = topolab_structures::meshes::open_tetrahedron();
    let (w, h) = (420.0, 380.0);
    let c = (w / 2.0, h / 2.0 + 20.0);
    let r = 160.0;
    let pos = |v: u32| figure_4_10_position(c, r, v);
    let mut s = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif"><text x="{}" y="20" font-size="15" text-anchor="middle">Figure 4.10: the open tetrahedron, unfolded</text>"#,
        w / 2.0
    );
    for (t, f) in soup.faces().enumerate() {
        let p: Vec<(f64, f64)> = f.iter().map(|&v| pos(v)).collect();
        let fill = FIGURE_4_10_FILLS[t % 3];
        let _ = write!(
            s,
            r##"<polygon points="{:.1},{:.1} {:.1},{:.1} {:.1},{:.1}" fill="{fill}" stroke="#333" stroke-width="1.5"/>"##,
            p[0].0, p[0].1, p[1].0, p[1].1, p[2].0, p[2].1
        );
        let g = (
            (p[0].0 + p[1].0 + p[2].0) / 3.0,
            (p[0].1 + p[1].1 + p[2].1) / 3.0,
        );
        let _ = write!(
            s,
            r#"<text x="{:.1}" y="{:.1}" font-size="14" font-weight="bold" text-anchor="middle">t{t}</text>"#,
            g.0,
            g.1 + 5.0
        );
        for i in 0..3 {
            let (a, b) = (p[i], p[(i + 1) % 3]);
            // Half-edge 3t+i from corner i to corner i+1, labelled between the edge's midpoint and the centroid.
            let m = ((a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0);
            let l = (m.0 * 0.7 + g.0 * 0.3, m.1 * 0.7 + g.1 * 0.3);
            let _ = write!(
                s,
                r##"<text x="{:.1}" y="{:.1}" font-size="12" fill="#a00" text-anchor="middle">h{}</text>"##,
                l.0,
                l.1 + 4.0,
                3 * t + i
            );
        }
    }
    for v in 0..4u32 {
        let (x, y) = pos(v);
        let _ = write!(
            s,
            r##"<circle cx="{x:.1}" cy="{y:.1}" r="11" fill="white" stroke="#333"/><text x="{x:.1}" y="{:.1}" font-size="12" text-anchor="middle">{v}</text>"##,
            y + 4.0
        );
    }
    s.push_str(r#"<text x="10" y="370" font-size="11">boundary: the outer edges 0-1, 1-2, 2-0 (one curve); apex 3 is interior</text></svg>"#);
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn drawings_are_svg_with_text() {
        let f = figure_4_10();
        assert!(f.contains(">h8<") && f.contains(">t2<"));
        let t = thumbnail(&topolab_structures::meshes::torus(6, 4), 120.0);
        assert_eq!(t.matches("<polygon").count(), 48);
        let style = crate::plot::styles(&[topolab_structures::Family::Che])[0];
        let b = bars("m", "B", &[("x".into(), style, 24.0, Some(20.0))]);
        assert!(b.contains("24.0 B") && b.contains(&style.hex()));
    }
}
