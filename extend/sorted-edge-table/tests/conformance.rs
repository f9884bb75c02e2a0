//! The lab's whole conformance suite for the sorted edge table: one test per canonical mesh of
//! the lab and a proptest on random meshes, each comparing every operator with the oracle.
//! (The tests' module, `suite`, must not be called like the crate: the module would shadow it.)

use sorted_edge_table::SortedEdgeTable;

topolab_structures::conformance!(suite, SortedEdgeTable);
