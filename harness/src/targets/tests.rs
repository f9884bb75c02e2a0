//! The Targets' rounds and ratios: the plan, two structures and a structure with the probe
//! taking turns, the ratios per round and the texts of a missed target.

use super::measured::{measured, measured_chain};
use super::plan::*;
use super::probe::{with_probe, ChaseTurns, ProbeTurns};
use super::rounds::pair;
use super::text::{checks_text, missed_limit_text, versus_text};
use crate::measuring::kernels::Kernel;
use crate::measuring::probe::Probe;
use crate::measuring::timing::median;
use crate::measuring::timing::meter::MemoryMeter;
use crate::results::{Limit, Measurement, Subject};
use topolab_structures::algorithms::changing::Changing;
use topolab_structures::{meshes, CheL2, IndexHalfEdge};
use topolab_structures::{Operator, Step};

#[test]
fn the_plan_times_each_pair_once_and_a_limit_alone_only_when_untimed() {
    let all = plan(|_, _| true);
    let find = |s: &[&str]| all.iter().find(|g| g.structures == s);
    assert_eq!(
        find(&["che-l2", "index-half-edge"]).unwrap().cells,
        [Cell::R00Sweep, Cell::Smoothing]
    );
    assert_eq!(
        find(&["index-half-edge", "openmesh"]).unwrap().cells,
        [
            Cell::R00Sweep,
            Cell::Changing(Changing::Sqrt3),
            Cell::Changing(Changing::Collapse)
        ]
    );
    assert_eq!(
        find(&["che-l1", "openmesh"]).unwrap().cells,
        [Cell::Construction]
    );
    // Every structure held to its limit takes turns with the probe's read.
    for s in ["che-l2", "openmesh", "che-l1", "pointer-half-edge"] {
        assert_eq!(find(&[s, PROBE]).unwrap().cells, [Cell::R00Sweep], "{s}");
    }
    // The Rust crates: the index half-edge against lox's half-edge on both cells, once.
    assert_eq!(
        find(&["index-half-edge", "lox-half-edge"]).unwrap().cells,
        [Cell::Construction, Cell::R00Sweep]
    );
    assert_eq!(all.len(), 3 + 7 + 3);
    // Without OpenMesh, its pairs and its limit go.
    let without = plan(|s, _| s != "openmesh");
    assert!(without.iter().all(|g| !g.structures.contains(&"openmesh")));
    assert_eq!(without.len(), 1 + 6 + 3);
    // Without the crates (a build without the feature `peers`), theirs go.
    let without = plan(|s, _| !s.starts_with("lox") && !s.starts_with("baby"));
    assert_eq!(without.len(), 3 + 7);
    // A cell the size sweep skipped is not run in turns either.
    let slow = plan(|s, c| !(s == "che-l1" && c == Cell::R00Sweep));
    assert!(slow.iter().all(|g| g.structures != ["che-l1", PROBE]));
    assert!(slow.iter().any(|g| g.structures == ["che-l1", "openmesh"]));
    // A structure held only to its limit.
    assert_eq!(
        plan(|s, _| s == "che-l2"),
        [Group {
            structures: vec!["che-l2", PROBE],
            cells: vec![Cell::R00Sweep]
        }]
    );
}

