//! Meshes to test and measure on: the [canonical](canonical()) tiny meshes (each named for
//! what it exercises), deterministic generators of grids, tori, spheres and random meshes of
//! any size, and the names the command line gives them ([`from_spec`]).

mod canonical;
mod generators;
mod spec;

pub use canonical::*;
pub use generators::*;
pub use spec::{from_spec, parse_spec, MeshSize, MeshSpec, SpecError, MAX_FACES, MAX_SLOTS};

#[cfg(test)]
use crate::core::soup::PolygonSoup;

#[cfg(test)]
/// V - E + F and the boundary curves, both from the edge analysis and from the oracle.
fn euler_and_curves(s: &PolygonSoup) -> (i64, usize) {
    let c = s.connectivity().unwrap();
    c.check_vertex_fans(s).unwrap();
    let euler = s.num_vertices() as i64 - c.num_edges() as i64 + s.num_faces() as i64;
    let oracle = crate::testing::oracle::Oracle::new(s);
    assert_eq!(oracle.edge_faces.len(), c.num_edges());
    assert!(
        oracle.vertex_faces.iter().all(|f| !f.is_empty()),
        "unused vertex"
    );
    (
        euler,
        oracle.boundary_curve_count().expect("simple boundary"),
    )
}
