//! The rounds themselves: who builds and runs in which order, how many rounds, and the check
//! of every answer against the other structures'.

use crate::measuring::measure::RoundPlan;
use crate::measuring::rounds::{cells, CellKey, Contender, Said, CONSTRUCTION, WIDE};
use crate::measuring::timing::interval::Interval;
use crate::measuring::timing::meter::MemoryMeter;
use crate::measuring::timing::turns::Answer;
use rand::seq::SliceRandom;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::collections::HashMap;
use std::time::{Duration, Instant};

/// What a run of rounds did.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct RoundsRun {
    /// Rounds made (the most any cell got).
    pub rounds: usize,
    /// Of them, extra rounds for wide cells.
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

/// Runs the rounds of `contenders` (structures on one or several meshes) with `plan`: every
/// round is every contender with every cell it times, so all cells of a mesh share their rounds
/// (their medians are taken over the same moments of the machine). `plan.min_rounds` rounds,
/// then more while some cell's interval is wide ([`WIDE`]), at most `plan.max_rounds`, and
/// only while the next round, as long as the last, fits the extra budget (`plan.extra` of the
/// first rounds' time). `progress` is told each round as it starts. Fails at the first failed
/// build or run, or answer that disagrees.
pub fn run_rounds(
    contenders: &mut [Box<dyn Contender + '_>],
    plan: &RoundPlan,
    meter: &dyn MemoryMeter,
    progress: &mut dyn FnMut(usize),
) -> Result<RoundsRun, String> {
    let start = Instant::now();
    let mut rng = ChaCha8Rng::seed_from_u64(plan.seed);
    let mut answers = Answers::default();
    let everyone: Vec<(usize, Vec<CellKey>)> = contenders
        .iter()
        .enumerate()
        .map(|(i, c)| (i, c.cells()))
        .collect();
    let (mut round, mut extra) = (0, 0);
    let mut last = Duration::ZERO;
    let mut budget = Duration::ZERO;
    while round < plan.max_rounds {
        if round >= plan.min_rounds {
            if round == plan.min_rounds {
                budget = start.elapsed().mul_f64(plan.extra.max(0.0));
            }
            let wide = contenders.iter().any(|c| {
                std::iter::once(CONSTRUCTION)
                    .chain(c.cells())
                    .any(|k| is_wide(c.rounds(k)))
            });
            if !wide || last * (extra + 1) as u32 > budget {
                break;
            }
            extra += 1;
        }
        round += 1;
        progress(round);
        let t = Instant::now();
        one_round(
            contenders,
            &everyone,
            (round, plan.cold_rounds),
            &mut rng,
            meter,
            &mut answers,
        )?;
        last = t.elapsed();
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
            ci.relative_width(crate::measuring::timing::median(&s)) > WIDE
        }
        None => false,
    }
}

/// One round of `participants` (a contender and the cells it runs): every one built afresh in
/// a random order, then each cell run by its participants in a random order.
fn one_round(
    contenders: &mut [Box<dyn Contender + '_>],
    participants: &[(usize, Vec<CellKey>)],
    (round, cold_rounds): (usize, usize),
    rng: &mut ChaCha8Rng,
    meter: &dyn MemoryMeter,
    answers: &mut Answers,
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
        let c = &mut contenders[i];
        c.build(round, round <= cold_rounds, meter)
            .map_err(|e| context(&**c, "construction", e))?;
    }
    for cell in cells(false, true) {
        let mut order: Vec<usize> = participants
            .iter()
            .filter(|p| p.1.contains(&cell))
            .map(|p| p.0)
            .collect();
        order.shuffle(rng);
        for i in order {
            let c = &mut contenders[i];
            let what = format!("{} {}", cell.0, cell.1);
            let said = c
                .run(cell, round, meter)
                .map_err(|e| context(&**c, &what, e))?;
            let (who, mesh) = (c.name(), c.mesh().to_string());
            answers.check(who, &mesh, cell, round, said)?;
        }
    }
    Ok(())
}
