//! The results of a report run: what `results.json` holds and the HTML is drawn from.

use crate::measuring::kernels::Kernel;
use crate::measuring::machine::Machine;
use crate::measuring::probe::Probe;
use topolab_structures::{Cost, Operator};

// The schema in one place: the records of a cell are the measuring machinery's, the rows of a
// study and of the teaching section are their own modules'; results.json holds them all.
pub use crate::measuring::cells::{
    Bound, Cell, CostRow, FitRow, Limit, Measurement, MeshCounts, RoundSettings, Status,
    StructureInfo, Subject, Turns,
};
pub use crate::studies::hull::rows::{HullFit, HullRow};
pub use crate::studies::reads::{ReadsRow, Verdict};
pub use crate::teaching::edits::picture::{EditPicture, TeachingEdit};

/// The version of `results.json`'s format, written as its `format_version`: raised when a
/// field that readers rely on (`topolab compare` reads the machine, the settings' command, the
/// meshes and the measurements) changes its meaning or its name. Adding a field does not raise
/// it. Files without the field were written before it existed; their measurements read as
/// version 1's (version 0).
pub const FORMAT_VERSION: u32 = 1;

/// Everything one run measured.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Results {
    /// [`FORMAT_VERSION`] of the code that wrote it.
    pub format_version: u32,
    /// Machine and build facts.
    pub machine: Machine,
    /// How each outside library was built, used, timed and counted ([`crate::measuring::baselines`]).
    pub baselines: Vec<crate::measuring::baselines::BaselineRun>,
    /// The memory probe, measured in the same run.
    pub probe: Probe,
    /// How the run was configured.
    pub settings: Settings,
    /// The structures measured, with their declared costs.
    pub structures: Vec<StructureInfo>,
    /// The meshes measured.
    pub meshes: Vec<MeshInfo>,
    /// One entry per (structure, operator, kernel, mesh).
    pub measurements: Vec<Measurement>,
    /// Fitted exponents of time per query against size.
    pub fits: Vec<FitRow>,
    /// libigl's reference timings, when it ran.
    pub libigl: Vec<LibiglRow>,
    /// The 3D convex hull algorithms (and Qhull) against n.
    pub hull: Vec<HullRow>,
    /// Fitted exponents of the hull rows against n, next to the lecture's bounds.
    pub hull_fits: Vec<HullFit>,
    /// How the hull section ran Qhull (its library's version and options), when it did.
    pub qhull: Option<String>,
    /// The changing workloads (√3 subdivision, the collapse test) on the editable structures.
    pub changing: Vec<crate::studies::changing::ChangingRow>,
    /// Adaptive refinement in one region of each torus on the editable structures (the
    /// changing section's local refinement).
    pub local_refinement: crate::studies::changing::LocalRefinement,
    /// The lecture's editing operations, one at a time, on the editable structures and
    /// explicit storage ([`crate::report::sections::edit_ops`]).
    pub edit_ops: Vec<EditOpRow>,
    /// The Targets table's rounds: the structures of each target taking turns
    /// ([`crate::targets`]).
    pub targets: Vec<Turns>,
    /// Decimation by quadric error (the lab's, OpenMesh's, CGAL's) and the reconstruction.
    pub decimate: Vec<crate::studies::decimate::DecimateRow>,
    /// What each structure stores for the open tetrahedron (teaching section).
    pub teaching: Vec<Teaching>,
    /// Edits shown record by record, with the mesh before and after (teaching section,
    /// `edit_explain::teaching_edits`).
    pub teaching_edits: Vec<TeachingEdit>,
    /// Reads per query of every operator on every structure against mesh size, counted
    /// ([`crate::studies::reads`]).
    pub reads: Vec<ReadsRow>,
    /// Anything the reader should know (skipped baselines, missing data).
    pub notes: Vec<String>,
    /// How long each section of the run took, wall and CPU ([`crate::measuring::phases`]).
    pub phases: Vec<crate::measuring::phases::PhaseTime>,
    /// The rounds of each mesh of the size sweep.
    pub rounds: Vec<MeshRoundsRow>,
    /// The drift probe, read before every mesh of the size sweep ([`crate::measuring::probe::Drift`]).
    pub drift: Vec<crate::measuring::probe::DriftPoint>,
}

/// Settings of a run.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Settings {
    /// `--quick`.
    pub quick: bool,
    /// Triangle counts of the size sweep.
    pub sizes: Vec<usize>,
    /// Sampled queries drawn per kind and round.
    pub samples: usize,
    /// How the cells were measured in rounds.
    pub rounds: RoundSettings,
    /// A cell whose single run is estimated above this is skipped, seconds.
    pub cell_max_s: f64,
    /// The command that produced the results.
    pub command: String,
    /// The sections of the report this run measured and shows (`--sections`), by name, in
    /// page order.
    pub sections: Vec<&'static str>,
}

