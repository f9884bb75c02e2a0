//! `topolab report`: measures every structure on the size sweep and writes `results.json` and
//! a self-contained `index.html`. [`report_with`] is the same report with structures from
//! outside the lab beside the lab's (see [`crate::extend`]).

use crate::extend::Lab;
use crate::input::Failure;
use crate::registry::StructureVisitor;
use indicatif::{ProgressBar, ProgressStyle};
use std::path::{Path, PathBuf};
use std::time::Duration;
use topolab_harness::kernels::sample_queries;
use topolab_harness::limit::{self, MeshCounts};
use topolab_harness::measure::{cross_check, measure_structure, Estimator, MeshCase, Plan};
use topolab_harness::phases::Phase;
use topolab_harness::report::clock::{self, Clock};
use topolab_harness::report::run::{Listed, MeshFamily, ReportError, Request, Run};
use topolab_harness::report::section::{Real, Refined};
use topolab_harness::report::sections::libigl::LIBIGL;
use topolab_harness::report::sections::real_at_scale::FAMILY;
use topolab_harness::report::selection::Selection;
use topolab_harness::report::{refined, repair};
use topolab_harness::results::{
    CostRow, Measurement, MeshInfo, Results, Settings, StructureInfo, Teaching, FORMAT_VERSION,
};
use topolab_harness::{fit, html, machine, probe, svg};
use topolab_structures::registry::{duplicate_name, names, Structures};
use topolab_structures::{meshes, MeshTopology, Operator, PolygonSoup};

/// Options of `topolab report`.
#[derive(clap::Args, Debug, Clone)]
pub struct ReportArgs {
    /// A smaller, faster run (three sizes up to 16k triangles, short budgets): under 2 minutes.
    #[arg(long)]
    pub quick: bool,
    /// The full measurement, beyond the default's 15-minute budget: the hull on a sphere up to
    /// 1M points and the slow hull algorithms' larger sizes, the 3.3M refined armadillo
    /// measured like the 1.2M bunny, and five runs of the changing workloads on the 1M torus.
    #[arg(long, conflicts_with = "quick")]
    pub full: bool,
    /// Triangle counts of the size sweep, comma separated, each from 1 to 2^30, measured smallest
    /// first (default 1000,4000,16000,64000,256000,1000000).
    #[arg(long, value_delimiter = ',')]
    pub sizes: Option<Vec<usize>>,
    /// Structures to measure, comma separated (default: all; see `topolab list`). Given, the
    /// libigl section runs only when it names `libigl`, the hull section only when it names
    /// `winged-edge` (the structure the hull algorithms build).
    #[arg(long, value_delimiter = ',')]
    pub structures: Option<Vec<String>>,
    /// Sections of the page to measure and show, comma separated (default: all): chooser,
    /// table-4-1, plots, sweeps, workloads, memory, construction, orderings, real-meshes,
    /// real-at-scale, libigl, hull, changing, decimate, teaching, meshes, targets. Only what
    /// they are drawn from is measured.
    #[arg(long, value_delimiter = ',', value_parser = super::report_sections::section)]
    pub sections: Option<Vec<String>>,
    /// Mesh families, comma separated: `torus` (closed), `grid` (open, with boundary), `real`
    /// (the meshes `make data` fetched into bench-data/cache/, when present), `refined` (two of
    /// them refined by Loop subdivision to 1.2M and 3.3M triangles, measured like the tori).
    #[arg(long, value_delimiter = ',', default_value = "torus,grid,real,refined")]
    pub meshes: Vec<String>,
    /// Output folder.
    #[arg(long, default_value = "reports/latest")]
    pub out: PathBuf,
    /// Size of the memory probe's arrays, MiB, from 1 to 4096 (default 256, 64 with --quick).
    #[arg(long, hide = true, value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(1..=4096))]
    pub probe_mb: Option<usize>,
}

struct Measure<'a> {
    case: &'a MeshCase<'a>,
    plan: &'a Plan,
    est: &'a mut Estimator,
    out: &'a mut Vec<Measurement>,
}

impl StructureVisitor for Measure<'_> {
    type Output = Result<(), String>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        measure_structure::<M>(self.case, self.plan, &crate::ALLOCATOR, self.est, self.out)
    }
}

