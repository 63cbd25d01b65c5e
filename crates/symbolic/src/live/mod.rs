//! Temporal properties on the SAT engines (docs/properties.md, "SAT engines").
//!
//! An `ltl` property (or unbounded `respond`) becomes a justice problem on the step circuit
//! in product with the IR's Büchi automaton of its negation ([`monitor`]); the system's
//! `fair` constraints become further justice signals and compassion pairs. Two reductions to
//! safety decide it ([`l2s`]): liveness-to-safety, whose counterexamples are lassos (with
//! IC3, k-induction or BMC), and k-liveness, which proves (with IC3). A lasso found on the
//! circuit (which compares only the latches in the property's cone of influence) is turned
//! into a lasso of the whole state by running the loop in the IR's interpreter until a state
//! at its start recurs ([`full_lasso`]), so `sim` replays it. CTL and `nonblocking` are not
//! decided here.

mod l2s;
mod monitor;
mod persist;

pub use l2s::{klive, l2s, L2s};
pub use monitor::{monitor, Justice};
pub use persist::persistence;

use crate::blast::Blasted;
use crate::check::{input_vectors, run_reduced, Engine, Reductions, SymResult};
use crate::engine::{Limits, Outcome};
use statecheck_ir::temporal::{TemporalFormula, Written};
use statecheck_ir::verdict::{PropKind, PropResult, Verdict};
use statecheck_ir::{Machine, Program};
use std::collections::HashMap;
use std::time::Instant;

/// How a temporal property is reduced to safety.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Liveness-to-safety, decided by this engine (lasso counterexamples and proofs).
    L2s(Engine),
    /// k-liveness with IC3 for k = 0, 1, 2, … (proofs only).
    KLive,
}

impl Method {
    /// The engine word of its results (`ic3`, `kind`, `bmc`, or `klive`).
    pub fn as_str(self) -> &'static str {
        match self {
            Method::L2s(e) => e.as_str(),
            Method::KLive => "klive",
        }
    }
}

/// Why the SAT engines leave CTL to the explicit engine.
pub const CTL_UNSUPPORTED: &str =
    "not supported by this engine: CTL is decided by the explicit engine";

/// The kind word of a temporal property.
pub fn kind(w: Written) -> PropKind {
    match w {
        Written::Ltl => PropKind::Ltl,
        Written::Respond => PropKind::Respond,
        Written::Ctl => PropKind::Ctl,
        Written::Nonblocking => PropKind::Nonblocking,
    }
}

/// Most k tried by k-liveness.
const MAX_K: u32 = 1 << 12;

/// Decide temporal property `t` (index into `p.temporal`) of `p` (blasted as `bl`) by `method`.
pub fn decide(p: &Program, bl: &Blasted, t: usize, method: Method, limits: &Limits) -> SymResult {
    let start = Instant::now();
    let (r, reason) = match p.temporal.get(t) {
        None => (
            PropResult::unknown("", PropKind::Ltl),
            Some("no such property".into()),
        ),
        Some(tp) => {
            let mut r = PropResult::unknown(&tp.name, kind(tp.written));
            let reason = match &tp.formula {
                TemporalFormula::Ctl(_) => Some(CTL_UNSUPPORTED.to_string()),
                TemporalFormula::Ltl(f) => match monitor(bl, f, &p.fairness) {
                    Err(_) => Some("the formula's automaton is too large".to_string()),
                    Ok(j) => run(p, bl, &j, method, limits, &mut r),
                },
            };
            (r, reason)
        }
    };
    SymResult {
        result: r,
        invariant: None,
        time: start.elapsed(),
        reason,
    }
}

/// The answer of a liveness check on a [`Justice`] circuit.
#[derive(Clone, Debug)]
pub enum LiveOutcome {
    /// A fair lasso: frames `0..trace.inputs.len()`, after which the state at the start of
    /// frame `loop_start` recurs (on the latches of the justice circuit's cone of influence).
    Lasso {
        /// The frames' inputs (over the justice circuit's inputs, then `save`).
        trace: crate::engine::Trace,
        /// The loop's first frame.
        loop_start: usize,
    },
    /// No fair run exists: the property holds.
    Proved,
    /// No lasso of at most this many frames.
    Bounded(usize),
    /// A limit stopped the check; the text says which.
    Unknown(String),
}

