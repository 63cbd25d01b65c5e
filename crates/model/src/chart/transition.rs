//! Transitions: triggers, guards, `after` delays, destinations (relative names, choice
//! branches) and their actions.

use super::check_block;
use crate::expr::ExprChecker;
use crate::model::{Branch, Chart, Dest, NodeKind, StateId, Transition, Trigger};
use crate::scope::Scope;
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast;

/// Most junctions one path of a transition may pass through. Junctions are expanded into the
/// transition's choice tree, which every later phase walks recursively, so a chain as long as
/// the input allows would exhaust the stack.
pub const MAX_JUNCTION_DEPTH: usize = 100;

/// Most junction expansions in one transition: junctions reached along several paths are
/// expanded once per path, which could otherwise grow exponentially.
pub const MAX_JUNCTION_EXPANSIONS: usize = 10_000;

/// The junctions on the path being resolved, and how many have been expanded so far.
#[derive(Default)]
pub(super) struct JunctionWalk {
    stack: Vec<(StateId, String)>,
    expanded: usize,
    /// The limit was reported (once per transition).
    reported: bool,
}

impl JunctionWalk {
    fn contains(&self, key: &(StateId, String)) -> bool {
        self.stack.contains(key)
    }
}

pub(super) fn check_transition(
    ck: &mut ExprChecker,
    scope: &Scope,
    chart: &Chart,
    bodies: &[&ast::StateBody],
    source: StateId,
    t: &ast::Transition,
) -> Transition {
    let trigger = match &t.trigger {
        None => Trigger::None,
        Some(ast::Trigger::Event(id)) => match chart.var(&id.name) {
            Some(v) if chart.vars[v as usize].is_event => Trigger::Event(v),
            Some(_) => {
                ck.sink.push(
                    Diagnostic::error(
                        "E0110",
                        format!("`{}` is a variable, not an event", id.name),
                        id.span,
                    )
                    .with_label("not an event")
                    .with_hint(format!(
                        "to fire while it holds, write a guard: `on [{}] -> ...`",
                        id.name
                    )),
                );
                Trigger::None
            }
            None => {
                let mut d =
                    Diagnostic::error("E0101", format!("unknown event `{}`", id.name), id.span)
                        .with_label("not declared in this chart");
                let events = chart
                    .vars
                    .iter()
                    .filter(|v| v.is_event)
                    .map(|v| v.name.as_str());
                d = match crate::suggest::closest(&id.name, events) {
                    Some(s) => d.with_hint(format!("did you mean `{s}`?")),
                    None => d.with_hint(format!("declare it: `input event {};`", id.name)),
                };
                ck.sink.push(d);
                Trigger::None
            }
        },
        Some(ast::Trigger::After { delay, span }) => {
            let n = crate::duration::delay_ticks(ck, scope, delay);
            match n {
                Some(n) if n >= 1 => Trigger::After(n),
                Some(n) => {
                    ck.sink.push(
                        Diagnostic::error(
                            "E0117",
                            format!("`after({n})` must wait at least one tick"),
                            *span,
                        )
                        .with_hint("for a transition in the same tick, use a guard-only trigger"),
                    );
                    Trigger::None
                }
                None => Trigger::None,
            }
        }
    };
    let guard = t.guard.as_ref().map(|g| ck.check_bool(scope, g));
    let action = t
        .action
        .as_ref()
        .map(|b| check_block(ck, scope, b))
        .unwrap_or_default();
    let dest = match &t.target {
        None => Dest::Internal,
        Some(target) => resolve_dest(
            ck,
            scope,
            chart,
            bodies,
            source,
            target,
            &mut JunctionWalk::default(),
        ),
    };
    let priority = t.priority.map(|(p, span)| {
        if p < 1 {
            ck.sink.push(
                Diagnostic::error("E0104", format!("priority {p} is not allowed"), span)
                    .with_hint("priorities count from 1 (highest)"),
            );
        }
        p
    });
    Transition {
        source,
        trigger,
        guard,
        action,
        dest,
        priority,
        span: t.span,
    }
}