#[test]
fn two_structures_take_turns_with_equal_checksums() {
    let soup = meshes::torus(12, 9);
    struct Wall;
    impl MemoryMeter for Wall {
        fn current(&self) -> usize {
            0
        }
        fn peak(&self) -> usize {
            0
        }
        fn reset_peak(&self) {}
    }
    let cells = [Cell::R00Sweep, Cell::Smoothing, Cell::Construction];
    let turns = pair::<CheL2, IndexHalfEdge>("t", &soup, &cells, &Wall).unwrap();
    assert_eq!(turns.len(), 3);
    for t in &turns {
        assert_eq!(t.structures, ["che-l2", "index-half-edge"]);
        assert!(t.ns_per_item.iter().all(|r| r.len() == ROUNDS));
    }
    let target = pair_target(Cell::Smoothing);
    let s = measured(&turns, &target, None).unwrap();
    assert_eq!(s.rounds, ROUNDS);
    assert!(s.min <= s.median && s.median <= s.max);
    // Against a limit: the sweep takes turns with the probe's read.
    let target = Target {
        against: Against::Limit,
        ..pair_target(Cell::R00Sweep)
    };
    // What the probe takes turns with, from the limit: the level's working sets, about
    // 4 ms of work a turn on the run's probe's machine.
    let mut l = limit_of(0.0, 0.0, 0.0);
    (l.loads_per_item, l.step) = (3.0, Step::Corner);
    let probe = ProbeTurns::for_limit(&l, &machine()).unwrap();
    let chase = ChaseTurns {
        bytes: 1 << 14,
        hops: 2_000_000,
        step: Step::Corner,
    };
    let expected = ProbeTurns {
        read_bytes: 1 << 14,
        read_per_turn: 400_000_000,
        chase: Some(chase),
    };
    assert_eq!(probe, expected);
    // No chain, no chases; no level of that name, no turns.
    let flat = ProbeTurns::for_limit(&limit_of(0.0, 0.0, 0.0), &machine()).unwrap();
    assert_eq!(flat.chase, None);
    l.latency_level = "L7".into();
    assert_eq!(ProbeTurns::for_limit(&l, &machine()), None);
    // Shorter turns for the test.
    let probe = ProbeTurns {
        read_per_turn: 1 << 20,
        chase: Some(ChaseTurns {
            hops: 1 << 12,
            ..chase
        }),
        ..probe
    };
    let turns = with_probe::<CheL2>("t", &soup, &[Cell::R00Sweep], probe, &Wall).unwrap();
    assert_eq!(
        turns[0].structures,
        ["che-l2", PROBE, PROBE_LOAD, PROBE_STEP, PROBE_CHECKSUM]
    );
    assert_eq!(measured(&turns, &target, None), None);
    let probe_runs = |name| {
        let r = turns[0].runs(name).unwrap();
        assert!(
            r.iter().all(|&ns| ns > 0.0 && ns.is_finite()),
            "{name}: {r:?}"
        );
        assert_eq!(r.len(), ROUNDS);
        r
    };
    let (read, load, step, terms) = (
        probe_runs(PROBE),
        probe_runs(PROBE_LOAD),
        probe_runs(PROBE_STEP),
        probe_runs(PROBE_CHECKSUM),
    );
    let runs = turns[0].runs("che-l2").unwrap();
    // Each round's sweep over that round's limit, the largest of its three bounds.
    let expect = |l: &Limit, bound: &dyn Fn(usize) -> f64| {
        assert_eq!(
            measured(&turns, &target, Some(l)).unwrap().median,
            median_of((0..ROUNDS).map(|i| runs[i] / bound(i)))
        );
    };
    // A bandwidth bound: the bytes at that round's read.
    let mut l = limit_of(1000.0, 0.0, 0.0);
    expect(&l, &|i| 1000.0 * read[i]);
    // A latency bound far above it: the loads at that round's chase, not the run's probe's.
    (l.loads_per_item, l.latency_ns_per_item) = (1e9, 1.0);
    expect(&l, &|i| 1e9 * load[i]);
    // A checksum bound above both: the terms at that round's time per term.
    (l.checksum_terms_per_item, l.checksum_ns_per_item) = (1e12, 1.0);
    expect(&l, &|i| 1e12 * terms[i]);
    // Rounds measured without the chase and the checksum turns take the run's probe's.
    let old = without_probe_turns(&turns);
    (l.checksum_terms_per_item, l.checksum_ns_per_item) = (0.0, 0.0);
    l.latency_ns_per_item = 1e6;
    assert_eq!(
        measured(&old, &target, Some(&l)).unwrap().median,
        median_of(runs.iter().map(|r| r / 1e6))
    );
    // A probe's turn with fewer rounds than the sweep's makes no ratio.
    let mut short = turns.clone();
    short[0].ns_per_item[2].pop();
    assert_eq!(measured(&short, &target, Some(&l)), None);
    // Against its chain: the loads at that round's chase of the chain's own step; a plain
    // load's chain is the plain chase.
    l.loads_per_item = 3.0;
    for (kind, chase) in [(Step::Corner, step), (Step::Load, load)] {
        l.step = kind;
        let expected = median_of((0..ROUNDS).map(|i| runs[i] / (3.0 * chase[i])));
        let chain = measured_chain(&turns, &target, Some(&l)).unwrap();
        assert!(
            (chain.median - expected).abs() <= 1e-12 * chain.median,
            "{kind:?}: {chain:?}"
        );
    }
    // No chain without its turns.
    assert_eq!(measured_chain(&old, &target, Some(&l)), None);
}

