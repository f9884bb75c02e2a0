//! Where a cell's spread from run to run comes from, measured: the same build swept again
//! against a fresh build each round (where the allocator put the arrays), and a sampled cell's
//! fixed queries asked again against fresh queries each round (what the cache holds). The
//! structures take turns in a random order each round, as the report's rounds do
//! (`topolab_harness::measuring::rounds`), and each round's value is what a round of the report would
//! record; the table gives, per structure and way, the median, the smallest and largest round
//! and the interval of the median (order statistics) relative to the median.
//!
//! ```sh
//! cargo run --release --example spread_sources                        # torus, 1M, 15 rounds
//! cargo run --release --example spread_sources -- 1000000 15 index-half-edge,che-l2,che-l3
//! ```

use rand::seq::SliceRandom;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::time::Duration;
use topolab_harness::measuring::kernels::Kernel;
use topolab_harness::measuring::measure::{Estimator, MeshCase, Plan};
use topolab_harness::measuring::rounds::{round_sets, CellKey, Contender, SetUp, Setup};
use topolab_harness::measuring::timing::interval::Interval;
use topolab_harness::measuring::timing::median;
use topolab_harness::results::Subject;
use topolab_structures::{meshes, Operator};

/// The ways a cell is measured round after round.
#[derive(Copy, Clone, PartialEq, Debug)]
enum Way {
    /// The round's structure built once, before the first round.
    SameBuild,
    /// Built afresh every round.
    FreshBuild,
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let triangles: usize = args
        .first()
        .map_or(1_000_000, |a| a.parse().expect("TRIANGLES"));
    let rounds: usize = args.get(1).map_or(15, |a| a.parse().expect("ROUNDS"));
    let names: Vec<String> = args.get(2).map_or_else(
        || {
            [
                "index-half-edge",
                "che-l2",
                "che-l3",
                "openmesh",
                "pointer-half-edge",
            ]
            .iter()
            .filter(|n| topolab::registry::NAMES.contains(n))
            .map(|s| s.to_string())
            .collect()
        },
        |a| a.split(',').map(str::to_string).collect(),
    );
    let soup = meshes::torus_with_triangles(triangles);
    let case = MeshCase {
        name: "torus",
        family: "torus",
        soup: &soup,
        seed: 2026,
    };
    let plan = Plan::fixed(Duration::from_secs(1), rounds, 4096, false);
    let sets = round_sets(&case, &plan);
    let est = Estimator::default();
    let meter = &topolab::ALLOCATOR;
    let sweep: CellKey = (Subject::Query(Operator::R00), Kernel::Sweep);
    let sampled: CellKey = (Subject::Query(Operator::R00), Kernel::Sampled);
    println!(
        "torus of {} triangles, {rounds} rounds, structures in a random order each round",
        soup.num_faces()
    );
    println!(
        "{:<22} {:<12} {:<13} {:>9} {:>9} {:>9} {:>12}",
        "structure", "cell", "way", "median", "min", "max", "interval/med"
    );
    for way in [Way::SameBuild, Way::FreshBuild] {
        let mut contenders: Vec<Box<dyn Contender + '_>> = names
            .iter()
            .filter_map(|n| {
                let set_up = SetUp {
                    case: &case,
                    sets: &sets,
                    plan: &plan,
                    meter,
                    est: &est,
                    checks: false,
                };
                match topolab::registry::visit(n, set_up)?.expect("set up") {
                    Setup::Ready(c) => Some(c),
                    Setup::Refused(_) => None,
                }
            })
            .collect();
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        // Sampled: the same build asks the first round's queries again each round (a hot
        // cache, as a fixed sample repeated); a fresh build asks each round's own.
        for round in 1..=rounds {
            let mut order: Vec<usize> = (0..contenders.len()).collect();
            order.shuffle(&mut rng);
            for &i in &order {
                if way == Way::FreshBuild || round == 1 {
                    contenders[i].build(round, false, meter).expect("build");
                }
            }
            for cell in [sweep, sampled] {
                order.shuffle(&mut rng);
                for &i in &order {
                    let queries_of = if way == Way::SameBuild && cell == sampled {
                        1
                    } else {
                        round
                    };
                    contenders[i].run(cell, queries_of, meter).expect("run");
                }
            }
        }
        for c in &contenders {
            for (cell, what) in [(sweep, "r00 sweep"), (sampled, "r00 sampled")] {
                let v: Vec<f64> = c.rounds(cell).iter().map(|x| x.1).collect();
                let mut s = v.clone();
                s.sort_by(f64::total_cmp);
                let m = median(&s);
                let ci = Interval::of_median(&v).expect("values");
                let way = match way {
                    Way::SameBuild if cell == sampled => "same queries",
                    Way::SameBuild => "same build",
                    Way::FreshBuild if cell == sampled => "fresh queries",
                    Way::FreshBuild => "fresh builds",
                };
                println!(
                    "{:<22} {:<12} {:<13} {:>9.2} {:>9.2} {:>9.2} {:>11.1}%",
                    c.name(),
                    what,
                    way,
                    m,
                    s[0],
                    s[s.len() - 1],
                    100.0 * ci.relative_width(m)
                );
            }
        }
    }
}
