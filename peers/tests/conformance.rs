//! The lab's conformance suite on every peer: each canonical mesh and random meshes against
//! the oracle, refusals included (one line per structure, as the baselines enrol).

topolab_structures::conformance!(lox_half_edge, topolab_peers::LoxHalfEdge);
topolab_structures::conformance!(lox_directed_edge, topolab_peers::LoxDirectedEdge);
topolab_structures::conformance!(baby_shark_corner_table, topolab_peers::BabySharkCornerTable);
topolab_structures::conformance!(tri_mesh, topolab_peers::TriMesh);
