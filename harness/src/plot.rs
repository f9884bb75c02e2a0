//! The report's log-log line plots, drawn as plain SVG (no fonts, no network).
//!
//! Readability rules the page relies on, each enforced by construction here and checked by the
//! tests on the SVG geometry:
//!
//! - **The legend is outside the data area.** [`Layout::new`] puts the legend in a column to the
//!   right of the plot rectangle, never over it; the SVG marks both rectangles
//!   (`class="plot-area"`, `class="legend"`) so a test can read them back.
//! - **One hue family per structure family** ([`styles`]): the CHE levels are a ramp of blues
//!   (level 0 lightest), the half-edges oranges, the edge lists greens, the scanning corner
//!   lists greys, the grids purples; structures from outside the lab (OpenMesh, a crate's own
//!   structure) are dashed, the first black. The family comes from the structure's declared
//!   [`Family`], never from its name.
//! - **Markers tell lines apart in print**: each line of a plot gets its own marker shape
//!   (seven shapes, filled then hollow), so a grey printout still separates them.
//! - **Hover titles** (`<title>`): each point gives the structure, the size and the median,
//!   fastest and slowest run and the number of repetitions.

use std::fmt::Write;
use topolab_structures::Family;

/// How a line is drawn.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Style {
    /// Stroke and marker colour.
    pub rgb: (u8, u8, u8),
    /// Dashed: a structure from outside the lab (a baseline).
    pub dashed: bool,
    /// The marker's shape.
    pub marker: Marker,
    /// A hollow marker (white inside), the second round of the seven shapes.
    pub hollow: bool,
}

impl Style {
    /// CSS hex of the colour.
    pub fn hex(&self) -> String {
        let (r, g, b) = self.rgb;
        format!("#{r:02x}{g:02x}{b:02x}")
    }
}

/// A marker shape.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Marker {
    /// ●
    Circle,
    /// ■
    Square,
    /// ▲
    TriangleUp,
    /// ◆
    Diamond,
    /// ▼
    TriangleDown,
    /// ×
    Cross,
    /// +
    Plus,
}

impl Marker {
    /// Every shape, in the order lines take them.
    pub const ALL: [Marker; 7] = [
        Marker::Circle,
        Marker::Square,
        Marker::TriangleUp,
        Marker::Diamond,
        Marker::TriangleDown,
        Marker::Cross,
        Marker::Plus,
    ];

