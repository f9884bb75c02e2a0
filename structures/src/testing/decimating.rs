//! The decimation suite: [`decimate`] on a structure, with each [`Strategy`],
//! then [`reconstruct`], on seeded random small
//! closed meshes (tori, spheres and plates of genus 1–3, their vertices moved at random so
//! that errors do not tie), open ones (random grids; their boundary vertices stay), and every
//! canonical triangle mesh the structure takes. After the decimation `validate()` holds, the
//! live face count is at most the target or no collapse is left, and the count fell by two per
//! collapse; after the reconstruction `validate()` holds and the mesh is the original exactly
//! ([`same_mesh`]: positions bit-identical, the same
//! oriented faces through the documented id mapping). The eager strategy is also compared,
//! collapse for collapse, with a naive oracle of OpenMesh's discipline ([`eager_oracle`]).
//! Levels of detail ([`levels_round_trip`]): the same meshes decimated through random levels,
//! the record written in its file format ([`Record`]) and read back, and each level and the
//! original rebuilt from the coarse mesh and that record alone. The
//! [`decimate_conformance!`](macro@crate::decimate_conformance) macro enrols a structure in one
//! line.

use crate::algorithms::decimate::record::{fingerprint, Counts, Level, Record};
use crate::algorithms::decimate::{
    canonical_input, decimate, decimate_levels, live_soup, reconstruct, reconstruct_from,
    same_mesh, triangle_quadric, Quadric, Strategy,
};
use crate::core::edit::MeshEdit;
use crate::core::ids::FaceId;
use crate::core::soup::PolygonSoup;
use crate::meshes::{self, RandomMeshParams};
use crate::testing::editing::Model;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Decimates `soup` built as `M` to `target` faces with `strategy` and rebuilds it;
/// `Ok(collapses)` or what went wrong. A soup `M` refuses is `Ok(0)`.
pub fn round_trip<M: MeshEdit>(
    soup: &PolygonSoup,
    target: usize,
    strategy: Strategy,
) -> Result<usize, String> {
    let Ok(mut m) = M::from_soup(soup) else {
        return Ok(0);
    };
    let live = |m: &M| {
        (0..m.num_faces())
            .filter(|&f| !m.is_deleted_face(FaceId::new(f)))
            .count()
    };
    let d = decimate(&mut m, target, strategy).map_err(|e| format!("decimate: {e}"))?;
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

/// The target of the suite's case `seed` for `soup`: a random fraction of its faces (0
/// included: as far as the topology allows).
fn target_of(seed: u64, soup: &PolygonSoup) -> usize {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x9e37_79b9);
    rng.random_range(0..=soup.num_faces())
}

/// One case of the suite: [`random_mesh`] of `seed`, decimated to a random fraction of its
/// faces with `strategy` and rebuilt.
pub fn run<M: MeshEdit>(seed: u64, strategy: Strategy) -> Result<usize, String> {
    let soup = random_mesh(seed);
    let target = target_of(seed, &soup);
    round_trip::<M>(&soup, target, strategy)
        .map_err(|e| format!("{strategy}, target {target}: {e}"))
}

/// Every canonical triangle mesh `M` takes, decimated to nothing with each strategy and
/// rebuilt.
pub fn canonical<M: MeshEdit>() -> Result<(), String> {
    for c in meshes::canonical() {
        if !c.soup.is_triangle_mesh() {
            continue;
        }
        for strategy in Strategy::ALL {
            round_trip::<M>(&c.soup, 0, strategy)
                .map_err(|e| format!("{}, {strategy}: {e}", c.name))?;
        }
    }
    Ok(())
}

