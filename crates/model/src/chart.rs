//! Checking one chart: variables, the state hierarchy, actions and transitions.

use crate::expr::{is_placeholder, type_name, ExprChecker};
use crate::model::{
    Branch, Chart, ChartRole, Dest, NodeKind, StateId, StateNode, Stmt, Transition, Trigger, Var,
};
use crate::scope::Scope;
use crate::types::Type;
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast::{self, VarKind};
use std::collections::HashMap;

/// The chart under construction and the AST bodies of its nodes.
pub(crate) struct Skeleton<'a> {
    /// The chart with variables and hierarchy, but no actions or transitions yet.
    pub chart: Chart,
    /// The AST body of each state node, by id.
    pub bodies: Vec<&'a ast::StateBody>,
}

/// Phase 1: variables and the state hierarchy.
pub(crate) fn skeleton<'a>(
    ck: &mut ExprChecker,
    c: &'a ast::Chart,
    role: ChartRole,
) -> Skeleton<'a> {
    let mut chart = Chart {
        name: c.name.name.clone(),
        span: c.name.span,
        role,
        vars: Vec::new(),
        states: Vec::new(),
        transitions: Vec::new(),
        properties: Vec::new(),
    };
    let mut seen: HashMap<&str, Span> = HashMap::new();
    let empty = Scope {
        chart: None,
        instances: None,
        charts: &[],
        locals: Vec::new(),
        fn_limit: usize::MAX,
    };
    // Initial values are checked once every variable is declared, so that one naming a
    // variable is reported as "not constant" rather than as an unknown name.
    let mut inits: Vec<(usize, &ast::Expr)> = Vec::new();
    for v in &c.vars {
        if let Some(prev) = seen.insert(&v.name.name, v.name.span) {
            ck.sink.push(
                Diagnostic::error(
                    "E0102",
                    format!("`{}` is declared twice", v.name.name),
                    v.name.span,
                )
                .with_label("second declaration")
                .with_secondary(prev, "first declared here")
                .with_hint("rename one of them"),
            );
            continue;
        }
        let reported = ck.sink.diags.len();
        let ty = match (&v.ty, v.is_event) {
            (_, true) => Type::Bool,
            (Some(t), false) => ck.resolve_type(t),
            (None, false) => Type::UNBOUNDED,
        };
        // A type that could not be resolved was reported already: say nothing more about it.
        let bad_type = ck.sink.diags.len() > reported;
        if ty == Type::UNBOUNDED && !v.is_event && !bad_type {
            ck.sink.push(
                Diagnostic::error(
                    "E0103",
                    format!("variable `{}` needs a bounded type", v.name.name),
                    v.ty.as_ref().map_or(v.name.span, |t| t.span()),
                )
                .with_label("unbounded")
                .with_hint(
                    "write `int[lo..hi]`: every variable has a finite range, so it can be verified",
                ),
            );
        }
        let (lo, hi) = ty.bounds(|e| {
            ck.globals
                .enums
                .get(e as usize)
                .map_or(1, |d| d.variants.len())
        });
        let default = lo.max(0).min(hi);
        match &v.init {
            Some(e) if v.is_event => {
                ck.sink.push(
                    Diagnostic::error("E0103", "events have no initial value", e.span())
                        .with_label("remove this"),
                );
            }
            Some(e) if bad_type => {
                // Still report unknown names in it, but not a mismatch with the unknown type.
                let empty = Scope {
                    chart: None,
                    instances: None,
                    charts: &[],
                    locals: Vec::new(),
                    fn_limit: usize::MAX,
                };
                let _ = ck.check(&empty, e);
            }
            Some(e) => inits.push((chart.vars.len(), e)),
            None if v.kind == VarKind::Input || v.is_event => {}
            None => {
                ck.sink.push(
                    Diagnostic::warning(
                        "W0201",
                        format!(
                            "`{}` has no initial value; it starts at {default}",
                            v.name.name
                        ),
                        v.name.span,
                    )
                    .with_label("no `= value`")
                    .with_hint("write the initial value explicitly"),
                );
            }
        }
        chart.vars.push(Var {
            name: v.name.name.clone(),
            kind: v.kind,
            is_event: v.is_event,
            ty,
            init: default,
            span: v.name.span,
        });
    }
    let vars_only = chart.clone();
    let var_scope = Scope {
        chart: Some(&vars_only),
        ..empty
    };
    for (index, e) in inits {
        let ty = chart.vars[index].ty;
        let x = ck.check(&var_scope, e);
        let x = ck.coerce(x, ty, "initial value");
        match x.kind {
            crate::model::ExprKind::Const(v) => chart.vars[index].init = v,
            _ => {
                ck.sink.push(
                    Diagnostic::error("E0105", "an initial value must be constant", e.span())
                        .with_label("depends on variables")
                        .with_hint("use literals, constants and operators only; to start from an input's value, assign it in the `initial` action"),
                );
            }
        }
    }
    let mut bodies = Vec::new();
    build_node(
        ck,
        &mut chart,
        &mut bodies,
        &c.body,
        "",
        "",
        None,
        false,
        c.name.span,
    );
    Skeleton { chart, bodies }
}

