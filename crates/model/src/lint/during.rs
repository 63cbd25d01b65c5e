//! W0310: a target-less (internal) transition of a state that has a `during` action.
//!
//! By rule R4 (`docs/semantics.md`) a transition that fires ends its state's reaction for the
//! tick, internal ones included: in every tick in which it fires, the state's `during` action
//! does not run (and its children are not walked). Stateflow's inner transitions behave
//! differently, so a user coming from there expects both to run. The finding holds whatever
//! the guards: whenever the transition fires, the `during` is skipped.

use super::{const_false, state_name, Cx};
use crate::model::{ChartId, Dest};
use statecheck_base::Diagnostic;

/// Run the rule on one chart.
pub(super) fn check(cx: &Cx, chart_id: ChartId, out: &mut Vec<Diagnostic>) {
    let chart = &cx.model.charts[chart_id as usize];
    for (s, node) in chart.states.iter().enumerate() {
        if node.during.is_empty() {
            continue;
        }
        for &t in &node.transitions {
            let t = &chart.transitions[t as usize];
            if !matches!(t.dest, Dest::Internal) || t.guard.as_ref().is_some_and(const_false) {
                continue;
            }
            let name = state_name(cx.model, chart_id, s as crate::model::StateId);
            let what = if name.is_empty() {
                "the chart".to_string()
            } else {
                format!("state `{name}`")
            };
            out.push(
                Diagnostic::warning(
                    "W0310",
                    format!(
                        "this transition without a target suppresses the `during` action of {what}"
                    ),
                    t.span,
                )
                .with_label("in the ticks where this fires, `during` does not run")
                .with_secondary(node.span, format!("{what} has a `during` action"))
                .with_hint(
                    "a transition that fires ends the state's reaction for the tick (rule R4); \
                     to run both, do the work of the transition inside `during` with an `if`",
                ),
            );
        }
    }
}