/// The random levels of the suite's case `seed` for `soup`: one to four targets, strictly
/// decreasing fractions of its faces.
fn levels_of(seed: u64, soup: &PolygonSoup) -> Vec<usize> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5bd1_e995);
    let mut fractions: Vec<f64> = (0..rng.random_range(1..=4))
        .map(|_| rng.random_range(0.01..1.0))
        .collect();
    fractions.sort_by(|a, b| b.total_cmp(a));
    fractions.dedup();
    fractions
        .iter()
        .map(|p| (p * soup.num_faces() as f64).round() as usize)
        .collect()
}

/// Levels of detail through the record file, one case: [`random_mesh`] of `seed` built as `M`
/// and decimated with `strategy` through random levels ([`decimate_levels`]), each level kept
/// in canonical form ([`live_soup`]); the record written as text and read back (it must be the
/// same record); then, from the coarse mesh and the record read back alone (built as `M`
/// afresh, numbered as the file numbers it), a reconstruction to each level's face count
/// (the same canonical mesh as the level, with that many faces) and to the original (the
/// input's canonical form: every vertex at its original id with its position's bits, the same
/// faces). `Ok(collapses)`, or what went wrong; a soup `M` refuses is `Ok(0)`.
pub fn levels_round_trip<M: MeshEdit>(seed: u64, strategy: Strategy) -> Result<usize, String> {
    let soup = random_mesh(seed);
    let Ok(mut m) = M::from_soup(&soup) else {
        return Ok(0);
    };
    let targets = levels_of(seed, &soup);
    let identity: Vec<u32> = (0..soup.num_vertices() as u32).collect();
    let mut soups = Vec::new();
    let d = decimate_levels(&mut m, &targets, strategy, |m, _| {
        soups.push(live_soup(m, &identity))
    })
    .map_err(|e| format!("decimate: {e}"))?;
    let original = canonical_input(&soup);
    let coarse = soups.last().ok_or("no level")?.clone();
    let record = Record {
        original: Counts::of(&original),
        coarse: Counts::of(&coarse),
        levels: d
            .levels
            .iter()
            .zip(&soups)
            .map(|(&collapses, s)| Level {
                faces: s.num_faces(),
                collapses,
                fingerprint: fingerprint(s),
            })
            .collect(),
        collapses: d.collapses,
    };
    let read = Record::parse(&record.to_text()).map_err(|e| format!("record: {e}"))?;
    if read != record {
        return Err("the record read back differs from the one written".into());
    }
    for (i, (level, state)) in read.levels.iter().zip(&soups).enumerate() {
        // Short of its target only when no legal collapse was left: then nothing follows.
        if level.faces > targets[i] && level.collapses < read.collapses.len() {
            return Err(format!(
                "level {i}: {} faces for a target of {}",
                level.faces, targets[i]
            ));
        }
        let rebuilt = rebuild::<M>(&coarse, &read, level.faces)?;
        if rebuilt.num_faces() != level.faces || &rebuilt != state {
            return Err(format!(
                "level {i} ({} faces) rebuilt as another mesh of {} faces",
                level.faces,
                rebuilt.num_faces()
            ));
        }
    }
    let rebuilt = rebuild::<M>(&coarse, &read, read.original.faces)?;
    let bits = |s: &PolygonSoup| -> Vec<[u64; 3]> {
        s.positions
            .iter()
            .map(|p| p.to_array().map(f64::to_bits))
            .collect()
    };
    if bits(&rebuilt) != bits(&original) {
        return Err("the original's positions did not come back bit for bit".into());
    }
    if rebuilt != original {
        return Err("the original's faces did not come back".into());
    }
    read.original
        .check("the original", &rebuilt)
        .map_err(|e| e.to_string())?;
    Ok(read.collapses.len())
}