    /// The marker as SVG at (x, y), radius about `r`.
    fn svg(self, x: f64, y: f64, r: f64, colour: &str, hollow: bool) -> String {
        let fill = if hollow { "white" } else { colour };
        let paint = format!(r#"fill="{fill}" stroke="{colour}" stroke-width="1.5""#);
        match self {
            Marker::Circle => format!(r#"<circle cx="{x:.1}" cy="{y:.1}" r="{r:.1}" {paint}/>"#),
            Marker::Square => format!(
                r#"<rect x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}" {paint}/>"#,
                x - r * 0.85,
                y - r * 0.85,
                r * 1.7,
                r * 1.7
            ),
            Marker::TriangleUp | Marker::TriangleDown => {
                let s = if self == Marker::TriangleUp {
                    1.0
                } else {
                    -1.0
                };
                format!(
                    r#"<polygon points="{:.1},{:.1} {:.1},{:.1} {:.1},{:.1}" {paint}/>"#,
                    x,
                    y - s * r * 1.15,
                    x - r,
                    y + s * r * 0.75,
                    x + r,
                    y + s * r * 0.75
                )
            }
            Marker::Diamond => format!(
                r#"<polygon points="{x:.1},{:.1} {:.1},{y:.1} {x:.1},{:.1} {:.1},{y:.1}" {paint}/>"#,
                y - r * 1.2,
                x + r * 1.2,
                y + r * 1.2,
                x - r * 1.2
            ),
            // Strokes only: hollow and filled look alike, so the second round of crosses and
            // pluses is drawn thinner.
            Marker::Cross | Marker::Plus => {
                let w = if hollow { 1.2 } else { 2.2 };
                let (a, b) = if self == Marker::Cross {
                    ((r, r), (r, -r))
                } else {
                    ((r * 1.2, 0.0), (0.0, r * 1.2))
                };
                format!(
                    r#"<path d="M{:.1},{:.1}L{:.1},{:.1}M{:.1},{:.1}L{:.1},{:.1}" stroke="{colour}" stroke-width="{w}" fill="none"/>"#,
                    x - a.0,
                    y - a.1,
                    x + a.0,
                    y + a.1,
                    x - b.0,
                    y - b.1,
                    x + b.0,
                    y + b.1
                )
            }
        }
    }
}

/// The light and dark ends of a family's hue: a family's members are spread between them in
/// the order they are given (the CHE levels from level 0, lightest, to level 3, darkest).
fn ramp_ends(family: Family) -> ((u8, u8, u8), (u8, u8, u8)) {
    match family {
        Family::Che => ((140, 190, 230), (8, 48, 107)),
        Family::HalfEdge => ((253, 141, 60), (166, 54, 3)),
        Family::EdgeLists => ((102, 189, 99), (0, 100, 40)),
        Family::CornerLists => ((165, 165, 165), (95, 95, 95)),
        Family::RegularGrid => ((170, 150, 210), (84, 39, 143)),
        // A placeholder hue until the report's palette gives the Rust crates their own.
        Family::RustCrate => ((0, 0, 0), (90, 60, 40)),
        Family::Outside => ((0, 0, 0), (90, 60, 40)),
    }
}

fn mix(a: (u8, u8, u8), b: (u8, u8, u8), t: f64) -> (u8, u8, u8) {
    let m = |x: u8, y: u8| (x as f64 + (y as f64 - x as f64) * t).round() as u8;
    (m(a.0, b.0), m(a.1, b.1), m(a.2, b.2))
}

/// The style of each structure, given in report order with its family: a ramp of the family's
/// hue over its members (one member: the middle of the ramp; outside structures start at
/// black), dashed outside the lab, and a marker of its own per position (seven shapes, then
/// the same hollow), so that no two of up to fourteen structures look alike.
pub fn styles(families: &[Family]) -> Vec<Style> {
    families
        .iter()
        .enumerate()
        .map(|(i, &f)| {
            let members: Vec<usize> = (0..families.len()).filter(|&j| families[j] == f).collect();
            let rank = members.iter().position(|&j| j == i).unwrap_or(0);
            let (light, dark) = ramp_ends(f);
            let t = match (f, members.len()) {
                (Family::Outside, _) => rank as f64 / members.len().max(2) as f64,
                (_, 1) => 0.6,
                (_, n) => rank as f64 / (n - 1) as f64,
            };
            Style {
                rgb: mix(light, dark, t),
                dashed: f == Family::Outside,
                marker: Marker::ALL[i % Marker::ALL.len()],
                hollow: (i / Marker::ALL.len()) % 2 == 1,
            }
        })
        .collect()
}

/// One measured point: the median and, when known, the spread of the runs.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Point {
    /// x (size).
    pub x: f64,
    /// y: the median.
    pub y: f64,
    /// Fastest run.
    pub min: Option<f64>,
    /// Slowest run.
    pub max: Option<f64>,
    /// Timed runs.
    pub reps: usize,
}

/// One line of a plot.
#[derive(Clone, Debug)]
pub struct Line {
    /// Legend label.
    pub name: String,
    /// How it is drawn.
    pub style: Style,
    /// Its points.
    pub points: Vec<Point>,
}

/// An axis-aligned rectangle of the drawing.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Rect {
    /// Left.
    pub x: f64,
    /// Top.
    pub y: f64,
    /// Width.
    pub w: f64,
    /// Height.
    pub h: f64,
}

impl Rect {
    /// Whether the two rectangles share any interior point.
    pub fn overlaps(&self, o: &Rect) -> bool {
        self.x < o.x + o.w && o.x < self.x + self.w && self.y < o.y + o.h && o.y < self.y + self.h
    }

    /// Whether (x, y) lies inside or on the border.
    pub fn contains(&self, x: f64, y: f64) -> bool {
        x >= self.x && x <= self.x + self.w && y >= self.y && y <= self.y + self.h
    }
}

/// Where a plot's parts go: the data in `plot`, the legend in `legend`, to its right.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Layout {
    /// The whole drawing's width and height.
    pub size: (f64, f64),
    /// The data area (axes at its left and bottom edges).
    pub plot: Rect,
    /// The legend box.
    pub legend: Rect,
}

const LEGEND_ROW: f64 = 15.0;
/// Average advance of a legend character at 11 px (sans-serif), generous so names fit.
const CHAR_W: f64 = 6.6;

impl Layout {
    /// The layout for `entries` legend rows, the longest `longest` characters: the data area
    /// is always 340 × 230; the legend column starts 14 px right of it, so the two never
    /// overlap, and the drawing grows to hold every row.
    pub fn new(entries: usize, longest: usize) -> Layout {
        let plot = Rect {
            x: 66.0,
            y: 34.0,
            w: 340.0,
            h: 230.0,
        };
        let legend = Rect {
            x: plot.x + plot.w + 14.0,
            y: plot.y,
            w: 34.0 + longest as f64 * CHAR_W,
            h: 8.0 + entries as f64 * LEGEND_ROW,
        };
        let width = legend.x + legend.w + 6.0;
        let height = (plot.y + plot.h + 46.0).max(legend.y + legend.h + 6.0);
        Layout {
            size: (width, height),
            plot,
            legend,
        }
    }
}

