//! The editing suite ([`topolab_structures::testing::editing`]) on every structure that
//! implements `MeshEdit`: the registry's `[editable]` or `[moves]` capability enrols it
//! ([`topolab_structures::editing_suite`]); a structure outside the registry enrols with one
//! line `topolab_structures::edit_conformance!(module, Type);`.

topolab_structures::for_each_structure!(topolab_structures::editing_suite);
