//! The differential test of `topolab info`: random soups of the kind users have (non-manifold
//! vertices and edges, unused vertices, duplicate and degenerate faces, faces that disagree on
//! orientation, triangles mixed with quads), each given to a structure, which either refuses it
//! with the lab's typed error or answers every field of [`Summary`] exactly as the naive
//! [`Oracle`] does (the definitions are in [`crate::summary`]).
//!
//! A crate enrols its structures by running [`agrees_with_the_oracle`] for each on
//! [`info_soups`]: `topolab-baselines` does it for every name of its registry (the lab's
//! structures and the C++ baselines), `topolab-peers` for each peer.

use crate::algorithms::summary::{summarize, Summary};
use crate::core::soup::PolygonSoup;
use crate::core::topology::MeshTopology;
use crate::meshes::{self, RandomMeshParams};
use crate::testing::oracle::Oracle;
use glam::DVec3;
use proptest::prelude::*;

/// Random soups of two kinds, half each. Free soups: 4 to 9 vertices, 2 to 12 faces of 3 or 4
/// corners, vertices chosen at random (so: non-manifold vertices and edges, unused vertices,
/// duplicate faces and faces running either way), one face in ten repeating a vertex (which
/// every structure must refuse). Glued meshes: a random mesh ([`meshes::random_mesh`]) or a
/// small torus, oriented, with two of its vertices made one (a pinch: non-manifold vertices,
/// sometimes edges), and sometimes an unused vertex. Positions are distinct (the explicit
/// storage names a vertex by its position).
pub fn info_soups() -> impl Strategy<Value = PolygonSoup> {
    prop_oneof![free_soups(), glued_meshes()]
}

/// Distinct positions for `n` vertices.
fn positions(n: u32) -> Vec<DVec3> {
    (0..n)
        .map(|i| DVec3::new(i as f64, (i * i) as f64 * 0.25, (i % 3) as f64))
        .collect()
}

/// The glued meshes of [`info_soups`].
fn glued_meshes() -> impl Strategy<Value = PolygonSoup> {
    let params = RandomMeshParams {
        max_side: 4,
        ..RandomMeshParams::default()
    };
    (
        any::<u64>(),
        any::<bool>(),
        any::<u32>(),
        any::<u32>(),
        any::<bool>(),
    )
        .prop_map(move |(seed, torus, a, b, unused)| {
            let base = if torus {
                meshes::torus(3 + (seed % 3) as usize, 3 + (seed / 3 % 3) as usize)
            } else {
                meshes::random_mesh(seed, params)
            };
            let n = base.num_vertices() as u32;
            let (a, b) = (a % n, b % n);
            let faces: Vec<Vec<u32>> = base
                .faces()
                .map(|f| f.iter().map(|&v| if v == b { a } else { v }).collect())
                .collect();
            // A face with both glued vertices would repeat one: keep it unglued.
            let faces: Vec<Vec<u32>> = faces
                .into_iter()
                .zip(base.faces())
                .map(|(glued, f)| {
                    let repeats = (1..glued.len()).any(|i| glued[..i].contains(&glued[i]));
                    if repeats {
                        f.to_vec()
                    } else {
                        glued
                    }
                })
                .collect();
            PolygonSoup::from_polygons(positions(n + unused as u32), &faces)
        })
}

/// The free soups of [`info_soups`].
fn free_soups() -> impl Strategy<Value = PolygonSoup> {
    (4u32..=9).prop_flat_map(|n| {
        let distinct = prop::sample::subsequence((0..n).collect::<Vec<_>>(), 3..=4).prop_shuffle();
        let repeating = prop::collection::vec(0..n, 3..=4);
        let face = prop_oneof![9 => distinct, 1 => repeating];
        prop::collection::vec(face, 2..=12)
            .prop_map(move |faces| PolygonSoup::from_polygons(positions(n), &faces))
    })
}

/// `M`'s answer to `topolab info` on `soup`, compared with the oracle's: `Ok(Some(summary))`
/// when `M` stores the soup and agrees on every field, `Ok(None)` when it refuses the soup with
/// a typed error, `Err(why)` when it disagrees, accepts a soup that no structure can store, or
/// stores one that fails its own `validate`.
pub fn agrees_with_the_oracle<M: MeshTopology>(
    soup: &PolygonSoup,
) -> Result<Option<Summary>, String> {
    let storable = soup.check();
    let m = match M::from_soup(soup) {
        Ok(m) => m,
        Err(_) => return Ok(None),
    };
    if let Err(e) = storable {
        return Err(format!("{} stores a soup it must refuse ({e})", M::NAME));
    }
    m.validate()
        .map_err(|e| format!("{} stores the soup but fails validate: {e}", M::NAME))?;
    let mut got = summarize(&m);
    let expected = Oracle::new(soup).summary();
    got.structure = expected.structure;
    if got != expected {
        return Err(format!(
            "{} answers {got:#?}\nthe oracle {expected:#?}\non the faces {:?}",
            M::NAME,
            soup.faces().collect::<Vec<_>>()
        ));
    }
    Ok(Some(got))
}

/// The soup of issue #38: five triangles on nine vertices, five of the vertices with two fans,
/// one unused. Four boundary curves by the lab's definition, genus undefined.
pub fn two_fan_soup() -> PolygonSoup {
    let faces: [[u32; 3]; 5] = [[2, 6, 5], [3, 6, 8], [4, 0, 3], [1, 4, 5], [2, 0, 6]];
    let positions = (0..9)
        .map(|i| DVec3::new(i as f64, (i * i) as f64, 0.0))
        .collect();
    PolygonSoup::from_polygons(positions, &faces)
}
