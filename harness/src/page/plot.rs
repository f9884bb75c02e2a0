//! The report's log-log line plots, drawn with the `plotters` crate's SVG backend: inline SVG
//! with real `<text>`, no font files, no network.
//!
//! Readability rules the page relies on, each enforced by construction here and checked by the
//! tests on the SVG geometry:
//!
//! - **The legend is outside the data area.** [`Layout::new`] puts the legend in a column to the
//!   right of the plot rectangle, never over it; the SVG marks both rectangles
//!   (`class="plot-area"`, `class="legend"`) so a test can read them back.
//! - **One hue family per structure family** ([`styles`]): the CHE levels are a ramp of blues
//!   (level 0 lightest), the half-edges oranges, the edge lists greens, the scanning corner
//!   lists greys, the grids purples, the Rust crates (lox, baby_shark, tri-mesh) rust reds;
//!   structures from outside the lab (OpenMesh, a crate's own structure, the Rust crates) are
//!   dashed, the first of the baselines black. The family comes from the structure's declared
//!   [`Family`], never from its name.
//! - **Markers tell lines apart in print**: each line of a plot gets its own marker shape
//!   (seven shapes, filled then hollow), so a grey printout still separates them.
//! - **Intervals**: each point's interval of its median, when it has one, is a vertical bar
//!   through its marker in its line's colour.
//! - **Hover titles** (`<title>`): each point gives the structure, the size, the median, its
//!   interval and the number of rounds. plotters' SVG backend writes no
//!   `<title>` (nor `class`), so these are added to its output by `finish`: one invisible
//!   circle over each marker holds the point's title.

use crate::format::esc;
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::fmt::Write;
use topolab_structures::Family;

/// A drawing area of plotters' SVG backend, in pixels from its top left corner.
type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;
/// What drawing can fail with (plotters' error type; its SVG backend writes into a string).
type Drawn = Result<(), DrawingAreaErrorKind<<SVGBackend<'static> as DrawingBackend>::ErrorType>>;

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

    /// Draws the marker centred on pixel `at`, about `r` pixels in radius, in `colour`
    /// (white inside when hollow).
    fn draw(self, area: &Area, at: (i32, i32), r: f64, colour: RGBColor, hollow: bool) -> Drawn {
        let px = |dx: f64, dy: f64| (at.0 + dx.round() as i32, at.1 + dy.round() as i32);
        let inside = if hollow {
            WHITE.filled()
        } else {
            colour.filled()
        };
        let outline = colour.stroke_width(if hollow { 2 } else { 1 });
        let corners: Vec<(f64, f64)> = match self {
            Marker::Circle => {
                let radius = r.round() as i32;
                area.draw(&Circle::new(at, radius, inside))?;
                return area.draw(&Circle::new(at, radius, outline));
            }
            // Strokes only: hollow and filled look alike, so the second round of crosses and
            // pluses is drawn thinner.
            Marker::Cross | Marker::Plus => {
                let stroke = colour.stroke_width(if hollow { 1 } else { 2 });
                let arms = if self == Marker::Cross {
                    [(r, r), (r, -r)]
                } else {
                    [(r * 1.2, 0.0), (0.0, r * 1.2)]
                };
                for (dx, dy) in arms {
                    area.draw(&PathElement::new(vec![px(-dx, -dy), px(dx, dy)], stroke))?;
                }
                return Ok(());
            }
            Marker::Square => {
                let d = r * 0.85;
                vec![(-d, -d), (d, -d), (d, d), (-d, d)]
            }
            Marker::TriangleUp => vec![(0.0, -r * 1.15), (-r, r * 0.75), (r, r * 0.75)],
            Marker::TriangleDown => vec![(0.0, r * 1.15), (-r, -r * 0.75), (r, -r * 0.75)],
            Marker::Diamond => {
                let d = r * 1.2;
                vec![(0.0, -d), (d, 0.0), (0.0, d), (-d, 0.0)]
            }
        };
        let mut ring: Vec<(i32, i32)> = corners.iter().map(|&(dx, dy)| px(dx, dy)).collect();
        area.draw(&Polygon::new(ring.clone(), inside))?;
        ring.push(ring[0]);
        area.draw(&PathElement::new(ring, outline))
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
        // A rust red of their own, apart from the half-edge's orange: the crates are read
        // beside the lab's structures of the same design.
        Family::RustCrate => ((240, 120, 150), (140, 10, 60)),
        Family::Outside => ((0, 0, 0), (90, 60, 40)),
    }
}

