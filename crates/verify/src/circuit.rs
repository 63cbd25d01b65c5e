//! Deciding one AIGER circuit (`statecheck verify FILE.aig`): one SAT engine, or IC3,
//! k-induction and BMC side by side; justice properties by the liveness reductions.

use statecheck_symbolic::aig::Aig;
use statecheck_symbolic::check::{run_reduced, Engine, Reductions};
use statecheck_symbolic::engine::{Limits, Outcome};
use statecheck_symbolic::live::{check_justice, Justice, LiveOutcome, Method};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{mpsc, Arc};

/// The symbolic engines raced on a circuit and in [`crate::Engine::Auto`]: IC3 for proofs,
/// k-induction for proofs whose invariant is "no bad state within k ticks", BMC for deep
/// counterexamples, and IC3 on localization abstractions for proofs that need only a small
/// part of a large circuit (master + N FAMs: a property of slave 0).
pub(crate) const SYMBOLIC_RACE: [Engine; 4] =
    [Engine::Ic3, Engine::Kind, Engine::Bmc, Engine::Cegar];

/// Decide the single bad output of `g` with `engine` (with signal-correspondence reduction
/// where it pays).
pub fn decide_circuit(engine: Engine, g: &Aig, lim: &Limits) -> Outcome {
    run_reduced(engine, g, 0, &Reductions::new(1), lim)
}

/// IC3, k-induction and BMC side by side on one circuit; the first definitive answer, with
/// the engine that gave it.
pub fn race(g: &Aig, lim: &Limits) -> (Outcome, &'static str) {
    let stop = Arc::new(AtomicBool::new(false));
    let mut l = lim.clone();
    l.stop = Some(Arc::clone(&stop));
    let reductions = Reductions::new(1);
    std::thread::scope(|s| {
        let (tx, rx) = mpsc::channel();
        for e in SYMBOLIC_RACE {
            let tx = tx.clone();
            let l = l.clone();
            let reductions = &reductions;
            s.spawn(move || {
                let _ = tx.send((run_reduced(e, g, 0, reductions, &l), e.as_str()));
            });
        }
        drop(tx);
        let mut last = (Outcome::unknown("no engine answered"), "ic3");
        for (o, e) in rx.iter() {
            let def = matches!(o, Outcome::Reached(_) | Outcome::Proved(_));
            last = (o, e);
            if def {
                stop.store(true, Ordering::Relaxed);
                break;
            }
        }
        stop.store(true, Ordering::Relaxed);
        last
    })
}

/// Decide justice property `k` of an AIGER circuit (with its fairness constraints): one
/// method, or liveness-to-safety with IC3 and with BMC and k-liveness side by side (`None`);
/// the first definitive answer, with the method that gave it.
pub fn race_justice(
    g: &Aig,
    k: usize,
    method: Option<Method>,
    lim: &Limits,
) -> (LiveOutcome, &'static str) {
    let j = Justice::from_aiger(g, k);
    if let Some(m) = method {
        return (check_justice(&j, m, lim), m.as_str());
    }
    let stop = Arc::new(AtomicBool::new(false));
    let mut l = lim.clone();
    l.stop = Some(Arc::clone(&stop));
    let methods = [
        Method::L2s(Engine::Ic3),
        Method::L2s(Engine::Bmc),
        Method::KLive,
    ];
    std::thread::scope(|s| {
        let (tx, rx) = mpsc::channel();
        for m in methods {
            let tx = tx.clone();
            let (l, j) = (l.clone(), &j);
            s.spawn(move || {
                let _ = tx.send((check_justice(j, m, &l), m.as_str()));
            });
        }
        drop(tx);
        let mut last = (LiveOutcome::Unknown("no engine answered".into()), "ic3");
        for (o, m) in rx.iter() {
            let def = matches!(o, LiveOutcome::Lasso { .. } | LiveOutcome::Proved);
            // A bound reached is an answer only when no engine gives a definitive one.
            if def || !matches!(last.0, LiveOutcome::Bounded(_)) {
                last = (o, m);
            }
            if def {
                stop.store(true, Ordering::Relaxed);
                break;
            }
        }
        stop.store(true, Ordering::Relaxed);
        last
    })
}
