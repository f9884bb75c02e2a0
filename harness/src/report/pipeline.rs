//! The report run, from a [`Request`] to `results.json`, `index.html` and `FINDINGS.md`:
//! the memory probe, the structures described, the meshes made (generated, read and repaired,
//! refined), the size sweep (every structure on every mesh its sections need), the fits and
//! the limits, then each shown section's own measurement in page order
//! ([`Section::measure`](crate::report::section::Section::measure)), each timed as its phase,
//! and the files. What only the program running it has (its allocator, the machine's limits
//! it admits) comes from its [`Host`].

use crate::measuring::baselines::{self, Used};
use crate::measuring::measure::{cross_check, Estimator, MeshCase};
use crate::measuring::phases::Phase;
use crate::measuring::speed_limit::MeshCounts;
use crate::measuring::timing::meter::MemoryMeter;
use crate::report::clock::{self, Clock};
use crate::report::listed::Listed;
use crate::report::run::{Case, MeshFamily, ReportError, Request, Run};
use crate::report::section::{Real, Refined};
use crate::report::sections::real_at_scale::FAMILY;
use crate::report::selection::Selection;
use crate::report::{refined, repair};
use crate::results::{
    CostRow, MeshInfo, MeshRoundsRow, Results, Settings, Status, StructureInfo, Teaching,
    FORMAT_VERSION,
};
use crate::{measuring::fit, measuring::machine, measuring::probe, page::svg};
use indicatif::{ProgressBar, ProgressStyle};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use topolab_structures::io::{echo, write_atomically};
use topolab_structures::registry::{StructureVisitor, Structures};
use topolab_structures::repair::RepairLog;
use topolab_structures::{meshes, MeshTopology, Operator, PolygonSoup};

/// What the program running a report provides.
pub trait Host {
    /// The process's memory meter and clock: the counting allocator it declares.
    fn meter(&self) -> &dyn MemoryMeter;
    /// Refuses a refined mesh of `faces` triangles the machine cannot hold with `structures`
    /// built on it.
    fn admit_refined(&self, faces: usize, structures: &[String]) -> Result<(), ReportError>;
}

struct Describe;

