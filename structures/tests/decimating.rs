//! The decimation suite ([`topolab_structures::testing::decimating`]): quadric-error
//! decimation then reconstruction by vertex splits, on every structure that implements
//! `MeshEdit`: one line each.

topolab_structures::decimate_conformance!(index_half_edge, topolab_structures::IndexHalfEdge);
topolab_structures::decimate_conformance!(pointer_half_edge, topolab_structures::PointerHalfEdge);
