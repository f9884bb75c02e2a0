//! Renders a quick report into a temporary folder and checks its JSON and HTML; looks at the
//! page in headless Chromium when it is installed.

use std::path::{Path, PathBuf};
use std::process::Command;
use topolab::registry;
use topolab_harness::page::plot;
use topolab_structures::Operator;

fn out_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("topolab-test-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn render(out: &Path) {
    let status = Command::new(env!("CARGO_BIN_EXE_topolab"))
        .args([
            "report",
            "--quick",
            "--sizes",
            "200,800",
            "--probe-mb",
            "4",
            "--out",
        ])
        .arg(out)
        .status()
        .expect("run topolab");
    assert!(status.success(), "topolab report failed: {status}");
}

#[test]
fn a_quick_report_has_every_structure_and_operator_and_no_mismatch() {
    let out = out_dir("report");
    render(&out);
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    let ms = json["measurements"].as_array().unwrap();
    let workloads = [
        "construction",
        "circulators",
        "barycenter",
        "normals",
        "smoothing",
    ];
    for s in registry::NAMES {
        for op in Operator::ALL.iter().map(|o| o.name()).chain(workloads) {
            let found = ms
                .iter()
                .any(|m| m["structure"] == *s && m["operator"] == op);
            let refused = ms
                .iter()
                .any(|m| m["structure"] == *s && m["status"] == "refused");
            assert!(found || refused, "{s} has no {op} measurement");
        }
    }
    for m in ms {
        for field in [
            "structure",
            "operator",
            "kernel",
            "mesh",
            "triangles",
            "ns_per_item",
            "items",
            "checksum",
            "status",
        ] {
            assert!(m.get(field).is_some(), "measurement lacks {field}: {m}");
        }
        if m["status"] == "measured" {
            assert!(m["ns_per_item"].as_f64().unwrap() > 0.0, "{m}");
        }
    }
    // Construction: warm builds (`ns_per_item`) everywhere, cold ones beside them on the
    // largest torus, whose table shows them.
    for m in ms
        .iter()
        .filter(|m| m["operator"] == "construction" && m["status"] == "measured")
    {
        assert!(m["ns_per_item"].as_f64().unwrap() > 0.0, "{m}");
        assert_eq!(
            m["cold_ns_per_item"].as_f64().is_some_and(|c| c > 0.0),
            m["mesh"] == "torus-800",
            "{m}"
        );
    }
    // Every measured cell has its interval around its value, from its rounds.
    for m in ms.iter().filter(|m| m["status"] == "measured") {
        let ci = m["ns_per_item_ci"]
            .as_array()
            .unwrap_or_else(|| panic!("{m}"));
        let (lo, hi, x) = (
            ci[0].as_f64().unwrap(),
            ci[1].as_f64().unwrap(),
            m["ns_per_item"].as_f64().unwrap(),
        );
        assert!(lo <= x && x <= hi, "{m}");
        assert!(m["rounds"].as_u64().unwrap() >= 6, "{m}");
    }
    // A limit on the sweeps of the structures that declare their access, none on the others.
    let sweep = |s: &str, op: &str| {
        ms.iter()
            .find(|m| {
                m["structure"] == s
                    && m["operator"] == op
                    && m["kernel"] == "sweep"
                    && m["mesh"] == "torus-800"
                    && m["status"] == "measured"
            })
            .unwrap_or_else(|| panic!("no {s} {op} sweep"))
    };
    for (s, op) in [
        ("index-half-edge", "r00"),
        ("che-l2", "r22"),
        ("pointer-half-edge", "boundary-curves"),
    ] {
        let limit = &sweep(s, op)["limit"];
        assert!(
            limit["ns_per_item"].as_f64().unwrap() > 0.0,
            "{s} {op}: {limit}"
        );
        assert!(limit["bound"].is_string(), "{limit}");
    }
    assert!(sweep("vertex-list", "r20").get("limit").is_none());
    assert!(!json["probe"]["levels"].as_array().unwrap().is_empty());
    assert!(json["probe"]["checksum_ns"].as_f64().unwrap() > 0.0);
    assert!(json["machine"]["cpu"].is_string());
    assert!(json["probe"]["read_bytes_per_s"].as_f64().unwrap() > 0.0);
    assert!(!json["fits"].as_array().unwrap().is_empty());
    // The hull section: every hull timed warm, by the median of its timed runs; Qhull
    // in-process on every point set of the randomized algorithm, with its vertices.
    let hull = json["hull"].as_array().unwrap();
    assert!(hull.iter().all(|r| r["timed_runs"].as_u64().unwrap() >= 1));
    let randomized: Vec<_> = hull
        .iter()
        .filter(|r| r["algorithm"] == "randomized")
        .collect();
    let qhull: Vec<_> = hull.iter().filter(|r| r["algorithm"] == "qhull").collect();
    assert!(!randomized.is_empty());
    if topolab::HAS_QHULL {
        assert_eq!(qhull.len(), randomized.len());
        for (q, r) in qhull.iter().zip(&randomized) {
            assert_eq!(
                (&q["n"], &q["vertex_checksum"]),
                (&r["n"], &r["vertex_checksum"])
            );
        }
        assert!(json["qhull"].as_str().unwrap().contains("i Qt"));
    } else {
        assert!(qhull.is_empty() && json["qhull"].is_null());
    }
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert_eq!(
        html.contains("<code>qhull</code>: Qhull 2020.2"),
        topolab::HAS_QHULL
    );
    assert!(html.contains("Table 4.1, measured") && html.contains("Figure 4.10"));
    // No number a reader cannot use: no infinite or undefined ratio anywhere on the page.
    for bad in ["inf×", "NaN", ">inf<", " inf "] {
        assert!(!html.contains(bad), "the page shows {bad:?}");
    }
    // How the baselines are run: one entry per outside library the run used, each saying its
    // build, on the page and in results.json.
    let baselines = json["baselines"].as_array().unwrap();
    let listed = |name: &str| baselines.iter().any(|b| b["name"] == name);
    assert_eq!(listed("openmesh"), topolab::HAS_OPENMESH, "{baselines:?}");
    assert_eq!(listed("qhull"), topolab::HAS_QHULL, "{baselines:?}");
    if let Some(build) = topolab::OPENMESH_BUILD {
        assert!(html.contains("<h2>How the baselines are run</h2>"));
        assert!(html.contains(build), "the OpenMesh build is on the page");
    }
    assert!(html.contains("× limit") && html.contains("worst × limit"));
    assert!(html.contains("cold − warm (page faults)"));
    for s in registry::NAMES {
        assert!(
            html.contains(&format!("<th>{s}</th>")),
            "{s} missing from the table"
        );
    }
    assert!(
        !html.contains("<script src") && !html.contains("<link"),
        "the page must be self-contained"
    );
    every_legend_is_outside_its_data_area(&html);
    assert!(html.contains("<h2>Choosing a structure</h2>"));
    // The chooser is at the top: before the machine and every measured section.
    assert!(html.find("Choosing a structure") < html.find("<h2>Machine</h2>"));
    // With the Rust crates (on by default), the paragraph for Rust users names the crate that
    // builds fastest, as results.json has it.
    let crates = [
        "lox-half-edge",
        "lox-directed-edge",
        "baby-shark-corner-table",
        "tri-mesh",
    ];
    if registry::HAS_PEERS {
        let paragraph = html
            .split("<p><b>For Rust users.</b>")
            .nth(1)
            .and_then(|rest| rest.split("</p>").next())
            .expect("the paragraph for Rust users");
        let fastest = ms
            .iter()
            .filter(|m| {
                crates.iter().any(|c| m["structure"] == *c)
                    && m["operator"] == "construction"
                    && m["mesh"] == "torus-800"
                    && m["status"] == "measured"
            })
            .min_by(|a, b| {
                a["ns_per_item"]
                    .as_f64()
                    .unwrap()
                    .total_cmp(&b["ns_per_item"].as_f64().unwrap())
            })
            .expect("the crates' construction on torus-800");
        let named = format!(
            "builds fastest: <b>{}</b>",
            fastest["structure"].as_str().unwrap()
        );
        assert!(paragraph.contains(&named), "{named} not in: {paragraph}");
    } else {
        assert!(!html.contains("For Rust users."));
    }
    local_refinement_has_every_editable_structure(&json, &html);
    findings_are_written_from_the_results(&out, ms);
    let _ = std::fs::remove_dir_all(&out);
}