/// The rounds one mesh of the size sweep took.
#[derive(Clone, Debug, serde::Serialize)]
pub struct MeshRoundsRow {
    /// The mesh.
    pub mesh: String,
    /// Rounds made (the most any cell got).
    pub rounds: usize,
    /// Of them, extra rounds for wide or wanted cells.
    pub extra: usize,
    /// Wall time of all of them, seconds.
    pub seconds: f64,
}

/// A mesh of the run.
#[derive(Clone, Debug, serde::Serialize)]
pub struct MeshInfo {
    /// Its name (e.g. `torus-16k`).
    pub name: String,
    /// Its family (`torus`, `grid`, or `real`).
    pub family: String,
    /// Vertices.
    pub vertices: usize,
    /// Faces.
    pub faces: usize,
    /// Triangles (faces, when all are triangles).
    pub triangles: usize,
    /// A small SVG rendering.
    #[serde(skip)]
    pub thumbnail_svg: String,
    /// Its element counts, for the limits of its sweeps (`None` when its edges cannot be
    /// analysed).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub counts: Option<MeshCounts>,
    /// What `topolab repair` changed, when the file as read was refused by the structures
    /// that need an oriented manifold and its repaired version was measured instead.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub repaired: Option<topolab_structures::repair::RepairLog>,
}

/// One libigl reference timing.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct LibiglRow {
    /// Mesh name.
    pub mesh: String,
    /// The operator (or workload) whose answer it computes.
    pub operator: Subject,
    /// The libigl function.
    pub function: String,
    /// Its checksum.
    pub checksum: String,
    /// Whether the checksum equals the lab's.
    pub agrees: bool,
    /// Nanoseconds per element (whole-mesh build divided by elements).
    pub ns_per_item: f64,
}

/// What a structure stores for the open tetrahedron.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Teaching {
    /// Structure.
    pub structure: String,
    /// Its `explain` text.
    pub text: String,
}