#[test]
fn a_missed_limit_says_how_far_the_sweep_is_from_its_chain() {
    let target = Target {
        against: Against::Limit,
        ..pair_target(Cell::R00Sweep)
    };
    let names = ["che-l2", PROBE, PROBE_LOAD, PROBE_STEP, PROBE_CHECKSUM];
    let turns = vec![Turns {
        cell: Cell::R00Sweep,
        mesh: "t".into(),
        items: 100,
        structures: names.iter().map(|s| s.to_string()).collect(),
        // The sweep 9, 12 and 15 ns; a corner step 2 ns, then 2, then 2.5.
        ns_per_item: vec![
            vec![9.0, 12.0, 15.0],
            vec![0.01; 3],
            vec![1.0; 3],
            vec![2.0, 2.0, 2.5],
            vec![0.5; 3],
        ],
        warm_up: 1,
        seconds: 1.0,
    }];
    let mut l = limit_of(52.0, 3.0, 3.0);
    (l.loads_per_item, l.step, l.chain_ns_per_item) = (3.0, Step::Corner, 6.0);
    let probe = machine();
    let text = missed_limit_text(&turns, &target, &l, &probe);
    // Per round 9 / 6, 12 / 6, 15 / 7.5: a median of 2, from 1.5 to 2.
    assert!(
        text.contains(
            "3 steps of the CHE's prev(h), then the load, one query after another): 2.00× in turns (1.50–2.00)"
        ),
        "{text}"
    );
    assert!(
        text.contains("the sweep took 12.0 ns per element"),
        "{text}"
    );
    assert!(text.contains("L1 6.0 ns, memory 600.0 ns"), "{text}");
    // The chain measured once, beside the limit.
    assert!(
        text.contains(
            "takes 2.00× a plain load at the L1 latency, so the chain alone takes 6.0 ns"
        ),
        "{text}"
    );
    // Without the probe's chases nothing is said of the chain in turns.
    let old = without_probe_turns(&turns);
    assert!(!missed_limit_text(&old, &target, &l, &probe).contains("against its chain"));
}

#[test]
fn a_missed_target_between_two_structures_says_how_far_each_is_from_its_limit() {
    let sweep = |s: &str, ns: f64, bytes: f64, limit_ns: f64| {
        let mut l = limit_of(bytes, 0.0, 0.0);
        (l.ns_per_item, l.bandwidth_level) = (limit_ns, "memory".into());
        Measurement {
            ns_per_item: Some(ns),
            items: 500_000,
            reps: 1,
            limit: Some(l),
            ..Measurement::new(
                s,
                Subject::Query(Operator::R00),
                Kernel::Sweep,
                "torus-1M",
                "torus",
                1_000_000,
            )
        }
    };
    let t = Target {
        cell: Cell::R00Sweep,
        structure: "index-half-edge",
        against: Against::Structure("openmesh"),
        goal: 0.5,
    };
    let ms = [
        sweep("index-half-edge", 9.2, 52.0, 8.0),
        sweep("openmesh", 16.0, 100.0, 15.0),
    ];
    let text = versus_text(&ms, "torus-1M", &t, "openmesh").unwrap();
    assert!(
        text.contains("index-half-edge 1.15× its limit (52 bytes"),
        "{text}"
    );
    assert!(
        text.contains("openmesh 1.07× its limit (100 bytes"),
        "{text}"
    );
    assert!(text.contains("the ratio would be 0.53×"), "{text}");
    // Without a limit on one side there is nothing measured to say.
    assert_eq!(versus_text(&ms[..1], "torus-1M", &t, "openmesh"), None);
}

/// L1 of 16 kB at 100 GB/s and 1 ns a load (a CHE corner step 2 ns), memory of 1 MiB at
/// 10 GB/s and 100 ns a load.
fn machine() -> Probe {
    use crate::measuring::probe::Level;
    Probe {
        read_bytes_per_s: 1e10,
        read_array_bytes: 1 << 20,
        chase_ns_per_hop: 100.0,
        chase_array_bytes: 1 << 20,
        levels: vec![
            Level::for_tests("L1", 1 << 14, 100.0, 1.0),
            Level::for_tests("memory", 1 << 20, 10.0, 100.0),
        ],
        checksum_ns: 0.5,
    }
}

