//! From the AST of a `system` of `plant`/`requirement` charts to a [`Problem`].
//!
//! The rules (reported as diagnostics `E0701`–`E0712`, all at once): every instance is a
//! single (non-array) instance of a `plant chart` or `requirement chart`; such a chart
//! declares only `controllable event`/`uncontrollable event`s, is flat (states without
//! children), has one `initial` state, and its transitions are `on EVENT -> STATE;` with no
//! guard, action or priority; it is deterministic; an event has the same controllability
//! everywhere; state requirements use `in(instance.State)`, `!`, `&&`, `||`, `true`, `false`.

use crate::problem::{Automaton, Event, EventId, Kind, Needs, Pred, Problem, NONE};
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast::{self, Control, Expr, Item, RequirementKind, Trigger};
use std::collections::HashMap;

/// Choose the system: by name, else the only `system` of the file.
pub fn find_system<'f>(
    file: &'f ast::File,
    name: Option<&str>,
) -> Result<&'f ast::System, crate::Error> {
    let err = |s: String| crate::Error::new(crate::ErrorKind::System(s));
    let systems: Vec<&ast::System> = file
        .items
        .iter()
        .filter_map(|i| match i {
            Item::System(s) => Some(s),
            _ => None,
        })
        .collect();
    let names = || {
        systems
            .iter()
            .map(|s| s.name.name.as_str())
            .collect::<Vec<_>>()
            .join(", ")
    };
    match name {
        Some(n) => systems
            .iter()
            .find(|s| s.name.name == n)
            .copied()
            .ok_or_else(|| err(format!("no system named `{n}`; available: {}", names()))),
        None => match systems.as_slice() {
            [one] => Ok(one),
            [] => Err(err(
                "the file declares no system of plants and requirements".into(),
            )),
            _ => Err(err(format!(
                "the file declares several systems; choose one with --system ({})",
                names()
            ))),
        },
    }
}

struct Ctx {
    events: Vec<Event>,
    event_ids: HashMap<String, (EventId, Span)>,
    diags: Vec<Diagnostic>,
}

impl Ctx {
    fn err(&mut self, code: &'static str, msg: impl Into<String>, span: Span) {
        self.diags.push(Diagnostic::error(code, msg.into(), span));
    }
}

