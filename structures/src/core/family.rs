//! The family a structure belongs to: what it stores to answer adjacency, as the lecture on
//! polygon-mesh data structures and the CHE thesis chapter group them (the folders of
//! [`crate::families`]). The report draws each family in one hue and picks structures by it;
//! it is declared with the structure ([`crate::MeshTopology::FAMILY`]), never read from a name.

/// What a structure stores for adjacency; one per folder of [`crate::families`], plus
/// [`Family::Outside`] for everything the lab did not write.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Family {
    /// Faces as lists of corners, nothing stored for adjacency: every vertex relation scans
    /// the faces (explicit storage, the vertex list).
    CornerLists,
    /// A record per edge with its faces (the edge list) and, doubly linked, its wings (the
    /// winged-edge).
    EdgeLists,
    /// Half-edges with `next` and `pair`, by pointers or by indices.
    HalfEdge,
    /// The Compact Half-Edge levels of the CHE thesis chapter: integer arrays, one more
    /// container per level.
    Che,
    /// Implicit topology: arithmetic on a regular grid's counts.
    RegularGrid,
    /// A Rust crate from crates.io (lox, baby_shark, tri-mesh), behind an adapter of the lab:
    /// what a Rust user would depend on instead of the lab.
    RustCrate,
    /// Not of the lab: a baseline library (OpenMesh) or a structure from another crate.
    Outside,
}

impl Family {
    /// Every family, in the order the report lists them.
    pub const ALL: [Family; 7] = [
        Family::CornerLists,
        Family::EdgeLists,
        Family::HalfEdge,
        Family::Che,
        Family::RegularGrid,
        Family::RustCrate,
        Family::Outside,
    ];

    /// The kebab-case name results and the page use.
    pub const fn name(self) -> &'static str {
        match self {
            Family::CornerLists => "corner-lists",
            Family::EdgeLists => "edge-lists",
            Family::HalfEdge => "half-edge",
            Family::Che => "che",
            Family::RegularGrid => "regular-grid",
            Family::RustCrate => "rust-crate",
            Family::Outside => "outside",
        }
    }
}

impl std::fmt::Display for Family {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_distinct_and_round_trip_through_serde() {
        for (i, a) in Family::ALL.iter().enumerate() {
            for b in &Family::ALL[..i] {
                assert_ne!(a.name(), b.name());
            }
            let json = serde_json::to_string(a).unwrap();
            assert_eq!(json, format!("\"{}\"", a.name()));
            assert_eq!(serde_json::from_str::<Family>(&json).unwrap(), *a);
        }
    }
}
