//! Proofs by bounded persistence, for justice problems whose acceptance is absorbing.
//!
//! k-liveness ([`super::klive`]) proves a response property `G(p => F q)` only when IC3 finds
//! an invariant that bounds the firings of the acceptance counter, i.e. relates a counter of
//! up to a few hundred to the plant's progress (the linear drive needs about 200 ticks from
//! Run to an end position): an arithmetic ranking that clause-based IC3 does not find in
//! minutes. This method avoids the counter.
//!
//! It applies when every justice signal is absorbing and there is no compassion. A justice
//! signal `J` is **absorbing** when, on every constrained step, `J` in one frame
//! implies `J` in the next (one SAT query; it holds for the Büchi automaton of
//! `F(p && G !q)`, whose accepting state is a sink). A fair run has `J` infinitely often,
//! hence from some frame on for ever. So if no reachable state starts a constrained path of
//! `L` frames with `J` in every frame, no run is fair and the property holds.
//!
//! The check is a BMC-like unrolling from a **free** first state restricted by an inductive
//! invariant `Inv`: frames `0..L` with the constraints and `J` in each, and `Inv` in each. If
//! it is unsatisfiable, the property holds. If it is satisfiable, either `L` is too small or
//! the first state is unreachable; IC3 is asked (with a short budget) to prove that first
//! state unreachable, and the invariant of its proof is conjoined to `Inv` (the conjunction of
//! inductive invariants is inductive; IC3 is given `Inv` as lemmas). When IC3 does not prove
//! it in its budget, `L` doubles. `Inv` only ever holds clauses IC3 proved, so a proof is
//! sound whatever the schedule; the schedule only decides how fast one is found.

use super::{Justice, LiveOutcome};
use crate::aig::{Aig, Lit};
use crate::engine::{Invariant, Limits, Outcome};
use crate::ic3::{coi_latches, ic3_with_lemmas};
use crate::sat::{with_limits, SLit, Solver, Start, Unroller};
use std::collections::HashSet;
use std::time::{Duration, Instant};

/// Unrolled gates at most (frames times AND gates of the circuit), so memory stays bounded.
const MAX_UNROLLED: usize = 40_000_000;
/// Most frames of the persistence query.
const MAX_FRAMES: usize = 1 << 13;
/// The first path length tried: short paths are reached from many unreachable states that
/// do not matter (each IC3 call refutes one), so the search starts where only the states that
/// can stay in the acceptance for long are left.
const FIRST_FRAMES: usize = 64;
/// Most IC3 refutations of first states before giving up.
const MAX_REFUTATIONS: usize = 500;

/// Add the constraints of frame `t` to `s`.
fn constrain(s: &mut Solver, u: &mut Unroller, t: usize) {
    let aig = u.aig();
    for &c in &aig.constraints {
        let x = u.lit(s, c, t);
        s.add(&[x]);
    }
}

/// The solver literal of "latch `i` has value `pol`" in frame `t`.
fn latch_lit(s: &mut Solver, u: &mut Unroller, i: usize, pol: bool, t: usize) -> SLit {
    let aig = u.aig();
    let l = Lit::var_lit(aig.latches[i].var).xor(!pol);
    u.lit(s, l, t)
}

/// Add clause `c` (over latches) in frame `t`.
fn add_clause(s: &mut Solver, u: &mut Unroller, c: &[(usize, bool)], t: usize) {
    let lits: Vec<SLit> = c.iter().map(|&(i, p)| latch_lit(s, u, i, p, t)).collect();
    s.add(&lits);
}

/// Is `x` absorbing on the constrained steps of `aig` (module doc)?
fn absorbing(aig: &Aig, x: Lit, limits: &Limits) -> bool {
    let mut s = Solver::plain();
    let mut u = Unroller::new(aig, Start::Free);
    constrain(&mut s, &mut u, 0);
    constrain(&mut s, &mut u, 1);
    let now = u.lit(&mut s, x, 0);
    let next = u.lit(&mut s, x, 1);
    s.add(&[now]);
    s.add(&[!next]);
    with_limits(limits, || s.solve(&[])) == Some(false)
}

