//! Rules about the transitions of one state: equal priorities (W0303), shadowed transitions and
//! branches (W0304), constant-false guards (W0305), self-transitions on composite states
//! (W0306) and choices that can fail (W0307).

use super::cover::{coverage, Coverage};
use super::{const_false, const_true, state_name, Cx};
use crate::model::{Chart, ChartId, Dest, Expr, NodeKind, StateId, Transition, Trigger, VarId};
use statecheck_base::{Diagnostic, Span};

/// Run the transition rules on one chart.
pub(super) fn check(cx: &Cx, chart_id: ChartId, out: &mut Vec<Diagnostic>) {
    let chart = &cx.model.charts[chart_id as usize];
    for (s, node) in chart.states.iter().enumerate() {
        let s = s as StateId;
        let own: Vec<&Transition> = node
            .transitions
            .iter()
            .map(|t| &chart.transitions[*t as usize])
            .collect();
        equal_priorities(&own, out);
        shadowed(cx, chart_id, chart, s, &own, out);
        for t in &own {
            self_transition(cx, chart_id, chart, t, out);
            let trigger = match t.trigger {
                Trigger::Event(e) => Some(e),
                _ => None,
            };
            let mut assume: Vec<&Expr> = t.guard.iter().collect();
            if let Some(g) = &t.guard {
                if const_false(g) {
                    out.push(always_false(g.span, t.span, "this transition never fires"));
                    continue;
                }
            }
            dest_rules(cx, chart_id, t, &t.dest, &mut assume, trigger, None, out);
        }
    }
}

/// W0303: two transitions of one state with the same explicit priority.
fn equal_priorities(own: &[&Transition], out: &mut Vec<Diagnostic>) {
    for (j, t) in own.iter().enumerate() {
        let Some(p) = t.priority else { continue };
        // Equal priorities keep their textual order, so the first one with `p` comes first.
        if let Some(first) = own[..j].iter().find(|u| u.priority == Some(p)) {
            out.push(
                Diagnostic::warning("W0303", format!("two transitions of this state have priority {p}"), t.span)
                    .with_label(format!("priority {p} again"))
                    .with_secondary(first.span, format!("priority {p} first given here"))
                    .with_hint("give each transition of a state its own priority; with equal numbers the textual order decides"),
            );
        }
    }
}

/// W0304: a transition that never fires because an earlier one with the same trigger (or none)
/// is always enabled when it is.
fn shadowed(
    cx: &Cx,
    chart_id: ChartId,
    chart: &Chart,
    s: StateId,
    own: &[&Transition],
    out: &mut Vec<Diagnostic>,
) {
    // always[i]: transition i fires whenever its trigger occurs (no real guard, and its
    // destination cannot fail).
    // (Only worth deciding when a later transition could be shadowed by it.)
    let always: Vec<bool> = own
        .iter()
        .enumerate()
        .map(|(i, t)| {
            let unguarded = t.guard.as_ref().is_none_or(const_true);
            let trigger = match t.trigger {
                Trigger::Event(e) => Some(e),
                _ => None,
            };
            let victims = own[i + 1..]
                .iter()
                .any(|u| t.trigger == Trigger::None || t.trigger == u.trigger);
            unguarded
                && victims
                && coverage(cx, chart_id, &[], trigger, &t.dest) == Coverage::Always
        })
        .collect();
    for (j, t) in own.iter().enumerate() {
        if t.guard.as_ref().is_some_and(const_false) {
            continue; // W0305 says it better
        }
        let earlier = (0..j).find(|&i| {
            always[i] && (own[i].trigger == Trigger::None || own[i].trigger == t.trigger)
        });
        let Some(i) = earlier else { continue };
        let u = own[i];
        let name = state_name(cx.model, chart_id, s);
        let what = match u.trigger {
            Trigger::None => format!("an earlier transition of `{name}` fires in every step"),
            Trigger::Event(e) => format!(
                "an earlier transition of `{name}` always fires on `{}`",
                chart.vars[e as usize].name
            ),
            Trigger::After(n) => {
                format!("an earlier transition of `{name}` always fires after {n} ticks")
            }
        };
        out.push(
            Diagnostic::warning("W0304", format!("this transition can never fire: {what}"), t.span)
                .with_label("shadowed")
                .with_secondary(u.span, "always taken first")
                .with_hint("give the earlier transition a guard, or move this one before it (or give it a smaller `priority`)"),
        );
    }
}

