//! Replaying a lasso scenario (one ending in a `loop:` section): the ticks run once and the
//! loop a second time; the state after tick `loop_start - 1` must recur after each pass
//! (otherwise the scenario is not a lasso of this model). The run is then an ultimately
//! periodic run, and each `ltl` (and unbounded `respond`) property is evaluated on it with
//! `statecheck_ir::temporal::holds_on_lasso` — when the run is fair (every justice atom holds
//! somewhere in the loop; every compassion trigger that does has its response there too).

use crate::run::{run, Options, Run, ScenarioInputs, Stop};
use crate::scenario::{from_input_vectors, Scenario};
use statecheck_ir::temporal::{holds_on_lasso, TemporalFormula};
use statecheck_ir::Program;

/// The outcome of a lasso replay.
pub struct LassoRun {
    /// The run of the scenario (its first pass): `stop` is the first violated temporal
    /// property, at the last tick, when the lasso violates one.
    pub run: Run,
    /// Set when the loop does not return to the state at its start.
    pub broken: Option<String>,
    /// False when the lasso is not fair (the temporal properties were not evaluated).
    pub fair: bool,
    /// Every `ltl` (and unbounded `respond`) property the lasso violates, in declaration
    /// order (`run.stop` names the first).
    pub violated: Vec<String>,
}

/// Replay `sc`, whose `loop_start` is set.
pub fn run_lasso(program: &Program, sc: &Scenario, opts: Options) -> LassoRun {
    // The replay compares states and evaluates formulas on the trace: it is always recorded.
    let opts = Options {
        no_trace: false,
        ..opts
    };
    let first = run(program, &mut ScenarioInputs::new(sc), opts);
    let k = sc.loop_start.unwrap_or(0);
    let t = sc.len();
    if first.stop != Stop::Completed || k == 0 || k >= t || first.trace.len() != t {
        return LassoRun {
            run: first,
            broken: None,
            fair: true,
            violated: Vec::new(),
        };
    }
    let mut vectors = first.inputs.clone();
    vectors.extend_from_slice(&first.inputs[k..]);
    let twice = from_input_vectors(program, &vectors);
    let second = run(program, &mut ScenarioInputs::new(&twice), opts);
    let ns = program.n_state;
    let state = |r: &Run, i: usize| r.trace.get(i).map(|x| x.slots[..ns].to_vec());
    let at_start = state(&second, k - 1);
    let ends = [t - 1, vectors.len() - 1];
    let broken = if second.stop != Stop::Completed {
        Some("the second pass of the loop stopped early".to_string())
    } else if ends.iter().any(|&e| state(&second, e) != at_start) {
        Some(format!(
            "the loop does not return to the state after tick {}: the scenario is not a lasso of this model",
            k - 1
        ))
    } else {
        None
    };
    let mut out = LassoRun {
        run: first,
        broken,
        fair: true,
        violated: Vec::new(),
    };
    if out.broken.is_some() {
        return out;
    }
    let slots = |i: usize| &out.run.trace[i].slots;
    let holds = |e: u32, i: usize| matches!(statecheck_ir::eval(&program.nodes, slots(i), e), Ok(v) if v != 0);
    let in_loop = |e: u32| (k..t).any(|i| holds(e, i));
    out.fair = program.fairness.iter().all(|f| match f.trigger {
        None => in_loop(f.expr),
        Some(p) => !in_loop(p) || in_loop(f.expr),
    });
    if !out.fair {
        return out;
    }
    let violated: Vec<String> = program
        .temporal
        .iter()
        .filter(|p| match &p.formula {
            TemporalFormula::Ltl(f) => !holds_on_lasso(f, &holds, t, k),
            TemporalFormula::Ctl(_) => false,
        })
        .map(|p| p.name.clone())
        .collect();
    if let Some(p) = violated.first() {
        out.run.stop = Stop::Violation {
            tick: (t - 1) as u64,
            property: p.clone(),
        };
    }
    out.violated = violated;
    out
}