/// Decide `j` by `method`.
pub fn check_justice(j: &Justice, method: Method, limits: &Limits) -> LiveOutcome {
    match method {
        Method::KLive => {
            // Compassion pairs become justice signals (an exact reduction, [`Justice::without_compassion`]).
            let owned;
            let j = if j.compassion.is_empty() {
                j
            } else {
                owned = j.without_compassion();
                &owned
            };
            // k-liveness first, with an eighth of the time: a response the acceptance leaves
            // within a few firings is proved with a small k at once. Then bounded persistence
            // ([`persistence`], no counter; it answers at once when it does not apply) with
            // three quarters of what is left: a slow response (a plant that needs a hundred
            // ticks or more) needs k-liveness to relate a large counter to the plant's
            // progress, which IC3 rarely finds, while persistence proves it given the time
            // (the linear drive's `run_reaches_left`: 162 s of it, docs/case-studies/
            // temporal.md). Then k-liveness again, from the k it had reached.
            // (Without a deadline persistence goes first: it ends by its own bounds, and
            // k-liveness would not.)
            let mut k = 0;
            let timed = limits.deadline.is_some() || limits.attempt_deadline.is_some();
            if timed {
                // Only a proof or the run's end is final here: a depth bound or an IC3
                // failure at some k leaves persistence its chance (and comes back below).
                match klive_from(j, &mut k, limits, &share(limits, 1, 8)) {
                    Some(LiveOutcome::Proved) => return LiveOutcome::Proved,
                    Some(LiveOutcome::Unknown(why)) if limits.expired().is_some() => {
                        return LiveOutcome::Unknown(why)
                    }
                    _ => {}
                }
            }
            if let LiveOutcome::Proved = persistence(j, &share(limits, 3, 4)) {
                return LiveOutcome::Proved;
            }
            let outcome = klive_from(j, &mut k, limits, limits).unwrap_or_else(|| {
                LiveOutcome::Unknown(limits.expired().unwrap_or_else(|| "time limit".into()))
            });
            match outcome {
                // For the row's reason: every k below `k` was refuted (past MAX_K
                // `klive_from`'s own reason says so).
                LiveOutcome::Unknown(why) if (2..=MAX_K).contains(&k) => {
                    LiveOutcome::Unknown(format!("{why}, k-liveness reached k = {k}"))
                }
                outcome => outcome,
            }
        }
        Method::L2s(engine) => {
            let l = l2s(j);
            match run_reduced(engine, &l.aig, 0, &Reductions::new(1), limits) {
                Outcome::Proved(_) => LiveOutcome::Proved,
                Outcome::Bounded(k) => LiveOutcome::Bounded(k),
                // A lasso of n ticks is a trace of n + 1 frames of the l2s circuit (the last
                // closes the loop), so `cleared` frames exclude lassos of `cleared - 1` ticks.
                Outcome::Unknown { why, cleared } if cleared > 1 => LiveOutcome::Unknown(format!(
                    "{why}, no lasso of at most {} ticks",
                    cleared - 1
                )),
                Outcome::Unknown { why, .. } => LiveOutcome::Unknown(why),
                Outcome::Reached(mut trace) => {
                    // The last frame only closes the loop (its state is the saved one).
                    trace.inputs.pop();
                    let loop_start = trace
                        .inputs
                        .iter()
                        .position(|f| f.get(l.save).copied().unwrap_or(false))
                        .unwrap_or(0);
                    LiveOutcome::Lasso { trace, loop_start }
                }
            }
        }
    }
}

/// `limits` with the attempt ending after `num / den` of the time left (unchanged without a
/// deadline).
fn share(limits: &Limits, num: u32, den: u32) -> Limits {
    match limits.time_left() {
        Some(left) => limits.attempt_until(Instant::now() + left * num / den),
        None => limits.clone(),
    }
}

