//! Minimised counterexamples and witnesses: inputs that do not matter are kept at their
//! previous value, so that a trace shows only what causes the violation.
//!
//! A trace is a list of input vectors, one per tick. Tick by tick (from the first), each input
//! that changes is set back to its value of the tick before (an event to absent, an input at
//! tick 0 to its initial value); the change is kept when the replay on the IR [`Machine`] ends
//! the same way — the same property violated (or the same run-time error) at the same tick,
//! or for a witness the same `reachable` target first reached at the same tick. The result
//! never has more changes than the input and decides the property exactly as it did.
//!
//! Replays start from the state before the tick that changed (kept per tick), so a pass costs
//! at most ticks² × inputs / 2 steps; [`MAX_STEPS`] bounds it, after which the trace is kept
//! as minimised so far.

use crate::run::{tick_once, unreached, Stop};
use statecheck_ir::verdict::{PropKind, PropResult};
use statecheck_ir::{Machine, Program};

/// Most ticks replayed by one minimisation.
pub const MAX_STEPS: u64 = 2_000_000;

/// What a replay must still show.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Target {
    /// The run stops with this property violated at the last tick.
    Violation(String),
    /// The run stops with a run-time error of this built-in property at the last tick.
    RuntimeError(String),
    /// This `reachable` property first holds at the last tick.
    Reached(String),
}

impl Target {
    /// What the minimised trace of a checker's result must still show, or `None` for the
    /// traces that are not minimised: lassos, CTL and nonblocking paths (the simulator does not
    /// evaluate them) and deadlocks. Shared by every consumer that minimises (the CLI, the
    /// studio), so that they show the same trace.
    pub fn of(r: &PropResult) -> Option<Target> {
        if r.loop_start.is_some() {
            return None;
        }
        let name = r.name.clone();
        match r.kind {
            PropKind::Ctl | PropKind::Nonblocking => None,
            PropKind::Reachable => Some(Target::Reached(name)),
            PropKind::Builtin if r.name == "deadlock_free" => None,
            PropKind::Builtin => Some(Target::RuntimeError(name)),
            _ => Some(Target::Violation(name)),
        }
    }
}

/// How a replay of ticks `from..` ended: the stop (if any) and the tick at which the target
/// `reachable` property first held (if it did).
fn outcome(
    program: &Program,
    start: &Machine,
    vectors: &[Vec<i64>],
    from: usize,
    target: &Target,
    steps: &mut u64,
) -> (Option<Stop>, Option<u64>) {
    let mut m = start.clone();
    let mut reached = unreached(program);
    let idx = match target {
        Target::Reached(n) => reached.iter().position(|(r, _)| r == n),
        _ => None,
    };
    for (t, v) in vectors.iter().enumerate().skip(from) {
        *steps += 1;
        if let Err(stop) = tick_once(program, &mut m, t as u64, v, &mut reached, &mut || {}) {
            return (Some(stop), idx.and_then(|i| reached[i].1));
        }
        if let Some(i) = idx {
            if reached[i].1.is_some() {
                return (None, reached[i].1);
            }
        }
    }
    (None, idx.and_then(|i| reached[i].1))
}

/// Whether an outcome shows the target at tick `last`.
fn shows(target: &Target, out: &(Option<Stop>, Option<u64>), last: u64) -> bool {
    match (target, out) {
        (Target::Violation(p), (Some(Stop::Violation { tick, property }), _)) => {
            property == p && *tick == last
        }
        (Target::RuntimeError(p), (Some(Stop::RuntimeError { tick, error }), _)) => {
            error.kind.builtin_property() == p && *tick == last
        }
        (Target::Reached(_), (stop, Some(t))) => {
            *t == last && !matches!(stop, Some(s) if stop_tick(s) < last)
        }
        _ => false,
    }
}

fn stop_tick(s: &Stop) -> u64 {
    match s {
        Stop::Completed => u64::MAX,
        Stop::RuntimeError { tick, .. }
        | Stop::Violation { tick, .. }
        | Stop::AssumeViolated { tick, .. } => *tick,
    }
}

/// `vectors` (one input vector per tick, in [`Program::inputs`] order) with every input change
/// that the target does not need undone. Returns `None` when the trace does not show the
/// target in the first place (nothing to minimise against).
pub fn minimise(program: &Program, vectors: &[Vec<i64>], target: &Target) -> Option<Vec<Vec<i64>>> {
    minimise_until(program, vectors, target, None)
}

/// [`minimise`], giving up undoing further changes once `deadline` has passed (the result
/// still shows the target: every change undone so far was checked to keep it).
pub fn minimise_until(
    program: &Program,
    vectors: &[Vec<i64>],
    target: &Target,
    deadline: Option<std::time::Instant>,
) -> Option<Vec<Vec<i64>>> {
    let late = || deadline.is_some_and(|d| std::time::Instant::now() >= d);
    let n = vectors.len();
    let last = (n as u64).checked_sub(1)?;
    let mut steps = 0u64;
    let mut v: Vec<Vec<i64>> = vectors.to_vec();
    let init = Machine::new(program);
    if !shows(
        target,
        &outcome(program, &init, &v, 0, target, &mut steps),
        last,
    ) {
        return None;
    }
    let initial: Vec<i64> = program
        .inputs
        .iter()
        .map(|i| program.slots[i.slot as usize].init)
        .collect();
    // The state before tick t of the accepted trace.
    let mut before = init;
    let mut reached = unreached(program);
    for t in 0..n {
        for k in 0..program.inputs.len() {
            let calm = if program.inputs[k].is_event {
                0
            } else if t == 0 {
                initial[k]
            } else {
                v[t - 1][k]
            };
            if v[t][k] == calm || steps >= MAX_STEPS || late() {
                continue;
            }
            let was = v[t][k];
            v[t][k] = calm;
            let out = outcome(program, &before, &v, t, target, &mut steps);
            if !shows(target, &out, last) {
                v[t][k] = was;
            }
        }
        // Advance the accepted trace by one tick (its outcome is known to show the target).
        if t + 1 < n {
            let _ = tick_once(
                program,
                &mut before,
                t as u64,
                &v[t],
                &mut reached,
                &mut || {},
            );
        }
    }
    Some(v)
}
