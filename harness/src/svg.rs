//! SVG drawings of the report: log-log plots (plotters), bar charts, mesh thumbnails and the CHE
//! thesis chapter's Figure 4.10. Everything is inline SVG with real `<text>`, no fonts or network.

use glam::DVec3;
use plotters::prelude::*;
use std::fmt::Write;
use topolab_structures::PolygonSoup;

/// Colour of series `i` (a palette that stays distinguishable for ~14 series).
pub fn colour(i: usize) -> RGBColor {
    const P: [(u8, u8, u8); 14] = [
        (31, 119, 180),
        (255, 127, 14),
        (44, 160, 44),
        (214, 39, 40),
        (148, 103, 189),
        (140, 86, 75),
        (227, 119, 194),
        (127, 127, 127),
        (188, 189, 34),
        (23, 190, 207),
        (0, 0, 0),
        (174, 199, 232),
        (255, 152, 150),
        (152, 223, 138),
    ];
    let (r, g, b) = P[i % P.len()];
    RGBColor(r, g, b)
}

/// CSS hex of [`colour`].
pub fn colour_hex(i: usize) -> String {
    let c = colour(i);
    format!("#{:02x}{:02x}{:02x}", c.0, c.1, c.2)
}

fn si(x: f64) -> String {
    match x {
        x if x >= 1e6 => format!("{}M", trim(x / 1e6)),
        x if x >= 1e3 => format!("{}k", trim(x / 1e3)),
        x if x >= 1.0 => trim(x),
        x => format!("{x:.2}"),
    }
}

fn trim(x: f64) -> String {
    let s = format!("{x:.1}");
    s.strip_suffix(".0").map(str::to_string).unwrap_or(s)
}

/// One line of a plot.
#[derive(Clone, Debug)]
pub struct Series {
    /// Legend label.
    pub name: String,
    /// Colour index (see [`colour`]).
    pub colour: usize,
    /// (x, y) points.
    pub points: Vec<(f64, f64)>,
}

/// A log-log line plot of `series`.
pub fn loglog(title: &str, xlabel: &str, ylabel: &str, series: &[Series]) -> String {
    let pts: Vec<(f64, f64)> = series
        .iter()
        .flat_map(|s| s.points.iter().copied())
        .filter(|p| p.0 > 0.0 && p.1 > 0.0)
        .collect();
    if pts.is_empty() {
        return format!("<p class=\"empty\">{title}: nothing measured</p>");
    }
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for (x, y) in &pts {
        x0 = x0.min(*x);
        x1 = x1.max(*x);
        y0 = y0.min(*y);
        y1 = y1.max(*y);
    }
    let (x0, x1) = (x0 / 1.5, x1 * 1.5);
    let (y0, y1) = (y0 / 2.0, y1 * 2.0);
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, (520, 340)).into_drawing_area();
        let _ = root.fill(&WHITE);
        let chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 18))
            .margin(10)
            .x_label_area_size(40)
            .y_label_area_size(64)
            .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale());
        let Ok(mut chart) = chart else {
            return String::new();
        };
        let _ = chart
            .configure_mesh()
            .x_desc(xlabel)
            .y_desc(ylabel)
            .x_label_formatter(&|x| si(*x))
            .y_label_formatter(&|y| si(*y))
            .x_labels(8)
            .y_labels(6)
            .light_line_style(RGBColor(245, 245, 245))
            .label_style(("sans-serif", 13))
            .axis_desc_style(("sans-serif", 14))
            .draw();
        for Series {
            name,
            colour: ci,
            points,
        } in series
        {
            let c = colour(*ci);
            let mut p: Vec<(f64, f64)> = points
                .iter()
                .copied()
                .filter(|p| p.0 > 0.0 && p.1 > 0.0)
                .collect();
            p.sort_by(|a, b| a.0.total_cmp(&b.0));
            if p.is_empty() {
                continue;
            }
            if let Ok(s) = chart.draw_series(LineSeries::new(p.clone(), c.stroke_width(2))) {
                s.label(name.clone()).legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 16, y)], c.stroke_width(2))
                });
            }
            let _ = chart.draw_series(p.into_iter().map(|q| Circle::new(q, 3, c.filled())));
        }
        let _ = chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperLeft)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.3))
            .label_font(("sans-serif", 12))
            .draw();
        let _ = root.present();
    }
    out
}

