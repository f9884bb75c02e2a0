//! One answer per question: every peer either refuses a random soup with a typed error or
//! answers `topolab info`'s every field as the naive oracle does, as the lab's structures and
//! the C++ baselines do (`topolab_structures::testing::differential`). Enrolled from the
//! peers' registry: a new peer is covered without a line here.

use proptest::prelude::*;
use topolab_structures::registry::StructureVisitor;
use topolab_structures::testing::differential::{agrees_with_the_oracle, info_soups, two_fan_soup};
use topolab_structures::{summary::Summary, MeshTopology, PolygonSoup};

struct Differential<'a>(&'a PolygonSoup);

impl StructureVisitor for Differential<'_> {
    type Output = Result<Option<Summary>, String>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        agrees_with_the_oracle::<M>(self.0)
    }
}

fn every_peer(soup: &PolygonSoup) -> Result<(), String> {
    for name in topolab_peers::NAMES {
        let answer = topolab_peers::registry::visit(name, Differential(soup))
            .unwrap_or_else(|_| panic!("{name} is in the peers' registry"));
        answer.map_err(|e| format!("{name}: {e}"))?;
    }
    Ok(())
}

#[test]
fn the_two_fan_soup_is_refused_or_answered_as_the_oracle_does() {
    every_peer(&two_fan_soup()).unwrap_or_else(|e| panic!("{e}"));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]
    #[test]
    fn every_peer_answers_info_as_the_oracle_or_refuses(soup in info_soups()) {
        every_peer(&soup).map_err(TestCaseError::fail)?;
    }
}