/// Try to prove that `j` has no fair run by bounded persistence (module doc). `Proved`, or
/// `Unknown` with the reason (no absorbing signal, a limit, or the bounds of the unrolling).
pub fn persistence(j: &Justice, limits: &Limits) -> LiveOutcome {
    // Only when every signal is absorbing and there is no compassion: otherwise a path that
    // stays in the absorbing signals may be unfair, and such paths usually exist (the
    // fairness is what makes the property hold), so the search could only run out of time.
    let signals: Vec<Lit> = j
        .justice
        .iter()
        .copied()
        .filter(|&x| x != Lit::TRUE)
        .collect();
    if signals.is_empty()
        || !j.compassion.is_empty()
        || !signals.iter().all(|&x| absorbing(&j.aig, x, limits))
    {
        return LiveOutcome::Unknown("not every acceptance signal is absorbing".into());
    }
    let mut g = j.aig.clone();
    let all = g.and_all(signals.iter().copied());
    g.bad = vec![all];
    let cone = coi_latches(&g);
    let max_frames = (MAX_UNROLLED / g.num_ands().max(1)).clamp(1, MAX_FRAMES);

    let mut s = Solver::plain();
    let mut u = Unroller::new(&g, Start::Free);
    let mut inv: Invariant = Vec::new();
    let mut known: HashSet<Vec<(usize, bool)>> = HashSet::new();
    let mut frames = 0;
    let mut target = FIRST_FRAMES.min(max_frames);
    let mut refutations = 0;
    loop {
        if let Some(why) = limits.expired() {
            return LiveOutcome::Unknown(why);
        }
        while frames < target {
            constrain(&mut s, &mut u, frames);
            let x = u.lit(&mut s, all, frames);
            s.add(&[x]);
            for c in &inv {
                add_clause(&mut s, &mut u, c, frames);
            }
            frames += 1;
        }
        match with_limits(limits, || s.solve(&[])) {
            Some(false) => return LiveOutcome::Proved,
            None => {
                return LiveOutcome::Unknown(
                    limits
                        .expired()
                        .unwrap_or_else(|| "the SAT solver stopped".into()),
                )
            }
            Some(true) => {}
        }
        if refutations >= MAX_REFUTATIONS {
            return LiveOutcome::Unknown(format!(
                "bounded persistence: {MAX_REFUTATIONS} first states refuted without a proof"
            ));
        }
        // The first state of the path, on the latches the question depends on.
        let cube: Vec<Lit> = cone
            .iter()
            .map(|&i| {
                let v = latch_lit(&mut s, &mut u, i, true, 0);
                Lit::var_lit(g.latches[i].var).xor(!s.value(v))
            })
            .collect();
        let mut q = j.aig.clone();
        let bad = q.and_all(cube);
        q.bad = vec![bad];
        q.bad_names = vec![None];
        let slice = ic3_slice(limits);
        let sub = limits.attempt_until(Instant::now() + slice);
        refutations += 1;
        match ic3_with_lemmas(&q, &sub, &inv) {
            Outcome::Proved(Some(found)) => {
                let fresh: Vec<Vec<(usize, bool)>> = found
                    .into_iter()
                    .filter(|c| known.insert(c.clone()))
                    .collect();
                if fresh.is_empty() {
                    // Nothing new to exclude the state with: only a longer path helps.
                    target = next_target(target, max_frames);
                }
                for c in &fresh {
                    for t in 0..frames {
                        add_clause(&mut s, &mut u, c, t);
                    }
                }
                inv.extend(fresh);
            }
            // The state may be reachable (the path is then too short), or IC3 needs longer.
            _ => target = next_target(target, max_frames),
        }
        if target == 0 {
            return LiveOutcome::Unknown(format!(
                "bounded persistence: no proof with paths of {max_frames} frames"
            ));
        }
    }
}

/// The next path length: doubled, or 0 past `max`.
fn next_target(t: usize, max: usize) -> usize {
    if t >= max {
        0
    } else {
        (2 * t).min(max)
    }
}

/// IC3's budget for one first state: an eighth of the time left, between 0.5 s and 10 s.
fn ic3_slice(limits: &Limits) -> Duration {
    let left = limits.time_left();
    left.map_or(Duration::from_secs(10), |l| {
        (l / 8).clamp(Duration::from_millis(500), Duration::from_secs(10))
    })
}