/// The state with at least `faces` faces rebuilt from `coarse` (as `M`) and `record`, in
/// canonical form.
fn rebuild<M: MeshEdit>(
    coarse: &PolygonSoup,
    record: &Record,
    faces: usize,
) -> Result<PolygonSoup, String> {
    record
        .coarse
        .check("the coarse mesh", coarse)
        .map_err(|e| e.to_string())?;
    let mut m = M::from_soup(coarse).map_err(|e| format!("the coarse mesh: {e}"))?;
    let keep = record.keep_for(faces).ok_or("faces out of range")?;
    let r = reconstruct_from(&mut m, &record.collapses, keep, record.coarse_ids())
        .map_err(|e| format!("reconstruct to {faces} faces: {e}"))?;
    m.validate()
        .map_err(|e| format!("invalid after reconstruction to {faces} faces: {e}"))?;
    Ok(live_soup(&m, &r.original))
}

/// The eager strategy's discipline (OpenMesh's `DecimaterT` with `ModQuadricT` alone, see
/// [`crate::algorithms::decimate`]) written naively over the editing suite's [`Model`], a
/// face list: legality and the collapse are the model's, a vertex's key is found by trying
/// every neighbour, and the heap is a scan for the smallest key. Ties are broken by ids, as
/// [`decimate`] does ([`crate::algorithms::decimate::Ties::Ids`]): of a vertex's legal
/// collapses of equal error the one onto the smallest neighbour, of keyed vertices with equal
/// errors the smallest. Decimates `soup` to `target` faces and returns the collapses
/// `(from, to)` in order.
pub fn eager_oracle(soup: &PolygonSoup, target: usize) -> Vec<(u32, u32)> {
    let mut model = Model::of(soup);
    let mut quadric = vec![Quadric::default(); soup.num_vertices()];
    for f in soup.faces() {
        let q = triangle_quadric(
            soup.positions[f[0] as usize],
            soup.positions[f[1] as usize],
            soup.positions[f[2] as usize],
        );
        for &v in &f[..3] {
            quadric[v as usize].add_assign(&q);
        }
    }
    // A vertex's key: its legal collapse of smallest (error, neighbour).
    let key_of = |model: &Model, quadric: &[Quadric], v: u32| -> Option<(f32, u32)> {
        if model.is_boundary_vertex(v) {
            return None;
        }
        let mut legal: Vec<(f32, u32)> = Vec::new();
        for w in model.neighbours(v) {
            if model.collapse(v, w).is_none() {
                continue;
            }
            let q = quadric[v as usize].add(&quadric[w as usize]);
            let p = q.eval(soup.positions[w as usize]) as f32;
            if (0.0..f32::MAX).contains(&p) {
                legal.push((p, w));
            }
        }
        smallest(&legal)
    };
    let mut keys: Vec<Option<(f32, u32)>> = Vec::with_capacity(soup.num_vertices());
    for v in 0..soup.num_vertices() as u32 {
        keys.push(key_of(&model, &quadric, v));
    }
    let mut out = Vec::new();
    while model.num_live_faces() > target {
        let keyed: Vec<(f32, u32)> = (0..keys.len() as u32)
            .filter_map(|v| keys[v as usize].map(|(p, _)| (p, v)))
            .collect();
        let Some((_, v)) = smallest(&keyed) else {
            break;
        };
        let Some((_, to)) = keys[v as usize].take() else {
            break;
        };
        // A refused collapse is dropped: the vertex stays unkeyed until a neighbour's collapse.
        let Some(next) = model.collapse(v, to) else {
            continue;
        };
        let support = model.neighbours(v);
        model = next;
        let q = quadric[v as usize];
        quadric[to as usize].add_assign(&q);
        out.push((v, to));
        for s in support {
            keys[s as usize] = key_of(&model, &quadric, s);
        }
    }
    out
}

/// The smallest `(f32, id)` of `items`, ordered by the key then by the id.
fn smallest(items: &[(f32, u32)]) -> Option<(f32, u32)> {
    items
        .iter()
        .copied()
        .min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)))
}

/// The eager strategy on `M` against [`eager_oracle`] on the case `seed` of [`run`]:
/// `Ok(true)` when both made the same collapses, `Ok(false)` when `M` refuses the mesh and
/// nothing was compared, the first difference otherwise.
pub fn follows_oracle<M: MeshEdit>(seed: u64) -> Result<bool, String> {
    let soup = random_mesh(seed);
    follows_oracle_on::<M>(&soup, target_of(seed, &soup))
}

