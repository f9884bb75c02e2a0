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
//! Structures outside this list (a crate of their own, the root crate's C++ baselines) join a
//! run as a [`Structures`] list: a type naming several structures, of which [`Registered`] is
//! this registry.
//!
//! A new structure is its folder under `families/` (declared in its family's `mod.rs`) and one
//! line in [`for_each_structure!`](crate::for_each_structure).
//!
//! Code that must work with a structure chosen at run time (the CLI) implements
//! [`StructureVisitor`] and calls [`visit`]; the visitor's generic method is monomorphised for
//! each structure, so nothing goes through `dyn`.

use crate::core::edit::MeshEdit;
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
/// its conformance module), followed by its capabilities in brackets: `[editable]` for a
/// structure that implements [`MeshEdit`] with the lecture's topological edits (the CLI's and
/// the report's changing workloads, the editing suite), `[moves]` for one that implements
/// [`MeshEdit`] for the operations on positions only (moving, selecting, rotating, scaling,
/// smoothing) and refuses every topological edit as not offered. This is the registry: add a
/// structure here and the CLI, the report, the benches, the conformance suite and, with either
/// capability, the editing suite and `explain --op` have it.
/// A callback matches each line as `$module:ident => $ty:ty $([$($capability:ident),*])?`.
#[macro_export]
macro_rules! for_each_structure {
    ($($callback:ident)::+) => {
        $($callback)::+! {
            explicit => $crate::families::corner_lists::explicit::ExplicitStorage [moves],
            vertex_list => $crate::families::corner_lists::vertex_list::VertexList [editable],
            edge_list => $crate::families::edge_lists::edge_list::EdgeList [editable],
            winged_edge => $crate::families::edge_lists::winged_edge::WingedEdge [editable],
            pointer_half_edge => $crate::families::half_edge::pointer::PointerHalfEdge [editable],
            index_half_edge => $crate::families::half_edge::index::IndexHalfEdge [editable],
            regular_grid => $crate::families::regular_grid::RegularGrid,
            height_field => $crate::families::regular_grid::HeightField,
            che_l0 => $crate::families::che::CheL0 [editable],
            che_l1 => $crate::families::che::CheL1 [editable],
            che_l2 => $crate::families::che::CheL2 [editable],
            che_l3 => $crate::families::che::CheL3 [editable],
        }
    };
}

/// Code generic over an editable structure, run for a structure named at run time.
pub trait EditVisitor {
    /// What the visit returns.
    type Output;
    /// Runs with the structure `M` (`'static`, as every registered structure is, so that a
    /// visitor may tell the concrete type, as `explain --op` does to print its records).
    fn visit<M: MeshEdit + 'static>(self) -> Self::Output;
}

/// One line's `[editable]` or `[moves]` capability: the visit of a structure that implements
/// [`MeshEdit`], `None` otherwise.
macro_rules! visit_if {
    ($visitor:ident, $ty:ty $(,)?) => {
        None
    };
    ($visitor:ident, $ty:ty, editable) => {
        Some($visitor.visit::<$ty>())
    };
    ($visitor:ident, $ty:ty, moves) => {
        Some($visitor.visit::<$ty>())
    };
}

/// One line's capabilities: is `editable` among them (the topological edits)?
macro_rules! is_editable {
    () => {
        false
    };
    (editable) => {
        true
    };
    (moves) => {
        false
    };
}

/// [`NAMES`], [`visit`], [`editable_names`] and [`visit_editable`] from the list of
/// [`for_each_structure!`](crate::for_each_structure).
macro_rules! registry {
    ($($module:ident => $ty:ty $([$($capability:ident),*])?),* $(,)?) => {
        /// Names of every structure of this crate, in report order.
        pub const NAMES: &[&str] = &[$(<$ty as MeshTopology>::NAME),*];

        /// Per structure of [`NAMES`], whether it is editable (`[editable]` in the list).
        const EDITABLE_FLAGS: &[bool] = &[$(is_editable!($($($capability),*)?)),*];

        /// Runs `visitor` with the structure called `name` if it implements [`MeshEdit`]
        /// (`[editable]` or `[moves]`); `None` if there is none of that name or it edits
        /// nothing. What it offers is [`MeshEdit::supports`].
        pub fn visit_editable<V: EditVisitor>(name: &str, visitor: V) -> Option<V::Output> {
            $(
                if name == <$ty as MeshTopology>::NAME {
                    return visit_if!(visitor, $ty, $($($capability),*)?);
                }
            )*
            None
        }

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

/// The names of the editable structures of this crate (`[editable]` in the list), in
/// [`NAMES`] order.
pub fn editable_names() -> Vec<&'static str> {
    NAMES
        .iter()
        .zip(EDITABLE_FLAGS)
        .filter(|(_, &e)| e)
        .map(|(&n, _)| n)
        .collect()
}

/// A list of structures, given as a type, that code choosing a structure by name at run time
/// can run with: this crate's registry ([`Registered`]), one structure (every
/// [`MeshTopology`] type is a list of itself), none (`()`), or a tuple of lists (their
/// concatenation, in order). This is how a crate outside the lab puts its own structure beside
/// the registered ones without editing the registry: the report entry point of the `topolab`
/// crate and the `cargo bench` groups of `topolab-harness` take such a list.
///
/// ```
/// use topolab_structures::registry::{names, Registered, Structures};
/// use topolab_structures::{CheL2, VertexList};
///
/// type Mine = (Registered, (VertexList, CheL2));
/// assert_eq!(names::<Mine>().len(), topolab_structures::registry::NAMES.len() + 2);
/// assert_eq!(names::<(CheL2,)>(), ["che-l2"]);
/// ```
pub trait Structures {
    /// Appends the names of the list, in order.
    fn names(out: &mut Vec<&'static str>);
    /// Runs `visitor` with the structure of the list called `name`, or hands the visitor back
    /// when the list has none of that name (so that lists can be chained).
    fn visit<V: StructureVisitor>(name: &str, visitor: V) -> Result<V::Output, V>;
}

/// The names of the list `S`, in order (a name that occurs twice is a mistake of the list;
/// [`duplicate_name`] finds it).
pub fn names<S: Structures>() -> Vec<&'static str> {
    let mut out = Vec::new();
    S::names(&mut out);
    out
}

/// The first name that occurs twice in `names`, if any: two structures of one name would make
/// run-time choice by name ambiguous (the second could never be chosen).
pub fn duplicate_name<'a>(names: &[&'a str]) -> Option<&'a str> {
    names
        .iter()
        .enumerate()
        .find(|&(i, n)| names[..i].contains(n))
        .map(|(_, &n)| n)
}

