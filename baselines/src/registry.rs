//! Every structure of the lab by name: those of [`topolab_structures::registry`] plus the C++
//! baselines when they are compiled in, then the Rust crates of `topolab-peers` when the
//! feature `peers` is on (lox's two structures, baby_shark's corner table, tri-mesh; see
//! [`peer_crate`]). The C++ baselines when they are compiled in: OpenMesh ([`crate::openmesh::OpenMesh`], name
//! `openmesh`) and CGAL's two halfedge structures ([`crate::cgal::SurfaceMesh`],
//! `cgal-surface-mesh`; [`crate::cgal::Polyhedron`], `cgal-polyhedron`). The CLI and the
//! report go through this registry, so `topolab list`, `topolab info --structure NAME` and
//! every table of the report include them.

use topolab_structures::registry as structures;
pub use topolab_structures::registry::{EditVisitor, StructureVisitor};

/// The name of the OpenMesh baseline (whether or not this build includes it).
pub const OPENMESH: &str = "openmesh";
/// The name of CGAL's `Surface_mesh` baseline (whether or not this build includes it).
pub const CGAL_SURFACE_MESH: &str = "cgal-surface-mesh";
/// The name of CGAL's `Polyhedron_3` baseline (whether or not this build includes it).
pub const CGAL_POLYHEDRON: &str = "cgal-polyhedron";

const OPENMESH_NAMES: &[&str] = if cfg!(has_openmesh) { &[OPENMESH] } else { &[] };
const CGAL_NAMES: &[&str] = if cfg!(has_cgal) {
    &[CGAL_SURFACE_MESH, CGAL_POLYHEDRON]
} else {
    &[]
};

#[cfg(feature = "peers")]
const PEER_NAMES: &[&str] = &topolab_peers::NAMES;
#[cfg(not(feature = "peers"))]
const PEER_NAMES: &[&str] = &[];

/// Whether this build has the Rust crates of `topolab-peers` (the feature `peers`).
pub const HAS_PEERS: bool = cfg!(feature = "peers");

/// Names of every structure, in report order: the crate's, then the C++ baselines, then the
/// Rust crates.
pub const NAMES: &[&str] = &concat::<
    { structures::NAMES.len() + OPENMESH_NAMES.len() + CGAL_NAMES.len() + PEER_NAMES.len() },
    4,
>([structures::NAMES, OPENMESH_NAMES, CGAL_NAMES, PEER_NAMES]);

