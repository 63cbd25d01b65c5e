//! Phase 1 of checking a chart: the state hierarchy (names, kinds, `initial`, history,
//! regions) built before any action or transition is checked.

use crate::expr::ExprChecker;
use crate::model::{Chart, ChartRole, NodeKind, StateId, StateNode, Var};
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
    let empty = Scope::constants(usize::MAX);
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
                let empty = Scope::constants(usize::MAX);
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
            control: v.control,
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
pub(super) fn build_node<'a>(
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
        marked: false,
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
            chart.states[sid as usize].marked = s.marked;
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