impl Results {
    /// Puts its limit ([`crate::measuring::speed_limit::limit`]) on every measured sweep whose
    /// structure declares an access model for the operator, on a mesh of the run whose counts are
    /// known.
    pub fn annotate_limits(&mut self) {
        let Results {
            structures,
            meshes,
            measurements,
            probe,
            ..
        } = self;
        for m in measurements
            .iter_mut()
            .filter(|m| m.kernel == Kernel::Sweep && m.status == Status::Measured)
        {
            let Subject::Query(op) = m.operator else {
                continue;
            };
            let Some(s) = structures.iter().find(|s| s.name == m.structure) else {
                continue;
            };
            let model = |op| {
                s.costs
                    .iter()
                    .find(|c| c.operator == op)
                    .and_then(|c| c.access.as_ref())
            };
            let counts = meshes
                .iter()
                .find(|x| x.name == m.mesh)
                .and_then(|x| x.counts);
            if let (Some(access), Some(counts)) = (model(op), counts) {
                m.limit = crate::measuring::speed_limit::limit(
                    access,
                    model(Operator::R10),
                    op,
                    &counts,
                    m.items,
                    probe,
                );
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::Workload;

    fn cell(operator: Subject, kernel: Kernel) -> Measurement {
        Measurement {
            ns_per_item: Some(9540.225490196079),
            min_ns_per_item: Some(9504.588235294117),
            max_ns_per_item: Some(49622.12745098039),
            items: 102,
            reps: 23,
            checksum: Some("13793524636986848482".into()),
            ..Measurement::new("explicit", operator, kernel, "torus-200", "torus", 204)
        }
    }

    /// A measurement of results.json as the report wrote it before its fields were typed.
    const R02_SWEEP: &str = r#"{
  "structure": "explicit",
  "operator": "r02",
  "kernel": "sweep",
  "mesh": "torus-200",
  "family": "torus",
  "triangles": 204,
  "status": "measured",
  "ns_per_item": 9540.225490196079,
  "min_ns_per_item": 9504.588235294117,
  "max_ns_per_item": 49622.12745098039,
  "items": 102,
  "reps": 23,
  "checksum": "13793524636986848482",
  "bytes": null,
  "peak_bytes": null,
  "declared_bytes": null,
  "estimate_ns_per_item": null,
  "native": false,
  "note": null
}"#;

    #[test]
    fn a_measurement_serializes_as_results_json_always_had_it() {
        let m = cell(Subject::Query(Operator::R02), Kernel::Sweep);
        assert_eq!(serde_json::to_string_pretty(&m).unwrap(), R02_SWEEP);
        for (subject, kernel, operator_field, kernel_field) in [
            (
                Subject::Construction,
                Kernel::Construction,
                "construction",
                "construction",
            ),
            (
                Subject::Query(Operator::BoundaryVertex),
                Kernel::Sampled,
                "boundary-vertex",
                "sampled",
            ),
            (
                Subject::Workload(Workload::Circulators),
                Kernel::Workload,
                "circulators",
                "workload",
            ),
        ] {
            let v = serde_json::to_value(cell(subject, kernel)).unwrap();
            assert_eq!(v["operator"], operator_field);
            assert_eq!(v["kernel"], kernel_field);
        }
    }

    #[test]
    fn measurements_round_trip_and_unknown_names_are_refused() {
        let parsed: Measurement = serde_json::from_str(R02_SWEEP).unwrap();
        assert_eq!(
            (parsed.operator, parsed.kernel, parsed.status),
            (
                Subject::Query(Operator::R02),
                Kernel::Sweep,
                Status::Measured
            )
        );
        for subject in Operator::ALL
            .map(Subject::Query)
            .into_iter()
            .chain(Workload::ALL.map(Subject::Workload))
            .chain([Subject::Construction])
        {
            // Names are distinct: each one parses back to its own subject.
            assert_eq!(Subject::from_name(subject.name()), Some(subject));
            for kernel in Kernel::ALL {
                let mut m = cell(subject, kernel);
                // serde_json reads decimals back exactly only when they are binary fractions.
                (m.ns_per_item, m.min_ns_per_item, m.max_ns_per_item) =
                    (Some(9540.25), Some(9504.5), Some(49622.125));
                let text = serde_json::to_string(&m).unwrap();
                assert_eq!(serde_json::from_str::<Measurement>(&text).unwrap(), m);
            }
        }
        let wrong = R02_SWEEP.replace("\"r02\"", "\"r03\"");
        let err = serde_json::from_str::<Measurement>(&wrong).unwrap_err();
        assert!(
            err.to_string().contains("unknown operator \"r03\""),
            "{err}"
        );
        let wrong = R02_SWEEP.replace("\"sweep\"", "\"swept\"");
        assert!(serde_json::from_str::<Measurement>(&wrong).is_err());
    }

    #[test]
    fn costs_and_fits_are_written_in_the_lecture_notation() {
        let cost = CostRow {
            operator: Operator::EdgeSuccessor,
            cost: Cost::Boundary,
            expected_exponent: 0.5,
            access: None,
        };
        assert_eq!(
            serde_json::to_string(&cost).unwrap(),
            r#"{"operator":"edge-successor","cost":"O(∂n1)","expected_exponent":0.5}"#
        );
        let fit = FitRow {
            structure: "che-l0".into(),
            operator: Operator::BoundaryEdge,
            kernel: Kernel::Sampled,
            family: "grid".into(),
            exponent: 0.9257697736871451,
            class: "linear".into(),
            theory: Cost::Linear,
            expected_exponent: 1.0,
            agrees: true,
            points: 2,
        };
        assert_eq!(
            serde_json::to_string_pretty(&fit).unwrap(),
            r#"{
  "structure": "che-l0",
  "operator": "boundary-edge",
  "kernel": "sampled",
  "family": "grid",
  "exponent": 0.9257697736871451,
  "class": "linear",
  "theory": "O(n)",
  "expected_exponent": 1.0,
  "agrees": true,
  "points": 2
}"#
        );
    }
}

/// What one cell of the report's edit-ops section ([`crate::report::sections::edit_ops`])
/// gave.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
#[serde(rename_all = "kebab-case", tag = "status")]
pub enum EditOpOutcome {
    /// Timed.
    Measured {
        /// Median nanoseconds per operation over the samples.
        ns_per_op: f64,
        /// Samples, each on a fresh mesh.
        samples: usize,
        /// Operations timed together per sample.
        ops_per_sample: usize,
        /// The samples' checksums, summed (compared between structures).
        checksum: u64,
    },
    /// The structure does not offer the operation.
    NotOffered,
    /// Skipped: the declared cost predicts too long, or the preparation needs an operation
    /// the structure does not offer.
    Skipped {
        /// Why (the same words on every mesh, so that the notes group them).
        reason: String,
        /// What differs by mesh (the estimate).
        detail: Option<String>,
    },
}

/// One operation on one structure and torus.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct EditOpRow {
    /// The operation.
    pub op: topolab_structures::EditOp,
    /// The torus.
    pub mesh: String,
    /// Its faces.
    pub faces: usize,
    /// The structure.
    pub structure: String,
    /// The cost it declares for the operation.
    pub declared: Cost,
    /// What was measured, or why not.
    pub outcome: EditOpOutcome,
}