struct Describe;

impl StructureVisitor for Describe {
    type Output = (StructureInfo, Teaching);
    fn visit<M: MeshTopology>(self) -> Self::Output {
        let info = StructureInfo {
            name: M::NAME.into(),
            family: M::FAMILY,
            editable: crate::registry::is_editable(M::NAME),
            capabilities: M::capabilities(),
            costs: Operator::ALL
                .iter()
                .map(|&op| CostRow {
                    operator: op,
                    cost: M::cost(op),
                    expected_exponent: M::cost(op).expected_exponent(),
                    access: M::access(op),
                })
                .collect(),
        };
        let mut text = String::new();
        let soup = if M::capabilities().grids_only {
            meshes::grid(2, 2, true)
        } else {
            meshes::open_tetrahedron()
        };
        match M::from_soup(&soup) {
            Ok(m) => m
                .explain(&mut text)
                .expect("writing to a String cannot fail"),
            Err(e) => text = format!("cannot store the open tetrahedron: {e}"),
        }
        (
            info,
            Teaching {
                structure: M::NAME.into(),
                text,
            },
        )
    }
}

/// Runs the report; returns a summary line or a failure (exit 1 on a checksum mismatch).
pub fn report(args: &ReportArgs, command: String) -> Result<String, Failure> {
    report_with::<()>(args, command)
}

/// The structure called `name` among the lab's and the list `X`'s.
fn visit<X: Structures, V: StructureVisitor>(name: &str, visitor: V) -> Option<V::Output> {
    <(Lab, X)>::visit(name, visitor).ok()
}

