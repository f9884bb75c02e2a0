//! The report page: its shell (head, CSS, title), the Machine block with the run's time by
//! section, and the sections in page order, drawn from [`Results`].

use crate::format::{bytes, esc};
use crate::report::section::Page;
use crate::report::sections::SECTIONS;
use crate::results::Results;
use std::fmt::Write;
use topolab_structures::Step;

/// The report's style sheet, shared by the pages the lab writes in its format (the scale run's).
pub(crate) const CSS: &str = r#"
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

/// Renders the whole report page: the sections the run measured (`settings.sections`), in the
/// order of [`SECTIONS`], the chooser above the Machine block.
pub fn render(r: &Results) -> String {
    let mut h = String::new();
    let page = Page::new(r);
    let _ = write!(h, "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>topolab report</title><style>{CSS}</style></head><body>");
    let _ = write!(h, "<h1>topolab report</h1><p>Mesh data structures side by side: every operator timed on every structure, on meshes of growing size, with the theory next to the measurement. Produced by <code>{}</code>.</p>", esc(&r.settings.command));
    // `--sections`: only the sections the run measured.
    let shown = || {
        SECTIONS
            .iter()
            .filter(|s| r.settings.sections.contains(&s.name()))
    };
    for s in shown().filter(|s| s.before_machine()) {
        s.render(&mut h, &page);
    }
    machine_section(&mut h, r);
    crate::measuring::baselines::render(&mut h, &r.baselines);
    for s in shown().filter(|s| !s.before_machine()) {
        s.render(&mut h, &page);
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
fn level_text(l: &crate::measuring::probe::Level) -> String {
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
        "<h2>Machine</h2><table><tr><th class=l>CPU</th><td class=l>{}</td></tr><tr><th class=l>cores</th><td class=l>{}</td></tr><tr><th class=l>caches</th><td class=l>{}</td></tr><tr><th class=l>memory</th><td class=l>{}</td></tr><tr><th class=l>compiler</th><td class=l>{}</td></tr><tr><th class=l>OpenMesh</th><td class=l>{}</td></tr><tr><th class=l>commit, date</th><td class=l>{}, {}</td></tr><tr><th class=l>sequential read (probe)</th><td class=l>{:.1} GB/s over {}</td></tr><tr><th class=l>dependent random access (probe)</th><td class=l>{:.1} ns per hop over {}</td></tr><tr><th class=l>by working set (probe)</th><td class=l>{}</td></tr><tr><th class=l>timing</th><td class=l>in rounds: every structure of a mesh built afresh each round and run once per cell, in a random order; a round's value of a sweep or workload is the median of batches of runs after an untimed warm-up, of a sampled cell the time per query of passes of {} queries drawn afresh each round ({} per kind and round), until {:.0} ms of runs; a cell's value is the median of its rounds (at least {}, at most {}), its interval the order-statistics interval of that median (at least 95% from 6 rounds on); single-threaded, in the measuring thread's CPU time</td></tr></table>",
        esc(&m.cpu), m.cores, esc(&m.caches), esc(&m.memory), esc(&m.rustc), esc(&m.openmesh), esc(&m.commit), esc(&m.date),
        p.read_bytes_per_s / 1e9, bytes(p.read_array_bytes as f64), p.chase_ns_per_hop, bytes(p.chase_array_bytes as f64),
        p.levels.iter().map(level_text).collect::<Vec<_>>().join("; "),
        r.settings.rounds.pass, r.settings.samples, r.settings.rounds.round_ns / 1e6,
        r.settings.rounds.min_rounds, r.settings.rounds.max_rounds
    );
    crate::report::sure::machine(h, r);
    crate::measuring::phases::render(h, &r.phases);
}
