//! Checking systems: instances (arrays flattened), connections, execution order, assumptions,
//! properties and observer charts.

use crate::chart;
use crate::expr::{type_name, ExprChecker};
use crate::model::{
    Chart, ChartRole, Connection, Instance, Property, Requirement, RequirementKind, System,
};
use crate::scope::{InstanceGroup, Scope};
use statecheck_base::Diagnostic;
use statecheck_syntax::ast::{self, VarKind};
use std::collections::HashMap;

/// Check one system; observer charts are appended to `charts`.
pub(crate) fn check_system(
    ck: &mut ExprChecker,
    s: &ast::System,
    charts: &mut Vec<Chart>,
) -> System {
    let mut instances = Vec::new();
    let mut groups: HashMap<String, InstanceGroup> = HashMap::new();
    let mut group_order: Vec<String> = Vec::new();
    let empty = Scope::constants(usize::MAX);
    for inst in &s.instances {
        let Some(&chart) = ck.globals.chart_ids.get(&inst.chart.name) else {
            let mut d = Diagnostic::error(
                "E0101",
                format!("unknown chart `{}`", inst.chart.name),
                inst.chart.span,
            )
            .with_label("no chart of this name");
            if let Some(c) = crate::suggest::closest(
                &inst.chart.name,
                ck.globals.chart_ids.keys().map(String::as_str),
            ) {
                d = d.with_hint(format!("did you mean `{c}`?"));
            }
            ck.sink.push(d);
            continue;
        };
        if groups.contains_key(&inst.name.name) {
            let mut d = Diagnostic::error(
                "E0102",
                format!("instance `{}` is declared twice", inst.name.name),
                inst.name.span,
            )
            .with_label("second declaration");
            if let Some(first) = s.instances.iter().find(|i| i.name.name == inst.name.name) {
                d = d.with_secondary(first.name.span, "first declared here");
            }
            ck.sink.push(d);
            continue;
        }
        let first = instances.len() as u32;
        let len = match &inst.count {
            None => {
                let renames = renames(ck, inst, charts.get(chart as usize));
                instances.push(Instance {
                    name: inst.name.name.clone(),
                    chart,
                    index: None,
                    renames,
                    span: inst.name.span,
                });
                None
            }
            Some(e) => {
                let n = ck.const_value(&empty, e).unwrap_or(1);
                if !(1..=4096).contains(&n) {
                    ck.sink.push(
                        Diagnostic::error(
                            "E0104",
                            format!("an instance array needs 1..4096 elements, not {n}"),
                            e.span(),
                        )
                        .with_label("bad length"),
                    );
                }
                let n = n.clamp(1, 4096) as u32;
                if let Some(r) = inst.renames.first() {
                    ck.sink.push(
                        Diagnostic::error(
                            "E0191",
                            "an instance array cannot rename events",
                            r.span,
                        )
                        .with_label("every element would get the same names")
                        .with_hint("declare the elements one by one, each with its own renames"),
                    );
                }
                for i in 0..n {
                    instances.push(Instance {
                        name: format!("{}[{i}]", inst.name.name),
                        chart,
                        index: Some(i),
                        renames: Vec::new(),
                        span: inst.name.span,
                    });
                }
                Some(n)
            }
        };
        groups.insert(inst.name.name.clone(), InstanceGroup { first, len, chart });
        group_order.push(inst.name.name.clone());
    }

    // Observers: charts that may read the system's instances by path.
    let mut observer_charts = Vec::new();
    for o in &s.observers {
        let sk = chart::skeleton(ck, o, ChartRole::Observer);
        let filled = chart::fill(ck, sk, o, Some(&groups), charts);
        if filled.state_by_path("error").is_none() {
            ck.sink.push(
                Diagnostic::error(
                    "E0121",
                    format!(
                        "observer `{}` has no top-level state named `error`",
                        o.name.name
                    ),
                    o.name.span,
                )
                .with_hint("an observer's property is that its state `error` is never entered"),
            );
        }
        observer_charts.push(filled);
    }
    for oc in observer_charts {
        let id = charts.len() as u32;
        let name = oc.name.clone();
        charts.push(oc);
        instances.push(Instance {
            name: name.clone(),
            chart: id,
            index: None,
            renames: Vec::new(),
            span: s.name.span,
        });
        groups.insert(
            name.clone(),
            InstanceGroup {
                first: instances.len() as u32 - 1,
                len: None,
                chart: id,
            },
        );
    }

    let scope = Scope {
        chart: None,
        instances: Some(&groups),
        charts,
        locals: Vec::new(),
        fn_limit: usize::MAX,
    };
    let connections = check_connections(ck, &scope, s, &instances);
    let rates = crate::rate::check_rates(ck, &scope, s, &instances, &connections);

    // Execution order: the written order, then observers.
    let mut order: Vec<u32> = Vec::new();
    match s.order.as_slice() {
        [] => {
            order.extend((0..instances.len() as u32).filter(|i| {
                charts[instances[*i as usize].chart as usize].role != ChartRole::Observer
            }))
        }
        [o, rest @ ..] => {
            for extra in rest {
                ck.sink.push(
                    Diagnostic::error(
                        "E0108",
                        "only one `order` declaration is allowed",
                        extra.span,
                    )
                    .with_secondary(o.span, "first one here"),
                );
            }
            let mut listed = Vec::new();
            for name in &o.instances {
                match groups.get(&name.name) {
                    Some(g) if charts[g.chart as usize].role == ChartRole::Observer => {
                        ck.sink.push(Diagnostic::error(
                            "E0122",
                            "observers always run last; do not list them in `order`",
                            name.span,
                        ));
                    }
                    Some(g) => {
                        if listed.contains(&name.name) {
                            ck.sink.push(Diagnostic::error(
                                "E0122",
                                format!("`{}` appears twice in `order`", name.name),
                                name.span,
                            ));
                            continue;
                        }
                        listed.push(name.name.clone());
                        order.extend(g.first..g.first + g.len.unwrap_or(1));
                    }
                    None => ck.sink.push(unknown_instance(
                        &name.name,
                        name.span,
                        group_order.iter().map(String::as_str),
                    )),
                }
            }
            for g in &group_order {
                if !listed.contains(g) {
                    ck.sink.push(
                        Diagnostic::error(
                            "E0122",
                            format!("instance `{g}` is missing from `order`"),
                            o.span,
                        )
                        .with_hint("list every instance exactly once"),
                    );
                }
            }
        }
    }
    order.extend(
        (0..instances.len() as u32)
            .filter(|i| charts[instances[*i as usize].chart as usize].role == ChartRole::Observer),
    );

    let assumes = s
        .assumes
        .iter()
        .map(|a| ck.check_bool(&scope, &a.expr))
        .collect();
    let mut properties: Vec<Property> =
        crate::property::check_properties(ck, &scope, &s.properties);
    // Chart-level properties hold for every instance.
    for (i, inst) in instances.iter().enumerate() {
        for p in &charts[inst.chart as usize].properties {
            let mut p = p.clone();
            p.name = format!("{}.{}", inst.name, p.name);
            crate::rebase::property(&mut p, i as u32);
            properties.push(p);
        }
    }
    let mut seen = HashMap::new();
    for p in &properties {
        if let Some(prev) = seen.insert(p.name.clone(), p.span) {
            ck.sink.push(
                Diagnostic::error(
                    "E0102",
                    format!("property `{}` is declared twice", p.name),
                    p.span,
                )
                .with_label("second declaration")
                .with_secondary(prev, "first declared here"),
            );
        }
    }
    let requirements = s
        .requirements
        .iter()
        .map(|r| Requirement {
            kind: match &r.kind {
                ast::RequirementKind::Never(e) => RequirementKind::Never(ck.check_bool(&scope, e)),
                ast::RequirementKind::Needs { event, cond } => RequirementKind::Needs {
                    event: event.name.clone(),
                    event_span: event.span,
                    cond: ck.check_bool(&scope, cond),
                },
            },
            span: r.span,
        })
        .collect();
    let interleaved = s
        .interleaved
        .then(|| interleaving(&instances, &order, s.observers.len()))
        .flatten();
    System {
        name: s.name.name.clone(),
        implicit: false,
        interleaved,
        instances,
        connections,
        order,
        assumes,
        rates,
        properties,
        requirements,
        span: s.name.span,
    }
}