/// The median of `values`.
fn median_of(values: impl IntoIterator<Item = f64>) -> f64 {
    let mut v: Vec<f64> = values.into_iter().collect();
    v.sort_by(f64::total_cmp);
    median(&v)
}

/// `turns` as measured before the probe took its chase and checksum turns: the structure
/// and the probe's read only.
fn without_probe_turns(turns: &[Turns]) -> Vec<Turns> {
    let mut old = turns.to_vec();
    for t in &mut old {
        t.structures.truncate(2);
        t.ns_per_item.truncate(2);
    }
    old
}

fn limit_of(bytes: f64, latency: f64, checksum: f64) -> Limit {
    Limit {
        ns_per_item: 0.0,
        bound: crate::measuring::speed_limit::Bound::Bandwidth,
        bytes_per_item: bytes,
        bandwidth_ns_per_item: 0.0,
        bandwidth_level: "L1".into(),
        loads_per_item: 0.0,
        latency_ns_per_item: latency,
        latency_level: "L1".into(),
        checksum_ns_per_item: checksum,
        checksum_terms_per_item: 0.0,
        step: Step::Load,
        chain_ns_per_item: 0.0,
        note: None,
    }
}

fn pair_target(cell: Cell) -> Target {
    Target {
        cell,
        structure: "che-l2",
        against: Against::Structure("index-half-edge"),
        goal: 1.2,
    }
}

/// A construction target of a lab structure against an outside one: the lab's checks take a
/// third turn, and the text gives their time and the ratio without them, per round.
#[test]
fn the_checks_text_takes_them_out_round_by_round() {
    let turns = Turns {
        cell: Cell::Construction,
        mesh: "t".into(),
        items: 10,
        structures: vec![
            "index-half-edge".into(),
            "lox-half-edge".into(),
            CHECKS.into(),
        ],
        ns_per_item: vec![
            vec![60.0, 70.0, 64.0],
            vec![30.0, 30.0, 32.0],
            vec![45.0, 50.0, 48.0],
        ],
        warm_up: 1,
        seconds: 1.0,
    };
    let t = Target {
        cell: Cell::Construction,
        structure: "index-half-edge",
        against: Against::Structure("lox-half-edge"),
        goal: 1.0,
    };
    let text = checks_text(std::slice::from_ref(&turns), &t, "lox-half-edge").unwrap();
    // Checks 45, 50, 48: median 48. Without them 15/30, 20/30, 16/32: 0.50, 0.67, 0.50.
    assert!(
        text.contains("48.0 ns/face in these rounds (45.0–50.0)"),
        "{text}"
    );
    assert!(text.contains("would be 0.50× (0.50–0.67)"), "{text}");
    // Without the third turn, nothing to say.
    let mut two = turns.clone();
    two.structures.pop();
    two.ns_per_item.pop();
    assert_eq!(checks_text(&[two], &t, "lox-half-edge"), None);
}

/// OpenMesh builds apart from the lab's checks, so against one of the lab's structures the
/// checks take a third turn; between two lab structures they do not.
#[cfg(has_openmesh)]
#[test]
fn the_checks_take_a_turn_against_an_outside_build_only() {
    use topolab_baselines::openmesh::OpenMesh;
    struct Wall;
    impl MemoryMeter for Wall {
        fn current(&self) -> usize {
            0
        }
        fn peak(&self) -> usize {
            0
        }
        fn reset_peak(&self) {}
    }
    let soup = meshes::torus(12, 9);
    let cells = [Cell::Construction];
    let turns = pair::<IndexHalfEdge, OpenMesh>("t", &soup, &cells, &Wall).unwrap();
    assert_eq!(turns[0].structures, ["index-half-edge", "openmesh", CHECKS]);
    assert!(turns[0].ns_per_item.iter().all(|r| r.len() == ROUNDS));
    let turns = pair::<CheL2, IndexHalfEdge>("t", &soup, &cells, &Wall).unwrap();
    assert_eq!(turns[0].structures, ["che-l2", "index-half-edge"]);
}
