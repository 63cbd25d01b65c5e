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
//! The first abstraction is the latches the bad output and constraints read directly.

mod abstraction;
mod concrete;

use crate::aig::Aig;
use crate::engine::{Invariant, Limits, Outcome};
use abstraction::Abstraction;
use concrete::{Check, Concrete};

/// What one run did.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    /// Latches of the concrete circuit (in the cone of influence).
    pub latches: usize,
    /// Latches of the last abstraction.
    pub kept: usize,
    /// Abstract counterexamples refuted on the concrete circuit.
    pub refinements: usize,
    /// The depth of each refuted abstract counterexample, in order.
    pub depths: Vec<usize>,
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
    let Some(&bad) = aig.bad.first() else {
        return (Outcome::Proved(Some(Vec::new())), Stats::default());
    };
    let mut keep = abstraction::support(aig);
    let cone = aig.cone();
    let mut st = Stats {
        latches: aig.latches.iter().filter(|l| cone[l.var as usize]).count(),
        ..Stats::default()
    };
    let cut = concrete::cuttable(aig);
    let mut conc = Concrete::new(aig, &cut);
    debug_assert_eq!(cut.bad.first(), Some(&bad));
    loop {
        let abs = Abstraction::new(aig, &keep);
        st.kept = abs.aig.latches.len();
        let given = lemmas_over(lemmas, &abs.origin);
        let out = crate::ic3::ic3_with_lemmas(&abs.aig, limits, &given);
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
                match conc.check(k, limits) {
                    Check::Real(trace) => {
                        if crate::scorr::replays(aig, &trace) {
                            return (Outcome::Reached(trace), st);
                        }
                        // Cannot happen (the model is a trace of the concrete circuit);
                        // never report a trace that does not replay.
                        return (
                            Outcome::Unknown("a counterexample did not replay".into()),
                            st,
                        );
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
                                    Outcome::Unknown(
                                        "the abstraction cannot be refined further".into(),
                                    ),
                                    st,
                                );
                            }
                            keep = wider;
                        }
                    }
                    Check::Stopped(why) => return (Outcome::Unknown(why), st),
                }
            }
            Outcome::Proved(None) | Outcome::Bounded(_) | Outcome::Unknown(_) => return (out, st),
        }
    }
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