/// Build the synthesis problem of `system`. Errors are returned all together.
pub fn extract(file: &ast::File, system: &ast::System) -> Result<Problem, Vec<Diagnostic>> {
    let charts: HashMap<&str, &ast::Chart> = file
        .items
        .iter()
        .filter_map(|i| match i {
            Item::Chart(c) => Some((c.name.name.as_str(), c)),
            _ => None,
        })
        .collect();
    let mut cx = Ctx {
        events: Vec::new(),
        event_ids: HashMap::new(),
        diags: Vec::new(),
    };
    // Pass 1: the alphabet, in order of first declaration.
    let mut inst_charts = Vec::new();
    for inst in &system.instances {
        if inst.count.is_some() {
            cx.err(
                "E0701",
                "instance arrays are not supported in synthesis systems (events synchronise by name)",
                inst.span,
            );
            continue;
        }
        let Some(chart) = charts.get(inst.chart.name.as_str()) else {
            cx.err(
                "E0701",
                format!("no chart named `{}`", inst.chart.name),
                inst.chart.span,
            );
            continue;
        };
        let kind = match chart.role.as_ref().map(|r| r.name.as_str()) {
            Some("plant") => Kind::Plant,
            Some("requirement") => Kind::Requirement,
            _ => {
                cx.err(
                    "E0702",
                    format!(
                        "`{}` is not a `plant chart` or `requirement chart`; synthesis systems hold only those",
                        chart.name.name
                    ),
                    inst.span,
                );
                continue;
            }
        };
        for v in &chart.vars {
            let Some(control) = v.control else {
                cx.err(
                    "E0703",
                    "plant and requirement charts declare only `controllable event`s and `uncontrollable event`s",
                    v.span,
                );
                continue;
            };
            let controllable = control == Control::Controllable;
            match cx.event_ids.get(&v.name.name) {
                Some(&(id, first)) => {
                    if cx.events[id as usize].controllable != controllable {
                        cx.diags.push(
                            Diagnostic::error(
                                "E0704",
                                format!(
                                    "event `{}` is declared both controllable and uncontrollable",
                                    v.name.name
                                ),
                                v.name.span,
                            )
                            .with_secondary(first, "first declared here"),
                        );
                    }
                }
                None => {
                    if v.name.name == "none" {
                        cx.err(
                            "E0705",
                            "`none` is reserved (it means \"no event\" in the emitted chart)",
                            v.name.span,
                        );
                    }
                    let id = cx.events.len() as EventId;
                    cx.event_ids.insert(v.name.name.clone(), (id, v.name.span));
                    cx.events.push(Event {
                        name: v.name.name.clone(),
                        controllable,
                    });
                }
            }
        }
        inst_charts.push((inst, *chart, kind));
    }
    // Pass 2: automata.
    let n_events = cx.events.len();
    let mut automata = Vec::new();
    for (inst, chart, kind) in inst_charts {
        if let Some(a) = automaton(&mut cx, inst, chart, kind, n_events) {
            automata.push(a);
        }
    }
    // Pass 3: state requirements.
    let mut never = Vec::new();
    let mut needs = Vec::new();
    for r in &system.requirements {
        match &r.kind {
            RequirementKind::Never(e) => {
                if let Some(p) = pred(&mut cx, &automata, e) {
                    never.push(p);
                }
            }
            RequirementKind::Needs { event, cond } => {
                let id = cx.event_ids.get(&event.name).map(|(i, _)| *i);
                let p = pred(&mut cx, &automata, cond);
                match (id, p) {
                    (Some(event), Some(cond)) => needs.push(Needs { event, cond }),
                    (None, _) => cx.err(
                        "E0706",
                        format!("no event `{}` in this system", event.name),
                        event.span,
                    ),
                    _ => {}
                }
            }
        }
    }
    if automata.iter().all(|a| a.kind != Kind::Plant) && cx.diags.is_empty() {
        cx.err(
            "E0707",
            "a synthesis system needs at least one plant",
            system.name.span,
        );
    }
    if !cx.diags.is_empty() {
        return Err(cx.diags);
    }
    Ok(Problem {
        name: system.name.name.clone(),
        events: cx.events,
        automata,
        never,
        needs,
    })
}

