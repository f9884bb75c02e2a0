//! "How the baselines are run": for every outside library the run measured, which version,
//! from where, built how, used how, what the clock covers, how its memory is counted, and the
//! differences from the lab's own structures that remain, each with its reason. The facts come
//! from the build that ran ([`runs`] fills the [`BaselineRun`]s of the libraries compiled in),
//! so the page says what was measured, not what was meant.

mod runs;
pub use runs::{runs, Used};

use crate::format::esc;
use std::fmt::Write;

/// How one outside library was run in a report.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct BaselineRun {
    /// The names it appears under on the page (structures, hull or decimater rows).
    pub name: String,
    /// The library and its version.
    pub library: String,
    /// Where its code came from and how it was compiled (or installed).
    pub build: String,
    /// How the lab uses it: the classes and calls, as the library's documentation shows them.
    pub used_as: String,
    /// What the clock covers, and what happens before and after it.
    pub timed: String,
    /// How its memory is counted.
    pub counted: String,
    /// Differences from the lab's own structures that remain, each with its reason.
    pub differences: Vec<String>,
}

/// Renders the section, nothing when no baseline ran.
pub fn render(h: &mut String, runs: &[BaselineRun]) {
    if runs.is_empty() {
        return;
    }
    h.push_str("<h2>How the baselines are run</h2><div class=read><b>How to read it.</b> Each outside library as this run built and used it. The rules that hold for all of them: every timed loop runs inside the library's own language (a whole sweep, sampled kernel, workload or construction is one call, its queries handed over in the library's own handles before the clock starts), returns the lab's checksum, and must agree with every other structure or the report stops (the Rust crates are Rust: the lab's own kernels call them through their adapters, inlined, as they call the lab's structures, and their answers go into the same checksums); builds are told the exact vertex, edge and face counts before the clock and dropped after it; heap bytes are counted by one rule for Rust and C++ (each block allocated while the structure is built, for the bytes glibc's <code>malloc_usable_size</code> gives it).</div>");
    h.push_str("<table><tr><th class=l>baseline</th><th class=l>library</th><th class=l>built</th><th class=l>used as</th><th class=l>timed</th><th class=l>memory</th><th class=l>differences that remain</th></tr>");
    for r in runs {
        let differences = if r.differences.is_empty() {
            "none known".to_string()
        } else {
            let items: String = r
                .differences
                .iter()
                .map(|d| format!("<li>{}</li>", esc(d)))
                .collect();
            format!("<ul>{items}</ul>")
        };
        let _ = write!(
            h,
            "<tr><td class=l>{}</td><td class=l>{}</td><td class=l>{}</td><td class=l>{}</td><td class=l>{}</td><td class=l>{}</td><td class=l>{differences}</td></tr>",
            esc(&r.name),
            esc(&r.library),
            esc(&r.build),
            esc(&r.used_as),
            esc(&r.timed),
            esc(&r.counted),
        );
    }
    h.push_str("</table>");
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(name: &str, differences: &[&str]) -> BaselineRun {
        BaselineRun {
            name: name.into(),
            library: "Lib 1.0 <x>".into(),
            build: "-O3".into(),
            used_as: "a class".into(),
            timed: "the loop".into(),
            counted: "operator new".into(),
            differences: differences.iter().map(|d| d.to_string()).collect(),
        }
    }

    #[test]
    fn every_run_is_a_row_with_its_differences_escaped() {
        let mut h = String::new();
        render(&mut h, &[run("a", &["d1 & d2"]), run("b", &[])]);
        assert!(h.contains("<h2>How the baselines are run</h2>"));
        assert_eq!(h.matches("<tr><td class=l>").count(), 2);
        assert!(h.contains("<li>d1 &amp; d2</li>"), "{h}");
        assert!(h.contains("Lib 1.0 &lt;x&gt;"), "{h}");
        assert!(h.contains("none known"));
    }

    #[test]
    fn no_baseline_no_section() {
        let mut h = String::new();
        render(&mut h, &[]);
        assert!(h.is_empty());
    }
}