/// Horizontal bars: (label, colour index, value, optional second value drawn as a tick).
pub fn bars(title: &str, unit: &str, rows: &[(String, usize, f64, Option<f64>)]) -> String {
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
    for (i, (label, ci, v, tick)) in rows.iter().enumerate() {
        let y = 30.0 + i as f64 * row_h;
        let bw = (w - left - right) * v / max;
        let _ = write!(
            s,
            r#"<text x="{}" y="{}" font-size="12" text-anchor="end">{label}</text><rect x="{left}" y="{}" width="{bw:.1}" height="{}" fill="{}"/><text x="{}" y="{}" font-size="12">{} {unit}</text>"#,
            left - 6.0,
            y + 14.0,
            y + 3.0,
            row_h - 6.0,
            colour_hex(*ci),
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

/// A shaded orthographic thumbnail of a mesh (at most ~1500 faces drawn, evenly sampled).
pub fn thumbnail(soup: &PolygonSoup, size: f64) -> String {
    let view = DVec3::new(1.0, -1.6, 1.2).normalize();
    let right = DVec3::Z.cross(view).normalize_or(DVec3::X);
    let up = view.cross(right);
    let light = DVec3::new(0.3, -0.5, 1.0).normalize();
    let (lo, hi) = soup
        .positions
        .iter()
        .fold((DVec3::MAX, DVec3::MIN), |(a, b), p| (a.min(*p), b.max(*p)));
    let centre = (lo + hi) * 0.5;
    let scale = size * 0.45 / ((hi - lo).length() * 0.5).max(1e-12);
    let stride = (soup.num_faces() / 1500).max(1);
    let mut polys: Vec<(f64, String)> = Vec::new();
    for (j, f) in soup.faces().enumerate().step_by(stride) {
        let ps: Vec<DVec3> = f
            .iter()
            .map(|&v| soup.positions[v as usize] - centre)
            .collect();
        let mut n = DVec3::ZERO;
        for i in 0..ps.len() {
            n += ps[i].cross(ps[(i + 1) % ps.len()]);
        }
        let n = n.normalize_or_zero();
        let facing = n.dot(view);
        let shade = (0.25 + 0.75 * n.dot(light).abs()) * if facing < 0.0 { 0.6 } else { 1.0 };
        let g = (60.0 + 170.0 * shade).min(235.0) as u8;
        let depth = ps.iter().map(|p| p.dot(view)).sum::<f64>() / ps.len() as f64;
        let mut pts = String::new();
        for p in &ps {
            let _ = write!(
                pts,
                "{:.1},{:.1} ",
                size / 2.0 + p.dot(right) * scale,
                size / 2.0 - p.dot(up) * scale
            );
        }
        let _ = j;
        polys.push((depth, format!(r#"<polygon points="{pts}" fill="rgb({g},{g},{})" stroke="rgb(40,40,60)" stroke-width="0.3"/>"#, g.saturating_add(15))));
    }
    polys.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut s = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{size}" height="{size}" viewBox="0 0 {size} {size}">"#
    );
    for (_, p) in polys {
        s.push_str(&p);
    }
    s.push_str("</svg>");
    s
}

/// The CHE thesis chapter's Figure 4.10, unfolded: the open tetrahedron (apex 3 in the middle,
/// triangle t = (t, t+1 mod 3, 3)) with vertex numbers and the half-edge numbers 3t + i, each
/// drawn inside its triangle next to the edge it starts.
pub fn figure_4_10() -> String {
    let soup = topolab_structures::meshes::open_tetrahedron();
    let (w, h) = (420.0, 380.0);
    let c = (w / 2.0, h / 2.0 + 20.0);
    let r = 160.0;
    let pos = |v: u32| -> (f64, f64) {
        if v == 3 {
            c
        } else {
            let a = std::f64::consts::FRAC_PI_2 + std::f64::consts::TAU * v as f64 / 3.0;
            (c.0 + r * a.cos(), c.1 - r * a.sin())
        }
    };
    let mut s = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif"><text x="{}" y="20" font-size="15" text-anchor="middle">Figure 4.10: the open tetrahedron, unfolded</text>"#,
        w / 2.0
    );
    for (t, f) in soup.faces().enumerate() {
        let p: Vec<(f64, f64)> = f.iter().map(|&v| pos(v)).collect();
        let fill = ["#dbe9f6", "#fde2c8", "#d8f0d2"][t];
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
        let p = loglog(
            "t",
            "x",
            "y",
            &[Series {
                name: "a".into(),
                colour: 0,
                points: vec![(1e3, 5.0), (1e4, 7.0)],
            }],
        );
        assert!(p.starts_with("<svg") && p.contains("<text"), "{p}");
        let f = figure_4_10();
        assert!(f.contains(">h8<") && f.contains(">t2<"));
        let t = thumbnail(&topolab_structures::meshes::torus(6, 4), 120.0);
        assert_eq!(t.matches("<polygon").count(), 48);
        let b = bars("m", "B", &[("x".into(), 0, 24.0, Some(20.0))]);
        assert!(b.contains("24.0 B"));
    }
}
