//! The 3D convex hulls: the lecture's three algorithms beside Qhull and CGAL, and the
//! quantities of the lecture's analysis, counted in the same runs.

use crate::format::esc;
use crate::measuring::phases::Phase;
use crate::measuring::timing::meter::MemoryMeter;
use crate::measuring::timing::turns::{take_turns, Answer, Run as Turn};
use crate::page::plot;
use crate::report::run::{ReportError, Run};
use crate::report::section::{Needs, Page, Section};
use crate::results::HullRow;
use crate::results::Results;
use crate::studies::hull::bench::hull_target_row;
use crate::studies::hull::bench::vertex_checksum;
use crate::targets::plan::{Cell, Turns, HULL_POINTS};
use std::fmt::Write;
use std::time::Instant;
use topolab_baselines::hulls::HullLibrary;
use topolab_structures::hull::{convex_hull, random_points, Algorithm, Shape};
use topolab_structures::Family;

/// The structure the hull section's algorithms build on: the hull section runs when
/// `--structures` names it.
pub const HULL_STRUCTURE: &str = "winged-edge";

fn hull(h: &mut String, r: &Results) {
    if r.hull.is_empty() {
        return;
    }
    h.push_str("<h2>3D convex hull on the winged-edge (the lecture on 3D convex hulls)</h2><div class=read><b>How to read it.</b> The lecture's three algorithms build the hull of random points as a winged-edge mesh: gift wrapping (O(n·h)), incremental (O(n²)), randomized incremental with a conflict graph (expected O(n log n)), next to Qhull and CGAL's <code>convex_hull_3</code> on the same points in the same run (below the table: how each is run). Every hull is timed warm: a warm-up run, then the median of the timed runs (<i>runs</i>: 3 below 100k points, 1 from 100k on or after a warm-up over a second); the clock runs around the call alone (for the lab's algorithms, building the winged-edge they return is in it, dropping it is not), and the lab's peak heap (next table) is counted in the warm-up run, never in a timed one. Points in a ball have few hull vertices; points on a sphere are all on the hull (h = n). Gift wrapping and the incremental algorithm run a size only while its predicted <i>Volume6</i> tests stay within the run's budget (2·10<sup>9</sup> by default: their n² shows on the sizes before), and the sphere stops at 100k points by default (every point is on its hull; <code>topolab report --full</code> goes to 1M, as the ball does): the run's notes say what was left out. The table compares the faces each algorithm created with the lecture's expected bound 6n − 20.</div><div class=plots>");
    let algos = [
        "gift",
        "incremental",
        "randomized",
        "qhull",
        "cgal-convex-hull-3",
    ];
    // The lecture's three algorithms build a winged-edge: that family's hue; Qhull and CGAL
    // are outside.
    let styles = plot::styles(&[
        Family::EdgeLists,
        Family::EdgeLists,
        Family::EdgeLists,
        Family::Outside,
        Family::Outside,
    ]);
    let mut shapes: Vec<&str> = r.hull.iter().map(|x| x.shape.as_str()).collect();
    shapes.dedup();
    for shape in &shapes {
        let series: Vec<plot::Line> = algos
            .iter()
            .enumerate()
            .map(|(i, a)| plot::Line {
                name: a.to_string(),
                style: styles[i],
                points: r
                    .hull
                    .iter()
                    .filter(|x| x.shape == *shape && x.algorithm == *a)
                    .map(|x| plot::Point {
                        x: x.n as f64,
                        y: x.seconds * 1e9 / x.n as f64,
                        low: None,
                        high: None,
                        rounds: 0,
                    })
                    .collect(),
            })
            .collect();
        h.push_str(&plot::loglog(
            &format!(
                "hull of points {}",
                if *shape == "sphere" {
                    "on a sphere"
                } else {
                    "in a ball"
                }
            ),
            "points",
            "ns per point",
            "ns per point",
            &series,
        ));
    }
    h.push_str("</div><table><tr><th class=l>points</th><th>n</th><th class=l>algorithm</th><th>seconds</th><th>runs</th><th>× Qhull</th><th>hull vertices</th><th>faces created</th><th>/ (6n − 20)</th></tr>");
    for x in &r.hull {
        let q = r
            .hull
            .iter()
            .find(|y| y.shape == x.shape && y.n == x.n && y.algorithm == "qhull")
            .map(|y| y.seconds);
        let _ = write!(h, "<tr><td class=l>{}</td><td>{}</td><td class=l>{}</td><td>{:.4}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>", x.shape, x.n, x.algorithm, x.seconds, x.timed_runs, q.map(|q| format!("{:.2}", x.seconds / q)).unwrap_or_default(), x.hull_vertices, x.faces_created.map(|c| c.to_string()).unwrap_or_default(), x.faces_created.map(|c| format!("{:.3}", c as f64 / (6.0 * x.n as f64 - 20.0))).unwrap_or_default());
    }
    h.push_str("</table>");
    if let Some(qhull) = r
        .qhull
        .as_ref()
        .filter(|_| r.hull.iter().any(|x| x.algorithm == "qhull"))
    {
        let _ = write!(h, "<div class=read><code>qhull</code>: {}. The clock is read inside the shim, around <code>qh_new_qhull</code> (which builds, merges and triangulates the hull) and the walk that collects the hull's vertex ids, as the lab's algorithms are timed around building their output; SciPy's output arrays, volume and area are not in it, nor is freeing the hull. The report stops unless Qhull's hull has the randomized algorithm's vertices (the same count and vertex checksum) and 2h − 4 triangles. The tests check this Qhull against SciPy's <code>ConvexHull</code> on seeded point sets (the same vertices, triangles and volume).</div>", esc(qhull));
    }
    if r.hull.iter().any(|x| x.algorithm == "cgal-convex-hull-3") {
        h.push_str("<div class=read><code>cgal-convex-hull-3</code>: CGAL's <code>convex_hull_3</code> (C++ quickhull with exact predicates, into a <code>Surface_mesh</code>) on the same points in the same run, timed the same way, the clock inside the shim around the library call alone; the report stops unless its hull has the randomized algorithm's vertex count.</div>");
    }
}

