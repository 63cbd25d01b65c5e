//! A property's problem retimed by one tick: the bad output read on the latches.
//!
//! A property's bad output ([`super::PropSignal::bad`]) is a function of the pre-state and the
//! inputs: the step's post-state is computed combinationally and the property read on it. So
//! even a property of one variable reads, in the same tick, every latch the step's logic of
//! that variable reads (and the "no run-time error" conjunct reads nearly all of them), and a
//! localization abstraction built from it keeps almost the whole circuit
//! ([`crate::localize`]). A property that reads only persistent state has a second form: the
//! same expressions read on the latches, which hold the post-state of the tick before
//! ([`super::PropSignal::on_state`]). [`Blasted::retimed_problem`] watches that form:
//!
//! - a latch `stepped` (reset false, next true) says a tick has happened, so the reset state,
//!   which no tick produced, is not judged (the IR judges only states after a tick);
//! - the bad output is `stepped ∧ on_state`;
//! - the constraint is `C ∨ bad`, where `C` is the original problem's ("the assumes hold and
//!   the step has no run-time error"): the frame in which the retimed bad output holds is the
//!   state after the violating tick, and nothing is asked of the tick after it.
//!
//! Then a trace of the original problem that raises its bad output in frame `k` (constraints
//! in frames `0..=k`) is a trace of the retimed problem raising its bad output in frame `k+1`
//! (same inputs, any inputs in frame `k+1`), and conversely the first frame `j >= 1` in which
//! a valid retimed trace raises its bad output has `C` in frames `0..j` and the post-state of
//! tick `j-1` violating the property, which is the original bad output in frame `j-1`. So
//! the retimed problem is safe exactly when the original is, and its counterexamples are the
//! original's with one more frame (dropped by [`retimed_trace`]).

use super::Blasted;
use crate::aig::Lit;
use crate::engine::Trace;
use statecheck_ir::{Goal, Node, Program};

/// True when the goal's expressions read only persistent state slots (no input, no
/// temporary), through any `let` of an inlined call.
pub(crate) fn reads_only_state(p: &Program, goal: Goal) -> bool {
    let mut stack: Vec<u32> = goal.exprs().collect();
    let mut seen = std::collections::HashSet::new();
    while let Some(e) = stack.pop() {
        if !seen.insert(e) {
            continue;
        }
        let Some(node) = p.nodes.get(e as usize) else {
            return false;
        };
        match *node {
            Node::Const(_) | Node::Local(_) => {}
            Node::Slot(s) => {
                if s as usize >= p.n_state {
                    return false;
                }
            }
            Node::Unary(_, a) | Node::Abs(a, _) | Node::Check(a, _, _, _) => stack.push(a),
            Node::Binary(_, a, b, _) | Node::Min(a, b) | Node::Max(a, b) | Node::Let(_, a, b) => {
                stack.push(a);
                stack.push(b);
            }
            Node::Ite(c, a, b) => {
                stack.push(c);
                stack.push(a);
                stack.push(b);
            }
        }
    }
    true
}

impl Blasted {
    /// Property `prop`'s problem retimed by one tick (module docs), reduced to its cone of
    /// influence, with the index in [`Blasted::aig`] of each of its latches (`None` for the
    /// added `stepped` latch); `None` when the property has no [`super::PropSignal::on_state`]
    /// form. The inputs are [`Blasted::aig`]'s, in order.
    pub fn retimed_problem(&self, prop: usize) -> Option<(crate::aig::Aig, Vec<Option<usize>>)> {
        let sig = self.props.get(prop)?;
        let on_state = sig.on_state?;
        let mut g = self.aig.clone();
        let n = g.latches.len();
        let stepped = g.latch(Some(false), Some("retime.stepped".into()));
        g.set_next(n, Lit::TRUE);
        let bad = g.and(stepped, on_state);
        let any_err = g.or_all(self.errs);
        let c = g.and(self.assume, !any_err);
        let c = g.or(c, bad);
        g.bad = vec![bad];
        g.bad_names = vec![Some(sig.name.clone())];
        g.constraints = if c == Lit::TRUE { vec![] } else { vec![c] };
        let (aig, kept) = g.reduced_with_latches();
        let origin = kept.into_iter().map(|k| (k < n).then_some(k)).collect();
        Some((aig, origin))
    }
}

/// The original problem's counterexample of a retimed problem's trace: the same inputs
/// without the last frame (the state after the violating tick, whose inputs nothing reads).
pub fn retimed_trace(t: Trace) -> Trace {
    let mut inputs = t.inputs;
    inputs.pop();
    Trace {
        init: t.init,
        inputs,
    }
}