#[allow(clippy::too_many_arguments)] // reason: one recursive builder; a struct would only rename the arguments
fn build_node<'a>(
    ck: &mut ExprChecker,
    chart: &mut Chart,
    bodies: &mut Vec<&'a ast::StateBody>,
    body: &'a ast::StateBody,
    name: &str,
    path: &str,
    parent: Option<StateId>,
    is_region: bool,
    span: Span,
) -> StateId {
    let id = chart.states.len() as StateId;
    chart.states.push(StateNode {
        name: name.to_string(),
        path: path.to_string(),
        is_region,
        parent,
        kind: NodeKind::Simple,
        entry: Vec::new(),
        during: Vec::new(),
        exit: Vec::new(),
        initial_action: Vec::new(),
        transitions: Vec::new(),
        span,
    });
    bodies.push(body);
    let child_path = |n: &str| {
        if path.is_empty() {
            n.to_string()
        } else {
            format!("{path}.{n}")
        }
    };
    // Duplicate names among children (states, regions, junctions share one namespace).
    let mut seen: HashMap<&str, Span> = HashMap::new();
    let names = body
        .states
        .iter()
        .map(|s| &s.name)
        .chain(body.regions.iter().map(|r| &r.name))
        .chain(body.junctions.iter().map(|j| &j.name));
    for n in names {
        if let Some(prev) = seen.insert(&n.name, n.span) {
            ck.sink.push(
                Diagnostic::error(
                    "E0102",
                    format!("`{}` is declared twice here", n.name),
                    n.span,
                )
                .with_label("second declaration")
                .with_secondary(prev, "first declared here"),
            );
        }
    }
    if !body.states.is_empty() && !body.regions.is_empty() {
        ck.sink.push(
            Diagnostic::error(
                "E0109",
                format!(
                    "{} mixes child states and parallel regions",
                    if name.is_empty() {
                        "the chart".to_string()
                    } else {
                        format!("state `{name}`")
                    }
                ),
                body.regions[0].name.span,
            )
            .with_secondary(body.states[0].name.span, "a child state")
            .with_hint("put the states inside a region, or the regions inside a state"),
        );
    }
    if let Some(h) = body.history.get(1) {
        ck.sink.push(
            Diagnostic::error("E0108", "more than one `history` declaration", h.span)
                .with_secondary(body.history[0].span, "first one here"),
        );
    }
    if !body.regions.is_empty() {
        if let Some(h) = body.history.first() {
            ck.sink.push(
                Diagnostic::error("E0115", "a parallel state cannot have `history`", h.span)
                    .with_hint("put `history` inside the regions"),
            );
        }
        if let Some(i) = body.initial.first() {
            ck.sink.push(
                Diagnostic::error(
                    "E0107",
                    "a parallel state has no `initial`: all its regions start",
                    i.span,
                )
                .with_label("remove this"),
            );
        }
        let mut regions = Vec::new();
        for r in &body.regions {
            let rid = build_node(
                ck,
                chart,
                bodies,
                &r.body,
                &r.name.name,
                &child_path(&r.name.name),
                Some(id),
                true,
                r.name.span,
            );
            if !r.body.transitions.is_empty()
                || !r.body.entry.is_empty()
                || !r.body.exit.is_empty()
                || !r.body.during.is_empty()
            {
                ck.sink.push(
                    Diagnostic::error(
                        "E0109",
                        format!(
                            "region `{}` cannot have actions or transitions",
                            r.name.name
                        ),
                        r.name.span,
                    )
                    .with_hint(
                        "put them on the states inside the region, or on the parallel state",
                    ),
                );
            }
            regions.push(rid);
        }
        chart.states[id as usize].kind = NodeKind::And { regions };
    } else if !body.states.is_empty() {
        let mut children = Vec::new();
        for s in &body.states {
            let sid = build_node(
                ck,
                chart,
                bodies,
                &s.body,
                &s.name.name,
                &child_path(&s.name.name),
                Some(id),
                false,
                s.name.span,
            );
            children.push(sid);
        }
        let initial = match body.initial.as_slice() {
            [] => {
                let what = if name.is_empty() {
                    format!("chart `{}`", chart.name)
                } else {
                    format!("`{name}`")
                };
                ck.sink.push(
                    Diagnostic::error(
                        "E0106",
                        format!("{what} has child states but no `initial`"),
                        span,
                    )
                    .with_label("which child starts?")
                    .with_hint(format!("add `initial {};`", body.states[0].name.name)),
                );
                0
            }
            [first, rest @ ..] => {
                for extra in rest {
                    ck.sink.push(
                        Diagnostic::error(
                            "E0108",
                            "only one `initial` is allowed per level",
                            extra.span,
                        )
                        .with_label("second `initial`")
                        .with_secondary(first.span, "first one here"),
                    );
                }
                match body
                    .states
                    .iter()
                    .position(|s| s.name.name == first.target.name)
                {
                    Some(i) => i,
                    None => {
                        let mut d = Diagnostic::error(
                            "E0107",
                            format!(
                                "`initial {}` does not name a child state",
                                first.target.name
                            ),
                            first.target.span,
                        )
                        .with_label("not a child of this state");
                        if let Some(s) = crate::suggest::closest(
                            &first.target.name,
                            body.states.iter().map(|s| s.name.name.as_str()),
                        ) {
                            d = d.with_hint(format!("did you mean `{s}`?"));
                        }
                        ck.sink.push(d);
                        0
                    }
                }
            }
        };
        let history = body.history.first().map(|h| h.kind);
        chart.states[id as usize].kind = NodeKind::Or {
            children,
            initial,
            history,
        };
    } else {
        if let Some(i) = body.initial.first() {
            ck.sink.push(
                Diagnostic::error("E0107", "`initial` in a state without child states", i.span)
                    .with_label("nothing to start"),
            );
        }
        if let Some(h) = body.history.first() {
            ck.sink.push(
                Diagnostic::error("E0115", "`history` in a state without child states", h.span)
                    .with_label("nothing to remember"),
            );
        }
        if parent.is_none() || is_region {
            let what = if parent.is_none() {
                format!("chart `{}`", chart.name)
            } else {
                format!("region `{name}`")
            };
            ck.sink.push(
                Diagnostic::error("E0106", format!("{what} has no states"), span)
                    .with_hint("add `initial S; state S { }`"),
            );
        }
    }
    id
}