/// The quantities of the lecture's analysis of the hull algorithms, per run and fitted.
fn hull_analysis(h: &mut String, r: &Results) {
    use crate::studies::hull::bench::{bound, n_lg_n};
    let ours: Vec<_> = r
        .hull
        .iter()
        .filter(|x| x.volume6_tests.is_some())
        .collect();
    if ours.is_empty() {
        return;
    }
    h.push_str("<h3>The lecture's analysis, measured</h3><div class=read><b>How to read it.</b> What the lecture on 3D convex hulls counts to bound each algorithm, counted in the same runs as the table above. <i>Volume6</i>: orientation tests, the algorithms' unit of work; <i>/ bound</i> divides them by the algorithm's bound (gift wrapping n·h, incremental n², randomized n lg n): a ratio that stays level as n grows means the bound describes the work, a falling one that the bound is loose for this input (the incremental algorithm's n² is its worst case, reached on a sphere). <i>Σ|P(e)|</i>: the conflict-list work of the randomized algorithm, the sum of the merged lists P(e) = P(f1) ∪ P(f2) over all horizon edges, expected O(n lg n). <i>exact</i>: the tests the floating-point filter of the face's plane left to exact arithmetic (gift wrapping calls the adaptive predicate directly: 0). <i>B per point</i>: the peak heap the call allocated beyond its input, per point. The second table fits t ∝ n<sup>e</sup> to the time and to the work (Σ|P(e)| for the randomized algorithm, Volume6 tests otherwise) and compares the work's exponent with the bound's at the same n and h: green when it grows no faster.</div>");
    h.push_str("<table><tr><th class=l>points</th><th>n</th><th class=l>algorithm</th><th>hull vertices</th><th>µs per point</th><th>Volume6</th><th class=l>bound</th><th>Volume6 / bound</th><th>Σ|P(e)|</th><th>Σ|P(e)| / n lg n</th><th>exact</th><th>B per point</th></tr>");
    for x in &ours {
        let b = bound(&x.algorithm, x.n, x.hull_vertices);
        let tests = x.volume6_tests.unwrap_or(0);
        let _ = write!(
            h,
            "<tr><td class=l>{}</td><td>{}</td><td class=l>{}</td><td>{}</td><td>{:.2}</td><td>{}</td><td class=l>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            x.shape,
            x.n,
            x.algorithm,
            x.hull_vertices,
            x.seconds * 1e6 / x.n as f64,
            tests,
            b.map_or("", |b| b.0),
            b.map(|b| format!("{:.3}", tests as f64 / b.1)).unwrap_or_default(),
            x.conflict_work.map(|w| w.to_string()).unwrap_or_default(),
            x.conflict_work
                .map(|w| format!("{:.2}", w as f64 / n_lg_n(x.n)))
                .unwrap_or_default(),
            x.exact_tests.map(|e| e.to_string()).unwrap_or_default(),
            x.peak_bytes
                .map(|p| format!("{:.0}", p as f64 / x.n as f64))
                .unwrap_or_default(),
        );
    }
    h.push_str("</table>");
    if r.hull_fits.is_empty() {
        return;
    }
    h.push_str("<table><tr><th class=l>points</th><th class=l>algorithm</th><th>sizes</th><th>time exponent</th><th>work exponent</th><th class=l>bound</th><th>bound's exponent</th></tr>");
    for f in &r.hull_fits {
        let e = |x: Option<f64>| x.map(|x| format!("{x:.2}")).unwrap_or_default();
        let class = match f.within_bound {
            Some(true) => "ok",
            Some(false) => "bad",
            None => "l",
        };
        let _ = write!(
            h,
            "<tr><td class=l>{}</td><td class=l>{}</td><td>{}</td><td>{:.2}</td><td class={class}>{}</td><td class=l>{}</td><td>{}</td></tr>",
            f.shape,
            f.algorithm,
            f.sizes,
            f.time_exponent,
            e(f.conflict_exponent.or(f.tests_exponent)),
            f.bound.as_deref().unwrap_or(""),
            e(f.bound_exponent),
        );
    }
    h.push_str("</table>");
}