fn check_connections(
    ck: &mut ExprChecker,
    scope: &Scope,
    s: &ast::System,
    instances: &[Instance],
) -> Vec<Connection> {
    let mut out: Vec<Connection> = Vec::new();
    // Each connected input and its connection's index in `out`: one look-up per connection.
    let mut seen: std::collections::HashMap<(u32, u32), usize> = Default::default();
    for c in &s.connections {
        let (Some(from), Some(to)) = (
            endpoint(ck, scope, &c.from, false),
            endpoint(ck, scope, &c.to, true),
        ) else {
            continue;
        };
        let (fi, fv) = from[0];
        let fchart = &scope.charts[instances[fi as usize].chart as usize];
        let fvar = &fchart.vars[fv as usize];
        if fvar.kind == VarKind::Local {
            ck.sink.push(
                Diagnostic::error(
                    "E0123",
                    format!("`{}` is local to `{}`", fvar.name, fchart.name),
                    c.from.span,
                )
                .with_hint("declare it `output` to connect it"),
            );
            continue;
        }
        for (ti, tv) in to {
            let tchart = &scope.charts[instances[ti as usize].chart as usize];
            let tvar = &tchart.vars[tv as usize];
            if tvar.kind != VarKind::Input {
                ck.sink.push(
                    Diagnostic::error(
                        "E0123",
                        format!("`{}` of `{}` is not an input", tvar.name, tchart.name),
                        c.to.span,
                    )
                    .with_hint("a connection writes an input of the receiving instance"),
                );
                continue;
            }
            if tvar.is_event != fvar.is_event || !fvar.ty.compatible(tvar.ty) {
                let (a, b) = (
                    type_name(ck.globals, fvar.ty),
                    type_name(ck.globals, tvar.ty),
                );
                ck.sink.push(
                    Diagnostic::error("E0103", format!("cannot connect `{a}` to `{b}`"), c.span)
                        .with_secondary(fvar.span, format!("`{a}` here"))
                        .with_secondary(tvar.span, format!("`{b}` here")),
                );
                continue;
            }
            if let (
                crate::types::Type::Int { lo, hi },
                crate::types::Type::Int { lo: tl, hi: th },
            ) = (fvar.ty, tvar.ty)
            {
                if lo < tl || hi > th {
                    ck.sink.push(
                        Diagnostic::error(
                            "E0104",
                            format!(
                                "`{}.{}` ranges over {lo}..{hi}, but `{}.{}` accepts only {tl}..{th}",
                                instances[fi as usize].name, fvar.name, instances[ti as usize].name, tvar.name
                            ),
                            c.span,
                        )
                            .with_hint("widen the input's range or narrow the output's"),
                    );
                    continue;
                }
            }
            if let Some(prev) = seen.get(&(ti, tv)).map(|&k| &out[k]) {
                ck.sink.push(
                    Diagnostic::error(
                        "E0123",
                        format!(
                            "input `{}.{}` is connected twice",
                            instances[ti as usize].name, tvar.name
                        ),
                        c.span,
                    )
                    .with_secondary(prev.span, "first connection"),
                );
                continue;
            }
            if fi == ti {
                ck.sink.push(
                    Diagnostic::warning("W0202", "an instance connected to itself", c.span)
                        .with_hint(
                            "the input is the output itself: it reads what this instance wrote earlier in this step, else the previous tick's value",
                        ),
                );
            }
            seen.insert((ti, tv), out.len());
            out.push(Connection {
                from: (fi, fv),
                to: (ti, tv),
                span: c.span,
            });
        }
    }
    out
}