/// Every structure of this crate ([`NAMES`], [`visit`]) as a [`Structures`] list.
#[derive(Copy, Clone, Debug)]
pub struct Registered;

impl Structures for Registered {
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

impl<M: MeshTopology> Structures for M {
    fn names(out: &mut Vec<&'static str>) {
        out.push(M::NAME);
    }
    fn visit<V: StructureVisitor>(name: &str, visitor: V) -> Result<V::Output, V> {
        if name == M::NAME {
            Ok(visitor.visit::<M>())
        } else {
            Err(visitor)
        }
    }
}

impl Structures for () {
    fn names(_: &mut Vec<&'static str>) {}
    fn visit<V: StructureVisitor>(_: &str, visitor: V) -> Result<V::Output, V> {
        Err(visitor)
    }
}

/// [`Structures`] for tuples of lists: each element's names in order, the first match wins.
macro_rules! tuple_lists {
    ($(($($list:ident),+))*) => {
        $(
            impl<$($list: Structures),+> Structures for ($($list,)+) {
                fn names(out: &mut Vec<&'static str>) {
                    $($list::names(out);)+
                }
                fn visit<V: StructureVisitor>(name: &str, visitor: V) -> Result<V::Output, V> {
                    $(
                        let visitor = match $list::visit(name, visitor) {
                            Ok(output) => return Ok(output),
                            Err(visitor) => visitor,
                        };
                    )+
                    Err(visitor)
                }
            }
        )*
    };
}

tuple_lists! {
    (A)
    (A, B)
    (A, B, C)
    (A, B, C, D)
    (A, B, C, D, E)
    (A, B, C, D, E, F)
}

/// Builds `M` from the soup and validates it.
struct BuildAndValidate<'a>(&'a crate::core::soup::PolygonSoup);
impl StructureVisitor for BuildAndValidate<'_> {
    type Output = crate::core::error::Result<()>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        M::from_soup(self.0)?.validate()
    }
}

/// Builds every structure from `soup` and runs its `validate()`: per structure, in [`NAMES`]
/// order, its name and the outcome (a typed refusal for input it cannot store).
pub fn build_each(
    soup: &crate::core::soup::PolygonSoup,
) -> Vec<(&'static str, crate::core::error::Result<()>)> {
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
    fn a_list_names_and_visits_each_of_its_structures_in_order() {
        use crate::families::che::CheL2;
        use crate::families::corner_lists::vertex_list::VertexList;
        type List = ((CheL2, ()), Registered, (VertexList,));
        let names = names::<List>();
        assert_eq!(names[0], "che-l2");
        assert_eq!(&names[1..1 + NAMES.len()], NAMES);
        assert_eq!(names[1 + NAMES.len()..], ["vertex-list"]);
        for name in ["che-l2", "vertex-list", "regular-grid"] {
            assert_eq!(List::visit(name, Name).ok(), Some(name));
        }
        assert!(List::visit("no-such-structure", Name).is_err());
        assert!(<() as Structures>::visit("che-l2", Name).is_err());
        // CheL2 is in the list twice: a mistake the list's users refuse.
        assert_eq!(duplicate_name(&names), Some("che-l2"));
        assert_eq!(duplicate_name(NAMES), None);
    }

    /// The family a visit reached.
    struct FamilyOf;
    impl StructureVisitor for FamilyOf {
        type Output = crate::core::family::Family;
        fn visit<M: MeshTopology>(self) -> crate::core::family::Family {
            M::FAMILY
        }
    }

    #[test]
    fn every_structure_of_the_lab_declares_its_family() {
        // `Outside` is the default, for structures the lab did not write: each of the lab's
        // declares its own, and the CHE levels are one family.
        for &name in NAMES {
            let family = visit(name, FamilyOf).unwrap();
            assert_ne!(family, crate::core::family::Family::Outside, "{name}");
            assert_eq!(
                family == crate::core::family::Family::Che,
                name.starts_with("che-"),
                "{name}"
            );
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
