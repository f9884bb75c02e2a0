//! The editing suite ([`topolab_structures::testing::editing`]) on every structure that
//! implements `MeshEdit`: the registry's `[editable]` capability enrols it
//! ([`topolab_structures::editing_suite`]); a structure outside the registry enrols with one
//! line `topolab_structures::edit_conformance!(module, Type);`.

topolab_structures::for_each_structure!(topolab_structures::editing_suite);

// Explicit storage moves vertices only (the lecture's point about it: every copy of a
// position found); it is not `[editable]` in the registry, so it enrols here.
topolab_structures::edit_conformance!(
    explicit,
    topolab_structures::ExplicitStorage,
    offered_operations
);
