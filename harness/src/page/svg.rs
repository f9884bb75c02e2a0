//! SVG drawings of the report: bar charts (drawn with plotters, like [`crate::page::plot`]'s log-log
//! plots), mesh thumbnails ([`crate::page::thumbnail`]), the CHE thesis chapter's Figure 4.10 and a
//! small mesh before or after an edit ([`edit_picture`]).
//! Everything is inline SVG with real `<text>`, no fonts or network. The thumbnails and the
//! figure are drawings, not charts, and are written by hand: they place polygons and labels in
//! their own geometry (a shaded projection of a mesh, an unfolded tetrahedron), which a chart
//! library's axes and series do not describe.

use crate::format::esc;
use crate::page::plot::{self, Style};
use crate::results::EditPicture;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::fmt::Write;
use topolab_structures::PolygonSoup;

/// Horizontal bars: (label, style (its colour fills the bar), value, optional second value
/// drawn as a tick).
pub fn bars(title: &str, unit: &str, rows: &[(String, Style, f64, Option<f64>)]) -> String {
    draw_bars(title, unit, rows).unwrap_or_else(|e| {
        format!(
            "<p class=\"empty\">{}: the chart could not be drawn ({})</p>",
            esc(title),
            esc(&e.to_string())
        )
    })
}

/// Average advance of a 12 px sans-serif character, generous so the longest label fits.
const LABEL_CHAR_W: f64 = 7.2;

/// [`bars`] drawn with plotters: each row is two units of the y axis (first row on top),
/// labelled at its middle by the structure's name; each bar's value is written at its end. plotters writes
/// no `<title>`, so each tick's hover title ("containers: …") is an invisible rectangle over
/// it, added after plotters' drawing (`plot::finish`).
fn draw_bars(
    title: &str,
    unit: &str,
    rows: &[(String, Style, f64, Option<f64>)],
) -> Result<String, Box<dyn std::error::Error>> {
    let max = rows
        .iter()
        .map(|r| r.2.max(r.3.unwrap_or(0.0)))
        .fold(0.0, f64::max)
        .max(1e-9);
    if rows.is_empty() {
        return Ok(format!(
            "<p class=\"empty\">{}: nothing measured</p>",
            esc(title)
        ));
    }
    let n = rows.len() as u32;
    let longest = rows.iter().map(|r| r.0.chars().count()).max().unwrap_or(0);
    let (left, bars_w, right, row_h, top) = (
        (12.0 + longest as f64 * LABEL_CHAR_W).ceil() as u32,
        300,
        80,
        22,
        30,
    );
    let size = (left + bars_w + right, top + row_h * n + 6);
    let mut svg = String::new();
    let mut marks = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE)?;
        root.draw(&Text::new(
            title.to_string(),
            (size.0 as i32 / 2, 6),
            plot::font(15.0).pos(Pos::new(HPos::Center, VPos::Top)),
        ))?;
        let region = root.clone().shrink((0, top), (left + bars_w, row_h * n));
        // Row i spans y from 2(n-1-i) to 2(n-i) (plotters' y axis grows upwards, the rows are
        // read downwards); its label sits at the middle, an integer so that the axis, whose
        // values are integers, can write it (plotters' float axes take no chosen ticks).
        let bottom = |i: usize| 2 * (rows.len() - 1 - i) as i32;
        let label = |y: &i32| {
            let row = rows.len() as i32 - 1 - y.div_euclid(2);
            usize::try_from(row)
                .ok()
                .and_then(|r| rows.get(r))
                .map_or(String::new(), |r| r.0.clone())
        };
        let mut chart = ChartBuilder::on(&region)
            .y_label_area_size(left)
            .build_cartesian_2d(
                0.0..max,
                (0..2 * n as i32).with_key_points((0..rows.len()).map(|i| bottom(i) + 1).collect()),
            )?;
        chart
            .configure_mesh()
            .disable_x_mesh()
            .disable_y_mesh()
            .disable_x_axis()
            .y_label_formatter(&label)
            .label_style(plot::font(12.0))
            .axis_style(RGBColor(153, 153, 153))
            .draw()?;
        chart.draw_series(rows.iter().enumerate().map(|(i, (_, style, v, _))| {
            let mut bar = Rectangle::new(
                [(0.0, bottom(i)), (*v, bottom(i) + 2)],
                plot::colour(style).filled(),
            );
            bar.set_margin(3, 3, 0, 0);
            bar
        }))?;
        for (i, (_, _, v, tick)) in rows.iter().enumerate() {
            let (x, y) = chart.backend_coord(&(*v, bottom(i) + 1));
            root.draw(&Text::new(
                format!("{} {unit}", plot::value(*v)),
                (x + 4, y),
                plot::font(12.0).pos(Pos::new(HPos::Left, VPos::Center)),
            ))?;
            if let Some(t) = tick {
                let (tx, y0) = chart.backend_coord(&(*t, bottom(i) + 2));
                let (_, y1) = chart.backend_coord(&(*t, bottom(i)));
                root.draw(&PathElement::new(
                    vec![(tx, y0 + 1), (tx, y1 - 1)],
                    BLACK.stroke_width(2),
                ))?;
                let _ = write!(
                    marks,
                    r#"<rect x="{}" y="{y0}" width="6" height="{}" fill="none" pointer-events="all"><title>containers: {} {}</title></rect>"#,
                    tx - 3,
                    y1 - y0,
                    plot::value(*t),
                    esc(unit)
                );
            }
        }
        root.present()?;
    }
    plot::finish(&svg, size, "bars", &marks)
}

