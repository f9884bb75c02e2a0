//! The rounds themselves: who builds and runs in which order, how many rounds, and the check
//! of every answer against the other structures'.

use crate::rounds::{cells, CellKey, Contender, Said, CONSTRUCTION, WIDE};
use crate::timing::interval::Interval;
use crate::timing::meter::MemoryMeter;
use crate::timing::turns::Answer;
use rand::seq::SliceRandom;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::collections::HashMap;
use std::time::{Duration, Instant};

/// How many rounds a run of rounds makes.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct RoundPlan {
    /// Rounds every cell gets.
    pub min_rounds: usize,
    /// Rounds no cell passes (the sampled queries are drawn for this many).
    pub max_rounds: usize,
    /// Extra rounds for the cells whose interval is wide may take this share of the time the
    /// first `min_rounds` took.
    pub extra: f64,
    /// The first rounds that time a cold build before the warm one
    /// ([`crate::rounds::COLD_ROUNDS`] where cold builds are shown, else 0).
    pub cold_rounds: usize,
    /// The seed of the rounds' orders.
    pub seed: u64,
}

/// A cell that needs at least `rounds` rounds, whatever the budget (a Target's cell).
#[derive(Clone, Debug, PartialEq)]
pub struct Wanted {
    /// The structure.
    pub structure: String,
    /// Its cell.
    pub cell: CellKey,
    /// Rounds it needs.
    pub rounds: usize,
}

/// What a run of rounds did.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct RoundsRun {
    /// Rounds made (the most any cell got).
    pub rounds: usize,
    /// Of them, extra rounds for wide or wanted cells.
    pub extra: usize,
    /// Wall time of all of them.
    pub seconds: f64,
}