/// How far the hull benchmark goes: the largest n in a ball and on a sphere, and the
/// `Volume6` tests a slow algorithm's next size may be predicted to take
/// ([`crate::studies::hull::bench::run`]).
#[derive(Copy, Clone, Debug, PartialEq)]
struct HullSizes {
    ball: usize,
    sphere: usize,
    max_tests: f64,
}

impl HullSizes {
    /// The default: the ball to 1M, the sphere to 100k. On a sphere every point is on the hull
    /// (h = n); its 1M points took about 44 s alone (CGAL about 20 s, the randomized algorithm
    /// 12, Qhull 11) for the same n log n growth the sphere shows to 100k and the ball to 1M.
    /// The slow algorithms stop at [`MAX_TESTS`](crate::studies::hull::bench::MAX_TESTS). `--full` takes
    /// the sphere to 1M and lets the slow algorithms run to 1.5·10¹⁰ predicted tests (the
    /// incremental algorithm's 1M ball and 100k sphere, 53 s), `--quick` stays small.
    fn of(quick: bool, full: bool) -> Self {
        use crate::studies::hull::bench::MAX_TESTS;
        match (quick, full) {
            (true, _) => HullSizes {
                ball: 10_000,
                sphere: 1_000,
                max_tests: MAX_TESTS,
            },
            (false, false) => HullSizes {
                ball: 1_000_000,
                sphere: 100_000,
                max_tests: MAX_TESTS,
            },
            (false, true) => HullSizes {
                ball: 1_000_000,
                sphere: 1_000_000,
                max_tests: 1.5e10,
            },
        }
    }
}