fn mix(a: (u8, u8, u8), b: (u8, u8, u8), t: f64) -> (u8, u8, u8) {
    let m = |x: u8, y: u8| (x as f64 + (y as f64 - x as f64) * t).round() as u8;
    (m(a.0, b.0), m(a.1, b.1), m(a.2, b.2))
}

/// The style of each structure, given in report order with its family: a ramp of the family's
/// hue over its members (one member: the middle of the ramp; outside structures start at
/// black), dashed outside the lab (the C++ baselines and the Rust crates), and a marker of
/// its own per position (seven shapes, then the same hollow), so that no two of up to
/// fourteen structures look alike.
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
                dashed: matches!(f, Family::Outside | Family::RustCrate),
                marker: Marker::ALL[i % Marker::ALL.len()],
                hollow: (i / Marker::ALL.len()) % 2 == 1,
            }
        })
        .collect()
}

/// One measured point: the median and, when known, the interval of the median.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Point {
    /// x (size).
    pub x: f64,
    /// y: the median.
    pub y: f64,
    /// The interval's low end.
    pub low: Option<f64>,
    /// The interval's high end.
    pub high: Option<f64>,
    /// Rounds of the median.
    pub rounds: usize,
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
pub(crate) fn value(y: f64) -> String {
    if y >= 100.0 {
        format!("{y:.0}")
    } else if y >= 10.0 {
        format!("{y:.1}")
    } else {
        format!("{y:.2}")
    }
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
    let labels = Labels {
        title,
        xlabel,
        ylabel,
        unit,
    };
    draw_loglog(&lay, &labels, ((x0, x1), (y0, y1)), &shown).unwrap_or_else(|e| {
        format!(
            "<p class=\"empty\">{}: the plot could not be drawn ({})</p>",
            esc(title),
            esc(&e.to_string())
        )
    })
}

/// A plot's words: its title, its axes' descriptions and the unit of its hover titles.
struct Labels<'a> {
    title: &'a str,
    xlabel: &'a str,
    ylabel: &'a str,
    unit: &'a str,
}

/// plotters' SVG backend writes a font's size divided by 1.24 (its text metric's em), so a
/// font asked for at `px × 1.24` comes out `px` pixels high (printed with the float's noise for
/// some sizes, `15.000000000000002`, which browsers read as 15).
pub(crate) fn font(px: f64) -> TextStyle<'static> {
    TextStyle::from(("sans-serif", px * 1.24).into_font()).color(&BLACK)
}

/// The style's colour, for plotters.
pub(crate) fn colour(style: &Style) -> RGBColor {
    let (r, g, b) = style.rgb;
    RGBColor(r, g, b)
}

/// The hover title of one point: structure, size, median, its interval, rounds.
fn hover_title(name: &str, p: &Point, unit: &str) -> String {
    let spread = match (p.low, p.high) {
        (Some(a), Some(b)) => format!(" (interval {} to {})", value(a), value(b)),
        _ => String::new(),
    };
    let reps = match p.rounds {
        0 => String::new(),
        1 => ", 1 round".into(),
        n => format!(", {n} rounds"),
    };
    format!(
        "{} at {}: median {} {}{spread}{reps}",
        esc(name),
        si(p.x),
        value(p.y),
        esc(unit)
    )
}