/// k-liveness for k = `*k`, then doubling (a proof for some k is a proof for every larger one,
/// and a counter reached at k only says that k was too small, so a run whose acceptance fires
/// 100 times costs 8 IC3 calls instead of 101), within `slice`. The answer when there is one
/// (a proof, a depth bound, or `outer`'s limits or k's bound ending the check); `None` when
/// only `slice` ran out, with `*k` the value to go on from.
fn klive_from(j: &Justice, k: &mut u32, outer: &Limits, slice: &Limits) -> Option<LiveOutcome> {
    loop {
        if let Some(why) = outer.expired() {
            return Some(LiveOutcome::Unknown(why));
        }
        if slice.expired().is_some() {
            return None;
        }
        if *k > MAX_K {
            return Some(LiveOutcome::Unknown(format!(
                "k-liveness reached k = {MAX_K}"
            )));
        }
        let aig = klive(j, *k);
        match Engine::Ic3.run(&aig, slice) {
            Outcome::Proved(_) => return Some(LiveOutcome::Proved),
            Outcome::Reached(_) => *k = (2 * *k).max(1),
            Outcome::Bounded(d) => return Some(LiveOutcome::Bounded(d)),
            Outcome::Unknown { why, .. } => {
                return match outer.expired() {
                    Some(w) => Some(LiveOutcome::Unknown(w)),
                    None if slice.expired().is_some() => None,
                    None => Some(LiveOutcome::Unknown(why)),
                };
            }
        }
    }
}

impl Justice {
    /// The same problem with every compassion pair `(p, q)` replaced by a justice signal:
    /// a sticky latch `quiet`, set by a fresh input at any frame, from which on `p` may not
    /// hold (a constraint), and the justice signal `quiet || q`. A run is fair for the pair
    /// (`p` finitely often, or `q` infinitely often) exactly when some choice of the frame
    /// that sets `quiet` (after the last `p`, or never) makes `quiet || q` hold infinitely
    /// often; so the fair runs are those of the original, and the extra input only picks
    /// that frame.
    pub fn without_compassion(&self) -> Justice {
        let mut g = self.aig.clone();
        let mut justice = self.justice.clone();
        justice.retain(|&l| l != crate::aig::Lit::TRUE);
        for (k, &(p, q)) in self.compassion.iter().enumerate() {
            let go = g.input(Some(format!("compassion_quiet_now[{k}]")));
            let quiet = g.latch(Some(false), Some(format!("compassion_quiet[{k}]")));
            let now = g.or(quiet, go);
            let li = g.nodes[quiet.var() as usize].latch_index();
            g.set_next(li, now);
            let ok = g.or(!now, !p);
            g.constraints.push(ok);
            justice.push(g.or(now, q));
        }
        if justice.is_empty() {
            justice.push(crate::aig::Lit::TRUE);
        }
        Justice {
            aig: g,
            justice,
            compassion: Vec::new(),
        }
    }

    /// Justice property `k` of an AIGER circuit, with the file's fairness constraints as
    /// further justice signals (AIGER 1.9: a run violates it when all of them hold
    /// infinitely often).
    pub fn from_aiger(aig: &crate::aig::Aig, k: usize) -> Justice {
        let mut g = aig.clone();
        let mut justice = aig.justice.get(k).cloned().unwrap_or_default();
        justice.extend(aig.fairness.iter().copied());
        if justice.is_empty() {
            justice.push(crate::aig::Lit::TRUE);
        }
        g.bad.clear();
        g.bad_names.clear();
        g.justice.clear();
        g.justice_names.clear();
        g.fairness.clear();
        Justice {
            aig: g,
            justice,
            compassion: Vec::new(),
        }
    }

    /// The circuit as one AIGER justice property (the fairness constraints among its
    /// signals); `None` with compassion, which AIGER cannot state.
    pub fn to_aiger(&self, name: &str) -> Option<crate::aig::Aig> {
        if !self.compassion.is_empty() {
            return None;
        }
        let mut g = self.aig.clone();
        g.bad.clear();
        g.bad_names.clear();
        g.justice = vec![self.justice.clone()];
        g.justice_names = vec![Some(name.to_string())];
        g.fairness.clear();
        Some(g.reduced())
    }
}