/// The changing section's local refinement: every editable structure of the registry is
/// timed on the smallest torus or named in a note saying why not, every structure's result on
/// a torus is the same mesh, and the regular grid's row is on the page.
fn local_refinement_has_every_editable_structure(json: &serde_json::Value, html: &str) {
    let local = &json["local_refinement"];
    let cases = local["cases"].as_array().expect("local refinement cases");
    let rows = local["rows"].as_array().expect("local refinement rows");
    let smallest = cases
        .iter()
        .min_by_key(|c| c["faces"].as_u64().unwrap())
        .expect("a torus refined");
    let notes: Vec<&str> = json["notes"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|n| n.as_str())
        .filter(|n| n.starts_with("local refinement skipped"))
        .collect();
    for s in topolab::registry::NAMES
        .iter()
        .filter(|s| topolab_registry::is_editable(s))
    {
        let timed = rows
            .iter()
            .any(|r| r["structure"] == *s && r["mesh"] == smallest["mesh"]);
        let noted = notes.iter().any(|n| n.contains(s));
        assert!(
            timed || noted,
            "{s}: neither timed nor noted in local refinement"
        );
    }
    for c in cases {
        let results: Vec<&serde_json::Value> = rows
            .iter()
            .filter(|r| r["mesh"] == c["mesh"])
            .map(|r| &r["result"])
            .collect();
        assert!(!results.is_empty(), "no structure refined {}", c["mesh"]);
        assert!(results.iter().all(|r| *r == results[0]), "{results:?}");
        assert_eq!(results[0]["faces"], c["faces_after"]);
        assert!(c["faces_after"].as_u64() > c["faces"].as_u64());
    }
    assert!(html.contains("<h3>Local refinement: adaptive, in one region</h3>"));
    assert!(html.contains("regular-grid, height-field</td><td colspan=6 class=l>cannot:"));
}

