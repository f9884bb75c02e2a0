//! The conformance suite of every structure of the registry, generated from its one list.

topolab_structures::for_each_structure!(topolab_structures::conformance);
