//! Localization abstraction with counterexample-guided refinement (CEGAR) around IC3.
//!
//! A property of a large circuit often depends on a small part of it: of master + N FAMs,
//! a property of slave 0 needs the master's schedule and slave 0's LIN port, FAM and
//! controller, not the other slaves' internals. The engine keeps a set of latches and makes
//! every other latch a free input ([`abstraction`]): the abstract circuit has every trace of
//! the concrete one and more (an over-approximation), so an IC3 proof on it is a proof on the
//! concrete circuit, and its inductive invariant, over kept latches, is the concrete
//! circuit's too. A counterexample of the abstract circuit may be spurious: its depth is
//! checked on the concrete circuit by one incremental BMC unrolling ([`concrete`]); a concrete
//! trace there is a real violation (returned, and replayed on the concrete circuit before it
//! is believed); a refutation names the latches it used, which join the abstraction, and IC3
//! runs again. The kept set only grows, so the loop ends: at worst every latch is kept and the
//! abstract circuit is the concrete one.
//!
//! The first abstraction is the latches the bad output reads directly. On a retimed problem
//! (the bad output read on the latches, [`crate::blast::Blasted::retimed_problem`]) these are
//! the property's own variables; each abstraction is then reduced by signal correspondence
//! before IC3 ([`cegar_reducing`]), so the whole circuit is never reduced.

mod abstraction;
mod concrete;

use crate::aig::Aig;
use crate::engine::{Invariant, Limits, Outcome};
use crate::ic3::Ic3Frames;
use crate::scorr::{Reduction, SPURIOUS};
use abstraction::Abstraction;
use concrete::{Check, Concrete};
use std::sync::Arc;
use std::time::Instant;

/// What one run did.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    /// Latches of the concrete circuit (in the cone of influence).
    pub latches: usize,
    /// Latches of the last abstraction.
    pub kept: usize,
    /// Latches of the last abstraction after its own signal-correspondence reduction (equal
    /// to `kept` when it is not reduced).
    pub reduced: usize,
    /// Abstract counterexamples refuted on the concrete circuit.
    pub refinements: usize,
    /// The depth of each refuted abstract counterexample, in order.
    pub depths: Vec<usize>,
    /// Time spent reducing abstractions.
    pub reduce_time: std::time::Duration,
}

/// What localization keeps between attempts on one circuit (the passes of `--engine auto`
/// give each property growing budgets): the latches kept so far (refinement is never
/// undone: each latch joined because a concrete refutation needed it), the reduction of the
/// current abstraction and IC3's frames on it. Sound to reuse because an abstraction of a
/// larger kept set is still an over-approximation of the same concrete circuit, and the
/// frames and reduction are only reused for the same abstraction.
#[derive(Debug, Default)]
pub struct Progress {
    keep: Option<Vec<bool>>,
    /// The kept set the reduction and frames below are about.
    reduced_for: Vec<bool>,
    reduction: Option<Arc<Reduction>>,
    frames: Ic3Frames,
    stats: Stats,
}

/// Decide `aig.bad[0]` by localization abstraction and refinement (see the module docs).
/// Meant for a circuit reduced by signal correspondence already (as [`crate::check`] runs
/// it): on the circuit as blasted, a property's bad output reads most latches in the same
/// tick (it watches the values the step computes), and there is little to abstract.
pub fn cegar(aig: &Aig, limits: &Limits) -> Outcome {
    cegar_with_lemmas(aig, limits, &Vec::new()).0
}

/// [`cegar`], with `lemmas` (clauses over `aig`'s latches that hold in every reachable state
/// and together are inductive, as [`crate::ic3::ic3_with_lemmas`] takes them): each
/// abstraction's IC3 starts from those over its kept latches, and a proof's invariant ends
/// with all of them.
pub fn cegar_with_lemmas(aig: &Aig, limits: &Limits, lemmas: &Invariant) -> (Outcome, Stats) {
    run(aig, limits, lemmas, &mut Progress::default(), false)
}

/// [`cegar`] on a circuit that is *not* reduced (a retimed problem,
/// [`crate::blast::Blasted::retimed_problem`]): each abstraction is reduced by signal
/// correspondence before IC3 (sound: the reduced abstraction's proofs are the abstraction's,
/// which are the concrete circuit's; its counterexamples are replayed on the abstraction,
/// then checked on the concrete circuit). The small abstraction is reduced instead of the
/// whole circuit, which costs minutes on master + 3..5 FAMs. `progress` carries the kept
/// latches, the reduction and IC3's frames from one attempt to the next.
pub fn cegar_reducing(aig: &Aig, limits: &Limits, progress: &mut Progress) -> (Outcome, Stats) {
    run(aig, limits, &Vec::new(), progress, true)
}