/// The eager strategy on `M` against [`eager_oracle`] on symmetric meshes, whose `f32`
/// errors tie all over (a torus and a sphere as generated, unperturbed): the tie rule by ids
/// is followed. `Ok(n)` with the number of meshes compared (those `M` takes).
pub fn follows_oracle_on_ties<M: MeshEdit>() -> Result<usize, String> {
    let mut compared = 0;
    for (soup, target) in [(meshes::torus(12, 8), 40), (meshes::sphere(6, 8), 20)] {
        if follows_oracle_on::<M>(&soup, target)? {
            compared += 1;
        }
    }
    Ok(compared)
}

/// The eager strategy on `M` against [`eager_oracle`] on `soup` to `target` faces (see
/// [`follows_oracle`]).
fn follows_oracle_on<M: MeshEdit>(soup: &PolygonSoup, target: usize) -> Result<bool, String> {
    let Ok(mut m) = M::from_soup(soup) else {
        return Ok(false);
    };
    let expected = eager_oracle(soup, target);
    let d = decimate(&mut m, target, Strategy::Eager).map_err(|e| format!("decimate: {e}"))?;
    let got: Vec<(u32, u32)> = d
        .collapses
        .from
        .iter()
        .copied()
        .zip(d.collapses.to.iter().copied())
        .collect();
    match (0..expected.len().max(got.len())).find(|&i| expected.get(i) != got.get(i)) {
        None => Ok(true),
        Some(i) => Err(format!(
            "target {target}: collapse {i} is {:?}, the oracle's {:?} ({} and {} collapses)",
            got.get(i),
            expected.get(i),
            got.len(),
            expected.len()
        )),
    }
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
                    for strategy in $crate::algorithms::decimate::Strategy::ALL {
                        if let Err(msg) = $crate::testing::decimating::run::<$ty>(seed, strategy) {
                            panic!("{} on mesh seed {seed}: {msg}", <$ty as $crate::MeshTopology>::NAME);
                        }
                    }
                }

                #[test]
                fn levels_come_back_from_the_coarse_mesh_and_the_record_file(seed in $crate::testing::proptest::prelude::any::<u64>()) {
                    for strategy in $crate::algorithms::decimate::Strategy::ALL {
                        if let Err(msg) = $crate::testing::decimating::levels_round_trip::<$ty>(seed, strategy) {
                            panic!("{} on mesh seed {seed}: {msg}", <$ty as $crate::MeshTopology>::NAME);
                        }
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
                for strategy in $crate::algorithms::decimate::Strategy::ALL {
                    let done: usize = (0..30)
                        .map(|seed| {
                            $crate::testing::decimating::run::<$ty>(seed, strategy)
                                .unwrap_or_else(|msg| panic!("seed {seed}: {msg}"))
                        })
                        .sum();
                    assert!(done > 300, "{strategy}: {done} collapses in 30 cases");
                }
            }

            #[test]
            fn the_eager_strategy_makes_the_naive_oracles_collapses() {
                let compared = (0..24)
                    .filter(|&seed| {
                        $crate::testing::decimating::follows_oracle::<$ty>(seed)
                            .unwrap_or_else(|msg| panic!("seed {seed}: {msg}"))
                    })
                    .count();
                // Only a mesh the structure refuses is not compared.
                assert!(compared >= 16, "{compared} of 24 cases compared");
            }

            #[test]
            fn the_eager_strategy_breaks_ties_by_ids_as_the_oracle() {
                let compared = $crate::testing::decimating::follows_oracle_on_ties::<$ty>()
                    .unwrap_or_else(|msg| panic!("{msg}"));
                assert_eq!(compared, 2, "both symmetric meshes compared");
            }
        }
    };
}