/// FINDINGS.md lists every structure on the largest torus with its R00 sweep as results.json
/// has it, sorted fastest first.
fn findings_are_written_from_the_results(out: &Path, ms: &[serde_json::Value]) {
    let md = std::fs::read_to_string(out.join("FINDINGS.md")).expect("FINDINGS.md is written");
    assert!(md.starts_with("# Findings of this run"), "{md}");
    // The Targets' decimation row, timed in its own section, is in the findings when the page
    // shows it.
    let html = std::fs::read_to_string(out.join("index.html")).expect("the page is written");
    assert_eq!(
        html.contains("timed in turns in the Decimation section"),
        md.contains("(in the Decimation section)"),
        "{md}"
    );
    let sweeps: Vec<(&str, f64)> = ms
        .iter()
        .filter(|m| {
            m["operator"] == "r00"
                && m["kernel"] == "sweep"
                && m["mesh"] == "torus-800"
                && m["status"] == "measured"
        })
        .map(|m| {
            (
                m["structure"].as_str().unwrap(),
                m["ns_per_item"].as_f64().unwrap(),
            )
        })
        .collect();
    assert!(sweeps.len() >= registry::NAMES.len() / 2, "{sweeps:?}");
    let mut rows = Vec::new();
    for (s, ns) in sweeps {
        let shown = if ns >= 100.0 {
            format!("{ns:.0}")
        } else {
            format!("{ns:.1}")
        };
        // A row tied with the one above it (their intervals overlap) is marked ≈.
        let at = md
            .find(&format!("| {s} |"))
            .or_else(|| md.find(&format!("| ≈ {s} |")))
            .unwrap_or_else(|| panic!("{s} is not listed in\n{md}"));
        let line = md[at..].lines().next().unwrap();
        // The median, then its interval in brackets.
        assert!(
            line.contains(&format!("| {shown} [")),
            "{s}: {shown} not in {line}"
        );
        rows.push((at, ns));
    }
    for (a, x) in &rows {
        for (b, y) in &rows {
            assert!(x >= y || a < b, "a faster sweep is listed later:\n{md}");
        }
    }
}