/// Phase 2: actions, transitions and chart properties, with the complete hierarchy in scope.
pub(crate) fn fill(
    ck: &mut ExprChecker,
    sk: Skeleton,
    c: &ast::Chart,
    scope_instances: Option<&HashMap<String, crate::scope::InstanceGroup>>,
    charts: &[Chart],
) -> Chart {
    let Skeleton { mut chart, bodies } = sk;
    let snapshot = chart.clone();
    let scope = Scope {
        chart: Some(&snapshot),
        instances: scope_instances,
        charts,
        locals: Vec::new(),
        fn_limit: usize::MAX,
    };
    let mut transitions = Vec::new();
    for (id, body) in bodies.iter().enumerate() {
        let block = |ck: &mut ExprChecker, blocks: &[ast::Block]| -> Vec<Stmt> {
            blocks
                .iter()
                .flat_map(|b| check_block(ck, &scope, b))
                .collect()
        };
        let entry = block(ck, &body.entry);
        let during = block(ck, &body.during);
        let exit = block(ck, &body.exit);
        let initial_action = body
            .initial
            .first()
            .and_then(|i| i.action.as_ref())
            .map(|b| check_block(ck, &scope, b))
            .unwrap_or_default();
        for kind in [
            (&body.entry, "entry"),
            (&body.during, "during"),
            (&body.exit, "exit"),
        ] {
            if let Some(b) = kind.0.get(1) {
                ck.sink.push(
                    Diagnostic::error("E0108", format!("more than one `{}` block", kind.1), b.span)
                        .with_secondary(kind.0[0].span, "first one here")
                        .with_hint("merge them into one block"),
                );
            }
        }
        let node = &mut chart.states[id];
        node.entry = entry;
        node.during = during;
        node.exit = exit;
        node.initial_action = initial_action;
        let mut own = Vec::new();
        for (text_index, t) in body.transitions.iter().enumerate() {
            let tr = check_transition(ck, &scope, &snapshot, &bodies, id as StateId, t);
            own.push((
                tr.priority.is_none(),
                tr.priority.unwrap_or(0),
                text_index,
                tr,
            ));
        }
        own.sort_by_key(|(implicit, p, i, _)| (*implicit, *p, *i));
        for (_, _, _, tr) in own {
            let tid = transitions.len() as u32;
            transitions.push(tr);
            chart.states[id].transitions.push(tid);
        }
    }
    chart.transitions = transitions;
    chart.properties = crate::property::check_properties(ck, &scope, &c.properties);
    chart
}