/// W0306: an external self-transition of a composite state.
fn self_transition(
    cx: &Cx,
    chart_id: ChartId,
    chart: &Chart,
    t: &Transition,
    out: &mut Vec<Diagnostic>,
) {
    let node = &chart.states[t.source as usize];
    if matches!(node.kind, NodeKind::Simple) {
        return;
    }
    let mut ts = Vec::new();
    super::targets(&t.dest, &mut ts);
    if ts.contains(&t.source) {
        out.push(
            Diagnostic::warning(
                "W0306",
                format!("self-transition on the composite state `{}`", state_name(cx.model, chart_id, t.source)),
                t.span,
            )
            .with_label("leaves and re-enters the state")
            .with_secondary(node.span, "a composite state")
            .with_hint(format!(
                "it exits and re-enters all sub-states of `{}`; to stay in the current sub-state, use an internal transition without a target (`on e / {{ ... }};`)",
                node.name
            )),
        );
    }
}

fn always_false(guard: Span, at: Span, label: &str) -> Diagnostic {
    Diagnostic::warning("W0305", "guard is always false", at)
        .with_label(label.to_string())
        .with_secondary(guard, "this guard is constant `false`")
        .with_hint("remove the dead transition, or fix the guard (does it test constants only?)")
}

/// W0304 (branches), W0305 (branch guards) and W0307 (choices that can fail) below one
/// destination. `assume` holds the guards that are known to hold when `dest` is evaluated;
/// `via` is the branch that leads to `dest` (`None` for the transition's own destination).
#[allow(clippy::too_many_arguments)] // reason: the recursion threads the same context through every branch
fn dest_rules<'m>(
    cx: &Cx,
    chart_id: ChartId,
    t: &Transition,
    dest: &'m Dest,
    assume: &mut Vec<&'m Expr>,
    trigger: Option<VarId>,
    via: Option<Span>,
    out: &mut Vec<Diagnostic>,
) {
    let Dest::Choice(branches) = dest else { return };
    let has_else = branches.iter().any(|b| b.guard.is_none());
    if !has_else && coverage(cx, chart_id, assume, trigger, dest) == Coverage::Gap {
        let (at, label) = match via {
            None => (t.span, "then this transition does not fire"),
            Some(span) => (span, "then this branch is not taken"),
        };
        let last = branches.last().map_or(at, |b| b.span);
        out.push(
            Diagnostic::warning(
                "W0307",
                "choice without `else` whose guards can all be false",
                at,
            )
            .with_label(label)
            .with_secondary(last, "no `else` after this branch")
            .with_hint(
                "add `else -> ...;` as the last branch, or make the guards cover every case",
            ),
        );
    }
    let mut taken_always: Option<Span> = None;
    for b in branches {
        if let Some(g) = &b.guard {
            if const_false(g) {
                out.push(always_false(g.span, b.span, "this branch is never taken"));
                continue;
            }
        }
        if let Some(first) = taken_always {
            out.push(
                Diagnostic::warning(
                    "W0304",
                    "this branch can never be taken: an earlier branch is always taken",
                    b.span,
                )
                .with_label("shadowed")
                .with_secondary(first, "always taken first")
                .with_hint("remove the branch, or give the earlier one a guard"),
            );
            continue;
        }
        if b.guard.as_ref().is_none_or(const_true) && super::cover::structurally_valid(&b.dest) {
            taken_always = Some(b.span);
        }
        let pushed = b.guard.is_some();
        if let Some(g) = &b.guard {
            assume.push(g);
        }
        dest_rules(cx, chart_id, t, &b.dest, assume, trigger, Some(b.span), out);
        if pushed {
            assume.pop();
        }
    }
}