fn si(x: f64) -> String {
    let trim = |x: f64| {
        let s = format!("{x:.1}");
        s.strip_suffix(".0").map(str::to_string).unwrap_or(s)
    };
    match x {
        x if x >= 1e9 => format!("{}G", trim(x / 1e9)),
        x if x >= 1e6 => format!("{}M", trim(x / 1e6)),
        x if x >= 1e3 => format!("{}k", trim(x / 1e3)),
        x if x >= 1.0 => trim(x),
        x => format!("{x:.2}"),
    }
}

/// A y value with its unit, for titles.
fn value(y: f64) -> String {
    if y >= 100.0 {
        format!("{y:.0}")
    } else if y >= 10.0 {
        format!("{y:.1}")
    } else {
        format!("{y:.2}")
    }
}

fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Tick values of a log axis over [lo, hi]: the powers of ten inside, with 2 and 5 times them
/// when fewer than three powers fall inside.
fn ticks(lo: f64, hi: f64) -> Vec<f64> {
    let (a, b) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
    let decades: Vec<f64> = (a..=b)
        .map(|e| 10f64.powi(e))
        .filter(|&t| t >= lo && t <= hi)
        .collect();
    if decades.len() >= 3 {
        return decades;
    }
    (a..=b)
        .flat_map(|e| [1.0, 2.0, 5.0].map(|m| m * 10f64.powi(e)))
        .filter(|&t| t >= lo && t <= hi)
        .collect()
}