fn automaton(
    cx: &mut Ctx,
    inst: &ast::Instance,
    chart: &ast::Chart,
    kind: Kind,
    n_events: usize,
) -> Option<Automaton> {
    let body = &chart.body;
    let before = cx.diags.len();
    if !body.regions.is_empty() || !body.junctions.is_empty() || !body.transitions.is_empty() {
        cx.err(
            "E0708",
            "plant and requirement charts are flat: states and their `on EVENT -> STATE;` transitions only",
            chart.name.span,
        );
    }
    let locs: Vec<String> = body.states.iter().map(|s| s.name.name.clone()).collect();
    let index: HashMap<&str, u32> = locs
        .iter()
        .enumerate()
        .map(|(i, n)| (n.as_str(), i as u32))
        .collect();
    let initial = match body.initial.as_slice() {
        [one] => match index.get(one.target.name.as_str()) {
            Some(i) => *i,
            None => {
                cx.err(
                    "E0709",
                    format!("no state `{}`", one.target.name),
                    one.target.span,
                );
                0
            }
        },
        _ => {
            cx.err(
                "E0709",
                "the chart needs exactly one `initial` state",
                chart.name.span,
            );
            0
        }
    };
    let mut next = vec![NONE; locs.len() * n_events];
    let mut alphabet: Vec<EventId> = chart
        .vars
        .iter()
        .filter_map(|v| cx.event_ids.get(&v.name.name).map(|(i, _)| *i))
        .collect();
    alphabet.sort_unstable();
    alphabet.dedup();
    for (si, s) in body.states.iter().enumerate() {
        let b = &s.body;
        if !b.states.is_empty() || !b.regions.is_empty() || !b.junctions.is_empty() {
            cx.err(
                "E0708",
                "states of plant and requirement charts have no children",
                s.name.span,
            );
        }
        if !(b.entry.is_empty() && b.during.is_empty() && b.exit.is_empty()) {
            cx.err(
                "E0708",
                "states of plant and requirement charts have no actions",
                s.name.span,
            );
        }
        for t in &b.transitions {
            let ev = match &t.trigger {
                Some(Trigger::Event(e)) => match cx.event_ids.get(&e.name) {
                    Some((id, _)) if alphabet.binary_search(id).is_ok() => Some(*id),
                    _ => {
                        cx.err(
                            "E0710",
                            format!("`{}` is not an event of this chart", e.name),
                            e.span,
                        );
                        None
                    }
                },
                _ => {
                    cx.err("E0710", "a transition here is `on EVENT -> STATE;`", t.span);
                    None
                }
            };
            if t.guard.is_some() || t.action.is_some() || t.priority.is_some() {
                cx.err(
                    "E0710",
                    "a transition here has no guard, action or priority",
                    t.span,
                );
            }
            let target = match &t.target {
                Some(ast::Target::Path(p)) if p.segments.len() == 1 => {
                    let n = &p.segments[0].name;
                    match index.get(n.name.as_str()) {
                        Some(i) => Some(*i),
                        None => {
                            cx.err("E0709", format!("no state `{}`", n.name), n.span);
                            None
                        }
                    }
                }
                None => Some(si as u32),
                _ => {
                    cx.err("E0710", "the target is a sibling state's name", t.span);
                    None
                }
            };
            if let (Some(e), Some(to)) = (ev, target) {
                let slot = &mut next[si * n_events + e as usize];
                if *slot != NONE && *slot != to {
                    cx.err(
                        "E0711",
                        "nondeterministic: another transition on this event leaves this state",
                        t.span,
                    );
                }
                *slot = to;
            }
        }
    }
    if locs.is_empty() {
        cx.err("E0709", "the chart has no states", chart.name.span);
    }
    if cx.diags.len() > before {
        return None;
    }
    let mut marked: Vec<bool> = body.states.iter().map(|s| s.marked).collect();
    if !marked.iter().any(|m| *m) {
        marked.iter_mut().for_each(|m| *m = true);
    }
    Some(Automaton {
        name: inst.name.name.clone(),
        chart: chart.name.name.clone(),
        kind,
        locs,
        marked,
        initial,
        alphabet,
        next,
        n_events,
    })
}

fn pred(cx: &mut Ctx, automata: &[Automaton], e: &Expr) -> Option<Pred> {
    use ast::{BinOp, UnOp};
    Some(match e {
        Expr::Bool(b, _) => Pred::Const(*b),
        Expr::In(path, span) => {
            let names: Vec<&str> = path.segments.iter().map(|s| s.name.name.as_str()).collect();
            let found = match names.as_slice() {
                [inst, state] => automata.iter().enumerate().find_map(|(ai, a)| {
                    (a.name == *inst)
                        .then(|| a.locs.iter().position(|l| l == state))
                        .flatten()
                        .map(|l| Pred::At(ai as u32, l as u32))
                }),
                _ => None,
            };
            match found {
                Some(p) => p,
                None => {
                    cx.err(
                        "E0712",
                        "expected `in(instance.State)` naming an automaton's state",
                        *span,
                    );
                    return None;
                }
            }
        }
        Expr::Unary(UnOp::Not, x, _) => Pred::Not(Box::new(pred(cx, automata, x)?)),
        Expr::Binary(op @ (BinOp::And | BinOp::Or), a, b, _) => {
            let a = Box::new(pred(cx, automata, a)?);
            let b = Box::new(pred(cx, automata, b)?);
            if *op == BinOp::And {
                Pred::And(a, b)
            } else {
                Pred::Or(a, b)
            }
        }
        other => {
            cx.err(
                "E0712",
                "state requirements use `in(instance.State)`, `!`, `&&`, `||`, `true` and `false`",
                other.span(),
            );
            return None;
        }
    })
}
