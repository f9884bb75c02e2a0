//! The peers as one [`Structures`] list, which the lab's registry
//! (`topolab_registry`, behind its feature `peers`) chains after its own, as
//! a crate outside the lab joins a run; and those that implement
//! [`MeshEdit`](topolab_structures::MeshEdit) ([`EDITABLE`], [`visit_editable`]), chained
//! after the lab's editable structures the same way.

use crate::baby_shark_corner_table::BabySharkCornerTable;
use crate::lox_directed_edge::LoxDirectedEdge;
use crate::lox_half_edge::LoxHalfEdge;
use crate::tri_mesh::TriMesh;
use topolab_structures::registry::{EditVisitor, StructureVisitor, Structures};
use topolab_structures::MeshTopology;

/// Every peer, in registry order ([`crate::crates::NAMES`]).
pub type Peers = (LoxHalfEdge, LoxDirectedEdge, BabySharkCornerTable, TriMesh);

/// Runs `visitor` with the peer called `name`, or hands it back when no peer has that name
/// (so the caller can go on to other lists).
pub fn visit<V: StructureVisitor>(name: &str, visitor: V) -> Result<V::Output, V> {
    <Peers as Structures>::visit(name, visitor)
}

/// The peers that implement `MeshEdit`, in registry order: each does the operations its
/// crate offers and refuses the others (`MeshEdit::supports`).
pub const EDITABLE: [&str; 4] = [
    LoxHalfEdge::NAME,
    LoxDirectedEdge::NAME,
    BabySharkCornerTable::NAME,
    TriMesh::NAME,
];

/// Runs `visitor` with the editable peer called `name`, or hands it back when no peer of
/// that name edits (so the caller can go on to other lists).
pub fn visit_editable<V: EditVisitor>(name: &str, visitor: V) -> Result<V::Output, V> {
    if name == LoxHalfEdge::NAME {
        Ok(visitor.visit::<LoxHalfEdge>())
    } else if name == LoxDirectedEdge::NAME {
        Ok(visitor.visit::<LoxDirectedEdge>())
    } else if name == BabySharkCornerTable::NAME {
        Ok(visitor.visit::<BabySharkCornerTable>())
    } else if name == TriMesh::NAME {
        Ok(visitor.visit::<TriMesh>())
    } else {
        Err(visitor)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use topolab_structures::registry::{duplicate_name, names};
    use topolab_structures::{Family, MeshTopology};

    /// The list and the names the lab's registry shows agree, and no peer takes a name of
    /// the lab's own structures.
    #[test]
    fn the_list_is_the_names() {
        let listed = names::<Peers>();
        assert_eq!(listed, crate::crates::NAMES);
        assert_eq!(duplicate_name(&listed), None);
        for name in listed {
            assert!(
                !topolab_structures::registry::NAMES.contains(&name),
                "{name}"
            );
        }
    }

    #[test]
    fn every_peer_is_a_rust_crate_and_visits_by_name() {
        struct FamilyOf;
        impl StructureVisitor for FamilyOf {
            type Output = (&'static str, Family);
            fn visit<M: MeshTopology>(self) -> Self::Output {
                (M::NAME, M::FAMILY)
            }
        }
        for name in crate::crates::NAMES {
            let (visited, family) = visit(name, FamilyOf).ok().expect("a peer visits");
            assert_eq!((visited, family), (name, Family::RustCrate));
        }
        assert!(visit("index-half-edge", FamilyOf).is_err());
    }

    /// Every editable peer visits as itself; the others, and the lab's own names, are
    /// handed back.
    #[test]
    fn the_editable_peers_visit_as_themselves() {
        struct EditName;
        impl EditVisitor for EditName {
            type Output = &'static str;
            fn visit<M: topolab_structures::MeshEdit>(self) -> &'static str {
                M::NAME
            }
        }
        for name in crate::crates::NAMES {
            let got = visit_editable(name, EditName).ok();
            assert_eq!(got, EDITABLE.contains(&name).then_some(name), "{name}");
        }
        assert!(visit_editable("index-half-edge", EditName).is_err());
        assert!(EDITABLE.iter().all(|n| crate::crates::NAMES.contains(n)));
    }
}