/// A log-log plot of `lines` (`unit` ends each hover title's numbers, e.g. "ns per query");
/// lines without a positive point are left out of the plot and its legend.
pub fn loglog(title: &str, xlabel: &str, ylabel: &str, unit: &str, lines: &[Line]) -> String {
    let shown: Vec<(&Line, Vec<Point>)> = lines
        .iter()
        .map(|l| {
            let mut p: Vec<Point> = l
                .points
                .iter()
                .copied()
                .filter(|p| p.x > 0.0 && p.y > 0.0 && p.x.is_finite() && p.y.is_finite())
                .collect();
            p.sort_by(|a, b| a.x.total_cmp(&b.x));
            (l, p)
        })
        .filter(|(_, p)| !p.is_empty())
        .collect();
    if shown.is_empty() {
        return format!("<p class=\"empty\">{}: nothing measured</p>", esc(title));
    }
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for p in shown.iter().flat_map(|(_, p)| p) {
        (x0, x1, y0, y1) = (x0.min(p.x), x1.max(p.x), y0.min(p.y), y1.max(p.y));
    }
    let (x0, x1, y0, y1) = (x0 / 1.5, x1 * 1.5, y0 / 1.6, y1 * 1.6);
    let longest = shown
        .iter()
        .map(|(l, _)| l.name.chars().count())
        .max()
        .unwrap_or(0);
    let lay = Layout::new(shown.len(), longest);
    let Rect {
        x: px,
        y: py,
        w: pw,
        h: ph,
    } = lay.plot;
    let sx = |x: f64| px + pw * (x.ln() - x0.ln()) / (x1.ln() - x0.ln());
    let sy = |y: f64| py + ph - ph * (y.ln() - y0.ln()) / (y1.ln() - y0.ln());
    let (w, h) = lay.size;
    let mut s = String::new();
    let _ = write!(
        s,
        r##"<svg xmlns="http://www.w3.org/2000/svg" class="loglog" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.0} {h:.0}" font-family="sans-serif"><rect width="100%" height="100%" fill="white"/><text x="{:.1}" y="20" font-size="15" text-anchor="middle">{}</text>"##,
        px + pw / 2.0,
        esc(title)
    );
    let _ = write!(
        s,
        r##"<rect class="plot-area" x="{px:.1}" y="{py:.1}" width="{pw:.1}" height="{ph:.1}" fill="none" stroke="#999"/>"##
    );
    for t in ticks(x0, x1) {
        let x = sx(t);
        let _ = write!(
            s,
            r##"<line x1="{x:.1}" x2="{x:.1}" y1="{py:.1}" y2="{:.1}" stroke="#eee"/><text x="{x:.1}" y="{:.1}" font-size="12" text-anchor="middle">{}</text>"##,
            py + ph,
            py + ph + 15.0,
            si(t)
        );
    }
    for t in ticks(y0, y1) {
        let y = sy(t);
        let _ = write!(
            s,
            r##"<line x1="{px:.1}" x2="{:.1}" y1="{y:.1}" y2="{y:.1}" stroke="#eee"/><text x="{:.1}" y="{:.1}" font-size="12" text-anchor="end">{}</text>"##,
            px + pw,
            px - 5.0,
            y + 4.0,
            si(t)
        );
    }
    let _ = write!(
        s,
        r##"<text x="{:.1}" y="{:.1}" font-size="13" text-anchor="middle">{}</text><text transform="translate(16,{:.1}) rotate(-90)" font-size="13" text-anchor="middle">{}</text>"##,
        px + pw / 2.0,
        py + ph + 34.0,
        esc(xlabel),
        py + ph / 2.0,
        esc(ylabel)
    );
    for (line, pts) in &shown {
        let c = line.style.hex();
        let dash = if line.style.dashed {
            r#" stroke-dasharray="7 4""#
        } else {
            ""
        };
        let path: Vec<String> = pts
            .iter()
            .map(|p| format!("{:.1},{:.1}", sx(p.x), sy(p.y)))
            .collect();
        let _ = write!(
            s,
            r#"<g class="series"><title>{}</title><polyline points="{}" fill="none" stroke="{c}" stroke-width="2"{dash}/>"#,
            esc(&line.name),
            path.join(" ")
        );
        for p in pts {
            let spread = match (p.min, p.max) {
                (Some(a), Some(b)) => format!(" (fastest {}, slowest {})", value(a), value(b)),
                _ => String::new(),
            };
            let reps = match p.reps {
                0 => String::new(),
                1 => ", 1 run".into(),
                n => format!(", {n} runs"),
            };
            let _ = write!(
                s,
                "<g><title>{} at {}: median {} {}{spread}{reps}</title>{}</g>",
                esc(&line.name),
                si(p.x),
                value(p.y),
                esc(unit),
                line.style
                    .marker
                    .svg(sx(p.x), sy(p.y), 3.6, &c, line.style.hollow)
            );
        }
        s.push_str("</g>");
    }
    let l = lay.legend;
    let _ = write!(
        s,
        r##"<rect class="legend" x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}" fill="white" stroke="#ccc"/>"##,
        l.x, l.y, l.w, l.h
    );
    for (i, (line, _)) in shown.iter().enumerate() {
        let y = l.y + 4.0 + LEGEND_ROW * (i as f64 + 0.5);
        let c = line.style.hex();
        let dash = if line.style.dashed {
            r#" stroke-dasharray="5 3""#
        } else {
            ""
        };
        let _ = write!(
            s,
            r#"<line x1="{:.1}" x2="{:.1}" y1="{y:.1}" y2="{y:.1}" stroke="{c}" stroke-width="2"{dash}/>{}<text class="legend-label" x="{:.1}" y="{:.1}" font-size="11">{}</text>"#,
            l.x + 5.0,
            l.x + 27.0,
            line.style
                .marker
                .svg(l.x + 16.0, y, 3.3, &c, line.style.hollow),
            l.x + 31.0,
            y + 4.0,
            esc(&line.name)
        );
    }
    s.push_str("</svg>");
    s
}

