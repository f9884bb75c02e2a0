//! # topolab-registry
//!
//! Every structure of this build by name, in one list: the lab's own
//! ([`topolab_structures::registry`]), the C++ baselines compiled in
//! ([`topolab_baselines::compiled`]: OpenMesh, CGAL's two halfedge structures), then, with the
//! feature `peers`, the Rust crates of `topolab-peers` (lox's two structures, baby_shark's
//! corner table, tri-mesh; see [`peer_crate`]). It sits above the FFI crate and the peers,
//! which know nothing of each other: the CLI, the report and the benches go through it, so
//! `topolab list`, `topolab info --structure NAME` and every table of the report include them
//! all, and [`Lab`] is that list as one [`Structures`] type.
#![deny(missing_docs)]
#![forbid(unsafe_code)]

pub use topolab_baselines::compiled::{
    absent_baselines, missing_baseline, note_absent, qhull_description, CGAL_POLYHEDRON,
    CGAL_SURFACE_MESH, CPP_BASELINES, OPENMESH,
};
use topolab_structures::core::edit::edits_topology;
use topolab_structures::registry as structures;
pub use topolab_structures::registry::{EditVisitor, StructureVisitor, Structures};

#[cfg(feature = "peers")]
const PEER_NAMES: &[&str] = &topolab_peers::NAMES;
#[cfg(not(feature = "peers"))]
const PEER_NAMES: &[&str] = &[];

/// Whether this build has the Rust crates of `topolab-peers` (the feature `peers`).
pub const HAS_PEERS: bool = cfg!(feature = "peers");

/// The C++ baselines compiled in ([`topolab_baselines::compiled::COMPILED`]).
const COMPILED: &[&str] = topolab_baselines::compiled::COMPILED;

/// Names of every structure, in report order: the lab's, then the C++ baselines, then the
/// Rust crates.
pub const NAMES: &[&str] = &concat::<
    { structures::NAMES.len() + COMPILED.len() + PEER_NAMES.len() },
    3,
>([structures::NAMES, COMPILED, PEER_NAMES]);

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

/// Runs `visitor` with the structure called `name`; `None` if there is none in this build.
pub fn visit<V: StructureVisitor>(name: &str, visitor: V) -> Option<V::Output> {
    let visitor = match topolab_baselines::compiled::visit(name, visitor) {
        Ok(output) => return Some(output),
        Err(visitor) => visitor,
    };
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
/// `name`: the C++ baselines compiled in (OpenMesh and CGAL's two structures, through their
/// own Euler operations), then, with the feature `peers`, the Rust crates whose adapters
/// implement `MeshEdit` (`topolab_peers::registry::EDITABLE`: the operations each crate
/// offers, the others refused as not implemented, which `MeshEdit::supports` tells), then the
/// lab's structures marked `[editable]` in its registry list. `None` if there is none of that
/// name in this build or it does not edit.
///
/// Callers that need more than `MeshEdit` offers tell the baselines apart by
/// [`CPP_BASELINES`]: the report runs their changing workloads natively
/// ([`NATIVE_CHANGING`]), and `explain --op`, which lists a structure's records, cannot list
/// records kept inside a C++ library.
pub fn visit_editable<V: EditVisitor>(name: &str, visitor: V) -> Option<V::Output> {
    let visitor = match topolab_baselines::compiled::visit_editable(name, visitor) {
        Ok(output) => return Some(output),
        Err(visitor) => visitor,
    };
    #[cfg(feature = "peers")]
    let visitor = match topolab_peers::registry::visit_editable(name, visitor) {
        Ok(output) => return Some(output),
        Err(visitor) => visitor,
    };
    structures::visit_editable(name, visitor)
}

/// The baselines that run the changing workloads natively, the whole workload in C++ through
/// their own Euler operations (OpenMesh's, CGAL's), when compiled in.
pub const NATIVE_CHANGING: &[&str] = COMPILED;

/// Does the structure called `name` offer `op` ([`MeshEdit::supports`](topolab_structures::MeshEdit::supports))?
/// `None` where it implements no `MeshEdit` (or there is none of that name).
pub fn offers(name: &str, op: topolab_structures::EditOp) -> Option<bool> {
    struct Offers(topolab_structures::EditOp);
    impl EditVisitor for Offers {
        type Output = bool;
        fn visit<M: topolab_structures::MeshEdit>(self) -> bool {
            M::supports(self.0)
        }
    }
    visit_editable(name, Offers(op))
}

/// Does the structure called `name` change a mesh's topology: through `MeshEdit`'s
/// topological edits ([`visit_editable`], [`edits_topology`]) or natively
/// ([`NATIVE_CHANGING`])? Explicit storage implements `MeshEdit` for its moves only: not
/// editable in this sense.
pub fn is_editable(name: &str) -> bool {
    struct Probe;
    impl EditVisitor for Probe {
        type Output = bool;
        fn visit<M: topolab_structures::MeshEdit>(self) -> bool {
            edits_topology::<M>()
        }
    }
    visit_editable(name, Probe) == Some(true) || NATIVE_CHANGING.contains(&name)
}

/// Every structure of this build of the lab (this crate's list: the structures of
/// `topolab-structures`, then the C++ baselines compiled in, then the Rust crates) as a [`Structures`] list, for
/// the report and the `cargo bench` groups of the harness.
#[derive(Copy, Clone, Debug)]
pub struct Lab;

impl Structures for Lab {
    fn names(out: &mut Vec<&'static str>) {
        out.extend_from_slice(NAMES);
    }
    fn visit<V: StructureVisitor>(name: &str, visitor: V) -> Result<V::Output, V> {
        if NAMES.contains(&name) {
            Ok(visit(name, visitor).expect("a registered name visits its structure"))
        } else {
            Err(visitor)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_extend_the_crate_registry() {
        assert_eq!(&NAMES[..structures::NAMES.len()], structures::NAMES);
        assert_eq!(NAMES.contains(&OPENMESH), topolab_baselines::HAS_OPENMESH);
        assert_eq!(
            NAMES.contains(&CGAL_SURFACE_MESH),
            topolab_baselines::HAS_CGAL
        );
        assert_eq!(
            NAMES.contains(&CGAL_POLYHEDRON),
            topolab_baselines::HAS_CGAL
        );
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
        assert_eq!(is_editable(OPENMESH), topolab_baselines::HAS_OPENMESH);
        assert_eq!(is_editable(CGAL_SURFACE_MESH), topolab_baselines::HAS_CGAL);
        assert_eq!(is_editable(CGAL_POLYHEDRON), topolab_baselines::HAS_CGAL);
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
    fn the_lab_is_every_registered_structure_and_only_those() {
        assert_eq!(topolab_structures::registry::names::<Lab>(), NAMES);
        for &name in NAMES {
            assert_eq!(Lab::visit(name, Name).ok(), Some(name));
        }
        assert!(Lab::visit("no-such-structure", Name).is_err());
    }

    struct Name;
    impl StructureVisitor for Name {
        type Output = &'static str;
        fn visit<M: topolab_structures::MeshTopology>(self) -> &'static str {
            M::NAME
        }
    }
}