/// Run `method` on `j`, filling `r`; the reason of an `unknown` verdict.
fn run(
    p: &Program,
    bl: &Blasted,
    j: &Justice,
    method: Method,
    limits: &Limits,
    r: &mut PropResult,
) -> Option<String> {
    match check_justice(j, method, limits) {
        LiveOutcome::Proved => {
            r.verdict = Verdict::Proved;
            None
        }
        LiveOutcome::Bounded(k) => {
            r.verdict = Verdict::Bounded;
            r.depth = k as u64;
            None
        }
        LiveOutcome::Unknown(why) => Some(why),
        LiveOutcome::Lasso { trace, loop_start } => {
            r.verdict = Verdict::Violated;
            let vectors = input_vectors(bl, &trace);
            match full_lasso(p, &vectors, loop_start) {
                Some((ticks, k)) => {
                    r.depth = ticks.len() as u64;
                    r.loop_start = Some(k as u64);
                    r.counterexample = Some(ticks);
                }
                None => {
                    r.note = Some(
                        "the lasso found does not close on the whole state within the replay \
                         bound: no counterexample"
                            .into(),
                    );
                }
            }
            None
        }
    }
}

/// Most passes of the loop [`full_lasso`] runs looking for a recurring state.
const MAX_PASSES: usize = 4096;
/// Most ticks of a lasso [`full_lasso`] returns.
const MAX_TICKS: usize = 1 << 20;

/// A lasso of `p` on the whole state from one on part of it: `ticks` with the loop from tick
/// `k`, whose state at the loop's start recurs on the circuit's latches (those in the cone of
/// influence). The loop is run again until the whole state at its start recurs (it must, the
/// states being finite; the other latches do not change which inputs are allowed nor which
/// signals hold). `None` when a tick fails or the bounds are hit.
pub fn full_lasso(p: &Program, ticks: &[Vec<i64>], k: usize) -> Option<(Vec<Vec<i64>>, usize)> {
    let (prefix, body) = ticks.split_at(k.min(ticks.len()));
    if body.is_empty() {
        return None;
    }
    let mut m = Machine::new(p);
    let step = |m: &mut Machine, v: &[i64]| -> Option<()> {
        for (inp, &x) in p.inputs.iter().zip(v) {
            m.set(inp.slot, x);
        }
        m.step().ok()
    };
    for v in prefix {
        step(&mut m, v)?;
    }
    let mut seen: HashMap<Vec<i64>, usize> = HashMap::new();
    seen.insert(m.state().to_vec(), 0);
    for pass in 1..=MAX_PASSES {
        if (k + pass * body.len()) > MAX_TICKS {
            return None;
        }
        for v in body {
            step(&mut m, v)?;
        }
        if let Some(&i) = seen.get(m.state()) {
            // Passes i..pass repeat; the loop may not start at the initial state (tick 0).
            let (first, passes) = if k + i * body.len() == 0 {
                (pass, 2 * pass)
            } else {
                (i, pass)
            };
            let mut out = prefix.to_vec();
            for _ in 0..passes {
                out.extend(body.iter().cloned());
            }
            return Some((out, k + first * body.len()));
        }
        seen.insert(m.state().to_vec(), pass);
    }
    None
}

/// The justice problem of `p`'s temporal property `name` (blasted as `bl`): `None` when `p`
/// has no temporal property of that name; `Err` with the reason when it is not LTL or its
/// automaton is too large.
pub fn justice_of(p: &Program, bl: &Blasted, name: &str) -> Option<Result<Justice, String>> {
    let t = p.temporal.iter().find(|t| t.name == name)?;
    Some(match &t.formula {
        TemporalFormula::Ctl(_) => Err(CTL_UNSUPPORTED.to_string()),
        TemporalFormula::Ltl(f) => monitor(bl, f, &p.fairness)
            .map_err(|_| "the formula's automaton is too large".to_string()),
    })
}
