//! `topolab report`: measures every structure on the size sweep and writes `results.json` and
//! a self-contained `index.html`.

use crate::cli::Failure;
use crate::registry::{self, StructureVisitor};
use indicatif::{ProgressBar, ProgressStyle};
use std::path::{Path, PathBuf};
use std::time::Duration;
use topolab_harness::kernels::sample_queries;
use topolab_harness::measure::{
    cross_check, measure_structure, Estimator, MemoryMeter, MeshCase, Plan,
};
use topolab_harness::results::{
    CostRow, Measurement, MeshInfo, Results, Settings, StructureInfo, Teaching,
};
use topolab_harness::{fit, html, machine, probe, svg};
use topolab_structures::{meshes, MeshTopology, Operator, PolygonSoup};

/// Options of `topolab report`.
#[derive(clap::Args, Debug, Clone)]
pub struct ReportArgs {
    /// A smaller, faster run (three sizes up to 16k triangles, short budgets): under 2 minutes.
    #[arg(long)]
    pub quick: bool,
    /// Triangle counts of the size sweep, comma separated (default 1000,4000,16000,64000,256000,1000000).
    #[arg(long, value_delimiter = ',')]
    pub sizes: Option<Vec<usize>>,
    /// Structures to measure, comma separated (default: all; see `topolab list`).
    #[arg(long, value_delimiter = ',')]
    pub structures: Option<Vec<String>>,
    /// Mesh families, comma separated: `torus` (closed), `grid` (open, with boundary).
    #[arg(long, value_delimiter = ',', default_value = "torus,grid")]
    pub meshes: Vec<String>,
    /// Output folder.
    #[arg(long, default_value = "reports/latest")]
    pub out: PathBuf,
    /// Size of the memory probe's arrays, MiB (default 256, 64 with --quick).
    #[arg(long, hide = true)]
    pub probe_mb: Option<usize>,
}

/// The process's allocator as the harness's memory meter.
struct Allocator;

impl MemoryMeter for Allocator {
    fn current(&self) -> usize {
        crate::ALLOCATOR.current_usage()
    }
    fn peak(&self) -> usize {
        crate::ALLOCATOR.peak_usage()
    }
    fn reset_peak(&self) {
        crate::ALLOCATOR.reset_peak_usage()
    }
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
        measure_structure::<M>(self.case, self.plan, &Allocator, self.est, self.out)
    }
}

struct Describe;

impl StructureVisitor for Describe {
    type Output = (StructureInfo, Teaching);
    fn visit<M: MeshTopology>(self) -> Self::Output {
        let info = StructureInfo {
            name: M::NAME.into(),
            capabilities: M::capabilities(),
            costs: Operator::ALL
                .iter()
                .map(|&op| CostRow {
                    operator: op,
                    cost: M::cost(op).notation().into(),
                    expected_exponent: M::cost(op).expected_exponent(),
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
    let quick = args.quick;
    let sizes = args.sizes.clone().unwrap_or_else(|| {
        if quick {
            vec![1_000, 4_000, 16_000]
        } else {
            vec![1_000, 4_000, 16_000, 64_000, 256_000, 1_000_000]
        }
    });
    let names: Vec<String> = match &args.structures {
        Some(list) => {
            for n in list {
                if !registry::NAMES.contains(&n.as_str()) {
                    return Err(Failure::usage(format!(
                        "unknown structure {n:?}; known: {}",
                        registry::NAMES.join(", ")
                    )));
                }
            }
            list.clone()
        }
        None => registry::NAMES.iter().map(|s| s.to_string()).collect(),
    };
    for f in &args.meshes {
        if f != "torus" && f != "grid" {
            return Err(Failure::usage(format!(
                "unknown mesh family {f:?}; known: torus, grid"
            )));
        }
    }
    let plan = Plan {
        cell_budget: Duration::from_millis(if quick { 30 } else { 250 }),
        cell_max: Duration::from_millis(if quick { 150 } else { 2_000 }),
        min_reps: 3,
        max_reps: 25,
    };
    let samples = if quick { 64 } else { 256 };
    let probe_mb = args.probe_mb.unwrap_or(if quick { 64 } else { 256 });
    eprintln!("topolab report: probing the machine's memory ({probe_mb} MiB)...");
    let probe = probe::measure(probe_mb, probe_mb);
    let mut results = Results {
        machine: machine::facts(),
        probe,
        settings: Settings {
            quick,
            sizes: sizes.clone(),
            samples,
            cell_budget_s: plan.cell_budget.as_secs_f64(),
            cell_max_s: plan.cell_max.as_secs_f64(),
            command,
        },
        structures: Vec::new(),
        meshes: Vec::new(),
        measurements: Vec::new(),
        fits: Vec::new(),
        libigl: Vec::new(),
        teaching: Vec::new(),
        notes: Vec::new(),
    };
    for n in &names {
        let (info, teach) = registry::visit(n, Describe).expect("checked above");
        results.structures.push(info);
        results.teaching.push(teach);
    }
    let mut cases: Vec<(String, String, PolygonSoup)> = Vec::new();
    for size in &sizes {
        for fam in &args.meshes {
            let soup = meshes::from_spec(&format!("{fam}:{size}")).expect("known family");
            cases.push((format!("{fam}-{}", short(*size)), fam.clone(), soup));
        }
    }
    let bar = ProgressBar::new((cases.len() * names.len()) as u64);
    bar.set_style(
        ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {pos}/{len} {msg}")
            .expect("valid template")
            .progress_chars("=> "),
    );
    let mut est = Estimator::default();
    for (i, (name, fam, soup)) in cases.iter().enumerate() {
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
        for s in &names {
            bar.set_message(format!("{name}: {s}"));
            registry::visit(
                s,
                Measure {
                    case: &case,
                    plan: &plan,
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
        });
    }
    bar.finish_and_clear();
    results.fits = fit::fit_all(&results.measurements, &results.structures);
    let skipped = results
        .measurements
        .iter()
        .filter(|m| m.status == topolab_harness::results::Status::Skipped)
        .count();
    if skipped > 0 {
        results.notes.push(format!(
            "{skipped} cells were skipped because their estimated run exceeded {:.1} s; the table shows the estimate from smaller sizes.",
            plan.cell_max.as_secs_f64()
        ));
    }
    write(&args.out, &results)?;
    Ok(format!(
        "wrote {} measurements of {} structures on {} meshes to {}\n",
        results.measurements.len(),
        names.len(),
        cases.len(),
        args.out.join("index.html").display()
    ))
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

fn write(out: &Path, results: &Results) -> Result<(), Failure> {
    let fail = |e: std::io::Error| Failure {
        message: format!("cannot write the report to {}: {e}", out.display()),
        code: 2,
    };
    std::fs::create_dir_all(out).map_err(fail)?;
    let json = serde_json::to_string_pretty(results).expect("serialisable");
    std::fs::write(out.join("results.json"), json).map_err(fail)?;
    std::fs::write(out.join("index.html"), html::render(results)).map_err(fail)?;
    Ok(())
}