/// "unknown instance" with a suggestion among the declared ones.
fn unknown_instance<'a>(
    name: &str,
    span: statecheck_base::Span,
    declared: impl Iterator<Item = &'a str>,
) -> Diagnostic {
    let mut d = Diagnostic::error("E0101", format!("unknown instance `{name}`"), span)
        .with_label("no instance of this name");
    if let Some(c) = crate::suggest::closest(name, declared) {
        d = d.with_hint(format!("did you mean `{c}`?"));
    }
    d
}

/// The instances and variable that `instance.variable` names in a system (every element for
/// `instance[*].variable` when `allow_all`); `None` after reporting why it names none.
pub(crate) fn endpoint(
    ck: &mut ExprChecker,
    scope: &Scope,
    p: &ast::Path,
    allow_all: bool,
) -> Option<Vec<(u32, u32)>> {
    let groups = scope.instances?;
    if p.segments.len() != 2 || p.segments[1].index.is_some() {
        ck.sink.push(
            Diagnostic::error(
                "E0123",
                "a connection endpoint is `instance.variable`",
                p.span,
            )
            .with_label("expected `instance.variable`"),
        );
        return None;
    }
    let seg = &p.segments[0];
    let Some(g) = groups.get(&seg.name.name) else {
        if !ck.sink.first("E0101", seg.name.span) {
            return None;
        }
        // `closest` breaks ties by name, so the candidates need no sorting.
        ck.sink.push(unknown_instance(
            &seg.name.name,
            seg.name.span,
            groups.keys().map(String::as_str),
        ));
        return None;
    };
    let chart = &scope.charts[g.chart as usize];
    let vname = &p.segments[1].name.name;
    let Some(v) = chart.var(vname) else {
        let mut d = Diagnostic::error(
            "E0101",
            format!("chart `{}` has no variable `{vname}`", chart.name),
            p.segments[1].name.span,
        )
        .with_label("unknown variable");
        if let Some(c) = crate::suggest::closest(vname, chart.vars.iter().map(|v| v.name.as_str()))
        {
            d = d.with_hint(format!("did you mean `{c}`?"));
        }
        ck.sink.push(d);
        return None;
    };
    let insts: Vec<u32> = match (&seg.index, g.len) {
        (Some(ast::Index::All(span)), Some(len)) => {
            if !allow_all {
                ck.sink.push(
                    Diagnostic::error(
                        "E0123",
                        "`[*]` is only allowed on the receiving side",
                        *span,
                    )
                    .with_label("one sender per connection")
                    .with_hint(
                        "connect one element (`[0]`) to many receivers (`[*]`), not many to one",
                    ),
                );
                return None;
            }
            (g.first..g.first + len).collect()
        }
        (Some(ast::Index::At(e)), Some(len)) => {
            let i = ck.const_value(&Scope::constants(usize::MAX), e)?;
            if i < 0 || i >= len as i64 {
                ck.sink.push(
                    Diagnostic::error(
                        "E0104",
                        format!(
                            "index {i} out of range for `{}` (length {len})",
                            seg.name.name
                        ),
                        e.span(),
                    )
                    .with_label(format!("must be within 0..{}", len - 1)),
                );
                return None;
            }
            vec![g.first + i as u32]
        }
        (None, None) => vec![g.first],
        (None, Some(_)) => {
            let n = &seg.name.name;
            let hint = if allow_all {
                format!("write `{n}[0]` for one element, or `{n}[*]` for every element")
            } else {
                format!("write `{n}[0]`")
            };
            ck.sink.push(
                Diagnostic::error(
                    "E0123",
                    format!("`{n}` is an array of instances and needs an index"),
                    seg.name.span,
                )
                .with_label("needs an index")
                .with_hint(hint),
            );
            return None;
        }
        (Some(_), None) => {
            ck.sink.push(
                Diagnostic::error(
                    "E0123",
                    format!("`{}` is not an instance array", seg.name.name),
                    seg.name.span,
                )
                .with_label("remove the index"),
            );
            return None;
        }
    };
    Some(insts.into_iter().map(|i| (i, v)).collect())
}

