//! Signal correspondence: a sequential simplification before the unbounded engines.
//!
//! Many latches and gates of a bit-blasted controller are equal, complementary or constant in
//! every reachable state (an enum's one-hot decoding and its binary code, a flag and the state
//! it mirrors, a counter's bits that never change). Proving such equalities inductively and
//! merging them shrinks the circuit and, more importantly, hands IC3 and k-induction facts they
//! would otherwise have to discover clause by clause: on the master + 1 FAM closed loop, ABC's
//! `scorr` does the same before `pdr`.
//!
//! The steps: candidate classes from random simulation ([`signature`]), refined until they hold
//! initially and inductively ([`induction`]), then merged ([`rebuild`]) and reduced to the cone
//! of influence. The reduced circuit keeps every input, in order, and every valid trace of the
//! original is one of its traces with the same outputs, so its proofs are the original's; its
//! counterexamples are replayed on the original before they are believed, and IC3's invariant
//! is translated back to the original latches (with the proved latch equalities) and kept
//! only when it checks there as a certificate ([`Reduction::lift`]).

mod classes;
mod induction;
mod rebuild;
mod signature;

use crate::aig::{lit_val, Aig, Node};
use crate::engine::{Invariant, Limits, Outcome, Trace};
use std::time::{Duration, Instant};

/// Sizes and effort of one reduction.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    /// Latches before and after.
    pub latches: (usize, usize),
    /// AND gates before and after.
    pub ands: (usize, usize),
    /// Nodes merged into a representative.
    pub merged: usize,
    /// Inductive rounds, SAT calls and refuted candidate equalities.
    pub rounds: usize,
    /// SAT calls.
    pub calls: usize,
    /// Candidate equalities refuted by the solver.
    pub refuted: usize,
    /// Time spent.
    pub time: Duration,
}

/// A circuit reduced by proved equalities, and how to read its answers on the original.
#[derive(Clone, Debug)]
pub struct Reduction {
    /// The reduced circuit.
    pub aig: Aig,
    /// The original latch of each latch of [`Reduction::aig`].
    latch_origin: Vec<usize>,
    /// Proved latch equalities and constant latches, as clauses over the original latches.
    latch_facts: Invariant,
    /// What the reduction did.
    pub stats: Stats,
}

/// Random simulation effort: 256 traces of 128 ticks.
const EFFORT: signature::Effort = signature::Effort {
    words: 4,
    steps: 128,
    retries: 8,
};

/// Reduce `aig` by signal correspondence. `Err`: a limit stopped it (the reduction is only
/// sound once the refinement has reached its fixpoint).
pub fn reduce(aig: &Aig, limits: &Limits) -> Result<Reduction, crate::Error> {
    let start = Instant::now();
    let cone = aig.cone();
    let cands: Vec<u32> = (0..aig.nodes.len() as u32)
        .filter(|&v| {
            v == 0
                || cone[v as usize]
                    && match aig.nodes[v as usize] {
                        Node::And(..) => true,
                        Node::Latch(i) => aig.latches[i as usize].init.is_some(),
                        Node::Input(_) | Node::False => false,
                    }
        })
        .collect();
    let keys = signature::keys(aig, EFFORT, 0x5EED);
    let mut classes = classes::Classes::from_keys(&cands, |v| keys[v as usize]);
    let rounds = induction::prove(aig, &mut classes, limits)?;
    let repr = classes.repr_map(aig.nodes.len());
    let mut latch_facts = Vec::new();
    for c in classes.iter() {
        let (r, _) = c[0];
        for &(m, p) in &c[1..] {
            let Node::Latch(mi) = aig.nodes[m as usize] else {
                continue;
            };
            let mi = mi as usize;
            match aig.nodes[r as usize] {
                Node::False => latch_facts.push(vec![(mi, p)]),
                Node::Latch(ri) => {
                    let ri = ri as usize;
                    latch_facts.push(vec![(mi, false), (ri, !p)]);
                    latch_facts.push(vec![(mi, true), (ri, p)]);
                }
                _ => {}
            }
        }
    }
    let (merged, origin) = rebuild::merge(aig, &repr);
    let (reduced, kept) = merged.reduced_with_latches();
    let latch_origin = kept.iter().map(|&k| origin[k]).collect();
    let stats = Stats {
        latches: (aig.latches.len(), reduced.latches.len()),
        ands: (aig.num_ands(), reduced.num_ands()),
        merged: classes.merged(),
        rounds: rounds.rounds,
        calls: rounds.calls,
        refuted: rounds.refuted,
        time: start.elapsed(),
    };
    Ok(Reduction {
        aig: reduced,
        latch_origin,
        latch_facts,
        stats,
    })
}

/// Why [`Reduction::lift`] answers `unknown` for a counterexample that does not replay on the
/// original circuit (its inputs violate an original constraint the merged one lets through):
/// the caller then decides on the original circuit.
pub const SPURIOUS: &str = "the reduced circuit's counterexample does not replay on the original";

impl Reduction {
    /// The reduction with only bad output `k` (of a circuit of several properties).
    pub fn with_bad(&self, k: usize) -> Reduction {
        let mut r = self.clone();
        r.aig.bad = vec![self.aig.bad[k]];
        r.aig.bad_names = vec![self.aig.bad_names.get(k).cloned().flatten()];
        r
    }

    /// An engine's answer on the reduced circuit, read on `original` (the circuit it was
    /// reduced from): a counterexample must replay there, and an invariant is kept only when,
    /// translated to the original latches and joined with the proved latch equalities, it
    /// checks there as a certificate.
    pub fn lift(&self, original: &Aig, out: Outcome) -> Outcome {
        match out {
            Outcome::Reached(t) => {
                let mut init = original.reset_state();
                for (k, &o) in self.latch_origin.iter().enumerate() {
                    if original.latches[o].init.is_none() {
                        init[o] = t.init.get(k).copied().unwrap_or(false);
                    }
                }
                let lifted = Trace {
                    init,
                    inputs: t.inputs,
                };
                if replays(original, &lifted) {
                    Outcome::Reached(lifted)
                } else {
                    Outcome::unknown(SPURIOUS)
                }
            }
            Outcome::Proved(Some(inv)) => {
                let mut full: Invariant = inv
                    .iter()
                    .map(|c| c.iter().map(|&(j, v)| (self.latch_origin[j], v)).collect())
                    .collect();
                full.extend(self.latch_facts.iter().cloned());
                match crate::cert::check(original, &full) {
                    Ok(()) => Outcome::Proved(Some(full)),
                    Err(_) => Outcome::Proved(None),
                }
            }
            other => other,
        }
    }
}

/// True when `t` is a valid trace of `aig` (constraints hold in every frame) whose last frame
/// raises the first bad output.
pub fn replays(aig: &Aig, t: &Trace) -> bool {
    let Some(&bad) = aig.bad.first() else {
        return false;
    };
    let mut state = t.init.clone();
    for (k, ins) in t.inputs.iter().enumerate() {
        let val = aig.simulate(ins, &state);
        if !aig.constraints.iter().all(|&c| lit_val(&val, c)) {
            return false;
        }
        if k + 1 == t.inputs.len() {
            return lit_val(&val, bad);
        }
        state = aig.latches.iter().map(|l| lit_val(&val, l.next)).collect();
    }
    false
}
