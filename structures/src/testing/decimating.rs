//! The decimation suite: [`decimate`] on a structure,
//! then [`reconstruct`], on seeded random small
//! closed meshes (tori, spheres and plates of genus 1–3, their vertices moved at random so
//! that errors do not tie), open ones (random grids; their boundary vertices stay), and every
//! canonical triangle mesh the structure takes. After the decimation `validate()` holds, the
//! live face count is at most the target or no collapse is left, and the count fell by two per
//! collapse; after the reconstruction `validate()` holds and the mesh is the original exactly
//! ([`same_mesh`]: positions bit-identical, the same
//! oriented faces through the documented id mapping). The
//! [`decimate_conformance!`](macro@crate::decimate_conformance) macro enrols a structure in one
//! line.

use crate::algorithms::decimate::{decimate, reconstruct, same_mesh};
use crate::core::edit::MeshEdit;
use crate::core::ids::FaceId;
use crate::core::soup::PolygonSoup;
use crate::testing::meshes::{self, RandomMeshParams};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Decimates `soup` built as `M` to `target` faces and rebuilds it; `Ok(collapses)` or what
/// went wrong. A soup `M` refuses is `Ok(0)`.
pub fn round_trip<M: MeshEdit>(soup: &PolygonSoup, target: usize) -> Result<usize, String> {
    let Ok(mut m) = M::from_soup(soup) else {
        return Ok(0);
    };
    let live = |m: &M| {
        (0..m.num_faces())
            .filter(|&f| !m.is_deleted_face(FaceId::new(f)))
            .count()
    };
    let d = decimate(&mut m, target).map_err(|e| format!("decimate: {e}"))?;
    m.validate()
        .map_err(|e| format!("invalid after decimation: {e}"))?;
    let n = d.collapses.len();
    if d.faces_before != soup.num_faces() || live(&m) != d.faces_after {
        return Err(format!(
            "face counts: {} before ({} in the soup), {} after ({} live)",
            d.faces_before,
            soup.num_faces(),
            d.faces_after,
            live(&m)
        ));
    }
    if d.faces_before - d.faces_after != 2 * n {
        return Err(format!(
            "{n} collapses removed {} faces",
            d.faces_before - d.faces_after
        ));
    }
    let r = reconstruct(&mut m, &d.collapses).map_err(|e| format!("reconstruct: {e}"))?;
    m.validate()
        .map_err(|e| format!("invalid after reconstruction: {e}"))?;
    same_mesh(soup, &m, &r).map_err(|e| format!("not rebuilt exactly: {e}"))?;
    Ok(n)
}

/// A seeded random small mesh: closed (torus, sphere, plate of genus 1–3) or open (a random
/// triangle grid), positions perturbed.
pub fn random_mesh(seed: u64) -> PolygonSoup {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let soup = match rng.random_range(0..4) {
        0 => meshes::torus(rng.random_range(3..10), rng.random_range(3..10)),
        1 => meshes::sphere(rng.random_range(2..7), rng.random_range(3..9)),
        2 => meshes::perforated_plate(rng.random_range(1..4), 0, rng.random_range(100..400)),
        _ => meshes::random_mesh(
            seed,
            RandomMeshParams {
                triangles_only: true,
                max_side: 6,
                keep: 0.9,
            },
        ),
    };
    meshes::perturb(&soup, 0.02, seed)
}

/// One case of the suite: [`random_mesh`] of `seed`, decimated to a random fraction of its
/// faces (0 included: as far as the topology allows) and rebuilt.
pub fn run<M: MeshEdit>(seed: u64) -> Result<usize, String> {
    let soup = random_mesh(seed);
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x9e37_79b9);
    let target = rng.random_range(0..=soup.num_faces());
    round_trip::<M>(&soup, target).map_err(|e| format!("target {target}: {e}"))
}

/// Every canonical triangle mesh `M` takes, decimated to nothing and rebuilt.
pub fn canonical<M: MeshEdit>() -> Result<(), String> {
    for c in meshes::canonical() {
        if !c.soup.is_triangle_mesh() {
            continue;
        }
        round_trip::<M>(&c.soup, 0).map_err(|e| format!("{}: {e}", c.name))?;
    }
    Ok(())
}

/// Enrols a [`MeshEdit`] structure in the decimation suite: a property test over seeded random
/// meshes, the canonical meshes, and a check that the random cases do collapse.
///
/// ```ignore
/// topolab_structures::decimate_conformance!(index_half_edge, topolab_structures::IndexHalfEdge);
/// ```
#[macro_export]
macro_rules! decimate_conformance {
    ($module:ident, $ty:ty) => {
        mod $module {
            #[allow(unused_imports)]
            use super::*;

            $crate::testing::proptest::proptest! {
                #![proptest_config($crate::testing::proptest::prelude::ProptestConfig::with_cases(48))]
                #[test]
                fn decimation_then_reconstruction_gives_the_mesh_back(seed in $crate::testing::proptest::prelude::any::<u64>()) {
                    if let Err(msg) = $crate::testing::decimating::run::<$ty>(seed) {
                        panic!("{} on mesh seed {seed}: {msg}", <$ty as $crate::MeshTopology>::NAME);
                    }
                }
            }

            #[test]
            fn canonical_meshes_round_trip() {
                if let Err(msg) = $crate::testing::decimating::canonical::<$ty>() {
                    panic!("{}: {msg}", <$ty as $crate::MeshTopology>::NAME);
                }
            }

            #[test]
            fn the_random_cases_collapse() {
                let done: usize = (0..30)
                    .map(|seed| {
                        $crate::testing::decimating::run::<$ty>(seed)
                            .unwrap_or_else(|msg| panic!("seed {seed}: {msg}"))
                    })
                    .sum();
                assert!(done > 300, "{done} collapses in 30 cases");
            }
        }
    };
}