impl StructureVisitor for Describe {
    type Output = (StructureInfo, Teaching);
    fn visit<M: MeshTopology>(self) -> Self::Output {
        let info = StructureInfo {
            name: M::NAME.into(),
            family: M::FAMILY,
            editable: topolab_registry::is_editable(M::NAME),
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

/// Runs the report `req` asks for on the structures of the list `L` (each name of
/// `req.names` must be among them); returns a summary line.
pub fn report<L: Structures>(req: &Request, host: &dyn Host) -> Result<String, ReportError> {
    let plan = clock::plan(req.quick, req.full);
    // The same glibc policy for every structure, C++ baselines included: freed memory stays
    // with the process, so warm builds reuse it whatever the run built before.
    if !topolab_alloc::keep_freed_memory() {
        eprintln!("topolab report: this allocator keeps its own policy (not glibc): warm builds may still fault in fresh pages");
    }
    let probe_mb = req.probe_mb;
    eprintln!("topolab report: probing the machine's memory ({probe_mb} MiB)...");
    let mut clock = Clock::start();
    let probe = probe::measure(probe_mb, probe_mb);
    clock.lap(Phase::PROBE, None);
    let mut notes = Vec::new();
    let selection = Selection::new(
        req.sections.as_deref(),
        req.structures.as_deref(),
        &mut notes,
    );
    let mut results = Results {
        format_version: FORMAT_VERSION,
        baselines: Vec::new(),
        machine: machine::facts(&topolab_baselines::openmesh_description()),
        probe,
        settings: Settings {
            quick: req.quick,
            sizes: req.sizes.clone(),
            samples: plan.samples,
            rounds: crate::measuring::rounds::round_settings(&plan),
            cell_max_s: plan.cell_max.as_secs_f64(),
            command: req.command.clone(),
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
        local_refinement: Default::default(),
        edit_ops: Vec::new(),
        targets: Vec::new(),
        decimate: Vec::new(),
        teaching: Vec::new(),
        teaching_edits: crate::teaching::edits::teaching_edits(),
        reads: Vec::new(),
        notes,
        phases: Vec::new(),
        rounds: Vec::new(),
        drift: Vec::new(),
    };
    topolab_registry::note_absent(&mut results.notes);
    results
        .notes
        .extend(clock::budget_notes(req.quick, req.full));
    for n in &req.names {
        let (info, teach) = L::visit(n, Describe)
            .map_err(|_| ReportError::Usage(format!("no structure is called {n}")))?;
        results.structures.push(info);
        results.teaching.push(teach);
    }
    let (cases, mut repaired) = make_meshes(req, &selection, host, &mut results.notes)?;
    clock.lap(Phase::MESHES, None);
    let measured = cases.iter().filter(|c| selection.measures(&c.1)).count();
    let bar = ProgressBar::new(measured as u64);
    bar.set_style(
        ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {pos}/{len} {msg}")
            .expect("valid template")
            .progress_chars("=> "),
    );
    let mut est = Estimator::default();
    // The Targets between two structures read the size sweep's rounds on the largest torus,
    // which gets the run's most rounds.
    let target_mesh = cases
        .iter()
        .filter(|c| c.1 == "torus" && selection.measures(&c.1))
        .max_by_key(|c| c.2.num_faces())
        .map(|c| c.0.clone());
    let kept = crate::targets::swept::kept(&req.names);
    let drift = crate::measuring::probe::Drift::new();
    for (i, (name, fam, soup)) in cases.iter().enumerate() {
        let light_here = selection.light(fam) || (!req.full && refined::light(name));
        let targets_here = target_mesh.as_deref() == Some(name.as_str());
        let mut plan = clock::plan_for(&plan, light_here, fam, targets_here);
        if targets_here {
            // The Targets read this mesh's rounds: all of them, the run's most.
            plan.rounds.min_rounds = plan.rounds.max_rounds;
        }
        let plan = &plan;
        let case = MeshCase {
            name,
            family: fam,
            soup,
            seed: 2026,
        };
        if bar.is_hidden() {
            eprintln!(
                "topolab report: mesh {}/{}: {name} ({} faces)",
                i + 1,
                cases.len(),
                soup.num_faces()
            );
        }
        if selection.measures(fam) {
            // The machine's drift over the run: the same probe before every mesh.
            results.drift.push(drift.read(name, clock.since_start()));
            let keep = if targets_here { &kept[..] } else { &[] };
            let mut progress = |round: usize| bar.set_message(format!("{name}: round {round}"));
            let done = crate::measuring::rounds::measure_mesh::<L>(
                &req.names,
                &case,
                plan,
                keep,
                host.meter(),
                &mut est,
                &mut progress,
            )
            .map_err(|e| {
                ReportError::Measurement(if e.contains("checksum mismatch") {
                    format!("{e}\nThe report stops: two structures disagree.")
                } else {
                    e
                })
            })?;
            if targets_here {
                results.targets.extend(crate::targets::swept::turns(
                    &req.names,
                    name,
                    soup,
                    &done,
                    done.run.seconds,
                ));
            }
            results.rounds.push(MeshRoundsRow {
                mesh: name.clone(),
                rounds: done.run.rounds,
                extra: done.run.extra,
                seconds: done.run.seconds,
            });
            results.measurements.extend(done.measurements);
            bar.inc(1);
        }
        cross_check(&results.measurements, name).map_err(|e| {
            ReportError::Measurement(format!("{e}\nThe report stops: two structures disagree."))
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
    results.annotate_limits();
    clock.lap(Phase::FITS, None);
    let listed = Listed::<L>::new();
    let mut run = Run {
        request: req,
        cases: &cases,
        plan: &plan,
        results: &mut results,
        structures: &listed,
        meter: host.meter(),
        libigl_version: None,
    };
    // Each shown section's own measurement, in page order, timed as its phase (after the fits:
    // the Targets hold sweeps to their limits).
    for section in &selection.sections {
        section.measure(&mut run)?;
        if let Some(phase) = section.phase() {
            clock.lap(phase, None);
        }
    }
    let libigl_version = run.libigl_version;
    let measured: Vec<&str> = req.names.iter().map(String::as_str).collect();
    results.baselines = baselines::runs(Used {
        structures: &measured,
        hull: !results.hull.is_empty(),
        decimate: !results.decimate.is_empty(),
        libigl: libigl_version.as_deref(),
    });
    let skipped = results
        .measurements
        .iter()
        .filter(|m| m.status == Status::Skipped)
        .count();
    if skipped > 0 {
        results.notes.push(format!(
            "{skipped} cells were skipped because their estimated run exceeded {:.1} s; the table shows the estimate (from the smaller sizes, or, at a family's first size, from the time per query of a timed sample of its queries).",
            plan.cell_max.as_secs_f64()
        ));
    }
    write_report(&req.out, &mut results, clock)?;
    Ok(format!(
        "wrote {} measurements of {} structures on {} meshes to {}\n",
        results.measurements.len(),
        req.names.len(),
        cases.len(),
        req.out.join("index.html").display()
    ))
}

/// The meshes of the run, in the order measured: the generated ones at every size (when a shown
/// section needs them), the real ones (repaired where the strict structures refuse them: the
/// repairs by mesh name) and the refined ones, each as the request's families allow.
fn make_meshes(
    req: &Request,
    selection: &Selection,
    host: &dyn Host,
    notes: &mut Vec<String>,
) -> Result<(Vec<Case>, HashMap<String, RepairLog>), ReportError> {
    let generated: Vec<&str> = req
        .meshes
        .iter()
        .filter(|f| f.generated())
        .map(|f| f.name())
        .collect();
    let mut cases: Vec<Case> = Vec::new();
    for size in req.sizes.iter().filter(|_| selection.generated()) {
        for fam in &generated {
            let spec = format!("{fam}:{size}");
            let soup = meshes::from_spec(&spec)
                .map_err(|e| ReportError::Usage(format!("cannot generate the mesh {spec}: {e}")))?;
            cases.push((format!("{fam}-{}", short(*size)), fam.to_string(), soup));
        }
    }
    let mut repaired = HashMap::new();
    if req.meshes.contains(&MeshFamily::Real) && selection.needs.real != Real::None {
        for (name, soup) in real_meshes(notes) {
            let (soup, log) = repair::measurable(&name, soup, notes);
            repaired.extend(log.map(|log| (name.clone(), log)));
            cases.push((name, "real".into(), soup));
        }
    }
    if req.meshes.contains(&MeshFamily::Refined) && selection.needs.refined != Refined::None {
        let list: &[refined::Refined] = if req.quick {
            &refined::QUICK
        } else {
            &refined::FULL
        };
        let admit = |faces: usize| host.admit_refined(faces, &req.names);
        let made = refined::refined_meshes(list, &admit, notes)?;
        for (name, soup) in made {
            cases.push((name, FAMILY.into(), soup));
        }
    }
    Ok((cases, repaired))
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

/// Writes `results.json`, `index.html` and `FINDINGS.md`, with the phases' times of `clock`
/// and the time of rendering the page itself (its row is put into the rendered page's table
/// afterwards).
fn write_report(out: &Path, results: &mut Results, mut clock: Clock) -> Result<(), ReportError> {
    std::fs::create_dir_all(out).map_err(|e| {
        ReportError::Output(format!(
            "cannot write the report to {}: {e}",
            echo::path(out)
        ))
    })?;
    results.phases = clock.times().to_vec();
    let mut without = String::new();
    crate::measuring::phases::render(&mut without, &results.phases);
    let page = crate::report::page::render(results);
    clock.lap(Phase::WRITING, None);
    results.phases = clock.times().to_vec();
    let mut with = String::new();
    crate::measuring::phases::render(&mut with, &results.phases);
    let page = page.replacen(&without, &with, 1);
    let json = serde_json::to_string_pretty(results).expect("serialisable");
    write_file(&out.join("results.json"), json.as_bytes())?;
    write_file(&out.join("index.html"), page.as_bytes())?;
    let findings = crate::page::findings::markdown(results);
    write_file(&out.join("FINDINGS.md"), findings.as_bytes())?;
    Ok(())
}

/// Writes one file of the report, whole or not at all (a reader never sees half a page).
fn write_file(path: &Path, bytes: &[u8]) -> Result<(), ReportError> {
    use std::io::Write as _;
    write_atomically(path, |w| w.write_all(bytes))
        .map_err(|e| ReportError::Output(format!("cannot write {}: {e}", echo::path(path))))
}