/// Draws the plot with plotters on `lay` and returns the SVG.
///
/// plotters writes no `<title>` and no `class`, so two small additions are made to its SVG
/// string, both at its ends and neither touching what plotters wrote in between: its opening
/// `<svg>` tag is replaced by one with `class="loglog"` (so the page and its tests can find the
/// plots), and before the closing tag go (1) the marked rectangles `class="plot-area"` (the
/// pixel range of plotters' own plotting area, drawn as the data's frame, widened by the
/// pixel to its left where plotters draws the y axis, so that the two lines do not stand side
/// by side) and `class="legend"` (the legend's border), and (2) one invisible circle per
/// point, over its marker, holding the point's hover `<title>` (`pointer-events="all"`, so it
/// catches the pointer unpainted).
fn draw_loglog(
    lay: &Layout,
    labels: &Labels,
    ((x0, x1), (y0, y1)): ((f64, f64), (f64, f64)),
    shown: &[(&Line, Vec<Point>)],
) -> Result<String, Box<dyn std::error::Error>> {
    let size = (lay.size.0.ceil() as u32, lay.size.1.ceil() as u32);
    let p = lay.plot;
    let mut svg = String::new();
    let mut marks = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE)?;
        root.draw(&Text::new(
            labels.title.to_string(),
            ((p.x + p.w / 2.0) as i32, 6),
            font(15.0).pos(Pos::new(HPos::Center, VPos::Top)),
        ))?;
        // The chart's region: the y labels fill everything left of the data area, the x
        // labels 40 px below it (6 px of the layout's 46 stay blank under the x axis's
        // description), so plotters' plotting area is `lay.plot`.
        let below = 40;
        let region = root
            .clone()
            .shrink((0, p.y as i32), ((p.x + p.w) as u32, p.h as u32 + below));
        let mut chart = ChartBuilder::on(&region)
            .y_label_area_size(p.x as u32)
            .x_label_area_size(below)
            .build_cartesian_2d(
                (x0..x1).log_scale().with_key_points(ticks(x0, x1)),
                (y0..y1).log_scale().with_key_points(ticks(y0, y1)),
            )?;
        chart
            .configure_mesh()
            .bold_line_style(RGBColor(238, 238, 238))
            .axis_style(RGBColor(153, 153, 153))
            .x_label_formatter(&|x| si(*x))
            .y_label_formatter(&|y| si(*y))
            .label_style(font(12.0))
            .axis_desc_style(font(13.0))
            .x_desc(labels.xlabel)
            .y_desc(labels.ylabel)
            .draw()?;
        for (line, pts) in shown {
            let stroke = colour(&line.style).stroke_width(2);
            let xy = pts.iter().map(|p| (p.x, p.y));
            if line.style.dashed {
                chart.draw_series(DashedLineSeries::new(xy, 7, 4, stroke))?;
            } else {
                chart.draw_series(LineSeries::new(xy, stroke))?;
            }
        }
        // The intervals under the markers, thin, in their line's colour.
        for (line, pts) in shown {
            for point in pts {
                if let (Some(lo), Some(hi)) = (point.low, point.high) {
                    let (lo, hi) = (lo.clamp(y0, y1), hi.clamp(y0, y1));
                    let bar = vec![(point.x, lo), (point.x, hi)];
                    chart.draw_series(LineSeries::new(bar, colour(&line.style).stroke_width(1)))?;
                }
            }
        }
        // Every marker after every line, so no line hides another line's points.
        for (line, pts) in shown {
            for point in pts {
                let at = chart.backend_coord(&(point.x, point.y));
                let st = line.style;
                st.marker.draw(&root, at, 3.6, colour(&st), st.hollow)?;
                let _ = write!(
                    marks,
                    r#"<circle cx="{}" cy="{}" r="6" fill="none" pointer-events="all"><title>{}</title></circle>"#,
                    at.0,
                    at.1,
                    hover_title(&line.name, point, labels.unit)
                );
            }
        }
        let l = lay.legend;
        for (i, (line, _)) in shown.iter().enumerate() {
            let y = (l.y + 4.0 + LEGEND_ROW * (i as f64 + 0.5)).round() as i32;
            let st = line.style;
            let stroke = colour(&st).stroke_width(2);
            let sample = vec![((l.x + 5.0) as i32, y), ((l.x + 27.0) as i32, y)];
            if st.dashed {
                root.draw(&DashedPathElement::new(sample, 5, 3, stroke))?;
            } else {
                root.draw(&PathElement::new(sample, stroke))?;
            }
            st.marker
                .draw(&root, ((l.x + 16.0) as i32, y), 3.3, colour(&st), st.hollow)?;
            root.draw(&Text::new(
                line.name.clone(),
                ((l.x + 31.0) as i32, y),
                font(11.0).pos(Pos::new(HPos::Left, VPos::Center)),
            ))?;
        }
        let (xs, ys) = chart.plotting_area().get_pixel_range();
        let _ = write!(
            marks,
            r##"<rect class="plot-area" x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#999"/><rect class="legend" x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}" fill="none" stroke="#ccc"/>"##,
            xs.start - 1,
            ys.start,
            xs.end - xs.start + 1,
            ys.end - ys.start,
            l.x,
            l.y,
            l.w,
            l.h
        );
        root.present()?;
    }
    finish(&svg, size, "loglog", &marks)
}