/// [`report`] with the structures of the list `X` (structures outside the lab) measured beside
/// the lab's, after them in every table. A name of `X` that is already taken is a usage error.
pub fn report_with<X: Structures>(args: &ReportArgs, command: String) -> Result<String, Failure> {
    let all = names::<(Lab, X)>();
    if let Some(name) = duplicate_name(&all) {
        return Err(Failure::usage(format!(
            "two structures are called {name:?}: a structure added to the report needs a name \
             of its own (see `topolab list`)"
        )));
    }
    let quick = args.quick;
    let mut sizes = args.sizes.clone().unwrap_or_else(|| {
        if quick {
            vec![1_000, 4_000, 16_000]
        } else {
            vec![1_000, 4_000, 16_000, 64_000, 256_000, 1_000_000]
        }
    });
    // Smallest first, each once: the skip-by-estimate extrapolates from the sizes before.
    sizes.sort_unstable();
    sizes.dedup();
    let names: Vec<String> = match &args.structures {
        Some(list) => {
            let mut names: Vec<String> = Vec::with_capacity(list.len());
            for n in list.iter().filter(|n| *n != LIBIGL) {
                if !all.contains(&n.as_str()) {
                    return Err(crate::input::unknown_structure(n));
                }
                if !names.contains(n) {
                    names.push(n.clone());
                }
            }
            names
        }
        None => all.iter().map(|s| s.to_string()).collect(),
    };
    let mut families: Vec<&str> = Vec::with_capacity(args.meshes.len());
    for f in &args.meshes {
        if !["torus", "grid", "real", FAMILY].contains(&f.as_str()) {
            return Err(Failure::usage(format!(
                "unknown mesh family {f:?}; known: torus, grid, real, refined"
            )));
        }
        if !families.contains(&f.as_str()) {
            families.push(f);
        }
    }
    let plan = Plan {
        cell_budget: Duration::from_millis(if quick { 30 } else { 100 }),
        cell_max: Duration::from_millis(if quick { 150 } else { 300 }),
        min_reps: 3,
        max_reps: if args.full {
            clock::FULL_MAX_REPS
        } else {
            clock::MAX_REPS
        },
        light: false,
    };
    let samples = if quick { 64 } else { 128 };
    // The same glibc policy for every structure, C++ baselines included: freed memory stays
    // with the process, so warm builds reuse it whatever the run built before.
    if !crate::alloc::keep_freed_memory() {
        eprintln!("topolab report: this allocator keeps its own policy (not glibc): warm builds may still fault in fresh pages");
    }
    let probe_mb = args.probe_mb.unwrap_or(if quick { 64 } else { 256 });
    // Refused here, before anything is measured: sizes past u32 ids, more memory than there
    // is, an output folder that cannot be written (it used to fail after the whole run).
    let generated: Vec<&str> = families
        .iter()
        .copied()
        .filter(|f| ["torus", "grid"].contains(f))
        .collect();
    crate::limits::admit_report(&sizes, &generated, &names, probe_mb)?;
    crate::output::check_folder(&args.out, &["results.json", "index.html", "FINDINGS.md"])?;
    eprintln!("topolab report: probing the machine's memory ({probe_mb} MiB)...");
    let mut clock = Clock::start(cpu_now);
    let probe = probe::measure(probe_mb, probe_mb);
    clock.lap(Phase::PROBE, None);
    let mut notes = Vec::new();
    let selection = Selection::new(
        args.sections.as_deref(),
        args.structures.as_deref(),
        &mut notes,
    );
    let mut results = Results {
        format_version: FORMAT_VERSION,
        baselines: Vec::new(),
        machine: machine::facts(
            crate::OPENMESH_BUILD
                .map(str::to_string)
                .unwrap_or_else(|| format!("not in this build: {}", crate::OPENMESH_MISSING))
                .as_str(),
        ),
        probe,
        settings: Settings {
            quick,
            sizes: sizes.clone(),
            samples,
            cell_budget_s: plan.cell_budget.as_secs_f64(),
            cell_max_s: plan.cell_max.as_secs_f64(),
            command,
            sections: selection.names(),
        },
        structures: Vec::new(),
        meshes: Vec::new(),
        measurements: Vec::new(),
        fits: Vec::new(),
        libigl: Vec::new(),
        hull: Vec::new(),
        hull_fits: Vec::new(),
        qhull: None,
        changing: Vec::new(),
        targets: Vec::new(),
        decimate: Vec::new(),
        teaching: Vec::new(),
        reads: Vec::new(),
        notes,
        phases: Vec::new(),
    };
    crate::registry::note_absent(&mut results.notes);
    results.notes.extend(clock::budget_notes(quick, args.full));
    for n in &names {
        let (info, teach) = visit::<X, _>(n, Describe).expect("checked above");
        results.structures.push(info);
        results.teaching.push(teach);
    }
    let mut cases: Vec<(String, String, PolygonSoup)> = Vec::new();
    for size in sizes.iter().filter(|_| selection.generated()) {
        for fam in &generated {
            let spec = format!("{fam}:{size}");
            let soup = meshes::from_spec(&spec)
                .map_err(|e| Failure::usage(format!("cannot generate the mesh {spec}: {e}")))?;
            cases.push((format!("{fam}-{}", short(*size)), fam.to_string(), soup));
        }
    }
    let mut repaired = std::collections::HashMap::new();
    if families.contains(&"real") && selection.needs.real != Real::None {
        for (name, soup) in real_meshes(&mut results.notes) {
            let (soup, log) = repair::measurable(&name, soup, &mut results.notes);
            repaired.extend(log.map(|log| (name.clone(), log)));
            cases.push((name, "real".into(), soup));
        }
    }
    if families.contains(&FAMILY) && selection.needs.refined != Refined::None {
        let list: &[refined::Refined] = if quick {
            &refined::QUICK
        } else {
            &refined::FULL
        };
        // A refined mesh is admitted as a torus of as many triangles.
        let admit = |faces: usize| {
            crate::limits::admit_report(&[faces], &["torus"], &names, 0)
                .map_err(|f| ReportError::Usage(f.message))
        };
        let made = refined::refined_meshes(list, &admit, &mut results.notes).map_err(failure)?;
        for (name, soup) in made {
            cases.push((name, FAMILY.into(), soup));
        }
    }
    clock.lap(Phase::MESHES, None);
    let measured = cases.iter().filter(|c| selection.measures(&c.1)).count();
    let bar = ProgressBar::new((measured * names.len()) as u64);
    bar.set_style(
        ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {pos}/{len} {msg}")
            .expect("valid template")
            .progress_chars("=> "),
    );
    let mut est = Estimator::default();
    // Real meshes appear in one table (construction and the 1-ring sweep): measure only those.
    let light = Plan {
        light: true,
        ..plan
    };
    for (i, (name, fam, soup)) in cases.iter().enumerate() {
        let light_here = selection.light(fam) || (!args.full && refined::light(name));
        let plan = if light_here { &light } else { &plan };
        let queries = sample_queries(soup, samples, 2026);
        let case = MeshCase {
            name,
            family: fam,
            soup,
            queries: &queries,
        };
        if bar.is_hidden() {
            eprintln!(
                "topolab report: mesh {}/{}: {name} ({} faces)",
                i + 1,
                cases.len(),
                soup.num_faces()
            );
        }
        for s in names.iter().filter(|_| selection.measures(fam)) {
            bar.set_message(format!("{name}: {s}"));
            visit::<X, _>(
                s,
                Measure {
                    case: &case,
                    plan,
                    est: &mut est,
                    out: &mut results.measurements,
                },
            )
            .expect("checked above")
            .map_err(|e| Failure {
                message: e,
                code: 1,
            })?;
            bar.inc(1);
        }
        cross_check(&results.measurements, name).map_err(|e| Failure {
            message: format!("{e}\nThe report stops: two structures disagree."),
            code: 1,
        })?;
        results.meshes.push(MeshInfo {
            name: name.clone(),
            family: fam.clone(),
            vertices: soup.num_vertices(),
            faces: soup.num_faces(),
            triangles: soup.num_faces(),
            thumbnail_svg: svg::thumbnail(soup, 140.0),
            counts: MeshCounts::of(soup),
            repaired: repaired.remove(name),
        });
        bar.suspend(|| clock.lap(Phase::MEASURE, Some(name)));
    }
    bar.finish_and_clear();
    results.fits = fit::fit_all(&results.measurements, &results.structures);
    limit::annotate(&mut results);
    clock.lap(Phase::FITS, None);
    let request = Request {
        quick,
        full: args.full,
        sizes: sizes.clone(),
        names: names.clone(),
        structures: args.structures.clone(),
        added: topolab_structures::registry::names::<X>()
            .into_iter()
            .map(str::to_string)
            .collect(),
        sections: args.sections.clone(),
        meshes: families
            .iter()
            .map(|f| MeshFamily::from_name(f))
            .collect::<Result<_, _>>()
            .map_err(failure)?,
        out: args.out.clone(),
        probe_mb,
        command: results.settings.command.clone(),
    };
    let listed = Listed::<(Lab, X)>::new();
    let mut run = Run {
        request: &request,
        cases: &cases,
        plan: &plan,
        results: &mut results,
        structures: &listed,
        meter: &crate::ALLOCATOR,
        libigl_version: None,
    };
    // Each shown section's own measurement, in page order, timed as its phase (after the fits:
    // the Targets hold sweeps to their limits).
    for section in &selection.sections {
        let Some(phase) = section.phase() else {
            continue;
        };
        let results = &mut *run.results;
        match section.name() {
            "hull" => {
                results.hull = hull(HullSizes::of(quick, args.full), &mut results.notes)?;
                results.hull_fits = topolab_harness::hull::bench::fits(&results.hull);
                results.qhull = crate::registry::qhull_description();
            }
            "changing" => {
                results.changing = super::report_changing::measure(
                    &cases,
                    &names,
                    quick,
                    args.full,
                    &mut results.notes,
                )?
            }
            "decimate" => {
                results.decimate =
                    super::report_decimate::measure(&cases, &names, quick, &mut results.notes)?
            }
            "targets" => {
                results.targets = super::report_targets::measure::<X>(
                    &cases,
                    &names,
                    &results.measurements,
                    &results.probe,
                    &mut results.notes,
                )?
            }
            _ => section.measure(&mut run).map_err(failure)?,
        }
        clock.lap(phase, None);
    }
    let libigl_version = run.libigl_version;
    let measured: Vec<&str> = names.iter().map(String::as_str).collect();
    results.baselines = crate::baselines::runs(crate::baselines::Used {
        structures: &measured,
        hull: !results.hull.is_empty(),
        decimate: !results.decimate.is_empty(),
        libigl: libigl_version.as_deref(),
    });
    let skipped = results
        .measurements
        .iter()
        .filter(|m| m.status == topolab_harness::results::Status::Skipped)
        .count();
    if skipped > 0 {
        results.notes.push(format!(
            "{skipped} cells were skipped because their estimated run exceeded {:.1} s; the table shows the estimate (from the smaller sizes, or, at a family's first size, from the time per query of a timed sample of its queries).",
            plan.cell_max.as_secs_f64()
        ));
    }
    write(&args.out, &mut results, clock)?;
    Ok(format!(
        "wrote {} measurements of {} structures on {} meshes to {}\n",
        results.measurements.len(),
        names.len(),
        cases.len(),
        args.out.join("index.html").display()
    ))
}

