//! The C++ baselines of this build by name: which ones `build.rs` compiled in
//! ([`COMPILED`]), one visit of each by its name (the single `cfg` ladder of the crate, for a
//! structure visitor and an editing one alike), and what to install for those left out. The
//! registry of every structure (`topolab-registry`) chains these after the lab's own.

pub use topolab_structures::registry::{EditVisitor, StructureVisitor};

/// The name of the OpenMesh baseline (whether or not this build includes it).
pub const OPENMESH: &str = "openmesh";
/// The name of CGAL's `Surface_mesh` baseline (whether or not this build includes it).
pub const CGAL_SURFACE_MESH: &str = "cgal-surface-mesh";
/// The name of CGAL's `Polyhedron_3` baseline (whether or not this build includes it).
pub const CGAL_POLYHEDRON: &str = "cgal-polyhedron";

/// The C++ baselines, whether or not this build includes them.
pub const CPP_BASELINES: [&str; 3] = [OPENMESH, CGAL_SURFACE_MESH, CGAL_POLYHEDRON];

/// The C++ baselines this build compiled in, in [`CPP_BASELINES`] order. Each implements
/// `MeshEdit` through its library's Euler operations and runs the changing workloads natively.
pub const COMPILED: &[&str] = match (cfg!(has_openmesh), cfg!(has_cgal)) {
    (true, true) => &[OPENMESH, CGAL_SURFACE_MESH, CGAL_POLYHEDRON],
    (true, false) => &[OPENMESH],
    (false, true) => &[CGAL_SURFACE_MESH, CGAL_POLYHEDRON],
    (false, false) => &[],
};

/// The one ladder of the compiled-in baselines: `return Ok($visitor.visit::<Type>())` for the
/// one called `$name`, whichever visitor trait `$visitor` implements.
macro_rules! visit_compiled {
    ($name:expr, $visitor:ident) => {{
        #[cfg(has_openmesh)]
        if $name == OPENMESH {
            return Ok($visitor.visit::<crate::openmesh::OpenMesh>());
        }
        #[cfg(has_cgal)]
        if $name == CGAL_SURFACE_MESH {
            return Ok($visitor.visit::<crate::cgal::SurfaceMesh>());
        }
        #[cfg(has_cgal)]
        if $name == CGAL_POLYHEDRON {
            return Ok($visitor.visit::<crate::cgal::Polyhedron>());
        }
        let _ = $name; // the ladder is empty in a build without the C++ baselines
        Err($visitor)
    }};
}

/// Runs `visitor` with the compiled-in baseline called `name`, or hands it back.
pub fn visit<V: StructureVisitor>(name: &str, visitor: V) -> Result<V::Output, V> {
    visit_compiled!(name, visitor)
}

/// Runs `visitor` with the compiled-in baseline called `name` as a `MeshEdit` structure (every
/// one is), or hands it back.
pub fn visit_editable<V: EditVisitor>(name: &str, visitor: V) -> Result<V::Output, V> {
    visit_compiled!(name, visitor)
}

/// Why a baseline named `name` is not in this build (what to install), or `None` when `name`
/// is not one of the baselines this build left out.
pub fn missing_baseline(name: &str) -> Option<&'static str> {
    if name == OPENMESH && !crate::HAS_OPENMESH {
        Some(crate::OPENMESH_MISSING)
    } else if (name == CGAL_SURFACE_MESH || name == CGAL_POLYHEDRON) && !crate::HAS_CGAL {
        Some(crate::CGAL_MISSING)
    } else {
        None
    }
}

/// The C++ baselines this build left out, each with why (what to install), in
/// [`CPP_BASELINES`] order.
pub fn absent_baselines() -> Vec<(&'static str, &'static str)> {
    CPP_BASELINES
        .into_iter()
        .filter_map(|name| missing_baseline(name).map(|why| (name, why)))
        .collect()
}

/// Adds to the report's `notes` which baselines this build left out and why, one note per
/// reason (CGAL's two structures and its hull share one).
pub fn note_absent(notes: &mut Vec<String>) {
    let absent = absent_baselines();
    let mut reasons: Vec<&str> = absent.iter().map(|&(_, why)| why).collect();
    reasons.dedup();
    for why in reasons {
        let names: Vec<&str> = absent
            .iter()
            .filter(|&&(_, w)| w == why)
            .map(|&(name, _)| name)
            .collect();
        notes.push(format!("No {} column: {why}.", names.join(" and ")));
    }
}

/// How the report's hull section runs Qhull (`qhull::description`), when it is compiled in.
#[cfg(has_qhull)]
pub fn qhull_description() -> Option<String> {
    Some(crate::qhull::description())
}

/// How the report's hull section runs Qhull: not at all, it is not compiled in.
#[cfg(not(has_qhull))]
pub fn qhull_description() -> Option<String> {
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Name;
    impl StructureVisitor for Name {
        type Output = &'static str;
        fn visit<M: topolab_structures::MeshTopology>(self) -> &'static str {
            M::NAME
        }
    }
    struct EditName;
    impl EditVisitor for EditName {
        type Output = &'static str;
        fn visit<M: topolab_structures::MeshEdit>(self) -> &'static str {
            M::NAME
        }
    }

    #[test]
    fn each_compiled_baseline_is_visited_as_itself_and_the_others_handed_back() {
        assert_eq!(COMPILED.contains(&OPENMESH), crate::HAS_OPENMESH);
        assert_eq!(COMPILED.contains(&CGAL_SURFACE_MESH), crate::HAS_CGAL);
        assert_eq!(COMPILED.contains(&CGAL_POLYHEDRON), crate::HAS_CGAL);
        for name in CPP_BASELINES {
            let there = COMPILED.contains(&name).then_some(name);
            assert_eq!(visit(name, Name).ok(), there, "{name}");
            assert_eq!(visit_editable(name, EditName).ok(), there, "{name}");
        }
        assert!(visit("index-half-edge", Name).is_err());
    }

    #[test]
    fn a_missing_baseline_says_what_to_install() {
        for name in CPP_BASELINES {
            match missing_baseline(name) {
                Some(why) => {
                    assert!(!COMPILED.contains(&name), "{name} is compiled in");
                    // Says how to get it: a Debian package (CGAL) or the pinned source
                    // (OpenMesh), and how to build with it again.
                    assert!(why.contains(".ci/install-deps"), "{why}");
                    assert!(why.contains("rebuild"), "{why}");
                }
                None => assert!(
                    COMPILED.contains(&name),
                    "{name} is neither there nor missing"
                ),
            }
        }
        assert_eq!(missing_baseline("vertex-list"), None);
        assert_eq!(
            absent_baselines().len() + COMPILED.len(),
            CPP_BASELINES.len()
        );
    }

    #[test]
    fn the_report_notes_each_missing_baseline_once_with_why() {
        let mut notes = Vec::new();
        note_absent(&mut notes);
        let absent = absent_baselines();
        for (name, why) in &absent {
            let with: Vec<_> = notes.iter().filter(|n| n.contains(why)).collect();
            assert_eq!(with.len(), 1, "{notes:?}");
            assert!(with[0].contains(name), "{notes:?}");
        }
        if absent.is_empty() {
            assert!(notes.is_empty(), "{notes:?}");
        }
    }
}