/// The refinement loop; with `reduce`, each abstraction is reduced before IC3.
fn run(
    aig: &Aig,
    limits: &Limits,
    lemmas: &Invariant,
    progress: &mut Progress,
    reduce: bool,
) -> (Outcome, Stats) {
    let Some(&bad) = aig.bad.first() else {
        return (Outcome::Proved(Some(Vec::new())), Stats::default());
    };
    let mut keep = progress
        .keep
        .take()
        .unwrap_or_else(|| abstraction::support(aig));
    let cone = aig.cone();
    let mut st = std::mem::take(&mut progress.stats);
    st.latches = aig.latches.iter().filter(|l| cone[l.var as usize]).count();
    let cut = concrete::cuttable(aig);
    let mut conc = Concrete::new(aig, &cut);
    debug_assert_eq!(cut.bad.first(), Some(&bad));
    // The attempt's limits, its budget extended by the time spent reducing abstractions.
    let mut lim = limits.clone();
    let limits = &mut lim;
    loop {
        let abs = Abstraction::new(aig, &keep);
        st.kept = abs.aig.latches.len();
        st.reduced = st.kept;
        let given = lemmas_over(lemmas, &abs.origin);
        let out = if reduce {
            prove_reduced(&abs, &keep, limits, progress, &mut st)
        } else {
            crate::ic3::ic3_with_lemmas(&abs.aig, limits, &given)
        };
        match out {
            Outcome::Proved(Some(inv)) => {
                // The frames' clauses (the invariant without the lemmas it was given, which
                // come last), over the concrete latches, then every lemma.
                let own = inv.len().saturating_sub(given.len());
                let mut full: Invariant = inv[..own]
                    .iter()
                    .map(|c| c.iter().map(|&(j, v)| (abs.origin[j], v)).collect())
                    .collect();
                full.extend(lemmas.iter().cloned());
                return (Outcome::Proved(Some(full)), st);
            }
            Outcome::Reached(t) => {
                let k = t.inputs.len().saturating_sub(1);
                let checked = crate::sat::with_limits(limits, || conc.check(k, limits));
                match checked {
                    Check::Real(trace) => {
                        if crate::scorr::replays(aig, &trace) {
                            return (Outcome::Reached(trace), st);
                        }
                        // Cannot happen (the model is a trace of the concrete circuit);
                        // never report a trace that does not replay.
                        return (Outcome::unknown("a counterexample did not replay"), st);
                    }
                    Check::Refuted(core) => {
                        st.refinements += 1;
                        st.depths.push(k);
                        let before = keep.iter().filter(|&&b| b).count();
                        for j in core {
                            keep[j] = true;
                        }
                        if keep.iter().filter(|&&b| b).count() == before {
                            // The refutation used only kept latches, yet the abstraction has
                            // a trace of that depth: widen by one step of the next-state
                            // functions so the loop always makes progress.
                            let wider = abstraction::grow(aig, &keep);
                            if wider == keep {
                                return (
                                    Outcome::unknown("the abstraction cannot be refined further"),
                                    st,
                                );
                            }
                            keep = wider;
                        }
                    }
                    Check::Stopped(why) => {
                        return stopped(progress, keep, st, Outcome::unknown(why))
                    }
                }
            }
            Outcome::Unknown { .. } => return stopped(progress, keep, st, out),
            Outcome::Proved(None) => return (out, st),
            Outcome::Bounded(_) => return (out, st),
        }
    }
}

/// A limit stopped the loop: keep what it refined for the next attempt.
fn stopped(progress: &mut Progress, keep: Vec<bool>, st: Stats, out: Outcome) -> (Outcome, Stats) {
    progress.keep = Some(keep);
    progress.stats = st.clone();
    (out, st)
}

/// IC3 on the abstraction `abs` (of the kept set `keep`) reduced by signal correspondence,
/// its answer read on `abs.aig` (a counterexample replayed there; an invariant over its
/// latches, with the reduction's proved equalities, checked there). The reduction and IC3's
/// frames are kept in `progress` for the next attempt on the same abstraction.
fn prove_reduced(
    abs: &Abstraction,
    keep: &[bool],
    limits: &mut Limits,
    progress: &mut Progress,
    st: &mut Stats,
) -> Outcome {
    if progress.reduced_for != keep {
        let t = Instant::now();
        // Computed to the run's end, not the attempt's (its SAT calls too): it is kept for
        // later attempts.
        let run = limits.for_run();
        let red = crate::sat::with_limits(&run, || crate::scorr::reduce(&abs.aig, &run));
        st.reduce_time += t.elapsed();
        // The attempt's budget counts from when the reduction is there (as for the whole
        // circuit's, `crate::check`), or an attempt that pays for one would end at once.
        if let Some(d) = limits.attempt_deadline {
            let later = d + t.elapsed();
            limits.attempt_deadline = Some(limits.deadline.map_or(later, |r| r.min(later)));
        }
        match red {
            Ok(r) => {
                progress.reduction = Some(Arc::new(r));
                progress.reduced_for = keep.to_vec();
                progress.frames = Ic3Frames::default();
            }
            Err(_) => {
                return Outcome::unknown(
                    limits
                        .run_expired()
                        .unwrap_or_else(|| "the abstraction's reduction stopped".into()),
                )
            }
        }
    }
    let Some(red) = progress.reduction.clone() else {
        return crate::ic3::ic3(&abs.aig, limits);
    };
    st.reduced = red.aig.latches.len();
    let limits = &*limits;
    crate::sat::with_limits(limits, || {
        let out = crate::ic3::ic3_resume(&red.aig, limits, &Vec::new(), &mut progress.frames);
        match red.lift(&abs.aig, out) {
            Outcome::Unknown { why, .. } if why == SPURIOUS => crate::ic3::ic3(&abs.aig, limits),
            out => out,
        }
    })
}

/// The clauses of `lemmas` (over concrete latches) that mention only kept latches, over the
/// abstract latches (`origin`: the concrete latch of each).
fn lemmas_over(lemmas: &Invariant, origin: &[usize]) -> Invariant {
    if lemmas.is_empty() {
        return Vec::new();
    }
    let mut to = std::collections::HashMap::with_capacity(origin.len());
    for (k, &o) in origin.iter().enumerate() {
        to.insert(o, k);
    }
    lemmas
        .iter()
        .filter_map(|c| c.iter().map(|&(j, v)| Some((*to.get(&j)?, v))).collect())
        .collect()
}