/// Every log-log plot of the page has a data area and a legend, and they do not overlap; the
/// page has as many plots as operators, workloads and construction families at least.
fn every_legend_is_outside_its_data_area(html: &str) {
    let plots: Vec<&str> = html
        .split("<svg ")
        .skip(1)
        .filter(|s| s.starts_with(r#"xmlns="http://www.w3.org/2000/svg" class="loglog""#))
        .map(|s| &s[..s.find("</svg>").expect("a closed svg")])
        .collect();
    assert!(
        plots.len() >= Operator::ALL.len() + 4 + 2,
        "{} plots",
        plots.len()
    );
    for p in plots {
        let area = plot::rect_of(p, "plot-area").expect("a plot area");
        let legend = plot::rect_of(p, "legend").expect("a legend");
        assert!(
            !area.overlaps(&legend),
            "a legend {legend:?} overlaps its data {area:?}"
        );
    }
}

#[test]
fn the_page_renders_in_headless_chromium() {
    let Some(chromium) = ["chromium", "chromium-browser"].into_iter().find(|c| {
        Command::new(c)
            .arg("--version")
            .output()
            .is_ok_and(|o| o.status.success())
    }) else {
        eprintln!("SKIPPED: Chromium is not installed (apt-get install chromium): the page was not looked at");
        return;
    };
    let out = out_dir("chromium");
    render(&out);
    let shot = out.join("shot.png");
    let run = Command::new(chromium)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-background-networking",
            "--disable-component-update",
            "--no-first-run",
            "--window-size=1200,2400",
        ])
        .arg(format!("--user-data-dir={}", out.join("profile").display()))
        .arg(format!("--screenshot={}", shot.display()))
        .arg(format!("file://{}", out.join("index.html").display()))
        .output()
        .expect("run chromium");
    assert!(
        run.status.success(),
        "chromium failed: {}",
        String::from_utf8_lossy(&run.stderr)
    );
    let png = std::fs::read(&shot).expect("a screenshot");
    assert_eq!(&png[1..4], b"PNG");
    assert!(
        png.len() > 50_000,
        "the screenshot is nearly empty ({} bytes)",
        png.len()
    );
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn a_single_large_size_skips_the_quadratic_cells_with_an_estimate() {
    // One size, nothing smaller to extrapolate from: `--sizes 1000000` never finished,
    // because the vertex list's O(n)-per-query sweeps ran in full. Here 64k triangles and the
    // quick budget (150 ms a run) make them seconds each.
    let out = out_dir("single-size");
    let status = Command::new(env!("CARGO_BIN_EXE_topolab"))
        .args([
            "report",
            "--quick",
            "--sizes",
            "64000",
            "--structures",
            "vertex-list",
            "--meshes",
            "torus",
            "--probe-mb",
            "4",
            "--out",
        ])
        .arg(&out)
        .status()
        .expect("run topolab");
    assert!(status.success(), "topolab report failed: {status}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    let cell = |op: &str, kernel: &str| {
        json["measurements"]
            .as_array()
            .unwrap()
            .iter()
            .find(|m| m["operator"] == op && m["kernel"] == kernel)
            .unwrap_or_else(|| panic!("no {op} {kernel} cell"))
            .clone()
    };
    for (op, kernel) in [
        ("r00", "sweep"),
        ("r22", "sweep"),
        ("boundary-curves", "sweep"),
        ("smoothing", "workload"),
    ] {
        let m = cell(op, kernel);
        assert_eq!(m["status"], "skipped", "{m}");
        assert!(m["estimate_ns_per_item"].as_f64().unwrap() > 0.0, "{m}");
    }
    assert_eq!(cell("r20", "sweep")["status"], "measured");
    let notes = json["notes"].to_string();
    assert!(notes.contains("timed sample of its queries"), "{notes}");
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn a_quick_report_measures_the_lectures_operations_on_every_editable_structure() {
    use topolab_harness::report::sections::edit_ops::{compared, MEASURED};
    let out = out_dir("edit-ops");
    let status = Command::new(env!("CARGO_BIN_EXE_topolab"))
        .args([
            "report",
            "--quick",
            "--sizes",
            "200,800",
            "--sections",
            "edit-ops",
            "--probe-mb",
            "4",
            "--out",
        ])
        .arg(&out)
        .status()
        .expect("run topolab");
    assert!(status.success(), "topolab report failed: {status}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    let rows = json["edit_ops"].as_array().expect("the section's rows");
    let editable: Vec<&str> = registry::NAMES
        .iter()
        .copied()
        .filter(|s| compared(s))
        .collect();
    // The lecture's contrast needs explicit storage and at least one structure that moves a
    // vertex in place.
    assert!(editable.contains(&"explicit") && editable.contains(&"index-half-edge"));
    let row = |s: &str, op: &str| {
        rows.iter()
            .find(|r| r["structure"] == s && r["op"] == op && r["mesh"] == "torus-800")
            .unwrap_or_else(|| panic!("no {op} row for {s}"))
    };
    for s in &editable {
        for op in MEASURED {
            let r = row(s, op.name());
            let status = r["outcome"]["status"].as_str().expect("a status");
            assert!(
                ["measured", "not-offered", "skipped"].contains(&status),
                "{r}"
            );
            if status == "measured" {
                assert!(r["outcome"]["ns_per_op"].as_f64().unwrap() > 0.0, "{r}");
            }
        }
    }
    // Moving a vertex: O(n) in explicit storage (every copy found), O(1) in place elsewhere.
    let explicit = row("explicit", "set-position");
    assert_eq!(
        (&explicit["declared"], &explicit["outcome"]["status"]),
        (&serde_json::json!("linear"), &serde_json::json!("measured"))
    );
    assert_eq!(
        row("index-half-edge", "set-position")["declared"],
        "constant"
    );
    assert_eq!(
        row("explicit", "delete-edge")["outcome"]["status"],
        "not-offered"
    );
    assert_eq!(
        row("che-l2", "insert-edge")["outcome"]["status"],
        "not-offered"
    );
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    let section = html
        .split("<h2>The lecture's operations, measured</h2>")
        .nth(1)
        .expect("the section on the page");
    for s in &editable {
        assert!(
            section.contains(&format!("<th>{s}</th>")),
            "{s} has no column"
        );
    }
    for op in MEASURED {
        assert!(
            section.contains(&format!("<td class=l>{op}</td>")),
            "{op} has no row"
        );
    }
    let _ = std::fs::remove_dir_all(&out);
}

/// The teaching section draws a flip, an edge split, a collapse and a vertex split on the
/// index half-edge, the winged-edge and the CHE's level 2: a picture before and one after
/// each, and the records it wrote, which results.json keeps and which are the lines
/// `topolab explain NAME --op OP` prints.
#[test]
fn the_teaching_section_shows_four_edits_before_and_after_on_three_structures() {
    let out = out_dir("teaching-edits");
    let status = Command::new(env!("CARGO_BIN_EXE_topolab"))
        .args([
            "report",
            "--quick",
            "--sizes",
            "200",
            "--meshes",
            "grid",
            "--structures",
            "index-half-edge",
            "--probe-mb",
            "4",
            "--sections",
            "teaching",
            "--out",
        ])
        .arg(&out)
        .status()
        .expect("run topolab");
    assert!(status.success(), "topolab report failed: {status}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    let edits = json["teaching_edits"].as_array().expect("teaching_edits");
    assert_eq!(edits.len(), 12, "{edits:?}");
    for op in ["flip-edge", "split-edge", "collapse-edge", "split-vertex"] {
        for structure in ["index-half-edge", "winged-edge", "che-l2"] {
            let e = edits
                .iter()
                .find(|e| e["op"] == op && e["structure"] == structure)
                .unwrap_or_else(|| panic!("no {op} on {structure}"));
            for side in ["before", "after"] {
                assert!(
                    !e[side]["faces"].as_array().unwrap().is_empty(),
                    "{op} {structure} {side}"
                );
            }
            // The block of this edit: its two pictures, before and after, each numbering the
            // vertices.
            let start = html
                .find(&format!(
                    "<div class=edit data-op=\"{op}\" data-structure=\"{structure}\">"
                ))
                .unwrap_or_else(|| panic!("no block for {op} on {structure}"));
            let block = &html[start..];
            let block = &block[..block.find("</details>").unwrap()];
            assert_eq!(
                block.matches("class=\"edit-picture\"").count(),
                2,
                "{block}"
            );
            assert!(block.contains(&format!(">before {op}</text>")), "{block}");
            assert!(block.contains(&format!(">after {op}</text>")), "{block}");
            assert!(block.contains(">0</text>"), "{block}");
            // The lines explain --op prints for the same edit on the same default element.
            let cli = Command::new(env!("CARGO_BIN_EXE_topolab"))
                .args(["explain", structure, "--op", op])
                .output()
                .expect("run topolab");
            let text = String::from_utf8_lossy(&cli.stdout);
            let printed: Vec<&str> = text
                .split("writes (old -> new; + added, - removed):\n")
                .nth(1)
                .unwrap()
                .lines()
                .take_while(|l| !l.is_empty())
                .collect();
            let kept: Vec<&str> = e["changes"]
                .as_array()
                .unwrap()
                .iter()
                .map(|l| l.as_str().unwrap())
                .collect();
            assert_eq!(kept, printed, "{op} on {structure}");
            assert!(!kept.is_empty());
        }
    }
    let _ = std::fs::remove_dir_all(&out);
}