/// Resolve a target relative to `source`: the nearest enclosing scope that declares the first
/// name wins (children of the source, then its siblings, then its parent's siblings, ...).
pub(super) fn resolve_dest(
    ck: &mut ExprChecker,
    scope: &Scope,
    chart: &Chart,
    bodies: &[&ast::StateBody],
    source: StateId,
    target: &ast::Target,
    junction_stack: &mut JunctionWalk,
) -> Dest {
    match target {
        ast::Target::Choice { branches, span } => Dest::Choice(check_branches(
            ck,
            scope,
            chart,
            bodies,
            source,
            branches,
            *span,
            junction_stack,
        )),
        ast::Target::Path(p) => {
            let names: Vec<&str> = p.segments.iter().map(|s| s.name.name.as_str()).collect();
            if let Some(seg) = p.segments.iter().find(|s| s.index.is_some()) {
                ck.sink.push(
                    Diagnostic::error("E0111", "a transition target has no index", seg.name.span)
                        .with_label("remove the index"),
                );
                return Dest::Internal;
            }
            let mut scope_node = Some(source);
            while let Some(n) = scope_node {
                // A junction declared in this node's body?
                if names.len() == 1 {
                    if let Some(j) = bodies[n as usize]
                        .junctions
                        .iter()
                        .find(|j| j.name.name == names[0])
                    {
                        let key = (n, j.name.name.clone());
                        if junction_stack.contains(&key) {
                            ck.sink.push(
                                Diagnostic::error(
                                    "E0119",
                                    format!("junction `{}` leads back to itself", names[0]),
                                    p.span,
                                )
                                .with_secondary(j.name.span, "junction declared here")
                                .with_hint("every path through junctions must end in a state"),
                            );
                            return Dest::Internal;
                        }
                        if junction_stack.stack.len() >= MAX_JUNCTION_DEPTH
                            || junction_stack.expanded >= MAX_JUNCTION_EXPANSIONS
                        {
                            if std::mem::replace(&mut junction_stack.reported, true) {
                                return Dest::Internal;
                            }
                            ck.sink.push(
                                Diagnostic::error(
                                    "E0124",
                                    format!(
                                        "this transition passes through too many junctions (more than {MAX_JUNCTION_DEPTH} on one path or {MAX_JUNCTION_EXPANSIONS} in all)"
                                    ),
                                    p.span,
                                )
                                .with_label("junction limit reached here")
                                .with_hint("merge chained junctions into one choice with more branches"),
                            );
                            return Dest::Internal;
                        }
                        junction_stack.expanded += 1;
                        junction_stack.stack.push(key);
                        let b = check_branches(
                            ck,
                            scope,
                            chart,
                            bodies,
                            source,
                            &j.branches,
                            j.name.span,
                            junction_stack,
                        );
                        junction_stack.stack.pop();
                        return Dest::Choice(b);
                    }
                }
                if let Some(found) = descend(chart, n, &names) {
                    return Dest::State(found);
                }
                scope_node = chart.states[n as usize].parent;
            }
            let mut d = Diagnostic::error(
                "E0111",
                format!("no state `{}` to go to", names.join(".")),
                p.span,
            )
            .with_label("unknown target");
            // Suggest states by the shortest path that reaches them from here.
            let reachable = relative_names(chart, source);
            let last = names[names.len() - 1];
            let same_name: Vec<&str> = reachable
                .iter()
                .filter(|(id, _)| chart.states[*id as usize].name == last)
                .map(|(_, rel)| rel.as_str())
                .collect();
            if !same_name.is_empty() {
                d = d.with_hint(format!(
                    "targets are looked up from the source state outwards; write the path from an enclosing state: `{}`",
                    same_name.join("` or `")
                ));
            } else if let Some(s) = crate::suggest::closest(
                &names.join("."),
                reachable.iter().map(|(_, rel)| rel.as_str()),
            ) {
                d = d.with_hint(format!("did you mean `{s}`?"));
            }
            ck.sink.push(d);
            Dest::Internal
        }
    }
}

