//! How long each section of a report run took: wall time and the process's CPU time, so that
//! a run on a loaded machine still tells what the report would take alone.
//!
//! The wall time of a section stretches with the load of the machine; its CPU time does not
//! (much). The report runs its sections one after the other, on one thread except where a
//! structure's construction or a subprocess (libigl) uses more, so the CPU seconds of a
//! section with a fixed amount of work are close to its wall seconds on an idle machine. A
//! section whose CPU time exceeds its wall time ran threads. The meshes' measurement is the
//! exception: its cells repeat until a wall-time budget, so under load they repeat less, and
//! its CPU time falls short of its time alone.

use crate::format::esc;
use std::fmt::Write;

/// A phase of a report run, as timed: one of the run's own steps ([`Phase::PROBE`],
/// [`Phase::MESHES`], [`Phase::MEASURE`], [`Phase::FITS`], [`Phase::WRITING`]) or a section's
/// own measurement ([`crate::report::section::Section::phase`]). `results.json` writes its name.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub struct Phase {
    /// Its kebab-case name in `results.json`.
    pub name: &'static str,
    /// What the page calls it.
    pub label: &'static str,
}

impl Phase {
    /// The machine's memory probe.
    pub const PROBE: Phase = Phase::new("probe", "memory probe");
    /// Describing the structures; generating, reading, repairing and refining the meshes.
    pub const MESHES: Phase = Phase::new("meshes", "structures and meshes");
    /// Every structure measured on one mesh (one entry per mesh, the mesh named).
    pub const MEASURE: Phase = Phase::new("measure", "measurement");
    /// Fitting exponents and putting limits on the sweeps.
    pub const FITS: Phase = Phase::new("fits", "fits and limits");
    /// Rendering the page and `results.json` (the writing of the files themselves is not in
    /// the file).
    pub const WRITING: Phase = Phase::new("writing", "rendering the page");

    /// The phase called `name`, which the page calls `label`.
    pub const fn new(name: &'static str, label: &'static str) -> Phase {
        Phase { name, label }
    }

    /// What the page calls it.
    pub fn label(self) -> &'static str {
        self.label
    }
}

impl serde::Serialize for Phase {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name)
    }
}

/// The time one phase took.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct PhaseTime {
    /// Which phase.
    pub phase: Phase,
    /// The mesh, for [`Phase::MEASURE`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mesh: Option<String>,
    /// Elapsed wall time, seconds.
    pub wall_s: f64,
    /// CPU time of the report's own process, user and system, all its threads, seconds.
    pub cpu_s: f64,
    /// CPU time of the subprocesses it waited for (Python with libigl), seconds.
    pub children_cpu_s: f64,
}

impl PhaseTime {
    /// The CPU time of the process and its subprocesses: what the section would take alone,
    /// where it runs one thread at a time.
    pub fn cpu_total_s(&self) -> f64 {
        self.cpu_s + self.children_cpu_s
    }
}

/// The phases summed by kind, in the order each kind first ran: (phase, entries, wall, CPU
/// with subprocesses).
pub fn by_phase(times: &[PhaseTime]) -> Vec<(Phase, usize, f64, f64)> {
    let mut out: Vec<(Phase, usize, f64, f64)> = Vec::new();
    for t in times {
        match out.iter_mut().find(|row| row.0 == t.phase) {
            Some(row) => {
                row.1 += 1;
                row.2 += t.wall_s;
                row.3 += t.cpu_total_s();
            }
            None => out.push((t.phase, 1, t.wall_s, t.cpu_total_s())),
        }
    }
    out
}

/// The run's time by section, for the page's run facts: one row per kind of section (the
/// meshes' measurements summed, each mesh in a list below), the share of the wall time, and
/// the total. Nothing when the run recorded no times.
pub fn render(h: &mut String, times: &[PhaseTime]) {
    if times.is_empty() {
        return;
    }
    let rows = by_phase(times);
    let wall: f64 = rows.iter().map(|r| r.2).sum();
    let cpu: f64 = rows.iter().map(|r| r.3).sum();
    let _ = write!(
        h,
        "<h3>Time by section</h3><p class=small>Wall time stretches with the machine's load; CPU time (the report's process, all its threads, and the subprocesses it waited for) is about what a section with a fixed amount of work takes alone, unless it runs threads (CPU above wall). The measurement of the meshes is not such a section: each cell repeats until a wall-time budget, so on a loaded machine it repeats less and its CPU time is below its time alone. This run: {wall:.0} s wall, {cpu:.0} s CPU.</p><table><tr><th class=l>section</th><th>wall s</th><th>CPU s</th><th>share of wall</th></tr>"
    );
    for (phase, n, w, c) in &rows {
        let label = if *n > 1 {
            format!("{} ({n} meshes)", phase.label())
        } else {
            phase.label().to_string()
        };
        let _ = write!(
            h,
            "<tr><td class=l>{}</td><td>{w:.1}</td><td>{c:.1}</td><td>{:.1}%</td></tr>",
            esc(&label),
            100.0 * w / wall.max(f64::MIN_POSITIVE)
        );
    }
    let _ = write!(
        h,
        "<tr><th class=l>total</th><th>{wall:.1}</th><th>{cpu:.1}</th><th>100%</th></tr></table>"
    );
    let meshes: Vec<&PhaseTime> = times.iter().filter(|t| t.mesh.is_some()).collect();
    if !meshes.is_empty() {
        h.push_str("<details><summary>measurement by mesh</summary><table><tr><th class=l>mesh</th><th>wall s</th><th>CPU s</th></tr>");
        for t in meshes {
            let _ = write!(
                h,
                "<tr><td class=l>{}</td><td>{:.1}</td><td>{:.1}</td></tr>",
                esc(t.mesh.as_deref().unwrap_or_default()),
                t.wall_s,
                t.cpu_total_s()
            );
        }
        h.push_str("</table></details>");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const HULL: Phase = Phase::new("hull", "3D convex hulls");

    fn t(phase: Phase, mesh: Option<&str>, wall_s: f64, cpu_s: f64) -> PhaseTime {
        PhaseTime {
            phase,
            mesh: mesh.map(str::to_string),
            wall_s,
            cpu_s,
            children_cpu_s: 0.5,
        }
    }

    #[test]
    fn phases_of_one_kind_are_summed_in_first_run_order() {
        let times = [
            t(Phase::PROBE, None, 2.0, 1.0),
            t(Phase::MEASURE, Some("torus-1k"), 3.0, 2.0),
            t(Phase::MEASURE, Some("grid-1k"), 5.0, 4.0),
            t(HULL, None, 1.0, 1.0),
        ];
        let rows = by_phase(&times);
        assert_eq!(rows.len(), 3);
        assert_eq!((rows[1].0, rows[1].1), (Phase::MEASURE, 2));
        assert_eq!(rows[1].2, 8.0);
        assert_eq!(rows[1].3, 7.0);
        assert_eq!(rows[2].0, HULL);
        // results.json writes a phase by its name.
        assert_eq!(serde_json::to_value(HULL).unwrap(), "hull");
        let mut h = String::new();
        render(&mut h, &times);
        assert!(h.contains("measurement (2 meshes)"), "{h}");
        assert!(h.contains("grid-1k"), "{h}");
        assert!(h.contains("<th>11.0</th>"), "total wall: {h}");
        let mut empty = String::new();
        render(&mut empty, &[]);
        assert!(empty.is_empty());
    }
}