/// The first answer of each cell on each mesh (and of each sampled pass), with who gave it.
#[derive(Default)]
struct Answers {
    one: HashMap<(String, CellKey), (&'static str, Answer)>,
    passes: HashMap<(String, CellKey, usize), (&'static str, Vec<u64>)>,
}

impl Answers {
    /// Checks `said` by `who` on `mesh` against the first answer; remembers it when first.
    fn check(
        &mut self,
        who: &'static str,
        mesh: &str,
        cell: CellKey,
        round: usize,
        said: Said,
    ) -> Result<(), String> {
        let mismatch = |first: &str, a: &dyn std::fmt::Debug, b: &dyn std::fmt::Debug| {
            format!(
                "checksum mismatch on mesh {mesh}, operator {} ({}), round {round}: {first} gives {a:?}, {who} gives {b:?}",
                cell.0, cell.1
            )
        };
        match said {
            Said::One(answer) => match self.one.get(&(mesh.to_string(), cell)) {
                None => {
                    self.one.insert((mesh.to_string(), cell), (who, answer));
                }
                Some((first, a)) if !a.agrees(&answer) => return Err(mismatch(first, a, &answer)),
                Some(_) => {}
            },
            Said::Passes(sums) => {
                let key = (mesh.to_string(), cell, round);
                let (first, known) = self.passes.entry(key).or_insert((who, Vec::new()));
                if let Some(j) = known.iter().zip(&sums).position(|(a, b)| a != b) {
                    return Err(mismatch(
                        first,
                        &format!("pass {j}: {}", known[j]),
                        &format!("pass {j}: {}", sums[j]),
                    ));
                }
                if sums.len() > known.len() {
                    *first = who;
                    known.extend_from_slice(&sums[known.len()..]);
                }
            }
        }
        Ok(())
    }
}

/// Runs the rounds of `contenders` (structures on one or several meshes) with `plan`; `wanted`
/// cells get at least their rounds. `progress` is told each round as it starts. Fails at the
/// first failed build or run, or answer that disagrees.
pub fn run_rounds(
    contenders: &mut [Box<dyn Contender + '_>],
    plan: &RoundPlan,
    wanted: &[Wanted],
    meter: &dyn MemoryMeter,
    progress: &mut dyn FnMut(usize),
) -> Result<RoundsRun, String> {
    let start = Instant::now();
    let mut rng = ChaCha8Rng::seed_from_u64(plan.seed);
    let mut answers = Answers::default();
    // The wall time of each contender's build and of each of its cells in its last round.
    let mut costs: HashMap<(usize, CellKey), Duration> = HashMap::new();
    let everyone: Vec<(usize, Vec<CellKey>)> = contenders
        .iter()
        .enumerate()
        .map(|(i, c)| (i, c.cells()))
        .collect();
    let mut round = 0;
    while round < plan.min_rounds.min(plan.max_rounds) {
        round += 1;
        progress(round);
        one_round(
            contenders,
            &everyone,
            (round, plan.cold_rounds),
            &mut rng,
            meter,
            &mut answers,
            &mut costs,
        )?;
    }
    let budget = start.elapsed().mul_f64(plan.extra.max(0.0));
    let extra_start = Instant::now();
    let mut extra = 0;
    while round < plan.max_rounds {
        let next = round + 1;
        // Who needs this round: the cells wanted for more rounds, and while the budget lasts
        // the cells whose interval is wide.
        let needs = |c: &dyn Contender, cell: CellKey, wide_too: bool| {
            let values = c.rounds(cell);
            let wants = wanted
                .iter()
                .any(|w| w.structure == c.name() && w.cell == cell && values.len() < w.rounds);
            wants || (wide_too && is_wide(values))
        };
        let participants = |wide_too: bool| -> Vec<(usize, Vec<CellKey>)> {
            contenders
                .iter()
                .enumerate()
                .filter_map(|(i, c)| {
                    let cells: Vec<CellKey> = c
                        .cells()
                        .into_iter()
                        .filter(|&k| needs(&**c, k, wide_too))
                        .collect();
                    (!cells.is_empty() || needs(&**c, CONSTRUCTION, wide_too)).then_some((i, cells))
                })
                .collect()
        };
        let all = participants(true);
        let cost = |p: &[(usize, Vec<CellKey>)]| -> Duration {
            p.iter()
                .flat_map(|(i, cells)| {
                    std::iter::once(CONSTRUCTION)
                        .chain(cells.iter().copied())
                        .map(move |k| (*i, k))
                })
                .filter_map(|k| costs.get(&k))
                .sum()
        };
        let who = if extra_start.elapsed() + cost(&all) <= budget {
            all
        } else {
            participants(false)
        };
        if who.is_empty() {
            break;
        }
        round = next;
        extra += 1;
        progress(round);
        one_round(
            contenders,
            &who,
            (round, plan.cold_rounds),
            &mut rng,
            meter,
            &mut answers,
            &mut costs,
        )?;
    }
    for c in contenders.iter_mut() {
        c.release();
    }
    Ok(RoundsRun {
        rounds: round,
        extra,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// Whether the interval of these round values is wider than [`WIDE`] of their median.
fn is_wide(values: &[(usize, f64)]) -> bool {
    let v: Vec<f64> = values.iter().map(|x| x.1).collect();
    match Interval::of_median(&v) {
        Some(ci) => {
            let mut s = v.clone();
            s.sort_by(f64::total_cmp);
            ci.relative_width(crate::timing::median(&s)) > WIDE
        }
        None => false,
    }
}

/// One round of `participants` (a contender and the cells it runs this round): every one
/// built afresh in a random order, then each cell run by its participants in a random order.
fn one_round(
    contenders: &mut [Box<dyn Contender + '_>],
    participants: &[(usize, Vec<CellKey>)],
    (round, cold_rounds): (usize, usize),
    rng: &mut ChaCha8Rng,
    meter: &dyn MemoryMeter,
    answers: &mut Answers,
    costs: &mut HashMap<(usize, CellKey), Duration>,
) -> Result<(), String> {
    let context = |c: &dyn Contender, what: &str, e: String| {
        format!("{} {what} on {}, round {round}: {e}", c.name(), c.mesh())
    };
    // The last round's structures go first, so the builds reuse their memory.
    for &(i, _) in participants {
        contenders[i].release();
    }
    let mut order: Vec<usize> = participants.iter().map(|p| p.0).collect();
    order.shuffle(rng);
    for i in order {
        let t = Instant::now();
        let c = &mut contenders[i];
        c.build(round, round <= cold_rounds, meter)
            .map_err(|e| context(&**c, "construction", e))?;
        costs.insert((i, CONSTRUCTION), t.elapsed());
    }
    for cell in cells(false, true) {
        let mut order: Vec<usize> = participants
            .iter()
            .filter(|p| p.1.contains(&cell))
            .map(|p| p.0)
            .collect();
        order.shuffle(rng);
        for i in order {
            let t = Instant::now();
            let c = &mut contenders[i];
            let what = format!("{} {}", cell.0, cell.1);
            let said = c
                .run(cell, round, meter)
                .map_err(|e| context(&**c, &what, e))?;
            costs.insert((i, cell), t.elapsed());
            let (who, mesh) = (c.name(), c.mesh().to_string());
            answers.check(who, &mesh, cell, round, said)?;
        }
    }
    Ok(())
}