/// The rectangle of the first `<rect class="CLASS" ...>` of an SVG drawing, read back from its
/// attributes (for the tests of this module and of the report page).
pub fn rect_of(svg: &str, class: &str) -> Option<Rect> {
    let start = svg.find(&format!(r#"<rect class="{class}""#))?;
    let tag = &svg[start..start + svg[start..].find('>')?];
    let attr = |name: &str| -> Option<f64> {
        let at = tag.find(&format!(" {name}=\""))? + name.len() + 3;
        tag[at..at + tag[at..].find('"')?].parse().ok()
    };
    Some(Rect {
        x: attr("x")?,
        y: attr("y")?,
        w: attr("width")?,
        h: attr("height")?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn numbers_after<'a>(svg: &'a str, key: &'a str) -> impl Iterator<Item = f64> + 'a {
        svg.match_indices(key).filter_map(move |(i, _)| {
            let rest = &svg[i + key.len()..];
            rest[..rest.find('"')?].parse().ok()
        })
    }

    fn plot(lines: usize, name_len: usize) -> String {
        let families = [
            Family::CornerLists,
            Family::CornerLists,
            Family::EdgeLists,
            Family::EdgeLists,
            Family::HalfEdge,
            Family::HalfEdge,
            Family::RegularGrid,
            Family::RegularGrid,
            Family::Che,
            Family::Che,
            Family::Che,
            Family::Che,
            Family::Outside,
            Family::Outside,
        ];
        let st = styles(&families[..lines.min(families.len())]);
        let ls: Vec<Line> = (0..lines)
            .map(|i| Line {
                name: format!("{i:0>name_len$}"),
                style: st[i % st.len()],
                // The largest values sit where an inside legend used to go: top left.
                points: (0..5)
                    .map(|k| Point {
                        x: 1e3 * 4f64.powi(k),
                        y: (1 + i) as f64 * 10f64.powi(4 - k),
                        min: Some(1.0),
                        max: Some(2.0),
                        reps: 3,
                    })
                    .collect(),
            })
            .collect();
        loglog("t", "triangles", "ns", "ns per query", &ls)
    }

    #[test]
    fn the_legend_is_outside_the_data_area_and_holds_every_label() {
        for (lines, name_len) in [(1, 1), (4, 8), (14, 17), (30, 40)] {
            let svg = plot(lines, name_len);
            let area = rect_of(&svg, "plot-area").expect("a plot area");
            let legend = rect_of(&svg, "legend").expect("a legend");
            assert!(!area.overlaps(&legend), "{area:?} {legend:?}");
            // Every legend label starts inside the legend box; the box is wide enough for the
            // longest name at the assumed character width.
            let xs: Vec<f64> = numbers_after(&svg, r#"class="legend-label" x=""#).collect();
            assert_eq!(xs.len(), lines);
            assert!(xs.iter().all(|&x| legend.contains(x, legend.y)));
            assert!(xs[0] + name_len as f64 * CHAR_W <= legend.x + legend.w);
            // The drawing holds the legend.
            let width: f64 = numbers_after(&svg, "width=\"").next().unwrap();
            let height: f64 = numbers_after(&svg, "height=\"").next().unwrap();
            assert!(legend.x + legend.w <= width && legend.y + legend.h <= height);
            // Every data point is drawn inside the data area.
            let circles: Vec<(f64, f64)> = numbers_after(&svg, "<circle cx=\"")
                .zip(numbers_after(&svg, "\" cy=\""))
                .collect();
            let inside = circles
                .iter()
                .filter(|(x, y)| area.contains(*x, *y))
                .count();
            // The legend's circle markers are outside it, one per circle-marker line.
            let legend_circles = circles.len() - inside;
            assert!(inside > 0 && legend_circles <= lines, "{circles:?}");
        }
    }

    #[test]
    fn families_get_one_hue_each_and_markers_differ() {
        let fam = [
            Family::CornerLists,
            Family::CornerLists,
            Family::HalfEdge,
            Family::HalfEdge,
            Family::Che,
            Family::Che,
            Family::Che,
            Family::Che,
            Family::Outside,
        ];
        let st = styles(&fam);
        // A ramp: CHE levels go from light to dark, strictly.
        let lum = |s: &Style| s.rgb.0 as u32 + s.rgb.1 as u32 + s.rgb.2 as u32;
        for w in st[4..8].windows(2) {
            assert!(lum(&w[0]) > lum(&w[1]), "{w:?}");
        }
        // The CHE levels are blue (blue channel the largest), the half-edges are orange (red
        // the largest), the corner lists grey (channels equal).
        assert!(st[4..8].iter().all(|s| s.rgb.2 > s.rgb.0));
        assert!(st[2..4].iter().all(|s| s.rgb.0 > s.rgb.2));
        assert!(st[0..2]
            .iter()
            .all(|s| s.rgb.0 == s.rgb.1 && s.rgb.1 == s.rgb.2));
        // Only outside structures are dashed, and the first one is black.
        assert!(st.iter().all(|s| s.dashed == (s == &st[8])));
        assert_eq!(st[8].rgb, (0, 0, 0));
        // No two structures share colour and marker.
        for (i, a) in st.iter().enumerate() {
            for b in &st[..i] {
                assert!(
                    (a.marker, a.hollow) != (b.marker, b.hollow) || a.rgb != b.rgb,
                    "{a:?} {b:?}"
                );
            }
        }
    }

    #[test]
    fn each_point_has_a_hover_title_with_its_spread() {
        let svg = plot(2, 3);
        assert_eq!(
            svg.matches("(fastest 1.00, slowest 2.00), 3 runs</title>")
                .count(),
            10
        );
        assert!(svg.contains("<title>000 at 1k: median 10000 ns per query"));
    }

    #[test]
    fn nothing_measured_is_said() {
        let empty = loglog("r00", "x", "y", "ns", &[]);
        assert!(empty.contains("nothing measured") && !empty.contains("<svg"));
    }
}