/// The hull benchmark: points in a ball and on a sphere ([`HullSizes`]), each row's peak heap
/// measured by the process's counting allocator in its untimed warm-up run, then the outside
/// hulls on the same points (Qhull in-process, CGAL), timed the same way.
fn measure(
    sizes: HullSizes,
    meter: &dyn MemoryMeter,
    notes: &mut Vec<String>,
) -> Result<Vec<HullRow>, ReportError> {
    use crate::studies::hull::bench;
    use topolab_structures::hull::Shape;
    if !topolab_baselines::HAS_QHULL {
        notes.push(format!(
            "The hull section has no Qhull: {}.",
            topolab_baselines::QHULL_MISSING
        ));
    }
    let mut rows = Vec::new();
    for (shape, name, max) in [
        (Shape::Ball, "ball", sizes.ball),
        (Shape::Sphere, "sphere", sizes.sphere),
    ] {
        let sizes_here: Vec<usize> = [1_000, 10_000, 100_000, 1_000_000]
            .into_iter()
            .filter(|&n| n <= max)
            .collect();
        let run = bench::run(
            shape,
            name,
            &sizes_here,
            sizes.max_tests,
            Some(meter),
            |row| {
                eprintln!(
                    "topolab report: hull {} {} {}: {:.3} s",
                    row.shape, row.n, row.algorithm, row.seconds
                )
            },
        );
        rows.extend(run.map_err(|e| ReportError::Measurement(format!("hull benchmark: {e}")))?);
    }
    crate::studies::hull::outside::add_outside_hulls(&mut rows)
        .map_err(|e| ReportError::Measurement(format!("hull benchmark: {e}")))?;
    Ok(rows)
}

/// The hull's target ([`Cell::Hull`]): the lab's randomized algorithm and Qhull taking turns on
/// the same [`HULL_POINTS`] points in a ball, after a warm-up round, each run by the clock of
/// the table above (around the call alone; Qhull's inside its shim), when both ran that size in
/// the table (`rows`). Both must find the same hull vertices in every run.
fn in_turns(rows: &[HullRow]) -> Result<Option<Turns>, ReportError> {
    let qhull = HullLibrary::Qhull;
    let ran = |a: &str| hull_target_row(rows, a).is_some();
    if !ran("randomized") || !ran(qhull.name()) {
        return Ok(None);
    }
    eprintln!("topolab report: hull ball {HULL_POINTS}: randomized and qhull taking turns");
    let points = random_points(
        Shape::Ball,
        HULL_POINTS,
        crate::studies::hull::bench::POINTS_SEED,
    );
    let names = ["randomized", qhull.name()];
    let (cell, start) = (Cell::Hull, Instant::now());
    let run = |i: usize| -> Result<Turn, String> {
        let (seconds, ids) = if i == 0 {
            let start = Instant::now();
            let randomized = Algorithm::Randomized {
                seed: crate::studies::hull::bench::RANDOMIZED_SEED,
            };
            let hull = convex_hull(&points, randomized).map_err(|e| e.to_string())?;
            let seconds = start.elapsed().as_secs_f64();
            (seconds, hull.vertices().iter().map(|v| v.0).collect())
        } else {
            let hull = qhull.hull(&points)?;
            let ids = hull.vertex_ids.ok_or("Qhull returned no vertex ids")?;
            (hull.seconds, ids)
        };
        Ok(Turn {
            ns: seconds * 1e9 / HULL_POINTS as f64,
            answer: Answer::Sum(vertex_checksum(ids)),
        })
    };
    let ns = take_turns(cell.warm_up(), cell.rounds(), &names, run).map_err(|e| {
        ReportError::Measurement(format!(
            "the hull's target in turns: {e}\nThe report stops."
        ))
    })?;
    Ok(Some(Turns {
        cell,
        mesh: format!("ball-{HULL_POINTS}"),
        items: HULL_POINTS,
        structures: names.iter().map(|s| s.to_string()).collect(),
        ns_per_item: ns,
        warm_up: cell.warm_up(),
        seconds: start.elapsed().as_secs_f64(),
    }))
}

