//! One result per algorithm: the lab's decimater, with either strategy, gives the same mesh on
//! every editable structure of this build that collapses edges (the lab's, the C++ baselines
//! through their `MeshEdit` adapters and, with the feature `peers`, the Rust crates that
//! collapse), because it breaks ties by ids
//! (`topolab_structures::algorithms::decimate::Ties::Ids`), not by a structure's storage. The
//! meshes are symmetric (a torus and a sphere as generated, whose `f32` errors tie all over; a
//! genus-2 plate, whose flat regions' errors are all 0; a grid with its boundary), where the
//! storage order decided the result before. Each result is compared in the canonical form of
//! `live_soup` (the input's ids, faces rotated and sorted) by its fingerprint, the one
//! `topolab decimate --levels` records. Enrolled from the registry: a new structure is covered
//! without a line here.

use topolab_registry::{self as registry, EditVisitor};
use topolab_structures::algorithms::decimate::record::fingerprint;
use topolab_structures::algorithms::decimate::{decimate, live_soup, Strategy};
use topolab_structures::{meshes, EditOp, MeshEdit, PolygonSoup};

/// The decimation of a soup on one structure: `None` when the structure does not collapse
/// edges or refuses the soup, else the fingerprint of the result and its face count.
struct Decimated<'a> {
    soup: &'a PolygonSoup,
    target: usize,
    strategy: Strategy,
}

impl EditVisitor for Decimated<'_> {
    type Output = Option<Result<(u64, usize), String>>;
    fn visit<M: MeshEdit + 'static>(self) -> Self::Output {
        if !M::supports(EditOp::CollapseEdge) {
            return None;
        }
        let mut m = M::from_soup(self.soup).ok()?;
        let identity: Vec<u32> = (0..self.soup.num_vertices() as u32).collect();
        Some(
            decimate(&mut m, self.target, self.strategy)
                .map(|d| (fingerprint(&live_soup(&m, &identity)), d.faces_after))
                .map_err(|e| e.to_string()),
        )
    }
}

/// The meshes: (name, soup, target faces).
fn cases() -> Vec<(&'static str, PolygonSoup, usize)> {
    vec![
        ("torus 20x12", meshes::torus(20, 12), 48),
        ("torus 40x20", meshes::torus(40, 20), 160),
        ("sphere 16x24", meshes::sphere(16, 24), 72),
        ("genus-2 plate", meshes::perforated_plate(2, 0, 600), 80),
        ("grid 12x12", meshes::grid(12, 12, true), 60),
    ]
}

#[test]
fn every_structure_that_collapses_gives_one_mesh_per_strategy() {
    let mut decimating = Vec::new();
    for (mesh, soup, target) in cases() {
        for strategy in Strategy::ALL {
            let mut results: Vec<(&str, u64, usize)> = Vec::new();
            for &name in registry::NAMES {
                let visitor = Decimated {
                    soup: &soup,
                    target,
                    strategy,
                };
                let Some(Some(result)) = registry::visit_editable(name, visitor) else {
                    continue;
                };
                let (print, faces) =
                    result.unwrap_or_else(|e| panic!("{mesh}, {strategy}, {name}: {e}"));
                results.push((name, print, faces));
            }
            // Every lab structure that collapses, at least: the comparison is not vacuous.
            assert!(
                results.len() >= 5,
                "{mesh}, {strategy}: only {results:?} decimated"
            );
            assert!(
                results[0].2 < soup.num_faces(),
                "{mesh}, {strategy}: nothing collapsed"
            );
            let differ: Vec<String> = results
                .iter()
                .filter(|r| (r.1, r.2) != (results[0].1, results[0].2))
                .map(|r| format!("{} {:016x} ({} faces)", r.0, r.1, r.2))
                .collect();
            assert!(
                differ.is_empty(),
                "{mesh}, {strategy}: {} gives {:016x} ({} faces), but {}",
                results[0].0,
                results[0].1,
                results[0].2,
                differ.join(", ")
            );
            decimating = results.iter().map(|r| r.0).collect();
        }
    }
    // The lab's editable structures that collapse are all compared.
    for name in ["index-half-edge", "winged-edge", "vertex-list", "che-l2"] {
        assert!(decimating.contains(&name), "{name} was not compared");
    }
}