fn check_transition(
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
            let n = match delay {
                ast::Delay::Ticks(e) => ck.const_value(scope, e),
                ast::Delay::Time(d) => duration_ticks(ck, scope, d),
            };
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
        Some(target) => resolve_dest(ck, scope, chart, bodies, source, target, &mut Vec::new()),
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

fn duration_ticks(ck: &mut ExprChecker, scope: &Scope, d: &ast::Duration) -> Option<i64> {
    let amount = ck.const_value(scope, &d.amount)?;
    let ms = match d.unit {
        ast::TimeUnit::Ms => amount,
        ast::TimeUnit::S => amount.checked_mul(1000)?,
        ast::TimeUnit::Min => amount.checked_mul(60_000)?,
    };
    let Some(tick) = ck.globals.tick_ms else {
        ck.sink.push(
            Diagnostic::error("E0120", "a delay in time units needs a tick length", d.span)
                .with_label("how many ticks is this?")
                .with_hint("declare the tick length at the top of the file, e.g. `tick 100 ms;`"),
        );
        return None;
    };
    if ms % tick != 0 {
        ck.sink.push(
            Diagnostic::error(
                "E0120",
                format!("{ms} ms is not a whole number of {tick} ms ticks"),
                d.span,
            )
            .with_hint("choose a delay that is a multiple of the tick length"),
        );
        return None;
    }
    Some(ms / tick)
}

/// Resolve a target relative to `source`: the nearest enclosing scope that declares the first
/// name wins (children of the source, then its siblings, then its parent's siblings, ...).
fn resolve_dest(
    ck: &mut ExprChecker,
    scope: &Scope,
    chart: &Chart,
    bodies: &[&ast::StateBody],
    source: StateId,
    target: &ast::Target,
    junction_stack: &mut Vec<(StateId, String)>,
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
                        junction_stack.push(key);
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
                        junction_stack.pop();
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

/// Every state (not region, not the root) with the shortest dotted name that resolves to it
/// from `source`, as a transition target would.
fn relative_names(chart: &Chart, source: StateId) -> Vec<(StateId, String)> {
    let mut out = Vec::new();
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
fn descend(chart: &Chart, from: StateId, names: &[&str]) -> Option<StateId> {
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
fn check_branches(
    ck: &mut ExprChecker,
    scope: &Scope,
    chart: &Chart,
    bodies: &[&ast::StateBody],
    source: StateId,
    branches: &[ast::Branch],
    span: Span,
    junction_stack: &mut Vec<(StateId, String)>,
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

/// Check a block of statements in a chart scope.
pub(crate) fn check_block(ck: &mut ExprChecker, scope: &Scope, b: &ast::Block) -> Vec<Stmt> {
    b.stmts
        .iter()
        .filter_map(|s| check_stmt(ck, scope, s))
        .collect()
}

fn check_stmt(ck: &mut ExprChecker, scope: &Scope, s: &ast::Stmt) -> Option<Stmt> {
    let chart = scope.chart?;
    match s {
        ast::Stmt::Assign {
            target,
            value,
            span,
        } => {
            let value = ck.check(scope, value);
            let Some(v) = chart.var(&target.name) else {
                let mut d = Diagnostic::error(
                    "E0101",
                    format!("unknown variable `{}`", target.name),
                    target.span,
                )
                .with_label("not declared in this chart");
                if let Some(s) = crate::suggest::closest(
                    &target.name,
                    chart.vars.iter().map(|v| v.name.as_str()),
                ) {
                    d = d.with_hint(format!("did you mean `{s}`?"));
                } else {
                    d = d.with_hint(format!(
                        "declare it: `local {}: int[0..10] = 0;`",
                        target.name
                    ));
                }
                ck.sink.push(d);
                return None;
            };
            let var = &chart.vars[v as usize];
            if var.is_event {
                ck.sink.push(
                    Diagnostic::error(
                        "E0110",
                        format!(
                            "`{}` is an event; events are raised, not assigned",
                            var.name
                        ),
                        target.span,
                    )
                    .with_hint(format!("write `raise {};`", var.name)),
                );
                return None;
            }
            if var.kind == VarKind::Input {
                ck.sink.push(
                    Diagnostic::error(
                        "E0110",
                        format!("cannot assign to input `{}`", var.name),
                        target.span,
                    )
                    .with_label("inputs are read-only inside the chart")
                    .with_secondary(var.span, "declared as an input here")
                    .with_hint("declare it `output` or `local` if the chart computes it"),
                );
                return None;
            }
            let before = value.ty;
            let value = ck.coerce(value, var.ty, &format!("assignment to `{}`", var.name));
            let checked = matches!(value.kind, crate::model::ExprKind::Check(..));
            let value = match value.kind {
                // The assignment itself performs the range check, so unwrap it here.
                crate::model::ExprKind::Check(inner, ..) => *inner,
                _ => value,
            };
            let _ = (
                before,
                is_placeholder(&value),
                type_name(ck.globals, var.ty),
            );
            Some(Stmt::Assign {
                var: v,
                value,
                checked,
                span: *span,
            })
        }
        ast::Stmt::Raise { event, span } => {
            let Some(v) = chart.var(&event.name) else {
                ck.sink.push(
                    Diagnostic::error(
                        "E0101",
                        format!("unknown event `{}`", event.name),
                        event.span,
                    )
                    .with_hint(format!("declare it: `local event {};`", event.name)),
                );
                return None;
            };
            let var = &chart.vars[v as usize];
            if !var.is_event || var.kind == VarKind::Input {
                ck.sink.push(
                    Diagnostic::error(
                        "E0116",
                        format!("cannot raise `{}`", event.name),
                        event.span,
                    )
                    .with_label(if var.is_event {
                        "input events come from outside"
                    } else {
                        "not an event"
                    })
                    .with_hint("only `local event` and `output event` declarations can be raised"),
                );
                return None;
            }
            Some(Stmt::Raise {
                event: v,
                span: *span,
            })
        }
        ast::Stmt::If {
            cond,
            then,
            otherwise,
            ..
        } => {
            let cond = ck.check_bool(scope, cond);
            let then = check_block(ck, scope, then);
            let otherwise = otherwise
                .as_ref()
                .map(|b| check_block(ck, scope, b))
                .unwrap_or_default();
            Some(Stmt::If {
                cond,
                then,
                otherwise,
            })
        }
    }
}
