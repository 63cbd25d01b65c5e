//! From a checked `system` of `plant`/`requirement` charts to a [`Problem`].
//!
//! Synthesis reads the checked model (names resolved once, by the checker), never the syntax
//! tree. The rules (reported as diagnostics `E0701`–`E0712` and `E0734`, all at once): every
//! instance is a single (non-array) instance of a `plant chart` or `requirement chart`, and the
//! system has no connections (events synchronise by name); such a chart
//! declares only `controllable event`/`uncontrollable event`s, is flat (states without
//! children), has one `initial` state, and its transitions are `on EVENT -> STATE;` with no
//! guard, action or priority; it is deterministic; an event has the same controllability
//! everywhere; state requirements use `in(instance.State)`, `!`, `&&`, `||`, `true`, `false`.

use crate::problem::{Automaton, Event, EventId, Kind, Needs, Pred, Problem, NONE};
use statecheck_base::{Diagnostic, Span};
use statecheck_model::{
    BinOp, Chart, ChartRole, Control, Dest, Expr, ExprKind, Model, NodeKind, RequirementKind,
    System, Trigger, Type, UnOp,
};
use std::collections::HashMap;

/// Choose the system: by name, else the only `system` the file declares.
pub fn find_system<'m>(model: &'m Model, name: Option<&str>) -> Result<&'m System, crate::Error> {
    let err = |s: String| crate::Error::new(crate::ErrorKind::System(s));
    let systems: Vec<&System> = model.systems.iter().filter(|s| !s.implicit).collect();
    let names = || {
        systems
            .iter()
            .map(|s| s.name.as_str())
            .collect::<Vec<_>>()
            .join(", ")
    };
    match name {
        Some(n) => systems
            .iter()
            .find(|s| s.name == n)
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

/// Build the synthesis problem of `system` of a checked model. Errors are returned all
/// together.
pub fn extract(model: &Model, system: &System) -> Result<Problem, Vec<Diagnostic>> {
    let mut cx = Ctx {
        events: Vec::new(),
        event_ids: HashMap::new(),
        diags: Vec::new(),
    };
    // Pass 1: the alphabet, in order of first declaration.
    let mut inst_charts = Vec::new();
    for (i, inst) in system.instances.iter().enumerate() {
        if let Some(k) = inst.index {
            if k == 0 {
                cx.err(
                    "E0701",
                    "instance arrays are not supported in synthesis systems (events synchronise by name)",
                    inst.span,
                );
            }
            continue;
        }
        let Some(chart) = model.charts.get(inst.chart as usize) else {
            continue;
        };
        let kind = match chart.role {
            ChartRole::Plant => Kind::Plant,
            ChartRole::Requirement => Kind::Requirement,
            ChartRole::Normal | ChartRole::Observer => {
                cx.err(
                    "E0702",
                    format!(
                        "`{}` is not a `plant chart` or `requirement chart`; synthesis systems hold only those",
                        chart.name
                    ),
                    inst.span,
                );
                continue;
            }
        };
        // Each event's name in synthesis: the chart's, or the instance's rename of it.
        let names: Vec<(String, Span)> = chart
            .vars
            .iter()
            .enumerate()
            .map(
                |(vi, v)| match inst.renames.iter().find(|r| r.var as usize == vi) {
                    Some(r) => (r.name.clone(), r.span),
                    None => (v.name.clone(), v.span),
                },
            )
            .collect();
        for (v, (name, span)) in chart.vars.iter().zip(&names) {
            let (name, span) = (name, *span);
            let Some(control) = v.control else {
                cx.err(
                    "E0703",
                    "plant and requirement charts declare only `controllable event`s and `uncontrollable event`s",
                    v.span,
                );
                continue;
            };
            let controllable = control == Control::Controllable;
            match cx.event_ids.get(name) {
                Some(&(id, first)) => {
                    if cx.events[id as usize].controllable != controllable {
                        cx.diags.push(
                            Diagnostic::error(
                                "E0704",
                                format!(
                                    "event `{name}` is declared both controllable and uncontrollable"
                                ),
                                span,
                            )
                            .with_secondary(first, "first declared here"),
                        );
                    }
                }
                None => {
                    if name == "none" {
                        cx.err(
                            "E0705",
                            "`none` is reserved (it means \"no event\" in the emitted chart)",
                            span,
                        );
                    }
                    let id = cx.events.len() as EventId;
                    cx.event_ids.insert(name.clone(), (id, span));
                    cx.events.push(Event {
                        name: name.clone(),
                        controllable,
                    });
                }
            }
        }
        let names: Vec<String> = names.into_iter().map(|(n, _)| n).collect();
        inst_charts.push((i as u32, &inst.name, chart, kind, names));
    }
    // Connections do not relabel events (they synchronise by name); a connection would be
    // silently ignored, so it is refused. After the flattening, a component's input port
    // that feeds several inner events is such a connection.
    for c in &system.connections {
        cx.diags.push(
            Diagnostic::error(
                "E0734",
                "connections are not used in synthesis systems: events synchronise by name",
                c.span,
            )
            .with_hint(
                "declare the event under the same name in every chart that shares it, or rename a chart's events per instance: `instance p1: Phil { take -> take1; }`",
            ),
        );
    }
    // Pass 2: automata, and which instance each one is.
    let n_events = cx.events.len();
    let mut automata = Vec::new();
    let mut of_instance: HashMap<u32, u32> = HashMap::new();
    for (i, name, chart, kind, names) in inst_charts {
        if let Some(a) = automaton(&mut cx, name, chart, &names, kind, n_events) {
            of_instance.insert(i, automata.len() as u32);
            automata.push(a);
        }
    }
    // Pass 3: state requirements.
    let mut never = Vec::new();
    let mut needs = Vec::new();
    let states = States {
        model,
        system,
        of_instance: &of_instance,
    };
    for r in &system.requirements {
        match &r.kind {
            RequirementKind::Never(e) => {
                if let Some(p) = pred(&mut cx, &states, e) {
                    never.push(p);
                }
            }
            RequirementKind::Needs {
                event,
                event_span,
                cond,
            } => {
                let id = cx.event_ids.get(event).map(|(i, _)| *i);
                let p = pred(&mut cx, &states, cond);
                match (id, p) {
                    (Some(event), Some(cond)) => needs.push(Needs { event, cond }),
                    (None, _) => cx.err(
                        "E0706",
                        format!("no event `{event}` in this system"),
                        *event_span,
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
            system.span,
        );
    }
    if !cx.diags.is_empty() {
        return Err(cx.diags);
    }
    Ok(Problem {
        name: system.name.clone(),
        events: cx.events,
        automata,
        never,
        needs,
    })
}

/// The automaton of one instance of a flat plant or requirement chart; `names` gives each of
/// the chart's variables its event name in synthesis (renames applied).
fn automaton(
    cx: &mut Ctx,
    name: &str,
    chart: &Chart,
    names: &[String],
    kind: Kind,
    n_events: usize,
) -> Option<Automaton> {
    let before = cx.diags.len();
    let root = &chart.states[0];
    let (children, initial) = match &root.kind {
        NodeKind::Or {
            children, initial, ..
        } => (children.as_slice(), *initial as u32),
        NodeKind::And { .. } => {
            cx.err(
                "E0708",
                "plant and requirement charts are flat: states and their `on EVENT -> STATE;` transitions only",
                chart.span,
            );
            return None;
        }
        NodeKind::Simple => {
            cx.err("E0709", "the chart has no states", chart.span);
            return None;
        }
    };
    if !root.transitions.is_empty() {
        cx.err(
            "E0708",
            "plant and requirement charts are flat: states and their `on EVENT -> STATE;` transitions only",
            chart.span,
        );
    }
    let locs: Vec<String> = children
        .iter()
        .map(|&c| chart.states[c as usize].name.clone())
        .collect();
    let loc_of = |state| children.iter().position(|&c| c == state).map(|l| l as u32);
    let mut next = vec![NONE; locs.len() * n_events];
    let mut alphabet: Vec<EventId> = chart
        .vars
        .iter()
        .zip(names)
        .filter(|(v, _)| v.control.is_some())
        .filter_map(|(_, n)| cx.event_ids.get(n).map(|(i, _)| *i))
        .collect();
    alphabet.sort_unstable();
    alphabet.dedup();
    for (si, &sid) in children.iter().enumerate() {
        let s = &chart.states[sid as usize];
        if s.kind != NodeKind::Simple {
            cx.err(
                "E0708",
                "states of plant and requirement charts have no children",
                s.span,
            );
        }
        if !(s.entry.is_empty() && s.during.is_empty() && s.exit.is_empty()) {
            cx.err(
                "E0708",
                "states of plant and requirement charts have no actions",
                s.span,
            );
        }
        for &tid in &s.transitions {
            let t = &chart.transitions[tid as usize];
            let ev = match t.trigger {
                Trigger::Event(v) => {
                    let var = &chart.vars[v as usize];
                    match names.get(v as usize).and_then(|n| cx.event_ids.get(n)) {
                        Some((id, _)) if var.control.is_some() && alphabet.contains(id) => {
                            Some(*id)
                        }
                        _ => {
                            cx.err(
                                "E0710",
                                format!("`{}` is not an event of this chart", var.name),
                                t.span,
                            );
                            None
                        }
                    }
                }
                Trigger::None | Trigger::After(_) => {
                    cx.err("E0710", "a transition here is `on EVENT -> STATE;`", t.span);
                    None
                }
            };
            if t.guard.is_some() || !t.action.is_empty() || t.priority.is_some() {
                cx.err(
                    "E0710",
                    "a transition here has no guard, action or priority",
                    t.span,
                );
            }
            let target = match &t.dest {
                Dest::Internal => Some(si as u32),
                Dest::State(d) => match loc_of(*d) {
                    Some(l) => Some(l),
                    None => {
                        cx.err("E0710", "the target is a sibling state's name", t.span);
                        None
                    }
                },
                Dest::Choice(_) => {
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
    if cx.diags.len() > before {
        return None;
    }
    let mut marked: Vec<bool> = children
        .iter()
        .map(|&c| chart.states[c as usize].marked)
        .collect();
    if !marked.iter().any(|m| *m) {
        marked.iter_mut().for_each(|m| *m = true);
    }
    Some(Automaton {
        name: name.to_string(),
        chart: chart.name.clone(),
        kind,
        locs,
        marked,
        initial,
        alphabet,
        next,
        n_events,
    })
}

/// What a state requirement's `in(instance.State)` can name.
struct States<'a> {
    model: &'a Model,
    system: &'a System,
    /// Flat instance index to automaton index.
    of_instance: &'a HashMap<u32, u32>,
}

impl States<'_> {
    /// The automaton and location of a state of an instance, if it is a location.
    fn location(&self, instance: u32, state: u32) -> Option<Pred> {
        let a = *self.of_instance.get(&instance)?;
        let inst = self.system.instances.get(instance as usize)?;
        let chart = self.model.charts.get(inst.chart as usize)?;
        let NodeKind::Or { children, .. } = &chart.states.first()?.kind else {
            return None;
        };
        let l = children.iter().position(|&c| c == state)?;
        Some(Pred::At(a, l as u32))
    }
}

fn pred(cx: &mut Ctx, states: &States<'_>, e: &Expr) -> Option<Pred> {
    let unsupported = |cx: &mut Ctx| {
        cx.err(
            "E0712",
            "state requirements use `in(instance.State)`, `!`, `&&`, `||`, `true` and `false`",
            e.span,
        );
        None
    };
    Some(match &e.kind {
        ExprKind::Const(v) if e.ty == Type::Bool => Pred::Const(*v != 0),
        ExprKind::In(r) => match r.instance.and_then(|i| states.location(i, r.state)) {
            Some(p) => p,
            None => {
                cx.err(
                    "E0712",
                    "expected `in(instance.State)` naming an automaton's state",
                    e.span,
                );
                return None;
            }
        },
        ExprKind::Unary(UnOp::Not, x) => Pred::Not(Box::new(pred(cx, states, x)?)),
        ExprKind::Binary(op @ (BinOp::And | BinOp::Or), a, b) => {
            let a = Box::new(pred(cx, states, a)?);
            let b = Box::new(pred(cx, states, b)?);
            if *op == BinOp::And {
                Pred::And(a, b)
            } else {
                Pred::Or(a, b)
            }
        }
        _ => return unsupported(cx),
    })
}
