//! The macros that enrol a structure in the editing suite in one line.

/// Generates the editing tests of every structure the registry marks `[editable]` (the full
/// suite) or `[moves]` (the operations it offers, the others refused as not offered): the
/// callback of [`for_each_structure!`](crate::for_each_structure), so that the capability
/// in the registry is the enrolment.
///
/// ```ignore
/// topolab_structures::for_each_structure!(topolab_structures::editing_suite);
/// ```
#[macro_export]
macro_rules! editing_suite {
    (@one $module:ident, $ty:ty $(,)?) => {};
    (@one $module:ident, $ty:ty, editable) => {
        $crate::edit_conformance!($module, $ty);
    };
    (@one $module:ident, $ty:ty, moves) => {
        $crate::edit_conformance!($module, $ty, offered_operations);
    };
    ($($module:ident => $ty:ty $([$($capability:ident),*])?),* $(,)?) => {
        $( $crate::editing_suite!(@one $module, $ty, $($($capability),*)?); )*

        #[test]
        fn the_registry_says_which_structures_are_editable() {
            let tested: Vec<&str> = [$($crate::editing_suite!(@name $ty, $($($capability),*)?)),*]
                .into_iter()
                .flatten()
                .collect();
            // The `[editable]` ones offer the topological edits, the `[moves]` ones none.
            let topological: Vec<&str> = tested
                .iter()
                .copied()
                .filter(|name| {
                    $crate::registry::visit_editable(name, Offers($crate::EditOp::SplitEdge))
                        == Some(true)
                })
                .collect();
            assert_eq!(topological, $crate::registry::editable_names());
            struct Offers($crate::EditOp);
            impl $crate::registry::EditVisitor for Offers {
                type Output = bool;
                fn visit<M: $crate::MeshEdit>(self) -> bool {
                    M::supports(self.0)
                }
            }
            // And run-time choice by name reaches exactly those, each as itself.
            struct Name;
            impl $crate::registry::EditVisitor for Name {
                type Output = &'static str;
                fn visit<M: $crate::MeshEdit>(self) -> &'static str {
                    M::NAME
                }
            }
            for name in $crate::registry::NAMES {
                let got = $crate::registry::visit_editable(name, Name);
                assert_eq!(got, tested.contains(name).then_some(*name), "{name}");
            }
            assert!(tested.len() >= 5, "{tested:?}");
        }
    };
    (@name $ty:ty $(,)?) => {
        None
    };
    (@name $ty:ty, editable) => {
        Some(<$ty as $crate::MeshTopology>::NAME)
    };
    (@name $ty:ty, moves) => {
        Some(<$ty as $crate::MeshTopology>::NAME)
    };
}