/// plotters' SVG `svg` of `size` pixels with its opening tag replaced by one with `class` (so
/// the page and its tests can find the chart) and `marks` (SVG plotters cannot write: classes,
/// `<title>`s) added last, on top of everything plotters drew.
pub(crate) fn finish(
    svg: &str,
    size: (u32, u32),
    class: &str,
    marks: &str,
) -> Result<String, Box<dyn std::error::Error>> {
    let body = svg
        .split_once('>')
        .map(|(_, rest)| rest)
        .and_then(|rest| rest.trim_end().strip_suffix("</svg>"))
        .ok_or("plotters wrote no <svg> element")?;
    let (w, h) = size;
    Ok(format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" class="{class}" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif">{body}{marks}</svg>"#
    ))
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

    /// Every `<text x=".." y="..">` of the drawing: its anchor and its (trimmed) words.
    fn texts(svg: &str) -> Vec<(f64, f64, String)> {
        svg.split("<text ")
            .skip(1)
            .filter_map(|t| {
                let end = t.find('>')?;
                let tag = format!(" {}", &t[..end]);
                let number = |key: &str| -> Option<f64> {
                    let at = tag.find(key)? + key.len();
                    tag[at..at + tag[at..].find('"')?].parse().ok()
                };
                let words = &t[end + 1..t.find("</text>")?];
                Some((number(" x=\"")?, number(" y=\"")?, words.trim().to_string()))
            })
            .collect()
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
                        low: Some(1.0),
                        high: Some(2.0),
                        rounds: 3,
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
            // The texts inside the legend box are the lines' names, in order, and the box is
            // wide enough for each at the assumed character width.
            let in_legend: Vec<(f64, String)> = texts(&svg)
                .into_iter()
                .filter(|&(x, y, _)| legend.contains(x, y))
                .map(|(x, _, t)| (x, t))
                .collect();
            let names: Vec<String> = (0..lines).map(|i| format!("{i:0>name_len$}")).collect();
            assert_eq!(
                in_legend.iter().map(|(_, t)| t).collect::<Vec<_>>(),
                names.iter().collect::<Vec<_>>()
            );
            assert!(in_legend
                .iter()
                .all(|(x, t)| x + t.chars().count() as f64 * CHAR_W <= legend.x + legend.w));
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
            // The legend's circle markers are outside it, one per circle-marker line (each
            // drawn as its inside, then its outline, at one place).
            let mut outside: Vec<&(f64, f64)> = circles
                .iter()
                .filter(|(x, y)| !area.contains(*x, *y))
                .collect();
            outside.dedup();
            assert!(inside > 0 && outside.len() <= lines, "{circles:?}");
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
    fn each_point_has_a_hover_title_with_its_interval() {
        let svg = plot(2, 3);
        assert_eq!(
            svg.matches("(interval 1.00 to 2.00), 3 rounds</title>")
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
