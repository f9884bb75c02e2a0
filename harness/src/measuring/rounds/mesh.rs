//! The rounds of whole meshes: every structure of a run set up on a mesh, the rounds, the
//! cells in the run's order ([`measure_mesh`]); one structure alone ([`measure_structure`], for
//! tests and probes).

use crate::measuring::cells::Measurement;
use crate::measuring::kernels::{draw_queries, QuerySet};
use crate::measuring::measure::{Estimator, MeshCase, Plan};
use crate::measuring::rounds::{
    run_rounds, CellKey, Contender, Entry, RoundsRun, SetUp, Setup, CONSTRUCTION,
};
use crate::measuring::timing::meter::MemoryMeter;
use std::collections::HashMap;
use topolab_structures::registry::Structures;
use topolab_structures::MeshTopology;

/// The sampled queries of every round `plan` may make on `case`: round `r` draws with the
/// seed `case.seed + r`, so every structure of the round gets the same ones and two runs of
/// the report the same ones. A light plan samples nothing but still draws the first round's,
/// whose vertices are the probe that estimates a sweep's time before it runs (at a family's
/// first size a quadratic sweep is skipped only by that estimate).
pub fn round_sets(case: &MeshCase, plan: &Plan) -> Vec<QuerySet> {
    let rounds = if plan.light {
        1
    } else {
        plan.rounds.max_rounds as u64
    };
    (1..=rounds)
        .map(|r| draw_queries(case.soup, plan.samples, case.seed.wrapping_add(r)))
        .collect()
}

/// What one mesh's rounds measured.
pub struct MeshRounds {
    /// Every cell of every structure, in the order of the names, each structure's
    /// construction first.
    pub measurements: Vec<Measurement>,
    /// The rounds made.
    pub run: RoundsRun,
    /// The round values of the kept cells, by structure and cell: (round, ns per item).
    pub kept: HashMap<(String, CellKey), Vec<(usize, f64)>>,
    /// The rounds of the input checks of the structures whose construction was kept, timed
    /// alone after each build: (round, ns per face).
    pub checks: HashMap<String, Vec<(usize, f64)>>,
}

/// Measures the structures `names` of the list `L` on `case` in rounds ([`crate::measuring::rounds`]):
/// each set up (or refused), then the rounds of all of them together; the round values of the
/// `keep` cells (structure, cell) are returned beside the cells, and a kept construction also
/// times the structure's input checks alone after each build. `progress` is told each round
/// as it starts.
pub fn measure_mesh<L: Structures>(
    names: &[String],
    case: &MeshCase,
    plan: &Plan,
    keep: &[(String, CellKey)],
    meter: &dyn MemoryMeter,
    est: &mut Estimator,
    progress: &mut dyn FnMut(usize),
) -> Result<MeshRounds, String> {
    let sets = round_sets(case, plan);
    let mut slots: Vec<Result<Box<dyn Contender + '_>, Measurement>> = Vec::new();
    for name in names {
        let visitor = SetUp {
            case,
            sets: &sets,
            plan,
            meter,
            est,
            checks: keep.contains(&(name.clone(), CONSTRUCTION)),
        };
        let setup =
            L::visit(name, visitor).map_err(|_| format!("no structure is called {name}"))??;
        slots.push(match setup {
            Setup::Ready(c) => Ok(c),
            Setup::Refused(m) => Err(*m),
        });
    }
    let mut contenders: Vec<Box<dyn Contender + '_>> = Vec::new();
    let mut order = Vec::new();
    for slot in slots {
        match slot {
            Ok(c) => {
                order.push(Ok(contenders.len()));
                contenders.push(c);
            }
            Err(m) => order.push(Err(m)),
        }
    }
    let run = run_rounds(&mut contenders, &plan.rounds, meter, progress)?;
    let (mut kept, mut checks) = (HashMap::new(), HashMap::new());
    for (structure, cell) in keep {
        if let Some(c) = contenders.iter().find(|c| c.name() == structure) {
            kept.insert((structure.clone(), *cell), c.rounds(*cell).to_vec());
            if !c.checks().is_empty() {
                checks.insert(structure.clone(), c.checks().to_vec());
            }
        }
    }
    let mut finished: Vec<Option<Vec<Measurement>>> = contenders
        .into_iter()
        .map(|c| Some(c.finish(est)))
        .collect();
    let mut measurements = Vec::new();
    for slot in order {
        match slot {
            Ok(i) => measurements.extend(finished[i].take().unwrap_or_default()),
            Err(m) => measurements.push(m),
        }
    }
    Ok(MeshRounds {
        measurements,
        run,
        kept,
        checks,
    })
}

/// Measures `M` alone on `case` in rounds, as [`measure_mesh`] measures it beside the others:
/// its cells appended to `out`.
pub fn measure_structure<M: MeshTopology>(
    case: &MeshCase,
    plan: &Plan,
    meter: &dyn MemoryMeter,
    est: &mut Estimator,
    out: &mut Vec<Measurement>,
) -> Result<(), String> {
    let sets = round_sets(case, plan);
    match Entry::<M>::set_up(case, &sets, plan, meter, est, false)? {
        Setup::Refused(m) => out.push(*m),
        Setup::Ready(c) => {
            let mut contenders = vec![c];
            run_rounds(&mut contenders, &plan.rounds, meter, &mut |_| {})?;
            let c = contenders.pop().expect("one contender");
            out.extend(c.finish(est));
        }
    }
    Ok(())
}
