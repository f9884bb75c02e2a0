//! The structures of this crate, registered once:
//! [`for_each_structure!`](crate::for_each_structure) holds the one list, and everything that needs
//! "every structure" is generated from it:
//!
//! - [`NAMES`] and [`visit`] here, which the root crate's registry extends with the OpenMesh
//!   baseline and which the CLI (`topolab list`, `info`, `explain`), the report and the
//!   benches go through;
//! - the conformance tests: `structures/tests/conformance.rs` is
//!   `for_each_structure!(conformance)`, and its test
//!   `every_registered_structure_is_conformance_tested` fails if the structures it tests are
//!   not exactly [`NAMES`];
//! - [`build_each`] (the fuzz and bad-input tests).
//!
//! A new structure is its folder under `families/` (declared in its family's `mod.rs`) and one
//! line in [`for_each_structure!`](crate::for_each_structure).
//!
//! Code that must work with a structure chosen at run time (the CLI) implements
//! [`StructureVisitor`] and calls [`visit`]; the visitor's generic method is monomorphised for
//! each structure, so nothing goes through `dyn`.

use crate::core::topology::MeshTopology;

/// Code generic over a structure, run for a structure named at run time.
pub trait StructureVisitor {
    /// What the visit returns.
    type Output;
    /// Runs with the structure `M`.
    fn visit<M: MeshTopology>(self) -> Self::Output;
}

/// Calls `$callback!` with every structure of this crate, in report order: one line
/// `module_name => Type` per structure (`module_name` names the structure's tests, such as
/// its conformance module). This is the registry: add a structure here and the CLI, the
/// report, the benches and the conformance suite have it.
#[macro_export]
macro_rules! for_each_structure {
    ($($callback:ident)::+) => {
        $($callback)::+! {
            explicit => $crate::families::corner_lists::explicit::ExplicitStorage,
            vertex_list => $crate::families::corner_lists::vertex_list::VertexList,
            edge_list => $crate::families::edge_lists::edge_list::EdgeList,
            winged_edge => $crate::families::edge_lists::winged_edge::WingedEdge,
            pointer_half_edge => $crate::families::half_edge::pointer::PointerHalfEdge,
            index_half_edge => $crate::families::half_edge::index::IndexHalfEdge,
            regular_grid => $crate::families::regular_grid::RegularGrid,
            height_field => $crate::families::regular_grid::HeightField,
            che_l0 => $crate::families::che::CheL0,
            che_l1 => $crate::families::che::CheL1,
            che_l2 => $crate::families::che::CheL2,
            che_l3 => $crate::families::che::CheL3,
        }
    };
}

/// [`NAMES`] and [`visit`] from the list of [`for_each_structure!`](crate::for_each_structure).
macro_rules! registry {
    ($($module:ident => $ty:ty),* $(,)?) => {
        /// Names of every structure of this crate, in report order.
        pub const NAMES: &[&str] = &[$(<$ty as MeshTopology>::NAME),*];

        /// Runs `visitor` with the structure called `name`; `None` if there is none.
        pub fn visit<V: StructureVisitor>(name: &str, visitor: V) -> Option<V::Output> {
            $(
                if name == <$ty as MeshTopology>::NAME {
                    return Some(visitor.visit::<$ty>());
                }
            )*
            None
        }
    };
}

crate::for_each_structure!(registry);

/// Builds `M` from the soup and validates it.
struct BuildAndValidate<'a>(&'a crate::PolygonSoup);
impl StructureVisitor for BuildAndValidate<'_> {
    type Output = crate::Result<()>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        M::from_soup(self.0)?.validate()
    }
}

/// Builds every structure from `soup` and runs its `validate()`: per structure, in [`NAMES`]
/// order, its name and the outcome (a typed refusal for input it cannot store).
pub fn build_each(soup: &crate::PolygonSoup) -> Vec<(&'static str, crate::Result<()>)> {
    NAMES
        .iter()
        .map(|&name| {
            (
                name,
                visit(name, BuildAndValidate(soup)).expect("registered"),
            )
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The name a visit reached.
    struct Name;
    impl StructureVisitor for Name {
        type Output = &'static str;
        fn visit<M: MeshTopology>(self) -> &'static str {
            M::NAME
        }
    }

    #[test]
    fn every_name_is_unique_and_visits_its_own_structure() {
        for (i, &name) in NAMES.iter().enumerate() {
            assert!(!NAMES[..i].contains(&name), "{name} is registered twice");
            assert_eq!(visit(name, Name), Some(name));
        }
        assert_eq!(visit("no-such-structure", Name), None);
    }
}
