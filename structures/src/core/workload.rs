//! The application [`Workload`]s the harness times on every structure: named here, next to the
//! [`crate::Operator`]s, so that a baseline's [`crate::NativeKernels`] can be asked for one by
//! type. The harness runs them (`topolab_harness::measuring::kernels::run_workload`).

use crate::core::operator::Operator;

/// The application workloads of the Surface_mesh benchmark (Sieger & Botsch, IMR 2011).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Workload {
    /// For each vertex count its faces, for each face subtract its vertices: the total is 0.
    Circulators,
    /// The mean of all positions.
    Barycenter,
    /// Face normals, then vertex normals as the normalised sum of unit face normals.
    Normals,
    /// One step of uniform 1-ring averaging of interior vertices.
    Smoothing,
}

impl Workload {
    /// Every workload.
    pub const ALL: [Workload; 4] = [
        Workload::Circulators,
        Workload::Barycenter,
        Workload::Normals,
        Workload::Smoothing,
    ];

    /// The kebab-case name.
    pub const fn name(self) -> &'static str {
        match self {
            Workload::Circulators => "circulators",
            Workload::Barycenter => "barycenter",
            Workload::Normals => "normals",
            Workload::Smoothing => "smoothing",
        }
    }

    /// The workload of a kebab-case name.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|w| w.name() == name)
    }

    /// The relations it asks once per element (for estimating its cost).
    pub fn relations(self) -> &'static [Operator] {
        match self {
            Workload::Circulators => &[Operator::R02, Operator::R20],
            Workload::Barycenter => &[],
            Workload::Normals => &[Operator::R20, Operator::R02],
            Workload::Smoothing => &[Operator::R00, Operator::BoundaryVertex],
        }
    }

    /// How many items one run handles on a mesh of `vertices` and `faces` (for ns per item).
    pub fn items(self, vertices: usize, faces: usize) -> usize {
        match self {
            Workload::Circulators | Workload::Normals => vertices + faces,
            Workload::Barycenter | Workload::Smoothing => vertices,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_parse_back_and_serialize_as_written() {
        for w in Workload::ALL {
            assert_eq!(Workload::from_name(w.name()), Some(w));
            assert_eq!(
                serde_json::to_value(w).unwrap(),
                serde_json::Value::from(w.name())
            );
        }
        assert_eq!(Workload::from_name("r00"), None);
    }
}