/// The 3D convex hull algorithms beside Qhull and CGAL.
pub struct Hull;

impl Section for Hull {
    fn name(&self) -> &'static str {
        "hull"
    }

    fn needs(&self) -> Needs {
        Needs {
            subject: Some(HULL_STRUCTURE),
            ..Needs::NOTHING
        }
    }

    fn phase(&self) -> Option<Phase> {
        Some(Phase::new("hull", "3D convex hulls"))
    }

    fn measure(&self, run: &mut Run) -> Result<(), ReportError> {
        let (req, r) = (run.request, &mut *run.results);
        r.hull = measure(HullSizes::of(req.quick, req.full), run.meter, &mut r.notes)?;
        r.hull_fits = crate::studies::hull::bench::fits(&r.hull);
        r.qhull = topolab_registry::qhull_description();
        r.targets.extend(in_turns(&r.hull)?);
        Ok(())
    }

    fn render(&self, h: &mut String, page: &Page) {
        hull(h, page.r);
        hull_analysis(h, page.r);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_hull_stops_the_sphere_at_100k_and_full_lifts_it() {
        let default = HullSizes::of(false, false);
        assert_eq!((default.ball, default.sphere), (1_000_000, 100_000));
        let full = HullSizes::of(false, true);
        assert_eq!((full.ball, full.sphere), (1_000_000, 1_000_000));
        assert!(full.max_tests > default.max_tests);
        let quick = HullSizes::of(true, false);
        assert!(quick.ball <= 10_000 && quick.sphere <= 1_000);
        // The incremental algorithm's next sizes, predicted from the tests counted: its 100k sphere and 1M ball run with --full only.
        use crate::studies::hull::bench::predicted_tests;
        let sphere = predicted_tests(Some((1_000, 995_004)), (10_000, 99_950_004), 100_000);
        let ball = predicted_tests(Some((10_000, 5_830_028)), (100_000, 185_455_794), 1_000_000);
        for next in [sphere, ball] {
            assert!(next > default.max_tests && next <= full.max_tests, "{next}");
        }
        // Gift wrapping's 100k ball runs by default, its 1M ball not even with --full.
        let gift = predicted_tests(Some((1_000, 525_737)), (10_000, 17_299_135), 100_000);
        assert!(gift <= default.max_tests, "{gift}");
        let gift = predicted_tests(
            Some((10_000, 17_299_135)),
            (100_000, 550_997_245),
            1_000_000,
        );
        assert!(gift > full.max_tests, "{gift}");
    }

    #[test]
    fn the_hull_target_takes_turns_only_where_the_table_ran_both_at_1m_in_a_ball() {
        let row = |shape: &str, n: usize, algorithm: &str| HullRow {
            shape: shape.into(),
            n,
            algorithm: algorithm.into(),
            ..HullRow::default()
        };
        // No Qhull at 1M, or 1M on a sphere only: nothing to time (and nothing built).
        for rows in [
            vec![row("ball", HULL_POINTS, "randomized")],
            vec![
                row("ball", 10_000, "randomized"),
                row("ball", 10_000, "qhull"),
            ],
            vec![
                row("sphere", HULL_POINTS, "randomized"),
                row("sphere", HULL_POINTS, "qhull"),
            ],
        ] {
            assert!(matches!(in_turns(&rows), Ok(None)), "{rows:?}");
        }
        // The plan of the structures' turns leaves the hull's target to this section.
        let plan = crate::targets::plan::plan(|_, _| true);
        assert!(plan.iter().all(|g| !g.cells.contains(&Cell::Hull)));
        let hull = crate::targets::plan::TARGETS
            .iter()
            .find(|t| t.cell == Cell::Hull)
            .expect("the guide's hull target");
        assert_eq!((hull.structure, hull.goal), ("randomized", 1.5));
    }
}
