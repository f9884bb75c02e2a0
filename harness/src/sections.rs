//! The sections of the report page (`topolab report --sections`), and what each one needs
//! measured: a focused run measures only what the sections it shows are drawn from.

/// A section of the report page, in page order.
#[derive(Copy, Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Section {
    /// "Choosing a structure", at the top: per structure its memory, construction, R00 sweep
    /// and smoothing on the largest torus, what it stores and when to pick it.
    Chooser,
    /// The measured Table 4.1 of the CHE thesis chapter: declared cost, fitted exponent, time.
    #[serde(rename = "table-4-1")]
    Table41,
    /// Time per query against mesh size, one plot per operator.
    Plots,
    /// Every sweep against its limit.
    Sweeps,
    /// The Surface_mesh workloads.
    Workloads,
    /// Heap bytes per triangle.
    Memory,
    /// Construction time, warm and cold.
    Construction,
    /// The vertex 1-ring sweep of a torus in each element order.
    Orderings,
    /// The real meshes of `bench-data/cache/` (repaired where the structures refuse them).
    RealMeshes,
    /// Real meshes refined to 1M triangles and more (family `refined`), measured like the tori.
    RealAtScale,
    /// libigl's functions timed on the tori, their answers checked against the lab's.
    Libigl,
    /// The 3D convex hull algorithms and Qhull.
    Hull,
    /// The changing workloads of the Surface_mesh benchmark (√3 subdivision, the collapse
    /// test) on the editable structures and OpenMesh.
    Changing,
    /// Decimation by quadric error against OpenMesh's and CGAL's decimaters, and the
    /// reconstruction by vertex splits.
    Decimate,
    /// What each structure stores for the CHE thesis chapter's Figure 4.10.
    Teaching,
    /// Thumbnails of the meshes.
    Meshes,
    /// The project's performance targets on the largest torus, last: the project's own
    /// bookkeeping, after what a reader came for.
    Targets,
}

/// How much of the size sweep (every structure on the generated tori and grids) a selection
/// of sections needs.
#[derive(Copy, Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum SizeSweep {
    /// None: the generated meshes are not measured.
    None,
    /// Construction and the vertex 1-ring sweep (memory and construction sections).
    Light,
    /// Every operator, kernel and workload.
    Full,
}

impl Section {
    /// Every section, in page order.
    pub const ALL: [Section; 17] = [
        Section::Chooser,
        Section::Table41,
        Section::Plots,
        Section::Sweeps,
        Section::Workloads,
        Section::Memory,
        Section::Construction,
        Section::Orderings,
        Section::RealMeshes,
        Section::RealAtScale,
        Section::Libigl,
        Section::Hull,
        Section::Changing,
        Section::Decimate,
        Section::Teaching,
        Section::Meshes,
        Section::Targets,
    ];

    /// The kebab-case name of `--sections` and `results.json`.
    pub fn name(self) -> &'static str {
        match self {
            Section::Chooser => "chooser",
            Section::Targets => "targets",
            Section::Table41 => "table-4-1",
            Section::Plots => "plots",
            Section::Sweeps => "sweeps",
            Section::Workloads => "workloads",
            Section::Memory => "memory",
            Section::Construction => "construction",
            Section::Orderings => "orderings",
            Section::RealMeshes => "real-meshes",
            Section::RealAtScale => "real-at-scale",
            Section::Libigl => "libigl",
            Section::Hull => "hull",
            Section::Changing => "changing",
            Section::Decimate => "decimate",
            Section::Teaching => "teaching",
            Section::Meshes => "meshes",
        }
    }

    /// The section called `name`.
    pub fn from_name(name: &str) -> Option<Section> {
        Section::ALL.into_iter().find(|s| s.name() == name)
    }

    /// What of the size sweep this section is drawn from. libigl's answers are checked against
    /// the lab's sweeps and workloads on the tori, so it needs them all; the chooser shows a
    /// workload; the refined real meshes are measured on their own, not by the size sweep.
    pub fn size_sweep(self) -> SizeSweep {
        match self {
            Section::Chooser
            | Section::Targets
            | Section::Table41
            | Section::Plots
            | Section::Sweeps
            | Section::Workloads
            | Section::Libigl => SizeSweep::Full,
            Section::Memory | Section::Construction => SizeSweep::Light,
            Section::Orderings
            | Section::RealMeshes
            | Section::RealAtScale
            | Section::Hull
            | Section::Changing
            | Section::Decimate
            | Section::Teaching
            | Section::Meshes => SizeSweep::None,
        }
    }
}

/// What of the size sweep `sections` need: the most any of them needs.
pub fn size_sweep(sections: &[Section]) -> SizeSweep {
    sections
        .iter()
        .map(|s| s.size_sweep())
        .max()
        .unwrap_or(SizeSweep::None)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_serialize_as_written() {
        for s in Section::ALL {
            assert_eq!(Section::from_name(s.name()), Some(s));
            assert_eq!(
                serde_json::to_value(s).unwrap(),
                serde_json::Value::from(s.name())
            );
        }
        assert_eq!(Section::from_name("table41"), None);
    }

    #[test]
    fn the_size_sweep_is_what_the_most_demanding_section_needs() {
        assert_eq!(
            size_sweep(&[Section::Hull, Section::Orderings]),
            SizeSweep::None
        );
        assert_eq!(
            size_sweep(&[Section::Memory, Section::Hull]),
            SizeSweep::Light
        );
        assert_eq!(
            size_sweep(&[Section::Memory, Section::Plots]),
            SizeSweep::Full
        );
        assert_eq!(size_sweep(&Section::ALL), SizeSweep::Full);
    }
}