const fn concat<const N: usize, const P: usize>(parts: [&[&'static str]; P]) -> [&'static str; N] {
    let mut out = [""; N];
    let (mut i, mut part) = (0, 0);
    while part < parts.len() {
        let mut j = 0;
        while j < parts[part].len() {
            out[i] = parts[part][j];
            i += 1;
            j += 1;
        }
        part += 1;
    }
    out
}

/// The C++ baselines, whether or not this build includes them.
pub const CPP_BASELINES: [&str; 3] = [OPENMESH, CGAL_SURFACE_MESH, CGAL_POLYHEDRON];

/// Runs `visitor` with the structure called `name`; `None` if there is none in this build.
pub fn visit<V: StructureVisitor>(name: &str, visitor: V) -> Option<V::Output> {
    #[cfg(has_openmesh)]
    if name == OPENMESH {
        return Some(visitor.visit::<crate::openmesh::OpenMesh>());
    }
    #[cfg(has_cgal)]
    if name == CGAL_SURFACE_MESH {
        return Some(visitor.visit::<crate::cgal::SurfaceMesh>());
    }
    #[cfg(has_cgal)]
    if name == CGAL_POLYHEDRON {
        return Some(visitor.visit::<crate::cgal::Polyhedron>());
    }
    #[cfg(feature = "peers")]
    let visitor = match topolab_peers::registry::visit(name, visitor) {
        Ok(output) => return Some(output),
        Err(visitor) => visitor,
    };
    structures::visit(name, visitor)
}

/// The crates of `topolab-peers` (name, exact version, structures, how they are used and what
/// differs), for the report's "How the baselines are run".
#[cfg(feature = "peers")]
pub use topolab_peers::{PeerCrate, CRATES as PEER_CRATES};

/// The crate from crates.io (its name and exact version) that the structure called `name`
/// adapts, `None` for the lab's own structures and the C++ baselines (and for every name in
/// a build without the feature `peers`).
pub fn peer_crate(name: &str) -> Option<(&'static str, &'static str)> {
    #[cfg(feature = "peers")]
    if let Some(c) = topolab_peers::crate_of(name) {
        return Some((c.name, c.version));
    }
    let _ = name;
    None
}

/// Runs `visitor` with the editable structure (one that implements `MeshEdit`) called
/// `name`: the crate's structures marked `[editable]` in its registry list, then the
/// baselines that implement `MeshEdit` (a baseline that does is one line here,
/// `#[cfg(has_x)] if name == X { return Some(visitor.visit::<X>()); }`): OpenMesh and CGAL's
/// two structures, through their own Euler operations; then, with the feature `peers`, the
/// Rust crates whose adapters implement `MeshEdit` (`topolab_peers::registry::EDITABLE`: the
/// operations each crate offers, the others refused as not implemented, which
/// `MeshEdit::supports` tells). `None` if there is none of that name in this build or it
/// does not edit.
///
/// Callers that need more than `MeshEdit` offers tell the baselines apart by
/// [`CPP_BASELINES`]: the report runs their changing workloads natively
/// ([`NATIVE_CHANGING`]), and `explain --op`, which lists a structure's records, cannot list
/// records kept inside a C++ library.
pub fn visit_editable<V: EditVisitor>(name: &str, visitor: V) -> Option<V::Output> {
    #[cfg(has_openmesh)]
    if name == OPENMESH {
        return Some(visitor.visit::<crate::openmesh::OpenMesh>());
    }
    #[cfg(has_cgal)]
    if name == CGAL_SURFACE_MESH {
        return Some(visitor.visit::<crate::cgal::SurfaceMesh>());
    }
    #[cfg(has_cgal)]
    if name == CGAL_POLYHEDRON {
        return Some(visitor.visit::<crate::cgal::Polyhedron>());
    }
    #[cfg(feature = "peers")]
    let visitor = match topolab_peers::registry::visit_editable(name, visitor) {
        Ok(output) => return Some(output),
        Err(visitor) => visitor,
    };
    structures::visit_editable(name, visitor)
}

/// The baselines that run the changing workloads natively, the whole workload in C++ through
/// their own Euler operations (OpenMesh's, CGAL's), when compiled in.
pub const NATIVE_CHANGING: &[&str] =
    &concat::<{ OPENMESH_NAMES.len() + CGAL_NAMES.len() }, 2>([OPENMESH_NAMES, CGAL_NAMES]);

/// Does the structure called `name` change meshes: through `MeshEdit`
/// ([`visit_editable`]) or natively ([`NATIVE_CHANGING`])?
pub fn is_editable(name: &str) -> bool {
    struct Probe;
    impl EditVisitor for Probe {
        type Output = ();
        fn visit<M: topolab_structures::MeshEdit>(self) {}
    }
    visit_editable(name, Probe).is_some() || NATIVE_CHANGING.contains(&name)
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

    #[test]
    fn names_extend_the_crate_registry() {
        assert_eq!(&NAMES[..structures::NAMES.len()], structures::NAMES);
        assert_eq!(NAMES.contains(&OPENMESH), crate::HAS_OPENMESH);
        assert_eq!(NAMES.contains(&CGAL_SURFACE_MESH), crate::HAS_CGAL);
        assert_eq!(NAMES.contains(&CGAL_POLYHEDRON), crate::HAS_CGAL);
        // Each name once, and each visits the structure of that name.
        for (i, name) in NAMES.iter().enumerate() {
            assert!(!NAMES[..i].contains(name), "{name} twice");
            assert_eq!(visit(name, Name), Some(*name));
        }
    }

    #[test]
    fn editability_comes_from_the_registry_capability() {
        for name in [
            "index-half-edge",
            "winged-edge",
            "edge-list",
            "vertex-list",
            "che-l2",
        ] {
            assert!(is_editable(name), "{name}");
        }
        for name in ["regular-grid", "explicit", "no-such-structure"] {
            assert!(!is_editable(name), "{name}");
        }
        assert_eq!(is_editable(OPENMESH), crate::HAS_OPENMESH);
        assert_eq!(is_editable(CGAL_SURFACE_MESH), crate::HAS_CGAL);
        assert_eq!(is_editable(CGAL_POLYHEDRON), crate::HAS_CGAL);
    }

    #[test]
    fn every_baseline_in_this_build_is_visited_as_an_editable_structure_as_itself() {
        struct EditName;
        impl EditVisitor for EditName {
            type Output = &'static str;
            fn visit<M: topolab_structures::MeshEdit>(self) -> &'static str {
                M::NAME
            }
        }
        for name in CPP_BASELINES {
            let expected = NAMES.contains(&name).then_some(name);
            assert_eq!(visit_editable(name, EditName), expected, "{name}");
        }
        for name in structures::editable_names() {
            assert_eq!(visit_editable(name, EditName), Some(name));
        }
        // The Rust crates that edit, with the feature `peers`; none without it.
        for name in PEER_NAMES {
            #[cfg(feature = "peers")]
            let expected = topolab_peers::registry::EDITABLE
                .contains(name)
                .then_some(*name);
            #[cfg(not(feature = "peers"))]
            let expected = None;
            assert_eq!(visit_editable(name, EditName), expected, "{name}");
        }
    }

    #[test]
    fn a_missing_baseline_says_what_to_install() {
        for name in [OPENMESH, CGAL_SURFACE_MESH, CGAL_POLYHEDRON] {
            match missing_baseline(name) {
                Some(why) => {
                    assert!(!NAMES.contains(&name), "{name} is registered");
                    // Says how to get it: a Debian package (CGAL) or the pinned source
                    // (OpenMesh), and how to build with it again.
                    assert!(why.contains(".ci/install-deps"), "{why}");
                    assert!(why.contains("rebuild"), "{why}");
                }
                None => assert!(NAMES.contains(&name), "{name} is neither there nor missing"),
            }
        }
        assert_eq!(missing_baseline("vertex-list"), None);
        let absent = absent_baselines();
        assert!(absent.iter().all(|(name, _)| !NAMES.contains(name)));
        assert_eq!(
            absent.len() + NAMES.len(),
            structures::NAMES.len() + CPP_BASELINES.len() + PEER_NAMES.len()
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

    struct Name;
    impl StructureVisitor for Name {
        type Output = &'static str;
        fn visit<M: topolab_structures::MeshTopology>(self) -> &'static str {
            M::NAME
        }
    }
}