/// (process, children) CPU seconds; 0 where `getrusage` is unavailable (the table then shows
/// zero CPU rather than failing the report).
fn cpu_now() -> (f64, f64) {
    use crate::alloc::{cpu_seconds, Who};
    (
        cpu_seconds(Who::Process).unwrap_or(0.0),
        cpu_seconds(Who::Children).unwrap_or(0.0),
    )
}

/// The CLI's failure of a report's error: exit 2 for a request that cannot run, 1 for a
/// measurement that failed, 2 for a report that cannot be written.
fn failure(e: ReportError) -> Failure {
    let code = match e {
        ReportError::Measurement(_) => 1,
        ReportError::Usage(_) | ReportError::Output(_) => 2,
    };
    Failure {
        message: e.message().to_string(),
        code,
    }
}

fn short(n: usize) -> String {
    if n >= 1_000_000 && n.is_multiple_of(1_000_000) {
        format!("{}M", n / 1_000_000)
    } else if n >= 1000 && n.is_multiple_of(1000) {
        format!("{}k", n / 1000)
    } else {
        n.to_string()
    }
}

/// How far the hull benchmark goes: the largest n in a ball and on a sphere, and the
/// `Volume6` tests a slow algorithm's next size may be predicted to take
/// ([`topolab_harness::hull::bench::run`]).
#[derive(Copy, Clone, Debug, PartialEq)]
struct HullSizes {
    ball: usize,
    sphere: usize,
    max_tests: f64,
}