/// Name segments [`relative_names`] may compare for one diagnostic: its cost grows with the
/// number of states times the cube of the nesting depth, and a mutated file with a thousand
/// states 200 deep and many unknown targets took minutes (found by `crates/fuzz`). Past the
/// budget the remaining states are not suggested.
const SUGGESTION_BUDGET: usize = 20_000;

/// Every state (not region, not the root) with the shortest dotted name that resolves to it
/// from `source`, as a transition target would (as many as [`SUGGESTION_BUDGET`] allows).
pub(super) fn relative_names(chart: &Chart, source: StateId) -> Vec<(StateId, String)> {
    let mut out = Vec::new();
    let mut budget = SUGGESTION_BUDGET;
    for (id, st) in chart.states.iter().enumerate() {
        if st.parent.is_none() || st.is_region {
            continue;
        }
        let segs: Vec<&str> = st.path.split('.').collect();
        for k in 1..=segs.len() {
            let suffix = &segs[segs.len() - k..];
            let mut scope_node = Some(source);
            let mut found = None;
            while let Some(n) = scope_node {
                if budget < k {
                    return out;
                }
                budget -= k;
                if let Some(f) = descend(chart, n, suffix) {
                    found = Some(f);
                    break;
                }
                scope_node = chart.states[n as usize].parent;
            }
            if found == Some(id as StateId) {
                out.push((id as StateId, suffix.join(".")));
                break;
            }
        }
    }
    out
}

/// Follow `names` down from the children of `from`.
pub(super) fn descend(chart: &Chart, from: StateId, names: &[&str]) -> Option<StateId> {
    let mut cur = from;
    for n in names {
        let kids: &[StateId] = match &chart.states[cur as usize].kind {
            NodeKind::Or { children, .. } => children,
            NodeKind::And { regions } => regions,
            NodeKind::Simple => return None,
        };
        cur = *kids
            .iter()
            .find(|k| chart.states[**k as usize].name == *n)?;
    }
    if chart.states[cur as usize].is_region {
        return None;
    }
    Some(cur)
}

#[allow(clippy::too_many_arguments)] // reason: mirrors `resolve_dest`, which it recurses with
pub(super) fn check_branches(
    ck: &mut ExprChecker,
    scope: &Scope,
    chart: &Chart,
    bodies: &[&ast::StateBody],
    source: StateId,
    branches: &[ast::Branch],
    span: Span,
    junction_stack: &mut JunctionWalk,
) -> Vec<Branch> {
    let mut out = Vec::new();
    for (i, b) in branches.iter().enumerate() {
        if b.guard.is_none() && i + 1 < branches.len() {
            ck.sink.push(
                Diagnostic::error(
                    "E0111",
                    "`else` must be the last branch of a choice",
                    b.span,
                )
                .with_secondary(branches[i + 1].span, "this branch could never be taken"),
            );
        }
        let guard = b.guard.as_ref().map(|g| ck.check_bool(scope, g));
        let action = b
            .action
            .as_ref()
            .map(|a| check_block(ck, scope, a))
            .unwrap_or_default();
        let dest = resolve_dest(ck, scope, chart, bodies, source, &b.target, junction_stack);
        out.push(Branch {
            guard,
            action,
            dest,
            span: b.span,
        });
    }
    if out.is_empty() {
        ck.sink.push(
            Diagnostic::error("E0111", "a choice needs at least one branch", span)
                .with_label("no branches")
                .with_hint("write `[condition] -> State;` branches, optionally ending with `else -> State;`"),
        );
    }
    out
}
