//! One answer per question: every structure of the registry (the lab's, the C++
//! baselines compiled into this build and, with the feature `peers`, the Rust crates) either refuses a random soup with a typed error or
//! answers `topolab info`'s every field as the naive oracle does
//! (`topolab_structures::testing::differential`). Enrolled from the registry: a new structure
//! is covered without a line here.

use proptest::prelude::*;
use topolab_registry::{self as registry, StructureVisitor};
use topolab_structures::testing::differential::{agrees_with_the_oracle, info_soups, two_fan_soup};
use topolab_structures::{summary::Summary, MeshTopology, PolygonSoup};

struct Differential<'a>(&'a PolygonSoup);

impl StructureVisitor for Differential<'_> {
    type Output = Result<Option<Summary>, String>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        agrees_with_the_oracle::<M>(self.0)
    }
}

/// Every registered structure on `soup`: the names of those that stored it, or the first
/// disagreement.
fn every_structure(soup: &PolygonSoup) -> Result<Vec<&'static str>, String> {
    let mut stored = Vec::new();
    for &name in registry::NAMES {
        let answer = registry::visit(name, Differential(soup)).expect("a registered name");
        if answer.map_err(|e| format!("{name}: {e}"))?.is_some() {
            stored.push(name);
        }
    }
    Ok(stored)
}

#[test]
fn the_two_fan_soup_gets_one_answer_from_every_structure_that_stores_it() {
    let soup = two_fan_soup();
    let stored = every_structure(&soup).unwrap_or_else(|e| panic!("{e}"));
    // The corner lists and the edge list store non-manifold vertices (so do OpenMesh and CGAL,
    // when compiled in): the comparison is not vacuous.
    let cpp: &[&str] = match (topolab_baselines::HAS_OPENMESH, topolab_baselines::HAS_CGAL) {
        (true, true) => &[registry::OPENMESH, registry::CGAL_SURFACE_MESH],
        (true, false) => &[registry::OPENMESH],
        (false, true) => &[registry::CGAL_SURFACE_MESH],
        (false, false) => &[],
    };
    for &name in ["explicit", "vertex-list", "edge-list"].iter().chain(cpp) {
        assert!(
            stored.contains(&name),
            "{name} refused the soup: {stored:?}"
        );
    }
    let expected = topolab_structures::testing::oracle::Oracle::new(&soup).summary();
    assert_eq!(expected.boundary_curves, Some(4));
    assert_eq!(expected.genus, None);
    assert_eq!(
        expected.genus_undefined.map(|u| u.to_string()).as_deref(),
        Some("5 vertices whose faces form several fans")
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]
    #[test]
    fn every_structure_answers_info_as_the_oracle_or_refuses(soup in info_soups()) {
        every_structure(&soup).map_err(TestCaseError::fail)?;
    }
}