/// Generates the editing tests of one structure: seeded random sequences of edits
/// ([`run`](crate::testing::editing::run)), each checked against the model and the oracle, as a proptest, and counts over
/// fixed seeds. An operation the structure does not implement ([`MeshEdit::supports`](crate::MeshEdit::supports)) must
/// be refused as not implemented, nothing changed.
///
/// With two arguments, a structure that implements every operation but perhaps the vertex
/// weld and the insertion and deletion of an edge (which structures of triangles only do not
/// offer): its counts ask for more than 400 edits done and 100 refused over 40 seeds and,
/// per operation, those of [`offered_operations`](crate::testing::editing::offered_operations),
/// and the weld tests run (the weld of vertices only where it implements it). A third argument:
/// - `not_implemented_on_polygons` runs [`run_with`](crate::testing::editing::run_with) instead (a library's polygon kernel that
///   refuses the triangle operations);
/// - `offered_operations` enrols a structure that implements a subset of the operations (the
///   Rust crates of `topolab-peers`): the same random sequences, and the counts of
///   [`offered_operations`](crate::testing::editing::offered_operations) (every operation it
///   implements done, every other refused as not implemented); the weld tests only for the
///   welds it implements ([`EditOp::WeldMeshes`](crate::EditOp::WeldMeshes), [`EditOp::WeldVertices`](crate::EditOp::WeldVertices)).
///
/// ```ignore
/// topolab_structures::edit_conformance!(index_half_edge, topolab_structures::IndexHalfEdge);
/// topolab_structures::edit_conformance!(openmesh, topolab::openmesh::OpenMesh, not_implemented_on_polygons);
/// topolab_structures::edit_conformance!(lox_half_edge, topolab_peers::LoxHalfEdge, offered_operations);
/// ```
#[macro_export]
macro_rules! edit_conformance {
    ($module:ident, $ty:ty) => {
        mod $module {
            #[allow(unused_imports)]
            use super::*;

            $crate::testing::proptest::proptest! {
                #![proptest_config($crate::testing::proptest::prelude::ProptestConfig::with_cases(64))]
                #[test]
                fn random_edit_sequences(seed in $crate::testing::proptest::prelude::any::<u64>()) {
                    if let Err(msg) = $crate::testing::editing::run::<$ty>(seed, 40) {
                        panic!("{} on edit seed {seed}: {msg}", <$ty as $crate::MeshTopology>::NAME);
                    }
                }
            }

            #[test]
            fn halves_weld_back_into_the_original_and_bad_welds_are_refused() {
                let cut = $crate::testing::weld::weld_halves::<$ty>()
                    .unwrap_or_else(|msg| panic!("{}: {msg}", <$ty as $crate::MeshTopology>::NAME));
                assert!(cut >= 3, "only {cut} meshes cut and welded");
            }

            #[test]
            fn most_edits_succeed_and_some_are_refused() {
                let (mut done, mut refused) = (0, 0);
                for seed in 0..40 {
                    let (d, r) = $crate::testing::editing::run::<$ty>(seed, 40)
                        .unwrap_or_else(|msg| panic!("seed {seed}: {msg}"));
                    done += d;
                    refused += r;
                }
                assert!(done > 400 && refused > 100, "{done} edits done, {refused} refused");
            }

            #[test]
            fn edge_and_face_welds_give_the_meshes_built_directly_or_are_refused() {
                if !<$ty as $crate::MeshEdit>::supports($crate::EditOp::WeldEdges) {
                    return;
                }
                let checked = $crate::testing::weld::weld_edge_and_face_cases::<$ty>()
                    .unwrap_or_else(|msg| panic!("{}: {msg}", <$ty as $crate::MeshTopology>::NAME));
                assert_eq!(checked, 8);
            }

            #[test]
            fn vertex_welds_zip_and_close_boundaries_or_are_refused() {
                $crate::testing::editing::vertex_welds::<$ty>(false);
            }

            #[test]
            fn every_operation_is_done_and_refused_or_refused_as_not_implemented() {
                $crate::testing::editing::offered_operations::<$ty>();
            }
        }
    };
    // A library whose polygon kernel lacks the triangle operations ([`run_with`]).
    ($module:ident, $ty:ty, not_implemented_on_polygons) => {
        mod $module {
            #[allow(unused_imports)]
            use super::*;

            $crate::testing::proptest::proptest! {
                #![proptest_config($crate::testing::proptest::prelude::ProptestConfig::with_cases(64))]
                #[test]
                fn random_edit_sequences(seed in $crate::testing::proptest::prelude::any::<u64>()) {
                    if let Err(msg) = $crate::testing::editing::run_with::<$ty>(seed, 40, true) {
                        panic!("{} on edit seed {seed}: {msg}", <$ty as $crate::MeshTopology>::NAME);
                    }
                }
            }

            #[test]
            fn most_edits_succeed_and_some_are_refused() {
                let (mut done, mut refused) = (0, 0);
                for seed in 0..40 {
                    let (d, r) = $crate::testing::editing::run_with::<$ty>(seed, 40, true)
                        .unwrap_or_else(|msg| panic!("seed {seed}: {msg}"));
                    done += d;
                    refused += r;
                }
                assert!(done > 400 && refused > 100, "{done} edits done, {refused} refused");
            }

            #[test]
            fn edge_and_face_welds_give_the_meshes_built_directly_or_are_refused() {
                if !<$ty as $crate::MeshEdit>::supports($crate::EditOp::WeldEdges) {
                    return;
                }
                let checked = $crate::testing::weld::weld_edge_and_face_cases::<$ty>()
                    .unwrap_or_else(|msg| panic!("{}: {msg}", <$ty as $crate::MeshTopology>::NAME));
                assert_eq!(checked, 8);
            }

            #[test]
            fn vertex_welds_zip_and_close_boundaries_or_are_refused() {
                $crate::testing::editing::vertex_welds::<$ty>(true);
            }
        }
    };
    // A structure that implements a subset of the operations ([`offered_operations`]).
    ($module:ident, $ty:ty, offered_operations) => {
        mod $module {
            #[allow(unused_imports)]
            use super::*;

            $crate::testing::proptest::proptest! {
                #![proptest_config($crate::testing::proptest::prelude::ProptestConfig::with_cases(64))]
                #[test]
                fn random_edit_sequences(seed in $crate::testing::proptest::prelude::any::<u64>()) {
                    if let Err(msg) = $crate::testing::editing::run::<$ty>(seed, 40) {
                        panic!("{} on edit seed {seed}: {msg}", <$ty as $crate::MeshTopology>::NAME);
                    }
                }
            }

            #[test]
            fn offered_operations_are_done_and_the_others_refused_as_not_implemented() {
                $crate::testing::editing::offered_operations::<$ty>();
            }

            #[test]
            fn halves_weld_back_into_the_original_and_bad_welds_are_refused() {
                if !<$ty as $crate::MeshEdit>::supports($crate::EditOp::WeldMeshes) {
                    return;
                }
                let cut = $crate::testing::weld::weld_halves::<$ty>()
                    .unwrap_or_else(|msg| panic!("{}: {msg}", <$ty as $crate::MeshTopology>::NAME));
                assert!(cut >= 3, "only {cut} meshes cut and welded");
            }

            #[test]
            fn edge_and_face_welds_give_the_meshes_built_directly_or_are_refused() {
                if !<$ty as $crate::MeshEdit>::supports($crate::EditOp::WeldEdges) {
                    return;
                }
                let checked = $crate::testing::weld::weld_edge_and_face_cases::<$ty>()
                    .unwrap_or_else(|msg| panic!("{}: {msg}", <$ty as $crate::MeshTopology>::NAME));
                assert_eq!(checked, 8);
            }

            #[test]
            fn vertex_welds_zip_and_close_boundaries_or_are_refused() {
                $crate::testing::editing::vertex_welds::<$ty>(false);
            }
        }
    };
}