/// The units of an interleaved system, numbered in execution order: each instance's
/// [`crate::interleave::unit_key`]; the scheduler and the observers (the last `observers`
/// instances) belong to none. `None` when the scheduler is missing (an error reported).
fn interleaving(
    instances: &[Instance],
    order: &[u32],
    observers: usize,
) -> Option<crate::model::Interleaving> {
    let scheduler = instances
        .iter()
        .position(|i| i.name == crate::interleave::SCHED)? as u32;
    let first_observer = instances.len().saturating_sub(observers);
    let mut unit = vec![None; instances.len()];
    let mut units: Vec<String> = Vec::new();
    for &i in order {
        if i == scheduler || i as usize >= first_observer {
            continue;
        }
        let key = crate::interleave::unit_key(&instances[i as usize].name);
        let u = match units.iter().position(|k| k == key) {
            Some(u) => u,
            None => {
                units.push(key.to_string());
                units.len() - 1
            }
        };
        unit[i as usize] = Some(u as u32);
    }
    Some(crate::model::Interleaving {
        scheduler,
        unit,
        units,
    })
}

/// The checked renames of a (non-array) instance of `chart`: each renamed name must be one of
/// the chart's events (`controllable event`/`uncontrollable event`), renamed once (E0190).
fn renames(
    ck: &mut ExprChecker,
    inst: &ast::Instance,
    chart: Option<&Chart>,
) -> Vec<crate::model::EventRename> {
    let mut out: Vec<crate::model::EventRename> = Vec::new();
    let Some(chart) = chart else {
        return out;
    };
    for r in &inst.renames {
        let var = chart
            .vars
            .iter()
            .position(|v| v.name == r.event.name && v.control.is_some());
        let Some(var) = var else {
            let events: Vec<&str> = chart
                .vars
                .iter()
                .filter(|v| v.control.is_some())
                .map(|v| v.name.as_str())
                .collect();
            let hint = if events.is_empty() {
                format!(
                    "`{}` declares no `controllable event` or `uncontrollable event`; renames are for synthesis",
                    chart.name
                )
            } else {
                format!("its events: {}", events.join(", "))
            };
            ck.sink.push(
                Diagnostic::error(
                    "E0190",
                    format!(
                        "`{}` is not an event of chart `{}`",
                        r.event.name, chart.name
                    ),
                    r.event.span,
                )
                .with_label("not a synthesis event of the chart")
                .with_hint(hint),
            );
            continue;
        };
        let var = var as crate::model::VarId;
        if let Some(first) = out.iter().find(|o| o.var == var) {
            ck.sink.push(
                Diagnostic::error(
                    "E0190",
                    format!("event `{}` is renamed twice", r.event.name),
                    r.event.span,
                )
                .with_label("second rename")
                .with_secondary(first.span, "first renamed here"),
            );
            continue;
        }
        out.push(crate::model::EventRename {
            var,
            name: r.to.name.clone(),
            span: r.span,
        });
    }
    out
}
