//! Reachability in the hierarchy: states without incoming transitions (W0301) and isolated
//! sub-graphs (W0302).
//!
//! Both rules over-approximate what can happen (guards are ignored), so a state they report is
//! really never entered. History is no way in: it only resumes a state entered before.

use super::{state_name, targets, Cx};
use crate::model::{Chart, ChartId, NodeKind, StateId};
use statecheck_base::{Diagnostic, Span};
use std::collections::VecDeque;

/// Run W0301 and W0302 on one chart.
pub(super) fn check(cx: &Cx, chart_id: ChartId, out: &mut Vec<Diagnostic>) {
    let chart = &cx.model.charts[chart_id as usize];
    let n = chart.states.len();

    // incoming[s]: some transition enters `s` from outside it (s is on the path from the
    // transition's scope down to its target, and the source is not inside s).
    let mut incoming = vec![false; n];
    for t in &chart.transitions {
        let mut ts = Vec::new();
        targets(&t.dest, &mut ts);
        for target in ts {
            for a in chart.ancestry(target) {
                if !chart.is_ancestor_or_self(a, t.source) {
                    incoming[a as usize] = true;
                }
            }
        }
    }

    let mut no_incoming = vec![false; n];
    for s in 1..n as StateId {
        let node = &chart.states[s as usize];
        let Some(parent) = node.parent else { continue };
        if node.is_region || cx.is_observer_error(chart_id, s) || incoming[s as usize] {
            continue;
        }
        let NodeKind::Or {
            children, initial, ..
        } = &chart.states[parent as usize].kind
        else {
            continue;
        };
        let Some(&init) = children.get(*initial) else {
            continue;
        };
        if init == s {
            continue;
        }
        no_incoming[s as usize] = true;
        out.push(
            Diagnostic::warning("W0301", format!("state `{}` has no incoming transition", state_name(cx.model, chart_id, s)), node.span)
                .with_label("never entered")
                .with_secondary(chart.states[init as usize].span, "the initial state of this level")
                .with_hint(format!(
                    "add a transition to `{}` or remove it (`history` does not count: it only resumes states entered before)",
                    node.name
                )),
        );
    }

    for (p, node) in chart.states.iter().enumerate() {
        let NodeKind::Or {
            children, initial, ..
        } = &node.kind
        else {
            continue;
        };
        isolated(
            cx,
            chart_id,
            chart,
            p as StateId,
            children,
            *initial,
            &no_incoming,
            out,
        );
    }
}

/// W0302 for the children of one OR node `p`: project every transition onto this level and
/// search from the initial child (and from children entered from outside `p`).
#[allow(clippy::too_many_arguments)] // reason: a helper of `check`; the arguments are its locals
fn isolated(
    cx: &Cx,
    chart_id: ChartId,
    chart: &Chart,
    p: StateId,
    children: &[StateId],
    initial: usize,
    no_incoming: &[bool],
    out: &mut Vec<Diagnostic>,
) {
    if initial >= children.len() {
        return;
    }
    // The child of `p` whose subtree holds `s`, if `s` is strictly inside `p`.
    let child_of = |s: StateId| -> Option<usize> {
        let chain = chart.ancestry(s);
        let at = chain.iter().position(|x| *x == p)?;
        let c = *chain.get(at + 1)?;
        children.iter().position(|x| *x == c)
    };
    let k = children.len();
    let mut edges: Vec<Vec<usize>> = vec![Vec::new(); k];
    let mut first_edge: Vec<Option<Span>> = vec![None; k];
    let mut reached = vec![false; k];
    let mut queue = VecDeque::new();
    reached[initial] = true;
    queue.push_back(initial);
    for t in &chart.transitions {
        let mut ts = Vec::new();
        targets(&t.dest, &mut ts);
        for target in ts {
            let Some(y) = child_of(target) else { continue };
            match child_of(t.source) {
                Some(x) if x == y => {}
                Some(x) => {
                    edges[x].push(y);
                    first_edge[y].get_or_insert(t.span);
                }
                None => {
                    // Entered from `p` itself or from outside it: a start point.
                    if !reached[y] {
                        reached[y] = true;
                        queue.push_back(y);
                    }
                }
            }
        }
    }
    while let Some(x) = queue.pop_front() {
        for &y in &edges[x] {
            if !reached[y] {
                reached[y] = true;
                queue.push_back(y);
            }
        }
    }
    let init = children[initial];
    for (i, &c) in children.iter().enumerate() {
        if reached[i] || no_incoming[c as usize] || cx.is_observer_error(chart_id, c) {
            continue;
        }
        let node = &chart.states[c as usize];
        let mut d = Diagnostic::warning(
            "W0302",
            format!(
                "state `{}` cannot be reached from the initial state `{}`",
                state_name(cx.model, chart_id, c),
                chart.states[init as usize].name
            ),
            node.span,
        )
        .with_label("part of an isolated sub-graph")
        .with_secondary(
            chart.states[init as usize].span,
            "the initial state of this level",
        );
        if let Some(span) = first_edge[i] {
            d = d.with_secondary(
                span,
                "entered only from states that are never reached themselves",
            );
        }
        out.push(
            d.with_hint("connect the isolated states to the rest of this level, or remove them"),
        );
    }
}