/// A shaded orthographic thumbnail of a mesh, at every size (see [`crate::page::thumbnail`]).
pub fn thumbnail(soup: &PolygonSoup, size: f64) -> String {
    crate::page::thumbnail::thumbnail(soup, size)
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

/// The colour of what an edit picture marks: the element edited, or what the edit made.
pub const EDIT_MARK: &str = "#c0392b";

/// A small mesh before or after an edit ([`EditPicture`]), seen from above (its x and y,
/// where the lab's small meshes lie: the grid in z = 0, the open tetrahedron with its base
/// there and its apex above the middle), fitted into `size` × `size` pixels under `title`:
/// every face filled, every live vertex numbered, the marked edges and vertices in
/// [`EDIT_MARK`].
pub fn edit_picture(picture: &EditPicture, title: &str, size: f64) -> String {
    let live: Vec<(usize, [f64; 3])> = picture
        .vertices
        .iter()
        .enumerate()
        .filter_map(|(v, p)| p.map(|p| (v, p)))
        .collect();
    let (top, margin) = (24.0, 16.0);
    let mut s = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" class="edit-picture" width="{size}" height="{}" viewBox="0 0 {size} {}" font-family="sans-serif"><text x="{}" y="16" font-size="13" text-anchor="middle">{}</text>"#,
        size + top,
        size + top,
        size / 2.0,
        esc(title)
    );
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for (_, p) in &live {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let span = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(1e-12);
    let scale = (size - 2.0 * margin) / span;
    // Centred in the box, y upwards.
    let off = (
        margin + ((size - 2.0 * margin) - (hi[0] - lo[0]) * scale) / 2.0,
        margin + ((size - 2.0 * margin) - (hi[1] - lo[1]) * scale) / 2.0,
    );
    let at = |v: u32| -> Option<(f64, f64)> {
        let p = picture.vertices.get(v as usize).copied().flatten()?;
        Some((
            off.0 + (p[0] - lo[0]) * scale,
            top + size - off.1 - (p[1] - lo[1]) * scale,
        ))
    };
    for (t, f) in picture.faces.iter().enumerate() {
        let points: Option<Vec<String>> = f
            .iter()
            .map(|&v| at(v).map(|(x, y)| format!("{x:.1},{y:.1}")))
            .collect();
        if let Some(points) = points {
            let _ = write!(
                s,
                r##"<polygon points="{}" fill="{}" fill-opacity="0.8" stroke="#555" stroke-width="1"/>"##,
                points.join(" "),
                FIGURE_4_10_FILLS[t % 3]
            );
        }
    }
    for [a, b] in &picture.marked_edges {
        if let (Some(p), Some(q)) = (at(*a), at(*b)) {
            let _ = write!(
                s,
                r#"<line class="marked" x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{EDIT_MARK}" stroke-width="3.5"/>"#,
                p.0, p.1, q.0, q.1
            );
        }
    }
    for (v, _) in &live {
        let Some((x, y)) = at(*v as u32) else {
            continue;
        };
        let marked = picture.marked_vertices.contains(&(*v as u32));
        let (fill, colour) = if marked {
            (EDIT_MARK, "white")
        } else {
            ("white", "black")
        };
        let _ = write!(
            s,
            r##"<circle cx="{x:.1}" cy="{y:.1}" r="9" fill="{fill}" stroke="#333"/><text x="{x:.1}" y="{:.1}" font-size="11" text-anchor="middle" fill="{colour}">{v}</text>"##,
            y + 4.0
        );
    }
    s.push_str("</svg>");
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
        let style = crate::page::plot::styles(&[topolab_structures::Family::Che])[0];
        let b = bars("m", "B", &[("x".into(), style, 24.0, Some(20.0))]);
        // plotters writes colours in capitals.
        assert!(b.contains("24.0 B") && b.to_lowercase().contains(&style.hex()));
        assert!(b.contains("<title>containers: 20.0 B</title>") && b.contains(">\nx\n</text>"));
    }

    #[test]
    fn an_edit_picture_numbers_the_live_vertices_and_marks_what_it_is_asked_to() {
        // Two triangles on a square; vertex 4 deleted: it is neither drawn nor numbered.
        let p = EditPicture {
            vertices: vec![
                Some([0.0, 0.0, 0.0]),
                Some([1.0, 0.0, 0.0]),
                Some([1.0, 1.0, 0.0]),
                Some([0.0, 1.0, 0.0]),
                None,
            ],
            faces: vec![vec![0, 1, 2], vec![0, 2, 3]],
            marked_vertices: vec![2],
            marked_edges: vec![[0, 2]],
        };
        let svg = edit_picture(&p, "before <flip>", 160.0);
        assert_eq!(svg.matches("<polygon").count(), 2);
        assert_eq!(svg.matches("<circle").count(), 4);
        assert!(!svg.contains(">4</text>"), "{svg}");
        assert_eq!(svg.matches(r#"class="marked""#).count(), 1);
        assert_eq!(svg.matches(&format!(r#"fill="{EDIT_MARK}""#)).count(), 1);
        assert!(svg.contains("before &lt;flip&gt;"), "{svg}");
        // The square fills the box: vertex 0 bottom left, vertex 2 top right.
        assert!(svg.contains(r#"cx="16.0" cy="168.0""#), "{svg}");
        assert!(svg.contains(r#"cx="144.0" cy="40.0""#), "{svg}");
    }
}