impl HullSizes {
    /// The default: the ball to 1M, the sphere to 100k. On a sphere every point is on the hull
    /// (h = n); its 1M points took 44 s alone (2026-12-01: CGAL 20 s, the randomized algorithm
    /// 12, Qhull through SciPy 11) for the same n log n growth the sphere shows to 100k and the ball to 1M.
    /// The slow algorithms stop at [`topolab_harness::hull::bench::MAX_TESTS`]. `--full` takes
    /// the sphere to 1M and lets the slow algorithms run to 1.5·10¹⁰ predicted tests (the
    /// incremental algorithm's 1M ball and 100k sphere, 53 s), `--quick` stays small.
    fn of(quick: bool, full: bool) -> Self {
        use topolab_harness::hull::bench::MAX_TESTS;
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
fn hull(
    sizes: HullSizes,
    notes: &mut Vec<String>,
) -> Result<Vec<topolab_harness::hull::bench::HullRow>, Failure> {
    use topolab_harness::hull::bench;
    use topolab_structures::hull::Shape;
    if !crate::HAS_QHULL {
        notes.push(format!(
            "The hull section has no Qhull: {}.",
            crate::QHULL_MISSING
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
            Some(&crate::ALLOCATOR),
            |row| {
                eprintln!(
                    "topolab report: hull {} {} {}: {:.3} s",
                    row.shape, row.n, row.algorithm, row.seconds
                )
            },
        );
        rows.extend(run.map_err(|e| Failure {
            message: format!("hull benchmark: {e}"),
            code: 1,
        })?);
    }
    crate::registry::add_outside_hulls(&mut rows).map_err(|e| Failure {
        message: format!("hull benchmark: {e}"),
        code: 1,
    })?;
    Ok(rows)
}

/// The meshes `make data` fetched: every mesh file in `bench-data/cache/` up to 64 MB,
/// smallest first. Unreadable ones are skipped with a note.
fn real_meshes(notes: &mut Vec<String>) -> Vec<(String, PolygonSoup)> {
    let dir = Path::new("bench-data/cache");
    let mut files: Vec<(u64, PathBuf)> = std::fs::read_dir(dir)
        .map(|d| {
            d.filter_map(|e| e.ok())
                .map(|e| e.path())
                .filter(|p| topolab_structures::io::format_of(p).is_ok())
                .filter_map(|p| std::fs::metadata(&p).ok().map(|m| (m.len(), p)))
                .collect()
        })
        .unwrap_or_default();
    if files.is_empty() {
        notes.push("No real meshes: bench-data/cache/ is empty (run `make data`).".into());
    }
    files.sort();
    let mut out = Vec::new();
    for (bytes, path) in files {
        let name = path
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or("mesh")
            .to_string();
        if bytes > 64 << 20 {
            notes.push(format!(
                "{}: skipped, {} MB is larger than the report reads",
                path.display(),
                bytes >> 20
            ));
            continue;
        }
        match topolab_structures::io::read(&path) {
            Ok(soup) => out.push((name, soup)),
            Err(e) => notes.push(format!("{}: not measured: {e}", path.display())),
        }
    }
    out
}

/// Writes `results.json`, `index.html` and `FINDINGS.md`, with the sections' times of `clock` and the time of
/// rendering the page itself (its row is put into the rendered page's table afterwards).
fn write(out: &Path, results: &mut Results, mut clock: Clock) -> Result<(), Failure> {
    use std::io::Write as _;
    std::fs::create_dir_all(out).map_err(|e| Failure {
        message: format!("cannot write the report to {}: {e}", out.display()),
        code: 2,
    })?;
    results.phases = clock.times().to_vec();
    let mut without = String::new();
    topolab_harness::phases::render(&mut without, &results.phases);
    let page = html::render(results);
    clock.lap(Phase::WRITING, None);
    results.phases = clock.times().to_vec();
    let mut with = String::new();
    topolab_harness::phases::render(&mut with, &results.phases);
    let page = page.replacen(&without, &with, 1);
    let json = serde_json::to_string_pretty(results).expect("serialisable");
    crate::output::write_file(&out.join("results.json"), |w| w.write_all(json.as_bytes()))?;
    crate::output::write_file(&out.join("index.html"), |w| w.write_all(page.as_bytes()))?;
    let findings = topolab_harness::findings::markdown(results);
    crate::output::write_file(&out.join("FINDINGS.md"), |w| {
        w.write_all(findings.as_bytes())
    })?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser as _;

    fn args(line: &[&str]) -> Result<ReportArgs, clap::Error> {
        crate::cli::Cli::try_parse_from(line).map(|cli| match cli.command {
            crate::cli::Command::Report(args) => args,
            _ => panic!("not a report"),
        })
    }

    #[test]
    fn the_default_hull_stops_the_sphere_at_100k_and_full_lifts_it() {
        let default = HullSizes::of(false, false);
        assert_eq!((default.ball, default.sphere), (1_000_000, 100_000));
        let full = HullSizes::of(false, true);
        assert_eq!((full.ball, full.sphere), (1_000_000, 1_000_000));
        assert!(full.max_tests > default.max_tests);
        let quick = HullSizes::of(true, false);
        assert!(quick.ball <= 10_000 && quick.sphere <= 1_000);
        // The incremental algorithm's next sizes, predicted from the tests counted on
        // 2026-12-01: its 100k sphere and 1M ball run with --full only.
        use topolab_harness::hull::bench::predicted_tests;
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
    fn full_is_an_option_of_its_own_and_not_with_quick() {
        let full = args(&["topolab", "report", "--full"]).expect("--full parses");
        assert!(full.full && !full.quick);
        assert!(!args(&["topolab", "report"]).expect("parses").full);
        let both = args(&["topolab", "report", "--quick", "--full"]).map(|_| ());
        assert_eq!(
            both.expect_err("conflict").kind(),
            clap::error::ErrorKind::ArgumentConflict
        );
    }
}
